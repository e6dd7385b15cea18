#!/usr/bin/env python3
"""Ten Sponzas in a 5 x 2 grid, rendered with a clipmap, against one Sponza (docs/clipmap.md).

Writes OUT_DIR/sponza-10x.gltf: sponza-sun.gltf's JSON with nine more instances of its mesh
(`spacing` metres apart), its buffer and textures hard-linked from SHARED_DIR (copied only across
file systems; OUT_DIR is never committed), the camera and the sun unchanged, so the camera stands in the first Sponza. Then
renders from that camera (the whole image, and its indirect term from the --aov file):
  - one Sponza, fitted 128^3 grid (voxels of 0.338 m);
  - one Sponza, --clipmap L at level-0 voxels of the same edge;
  - ten Sponzas, the same clipmap (a fitted 128^3 grid on them would have voxels of 1.6 m);
and prints the relative RMSE and mean-luminance ratio of each against the others, for the indirect
term and for the whole image (../shared/tools/compare.py), with each run's voxel grid.

usage: scripts/sponza-10x.py [BUILD_DIR] [SHARED_DIR] [OUT_DIR] [LEVELS] [--validate]
--validate: every render with the Khronos validation layer (the ctest sponza_10x passes it)
"""
import json
import os
import shutil
import subprocess
import sys

import OpenImageIO as oiio

args = [a for a in sys.argv[1:] if a != "--validate"]
build = args[0] if len(args) > 0 else "build"
shared = os.path.abspath(args[1] if len(args) > 1 else "../shared")
out = args[2] if len(args) > 2 else "out/sponza-10x"
levels = args[3] if len(args) > 3 else "4"
os.makedirs(out, exist_ok=True)
source_dir = os.path.join(shared, "scenes/crytek-sponza")
source = os.path.join(source_dir, "sponza-sun.gltf")
compare = os.path.join(shared, "tools/compare.py")

with open(source) as f:
    g = json.load(f)
# dvsgi reads only files inside a scene's folder (symbolic links resolved): hard-link the buffer and
# the textures in, or copy them where the folders lie on different file systems (out/ only; never
# committed).
files = [b["uri"] for b in g["buffers"]] + [im["uri"] for im in g.get("images", [])]
for name in files:
    dst = os.path.join(out, name)
    if os.path.exists(dst):
        continue
    os.makedirs(os.path.dirname(dst) or ".", exist_ok=True)
    try:
        os.link(os.path.join(source_dir, name), dst)
    except OSError:
        shutil.copyfile(os.path.join(source_dir, name), dst)
spacing = (60.0, 40.0)  # x, z: Sponza spans 37.2 m x 22.9 m
mesh_node = next(i for i, n in enumerate(g["nodes"]) if "mesh" in n)
for i in range(5):
    for j in range(2):
        if i == 0 and j == 0:
            continue
        g["nodes"].append({"name": "sponza-%d-%d" % (i, j), "mesh": g["nodes"][mesh_node]["mesh"],
                           "translation": [spacing[0] * i, 0.0, spacing[1] * j]})
        g["scenes"][g.get("scene", 0)]["nodes"].append(len(g["nodes"]) - 1)
big = os.path.join(out, "sponza-10x.gltf")
with open(big, "w") as f:
    json.dump(g, f)

# The fitted 128^3 grid's voxel on one Sponza: its longest side plus 9 voxels of margin, over 128.
voxel = "%.6f" % ((17.999 + 19.209) / (128 - 9))
common = ["--width", "320", "--height", "180", "--voxels", "128", "--shadow-map", "4096"]
if "--validate" in sys.argv:
    common.append("--validate")
runs = [
    ("one Sponza, fitted 128^3", "one-fitted", source, []),
    ("one Sponza, clipmap", "one-clipmap", source, ["--clipmap", levels, "--clipmap-voxel", voxel]),
    ("ten Sponzas, clipmap", "ten-clipmap", big, ["--clipmap", levels, "--clipmap-voxel", voxel]),
]
for label, name, scene, extra in runs:
    p = subprocess.run([os.path.join(build, "dvsgi"), "render", scene, *common, *extra,
                        "--out", os.path.join(out, name + "-full.exr"), "--aov", os.path.join(out, name + "-aov.exr")],
                       check=True, capture_output=True, text=True)
    grid = [l for l in p.stdout.splitlines() if l.startswith("voxel grid") or l.startswith("voxel clipmap")]
    print("%s: %s" % (label, " | ".join(grid)))
    # The indirect term of the same frame, as an RGB EXR for compare.py.
    aov = oiio.ImageBuf(os.path.join(out, name + "-aov.exr"))
    names = aov.spec().channelnames
    rgb = [names.index("indirect." + c) for c in "RGB"]
    oiio.ImageBufAlgo.channels(aov, tuple(rgb), ("R", "G", "B")).write(os.path.join(out, name + ".exr"))


def metrics(a, b):
    js = os.path.join(out, "%s-vs-%s.json" % (a, b))
    subprocess.run([sys.executable, compare, os.path.join(out, a + ".exr"), os.path.join(out, b + ".exr"),
                    "--json", js, "--panel-png", os.path.join(out, "%s-vs-%s.png" % (a, b))],
                   check=True, stdout=subprocess.DEVNULL)
    with open(js) as f:
        return json.load(f)


print("| candidate | reference | indirect term: relative RMSE | mean luminance ratio | "
      "whole image: relative RMSE | mean luminance ratio |")
print("|---|---|---|---|---|---|")
for a, b in [("ten-clipmap", "one-clipmap"), ("ten-clipmap", "one-fitted"), ("one-clipmap", "one-fitted")]:
    m, f = metrics(a, b), metrics(a + "-full", b + "-full")
    print("| %s | %s | %.3f | %.3f | %.3f | %.3f |" % (a, b, m["rel_rmse"], m["mean_lum_ratio"],
                                                      f["rel_rmse"], f["mean_lum_ratio"]))
