#!/usr/bin/env python3
"""Writes the lit corner of docs/quality.md ("One bounce at a time"): a 4 m x 4 m floor and a 4 m
high wall along its back edge, albedo 0.8, a sun from above and in front at 50 degrees, and a camera
looking at the corner.

    scripts/corner-scene.py OUT.gltf        (also writes OUT.bin)
"""
import math
import sys

from quad_gltf import quat_x, write_quads


def write_corner(path):
    quads = [([[-2, 0, -2], [-2, 0, 2], [2, 0, 2], [2, 0, -2]], [0, 1, 0]),
             ([[-2, 0, -2], [2, 0, -2], [2, 4, -2], [-2, 4, -2]], [0, 0, 1])]
    nodes = [{"camera": 0, "translation": [0, 2.0, 4.5], "rotation": quat_x(-math.radians(15))},
             {"rotation": quat_x(-math.radians(50)), "extensions": {"KHR_lights_punctual": {"light": 0}}}]
    cameras = [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 1.0, "znear": 0.01, "zfar": 100}}]
    write_quads(path, quads, [0.8, 0.8, 0.8], nodes, cameras, [{"type": "directional", "intensity": 1.0}])


if __name__ == "__main__":
    write_corner(sys.argv[1])
