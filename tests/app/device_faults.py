#!/usr/bin/python3
"""Device faults end to end (docs/RELIABILITY.md, "Device faults"): out of
device memory at image and voxel-grid creation, a lost device, a swapchain that
cannot be created and a misspelt DVSGI_FAULT each end in exactly one stderr
line naming what was being created and the setting that sized it, a non-zero
exit (no signal), and no output file. The real out-of-memory case asks lavapipe
for an image larger than its 2 GiB heap; the others go through the test-only
DVSGI_FAULT hook in src/gpu/fault.cpp. Every run has the validation layer on.
Usage: device_faults.py path/to/dvsgi"""
import os, shutil, subprocess, sys, tempfile

DVSGI = sys.argv[1]
TMP = tempfile.mkdtemp(prefix="dvsgi-faults-")
failures = []
checks = 0
SMALL = ["--width", "32", "--height", "32", "--voxels", "32", "--shadow-map", "256", "--quiet", "--validate"]


def run(args, fault=None, wrapper=()):
    env = dict(os.environ)
    env.pop("DVSGI_FAULT", None)
    if fault:
        env["DVSGI_FAULT"] = fault
    p = subprocess.run([*wrapper, DVSGI, *args], capture_output=True, text=True, timeout=240, env=env)
    return p.returncode, p.stdout, p.stderr


def expect_fault(name, args, fault, must_contain, wrapper=()):
    """One stderr line with every string of must_contain, rc > 0, nothing in the output folder."""
    global checks
    checks += 1
    outdir = os.path.join(TMP, name.replace(" ", "_"))
    os.makedirs(outdir)
    args = [a.replace("OUTDIR", outdir) for a in args]
    rc, out, err = run(args, fault, wrapper)
    lines = [l for l in err.splitlines() if l.strip()]
    line = lines[0] if lines else "<no message>"
    print("%-30s rc=%d  %s" % (name, rc, line))
    problems = []
    if rc <= 0:
        problems.append("exit code %d (wanted a non-zero exit, not a signal)" % rc)
    if len(lines) != 1:
        problems.append("%d stderr lines: %r" % (len(lines), err))
    problems += ["message lacks %r" % s for s in must_contain if s not in line]
    if os.listdir(outdir):
        problems.append("files written: %s" % os.listdir(outdir))
    if problems:
        failures.append("%s: %s" % (name, "; ".join(problems)))


out = ["--out", "OUTDIR/o.exr", "--png", "none"]  # render-only options
# Real: lavapipe's single heap is 2 GiB; a 16384^2 RGBA32F image needs 4 GiB.
rc, so, _ = run(["render", "--width", "8", "--height", "8", "--voxels", "0", "--out", os.path.join(TMP, "probe.exr")])
if "llvmpipe" not in so:
    failures.append("the real out-of-memory case is sized for lavapipe's 2 GiB heap; device line: %r" % so)
expect_fault("oom image (real)", ["render", "--width", "16384", "--height", "16384", "--voxels", "0",
                                  "--shadow-map", "256", "--quiet", "--validate", "--png", "none", *out], None,
             ["--width 16384 --height 16384", "4.0 GiB", "2.0 GiB", "VK_ERROR_OUT_OF_DEVICE_MEMORY"])
expect_fault("oom voxel grid", ["render", *SMALL, *out], "oom:voxel attributes",
             ["--voxels 32: allocating the voxel attributes", "the voxel volumes need", "VK_ERROR_OUT_OF_DEVICE_MEMORY"])
expect_fault("oom shadow map", ["render", *SMALL, *out], "oom:shadow map",
             ["--shadow-map 256: allocating the shadow map array", "try a smaller --shadow-map"])
expect_fault("oom g-buffer", ["render", *SMALL, "--supersample", "2", *out], "oom:gbuffer",
             ["--width 32 --height 32 --supersample 2: allocating the gbuffer"])
expect_fault("device lost at once", ["render", *SMALL, *out], "device-lost@1",
             ["was lost", "VK_ERROR_DEVICE_LOST"])
# Mid-sequence: --bounces 1 makes each frame a few submissions, so the 40th
# falls inside the 20 frames, after setup.
expect_fault("device lost mid-render", ["render", *SMALL, "--bounces", "1", "--frames", "20", *out],
             "device-lost@40", ["was lost", "VK_ERROR_DEVICE_LOST"])
expect_fault("device lost in soak", ["soak", *SMALL, "--soak-frames", "90", "--soak-every", "10",
                                     "--soak-out", "OUTDIR/soak.json"], "device-lost@60",
             ["was lost", "VK_ERROR_DEVICE_LOST"])
expect_fault("misspelt DVSGI_FAULT", ["render", *SMALL, *out], "device-lost@x", ["DVSGI_FAULT", "device-lost@x"])

xvfb = shutil.which("xvfb-run")
if not xvfb:
    failures.append("xvfb-run is not installed (Debian: xvfb): the swapchain case cannot run")
else:
    expect_fault("swapchain", ["view", *SMALL, "--view-frames", "2", "--screenshot", "OUTDIR/s.exr"], "swapchain",
                 ["swapchain", "could not be created", "VK_ERROR_INITIALIZATION_FAILED", "--width 32 --height 32"],
                 wrapper=(xvfb, "-a", "-s", "-screen 0 640x480x24"))

# Without a fault the same small render works, so the cases above failed for their fault.
checks += 1
rc, so, se = run(["render", *SMALL, "--out", os.path.join(TMP, "ok.exr")])
print("%-30s rc=%d" % ("no fault", rc))
if rc != 0 or not os.path.exists(os.path.join(TMP, "ok.exr")):
    failures.append("no fault: rc=%d %s" % (rc, se))

print("\n".join("FAIL " + f for f in failures))
print("%d passed, %d failed" % (max(checks - len(failures), 0), len(failures)))
shutil.rmtree(TMP, ignore_errors=True)
sys.exit(1 if failures else 0)
