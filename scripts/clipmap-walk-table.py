#!/usr/bin/env python3
"""Per-frame table of a Sponza walk with a fitted grid and with --clipmap (docs/clipmap.md).

Reads two `dvsgi bench --camera-path` JSON files (fitted, clipmap) and prints a markdown table:
GPU ms of the frame, of the clipmap scroll and of the static voxelization of the exposed slabs,
the flicker figure of each (of the indirect term, and of its irradiance before the albedo), and
the change of mean indirect luminance between the frames' compared pixels (the jump the issue
bounds by 2 % at a scroll).

usage: scripts/clipmap-walk-table.py FITTED.json CLIPMAP.json
"""
import json
import sys


def frames(path):
    with open(path) as f:
        j = json.load(f)
    return {f["frame"]: f for f in j["measurements"][0]["per_frame"]}


def jump(f):
    fl = f.get("flicker")
    if not fl or fl["mean_indirect_luminance_before"] <= 0:
        return None
    return fl["mean_indirect_luminance_after"] / fl["mean_indirect_luminance_before"] - 1.0


def pct(v):
    return "–" if v is None else f"{100 * v:.2f} %"


fitted, clip = frames(sys.argv[1]), frames(sys.argv[2])
print("| frame | GPU ms fitted | GPU ms clipmap | scroll ms | slabs voxelized ms | mean change fitted | "
      "mean change clipmap | 99th pct clipmap | irradiance: mean fitted | mean clipmap | 99th pct clipmap | "
      "luminance jump fitted | luminance jump clipmap |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
worst = 0.0
for k in sorted(clip):
    a, b = fitted.get(k), clip[k]
    fa, fb = (a or {}).get("flicker", {}), b.get("flicker", {})
    compared = fb.get("compared_pixels", 0) > 0
    mean = lambda fl: fl.get("mean_relative_change") if fl.get("compared_pixels", 0) > 0 else None
    # The same figures for the irradiance (before the albedo), where the JSON has them.
    irr = lambda fl, key: fl.get("irradiance", {}).get(key) if fl.get("compared_pixels", 0) > 0 else None
    scroll = b["passes"].get("clipmap scroll", 0.0)
    if scroll > 0 and compared and jump(b) is not None:
        worst = max(worst, abs(jump(b)))
    print(f"| {k} | {a['gpu_ms']:.0f} | {b['gpu_ms']:.0f} | {scroll:.2f} | {b['passes'].get('voxelize static', 0.0):.0f} | "
          f"{pct(mean(fa))} | {pct(mean(fb))} | {pct(fb.get('p99_relative_change') if compared else None)} | "
          f"{pct(irr(fa, 'mean_relative_change'))} | {pct(irr(fb, 'mean_relative_change'))} | "
          f"{pct(irr(fb, 'p99_relative_change'))} | {pct(jump(a) if a else None)} | {pct(jump(b))} |")
print(f"\nlargest luminance jump at a frame that scrolled: {100 * worst:.2f} %")
