#!/usr/bin/env python3
"""Writes a sunlit floor with a wall standing on it (docs/quality.md, "A room lit through a window"): a
10 m x 10 m floor at y = 0, a 4 m wide, 3 m high wall at x = 0 facing +x, albedo 0.7, a sun of 1 W/m^2
nearly overhead (its shadow falls behind the wall), and a camera looking at the wall's lit face. The
floor in front of the wall is lit evenly, so the wall's first bounce checks how the pixels' rays read a
floor they cross at every angle, grazing ones included, where the light does not depend on where they
meet it. For the CPU tracer (scripts/bounce-reference.py) and dvsgi.

    scripts/lit-floor-scene.py OUT.gltf        (also writes OUT.bin)
"""
import sys

from quad_gltf import box_quads, camera_and_light_nodes, write_quads

if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    quads = [box_quads([-5, -0.1, -5], [5, 0, 5])[2],   # the floor's top
             box_quads([-0.1, 0, -2], [0, 3, 2])[0]]     # the wall's +x face
    nodes = camera_and_light_nodes([4.0, 1.5, 0.0], [0.0, 1.2, 0.0], light_dir=[-0.1, -1.0, 0.05])
    cameras = [{"type": "perspective", "perspective": {"yfov": 1.0, "aspectRatio": 1.0, "znear": 0.05, "zfar": 50}}]
    write_quads(sys.argv[1], quads, [0.7, 0.7, 0.7], nodes, cameras, [{"type": "directional", "intensity": 1.0}])
