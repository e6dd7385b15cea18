#!/usr/bin/python3
"""The indirect light one bounce at a time, against a CPU path tracer
(scripts/bounce-reference.py): the per-pixel gather over direct-lit voxels
(--bounces 0) against the traced first bounce, and what one voxel bounce adds
(--bounces 1 minus --bounces 0) against the traced second bounce. Converged
GI multiplies a per-bounce error several times over (white walls keep about
0.8 of the light per bounce in the Cornell box), so this is where an energy
error shows first. Scenes: cornell-lights.gltf (64^2, 64^3) and a lit corner
(floor and wall, scripts/corner-scene.py), whose traced direct light must also match
dvsgi's, which checks the tracer.
Usage: bounce_reference.py path/to/dvsgi path/to/shared path/to/scripts/bounce-reference.py
To look further (the bounds are for the defaults): DVSGI_BOUNCE_VOXELS=N renders at N^3 instead of
64^3, DVSGI_BOUNCE_OPTIONS="..." adds dvsgi options to every render."""
import os
import subprocess
import sys
import tempfile

import numpy as np

dvsgi, shared, tracer = sys.argv[1:4]
cornell = os.path.join(shared, "scenes/cornell-box/cornell-lights.gltf")
for needed in (cornell, os.path.join(shared, "tools/compare.py")):
    if not os.path.exists(needed):
        print("FAIL: %s not found" % needed)  # a check that did not run must not pass
        sys.exit(1)
sys.path.insert(0, os.path.join(shared, "tools"))
import compare  # noqa: E402  (the project's metrics and EXR reader, ../shared/tools)
LUM = np.array([0.2126, 0.7152, 0.0722])
SIZE, SPP = 64, 128
VOXELS = int(os.environ.get("DVSGI_BOUNCE_VOXELS", "64"))
EXTRA = os.environ.get("DVSGI_BOUNCE_OPTIONS", "").split()
tmp = tempfile.mkdtemp(prefix="dvsgi-bounce-")
failures = []


def render(scene, name, *options, voxels=VOXELS):
    out = os.path.join(tmp, name + ".exr")
    subprocess.run([dvsgi, "render", scene, "--width", str(SIZE), "--height", str(SIZE), "--voxels", str(voxels),
                    "--trace-scale", "1", "--out", out, "--png", "none", "--validate", "--quiet", *options, *EXTRA],
                   check=True, timeout=300)
    return float((compare.read_rgb(out) @ LUM).mean())


def check(label, got, want, bound):
    ratio = got / want
    print("%-44s dvsgi %.5f, traced %.5f: ratio %.3f (bound +-%.3f)" % (label, got, want, ratio, bound))
    if abs(ratio - 1.0) > bound:
        failures.append("%s: ratio %.3f off by more than %.3f" % (label, ratio, bound))


corner = os.path.join(tmp, "corner.gltf")
subprocess.run(["/usr/bin/python3", os.path.join(os.path.dirname(tracer), "corner-scene.py"), corner], check=True)

# Bounds: 1.5x the errors measured on lavapipe (docs/quality.md, "One bounce at a time" and "A voxel seen
# from behind"), but no tighter than the tracer's own agreement with dvsgi's direct light (1 %; exact there:
# both are Lambert with hard shadows). Since a voxel seen from behind shows no light to the cones: first
# bounce -1.4 %, lit corner +8.8 %, second bounce with the default rays +2.0 %, with the paper's cones
# -6.3 %. Before it: +1.1 %, +8.9 %, +5.7 % and -0.3 % (the first two with the six cones turned per pixel;
# -0.2 % and +6.1 % before that); +3.0 %, +5.2 % and +18.5 % while walls on the scene's bounds were two
# voxels thick.
# secondBounds: (bound, dvsgi options) per way of tracing the voxel bounce.
cases = [("cornell-lights", cornell, 0.021, [(0.030, []), (0.095, ["--bounce-trace", "cones"])]),
         ("corner", corner, 0.134, [])]
for name, scene, firstBound, secondBounds in cases:
    prefix = os.path.join(tmp, name)
    subprocess.run(["/usr/bin/python3", tracer, scene, prefix, "--size", str(SIZE), "--spp", str(SPP), "--bounces", "2"],
                   check=True, timeout=600, stdout=subprocess.DEVNULL)
    traced = [float((np.load("%s-%s.npy" % (prefix, t)) @ LUM).mean()) for t in ("direct", "bounce1", "bounce2")]
    check(name + ": direct light (checks the tracer)", render(scene, name + "-direct", voxels=0), traced[0], 0.01)
    first = render(scene, name + "-b0", "--bounces", "0", "--output", "indirect")
    check(name + ": first bounce (per-pixel gather)", first, traced[1], firstBound)
    for secondBound, options in secondBounds:
        label = " ".join(["one voxel bounce", *options])
        second = render(scene, name + "-b1" + "".join(options), "--bounces", "1", "--output", "indirect",
                        *options) - first
        check("%s: second bounce (%s)" % (name, label), second, traced[2], secondBound)

print("\n".join("FAIL " + f for f in failures))
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
