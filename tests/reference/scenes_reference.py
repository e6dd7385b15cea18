#!/usr/bin/python3
"""Scenes other than the upright Cornell box against path-traced truth, with the defaults (64^3):
- the shared Sponza (sun, point light) and Sibenik scenes, a room lit through a window or by a spot
  light (scripts/window-room-scene.py [--spot]) and blocks outdoors (scripts/outdoor-scene.py) at
  320x180 against the Cycles references in docs/quality/cycles/
  (scripts/cycles-reference.py): the direct term against the direct-only render and the indirect
  term against converged - direct-only (computed by scripts/scene-compare.py);
- both Cornell scenes turned 45 degrees about the vertical (scripts/turn-scene.py), 256x256, whose
  path-traced image is the upright reference: the voxel grid keeps the world's axes, so this measures
  how much the voxels' light depends on the orientation of the walls.
The bounds allow 1.5 times the measured error, and at least 0.5 % (docs/quality.md, "Sponza and
Sibenik against Cycles", "A room lit through a window", "Walls at an angle" and "Where a voxel's light
is looked up";
scripts/scenes-vs-cycles.sh at VOXELS=64 writes the same figures).
Usage: scenes_reference.py path/to/dvsgi path/to/shared path/to/repository"""
import json
import os
import subprocess
import sys
import tempfile

dvsgi, shared, repo = sys.argv[1], sys.argv[2], sys.argv[3]
refs = os.path.join(repo, "docs/quality/cycles")
for need in (os.path.join(shared, "scenes/crytek-sponza"), os.path.join(shared, "scenes/sibenik"),
             os.path.join(shared, "reference/cornell-box"), os.path.join(refs, "sponza-sun.exr")):
    if not os.path.exists(need):
        print("FAIL: %s not found" % need)
        sys.exit(1)


def script(name, *args):
    """Runs scripts/NAME (the metrics the docs' figures come from) and returns its stdout."""
    run = subprocess.run([sys.executable, os.path.join(repo, "scripts", name), *args], capture_output=True,
                         text=True, timeout=600)
    if run.returncode != 0:
        print("FAIL: scripts/%s: %s" % (name, run.stderr.strip()))
        sys.exit(1)
    return run.stdout


def render(scene, out, width, height, *extra):
    subprocess.run([dvsgi, "render", scene, "--width", str(width), "--height", str(height), "--voxels", "64",
                    "--out", out, "--png", "none", "--quiet", "--validate", *extra], check=True, timeout=600)


# (name, measured direct ratio, measured indirect ratio), 320x180, 64^3, defaults.
SCENES = [("crytek-sponza/sponza-sun", 1.0051, 0.5965),
          ("crytek-sponza/sponza-point", 1.0133, 0.8489),
          ("sibenik/sibenik-point", 1.0076, 0.8985),
          ("window-room", 1.0001, 0.9497),
          ("window-room-spot", 0.9997, 0.9250),
          ("outdoor", 0.9989, 0.9867)]
# (name, measured mean-luminance ratio of the scene turned 45 degrees), 256x256, 64^3, defaults.
TURNED = [("cornell-lights", 1.0114), ("cornell-emissive", 0.9686)]

tmp = tempfile.mkdtemp(prefix="dvsgi-scenes-")
failures, checks = [], 0


def check(label, value, measured):
    global checks
    checks += 1
    bound = max(1.5 * abs(measured - 1.0), 0.005)
    ok = abs(value - 1.0) <= bound
    print("%-44s %.4f (measured %.4f, allowed 1 +- %.4f)%s" % (label, value, measured, bound, "" if ok else "  FAIL"))
    if not ok:
        failures.append("%s: %.4f beyond 1 +- %.4f" % (label, value, bound))


generated = {}
for name, generator, args in (("window-room", "window-room-scene.py", []),
                              ("window-room-spot", "window-room-scene.py", ["--spot"]),
                              ("outdoor", "outdoor-scene.py", [])):
    generated[name] = os.path.join(tmp, name + ".gltf")
    script(generator, generated[name], *args)
for scene, direct_measured, indirect_measured in SCENES:
    name = os.path.basename(scene)
    aov = os.path.join(tmp, name + "-aov.exr")
    path = generated.get(scene) or os.path.join(shared, "scenes", scene + ".gltf")
    render(path, os.path.join(tmp, name + ".exr"), 320, 180, "--aov", aov)
    metrics = os.path.join(tmp, name + ".json")
    script("scene-compare.py", os.path.join(refs, name), aov, "--json", metrics)
    with open(metrics) as f:
        r = json.load(f)
    check(name + " direct", r["direct"], direct_measured)
    check(name + " indirect", r["indirect"], indirect_measured)

for name, measured in TURNED:
    turned = os.path.join(tmp, name + "-turn45.gltf")
    script("turn-scene.py", os.path.join(shared, "scenes/cornell-box", name + ".gltf"), turned, "45")
    out = os.path.join(tmp, name + "-turn45.exr")
    render(turned, out, 256, 256, "--allow-outside-references")
    ratio = float(script("lum-ratio.py", out, os.path.join(shared, "reference/cornell-box", name + ".exr")))
    check(name + " turned 45 degrees", ratio, measured)

print("\n".join("FAIL " + f for f in failures))
print("%d passed, %d failed" % (checks - len(failures), len(failures)))
sys.exit(1 if failures else 0)
