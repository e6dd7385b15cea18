#!/usr/bin/env bash
# Static voxelization of two dvsgi binaries, run alternately on the same
# machine (lavapipe's timings drift by a third between runs, so only a
# same-run A/B tells a change apart): Sponza at 128^3 and 256^3, Sibenik at
# 256^3 and the Cornell box at 128^3, ROUNDS rounds of base then new. Writes
# one bench JSON per (scene, binary, round) under OUT_DIR and prints the
# median GPU ms of `voxelize static` per run and the voxel counts (which must
# agree: both voxelizers are exact).
#
#   scripts/voxelize-ab.sh BASE_BIN NEW_BIN OUT_DIR [ROUNDS=2]
#   DVSGI_SHARED=../shared
# Both binaries run the compute voxelizer (--voxelizer compute), whatever the
# device would pick.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: scripts/voxelize-ab.sh BASE_BIN NEW_BIN OUT_DIR [ROUNDS=2]" >&2
  exit 2
fi
base=$(realpath "$1"); new=$(realpath "$2"); out=$(realpath -m "$3"); rounds=${4:-2}
shared=${DVSGI_SHARED:-../shared}
mkdir -p "$out"
scenes="crytek-sponza/sponza-sun.gltf:128,256 sibenik/sibenik-point.gltf:256 cornell-box/cornell-lights.gltf:128"
for round in $(seq 1 "$rounds"); do
  for which in base new; do
    bin=$base; [ "$which" = new ] && bin=$new
    for item in $scenes; do
      scene=${item%%:*}; voxels=${item##*:}; name=$(basename "$scene" .gltf)
      "$bin" bench "$shared/scenes/$scene" --bench-voxels "$voxels" --bench-frames 3 --bench-warmup 1 \
        --bounces 1 --width 64 --height 36 --voxelizer compute --quiet \
        --bench-out "$out/$name-$which-$round.json" >/dev/null
    done
  done
done
python3 - "$out" "$rounds" <<'PY'
import glob, json, os, sys
rows = {}
rounds = int(sys.argv[2])
for f in sorted(glob.glob(os.path.join(sys.argv[1], '*-*-*.json'))):
    if int(f[:-5].rsplit('-', 1)[1]) > rounds:  # left from an earlier run with more rounds
        continue
    name, which, rnd = os.path.basename(f)[:-5].rsplit('-', 2)
    for m in json.load(open(f))['measurements']:
        ms = [p['median_ms'] for p in m['passes'] if p['name'] == 'voxelize static']
        rows.setdefault((name, m['voxels']), {}).setdefault(which, []).append((ms[0], m['voxel_counts']['occupied']))
print('| scene | N | base: voxelize static ms (runs) | new | occupied voxels base / new |')
print('|---|---|---|---|---|')
for (name, n), r in sorted(rows.items()):
    b, w = r.get('base', []), r.get('new', [])
    print(f"| {name} | {n}³ | {', '.join(f'{x[0]:.0f}' for x in b)} | {', '.join(f'{x[0]:.0f}' for x in w)} | "
          f"{sorted({x[1] for x in b})} / {sorted({x[1] for x in w})} |")
PY
