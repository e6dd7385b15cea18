#!/usr/bin/python3
"""Prints one markdown table row per `dvsgi bench --camera-path` JSON: the median (and range) over
the frames that compared pixels of the flicker figure's mean change and 99th percentile, for the
indirect term and for its irradiance (before the albedo), and the median GPU ms of a frame
(docs/benchmarks.md, "At 30 frames per second").
Usage: scripts/flicker-medians.py [--frames N] BENCH.json...
--frames N: only the first N measured frames of each file (to compare runs of different lengths);
a frame with nothing to compare among them is left out as always."""
import argparse
import json
import statistics


def summary(values, digits):
    values = [100.0 * v for v in values]
    return f"{statistics.median(values):.{digits}f} % ({min(values):.{digits}f}–{max(values):.{digits}f})"


def positive(text):
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


parser = argparse.ArgumentParser(description="Flicker medians of dvsgi bench --camera-path JSONs.")
parser.add_argument("--frames", type=positive, help="only the first N measured frames of each file")
parser.add_argument("files", nargs="+", metavar="BENCH.json")
args = parser.parse_args()

print("| file | term: mean change | term: 99th percentile | irradiance: mean change | "
      "irradiance: 99th percentile | GPU ms |")
print("|---|---|---|---|---|---|")
for path in args.files:
    with open(path) as f:
        frames = json.load(f)["measurements"][0]["per_frame"]
    if args.frames is not None:
        frames = frames[:args.frames]
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
