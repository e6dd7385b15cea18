#!/usr/bin/python3
"""Issue #10 part 4 end to end: `cmake --install` this build into a temporary
prefix, configure and build examples/embed against it with find_package(dvsgi),
run it, render the same frame with `dvsgi render`, and require the two EXRs to
agree to a relative RMSE below 1e-4.
Usage: embed_install.py CMAKE BUILD_DIR EMBED_SOURCE DVSGI GENERATOR CXX"""
import os, shutil, subprocess, sys, tempfile

import numpy as np
import OpenImageIO as oiio

CMAKE, BUILD, EMBED_SRC, DVSGI, GENERATOR, CXX = sys.argv[1:7]
TMP = tempfile.mkdtemp(prefix="dvsgi-embed-")
PREFIX = os.path.join(TMP, "prefix")
failures = []


def run(name, args, timeout=600):
    p = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    print("%-28s rc=%d" % (name, p.returncode))
    if p.returncode != 0:
        print(p.stdout[-4000:], p.stderr[-4000:])
        sys.exit("FAIL %s: %s exited %d" % (name, args[0], p.returncode))
    return p.stdout


def read_rgb(path):
    img = oiio.ImageInput.open(path)
    if img is None:
        sys.exit("FAIL cannot open %s: %s" % (path, oiio.geterror()))
    spec = img.spec()
    px = img.read_image(oiio.FLOAT)
    img.close()
    names = list(spec.channelnames)
    return np.stack([px[:, :, names.index(c)] for c in "RGB"], axis=-1)


run("install", [CMAKE, "--install", BUILD, "--prefix", PREFIX])
for rel in ("include/dvsgi/dvsgi.h", "lib/libdvsgi.a", "lib/cmake/dvsgi/dvsgiConfig.cmake",
            "lib/cmake/dvsgi/dvsgiConfigVersion.cmake", "lib/cmake/dvsgi/dvsgiTargets.cmake", "bin/dvsgi"):
    if not os.path.exists(os.path.join(PREFIX, rel)):
        failures.append("not installed: " + rel)
header = open(os.path.join(PREFIX, "include/dvsgi/dvsgi.h")).read()
if '#include "' in header:
    failures.append("the public header includes internal headers")

build = os.path.join(TMP, "build")
run("configure embed", [CMAKE, "-S", EMBED_SRC, "-B", build, "-G", GENERATOR, "-DCMAKE_BUILD_TYPE=Release",
                        "-DCMAKE_CXX_COMPILER=" + CXX, "-DCMAKE_PREFIX_PATH=" + PREFIX])
run("build embed", [CMAKE, "--build", build])

embed_exr = os.path.join(TMP, "embed.exr")
cli_exr = os.path.join(TMP, "cli.exr")
out = run("run embed", [os.path.join(build, "embed"), "-", embed_exr])
print(out)
if "gbuffer" not in out or "GPU memory" not in out:
    failures.append("embed printed no pass timings or memory")
run("dvsgi render", [DVSGI, "render", "--width", "64", "--height", "64", "--voxels", "32", "--out", cli_exr,
                     "--png", "none", "--quiet"])

a, b = read_rgb(embed_exr), read_rgb(cli_exr)
if a.shape != (64, 64, 3) or b.shape != (64, 64, 3):
    failures.append("sizes: embed %s, dvsgi %s" % (a.shape, b.shape))
else:
    rel = float(np.sqrt(np.mean((a - b) ** 2)) / np.sqrt(np.mean(b ** 2)))
    print("relative RMSE embed vs dvsgi render: %.3g (mean radiance %.4f)" % (rel, float(b.mean())))
    if not np.isfinite(a).all() or b.mean() <= 0.0:
        failures.append("image not finite or black")
    if not rel < 1e-4:
        failures.append("relative RMSE %.3g >= 1e-4" % rel)

for f in failures:
    print("FAIL " + f)
if not failures:
    shutil.rmtree(TMP, ignore_errors=True)
print("%s" % ("passed" if not failures else "failed"))
sys.exit(1 if failures else 0)
