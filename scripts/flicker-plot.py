#!/usr/bin/python3
"""Per-frame flicker of a `dvsgi bench --camera-path` run: prints a markdown
table (frame, time, GPU ms, mean and 99th-percentile relative change of the
indirect term, compared and disoccluded pixels) and draws a PNG plot of the
two changes per frame on a log scale (0.01 % .. 1000 %; grey lines at every
decade, green lines at the goals 1 % and 5 %; blue = mean, red = 99th
percentile). No text is drawn: docs/benchmarks.md captions the plot.
Usage: flicker-plot.py BENCH.json OUT.png   (needs numpy and ../shared/tools)"""
import json, math, os, sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../shared/tools"))
import compare  # noqa: E402  (write_png)

bench, png = sys.argv[1], sys.argv[2]
m = json.load(open(bench))["measurements"][0]
frames = [f for f in m.get("per_frame", []) if "flicker" in f]
print("| frame | time s | GPU ms | mean change | 99th percentile | compared px | disoccluded px |")
print("|---|---|---|---|---|---|---|")
for f in frames:
    fl = f["flicker"]
    if fl["compared_pixels"] == 0:  # nothing seen in both frames: no figure
        print("| %d | %.2f | %.0f | – | – | 0 | %d |" % (f["frame"], f["time"], f["gpu_ms"], fl["disoccluded_pixels"]))
        continue
    print("| %d | %.2f | %.0f | %.2f %% | %.1f %% | %d | %d |" % (
        f["frame"], f["time"], f["gpu_ms"], 100 * fl["mean_relative_change"], 100 * fl["p99_relative_change"],
        fl["compared_pixels"], fl["disoccluded_pixels"]))

W, H, M = 640, 320, 20
img = np.full((H, W, 3), 255, np.uint8)
lo, hi = math.log10(0.01), math.log10(1000.0)  # percent


def y_of(percent):
    v = math.log10(max(percent, 0.01))
    return int(round(H - M - (min(v, hi) - lo) / (hi - lo) * (H - 2 * M)))


def x_of(i):
    return int(round(M + i * (W - 2 * M) / max(len(frames) - 1, 1)))


def hline(y, colour, dashed=False):
    for x in range(M, W - M):
        if not dashed or (x // 6) % 2 == 0:
            img[y, x] = colour


def line(x0, y0, x1, y1, colour):
    n = max(abs(x1 - x0), abs(y1 - y0), 1)
    for k in range(n + 1):
        x = x0 + (x1 - x0) * k // n
        y = y0 + (y1 - y0) * k // n
        img[max(y - 1, 0):y + 2, max(x - 1, 0):x + 2] = colour


for d in range(-2, 4):
    hline(y_of(10.0 ** d), (200, 200, 200))
hline(y_of(1.0), (0, 160, 0), True)
hline(y_of(5.0), (0, 160, 0), True)
for key, colour in (("mean_relative_change", (30, 60, 220)), ("p99_relative_change", (220, 40, 40))):
    pts = [(x_of(i), y_of(100 * f["flicker"][key])) if f["flicker"]["compared_pixels"] else None
           for i, f in enumerate(frames)]
    for a, b in zip(pts, pts[1:]):
        if a and b:  # a frame with nothing compared breaks the line
            line(a[0], a[1], b[0], b[1], colour)
compare.write_png(png, img)
