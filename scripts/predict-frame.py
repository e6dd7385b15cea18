#!/usr/bin/env python3
"""The bytes model's floor for a frame on another device.

Reads a `dvsgi bench` JSON (its first measurement's per-pass modelled bytes,
which depend only on sizes and voxel counts, not on the device that ran it) and
divides the bytes of an "everything dynamic" frame by a memory bandwidth:
every pass of the measured frame, plus clearing and voxelizing all geometry
(`clear occupied voxels`, or `clear all voxels` in JSONs from before
2026-11-28, and `voxelize static`) in place of the dynamic clear. Cone
samples count as zero in the model, so this is a lower bound on the frame time.

usage: predict-frame.py BENCH.json BANDWIDTH_GB_PER_S
"""
import json
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    bench = json.load(open(sys.argv[1]))
    gbps = float(sys.argv[2])
    m = bench["measurements"][0]
    rows = [(p["name"], p["bytes"]) for p in m["passes"] if p.get("bytes") and p["name"] != "clear dynamic voxels"]
    total = sum(b for _, b in rows)
    print(f"| pass | modelled MB | floor ms at {gbps:g} GB/s |")
    print("|---|---|---|")
    for name, b in rows:
        print(f"| {name} | {b / 1e6:.1f} | {b / (gbps * 1e6):.3f} |")
    print(f"| **everything dynamic** | **{total / 1e6:.1f}** | **{total / (gbps * 1e6):.3f}** |")
    inputs = m.get("bytes_model", {})
    print(f"\ninputs: {inputs.get('voxels')}^3, {inputs.get('occupied_voxels')} occupied voxels, "
          f"{inputs.get('slots')} slots, internal {inputs.get('internal')}, trace {inputs.get('trace')}")


if __name__ == "__main__":
    main()
