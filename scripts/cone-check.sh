#!/usr/bin/env bash
# The six-cone gather cone by cone against a traced reference (docs/quality.md,
# "One bounce at a time"): builds dvsgi six times with DVSGI_SINGLE_CONE=k in a
# build folder of its own, renders the first bounce (--bounces 0 --output
# indirect) of SCENE with each, and prints each cone's mean luminance against
# scripts/cone-reference.py's.
#   scripts/cone-check.sh SCENE.gltf [VOXELS] [OUT_DIR] [-- RENDER OPTIONS...]
#   DVSGI_CONES="0 1 2 3 4 5" (which cones)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$(realpath "$1"); voxels=${2:-64}; out=$(realpath -m "${3:-out/cone-check}")
shift $(( $# < 3 ? $# : 3 ))
[ "${1:-}" = "--" ] && shift
cones=${DVSGI_CONES:-"0 1 2 3 4 5"}
build=build-single-cone
mkdir -p "$out"
[ -f "$out/reference.npy" ] || /usr/bin/python3 scripts/cone-reference.py "$scene" "$out/reference.npy" --size 64
for k in $cones; do
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDVSGI_BUILD_TESTS=OFF \
        -DDVSGI_SHADER_DEFINES="DVSGI_SINGLE_CONE=$k" >/dev/null
  cmake --build "$build" --target dvsgi >/dev/null
  "$build/dvsgi" render "$scene" --width 64 --height 64 --voxels "$voxels" --bounces 0 --output indirect \
      --trace-scale 1 --out "$out/cone$k.exr" --png none --quiet "$@"
done
/usr/bin/python3 - "$out" "$cones" <<'PY'
import sys
import numpy as np
import OpenImageIO as oiio
out = sys.argv[1]
lum = np.array([0.2126, 0.7152, 0.0722])
ref = np.load(out + "/reference.npy")
for k in [int(c) for c in sys.argv[2].split()]:
    i = oiio.ImageInput.open("%s/cone%d.exr" % (out, k))
    img = np.asarray(i.read_image(0, 0, 0, 3, "float")).reshape(64, 64, 3)
    i.close()
    got, want = float((img @ lum).mean()), float((ref[k] @ lum).mean())
    print("cone %d: dvsgi %.5f, traced %.5f, ratio %.3f" % (k, got, want, got / want if want > 0 else float("nan")))
PY
