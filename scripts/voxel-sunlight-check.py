"""The voxels' sunlight against rays cast in Blender, for scenes too large for scripts/voxel-truth.py's
tracer (Sponza, Sibenik): how much of the sun each floor's or wall's voxel is lit with.

    dvsgi render SCENE.gltf --bounces 0 --voxel-dump DUMP.npy ...
    blender -b --factory-startup -P scripts/voxel-sunlight-check.py -- SCENE.gltf DUMP.npy [DUMP2.npy ...]
            [--voxels 4000] [--points 16] [--seed 1] [--others 0|1]

For a sample of the one-sided voxels whose normal lies along an axis (within about 11 degrees) and whose
albedo is not black, finds points of the surface each holds, as seen from its front (rays cast along
-normal from two voxels in front, kept where they land inside the voxel), and traces there the scene's
first directional light: E cos / pi where a ray toward the sun (Blender's BVH over every mesh, alpha-masked
ones as opaque) meets nothing, else 0. The voxel's share is its direct light over its albedo (green).
--others 1 also samples the voxels whose normal lies off the axes (edges, corners, tilted and curved
surfaces), as a seventh class.
Prints, per dump, the voxels' sum over the traced one, in all and per class of normal with each class's
share of the traced light. The albedo divides out, so textures do not matter; cut-outs do (the rays
here see leaves and chains whole, which the renderer's alpha test does not), so compare dumps with each
other against the same rays rather than read a ratio of 1 as the goal.
"""
import json
import math
import sys

import numpy as np

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
if "bool" not in np.__dict__:
    np.bool = bool
import bpy  # noqa: E402
from mathutils import Quaternion, Vector  # noqa: E402
from mathutils.bvhtree import BVHTree  # noqa: E402


def fail(msg):
    print("voxel-sunlight-check: " + msg, file=sys.stderr)
    sys.exit(1)


def options():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    opts = {"--voxels": 4000, "--points": 16, "--seed": 1, "--others": 0}
    files = []
    i = 0
    while i < len(argv):
        if argv[i] in opts:
            if i + 1 >= len(argv):
                fail("%s needs a number" % argv[i])
            opts[argv[i]] = int(argv[i + 1])
            i += 2
        else:
            files.append(argv[i])
            i += 1
    if len(files) < 2:
        fail("usage: blender -b --factory-startup -P scripts/voxel-sunlight-check.py -- SCENE.gltf DUMP.npy ...")
    return files[0], files[1:], opts


def scene_bvh(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path)
    graph = bpy.context.evaluated_depsgraph_get()
    verts, polys = [], []
    for ob in bpy.context.scene.objects:
        if ob.type != "MESH":
            continue
        evaluated = ob.evaluated_get(graph)
        mesh = evaluated.to_mesh()
        base = len(verts)
        verts.extend([ob.matrix_world @ v.co for v in mesh.vertices])
        polys.extend([[base + i for i in p.vertices] for p in mesh.polygons])
        evaluated.to_mesh_clear()
    return BVHTree.FromPolygons(verts, polys)


def sun(path):
    """(irradiance E, the direction toward the sun) in glTF's frame, from the file itself."""
    g = json.load(open(path))
    lights = g.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    suns = [i for i, l in enumerate(lights) if l.get("type") == "directional"]
    if not suns:
        fail("%s has no directional light" % path)
    nodes = [n for n in g["nodes"] if n.get("extensions", {}).get("KHR_lights_punctual", {}).get("light") == suns[0]]
    q = nodes[0].get("rotation", [0.0, 0.0, 0.0, 1.0])
    travels = Quaternion((q[3], q[0], q[1], q[2])) @ Vector((0.0, 0.0, -1.0))
    return float(lights[suns[0]].get("intensity", 1.0)), -np.array(travels)


def to_blender(p):  # glTF is y up, Blender z up (the importer's conversion)
    return Vector((p[0], -p[2], p[1]))


def to_gltf(v):
    return np.array((v[0], v[2], -v[1]))


def check(bvh, E, toward, path, opts):
    d = np.load(path)
    if d.ndim != 2 or d.shape[1] != 26:
        fail("%s: not a dvsgi --voxel-dump table" % path)
    grid, centre, normal = d[:, 0:3], d[:, 3:6].astype(np.float64), d[:, 6:9].astype(np.float64)
    size = float(np.polyfit(grid[:, 0] + 0.5, centre[:, 0], 1)[0])
    albedo, direct = d[:, 9:12], d[:, 12:15]
    length = np.linalg.norm(normal, axis=1)
    along = np.abs(normal).max(axis=1) > 0.98 * np.maximum(length, 1e-9)
    usable = np.flatnonzero((d[:, 18] == 0) & (length > 0.5) & (albedo[:, 1] > 0.05) & (along | (opts["--others"] != 0)))
    rng = np.random.default_rng(opts["--seed"])
    chosen = rng.choice(usable, min(opts["--voxels"], len(usable)), replace=False)
    sun_b = to_blender(toward)
    held, traced, cls = [], [], []
    for i in chosen:
        n = normal[i] / length[i]
        lo = centre[i] - 0.5 * size
        values = []
        for _ in range(opts["--points"]):
            start = lo + rng.random(3) * size + n * 2.0 * size
            loc, face_n, _, _ = bvh.ray_cast(to_blender(start), to_blender(-n), 4.0 * size)
            if loc is None:
                continue
            p = to_gltf(loc)
            if np.any(p < lo - 1e-6) or np.any(p > lo + size + 1e-6):
                continue
            fn = to_gltf(face_n)
            fn = fn if fn @ n > 0 else -fn
            c = max(float(fn @ toward), 0.0)
            if c > 0.0 and bvh.ray_cast(to_blender(p + fn * 1e-4), sun_b)[0] is not None:
                c = 0.0
            values.append(E * c / math.pi)
        if len(values) < 2:
            continue
        held.append(direct[i, 1] / albedo[i, 1])
        traced.append(np.mean(values))
        a = int(np.argmax(np.abs(n)))
        cls.append(2 * a + int(n[a] < 0) if along[i] else 6)
    held, traced, cls = map(np.array, (held, traced, cls))
    def cell(c):  # a class the sun does not reach (traced 0) has no ratio
        t = traced[cls == c].sum()
        if t <= 1e-9 * traced.sum():
            return " – |"
        return " %.3f (%.0f %%) |" % (held[cls == c].sum() / t, 100.0 * t / traced.sum())

    print("| %s (voxel %.4f m) | %d | %.4f |" % (path, size, len(held), held.sum() / traced.sum()) +
          "".join(cell(c) for c in range(7 if opts["--others"] else 6)))


def main():
    scene, dumps, opts = options()
    E, toward = sun(scene)
    bvh = scene_bvh(scene)
    print("<!-- scripts/voxel-sunlight-check.py %s; toward the sun %s -->" % (scene, np.round(toward, 3)))
    print("| dump | voxels | sunlight: voxels / traced | +x | -x | +y | -y | +z | -z |" + (" others |" if opts["--others"] else ""))
    print("|---|---|---|---|---|---|---|---|---|" + ("---|" if opts["--others"] else ""))
    for path in dumps:
        check(bvh, E, toward, path, opts)


main()
