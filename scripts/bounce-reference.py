#!/usr/bin/env python3
"""Per-bounce reference radiance of a small glTF scene, traced on the CPU.

    scripts/bounce-reference.py SCENE.gltf OUT_PREFIX [--size 64] [--spp 64] [--bounces 6] [--pixel-centres]

Writes OUT_PREFIX-direct.npy and OUT_PREFIX-bounceK.npy (K = 1..bounces): the
radiance each bounce adds, per pixel (float32, rows top to bottom, linear RGB),
and prints their mean luminances. Path-traced references hold the converged
sum; splitting it per bounce shows which part of a renderer's transport is off
(the pixel gather's first bounce, the voxel bounce's later ones), because with
white walls a small error per bounce is multiplied several times over.

Scope, stated so nobody reads more into it: Lambertian materials with a
constant baseColorFactor (no textures), punctual point and directional lights
(ideal, inverse square, hard shadows), one-sided emissive triangles (emissiveFactor
x KHR_materials_emissive_strength, front face by winding; sampled by area at
every hit, so a path that meets an emitter after the first hit adds nothing:
its light came through that sampling), meshes under nodes without
transforms, the scene's first camera node (translation + rotation). Pixel
centres jittered within the pixel (box filter, as the path-traced references
are), or with --pixel-centres every sample through the pixel's centre (as a
rasterizer's G-buffer samples it: an edge pixel then shows one surface, not
a blend of the two), cosine-weighted hemisphere
sampling, back faces reflect like front faces (shared/reference/CONVENTIONS.md).
Brute force with numpy: fine for tens of triangles, not for Sponza.
"""
import argparse
import json
import os
import sys

import numpy as np

LUM = np.array([0.2126, 0.7152, 0.0722])


def fail(msg):
    print("bounce-reference: " + msg, file=sys.stderr)
    sys.exit(1)


def quat_rotate(q, v):
    x, y, z, w = q
    u = np.array([x, y, z])
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def load(path):
    try:
        g = json.load(open(path))
    except (OSError, ValueError) as e:
        fail("%s: %s" % (path, e))
    base = os.path.dirname(path)
    blobs = [open(os.path.join(base, b["uri"]), "rb").read() for b in g["buffers"]]

    def accessor(i):
        a = g["accessors"][i]
        view = g["bufferViews"][a["bufferView"]]
        comps = {"SCALAR": 1, "VEC3": 3}[a["type"]]
        dtype = {5126: np.float32, 5123: np.uint16, 5125: np.uint32}[a["componentType"]]
        off = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        return np.frombuffer(blobs[view["buffer"]], dtype, a["count"] * comps, off).reshape(-1, comps)

    tris, albedo, emission = [], [], []
    for node in g["nodes"]:
        if "mesh" not in node:
            continue
        if any(k in node for k in ("matrix", "translation", "rotation", "scale")):
            fail("%s: node %s has a transform (not supported here)" % (path, node.get("name")))
        for prim in g["meshes"][node["mesh"]]["primitives"]:
            pos = accessor(prim["attributes"]["POSITION"]).astype(np.float64)
            idx = accessor(prim["indices"]).reshape(-1, 3)
            mat = g["materials"][prim["material"]]
            if "emissiveTexture" in mat:
                fail("%s: emissive textures are not supported here" % path)
            strength = mat.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
            rho = mat.get("pbrMetallicRoughness", {}).get("baseColorFactor", [1, 1, 1, 1])[:3]
            tris.append(pos[idx])
            albedo += [rho] * len(idx)
            emission += [[c * strength for c in mat.get("emissiveFactor", [0, 0, 0])]] * len(idx)
    tris = np.concatenate(tris)
    lights = []
    for node in g["nodes"]:
        ext = node.get("extensions", {}).get("KHR_lights_punctual")
        if ext is None:
            continue
        l = g["extensions"]["KHR_lights_punctual"]["lights"][ext["light"]]
        colour = np.array(l.get("color", [1, 1, 1])) * l.get("intensity", 1.0)
        q = node.get("rotation", [0, 0, 0, 1])
        if l["type"] == "point":
            lights.append(("point", np.array(node["translation"], float), colour))
        elif l["type"] == "directional":
            lights.append(("sun", quat_rotate(q, np.array([0.0, 0.0, -1.0])), colour))
        else:
            fail("%s: light type %s is not supported here" % (path, l["type"]))
    cam_node = next(n for n in g["nodes"] if "camera" in n)
    cam = g["cameras"][cam_node["camera"]]["perspective"]
    q = cam_node.get("rotation", [0, 0, 0, 1])
    eye = np.array(cam_node.get("translation", [0, 0, 0]), float)
    axes = [quat_rotate(q, np.array(v, float)) for v in ([1, 0, 0], [0, 1, 0], [0, 0, -1])]
    return tris, np.array(albedo, float), np.array(emission, float), lights, (eye, axes, cam["yfov"])


