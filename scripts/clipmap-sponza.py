#!/usr/bin/env python3
"""Sponza's indirect term with a camera-following clipmap against fitted grids.

Renders the indirect term of sponza-sun from its own camera with fitted grids
of 64^3 (rays, the default, and cones) and 128^3 and with --clipmap 3 of 64^3 (level 0's voxels are half the
fitted 64^3's, the coarsest level spans twice the scene), compares each with
the fitted 128^3 (../shared/tools/compare.py) and prints a markdown table with
each run's GPU time and voxel memory (from --metrics). docs/clipmap.md shows
the table and the panel this writes.

usage: scripts/clipmap-sponza.py [BUILD_DIR] [SHARED_DIR] [OUT_DIR]
"""
import json
import os
import subprocess
import sys

build = sys.argv[1] if len(sys.argv) > 1 else "build"
shared = sys.argv[2] if len(sys.argv) > 2 else "../shared"
out = sys.argv[3] if len(sys.argv) > 3 else "out/clipmap"
os.makedirs(out, exist_ok=True)
scene = os.path.join(shared, "scenes/crytek-sponza/sponza-sun.gltf")
compare = os.path.join(shared, "tools/compare.py")
common = ["--width", "320", "--height", "180", "--output", "indirect", "--quiet"]
runs = [
    ("fitted 128^3", "fit128", ["--voxels", "128"]),
    ("fitted 64^3", "fit64", ["--voxels", "64"]),
    # A clipmap traces cones (bounce and gather): the fitted 64^3 grid again
    # with cones, like for like.
    ("fitted 64^3, cones", "fit64cones", ["--voxels", "64", "--bounce-trace", "cones", "--gather-trace", "cones"]),
    ("clipmap 3 x 64^3", "clip3x64", ["--voxels", "64", "--clipmap", "3"]),
]

rows = []
for label, name, extra in runs:
    exr = os.path.join(out, name + ".exr")
    metrics = os.path.join(out, name + ".json")
    subprocess.run([os.path.join(build, "dvsgi"), "render", scene, *common, *extra, "--out", exr,
                    "--metrics", metrics], check=True)
    with open(metrics) as f:
        m = json.load(f)
    voxel_mib = sum(b for n, b in m["memory_bytes"].items()
                    if "voxel" in n or "directional" in n or "clipmap" in n) / 2**20
    rows.append((label, name, exr, m["gpu_ms"], voxel_mib))

reference = rows[0][2]
print("| voxels | relative RMSE vs fitted 128^3 | mean luminance ratio | GPU ms (lavapipe) | voxel memory MiB |")
print("|---|---|---|---|---|")
for label, name, exr, gpu_ms, mib in rows:
    if exr == reference:
        print(f"| {label} | (reference) | 1 | {gpu_ms:.0f} | {mib:.1f} |")
        continue
    js = os.path.join(out, name + "-compare.json")
    panel = os.path.join(out, name + "-panel.png")
    subprocess.run([sys.executable, compare, exr, reference, "--json", js, "--panel-png", panel], check=True,
                   stdout=subprocess.DEVNULL)
    with open(js) as f:
        c = json.load(f)
    print(f"| {label} | {c['rel_rmse']:.3f} | {c['mean_lum_ratio']:.3f} | {gpu_ms:.0f} | {mib:.1f} |")
