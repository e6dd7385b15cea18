#!/usr/bin/python3
"""dvsgi's first bounce against Cycles', split by which way the surface faces.

    scripts/bounce-by-facing.py REF_PREFIX FIRST_BOUNCE_AOV.exr

REF_PREFIX names Cycles renders of the scene (scripts/cycles-reference.py):
REF_PREFIX-b0.exr (direct light only) and REF_PREFIX-b1.exr (direct + one
bounce), whose difference is the first bounce. FIRST_BOUNCE_AOV.exr is dvsgi's
`--aov` of the same view rendered with `--bounces 0`: its indirect term is the
per-pixel gather over the voxels' direct light, the first bounce. Pixels are
grouped by the largest axis of their normal (the AOV's normal layer) and its
sign; each group prints its share of Cycles' first bounce and dvsgi's over
Cycles' (mean-luminance ratio). A scene whose whole-image ratio looks right can
hide floors too bright and ceilings too dark (docs/quality.md, "Thin walls'
ends").
"""
import importlib.util
import os
import sys

import numpy as np

# The EXR reading of scripts/scene-compare.py, whose references these are.
_spec = importlib.util.spec_from_file_location(
    "scene_compare", os.path.join(os.path.dirname(os.path.abspath(__file__)), "scene-compare.py"))
sc = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(sc)


def main():
    if len(sys.argv) != 3:
        sc.fail("usage: scripts/bounce-by-facing.py REF_PREFIX FIRST_BOUNCE_AOV.exr")
    prefix, aov_path = sys.argv[1], sys.argv[2]
    first_ref = sc.luminance(prefix + "-b1.exr") - sc.luminance(prefix + "-b0.exr")
    first = sc.luminance(aov_path, "indirect")
    normal = sc.layer_pixels(aov_path, "normal", "XYZ")
    if first_ref.shape != first.shape:
        sc.fail("%s: %dx%d, the references %dx%d" %
                (aov_path, first.shape[1], first.shape[0], first_ref.shape[1], first_ref.shape[0]))
    axis = np.argmax(np.abs(normal), axis=-1)
    sign = np.sign(np.take_along_axis(normal, axis[..., None], -1)[..., 0])
    total = first_ref.sum()
    if total <= 0.0:
        sc.fail("%s: the references' first bounce is empty" % prefix)
    print("%-8s %8s %12s %10s" % ("facing", "pixels", "share (ref)", "dvsgi/ref"))
    for a in range(3):
        for s in (1.0, -1.0):
            m = (axis == a) & (sign == s)
            if m.sum() == 0 or first_ref[m].sum() <= 0.0:
                continue
            print("%-8s %8d %12.3f %10.3f" % (("+" if s > 0 else "-") + "xyz"[a], m.sum(), first_ref[m].sum() / total,
                                              first[m].sum() / first_ref[m].sum()))
    print("%-8s %8d %12.3f %10.3f" % ("all", first.size, 1.0, first.sum() / total))


main()
