#!/usr/bin/python3
"""`dvsgi render --aov` and `--exr-type`: the AOV file holds the seven named
layers OpenImageIO groups as layers, each term equals what `--output <term>`
writes, full = direct + indirect + specular, and the G-buffer layers are sane.
Usage: aov_end_to_end.py path/to/dvsgi"""
import os, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from e2e import Runner, read, rgb  # noqa: E402

DVSGI = sys.argv[1]
TMP = tempfile.mkdtemp(prefix="dvsgi-aov-")
BASE = ["render", "--width", "32", "--height", "32", "--voxels", "32", "--png", "none", "--quiet", "--validate"]
R = Runner(DVSGI, BASE)
run, render, check = R.run, R.render, R.check


aov, full = os.path.join(TMP, "aov.exr"), os.path.join(TMP, "full.exr")
render("full + --aov", "--out", full, "--aov", aov)
terms = {}
for term in ("direct", "indirect", "specular", "ao"):
    terms[term] = os.path.join(TMP, term + ".exr")
    render("--output " + term, "--output", term, "--out", terms[term])

ch, fmt = read(aov)
want = {"direct.R", "direct.G", "direct.B", "indirect.R", "indirect.G", "indirect.B", "specular.R", "specular.G",
        "specular.B", "ao.Y", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z"}
check(set(ch) == want, "AOV channels are the seven layers: %s" % sorted(ch))
check(all(f == "float" for f in fmt.values()), "AOV channels are float by default: %s" % set(fmt.values()))
check(ch["depth.Z"].shape == (32, 32), "AOV at output size 32x32")

# Direct light is deterministic, so it must match exactly. The voxel terms come
# from another process whose float-atomic voxelization may add in another
# order: they must agree to the suite's usual image tolerance.
ref = rgb(read(terms["direct"])[0])
check(np.array_equal(rgb(ch, "direct"), ref), "layer direct equals --output direct exactly")
for term in ("indirect", "specular", "ao"):
    ref = read(terms[term])[0]["R"][..., None] if term == "ao" else rgb(read(terms[term])[0])
    got = ch["ao.Y"][..., None] if term == "ao" else rgb(ch, term)
    e = float(np.sqrt(np.mean((got - ref) ** 2)) / max(np.sqrt(np.mean(ref ** 2)), 1e-30))
    check(e < 1e-4, "layer %s equals --output %s (relative RMSE %.3g)" % (term, term, e))
check(bool(((ch["ao.Y"] >= 0) & (ch["ao.Y"] <= 1)).all()), "ao in [0, 1]")

f = rgb(read(full)[0])
parts = rgb(ch, "direct") + rgb(ch, "indirect") + rgb(ch, "specular")
rel = float(np.sqrt(np.mean((parts - f) ** 2)) / np.sqrt(np.mean(f ** 2)))
check(rel < 1e-6, "direct + indirect + specular = --out image (relative RMSE %.3g)" % rel)
check(float(rgb(ch, "indirect").mean()) > 0.0, "indirect light is present (32^3 voxels)")

albedo = rgb(ch, "albedo")
check(bool(((albedo >= 0) & (albedo <= 1)).all()) and float(albedo.mean()) > 0.1, "albedo in [0, 1], not black")
# The Cornell box has a red and a green wall: some pixels are much redder than green and vice versa.
check(bool((albedo[..., 0] > albedo[..., 1] + 0.3).any() and (albedo[..., 1] > albedo[..., 0] + 0.3).any()),
      "albedo shows the red and the green wall")
n = np.stack([ch["normal." + c] for c in "XYZ"], axis=-1)
length = np.linalg.norm(n, axis=-1)
nm = float(np.median(np.abs(length - 1)))
check(nm < 1e-3, "normals are unit length (median |length - 1| %.3g)" % nm)
depth = ch["depth.Z"]
finite = depth[np.isfinite(depth)]
check(finite.size > 0.9 * depth.size and float(finite.min()) > 0 and float(finite.max()) < 100,
      "depth positive metres, geometry in most pixels (%.3f..%.3f)" % (finite.min(), finite.max()))

half = os.path.join(TMP, "half.exr")
render("--exr-type half", "--exr-type", "half", "--out", half)
hch, hfmt = read(half)
check(set(hfmt.values()) == {"half"}, "--exr-type half stores half channels: %s" % hfmt)
hr = rgb(hch)
# One rounding to half moves a value by at most 2^-11 of it (measured 3.35e-4 of the maximum).
hd = float(np.abs(hr - f).max()) / float(np.abs(f).max())
check(hd <= 5e-4, "the half image matches the float one (max difference %.3g of the maximum)" % hd)

# Supersampled: the G-buffer layers are box-averaged from the 2x internal size;
# --exr-type half applies to the AOV file too.
aov2, full2 = os.path.join(TMP, "aov2.exr"), os.path.join(TMP, "full2.exr")
render("--supersample 2 --aov half", "--supersample", "2", "--exr-type", "half", "--out", full2, "--aov", aov2)
ch2, fmt2 = read(aov2)
check(set(ch2) == want and set(fmt2.values()) == {"half"}, "supersampled AOV: seven layers, all half")
check(ch2["depth.Z"].shape == (32, 32), "supersampled AOV at output size 32x32")
f2 = rgb(read(full2)[0])
parts2 = rgb(ch2, "direct") + rgb(ch2, "indirect") + rgb(ch2, "specular")
# Each of the four half-precision images is rounded once: measured 2.58e-4, bound 1.5x.
e2 = float(np.sqrt(np.mean((parts2 - f2) ** 2)) / np.sqrt(np.mean(f2 ** 2)))
check(e2 < 4e-4, "supersampled: direct + indirect + specular = --out within half precision (%.3g)" % e2)
n2 = np.stack([ch2["normal." + c] for c in "XYZ"], axis=-1)
nm2 = float(np.median(np.abs(np.linalg.norm(n2, axis=-1) - 1)))
check(nm2 < 2e-3, "supersampled normals unit length (median |length - 1| %.3g)" % nm2)
# Box-averaged depth against the centre samples' (measured 2.32e-4 apart in the median).
d2 = ch2["depth.Z"][np.isfinite(ch2["depth.Z"])]
dd = abs(float(np.median(d2)) - float(np.median(finite))) / float(np.median(finite)) if d2.size else 1.0
check(d2.size > 0 and dd < 3.5e-4, "supersampled depth agrees with the 1x depth (medians %.3g apart)" % dd)

for name, args, needle in (("bad --exr-type", ["--exr-type", "double"], "--exr-type"),
                           ("--aov not .exr", ["--aov", os.path.join(TMP, "a.png")], "--aov"),
                           ("--aov with a voxel view", ["--aov", aov, "--view", "voxels:albedo"], "--aov")):
    rc, err = run(*args, "--out", os.path.join(TMP, "x.exr"))
    lines = [l for l in err.splitlines() if l.strip()]
    check(rc != 0 and len(lines) == 1 and needle in lines[0], "%s: one line naming %s (%r)" % (name, needle, err))

R.finish()
