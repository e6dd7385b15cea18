#!/usr/bin/python3
"""Tables of docs/quality.md from the quality renders of scripts/gpu-check.sh
(its OUT/quality folder): the Cornell scenes at 512x512 with 128^3 voxels
against the references, and the mean indirect luminance of cornell-lights at
64^3, 128^3, 256^3 and with beta = 1.
Usage: scripts/gpu-quality-table.py OUT/quality [SHARED_DIR]"""
import json
import os
import sys

folder = sys.argv[1]
shared = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "../../shared")
sys.path.insert(0, os.path.join(shared, "tools"))
import compare  # noqa: E402  (shared/tools/compare.py: the metric definitions)

print("| scene (512², 128³) | gather | bounces | relative RMSE | mean-luminance ratio | within 10 % | GPU ms |")
print("|---|---|---|---|---|---|---|")
for scene in ("cornell-lights", "cornell-emissive"):
    ref = compare.read_rgb(os.path.join(shared, "reference/cornell-box/%s.exr" % scene))
    for suffix, gather in (("128", "rays"), ("128-cones", "six cones")):
        m, _, _ = compare.compare(compare.read_rgb(os.path.join(folder, "%s-%s.exr" % (scene, suffix))), ref)
        j = json.load(open(os.path.join(folder, "%s-%s.json" % (scene, suffix))))
        b = j["bounces"]
        print("| %s | %s | %d%s | %.3f | %.3f | %.2f | %.1f |" % (
            scene, gather, b["first_frame"], " (converged)" if b["converged"] else "", m["rel_rmse"],
            m["mean_lum_ratio"], m["frac_within_tol"], j["gpu_ms"]))
print()
print("| cornell-lights, indirect term (512²) | 64³ | 128³ | 256³ | 128³, β = 1 |")
print("|---|---|---|---|---|")
lum = [json.load(open(os.path.join(folder, "indirect-%s.json" % n)))["output_mean_luminance"]
       for n in ("64", "128", "256", "128-beta1")]
print("| mean luminance | " + " | ".join("%.4f" % v for v in lum) + " |")
print("| relative to 128³ | " + " | ".join("%+.1f %%" % (100.0 * (v / lum[1] - 1.0)) for v in lum) + " |")
