#!/usr/bin/env bash
# Any passes of two dvsgi binaries, run alternately on the same machine
# (lavapipe's timings drift by a third between runs, so only a same-run A/B
# tells a change apart): ROUNDS rounds of base then new on each scene, one
# bench JSON per (scene, binary, round) under OUT_DIR, then the median GPU ms
# of each named pass per run.
#
#   scripts/pass-ab.sh BASE_BIN NEW_BIN OUT_DIR [ROUNDS=2]
#   DVSGI_AB_PASSES="gbuffer,shadow maps"
#   DVSGI_AB_SCENES="crytek-sponza/sponza-sun.gltf sibenik/sibenik-point.gltf"
#   DVSGI_AB_OPTIONS="--bench-voxels 32 --bench-frames 4 --bench-warmup 1 --width 640 --height 360 --bounces 1"
#   DVSGI_SHARED=../shared
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: scripts/pass-ab.sh BASE_BIN NEW_BIN OUT_DIR [ROUNDS=2]" >&2
  exit 2
fi
base=$(realpath "$1"); new=$(realpath "$2"); out=$(realpath -m "$3"); rounds=${4:-2}
shared=${DVSGI_SHARED:-../shared}
passes=${DVSGI_AB_PASSES:-gbuffer,shadow maps}
scenes=${DVSGI_AB_SCENES:-crytek-sponza/sponza-sun.gltf sibenik/sibenik-point.gltf}
read -r -a options <<< "${DVSGI_AB_OPTIONS:---bench-voxels 32 --bench-frames 4 --bench-warmup 1 --width 640 --height 360 --bounces 1}"
mkdir -p "$out"
for round in $(seq 1 "$rounds"); do
  for which in base new; do
    bin=$base; [ "$which" = new ] && bin=$new
    for scene in $scenes; do
      "$bin" bench "$shared/scenes/$scene" "${options[@]}" --quiet \
        --bench-out "$out/$(basename "$scene" .gltf)-$which-$round.json" >"$out/last.log" 2>&1 ||
        { cat "$out/last.log" >&2; echo "pass-ab: $bin failed on $scene" >&2; exit 1; }
    done
  done
done
rm -f "$out/last.log"
python3 - "$out" "$rounds" "$passes" <<'PY'
import json, os, sys
out, rounds, passes = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(',')
scenes = sorted({f.rsplit('-', 2)[0] for f in os.listdir(out) if f.endswith('.json')})
print('| scene | pass | base: median GPU ms (runs) | new |')
print('|---|---|---|---|')
for scene in scenes:
    for name in passes:
        cells = []
        for which in ('base', 'new'):
            runs = []
            for r in range(1, rounds + 1):
                path = os.path.join(out, f'{scene}-{which}-{r}.json')
                if not os.path.exists(path):
                    continue
                for m in json.load(open(path))['measurements']:
                    runs += [p['median_ms'] for p in m['passes'] if p['name'] == name]
            cells.append(', '.join(f'{ms:.1f}' for ms in runs) or '-')
        print(f'| {scene} | {name} | {cells[0]} | {cells[1]} |')
PY
