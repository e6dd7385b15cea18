#!/usr/bin/env python3
"""Sanitizer run: `dvsgi render` of the built-in Cornell box (32x32, 32^3
voxels, validation on). A sanitizer report ends the process with a non-zero
status, a validation error with status 3; besides the status this checks that
the image exists and holds finite, non-negative radiance with some light in it.

    render_check.py DVSGI WORKDIR"""

import os
import shutil
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio


def main():
    binary, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "cornell.exr")
    argv = [binary, "render", "--width", "32", "--height", "32", "--voxels", "32", "--shadow-map", "256",
            "--validate", "--out", out, "--png", "none"]
    proc = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    sys.stdout.write(proc.stdout.decode("utf-8", "replace"))
    sys.stderr.write(proc.stderr.decode("utf-8", "replace"))
    if proc.returncode != 0:
        sys.exit("render_check: dvsgi exited %d" % proc.returncode)
    inp = oiio.ImageInput.open(out)
    if not inp:
        sys.exit("render_check: cannot read %s: %s" % (out, oiio.geterror()))
    pixels = np.asarray(inp.read_image("float"))
    inp.close()
    if pixels.shape[:2] != (32, 32):
        sys.exit("render_check: image is %s, expected 32x32" % (pixels.shape,))
    if not np.all(np.isfinite(pixels)) or np.any(pixels < 0):
        sys.exit("render_check: non-finite or negative radiance")
    if float(pixels[..., :3].mean()) <= 0.0:
        sys.exit("render_check: the image is black")
    print("render_check: ok, mean radiance %.4g" % float(pixels[..., :3].mean()))


if __name__ == "__main__":
    main()
