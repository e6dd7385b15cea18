#!/usr/bin/python3
"""Smoke test of `dvsgi bench`: the quick suite runs, exits 0 and writes JSON
with positive voxelization timings; a missing scene is skipped with a warning
naming the file, never a crash; --pv-tables prints both of the progressive-
voxelization chapter's tables with sane figures.
Usage: bench_quick.py path/to/dvsgi path/to/shared path/to/tmpdir"""
import json, os, subprocess, sys

DVSGI, SHARED, TMP = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(TMP, exist_ok=True)
passed = 0
failed = []


def check(name, ok, detail=""):
    global passed
    print("%-52s %s%s" % (name, "ok" if ok else "FAILED", "" if ok else "  " + detail))
    if ok:
        passed += 1
    else:
        failed.append(name)


def run(args, timeout=240):
    p = subprocess.run([DVSGI, "bench", *args], capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        return {"_error": str(e)}


# 1. The quick suite with the validation layer.
out = os.path.join(TMP, "b.json")
if os.path.exists(out):
    os.remove(out)
rc, stdout, stderr = run(["--bench-quick", "--bench-out", out, "--shared", SHARED, "--validate"])
check("quick: exit code 0", rc == 0, "rc=%d stderr=%s" % (rc, stderr[-2000:]))
check("quick: progress line on stderr", "[1/1] cornell 32^3" in stderr, stderr[-500:])
check("quick: markdown table on stdout", "| voxelize static |" in stdout and "|---|" in stdout, stdout[-1000:])
j = load(out)
check("quick: JSON written", "_error" not in j, j.get("_error", ""))
ms = j.get("measurements", [])
check("quick: one measurement, status ok", len(ms) == 1 and ms[0].get("status") == "ok", json.dumps(ms)[:500])
m = ms[0] if ms else {}
passes = {p.get("name"): p for p in m.get("passes", [])}
for name in ("voxelize static", "clear dynamic voxels", "voxelize dynamic"):
    p = passes.get(name, {})
    ok = (p.get("count") == 2 and len(p.get("samples_ms", [])) == 2 and p.get("min_ms", 0) > 0
          and p["min_ms"] <= p["median_ms"] <= p["max_ms"])
    check("quick: '%s' timed in both frames, > 0 ms" % name, ok, json.dumps(p)[:300])
check("quick: frame GPU time > 0", m.get("frame_gpu", {}).get("median_ms", 0) > 0)
tris = m.get("triangles", {})
check("quick: static and dynamic triangles", tris.get("static", 0) > 0 and tris.get("dynamic", 0) > 0, str(tris))
check("quick: 32^3 grid", m.get("voxel_grid", {}).get("n") == 32 and m.get("voxels") == 32, str(m.get("voxel_grid")))
check("quick: GPU memory recorded", m.get("gpu_memory_bytes", 0) > 0)
dev = j.get("device", {})
check("quick: device and driver recorded", bool(dev.get("name")) and "driver_name" in dev, str(dev))
check("quick: date and command line", bool(j.get("date")) and "--bench-quick" in j.get("command_line", ""))
s = j.get("settings", {})
check("quick: 160x90, 2 frames", s.get("width") == 160 and s.get("height") == 90 and s.get("bench-frames") == 2
      and s.get("bench-voxels") == [32], str(s))
check("quick: every bench setting recorded by its flag name",
      all(k in s for k in ("voxels", "cone-step", "bounces", "shadow-map", "bench-quick", "validate")), str(s))
check("quick: no validation errors", j.get("validation_errors") == 0, str(j.get("validation_errors")))

# The efficiency figures: copy bandwidth, voxel counts, bytes model per pass (no timing asserted).
copy = dev.get("copy_bandwidth", {})
gbps = dev.get("copy_bandwidth_gbps") or 0
check("quick: copy bandwidth measured", gbps > 0 and copy.get("gbps") == gbps, str(copy)[:300])
check("quick: copy bandwidth size and repetitions recorded",
      copy.get("buffer_bytes", 0) >= 16 << 20 and copy.get("bytes_per_copy") == 2 * copy.get("buffer_bytes", 0)
      and copy.get("repetitions") == 5 and len(copy.get("samples_ms", [])) == 5, str(copy)[:300])
check("quick: copy bandwidth in the header", "copy bandwidth:" in stderr and "copy bandwidth" in stdout, stderr[-500:])
vc = m.get("voxel_counts", {})
check("quick: occupied and dynamic voxels counted",
      vc.get("occupied", 0) > 0 and 0 < vc.get("dynamic", 0) <= vc.get("occupied", 0), str(vc))
check("quick: bytes model inputs recorded", m.get("bytes_model", {}).get("occupied_voxels") == vc.get("occupied")
      and m.get("bytes_model", {}).get("voxels") == 32, str(m.get("bytes_model")))
modelled = ("clear occupied voxels", "voxelize static", "clear dynamic voxels", "voxelize dynamic", "shadow maps",
            "voxel direct light", "voxel bounce", "voxel filtering (bounce)", "gbuffer", "direct lighting",
            "cone tracing", "composite")
for name in modelled:
    p = passes.get(name, {})
    ok = (p.get("bytes", 0) > 0 and p["bytes"] == p.get("bytes_read", -1) + p.get("bytes_written", -1)
          and p.get("gbps", -1) >= 0 and p.get("bandwidth_fraction") is not None
          and abs(p["bandwidth_fraction"] - p["gbps"] / gbps) <= 1e-9 * max(p["bandwidth_fraction"], 1))
    check("quick: '%s' bytes, GB/s and fraction" % name, ok,
          json.dumps({k: v for k, v in p.items() if k != "samples_ms"})[:300])
fg = m.get("frame_gpu", {})
check("quick: frame bytes, GB/s and fraction", fg.get("bytes", 0) > 0 and fg.get("gbps", 0) > 0
      and fg.get("bandwidth_fraction") is not None, str({k: v for k, v in fg.items() if k != "samples_ms"}))
check("quick: efficiency table on stdout", "GB/s of the bytes model" in stdout
      and "| occupied / dynamic voxels |" in stdout, stdout[-1500:])

# 2. A shared folder without the scenes: skipped with a warning naming the file.
out2 = os.path.join(TMP, "missing.json")
missing = os.path.join(TMP, "no-shared-here")
rc, stdout, stderr = run(["--bench-quick", "--bench-out", out2, "--shared", missing], timeout=120)
check("missing scene: no crash, non-zero exit", rc > 0, "rc=%d" % rc)
check("missing scene: warning names the file", "cornell-lights.gltf" in stderr and "warning" in stderr, stderr[-500:])
j2 = load(out2)
ms2 = j2.get("measurements", [])
check("missing scene: recorded as skipped", len(ms2) == 1 and ms2[0].get("status") == "skipped"
      and "cornell-lights.gltf" in ms2[0].get("error", ""), json.dumps(ms2)[:300])

# 3. A camera path: every measured frame reported, with the flicker figure.
walk = os.path.join(TMP, "walk.json")
with open(walk, "w") as f:
    json.dump({"keyframes": [
        {"time": 0.0, "position": [0.0016, 0.2744, -0.763], "target": [0.0, 0.2744, 0.0]},
        {"time": 0.5, "position": [0.05, 0.30, -0.70], "target": [0.02, 0.25, 0.0]}]}, f)
out3 = os.path.join(TMP, "walk-bench.json")
rc, stdout, stderr = run(["--bench-quick", "--bench-out", out3, "--shared", SHARED, "--camera-path", walk,
                          "--add-model", "none"])
j3 = load(out3)
m3 = (j3.get("measurements") or [{}])[0]
check("--add-model none: no moving model", j3.get("dynamic_model", "x") is None
      and m3.get("triangles", {}).get("dynamic", -1) == 0, json.dumps(m3.get("triangles")))
frames = m3.get("per_frame", [])
flick = [f.get("flicker", {}) for f in frames]
check("camera path: exit 0, every measured frame reported", rc == 0 and len(frames) == 2
      and all("passes" in f and f.get("gpu_ms", 0) > 0 for f in frames), "rc=%d %s" % (rc, stderr[-500:]))
check("camera path: flicker per frame, pixels compared", all(
      f.get("compared_pixels", 0) > 1000 and 0.0 <= f.get("mean_relative_change", -1) <= f.get("p99_relative_change", -1)
      and f.get("mean_indirect_luminance_before", 0) > 0 for f in flick), json.dumps(flick)[:500])
check("camera path: flicker rows in the table", "flicker: mean relative change" in stdout, stdout[-800:])
check("camera path: luminance jump per frame, no scroll without a clipmap", all(
      f.get("scrolled") is False and abs(f.get("luminance_jump", 9.0) - (f.get("mean_indirect_luminance_after", 0.0)
      / f.get("mean_indirect_luminance_before", 1.0) - 1.0)) < 1e-9 for f in flick)
      and "scroll_luminance_jump" not in m3.get("flicker", {}), json.dumps(flick)[:500])

# 4. --pv-tables at 32^3 with small images: both tables, every row measured,
# pv's Hausdorff distance near the exact voxelizer's and most of its voxels.
out = os.path.join(TMP, "pv.json")
rc, stdout, stderr = run(["--pv-tables", "--bench-voxels", "32", "--width", "64", "--height", "64",
                          "--bench-out", out, "--shared", SHARED, "--validate"])
check("pv tables: exit code 0", rc == 0, "rc %d: %s" % (rc, stderr[-300:]))
check("pv tables: both tables printed", "Table 6.1" in stdout and "Table 6.2" in stdout)
j = load(out)
t1, t2 = j.get("table_6_1", []), j.get("table_6_2", [])
check("pv tables: 3 timed scenes, 3 orbited models", len(t1) == 3 and len(t2) == 3, "%d, %d" % (len(t1), len(t2)))
check("pv tables: every timing positive",
      all(r.get(k, 0) > 0 for r in t1 for k in ("geometry", "compute", "pv", "gbuffer")), str(t1)[:300])
check("pv tables: pv's distance within 1.5x the exact one's",
      all(0 < r.get("pv", 0) <= 1.5 * r.get("geometric", 0) for r in t2), str(t2)[:300])
check("pv tables: pv holds >= 99 % of the exact voxels",
      all(r.get("geometric_found_percent", 0) >= 99.0 for r in t2),
      str([r.get("geometric_found_percent") for r in t2]))
check("pv tables: one distance per orbit frame", all(len(r.get("pv_per_frame", [])) == 36 for r in t2))
check("pv tables: no validation errors", j.get("validation_errors") == 0, str(j.get("validation_errors")))

print("%d passed, %d failed" % (passed, len(failed)))
sys.exit(1 if failed else 0)
