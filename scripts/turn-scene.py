#!/usr/bin/python3
"""Writes a glTF scene turned about the vertical (Y) axis through the origin.

    scripts/turn-scene.py IN.gltf OUT.gltf DEGREES

Every node of the default scene goes under one new root node with that rotation,
so the geometry, the lights and the camera turn together and a path tracer renders
the same image: what changes in dvsgi's image shows how much its voxels (whose grid
keeps the world's axes) depend on the orientation of the surfaces. Relative buffer
and image URIs are rewritten to point where the input's do (dvsgi then needs
--allow-outside-references unless OUT sits next to IN); data URIs stay.
"""
import json
import math
import os
import sys


def fail(msg):
    print("turn-scene: " + msg, file=sys.stderr)
    sys.exit(1)


if len(sys.argv) != 4:
    fail("usage: turn-scene.py IN.gltf OUT.gltf DEGREES")
src, dst = sys.argv[1], sys.argv[2]
try:
    degrees = float(sys.argv[3])
    with open(src) as f:
        doc = json.load(f)
    scene = doc["scenes"][doc.get("scene", 0)]
except (OSError, ValueError, KeyError, IndexError, TypeError) as e:
    fail("%s: %s" % (src, e))
if not math.isfinite(degrees):
    fail("DEGREES must be a finite number")
half = math.radians(degrees) / 2.0
doc["nodes"].append({"name": "turn", "rotation": [0.0, math.sin(half), 0.0, math.cos(half)],
                     "children": list(scene["nodes"])})
scene["nodes"] = [len(doc["nodes"]) - 1]
rel = os.path.relpath(os.path.dirname(os.path.abspath(src)), os.path.dirname(os.path.abspath(dst)))
for item in doc.get("buffers", []) + doc.get("images", []):
    uri = item.get("uri")
    if uri and not uri.startswith("data:") and not os.path.isabs(uri):
        item["uri"] = os.path.join(rel, uri)
with open(dst, "w") as f:
    json.dump(doc, f)
