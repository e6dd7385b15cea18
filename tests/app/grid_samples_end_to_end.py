#!/usr/bin/python3
"""`dvsgi render --grid-samples K`: the image (and every --aov layer) is the mean of K renders of
the built-in Cornell box whose grids are the fitted one moved by the offsets the metrics JSON
lists, each rendered here on its own with --voxel-box; the renders differ (the grid did move);
combinations that have no single fitted grid under one frame are refused in one line.
Usage: grid_samples_end_to_end.py path/to/dvsgi"""
import json, os, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from e2e import Runner, read, rgb  # noqa: E402

DVSGI = sys.argv[1]
TMP = tempfile.mkdtemp(prefix="dvsgi-grid-samples-")
N = 32
R = Runner(DVSGI, ["render", "--width", "48", "--height", "48", "--voxels", str(N), "--png", "none", "--quiet",
                   "--validate"])
run, render, check = R.run, R.render, R.check


def rel_rmse(a, b):
    return float(np.sqrt(np.mean((a - b) ** 2)) / max(np.sqrt(np.mean(b ** 2)), 1e-30))


K = 3
out, aov, metrics = (os.path.join(TMP, n) for n in ("mean.exr", "mean-aov.exr", "mean.json"))
render("--grid-samples %d" % K, "--grid-samples", str(K), "--out", out, "--aov", aov, "--metrics", metrics)
m = json.load(open(metrics))
offsets = m.get("grid_sample_offsets", [])
check(len(offsets) == K, "metrics list %d offsets: %s" % (K, offsets))
check(offsets and offsets[0] == [0.0, 0.0, 0.0], "the first render is on the fitted grid")
check(all(0.0 <= v < 1.0 for d in offsets for v in d), "offsets lie within a voxel")
check(len({tuple(d) for d in offsets}) == len(offsets), "offsets differ")
origin, size = m["voxels"]["origin"], m["voxels"]["voxel_size"]

images, layers = [], []
for k, d in enumerate(offsets):
    lo = [o + v * size for o, v in zip(origin, d)]
    box = ",".join("%.9g" % v for v in lo + [v + N * size for v in lo])
    one, one_aov = os.path.join(TMP, "k%d.exr" % k), os.path.join(TMP, "k%d-aov.exr" % k)
    render("render %d on its own grid" % k, "--voxel-box=" + box, "--out", one, "--aov", one_aov)
    images.append(rgb(read(one)[0]))
    layers.append(read(one_aov)[0])

# Float atomics in the voxelization may add in another order from process to
# process: images agree to the suite's usual image tolerance, not bit for bit.
mean = sum(images) / K
got = rgb(read(out)[0])
check(rel_rmse(got, mean) < 1e-4, "--out is the mean of the %d renders (relative RMSE %.3g)" % (K, rel_rmse(got, mean)))
ch = read(aov)[0]
for layer in ("direct", "indirect", "specular"):
    want = sum(rgb(l, layer) for l in layers) / K
    check(rel_rmse(rgb(ch, layer), want) < 1e-4, "--aov layer %s is their mean" % layer)
spread = max(rel_rmse(rgb(l, "indirect"), rgb(layers[0], "indirect")) for l in layers[1:])
check(spread > 1e-3, "the renders differ: indirect light %.3g apart (relative RMSE)" % spread)

for extra, what in ((["--frames", "2"], "--frames"), (["--clipmap", "2"], "--clipmap"), (["--voxels", "0"], "--voxels 0"),
                    (["--voxelizer", "pv"], "--voxelizer pv"), (["--view", "voxels:albedo"], "--view voxels")):
    rc, err = run("--grid-samples", "2", *extra, "--out", os.path.join(TMP, "refused.exr"))
    lines = err.strip().splitlines()
    check(rc != 0 and len(lines) == 1 and "--grid-samples" in lines[0],
          "with %s refused in one line (rc=%d): %s" % (what, rc, err.strip()))

R.finish()
