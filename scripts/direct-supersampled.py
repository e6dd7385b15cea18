#!/usr/bin/python3
"""dvsgi's direct light on the Cycles scenes, supersampled, against Cycles' direct-only renders.

    scripts/direct-supersampled.py DVSGI SHARED_DIR [OUT_DIR] [-- extra dvsgi options]

Renders Sponza under the sun, Sponza with a point light and Sibenik (SHARED_DIR/scenes) at 4 x 4
the references' 320x180 with `--bounces 0 --output direct`, box-averages each 4 x 4 block into one
pixel and compares with docs/quality/cycles/NAME-b0.exr (pixels are area averages there). At the
references' own size a shadow edge falls on a pixel's centre or beside it, and that sampling moves
single pixels by 50 %; supersampled, what is left is where the shadows are. Prints a Markdown table:
the summed absolute difference over the reference's summed luminance, and the mean-luminance ratio.
About a minute on lavapipe.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

SCENES = ["crytek-sponza/sponza-sun", "crytek-sponza/sponza-point", "sibenik/sibenik-point"]
WIDTH, HEIGHT, SCALE = 320, 180, 4
LUMA = np.array([0.2126, 0.7152, 0.0722])


def luminance(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit("direct-supersampled: %s: %s" % (path, buf.geterror()))
    return np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)[:, :, :3] @ LUMA


args = sys.argv[1:]
extra = []
if "--" in args:
    extra = args[args.index("--") + 1:]
    args = args[:args.index("--")]
if len(args) not in (2, 3):
    sys.exit("usage: direct-supersampled.py DVSGI SHARED_DIR [OUT_DIR] [-- dvsgi options]")
dvsgi, shared = args[0], args[1]
out = args[2] if len(args) == 3 else tempfile.mkdtemp(prefix="dvsgi-direct-ss-")
os.makedirs(out, exist_ok=True)
refs = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "quality", "cycles")
print("| scene (direct light, %dx%d from %dx%d) | sum abs difference / sum | mean luminance / Cycles |" %
      (WIDTH, HEIGHT, WIDTH * SCALE, HEIGHT * SCALE))
print("|---|---|---|")
for s in SCENES:
    name = os.path.basename(s)
    scene = os.path.join(shared, "scenes", s + ".gltf")
    if not os.path.exists(scene):
        sys.exit("direct-supersampled: %s not found" % scene)
    exr = os.path.join(out, name + ".exr")
    subprocess.run([dvsgi, "render", scene, "--width", str(WIDTH * SCALE), "--height", str(HEIGHT * SCALE),
                    "--voxels", "128", "--bounces", "0", "--output", "direct", "--png", "none", "--quiet",
                    "--out", exr, *extra], check=True, timeout=600)
    fine = luminance(exr)
    mine = fine.reshape(HEIGHT, SCALE, WIDTH, SCALE).mean(axis=(1, 3))
    ref = luminance(os.path.join(refs, name + "-b0.exr"))
    print("| %s | %.4f | %.4f |" % (name, np.abs(mine - ref).sum() / ref.sum(), mine.mean() / ref.mean()))
