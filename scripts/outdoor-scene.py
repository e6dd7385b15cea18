#!/usr/bin/env python3
"""Writes an open scene under the sun (docs/quality.md, "Outdoors"): a 20 m x 20 m ground and four
blocks from 0.7 m to 3.5 m high, albedo 0.6, the sun (3 W/m^2) 37 degrees high, a camera looking at
the blocks' shadowed sides. Nothing closes it: light that leaves goes to the black sky, the blocks'
shadowed sides and the ground in their shadows are lit by the sunlit ground and blocks, and the
fitted grid spreads its voxels over the whole ground (16.8 cm at 128^3).

    scripts/outdoor-scene.py OUT.gltf        (also writes OUT.bin)
"""
import sys

from quad_gltf import box_quads, camera_and_light_nodes, write_quads


def write_outdoor(path):
    quads = [([[-10, 0, -10], [-10, 0, 10], [10, 0, 10], [10, 0, -10]], [0, 1, 0])]
    for lo, hi in (([-3, 0, -2], [-1, 2.5, 0]), ([0.5, 0, -3], [2.5, 1.2, -1]), ([-0.5, 0, 1], [0.3, 3.5, 1.8]),
                   ([1.5, 1.2, -2.8], [2.2, 1.9, -2.1])):
        quads += box_quads(lo, hi)
    nodes = camera_and_light_nodes(eye=[3.5, 2.2, 5.5], target=[-0.3, 0.8, -1.0], light_dir=[0.5, -0.6, -0.62])
    cameras = [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 16 / 9, "znear": 0.05, "zfar": 100}}]
    write_quads(path, quads, [0.6, 0.6, 0.6], nodes, cameras, [{"type": "directional", "intensity": 3.0}])


if __name__ == "__main__":
    write_outdoor(sys.argv[1])
