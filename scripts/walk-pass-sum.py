#!/usr/bin/env python3
"""Per-frame GPU ms of one pass in `dvsgi bench --camera-path` JSON files, and its sum over the walk.

Used for A/B runs of two builds on the same walk (docs/clipmap.md): run the bench command of the
walk with each build, alternating, then compare the sums.

usage: scripts/walk-pass-sum.py PASS_NAME RUN.json [RUN.json ...]
"""
import json
import sys

if len(sys.argv) < 3:
    sys.exit(__doc__)
name = sys.argv[1]
for path in sys.argv[2:]:
    with open(path) as f:
        frames = json.load(f)["measurements"][0]["per_frame"]
    ms = []
    for fr in frames:
        ms.append(fr.get("passes", {}).get(name, 0.0))
    print("%s: %s | sum %.0f ms" % (path, " ".join("%.0f" % v for v in ms), sum(ms)))
