#!/usr/bin/python3
"""Mean-luminance ratio of a render to a reference of any size (shared/reference/CONVENTIONS.md
pixels are area averages, so the mean does not depend on the size).

    scripts/lum-ratio.py RENDER.exr REFERENCE.exr
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


if len(sys.argv) != 3:
    print("usage: lum-ratio.py RENDER.exr REFERENCE.exr", file=sys.stderr)
    sys.exit(2)
print("%.4f" % (luminance(sys.argv[1]).mean() / luminance(sys.argv[2]).mean()))
