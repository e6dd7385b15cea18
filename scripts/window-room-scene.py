#!/usr/bin/env python3
"""Writes a closed room lit by the sun through one window (docs/quality.md, "A room lit through a
window"): 4 m x 2.8 m x 5 m inside, walls, floor and ceiling 0.12 m thick, albedo 0.7, a window of
1.4 m x 1.2 m in the +x wall, a 0.8 m block on the floor, the sun (5 W/m^2) shining in from outside and
a camera in the far corner. Most of what the camera sees is lit only by bounced light, while the sun
lights the outside of the room and a patch of the floor directly: the case where a renderer's
bounces must converge against the indirect light, not against all of it. With --spot the sun is
replaced by a spot light under the ceiling (3 W/sr, cone 20 to 40 degrees) tilted toward the +x
wall: the room is lit from inside only, by a light type the shared scenes do not have.

    scripts/window-room-scene.py OUT.gltf [--spot] [--no-block]        (also writes OUT.bin)

--no-block leaves the block out (the sun's patch then lies on the bare floor).
"""
import math
import sys

from quad_gltf import box_quads, camera_and_light_nodes, write_quads

W, H, D, T = 4.0, 2.8, 5.0, 0.12  # inside x in [0, W], y in [0, H], z in [0, D]; wall thickness


def write_room(path, spot=False, block=True):
    quads = []
    for lo, hi in (([-T, -T, -T], [W + T, 0, D + T]),          # floor
                   ([-T, H, -T], [W + T, H + T, D + T]),        # ceiling
                   ([-T, 0, -T], [0, H, D + T]),                # wall x = 0
                   ([0, 0, -T], [W, H, 0]),                     # wall z = 0
                   ([0, 0, D], [W, H, D + T]),                  # wall z = D
                   ([W, 0, -T], [W + T, 0.9, D + T]),           # wall x = W below the window,
                   ([W, 2.1, -T], [W + T, H, D + T]),           # above it,
                   ([W, 0.9, -T], [W + T, 2.1, 1.8]),           # and on its two sides
                   ([W, 0.9, 3.2], [W + T, 2.1, D + T]),
                   ([1.2, 0, 1.5], [2.0, 0.9, 2.3])):           # the block
        if block or lo != [1.2, 0, 1.5]:
            quads += box_quads(lo, hi)
    eye, target = [0.4, 1.6, 4.6], [3.6, 0.9, 1.8]
    if spot:
        nodes = camera_and_light_nodes(eye, target, light_dir=[0.45, -1.0, -0.2], light_at=[1.8, H - 0.1, 2.8])
        light = {"type": "spot", "intensity": 3.0,
                 "spot": {"innerConeAngle": math.radians(20), "outerConeAngle": math.radians(40)}}
    else:
        nodes = camera_and_light_nodes(eye, target, light_dir=[-0.62, -0.55, 0.12])
        light = {"type": "directional", "intensity": 5.0}
    cameras = [{"type": "perspective", "perspective": {"yfov": 1.1, "aspectRatio": 16 / 9, "znear": 0.05, "zfar": 50}}]
    write_quads(path, quads, [0.7, 0.7, 0.7], nodes, cameras, [light])


if __name__ == "__main__":
    flags = sys.argv[2:]
    if len(sys.argv) < 2 or any(f not in ("--spot", "--no-block") for f in flags):
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    write_room(sys.argv[1], spot="--spot" in flags, block="--no-block" not in flags)
