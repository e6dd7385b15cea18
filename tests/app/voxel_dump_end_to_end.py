#!/usr/bin/python3
"""`dvsgi render --voxel-dump`: the table holds the fitted grid's voxels where the metrics JSON puts
the grid, with unit normals, no reflected light before a bounce and some after one; and the voxels'
own light agrees with a tracer (scripts/voxel-truth.py on the shared cornell-lights.gltf, which the
built-in scene is): their direct light and the light one voxel bounce adds, summed over 4000 voxels,
within 3 % and 4 % of the traced sums (measured 1.008 and 1.021 at 64^3 with 64 points per voxel;
seeds 2-4 give 1.000-1.005 and 0.996-1.014, all 18 500 voxels 1.002 and 1.007-1.015). Bad requests
are refused in one line.
Usage: voxel_dump_end_to_end.py path/to/dvsgi path/to/scripts path/to/shared"""
import json, os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from e2e import Runner  # noqa: E402

DVSGI, SCRIPTS, SHARED = sys.argv[1], sys.argv[2], sys.argv[3]
scene = os.path.join(SHARED, "scenes/cornell-box/cornell-lights.gltf")
if not os.path.isfile(scene):
    sys.exit("FAIL %s not found (the shared folder is needed)" % scene)
TMP = tempfile.mkdtemp(prefix="dvsgi-voxel-dump-")
R = Runner(DVSGI, ["render", "--width", "64", "--height", "64", "--voxels", "64", "--png", "none", "--quiet",
                   "--validate", "--out", os.path.join(TMP, "frame.exr")])
dumps = [os.path.join(TMP, "d%d.npy" % k) for k in (0, 1)]
metrics = os.path.join(TMP, "m.json")
R.render("no bounce", "--bounces", "0", "--voxel-dump", dumps[0], "--metrics", metrics)
R.render("one bounce", "--bounces", "1", "--voxel-dump", dumps[1])
d0, d1 = np.load(dumps[0]), np.load(dumps[1])
grid = json.load(open(metrics))["voxels"]
R.check(d0.dtype == np.float32 and d0.ndim == 2 and d0.shape[1] == 26 and d0.shape[0] > 1000,
        "a float32 table of 26 columns, %d voxels" % d0.shape[0])
R.check(np.isfinite(d0).all() and np.isfinite(d1).all(), "every value finite")
g = d0[:, :3]
R.check(np.array_equal(g, d1[:, :3]) and g.min() >= 0 and g.max() < grid["n"] and
        len(np.unique(g, axis=0)) == len(g), "distinct grid voxels inside the %d^3 grid, the same in both" % grid["n"])
centre = np.array(grid["origin"]) + (g + 0.5) * grid["voxel_size"]
R.check(np.abs(d0[:, 3:6] - centre).max() < 1e-4, "centres where the metrics JSON puts the grid")
length = np.linalg.norm(d0[:, 6:9], axis=1)
R.check(np.all((np.abs(length - 1) < 1e-4) | (length == 0)), "normals unit (or none)")
one = d0[:, 18] == 0
R.check(set(np.unique(d0[:, 18])) <= {0, 1, 2, 3, 4} and one.mean() > 0.9, "side codes 0-4, mostly one-sided")
R.check(np.abs(d0[one, 15:18] - d0[one, 12:15]).max() < 1e-6, "no bounce: one-sided voxels' radiance is their direct light")
R.check(np.all(d0[one, 20:26] == 0), "one-sided voxels: no side light")
# A voxel two-sided along one axis shows the radiance volume its darker side (RGB9E5 sides, half-float radiance).
two = (d1[:, 18] >= 1) & (d1[:, 18] <= 3)
lum = np.array([0.2126, 0.7152, 0.0722])
darker = np.minimum(d1[two, 20:23] @ lum, d1[two, 23:26] @ lum)
R.check(two.sum() > 0 and np.allclose(darker, d1[two, 15:18] @ lum, rtol=0.02, atol=1e-4),
        "%d two-sided voxels: the radiance is the darker side's light" % two.sum())
lit = one & (d1[:, 9:12].max(axis=1) > 0)
gain = (d1[lit, 15:18] - d1[lit, 12:15]).sum(axis=1)
R.check(gain.min() > -1e-3 and (gain > 0).mean() > 0.9, "one bounce adds light to most voxels (%.3f)" % (gain > 0).mean())
R.check(np.all(d0[:, 19] > 0) and np.all((d0[:, 9:12] >= 0) & (d0[:, 9:12] <= 1)), "fragment counts > 0, albedos in [0, 1]")

out = os.path.join(TMP, "truth.json")
p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "voxel-truth.py"), scene, *dumps, "--voxels", "4000", "--spp",
                    "64", "--seed", "1", "--json", out], capture_output=True, text=True, timeout=600)
print(p.stdout + p.stderr)
if p.returncode != 0:
    sys.exit("FAIL voxel-truth.py: rc=%d" % p.returncode)
a = json.load(open(out))["rows"]["all"]
R.check(abs(a["direct"] - 1) <= 0.03, "voxels' direct light %.4f of the traced (within 3 %%)" % a["direct"])
R.check(abs(a["bounce"] - 1) <= 0.04, "voxels' first bounce %.4f of the traced (within 4 %%)" % a["bounce"])

for what, args, expect in [
        ("not .npy", ["--voxel-dump", os.path.join(TMP, "x.txt")], "--voxel-dump: expected a .npy file name"),
        ("no voxels", ["--voxels", "0", "--voxel-dump", dumps[0]], "--voxel-dump: there are no voxels"),
        ("clipmap", ["--clipmap", "2", "--voxel-dump", dumps[0]], "--voxel-dump: writes the fitted grid's voxels"),
        ("grid samples", ["--grid-samples", "2", "--voxel-dump", dumps[0]], "--voxel-dump: writes one render's")]:
    rc, err = R.run(*args)
    R.check(rc != 0 and expect in err and len(err.strip().splitlines()) == 1, "%s: refused in one line (%s)" %
            (what, err.strip()))
small = os.path.join(TMP, "small.npy")
R.render("32^3", "--voxels", "32", "--bounces", "0", "--voxel-dump", small)
p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "voxel-truth.py"), scene, dumps[0], small],
                   capture_output=True, text=True, timeout=120)
R.check(p.returncode == 1 and "different voxels" in p.stderr and len(p.stderr.strip().splitlines()) == 1,
        "voxel-truth.py refuses dumps of different grids in one line (%s)" % p.stderr.strip())
p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "voxel-truth.py"), scene, *dumps, "--bounce", "9"],
                   capture_output=True, text=True, timeout=120)
R.check(p.returncode == 1 and "--bounce 1-4" in p.stderr and len(p.stderr.strip().splitlines()) == 1,
        "voxel-truth.py refuses --bounce 9 in one line (%s)" % p.stderr.strip())
R.finish()
