#!/usr/bin/env python3
"""The voxels' own light against a tracer, voxel by voxel.

    dvsgi render SCENE.gltf --bounces K-1 --voxel-dump D0.npy ...
    dvsgi render SCENE.gltf --bounces K --voxel-dump D1.npy ...   (same grid)
    scripts/voxel-truth.py SCENE.gltf D0.npy D1.npy [--bounce K] [--voxels 20000] [--spp 64] [--seed 1]
                           [--json OUT.json]

For a sample of the one-sided voxels with a normal, finds the surface each
voxel holds as seen from its front (rays cast along -normal from two voxels in
front, kept where they hit inside the voxel), and traces there the direct
light (radiance leaving the surface) and the K-th bounce (K = 1, the default:
one cosine ray per point to a directly lit surface; K = 2: a path of two), with
the tracer of scripts/bounce-reference.py (whose scope applies: constant
albedos, punctual lights and emitters, no node transforms). It prints, per class
of voxel (walls along each axis, others such as edges and tilted surfaces), the
voxels' summed direct light (D0's) and the light the K-th voxel bounce added
(D1 radiance - D0 radiance) over the traced sums, and each class's share of the
traced K-th bounce. The renders' image size does not
matter; the voxels do. This separates the voxels' light from how rays see the
voxels: an image that is off while this is right is off in the gather.
"""
import argparse
import importlib.util
import json
import os
import sys

import numpy as np

LUM = np.array([0.2126, 0.7152, 0.0722])


def fail(msg):
    print("voxel-truth: " + msg, file=sys.stderr)
    sys.exit(1)


