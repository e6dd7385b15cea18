#!/usr/bin/env python3
"""Writes an open scene under the sun (docs/quality.md, "Outdoors"): a 20 m x 20 m ground and four
blocks from 0.7 m to 3.5 m high, albedo 0.6, the sun (3 W/m^2) 37 degrees high, a camera looking at
the blocks' shadowed sides. Nothing closes it: light that leaves goes to the black sky, the blocks'
shadowed sides and the ground in their shadows are lit by the sunlit ground and blocks, and the
fitted grid spreads its voxels over the whole ground (16.8 cm at 128^3).

    scripts/outdoor-scene.py OUT.gltf [--square | --from-above]       (also writes OUT.bin)

--square: the same camera with a square image (for scripts/bounce-reference.py, which traces square
images); --from-above: a square view straight down from 14 m (docs/quality.md, "Surfaces' extent
inside their voxels").
"""
import math
import sys

from quad_gltf import box_quads, camera_and_light_nodes, quat_x, write_quads


def write_outdoor(path, view=None):
    quads = [([[-10, 0, -10], [-10, 0, 10], [10, 0, 10], [10, 0, -10]], [0, 1, 0])]
    for lo, hi in (([-3, 0, -2], [-1, 2.5, 0]), ([0.5, 0, -3], [2.5, 1.2, -1]), ([-0.5, 0, 1], [0.3, 3.5, 1.8]),
                   ([1.5, 1.2, -2.8], [2.2, 1.9, -2.1])):
        quads += box_quads(lo, hi)
    nodes = camera_and_light_nodes(eye=[3.5, 2.2, 5.5], target=[-0.3, 0.8, -1.0], light_dir=[0.5, -0.6, -0.62])
    perspective = {"yfov": 0.9, "aspectRatio": 16 / 9, "znear": 0.05, "zfar": 100}
    if view == "--square":
        perspective["aspectRatio"] = 1.0
    elif view == "--from-above":
        # Looking along -y: the camera's -z turned down by a quarter turn about x.
        nodes[0] = {"camera": 0, "translation": [0.0, 14.0, 0.0], "rotation": quat_x(-math.pi / 2)}
        perspective.update(yfov=0.8, aspectRatio=1.0)
    write_quads(path, quads, [0.6, 0.6, 0.6], nodes, [{"type": "perspective", "perspective": perspective}],
                [{"type": "directional", "intensity": 3.0}])


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3) or (len(sys.argv) == 3 and sys.argv[2] not in ("--square", "--from-above")):
        sys.exit("usage: scripts/outdoor-scene.py OUT.gltf [--square | --from-above]")
    write_outdoor(sys.argv[1], sys.argv[2] if len(sys.argv) == 3 else None)
