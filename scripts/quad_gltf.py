"""Small glTF scenes of flat quads for the CPU path tracer, Cycles and dvsgi (scripts/corner-scene.py,
scripts/slab-scene.py, scripts/window-room-scene.py): one mesh, one Lambertian material, and the nodes,
cameras and punctual lights the caller gives."""
import json
import math
import os
import struct


def quat_x(angle):
    return [math.sin(angle / 2), 0.0, 0.0, math.cos(angle / 2)]


def look_rotation(forward):
    """The quaternion turning glTF's camera (looking along -z, y up) to look along `forward`."""
    yaw = math.atan2(-forward[0], -forward[2])
    pitch = math.asin(forward[1] / math.sqrt(sum(c * c for c in forward)))
    sy, cy, sp, cp = math.sin(yaw / 2), math.cos(yaw / 2), math.sin(pitch / 2), math.cos(pitch / 2)
    return [cy * sp, sy * cp, -sy * sp, cy * cp]  # yaw about y, then pitch about the turned x


def quat_from_to(a, b):
    """The rotation taking unit vector a to unit vector b (not opposite)."""
    axis = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    s = math.sqrt(sum(x * x for x in axis))
    angle = math.atan2(s, sum(x * y for x, y in zip(a, b)))
    return [x / s * math.sin(angle / 2) for x in axis] + [math.cos(angle / 2)]


def direction_rotation(d):
    """The quaternion turning -z (a glTF light's direction) to the unit vector `d`."""
    return quat_from_to([0.0, 0.0, -1.0], d)


def camera_and_light_nodes(eye, target, light_dir, light_at=None):
    """Nodes of camera 0 at `eye` looking at `target` and of light 0 shining along `light_dir` (any
    length), placed at `light_at` if given (a spot)."""
    n = math.sqrt(sum(c * c for c in light_dir))
    light = {"rotation": direction_rotation([c / n for c in light_dir]),
             "extensions": {"KHR_lights_punctual": {"light": 0}}}
    if light_at is not None:
        light["translation"] = list(light_at)
    return [{"camera": 0, "translation": list(eye), "rotation": look_rotation([t - e for t, e in zip(target, eye)])},
            light]


def box_quads(lo, hi):
    """The six outward-facing quads of the axis-aligned box from corner `lo` to corner `hi`."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [([[x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]], [1, 0, 0]),
            ([[x0, y0, z1], [x0, y1, z1], [x0, y1, z0], [x0, y0, z0]], [-1, 0, 0]),
            ([[x0, y1, z0], [x0, y1, z1], [x1, y1, z1], [x1, y1, z0]], [0, 1, 0]),
            ([[x0, y0, z1], [x0, y0, z0], [x1, y0, z0], [x1, y0, z1]], [0, -1, 0]),
            ([[x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], [0, 0, 1]),
            ([[x1, y0, z0], [x0, y0, z0], [x0, y1, z0], [x1, y1, z0]], [0, 0, -1])]


def write_quads(path, quads, albedo, nodes, cameras, lights):
    """Writes PATH (.gltf) and its .bin: `quads` are (four corners, normal) pairs, drawn as node 0's
    mesh; `nodes` (glTF node dicts) follow it in the scene."""
    pos, nrm, idx = [], [], []
    for corners, normal in quads:
        base = len(pos) // 3
        for c in corners:
            pos += c
            nrm += normal
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    data = struct.pack("%df" % len(pos), *pos) + struct.pack("%df" % len(nrm), *nrm) + struct.pack("%dH" % len(idx), *idx)
    n = len(pos) // 3
    with open(path[:-5] + ".bin", "wb") as f:
        f.write(data)
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": list(range(1 + len(nodes)))}],
        "nodes": [{"mesh": 0}] + nodes,
        "cameras": cameras,
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [dict({"name": "light%d" % i}, **l)
                                                          for i, l in enumerate(lights)]}},
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        # Named: scripts/cycles-reference.py finds materials and lights by name.
        "materials": [{"name": "surface",
                       "pbrMetallicRoughness": {"baseColorFactor": list(albedo) + [1], "metallicFactor": 0}}],
        "buffers": [{"uri": os.path.basename(path[:-5]) + ".bin", "byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": n * 12},
                        {"buffer": 0, "byteOffset": n * 12, "byteLength": n * 12},
                        {"buffer": 0, "byteOffset": n * 24, "byteLength": len(idx) * 2}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
                       "min": [min(pos[i::3]) for i in range(3)], "max": [max(pos[i::3]) for i in range(3)]},
                      {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5123, "count": len(idx), "type": "SCALAR"}],
    }
    with open(path, "w") as f:
        json.dump(gltf, f)
