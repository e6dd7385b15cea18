#!/usr/bin/python3
"""A single render converges the bounces against the indirect light: in a room lit through a window
(scripts/window-room-scene.py), where the sun lights the outside walls and a patch of the floor
directly and the camera sees mostly bounced light, `--bounces auto` must come within 1 % of the
indirect light of 64 bounces (the default threshold leaves about 0.5 % of the voxels' reflected
light; measured 0.3 % here, and about 4 % short when the change was measured against all of the voxels'
light), say in the metrics that it converged, and stop well before 64 bounces. And the threshold
is honoured: a looser one stops sooner, darker.
Usage: converge_end_to_end.py path/to/dvsgi path/to/scripts"""
import json, os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from e2e import Runner, read, rgb  # noqa: E402

DVSGI, SCRIPTS = sys.argv[1], sys.argv[2]
TMP = tempfile.mkdtemp(prefix="dvsgi-converge-")
scene = os.path.join(TMP, "window-room.gltf")
subprocess.run([sys.executable, os.path.join(SCRIPTS, "window-room-scene.py"), scene], check=True)
R = Runner(DVSGI, ["render", scene, "--width", "160", "--height", "90", "--voxels", "64", "--png", "none",
                   "--quiet", "--validate", "--out", os.path.join(TMP, "frame.exr")])
LUM = np.array([0.2126, 0.7152, 0.0722])


def indirect(name, *extra):
    aov, metrics = os.path.join(TMP, name + "-aov.exr"), os.path.join(TMP, name + ".json")
    R.render(name, "--aov", aov, "--metrics", metrics, *extra)
    return float((rgb(read(aov)[0], "indirect") @ LUM).mean()), json.load(open(metrics))["bounces"]


full, _ = indirect("64 bounces", "--bounces", "64")
auto, b = indirect("converged", "--bounces", "auto")
loose, bl = indirect("converged, threshold 0.05", "--bounces", "auto", "--bounce-convergence", "0.05")
R.check(full > 0.0, "64 bounces give indirect light (%.5f)" % full)
R.check(0.99 <= auto / full <= 1.001, "converged: %.4f of 64 bounces' indirect light after %d bounces" %
        (auto / full, b["first_frame"]))
R.check(b["converged"] and b["first_frame"] < 32, "the metrics say it converged, in fewer than 32 bounces: %s" % b)
R.check(bl["first_frame"] < b["first_frame"] and loose < auto,
        "threshold 0.05: fewer bounces (%d), less light (%.4f of 64 bounces')" % (bl["first_frame"], loose / full))
R.finish()
