#!/usr/bin/python3
"""A wall's first bounce with the true geometry, lit once exactly and once by the voxels' light.

    scripts/wall-gather-probe.py SCENE.gltf DUMP.npy [--x 0] [--z 1 4] [--points 4000] [--rays 16] [--seed 3]

DUMP.npy: `dvsgi render SCENE.gltf --bounces 0 --voxel-dump DUMP.npy`. Receivers: points on the plane
x = X facing +x, z in the given range, in bands of height. From each, cosine rays find the true surface
they meet (scripts/bounce-reference.py's tracer; its scope applies), and the light leaving it is taken
twice: traced exactly, and as the direct light of the voxel that holds that point (the voxel just behind
the surface). Prints per band the two means and their ratio: where the ratio is 1 and dvsgi's gather is
not, the error lies in where the gather's rays meet the voxels, not in the voxels' light.
"""
import argparse

import numpy as np

from tracer_probe import LUMA, dump_grid, scene_tracer

ap = argparse.ArgumentParser()
ap.add_argument("scene")
ap.add_argument("dump")
ap.add_argument("--x", type=float, default=0.0)
ap.add_argument("--z", type=float, nargs=2, default=[1.0, 4.0])
ap.add_argument("--points", type=int, default=4000)
ap.add_argument("--rays", type=int, default=16)
ap.add_argument("--seed", type=int, default=3)
a = ap.parse_args()

br, tracer, lights = scene_tracer(a.scene)
d, grid, centre, size, origin = dump_grid(a.dump)
direct = d[:, 12:15] @ LUMA
light_of = {tuple(g): v for g, v in zip(grid, direct)}

rng = np.random.default_rng(a.seed)
print("| heights (m) | exact | the voxels' light at the true hits | ratio |")
print("|---|---|---|---|")
for h0, h1 in [(0.02, 0.2), (0.2, 0.5), (0.5, 1.0), (1.0, 2.0), (2.0, 2.7)]:
    n = a.points
    p = np.stack([np.full(n, a.x + 1e-4), h0 + rng.random(n) * (h1 - h0), a.z[0] + rng.random(n) * (a.z[1] - a.z[0])], 1)
    p = np.repeat(p, a.rays, 0)
    normal = np.ascontiguousarray(np.broadcast_to(np.array([1.0, 0.0, 0.0]), p.shape))
    dirs = np.ascontiguousarray(br.cosine_directions(normal, rng))
    t, tri = tracer.hit(p + normal * 1e-5, dirs)
    ok = tri >= 0
    hit, hn, rho = br.surface(tracer, p[ok] + normal[ok] * 1e-5, dirs[ok], t[ok], tri[ok])
    exact = br.direct(tracer, lights, hit, hn, rho, rng) @ LUMA
    cells = np.floor((hit - origin) / size - 1e-4 * hn).astype(int)
    held = np.array([light_of.get(tuple(c), 0.0) for c in cells])
    print("| %.2f–%.2f | %.5f | %.5f | %.3f |" % (h0, h1, exact.sum() / len(p), held.sum() / len(p),
                                                held.sum() / exact.sum()))
