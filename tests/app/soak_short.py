#!/usr/bin/python3
"""A short `dvsgi soak` (docs/RELIABILITY.md, "Soak"): 200 frames at 32x32 with
32^3 voxels, settings changing every 20 frames (10 renderers; converging capped
at 4 bounces, which would take 45 at this size and dominate the run), the
validation layer on. No growth means: the device memory dvsgi holds is identical between
the two reports compared (same settings, after the first cycle), nothing is
left allocated once the last renderer is gone, and the resident set grows by
less than 2 % between those reports. Also checks that the scene really moved
(the output changes between reports of the same settings), that the
soak's own failure exit is what the JSON says, and the report count.
Usage: soak_short.py path/to/dvsgi"""
import json, os, shutil, subprocess, sys, tempfile

DVSGI = sys.argv[1]
TMP = tempfile.mkdtemp(prefix="dvsgi-soak-")
failures = []


def check(name, ok, detail=""):
    print("%-52s %s" % (name, "ok" if ok else "FAILED " + detail))
    if not ok:
        failures.append(name + ": " + detail)


out = os.path.join(TMP, "soak.json")
args = [DVSGI, "soak", "--width", "32", "--height", "32", "--voxels", "32", "--shadow-map", "256",
        "--soak-frames", "200", "--soak-every", "20", "--max-bounces", "4", "--soak-max-growth", "2",
        "--soak-out", out]
# Without the validation layer: its synchronization validation keeps history
# that grows the process by about 1.5 % over these 200 frames (measured), which
# is the layer's memory, not dvsgi's. The validated run below checks the messages.
p = subprocess.run(args, capture_output=True, text=True, timeout=280)
print(p.stdout)
print(p.stderr, file=sys.stderr)
check("exit code 0", p.returncode == 0, "rc=%d %s" % (p.returncode, p.stderr[-2000:]))
vargs = [DVSGI, "soak", "--width", "32", "--height", "32", "--voxels", "32", "--shadow-map", "256",
         "--soak-frames", "90", "--soak-every", "10", "--max-bounces", "4", "--soak-max-growth", "1000", "--validate",
         "--quiet", "--soak-out", os.path.join(TMP, "validated.json")]
v = subprocess.run(vargs, capture_output=True, text=True, timeout=280)
check("validated soak: exit code 0", v.returncode == 0, "rc=%d %s" % (v.returncode, v.stderr[-2000:]))
check("no validation messages", "[validation" not in v.stderr, v.stderr[-2000:])
if not os.path.exists(out):
    check("JSON written", False, out)
else:
    j = json.load(open(out))
    reports = j["reports"]
    check("10 reports, 10 renderers", len(reports) == 10 and j["renderers_created"] == 10,
          "%d reports, %d renderers" % (len(reports), j["renderers_created"]))
    check("validation errors 0", j["validation_errors"] == 0, str(j["validation_errors"]))
    base, last = j["baseline"], j["last"]
    check("baseline after warm-up, same variant as the last",
          not base["warmup"] and base["variant"] == last["variant"] and base["frame"] < last["frame"],
          "%r %r" % (base, last))
    check("device memory identical", base["device_bytes"] == last["device_bytes"] and
          base["device_allocations"] == last["device_allocations"],
          "%d B in %d -> %d B in %d" % (base["device_bytes"], base["device_allocations"], last["device_bytes"],
                                        last["device_allocations"]))
    check("device memory held at all", last["device_bytes"] > 100000, str(last["device_bytes"]))
    check("nothing allocated after the last renderer", j["device_bytes_after_last_renderer"] == 0,
          str(j["device_bytes_after_last_renderer"]))
    # dvsgi's own memory: RSS less the driver's JIT code (lavapipe's grows by about
    # 0.2 MiB per renderer; docs/RELIABILITY.md), which the soak reports apart.
    # Measured 2026-12-06 on the 2-core machine, frames 120..200: +0.20 to +1.34 %
    # with this code and with the code before it (ce837b5) alike, +1.49 % once
    # under the parallel test suite; no run grows from one report to the next
    # the way a leak would. Bound 1.5x the largest alone.
    rss = j["growth_percent"]["rss_excluding_jit_code"]
    check("RSS growth without JIT code < 2 %%", rss < 2.0,
          "%.3f %% (with it %.3f %%; JIT code %+.2f MiB)" % (rss, j["growth_percent"]["rss"],
                                                           j["growth_percent"]["jit_code_bytes"] / 2**20))
    check("passed flag", j["passed"] is True, str(j["passed"]))
    # The light and the model move: reports of one variant differ in output.
    by_variant = {}
    for r in reports:
        by_variant.setdefault(r["variant"], []).append(r["output_mean"])
    moved = all(len(set(v)) == len(v) for v in by_variant.values())
    check("the scene moved between reports", moved, str(by_variant))
    check("every variant ran", sorted(by_variant) == list(range(len(j["variants"]))), str(sorted(by_variant)))

# Too few frames for a baseline after warm-up: one line naming the option.
p = subprocess.run([DVSGI, "soak", "--voxels", "32", "--soak-frames", "40", "--soak-every", "10",
                    "--soak-out", os.path.join(TMP, "short.json")], capture_output=True, text=True, timeout=60)
lines = [l for l in p.stderr.splitlines() if l.strip()]
check("too short: one line naming --soak-frames", p.returncode != 0 and len(lines) == 1 and
      "--soak-frames 40" in lines[0] and not os.path.exists(os.path.join(TMP, "short.json")),
      "rc=%d %r" % (p.returncode, p.stderr))

shutil.rmtree(TMP, ignore_errors=True)
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
