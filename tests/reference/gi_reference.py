#!/usr/bin/python3
"""Full global illumination of both Cornell glTF scenes (256x256, 64^3 voxels,
the default settings: converged bounces, emitters as area lights) against the
path-traced references (512x512, averaged over 2x2 blocks), with the project's
metric definitions (shared/tools/compare.py). The bounds are 1.5 times the
measured errors recorded in docs/quality.md (scripts/quality.sh). Issue #15
item 1's own case, cornell-lights after exactly 32 bounces, must also lie
within +-3 % of the reference's mean luminance.
Usage: gi_reference.py path/to/dvsgi path/to/shared [out.json]"""
import json, os, subprocess, sys, tempfile
import numpy as np
import OpenImageIO as oiio

dvsgi, shared = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(shared, "tools"))
if not os.path.isdir(os.path.join(shared, "reference/cornell-box")):
    print("FAIL: shared references not found under %s" % shared)
    sys.exit(1)
import compare  # noqa: E402  (shared/tools/compare.py: the metric definitions)

# Measured (docs/quality.md): relative RMSE and mean-luminance ratio with the
# defaults (rays for the voxel bounce and the per-pixel gather), with the
# gather's six cones, and with the paper's six cones for both; the test allows
# 1.5 times the measured RMSE and luminance error.
ITEM1 = ["--bounces", "32"]  # issue #15 item 1's own case, also held to its +-3 %
CASES = [("cornell-lights", [], 0.0455, 1.0131),
         ("cornell-lights", ITEM1, 0.0460, 1.0148),
         ("cornell-emissive", [], 0.1519, 0.9813),
         ("cornell-lights", ["--edge-voxels", "faces"], 0.0447, 1.0112),
         ("cornell-emissive", ["--edge-voxels", "faces"], 0.1517, 0.9817),
         ("cornell-lights", ["--gather-trace", "cones"], 0.0942, 1.0053),
         ("cornell-emissive", ["--gather-trace", "cones"], 0.1530, 0.9770),
         ("cornell-lights", ["--gather-trace", "cones", "--bounce-trace", "cones"], 0.1256, 0.9184),
         ("cornell-emissive", ["--gather-trace", "cones", "--bounce-trace", "cones"], 0.1559, 0.9074)]
tmp = tempfile.mkdtemp(prefix="dvsgi-gi-")
results, failures = {}, []
for name, extra, rmse, lum in CASES:
    scene = os.path.join(shared, "scenes/cornell-box/%s.gltf" % name)
    out = os.path.join(tmp, name + ".exr")
    subprocess.run([dvsgi, "render", scene, "--width", "256", "--height", "256", "--voxels", "64", "--out", out,
                    "--png", "none", "--quiet", "--validate", *extra], check=True, timeout=600)
    cand = compare.read_rgb(out)
    ref = compare.read_rgb(os.path.join(shared, "reference/cornell-box/%s.exr" % name))
    ref = ref.reshape(256, 2, 256, 2, 3).mean(axis=(1, 3))
    m, _, _ = compare.compare(cand, ref)
    label = " ".join([name, *extra])
    results[label] = {k: m[k] for k in ("rel_rmse", "rel_rmse_pixel", "mean_lum_ratio", "frac_within_tol")}
    results[label]["options"] = extra
    print("%-38s rel_rmse %.4f  mean_lum_ratio %.4f  rel_rmse_pixel %.4f  within10%% %.3f" %
          (label, m["rel_rmse"], m["mean_lum_ratio"], m["rel_rmse_pixel"], m["frac_within_tol"]))
    if not m["rel_rmse"] <= 1.5 * rmse:
        failures.append("%s: relative RMSE %.4f > %.4f" % (label, m["rel_rmse"], 1.5 * rmse))
    if not abs(m["mean_lum_ratio"] - 1.0) <= 1.5 * abs(lum - 1.0):
        failures.append("%s: mean luminance ratio %.4f beyond +-%.4f" % (label, m["mean_lum_ratio"],
                                                                         1.5 * abs(lum - 1.0)))
    if extra == ITEM1 and not abs(m["mean_lum_ratio"] - 1.0) <= 0.03:
        failures.append("%s: mean luminance ratio %.4f beyond item 1's +-3 %%" % (label, m["mean_lum_ratio"]))
if len(sys.argv) > 3:
    json.dump(results, open(sys.argv[3], "w"), indent=2)
print("\n".join("FAIL " + f for f in failures))
checks = 2 * len(CASES) + sum(extra == ITEM1 for _, extra, _, _ in CASES)
print("%d passed, %d failed" % (checks - len(failures), len(failures)))
sys.exit(1 if failures else 0)
