#!/usr/bin/env python3
"""Table of scripts/bench-side-by-side.sh's JSONs: per scene, the median GPU ms
of every pass for the base build, the current build and the current build with
the compute voxelizer, and the per-frame work (base: frame minus its static
voxelization) with the speed-up. Usage: side-by-side-table.py DIR BASE CURRENT"""
import glob, json, os, sys

out_dir, base_rev, cur_rev = sys.argv[1], sys.argv[2], sys.argv[3]
STATIC = ("clear all voxels", "clear occupied voxels", "voxelize static")


def load(path):
    try:
        with open(path) as f:
            ms = json.load(f).get("measurements", [])
        return ms[0] if ms and ms[0].get("status") == "ok" else None
    except (OSError, ValueError):
        return None


def med(m, name):
    for p in (m or {}).get("passes", []):
        if p.get("name") == name:
            return p["median_ms"]
    return None


def frame_work(m, base):
    if not m:
        return None
    f = m["frame_gpu"]["median_ms"]
    if base:  # the base bench ran static voxelization inside the frame
        f -= sum(med(m, n) or 0.0 for n in STATIC)
    return f


def fmt(v):
    return "-" if v is None else ("%.1f" % v if v >= 10 else "%.2f" % v)


for base_path in sorted(glob.glob(os.path.join(out_dir, "*-base.json"))):
    name = os.path.basename(base_path)[:-len("-base.json")]
    base = load(base_path)
    cur = load(os.path.join(out_dir, name + "-current.json"))
    comp = load(os.path.join(out_dir, name + "-current-compute.json"))
    cols = [("base " + base_rev, base, True), ("current " + cur_rev, cur, False),
            ("current, `--voxelizer compute`", comp, False)]
    grid = (cur or base or {}).get("voxel_grid", {}).get("n", "?")
    print("### %s, %s^3 (median GPU ms)\n" % (name, grid))
    print("| pass | " + " | ".join(c[0] for c in cols) + " |")
    print("|---|" + "---|" * len(cols))
    names = []
    for _, m, _ in cols:
        for p in (m or {}).get("passes", []):
            if p["name"] not in names:
                names.append(p["name"])
    for n in names:
        print("| %s | %s |" % (n, " | ".join(fmt(med(m, n)) for _, m, _ in cols)))
    work = [frame_work(m, b) for _, m, b in cols]
    print("| **per-frame work** (frame without static voxelization) | %s |" % " | ".join(fmt(v) for v in work))
    if work[0]:
        print("| speed-up over base | %s |" % " | ".join(
            "-" if not v else "%.2fx" % (work[0] / v) for v in work))
    mem = [(m or {}).get("gpu_memory_bytes") for _, m, _ in cols]
    print("| GPU memory (MiB) | %s |" % " | ".join("-" if v is None else "%.1f" % (v / 1048576.0) for v in mem))
    print()
