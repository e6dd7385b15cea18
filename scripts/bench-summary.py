#!/usr/bin/python3
"""Prints the markdown tables of docs/benchmarks.md from a `dvsgi bench` JSON:
median GPU ms per pass for the default settings (one column per scene and
voxel resolution), then the frame time of every variant (Tables III and V),
then, for files that have them, the GB/s of the bytes model per pass and
their fraction of the copy bandwidth.
Usage: scripts/bench-summary.py BENCH.json"""
import json
import sys

data = json.load(open(sys.argv[1]))
ms = [m for m in data["measurements"] if m.get("status") == "ok"]
dev = data["device"]
s = data["settings"]
# Settings are named as their flags (dvsgi --help); files from before the
# settings table used frames/warmup_frames.
frames = s.get("bench-frames", s.get("frames"))
warmup = s.get("bench-warmup", s.get("warmup_frames"))
print(f"Device: {dev['name']} (driver {dev.get('driver_info', '?')}), {s['width']}x{s['height']}, "
      f"{frames} measured + {warmup} warm-up frames, {data['date']}\n")
base = [m for m in ms if not m.get("variant")]
cols = [f"{m['scene']} {m['voxels']}³" for m in base]
order = []
for m in base:
    for p in m["passes"]:
        if p["name"] not in order:
            order.append(p["name"])
print("| median GPU ms | " + " | ".join(cols) + " |")
print("|---|" + "---|" * len(cols))
for name in order:
    row = []
    for m in base:
        v = next((p["median_ms"] for p in m["passes"] if p["name"] == name), None)
        row.append("–" if v is None else f"{v:.2f}")
    print(f"| {name} | " + " | ".join(row) + " |")
print("| **frame** | " + " | ".join(f"**{m['frame_gpu']['median_ms']:.2f}**" for m in base) + " |")
print("| GPU memory (MiB) | " + " | ".join(f"{m['gpu_memory_bytes'] / 2**20:.0f}" for m in base) + " |")
variants = sorted({m.get("variant", "") for m in ms} - {""})
if variants:
    print("\n| frame GPU ms (median) | " + " | ".join(cols) + " |")
    print("|---|" + "---|" * len(cols))
    for v in [""] + variants:
        row = []
        for b in base:
            m = next((x for x in ms if x["scene"] == b["scene"] and x["voxels"] == b["voxels"]
                      and x.get("variant", "") == v), None)
            row.append("–" if m is None else f"{m['frame_gpu']['median_ms']:.2f}")
        print(f"| {v or 'defaults'} | " + " | ".join(row) + " |")
copy = dev.get("copy_bandwidth_gbps")
if copy and any("gbps" in p for m in base for p in m["passes"]):
    print(f"\n| GB/s (% of copy, {copy:.3g} GB/s) | " + " | ".join(cols) + " |")
    print("|---|" + "---|" * len(cols))
    for name in order:
        row = []
        for m in base:
            p = next((p for p in m["passes"] if p["name"] == name), {})
            row.append("–" if "gbps" not in p else f"{p['gbps']:.3g} ({100 * p['bandwidth_fraction']:.3g} %)")
        if any(r != "–" for r in row):
            print(f"| {name} | " + " | ".join(row) + " |")
    print("| occupied / dynamic voxels | " + " | ".join(
        f"{m['voxel_counts']['occupied']} / {m['voxel_counts']['dynamic']}" if "voxel_counts" in m else "–"
        for m in base) + " |")
