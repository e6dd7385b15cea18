#!/usr/bin/python3
"""Issue #12 item 4: GI with progressive voxelization along a camera path.
Renders the indirect term of every frame of a camera path with the compute
(exact, geometric) voxelizer and with --voxelizer pv (its defaults, and with
256^2 reflective shadow maps), then prints a markdown table of each pv
variant's relative RMSE and mean-luminance ratio against the geometric one
per frame, and draws them as a PNG (linear 0 .. 2; grey lines every 0.25;
blue = pv, orange = pv with reflective shadow maps, solid = relative RMSE,
light = luminance ratio; green dashes at 1). No text: docs/pv.md captions the plot.
Usage: pv-walk.py DVSGI SCENE PATH.json OUT_DIR [--frames F] [--time-step S]
       [--voxels N] [--width W] [--height H]   (needs numpy and ../shared/tools)"""
import argparse, os, subprocess, sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../shared/tools"))
import compare  # noqa: E402  (read_rgb, write_png)
import plot_png  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("dvsgi")
ap.add_argument("scene")
ap.add_argument("path")
ap.add_argument("out")
ap.add_argument("--frames", type=int, default=16)
ap.add_argument("--time-step", type=float, default=0.3)
ap.add_argument("--voxels", type=int, default=128)
ap.add_argument("--width", type=int, default=320)
ap.add_argument("--height", type=int, default=180)
a = ap.parse_args()
os.makedirs(a.out, exist_ok=True)

variants = {"geometric": ["--voxelizer", "compute"], "pv": ["--voxelizer", "pv"],
            "pv-rsm": ["--voxelizer", "pv", "--pv-rsm", "256"]}
for name, extra in variants.items():
    if os.path.exists(os.path.join(a.out, "%s-%04d.exr" % (name, a.frames - 1))):
        continue  # rendered by an earlier run into the same folder
    subprocess.run([a.dvsgi, "render", a.scene, "--camera-path", a.path, "--frames", str(a.frames), "--time-step",
                    str(a.time_step), "--voxels", str(a.voxels), "--width", str(a.width), "--height", str(a.height),
                    "--output", "indirect", "--quiet", "--out", os.path.join(a.out, name + "-####.exr")] + extra,
                   check=True)


def frame(name, i):
    return compare.read_rgb(os.path.join(a.out, "%s-%04d.exr" % (name, i)))


def luminance(img):
    return float(np.mean(img @ np.array([0.2126, 0.7152, 0.0722])))


rows = {"pv": [], "pv-rsm": []}
print("| frame | time s | pv relative RMSE | pv luminance ratio | pv with RSM relative RMSE | "
      "pv with RSM luminance ratio |")
print("|---|---|---|---|---|---|")
for i in range(a.frames):
    ref = frame("geometric", i)
    rms = float(np.sqrt(np.mean(ref ** 2)))
    cells = []
    for name in rows:
        img = frame(name, i)
        rel = float(np.sqrt(np.mean((img - ref) ** 2))) / rms
        ratio = luminance(img) / luminance(ref)
        rows[name].append((rel, ratio))
        cells += ["%.3f" % rel, "%.3f" % ratio]
    print("| %d | %.2f | %s |" % (i, i * a.time_step, " | ".join(cells)))

canvas = plot_png.Canvas(a.frames, 0.0, 2.0)
for k in range(9):
    canvas.hline(canvas.y_of(0.25 * k), (200, 200, 200))
canvas.hline(canvas.y_of(1.0), (0, 160, 0), True)
for name, (dark, light) in (("pv", ((30, 60, 220), (150, 170, 240))),
                            ("pv-rsm", ((230, 120, 20), (245, 195, 140)))):
    canvas.series([r[1] for r in rows[name]], light)
    canvas.series([r[0] for r in rows[name]], dark)
compare.write_png(os.path.join(a.out, "pv-walk.png"), canvas.img)