class Tracer:
    def __init__(self, tris, albedo, emission):
        self.v0 = tris[:, 0]
        self.e1 = tris[:, 1] - tris[:, 0]
        self.e2 = tris[:, 2] - tris[:, 0]
        n = np.cross(self.e1, self.e2)
        area = 0.5 * np.linalg.norm(n, axis=1)
        self.normal = n / (2.0 * area)[:, None]
        self.albedo = albedo
        self.emission = emission
        # Emitters, chosen with probability proportional to their area.
        self.emitters = np.flatnonzero(emission.max(axis=1) > 0)
        self.emitter_area = float(area[self.emitters].sum())
        self.emitter_cdf = np.cumsum(area[self.emitters]) / max(self.emitter_area, 1e-30)

    def hit(self, o, d, tmax=np.inf):
        """Nearest hit per ray (Moller-Trumbore against every triangle): t and triangle (-1 = none)."""
        best_t = np.full(len(o), np.inf)
        best_i = np.full(len(o), -1)
        for i in range(len(self.v0)):
            p = np.cross(d, self.e2[i])
            det = p @ self.e1[i]
            ok = np.abs(det) > 1e-12
            inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
            s = o - self.v0[i]
            u = np.einsum("ij,ij->i", s, p) * inv
            qv = np.cross(s, self.e1[i])
            v = np.einsum("ij,ij->i", d, qv) * inv
            t = qv @ self.e2[i] * inv
            good = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 1e-6) & (t < best_t) & (t < tmax)
            best_t = np.where(good, t, best_t)
            best_i = np.where(good, i, best_i)
        return best_t, best_i


def emitted_light(tracer, p, n, rng):
    """Irradiance / pi at points p (normals n) from the emitters, one area sample per point:
    E = L_e cos_r cos_e / d^2 over the pdf 1 / (total emitter area)."""
    pick = tracer.emitters[np.minimum(np.searchsorted(tracer.emitter_cdf, rng.random(len(p))),
                                      len(tracer.emitters) - 1)]
    u, v = rng.random(len(p)), rng.random(len(p))
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    q = tracer.v0[pick] + u[:, None] * tracer.e1[pick] + v[:, None] * tracer.e2[pick]
    to = q - p
    dist = np.linalg.norm(to, axis=1)
    l = to / dist[:, None]
    cos_r = np.einsum("ij,ij->i", n, l)
    cos_e = -np.einsum("ij,ij->i", tracer.normal[pick], l)  # one-sided: the emitter's front faces p
    ok = (cos_r > 0) & (cos_e > 0)
    origin = p + n * 1e-5
    t, _ = tracer.hit(origin[ok], np.ascontiguousarray(l[ok]), dist[ok] - 1e-4)
    vis = np.zeros(len(p))
    vis[ok] = np.isinf(t)
    g = vis * np.where(ok, cos_r * cos_e, 0.0) / dist ** 2
    return tracer.emission[pick] * (g * tracer.emitter_area / np.pi)[:, None]


def direct(tracer, lights, p, n, rho, rng):
    """Lambertian radiance from the punctual lights and the emitters at points p (normals n facing the
    viewer)."""
    out = np.zeros((len(p), 3))
    if len(tracer.emitters):
        out += rho * emitted_light(tracer, p, n, rng)
    for kind, value, colour in lights:
        if kind == "point":
            to = value - p
            dist = np.linalg.norm(to, axis=1)
            l = to / dist[:, None]
            e = colour[None, :] / (dist ** 2)[:, None]
            tmax = dist - 1e-4
        else:
            l = np.broadcast_to(-value / np.linalg.norm(value), p.shape)
            e = np.broadcast_to(colour, p.shape)
            tmax = np.inf
        cos = np.einsum("ij,ij->i", n, l)
        lit = cos > 0
        origin = p + n * 1e-5
        t, _ = tracer.hit(origin[lit], np.ascontiguousarray(l[lit]), tmax if np.isscalar(tmax) else tmax[lit])
        vis = np.zeros(len(p))
        vis[lit] = np.isinf(t)
        out += rho / np.pi * e * (cos * vis)[:, None]
    return out


