#!/usr/bin/env python3
"""Writes the slab of docs/quality.md ("A slab across the lattice"): a sunlit slab 0.7 of a voxel thick
(1.2 m high, 2.4 m wide) standing on a ground box 3.8 m square, albedo 0.8, for the grid
`--voxels 64 --voxel-box=-2,-2,-2,2,2,2` (voxels of 0.0625 m). The slab's faces lie at x = OFFSET and
OFFSET + 0.7 voxels: at offsets under 0.3 both lie in one voxel layer, above it in two. Sun of 3 W/m^2
along (-1, -1, -0.2), a camera 3 m above the ground looking straight down (image right = +x).

    scripts/slab-scene.py OUT.gltf OFFSET        (also writes OUT.bin)
"""
import math
import sys

from quad_gltf import box_quads, quat_from_to, quat_x, write_quads

VOXEL = 4.0 / 64


def write_slab(path, offset):
    quads = box_quads([-1.9, -2 * VOXEL, -1.9], [1.9, 0.0, 1.9]) + \
        box_quads([offset * VOXEL, 0.0, -1.2], [(offset + 0.7) * VOXEL, 1.2, 1.2])
    d = [-1.0, -1.0, -0.2]
    length = math.sqrt(sum(x * x for x in d))
    sun = quat_from_to([0.0, 0.0, -1.0], [x / length for x in d])
    nodes = [{"camera": 0, "translation": [0, 3.0, 0], "rotation": quat_x(-math.pi / 2)},
             {"rotation": sun, "extensions": {"KHR_lights_punctual": {"light": 0}}}]
    cameras = [{"type": "perspective",
                "perspective": {"yfov": math.radians(50), "aspectRatio": 1.0, "znear": 0.01, "zfar": 100}}]
    write_quads(path, quads, [0.8, 0.8, 0.8], nodes, cameras, [{"type": "directional", "intensity": 3.0}])


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    write_slab(sys.argv[1], float(sys.argv[2]))
