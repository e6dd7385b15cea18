#!/usr/bin/python3
"""Prints one markdown table row per `dvsgi bench --camera-path` JSON: the median (and range) over
the frames that compared pixels of the flicker figure's mean change and 99th percentile, for the
indirect term and for its irradiance (before the albedo), and the median GPU ms of a frame
(docs/benchmarks.md, "At 30 frames per second").
Usage: scripts/flicker-medians.py [--frames N] BENCH.json...
--frames N: only the first N measured frames of each file (to compare runs of different lengths)."""
import json
import statistics
import sys


def summary(values, digits):
    values = [100.0 * v for v in values]
    return f"{statistics.median(values):.{digits}f} % ({min(values):.{digits}f}–{max(values):.{digits}f})"


print("| file | term: mean change | term: 99th percentile | irradiance: mean change | "
      "irradiance: 99th percentile | GPU ms |")
print("|---|---|---|---|---|---|")
args = sys.argv[1:]
limit = None
if args[:1] == ["--frames"]:
    if len(args) < 2 or not args[1].isdigit() or int(args[1]) < 1:
        sys.exit("flicker-medians.py: --frames needs a positive whole number")
    limit = int(args[1])
    args = args[2:]
for path in args:
    with open(path) as f:
        frames = json.load(f)["measurements"][0]["per_frame"]
    if limit is not None:
        frames = frames[:limit]
    # A first frame without a warm-up has nothing to compare with.
    frames = [fr for fr in frames if "flicker" in fr and fr["flicker"]["compared_pixels"] > 0]
    if not frames:
        print(f"| {path} | – | – | – | – | – |")
        continue
    term = [fr["flicker"] for fr in frames]
    irr = [fl.get("irradiance") for fl in term]
    cells = [summary([fl["mean_relative_change"] for fl in term], 1), summary([fl["p99_relative_change"] for fl in term], 0)]
    if all(irr):
        cells += [summary([i["mean_relative_change"] for i in irr], 2), summary([i["p99_relative_change"] for i in irr], 1)]
    else:
        cells += ["–", "–"]
    gpu = statistics.median(fr["gpu_ms"] for fr in frames)
    print(f"| {path} | " + " | ".join(cells) + f" | {gpu:.0f} |")
