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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--spp", type=int, default=32)
    ap.add_argument("--seed", type=int, default=7)
    a = ap.parse_args()
    tris, albedo, lights, camera = br.load(a.scene)
    tracer = br.Tracer(tris, albedo)
    rng = np.random.default_rng(a.seed)
    size = a.size
    o, d = br.camera_rays(camera, size, (0.5, 0.5))
    t, tri = tracer.hit(o, d)
    h = tri >= 0
    p, n, rho = br.surface(tracer, o[h], d[h], t[h], tri[h])
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
        u, w = br.orthonormal_basis(axis)
        for _ in range(a.spp):
            # Uniform over the 30-degree cap around the axis.
            c = 1 - rng.random(len(n)) * (1 - np.cos(np.pi / 6))
            s, ph = np.sqrt(1 - c * c), 2 * np.pi * rng.random(len(n))
            dirs = (s * np.cos(ph))[:, None] * u + (s * np.sin(ph))[:, None] * w + c[:, None] * axis
            t2, tri2 = tracer.hit(p + n * 1e-5, dirs)
            hit = (tri2 >= 0) & (np.einsum("ij,ij->i", dirs, n) > 0)
            radiance = np.zeros((len(n), 3))
            if hit.any():
                q, nq, rq = br.surface(tracer, p[hit], dirs[hit], t2[hit], tri2[hit])
                radiance[hit] = br.direct(tracer, lights, q, nq, rq)
            cones[i][h] += rho * radiance / a.spp
    np.save(a.out, cones.reshape(6, size, size, 3).astype(np.float32))
    weights = np.array([1 / 3.5] + [0.5 / 3.5] * 5)
    means = [float((c @ br.LUM).mean()) for c in cones]
    print("per cone mean luminance: " + " ".join("%.5f" % m for m in means))
    print("six cones weighted (the paper's weights): %.5f" % float(np.dot(weights, means)))


if __name__ == "__main__":
    main()
