#!/usr/bin/python3
"""A wall's first bounce with the true geometry, lit once exactly and once by the voxels' light.

    scripts/wall-gather-probe.py SCENE.gltf DUMP.npy [--x 0] [--facing +x|-x] [--z 1 4] [--hole Y0 Y1 Z0 Z1]
                                 [--points 4000] [--rays 16] [--seed 3] [--march normal|ray]
                                 [--floor-x X0 X1]

DUMP.npy: `dvsgi render SCENE.gltf --bounces 0 --voxel-dump DUMP.npy`. Receivers: points on the plane
x = X facing +x (or -x), z in the given range, in bands of height, less those inside --hole (a window
in that wall: heights Y0-Y1, z Z0-Z1). From each, cosine rays find the true surface they meet
(scripts/bounce-reference.py's tracer; its scope applies), and the light leaving it is taken twice:
traced exactly, and as the direct light of the voxel that holds that point (the voxel just behind the
surface). Prints per band the two means and their ratio: where the ratio is 1 and dvsgi's gather is
not, the error lies in where the gather's rays meet the voxels, not in the voxels' light.

--march also walks each ray through the dump's voxels, with the core of the gather's rules
(lib/voxel_rays.glsl: voxels of the receiver's own surface passed, a voxel whose normal lies along an
axis met where the ray reaches the plane through its centre, a one-sided voxel seen from behind
dark), starting a voxel off the wall along its normal (`normal`, as the gather does) or on the ray,
as far along it as reaches a voxel off the wall (`ray`, at most two voxels along it), and adds the
light it meets as a fourth column. Slow: use --points 300 or so.
--floor-x prints, over all bands, the light the rays meet on the floor (normal +y) by 10 cm in x:
where the voxels hold a lit patch that the exact light does not.
"""
import argparse

import numpy as np

from tracer_probe import LUMA, dump_grid, scene_tracer

ap = argparse.ArgumentParser()
ap.add_argument("scene")
ap.add_argument("dump")
ap.add_argument("--x", type=float, default=0.0)
ap.add_argument("--facing", choices=["+x", "-x"], default="+x")
ap.add_argument("--z", type=float, nargs=2, default=[1.0, 4.0])
ap.add_argument("--hole", type=float, nargs=4, default=None)
ap.add_argument("--points", type=int, default=4000)
ap.add_argument("--rays", type=int, default=16)
ap.add_argument("--seed", type=int, default=3)
ap.add_argument("--march", choices=["normal", "ray"])
ap.add_argument("--floor-x", type=float, nargs=2)
a = ap.parse_args()

br, tracer, lights = scene_tracer(a.scene)
d, grid, centre, size, origin = dump_grid(a.dump)
direct = d[:, 12:15] @ LUMA
light_of = {tuple(g): v for g, v in zip(grid, direct)}
slot_of = {tuple(g): i for i, g in enumerate(grid)}
normals = d[:, 6:9].astype(np.float64)
N = int(round((centre[:, 0].max() - origin[0]) / size)) + 1  # at least the grid's extent along x
N = max(N, int(grid.max()) + 1)


def along_axis(n):
    m = np.abs(n)
    return m.max() >= 0.98 * max(np.linalg.norm(n), 1e-9)


def exit_t(p, inv, c):
    return np.min(np.maximum((c - p) * inv, (c + 1 - p) * inv))


