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

from quad_gltf import quat_x, write_quads

VOXEL = 4.0 / 64


def quat_from_to(a, b):
    """The rotation taking unit vector a to unit vector b (not opposite)."""
    axis = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    s = math.sqrt(sum(x * x for x in axis))
    angle = math.atan2(s, sum(x * y for x, y in zip(a, b)))
    return [x / s * math.sin(angle / 2) for x in axis] + [math.cos(angle / 2)]


def box_quads(lo, hi):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    return [([[x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]], [1, 0, 0]),
            ([[x0, y0, z1], [x0, y1, z1], [x0, y1, z0], [x0, y0, z0]], [-1, 0, 0]),
            ([[x0, y1, z0], [x0, y1, z1], [x1, y1, z1], [x1, y1, z0]], [0, 1, 0]),
            ([[x0, y0, z1], [x0, y0, z0], [x1, y0, z0], [x1, y0, z1]], [0, -1, 0]),
            ([[x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], [0, 0, 1]),
            ([[x1, y0, z0], [x0, y0, z0], [x0, y1, z0], [x1, y1, z0]], [0, 0, -1])]


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
