#!/usr/bin/python3
"""Per-frame flicker of a `dvsgi bench --camera-path` run: prints a markdown
table (frame, time, GPU ms, mean and 99th-percentile relative change of the
indirect term, compared and disoccluded pixels) and draws a PNG plot of the
two changes per frame on a log scale (0.01 % .. 1000 %; grey lines at every
decade, green lines at the goals 1 % and 5 %; blue = mean, red = 99th
percentile; where the JSON has the irradiance's figures, light blue = its
mean and orange = its 99th percentile). No text is drawn: docs/benchmarks.md
captions the plot.
Usage: flicker-plot.py BENCH.json OUT.png   (needs numpy and ../shared/tools)"""
import json, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../shared/tools"))
import compare  # noqa: E402  (write_png)
import plot_png  # noqa: E402

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

canvas = plot_png.Canvas(len(frames), 0.01, 1000.0, log=True)  # percent
for d in range(-2, 4):
    canvas.hline(canvas.y_of(10.0 ** d), (200, 200, 200))
canvas.hline(canvas.y_of(1.0), (0, 160, 0), True)
canvas.hline(canvas.y_of(5.0), (0, 160, 0), True)
for key, colour in (("mean_relative_change", (30, 60, 220)), ("p99_relative_change", (220, 40, 40))):
    # a frame with nothing compared breaks the line
    canvas.series([100 * f["flicker"][key] if f["flicker"]["compared_pixels"] else None for f in frames], colour)
for key, colour in (("mean_relative_change", (120, 190, 250)), ("p99_relative_change", (250, 160, 40))):
    values = [100 * f["flicker"]["irradiance"][key] if f["flicker"]["compared_pixels"] and "irradiance" in f["flicker"]
              else None for f in frames]
    if any(v is not None for v in values):
        canvas.series(values, colour)
compare.write_png(png, canvas.img)