def march(p, dv, wall, n):
    """The light a ray from voxel-space point p along dv meets (receiver on voxel-space plane point
    `wall`, normal n)."""
    inv = 1.0 / np.where(np.abs(dv) < 1e-7, 1e-7, dv)
    t = 0.0
    for _ in range(4 * N):
        q = p + dv * t
        c = np.floor(q).astype(int)
        k = slot_of.get(tuple(c))
        if k is not None:
            nc = normals[k]
            own = abs(np.dot(c + 0.5 - wall, n)) < 1.5 and np.dot(nc, n) > 0.8
            front = False
            if along_axis(nc) and not own:
                u = nc / np.linalg.norm(nc)
                ahead, toward = np.dot(c + 0.5 - q, u), np.dot(dv, u)
                front = ahead * toward > 0 and t + ahead / toward > exit_t(p, inv, c)
            if not own and not front:
                behind = np.dot(nc, nc) > 0.25 and np.dot(nc, dv) > 0
                return 0.0 if behind else direct[k]
        t = exit_t(p, inv, c) + 1e-3
        if np.any(np.floor(p + dv * t) < -1) or np.any(np.floor(p + dv * t) > N):
            return 0.0
    return 0.0


rng = np.random.default_rng(a.seed)
sign = 1.0 if a.facing == "+x" else -1.0
wall_n = np.array([sign, 0.0, 0.0])
floor_x = []
head = "| heights (m) | exact | the voxels' light at the true hits | ratio |"
if a.march:
    head += " marched through the voxels (start: %s) | ratio |" % a.march
print(head)
print("|---" * (4 + 2 * bool(a.march)) + "|")
for h0, h1 in [(0.02, 0.2), (0.2, 0.5), (0.5, 1.0), (1.0, 2.0), (2.0, 2.7)]:
    n = a.points
    p = np.stack([np.full(n, a.x + sign * 1e-4), h0 + rng.random(n) * (h1 - h0), a.z[0] + rng.random(n) * (a.z[1] - a.z[0])], 1)
    if a.hole:
        y0, y1, z0, z1 = a.hole
        p = p[~((p[:, 1] > y0) & (p[:, 1] < y1) & (p[:, 2] > z0) & (p[:, 2] < z1))]
    p = np.repeat(p, a.rays, 0)
    normal = np.ascontiguousarray(np.broadcast_to(wall_n, p.shape))
    dirs = np.ascontiguousarray(br.cosine_directions(normal, rng))
    t, tri = tracer.hit(p + normal * 1e-5, dirs)
    ok = tri >= 0
    hit, hn, rho = br.surface(tracer, p[ok] + normal[ok] * 1e-5, dirs[ok], t[ok], tri[ok])
    exact = br.direct(tracer, lights, hit, hn, rho, rng) @ LUMA
    cells = np.floor((hit - origin) / size - 1e-4 * hn).astype(int)
    held = np.array([light_of.get(tuple(c), 0.0) for c in cells])
    row = "| %.2f–%.2f | %.5f | %.5f | %.3f |" % (h0, h1, exact.sum() / len(p), held.sum() / len(p),
                                                 held.sum() / exact.sum())
    if a.march:
        got = 0.0
        for j in range(len(p)):
            pv = (p[j] - origin) / size
            if a.march == "normal":
                start = pv + wall_n
            else:
                start = pv + dirs[j] / max(float(dirs[j] @ wall_n), 0.5)
            got += march(start, dirs[j], pv, wall_n)
        row += " %.5f | %.3f |" % (got / len(p), got / exact.sum())
    print(row, flush=True)
    if a.floor_x:
        on_floor = hn[:, 1] > 0.9
        floor_x.append((hit[on_floor, 0], exact[on_floor], held[on_floor], len(p)))

if a.floor_x:
    xs = np.concatenate([f[0] for f in floor_x])
    ex = np.concatenate([f[1] for f in floor_x])
    he = np.concatenate([f[2] for f in floor_x])
    rays = sum(f[3] for f in floor_x)
    print()
    print("| floor x (m) | exact | the voxels' light |")
    print("|---|---|---|")
    for x0 in np.arange(a.floor_x[0], a.floor_x[1] - 1e-9, 0.1):
        m = (xs >= x0) & (xs < x0 + 0.1)
        print("| %.1f–%.1f | %.5f | %.5f |" % (x0, x0 + 0.1, ex[m].sum() / rays, he[m].sum() / rays))
