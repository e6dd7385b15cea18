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
import sys

import numpy as np
import OpenImageIO as oiio

LUM = np.array([0.2126, 0.7152, 0.0722])


def fail(msg):
    print("bounce-by-facing: " + msg, file=sys.stderr)
    sys.exit(1)


def read(path):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        fail("%s: cannot open (%s)" % (path, oiio.geterror()))
    names = list(inp.spec().channelnames)
    pixels = np.asarray(inp.read_image(format="float"), dtype=np.float64)
    inp.close()
    return pixels, names


def layer(pixels, names, path, name, suffixes):
    wanted = [name + "." + c for c in suffixes]
    if not all(w in names for w in wanted):
        fail("%s: no %s layer (write it with dvsgi render --aov)" % (path, name))
    return pixels[..., [names.index(w) for w in wanted]]


def main():
    if len(sys.argv) != 3:
        fail("usage: scripts/bounce-by-facing.py REF_PREFIX FIRST_BOUNCE_AOV.exr")
    prefix, aov_path = sys.argv[1], sys.argv[2]
    b0, _ = read(prefix + "-b0.exr")
    b1, _ = read(prefix + "-b1.exr")
    aov, names = read(aov_path)
    if b0.shape[:2] != aov.shape[:2] or b1.shape[:2] != aov.shape[:2]:
        fail("%s: %dx%d, the references %dx%d" % (aov_path, aov.shape[1], aov.shape[0], b0.shape[1], b0.shape[0]))
    first_ref = (b1[..., :3] - b0[..., :3]) @ LUM
    first = layer(aov, names, aov_path, "indirect", "RGB") @ LUM
    normal = layer(aov, names, aov_path, "normal", "XYZ")
    axis = np.argmax(np.abs(normal), axis=-1)
    sign = np.sign(np.take_along_axis(normal, axis[..., None], -1)[..., 0])
    total = first_ref.sum()
    if total <= 0.0:
        fail("%s: the references' first bounce is empty" % prefix)
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