def load_dump(path):
    try:
        d = np.load(path)
    except (OSError, ValueError) as e:
        fail("%s: %s" % (path, e))
    if d.ndim != 2 or d.shape[1] != 26 or d.dtype != np.float32:
        fail("%s: not a dvsgi --voxel-dump table (float32, 26 columns)" % path)
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("dump0")
    ap.add_argument("dump1")
    ap.add_argument("--voxels", type=int, default=20000, help="voxels sampled (0 = all)")
    ap.add_argument("--spp", type=int, default=64, help="surface points per voxel")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--bounce", type=int, default=1, help="the bounce D1 adds to D0 (1-4)")
    ap.add_argument("--json", help="also write the table's rows here")
    a = ap.parse_args()
    if a.voxels < 0 or a.spp < 8 or not 1 <= a.bounce <= 4:
        fail("--voxels must be >= 0, --spp >= 8 and --bounce 1-4")
    spec = importlib.util.spec_from_file_location("bounce_reference",
                                                  os.path.join(os.path.dirname(__file__), "bounce-reference.py"))
    br = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(br)
    tris, albedo, emission, lights, _ = br.load(a.scene)
    tracer = br.Tracer(tris, albedo, emission)
    d0, d1 = load_dump(a.dump0), load_dump(a.dump1)
    if d0.shape != d1.shape or not np.array_equal(d0[:, :3], d1[:, :3]):
        fail("%s and %s hold different voxels (render both on the same grid)" % (a.dump0, a.dump1))
    grid, centre, normal = d0[:, 0:3].astype(np.float64), d0[:, 3:6].astype(np.float64), d0[:, 6:9].astype(np.float64)
    # centre = origin + (grid + 0.5) * size along each axis: the size by least squares over x.
    size = float(np.polyfit(grid[:, 0] + 0.5, centre[:, 0], 1)[0]) if np.ptp(grid[:, 0]) > 0 else 0.0
    if not size > 0:
        fail("%s: cannot tell the voxel size (one column of voxels)" % a.dump0)
    rng = np.random.default_rng(a.seed)
    usable = np.flatnonzero((d0[:, 18] == 0) & (np.linalg.norm(normal, axis=1) > 0.5))
    chosen = usable if a.voxels == 0 or a.voxels >= len(usable) else rng.choice(usable, a.voxels, replace=False)
    points, normals, rhos, owner = [], [], [], []
    for i in chosen:
        n = normal[i] / np.linalg.norm(normal[i])
        lo = centre[i] - 0.5 * size
        start = lo + rng.random((a.spp, 3)) * size + n * (2.0 * size)
        t, tri = tracer.hit(start, np.ascontiguousarray(np.broadcast_to(-n, start.shape)), 4.0 * size)
        hit = start - n * np.where(tri >= 0, t, 0.0)[:, None]
        ok = (tri >= 0) & np.all((hit >= lo - 1e-7) & (hit <= lo + size + 1e-7), axis=1)
        if ok.sum() < a.spp // 8:
            continue  # the voxel's surface is not seen from its front (or the scene differs)
        tn = tracer.normal[tri[ok]]
        points.append(hit[ok])
        normals.append(np.where((tn @ n > 0)[:, None], tn, -tn))
        rhos.append(tracer.albedo[tri[ok]])
        owner.append(np.full(ok.sum(), i))
    if not points:
        fail("no voxel's surface found in %s: is it the scene the dumps were rendered from?" % a.scene)
    p, n, rho, owner = map(np.concatenate, (points, normals, rhos, owner))
    direct = br.direct(tracer, lights, p, n, rho, rng) @ LUM
    # One path of `bounce` cosine steps per point: its radiance is the receiver's albedo, times each
    # surface passed on the way's, times the direct light leaving the last.
    first = np.zeros(len(p))
    alive = np.arange(len(p))
    at, towards, weight = p, n, rho.copy()
    for step in range(a.bounce):
        d = br.cosine_directions(towards, rng)
        o = at + towards * 1e-5
        t, tri = tracer.hit(o, d)
        hit = tri >= 0
        alive, weight = alive[hit], weight[hit]
        at, towards, ha = br.surface(tracer, o[hit], d[hit], t[hit], tri[hit])
        if step + 1 < a.bounce:
            weight = weight * ha
        else:
            first[alive] = (weight * br.direct(tracer, lights, at, towards, ha, rng)) @ LUM
    voxels, inverse = np.unique(owner, return_inverse=True)
    count = np.bincount(inverse)
    t0 = np.bincount(inverse, direct) / count
    t1 = np.bincount(inverse, first) / count
    v0 = d0[voxels, 12:15] @ LUM
    v1 = (d1[voxels, 15:18] - d0[voxels, 15:18]) @ LUM
    m = np.abs(normal[voxels]) / np.linalg.norm(normal[voxels], axis=1, keepdims=True)
    axis = m.argmax(axis=1)
    sign = np.sign(normal[voxels, :][np.arange(len(voxels)), axis])
    cls = np.where(m.max(axis=1) > 0.99, axis * 2 + (sign < 0), 6)
    names = ["+x", "-x", "+y", "-y", "+z", "-z", "other"]
    print("<!-- scripts/voxel-truth.py %s %s %s --bounce %d --voxels %d --spp %d --seed %d; voxel %.5f m -->" %
          (a.scene, a.dump0, a.dump1, a.bounce, a.voxels, a.spp, a.seed, size))
    print("| voxels (normal) | count | direct light: voxels / traced | bounce %d: voxels / traced | share of the traced bounce %d |"
          % (a.bounce, a.bounce))
    print("|---|---|---|---|---|")
    rows = [(names[c], cls == c) for c in range(7)] + [("all", np.ones(len(voxels), bool))]
    table = {}
    for name, sel in rows:
        if not sel.any():
            continue
        table[name] = {"count": int(sel.sum()), "direct": v0[sel].sum() / max(t0[sel].sum(), 1e-30),
                       "bounce": v1[sel].sum() / max(t1[sel].sum(), 1e-30),
                       "share": t1[sel].sum() / max(t1.sum(), 1e-30)}
        r = table[name]
        print("| %s | %d | %.4f | %.4f | %.3f |" % (name, r["count"], r["direct"], r["bounce"], r["share"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"voxel_size": size, "bounce": a.bounce, "rows": table}, f, indent=2)


if __name__ == "__main__":
    main()
