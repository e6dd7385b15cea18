#!/usr/bin/env python3
# Estimates how many tiles the compute voxelizer (voxelize.comp) queues for a
# glTF scene at 128^3, 256^3 and 512^3: every triangle whose projected
# footprint along its dominant axis spans more than the threshold (voxel
# columns: VOXC_WALK_COLUMNS_GPU 32, VOXC_WALK_COLUMNS_CPU 256) gets
# ceil(w/(8 L)) * ceil(h/8) tiles, L the columns per tile lane (1 on GPUs, 8 on CPU devices). The grid is approximated as the bounds plus
# fitGrid's margin; meshes with translation/scale only.
# Usage: scripts/compute-tiles.py SCENE.gltf [THRESHOLD=32] [LANE_COLUMNS=1]
import json
import os
import sys

import numpy as np

path = sys.argv[1]
threshold = int(sys.argv[2]) if len(sys.argv) > 2 else 32
lane = int(sys.argv[3]) if len(sys.argv) > 3 else 1
g = json.load(open(path)); base = os.path.dirname(path)
buf = open(os.path.join(base, g['buffers'][0]['uri']), 'rb').read()
def acc(i, comps):
    a = g['accessors'][i]; bv = g['bufferViews'][a['bufferView']]
    dt = {5126: np.float32, 5125: np.uint32, 5123: np.uint16}[a['componentType']]
    off = bv.get('byteOffset', 0) + a.get('byteOffset', 0)
    n = a['count'] * comps
    stride = bv.get('byteStride')
    if stride and stride != comps * np.dtype(dt).itemsize:
        raw = np.frombuffer(buf, np.uint8, a['count'] * stride, off).reshape(-1, stride)[:, :comps * np.dtype(dt).itemsize]
        return np.frombuffer(raw.tobytes(), dt).reshape(-1, comps)
    return np.frombuffer(buf, dt, n, off).reshape(-1, comps) if comps > 1 else np.frombuffer(buf, dt, n, off)
tris = []
for node in g['nodes']:
    if 'mesh' not in node: continue
    assert 'matrix' not in node and 'rotation' not in node
    s = np.array(node.get('scale', [1, 1, 1])); t = np.array(node.get('translation', [0, 0, 0]))
    for p in g['meshes'][node['mesh']]['primitives']:
        P = acc(p['attributes']['POSITION'], 3) * s + t
        I = acc(p['indices'], 1).astype(np.int64)
        tris.append(P[I.reshape(-1, 3)])
T = np.concatenate(tris)
lo, hi = T.reshape(-1, 3).min(0), T.reshape(-1, 3).max(0)
for N in (128, 256, 512):
    vs = (hi - lo).max() / (N - 9)  # about fitGrid's margin
    V = (T - lo) / vs
    n = np.cross(V[:, 1] - V[:, 0], V[:, 2] - V[:, 0]); axis = np.abs(n).argmax(1)
    mn, mx = np.floor(V.min(1)), np.floor(V.max(1))
    span = mx - mn + 1
    uv = np.array([[1, 2], [2, 0], [0, 1]])[axis]
    su = np.take_along_axis(span, uv, 1)
    cols = su[:, 0] * su[:, 1]
    big = cols > threshold
    tiles = (np.ceil(su[:, 0] / (8 * lane)) * np.ceil(su[:, 1] / 8))[big].sum()
    print(N, 'triangles', len(T), 'tiled', big.sum(), 'tiles', int(tiles), 'largest', int(cols.max()))