def orthonormal_basis(v):
    """Unit vectors u, w with (u, w, v) orthonormal, per row of unit vectors v."""
    a = np.where(np.abs(v[:, 0:1]) > 0.9, np.array([[0.0, 1.0, 0.0]]), np.array([[1.0, 0.0, 0.0]]))
    u = np.cross(a, v)
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    return u, np.cross(v, u)


def cosine_directions(n, rng):
    u1, u2 = rng.random(len(n)), rng.random(len(n))
    r, phi = np.sqrt(u1), 2 * np.pi * u2
    t, b = orthonormal_basis(n)
    return (r * np.cos(phi))[:, None] * t + (r * np.sin(phi))[:, None] * b + np.sqrt(1 - u1)[:, None] * n


def camera_rays(camera, size, offset):
    """Unit directions through every pixel of a size x size image (rows top to bottom), at `offset` (0..1, per
    pixel) inside each pixel; the origin is the camera's position."""
    eye, axes, yfov = camera
    pix = np.arange(size * size)
    tan = np.tan(yfov / 2)
    px = (pix % size + offset[0]) / size * 2 - 1
    py = 1 - (pix // size + offset[1]) / size * 2
    d = axes[0][None] * (px * tan)[:, None] + axes[1][None] * (py * tan)[:, None] + axes[2][None]
    return np.broadcast_to(eye, d.shape).copy(), d / np.linalg.norm(d, axis=1, keepdims=True)


def surface(tracer, o, d, t, tri):
    """Hit points, normals facing the ray's origin (back faces reflect like front faces) and albedos."""
    n = tracer.normal[tri]
    return o + d * t[:, None], np.where((np.einsum("ij,ij->i", n, d) > 0)[:, None], -n, n), tracer.albedo[tri]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--bounces", type=int, default=6)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--pixel-centres", action="store_true")
    a = ap.parse_args()
    tris, albedo, emission, lights, camera = load(a.scene)
    tracer = Tracer(tris, albedo, emission)
    rng = np.random.default_rng(a.seed)
    size = a.size
    terms = np.zeros((a.bounces + 1, size * size, 3))
    pix = np.arange(size * size)
    for _ in range(a.spp):
        jitter = (np.full(len(pix), 0.5), np.full(len(pix), 0.5)) if a.pixel_centres else \
            (rng.random(len(pix)), rng.random(len(pix)))
        o, d = camera_rays(camera, size, jitter)
        alive = pix.copy()
        throughput = np.ones((len(pix), 3))
        for k in range(a.bounces + 1):
            t, tri = tracer.hit(o, d)
            h = tri >= 0
            alive, o, d, t, tri, throughput = alive[h], o[h], d[h], t[h], tri[h], throughput[h]
            if len(alive) == 0:
                break
            p, n, rho = surface(tracer, o, d, t, tri)
            if k == 0:  # an emitter the camera sees, from the front
                front = np.einsum("ij,ij->i", tracer.normal[tri], d) < 0
                np.add.at(terms[0], alive, tracer.emission[tri] * front[:, None])
            np.add.at(terms[k], alive, throughput * direct(tracer, lights, p, n, rho, rng))
            # Cosine-weighted sampling: the estimator's weight is the albedo.
            throughput = throughput * rho
            o, d = p + n * 1e-5, cosine_directions(n, rng)
    terms /= a.spp
    names = ["direct"] + ["bounce%d" % k for k in range(1, a.bounces + 1)]
    total = 0.0
    for name, img in zip(names, terms):
        np.save("%s-%s.npy" % (a.out, name), img.reshape(size, size, 3).astype(np.float32))
        m = float((img @ LUM).mean())
        total += m
        print("%-8s mean luminance %.5f (sum so far %.5f)" % (name, m, total))


if __name__ == "__main__":
    main()
