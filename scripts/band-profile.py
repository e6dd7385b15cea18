#!/usr/bin/python3
"""Row-by-row mean luminance of renders against a reference over one band of columns.

    scripts/band-profile.py REFERENCE (.exr | .npy) --cols C0:C1 --rows R0:R1 RENDER.exr [RENDER.exr ...]

For each image row R0 <= y < R1, the mean luminance of each render over columns
C0 <= x < C1 divided by the reference's over the same pixels; then each whole
image's mean against the reference's. The reference is an EXR or
scripts/bounce-reference.py's .npy (rows top to bottom, linear RGB). Made to follow
light away from a wall in a view that looks down on the floor beside it, where a
whole-image mean hides what happens within a voxel or two of the wall.
"""
import argparse
import os
import sys

import numpy as np
import OpenImageIO as oiio

LUM = np.array([0.2126, 0.7152, 0.0722])


def fail(msg):
    print("band-profile: " + msg, file=sys.stderr)
    sys.exit(1)


def luminance(path):
    if path.endswith(".npy"):
        if not os.path.isfile(path):
            fail("%s: no such file" % path)
        rgb = np.load(path)
    else:
        buf = oiio.ImageBuf(path)
        if buf.has_error:
            fail("%s: %s" % (path, buf.geterror()))
        rgb = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)
    if rgb.ndim != 3 or rgb.shape[2] < 3:
        fail("%s: expected an RGB image" % path)
    return rgb[:, :, :3].astype(np.float64) @ LUM


def span(text, name, limit):
    try:
        a, b = (int(v) for v in text.split(":"))
    except ValueError:
        fail("%s: expected A:B, got '%s'" % (name, text))
    if not 0 <= a < b <= limit:
        fail("%s: %s lies outside 0:%d or is empty" % (name, text, limit))
    return a, b


parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("reference")
parser.add_argument("renders", nargs="+")
parser.add_argument("--cols", required=True)
parser.add_argument("--rows", required=True)
args = parser.parse_args()

ref = luminance(args.reference)
renders = [luminance(p) for p in args.renders]
for path, img in zip(args.renders, renders):
    if img.shape != ref.shape:
        fail("%s: %dx%d, the reference is %dx%d" % (path, img.shape[1], img.shape[0], ref.shape[1], ref.shape[0]))
c0, c1 = span(args.cols, "--cols", ref.shape[1])
r0, r1 = span(args.rows, "--rows", ref.shape[0])
print("| row | reference | " + " | ".join(os.path.basename(p) for p in args.renders) + " |")
print("|---|---|" + "---|" * len(renders))
for y in range(r0, r1):
    r = ref[y, c0:c1].mean()
    cells = ["%.2f" % (img[y, c0:c1].mean() / r) if r > 0 else "-" for img in renders]
    print("| %d | %.3g | %s |" % (y, r, " | ".join(cells)))
print("| whole image | %.3g | %s |" % (ref.mean(), " | ".join("%.3f" % (img.mean() / ref.mean()) for img in renders)))
