#!/usr/bin/python3
"""How much a render's figures move with where the voxel lattice falls on the scene.

    scripts/grid-placement.py DVSGI SCENE (--reference REF.exr | --cycles PREFIX)
                              [--voxels N] [--width W] [--height H] [--shifts D0,D1,...]
                              [--out DIR] [-- extra dvsgi render options]

The grid dvsgi fits to SCENE (origin and voxel edge from `--metrics`) is moved by each
shift D (in voxels, along all three axes) with `--voxel-box`, and the scene rendered
again; nothing else changes, so what moves is the error of sampling the scene with a
lattice. --reference: the mean-luminance ratio of each render to REF.exr. --cycles: each
render and its `--bounces 0` twin against the Cycles renders PREFIX.exr, PREFIX-b0.exr and
PREFIX-b1.exr (scripts/scene-compare.py): indirect light, first bounce and later bounces.
Prints one markdown table, a row per shift, then the mean and the range. Shifts default
to 0,0.2,0.4,0.6,0.8 (0 is the fitted grid); renders go to DIR (default out/grid-placement).
"""
import json
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
LUM = np.array([0.2126, 0.7152, 0.0722])


def fail(msg):
    print("grid-placement: " + msg, file=sys.stderr)
    sys.exit(1)


def mean_luminance(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        fail("%s: %s" % (path, buf.geterror()))
    return float((np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)[:, :, :3] @ LUM).mean())


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        fail("%s failed (%d): %s" % (" ".join(cmd[:3]), r.returncode, r.stderr.strip()))
    return r.stdout


def parse(argv):
    extra = []
    if "--" in argv:
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1:]
    opts = {"--voxels": "128", "--width": "320", "--height": "180", "--shifts": "0,0.2,0.4,0.6,0.8",
            "--out": "out/grid-placement", "--reference": None, "--cycles": None}
    pos = []
    i = 0
    while i < len(argv):
        if argv[i] in opts:
            if i + 1 >= len(argv):
                fail("%s needs a value" % argv[i])
            opts[argv[i]] = argv[i + 1]
            i += 2
        elif argv[i].startswith("--"):
            fail("unknown option %s (dvsgi's own options go after --)" % argv[i])
        else:
            pos.append(argv[i])
            i += 1
    if len(pos) != 2 or (opts["--reference"] is None) == (opts["--cycles"] is None):
        fail("usage: grid-placement.py DVSGI SCENE (--reference REF.exr | --cycles PREFIX) [--voxels N] "
             "[--width W] [--height H] [--shifts D0,D1,...] [--out DIR] [-- dvsgi options]")
    try:
        shifts = [float(s) for s in opts["--shifts"].split(",")]
    except ValueError:
        fail("--shifts: not a comma-separated list of numbers: %s" % opts["--shifts"])
    return pos[0], pos[1], opts, shifts, extra


def main(argv):
    dvsgi, scene, opts, shifts, extra = parse(argv)
    out = opts["--out"]
    os.makedirs(out, exist_ok=True)
    n = int(opts["--voxels"])
    base = [dvsgi, "render", scene, "--voxels", str(n), "--png", "none", "--quiet"] + extra
    fit = os.path.join(out, "fit.json")
    run(base + ["--width", "16", "--height", "16", "--bounces", "0", "--out", os.path.join(out, "fit.exr"),
                "--metrics", fit])
    grid = json.load(open(fit))["voxels"]
    origin, size = grid["origin"], grid["voxel_size"]
    size_opts = ["--width", opts["--width"], "--height", opts["--height"]]
    columns = ["mean luminance / reference"] if opts["--reference"] else ["indirect", "first bounce", "later bounces"]
    rows = []
    for d in shifts:
        lo = [o + d * size for o in origin]
        box = ",".join("%.7g" % v for v in lo + [v + n * size for v in lo])
        tag = os.path.join(out, "shift%g" % d)
        placed = base + size_opts + ["--voxel-box=" + box]
        if opts["--reference"]:
            run(placed + ["--out", tag + ".exr"])
            rows.append([mean_luminance(tag + ".exr") / mean_luminance(opts["--reference"])])
        else:
            run(placed + ["--out", tag + ".exr", "--aov", tag + "-aov.exr"])
            run(placed + ["--bounces", "0", "--out", tag + "-first.exr", "--aov", tag + "-first-aov.exr"])
            run(["/usr/bin/python3", os.path.join(HERE, "scene-compare.py"), opts["--cycles"], tag + "-aov.exr",
                 tag + "-first-aov.exr", "--json", tag + ".json"])
            r = json.load(open(tag + ".json"))
            rows.append([r["indirect"], r["first"], r["later"]])
    print("<!-- scripts/grid-placement.py %s %s %s -- %s -->" % (
        os.path.basename(dvsgi), scene, " ".join("%s %s" % (k, v) for k, v in opts.items() if v is not None),
        " ".join(extra)))
    print("| shift (voxels; 0 = fitted), %s³ | %s |" % (n, " | ".join(columns)))
    print("|---|" + "---|" * len(columns))
    for d, r in zip(shifts, rows):
        print("| %g | %s |" % (d, " | ".join("%.3f" % v for v in r)))
    a = np.array(rows)
    print("| mean | %s |" % " | ".join("%.3f" % v for v in a.mean(axis=0)))
    print("| range | %s |" % " | ".join("%.3f–%.3f" % (lo, hi) for lo, hi in zip(a.min(axis=0), a.max(axis=0))))


main(sys.argv[1:])
