#!/usr/bin/env python3
"""The six-cone set's cones one at a time, traced on the CPU at each pixel's surface point.

    scripts/cone-reference.py SCENE.gltf OUT.npy [--size 64] [--spp 32]

For every pixel (centre) of the scene's camera, and each of the paper's six cones around the
surface normal (the directions of gatherIrradiance6 in shaders/lib/cone_trace.glsl: one along the
normal, five at 60 degrees, 30-degree half-angle, same tangent basis), the mean radiance of the
direct-lit scene over the cone's solid angle, times the albedo: the first-bounce radiance the pixel
would get if that cone covered the whole hemisphere. OUT.npy holds them as (6, size, size, 3).
Compare with dvsgi built with DVSGI_SHADER_DEFINES=DVSGI_SINGLE_CONE=k (scripts/cone-check.sh).
Same scope as scripts/bounce-reference.py, whose loader and tracer it uses.
"""
import argparse
import importlib.util
import os

import numpy as np

spec = importlib.util.spec_from_file_location("bounce_reference",
                                              os.path.join(os.path.dirname(__file__), "bounce-reference.py"))
br = importlib.util.module_from_spec(spec)
spec.loader.exec_module(br)


def basis(v):
    """Unit vectors u, w with (u, w, v) orthonormal, per row."""
    a = np.where((np.abs(v[:, 0]) > 0.9)[:, None], np.array([[0.0, 1.0, 0.0]]), np.array([[1.0, 0.0, 0.0]]))
    u = np.cross(a, v)
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    return u, np.cross(v, u)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--spp", type=int, default=32)
    ap.add_argument("--seed", type=int, default=7)
    a = ap.parse_args()
    tris, albedo, lights, (eye, axes, yfov) = br.load(a.scene)
    tracer = br.Tracer(tris, albedo)
    rng = np.random.default_rng(a.seed)
    size, pix = a.size, np.arange(a.size * a.size)
    tan = np.tan(yfov / 2)
    px = (pix % size + 0.5) / size * 2 - 1
    py = 1 - (pix // size + 0.5) / size * 2
    d = axes[0][None] * (px * tan)[:, None] + axes[1][None] * (py * tan)[:, None] + axes[2][None]
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    o = np.broadcast_to(eye, d.shape).copy()
    t, tri = tracer.hit(o, d)
    h = tri >= 0
    p = o[h] + d[h] * t[h][:, None]
    n = tracer.normal[tri[h]]
    n = np.where((np.einsum("ij,ij->i", n, d[h]) > 0)[:, None], -n, n)
    rho = tracer.albedo[tri[h]]
    # coneBasis() of cone_trace.glsl.
    up = np.where((np.abs(n[:, 1]) < 0.99)[:, None], np.array([[0.0, 1.0, 0.0]]), np.array([[1.0, 0.0, 0.0]]))
    tt = np.cross(up, n)
    tt /= np.linalg.norm(tt, axis=1, keepdims=True)
    bb = np.cross(n, tt)
    cones = np.zeros((6, size * size, 3))
    for i in range(6):
        axis = n
        if i > 0:
            phi = 2 * np.pi * (i - 1) / 5
            axis = 0.5 * n + 0.8660254 * (np.cos(phi) * tt + np.sin(phi) * bb)
            axis /= np.linalg.norm(axis, axis=1, keepdims=True)
        u, w = basis(axis)
        for _ in range(a.spp):
            # Uniform over the 30-degree cap around the axis.
            c = 1 - rng.random(len(n)) * (1 - np.cos(np.pi / 6))
            s, ph = np.sqrt(1 - c * c), 2 * np.pi * rng.random(len(n))
            dirs = (s * np.cos(ph))[:, None] * u + (s * np.sin(ph))[:, None] * w + c[:, None] * axis
            t2, tri2 = tracer.hit(p + n * 1e-5, dirs)
            hit = (tri2 >= 0) & (np.einsum("ij,ij->i", dirs, n) > 0)
            radiance = np.zeros((len(n), 3))
            if hit.any():
                q = p[hit] + dirs[hit] * t2[hit][:, None]
                nq = tracer.normal[tri2[hit]]
                nq = np.where((np.einsum("ij,ij->i", nq, dirs[hit]) > 0)[:, None], -nq, nq)
                radiance[hit] = br.direct(tracer, lights, q, nq, tracer.albedo[tri2[hit]])
            cones[i][h] += rho * radiance / a.spp
    np.save(a.out, cones.reshape(6, size, size, 3).astype(np.float32))
    weights = np.array([1 / 3.5] + [0.5 / 3.5] * 5)
    means = [float((c @ br.LUM).mean()) for c in cones]
    print("per cone mean luminance: " + " ".join("%.5f" % m for m in means))
    print("six cones weighted (the paper's weights): %.5f" % float(np.dot(weights, means)))


if __name__ == "__main__":
    main()
