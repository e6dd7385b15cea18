#!/usr/bin/env python3
"""Writes the lit corner of docs/quality.md ("One bounce at a time"): a 4 m x 4 m floor and a 4 m
high wall along its back edge, albedo 0.8, a sun from above and in front at 50 degrees, and a camera
looking at the corner.

    scripts/corner-scene.py OUT.gltf        (also writes OUT.bin)
"""
import json
import math
import os
import struct
import sys


def quat_x(angle):
    return [math.sin(angle / 2), 0.0, 0.0, math.cos(angle / 2)]


def write_corner(path):
    quads = [([[-2, 0, -2], [-2, 0, 2], [2, 0, 2], [2, 0, -2]], [0, 1, 0]),
             ([[-2, 0, -2], [2, 0, -2], [2, 4, -2], [-2, 4, -2]], [0, 0, 1])]
    pos, nrm, idx = [], [], []
    for corners, normal in quads:
        base = len(pos) // 3
        for c in corners:
            pos += c
            nrm += normal
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    data = struct.pack("%df" % len(pos), *pos) + struct.pack("%df" % len(nrm), *nrm) + struct.pack("%dH" % len(idx), *idx)
    n = len(pos) // 3
    with open(path[:-5] + ".bin", "wb") as f:
        f.write(data)
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 2.0, 4.5], "rotation": quat_x(-math.radians(15))},
                  {"rotation": quat_x(-math.radians(50)), "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 1.0, "znear": 0.01, "zfar": 100}}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 1.0}]}},
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0}}],
        "buffers": [{"uri": os.path.basename(path[:-5]) + ".bin", "byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": n * 12},
                        {"buffer": 0, "byteOffset": n * 12, "byteLength": n * 12},
                        {"buffer": 0, "byteOffset": n * 24, "byteLength": len(idx) * 2}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
                       "min": [min(pos[i::3]) for i in range(3)], "max": [max(pos[i::3]) for i in range(3)]},
                      {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5123, "count": len(idx), "type": "SCALAR"}],
    }
    with open(path, "w") as f:
        json.dump(gltf, f)


if __name__ == "__main__":
    write_corner(sys.argv[1])
