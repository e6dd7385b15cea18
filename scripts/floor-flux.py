#!/usr/bin/python3
"""The direct light the voxels hold on a room's floor against the floor's exact direct light.

    scripts/floor-flux.py SCENE.gltf DUMP.npy [DUMP.npy ...] --floor X0 X1 Z0 Z1 [--hole X0 X1 Z0 Z1]
                          [--points 200000] [--seed 1]

DUMP.npy: `dvsgi render SCENE.gltf --bounces 0 --voxel-dump DUMP.npy` (any image size; the grid is
what matters). The floor is the plane y = 0 over [X0, X1] x [Z0, Z1], less an optional covered
rectangle (--hole, e.g. a block standing on it). Prints, per dump, the floor voxels' summed direct
radiance times their face area (voxels whose normal is within 25 degrees of +y and whose centre lies
within a voxel of the floor) over the same integral traced exactly: uniform points on the floor, lit
with scripts/bounce-reference.py's tracer (its scope applies: constant albedos, punctual lights,
no node transforms). Also the light's centroid on the floor, both ways. Luminance (Rec. 709). For scripts/window-room-scene.py's room:
--floor 0 4 0 5 --hole 1.2 2.0 1.5 2.3.
"""
import argparse

import numpy as np

from tracer_probe import LUMA, dump_grid, scene_tracer

ap = argparse.ArgumentParser()
ap.add_argument("scene")
ap.add_argument("dumps", nargs="+")
ap.add_argument("--floor", type=float, nargs=4, required=True)
ap.add_argument("--hole", type=float, nargs=4)
ap.add_argument("--points", type=int, default=200000)
ap.add_argument("--seed", type=int, default=1)
a = ap.parse_args()

br, tracer, lights = scene_tracer(a.scene)

rng = np.random.default_rng(a.seed)
x0, x1, z0, z1 = a.floor
p = np.stack([x0 + rng.random(a.points) * (x1 - x0), np.zeros(a.points), z0 + rng.random(a.points) * (z1 - z0)], 1)
keep = np.ones(a.points, bool)
if a.hole:
    hx0, hx1, hz0, hz1 = a.hole
    keep = ~((p[:, 0] > hx0) & (p[:, 0] < hx1) & (p[:, 2] > hz0) & (p[:, 2] < hz1))
# The radiance under unit albedo, scaled by each point's own albedo below: the floor's
# material is found by the ray straight down onto it.
up = np.ascontiguousarray(np.broadcast_to(np.array([0.0, 1.0, 0.0]), p.shape))
_, tri = tracer.hit(p + up * 1e-3, -up)
if (tri < 0).any():
    raise SystemExit("floor-flux: %d points have no floor under them" % int((tri < 0).sum()))
radiance = br.direct(tracer, lights, p, up, tracer.albedo[tri], rng) @ LUMA
exact = (radiance * keep).sum() / a.points * (x1 - x0) * (z1 - z0)
w = radiance * keep
print("exact: the light's centroid on the floor at x %.3f, z %.3f" % ((w * p[:, 0]).sum() / w.sum(),
                                                                    (w * p[:, 2]).sum() / w.sum()))

for path in a.dumps:
    d, _, centre, size, _ = dump_grid(path)
    normal, direct = d[:, 6:9], d[:, 12:15] @ LUMA
    on = ((normal[:, 1] > np.cos(np.radians(25.0))) & (np.abs(centre[:, 1]) < size) &
          (centre[:, 0] > x0 - size) & (centre[:, 0] < x1 + size) & (centre[:, 2] > z0 - size) &
          (centre[:, 2] < z1 + size))
    held = direct[on].sum() * size * size
    v = direct * on
    print("%s: voxel %.4f m, %d floor voxels: held %.4f, exact %.4f, ratio %.4f; centroid x %.3f, z %.3f" %
          (path, size, on.sum(), held, exact, held / exact, (v * centre[:, 0]).sum() / v.sum(),
           (v * centre[:, 2]).sum() / v.sum()))
