#!/usr/bin/python3
"""The slab of scripts/slab-scene.py in dvsgi against the CPU path tracer, beside each of its faces:
renders `dvsgi render SLAB.gltf --width 96 --height 96 --voxels 64 --voxel-box=-2,-2,-2,2,2,2
--bounces 2 --output indirect --trace-scale 1` and traces the same scene's first three bounces
(scripts/bounce-reference.py, 1024 samples per pixel; dvsgi's --bounces 2 is the pixel gather plus two
voxel bounces), then prints the mean indirect luminance of the ground 1-3 and 4-8 voxels from each face. Traces
already in OUT_DIR (they depend only on the offset) are re-used.

    scripts/slab-compare.py path/to/dvsgi OUT_DIR OFFSET [OFFSET...] [--bounces K]

--bounces K: dvsgi's voxel bounces (default 2), against the first K + 1 traced bounces (0: the pixel
gather over the voxels' direct light against the traced first bounce alone).
"""
import math
import os
import subprocess
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "shared", "tools"))
import compare  # noqa: E402  (../shared/tools: the project's EXR reader)

LUM = np.array([0.2126, 0.7152, 0.0722])
VOXEL, SIZE = 4.0 / 64, 96
args = sys.argv[1:]
bounces = 2
if "--bounces" in args:
    at = args.index("--bounces")
    bounces = int(args[at + 1])
    del args[at:at + 2]
dvsgi, out = args[0], args[1]
print("| offset | ground beside the shadowed face, 1-3 / 4-8 voxels: traced, dvsgi | beside the sunlit face: traced, dvsgi |")
print("|---|---|---|")
for offset in [float(a) for a in args[2:]]:
    d = os.path.join(out, "slab-%.2f" % offset)
    os.makedirs(d, exist_ok=True)
    scene = os.path.join(d, "slab.gltf")
    subprocess.run([sys.executable, os.path.join(here, "slab-scene.py"), scene, str(offset)], check=True)
    subprocess.run([dvsgi, "render", scene, "--width", str(SIZE), "--height", str(SIZE), "--voxels", "64",
                    "--voxel-box=-2,-2,-2,2,2,2", "--bounces", str(bounces), "--output", "indirect", "--trace-scale", "1",
                    "--out", os.path.join(d, "dvsgi.exr"), "--png", "none", "--quiet"], check=True)
    # The trace takes minutes and depends only on the offset: kept and re-used.
    traced = [os.path.join(d, "ref-bounce%d.npy" % k) for k in range(1, bounces + 2)]
    if not all(os.path.exists(f) for f in traced):
        subprocess.run([sys.executable, os.path.join(here, "bounce-reference.py"), scene, os.path.join(d, "ref"),
                        "--size", str(SIZE), "--spp", "1024", "--bounces", str(bounces + 1)], check=True,
                       stdout=subprocess.DEVNULL)
    ref = sum(np.load(os.path.join(d, "ref-bounce%d.npy" % k)) for k in range(1, bounces + 2)) @ LUM
    dv = compare.read_rgb(os.path.join(d, "dvsgi.exr")) @ LUM
    # The camera looks straight down from 3 m with a 50 degree field: ground x of each column.
    half = math.tan(math.radians(25.0)) * 3.0
    coord = (np.arange(SIZE) + 0.5 - SIZE / 2) / (SIZE / 2) * half
    x0, x1 = offset * VOXEL, (offset + 0.7) * VOXEL
    rows = np.abs(coord) < 0.8

    def band(img, lo, hi, shadowed):
        dist = (x0 - coord) / VOXEL if shadowed else (coord - x1) / VOXEL
        cols = (dist >= lo) & (dist < hi)
        return float(img[np.ix_(rows, cols)].mean())

    cells = []
    for shadowed in (True, False):
        cells.append(" / ".join("%.4f, %.4f" % (band(ref, lo, hi, shadowed), band(dv, lo, hi, shadowed))
                                for lo, hi in ((1, 3), (4, 8))))
    print("| %.2f | %s | %s |" % (offset, cells[0], cells[1]))
