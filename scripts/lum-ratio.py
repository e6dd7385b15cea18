#!/usr/bin/python3
"""Mean-luminance ratio of a render to a reference of any size (shared/reference/CONVENTIONS.md
pixels are area averages, so the mean does not depend on the size).

    scripts/lum-ratio.py RENDER.exr REFERENCE.exr [--noise]

--noise also prints the reference's noise in its mean, relative to it: the per-pixel noise read from
neighbouring pixels' differences (a robust sigma, the median absolute deviation x 1.4826, over sqrt 2),
over the square root of the pixel count. It is what a path-traced reference's mean can be trusted to.
"""
import sys

import numpy as np
import OpenImageIO as oiio


def luminance(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        print("lum-ratio: %s: %s" % (path, buf.geterror()), file=sys.stderr)
        sys.exit(1)
    return np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)[:, :, :3] @ np.array([0.2126, 0.7152, 0.0722])


args = [a for a in sys.argv[1:] if a != "--noise"]
if len(args) != 2 or len(sys.argv) - 1 - len(args) > 1:
    print("usage: lum-ratio.py RENDER.exr REFERENCE.exr [--noise]", file=sys.stderr)
    sys.exit(2)
ref = luminance(args[1])
print("%.4f" % (luminance(args[0]).mean() / ref.mean()))
if "--noise" in sys.argv:
    d = (ref[:, 1:] - ref[:, :-1]) / np.sqrt(2.0)
    sigma = 1.4826 * np.median(np.abs(d - np.median(d)))
    print("reference noise in the mean: %.1e" % (sigma / np.sqrt(ref.size) / ref.mean()))
