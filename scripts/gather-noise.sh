#!/usr/bin/env bash
# The per-pixel gather's noise: each scene's indirect term (320x180, 64^3, the defaults: 16 rays per
# pixel, filtered) against the same binary's render with 1024 rays per pixel, as relative RMSE and
# mean-luminance ratio (shared/tools/compare.py). Also writes OUT_DIR/window-room-ceiling.png: the
# window room's ceiling and back walls from a 640x360, 128^3 render, contrast x3, to look at the noise.
# docs/quality.md, "The gather's rays spread over each block of pixels" and "The rays' filter keeps to
# the pixel's plane".
#
#   scripts/gather-noise.sh DVSGI OUT_DIR [SHARED_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: scripts/gather-noise.sh DVSGI OUT_DIR [SHARED_DIR]" >&2; exit 2; }
dvsgi=$1
out=$2
shared=${3:-../shared}
[ -x "$dvsgi" ] || { echo "gather-noise: $dvsgi is not an executable" >&2; exit 2; }
[ -d "$shared/scenes" ] || { echo "gather-noise: no scenes under $shared" >&2; exit 2; }
mkdir -p "$out"
/usr/bin/python3 scripts/window-room-scene.py "$out/window-room.gltf"
/usr/bin/python3 scripts/window-room-scene.py "$out/window-room-spot.gltf" --spot
/usr/bin/python3 scripts/outdoor-scene.py "$out/outdoor.gltf"
echo "| scene (indirect term, 320x180, 64³) | relative RMSE against 1024 rays | mean luminance / 1024 rays' |"
echo "|---|---|---|"
for scene in "$out/window-room.gltf" "$out/window-room-spot.gltf" "$out/outdoor.gltf" \
             "$shared/scenes/cornell-box/cornell-lights.gltf" "$shared/scenes/crytek-sponza/sponza-sun.gltf" \
             "$shared/scenes/sibenik/sibenik-point.gltf"; do
  n=$(basename "$scene" .gltf)
  common=(render "$scene" --width 320 --height 180 --voxels 64 --output indirect --png none --quiet)
  "$dvsgi" "${common[@]}" --gather-rays 1024 --out "$out/$n-1024.exr"
  "$dvsgi" "${common[@]}" --out "$out/$n.exr"
  /usr/bin/python3 - "$shared/tools" "$out/$n.exr" "$out/$n-1024.exr" "$n" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import compare  # noqa: E402  (shared/tools/compare.py: the metric definitions)
m, _, _ = compare.compare(compare.read_rgb(sys.argv[2]), compare.read_rgb(sys.argv[3]))
print("| %s | %.4f | %.4f |" % (sys.argv[4], m["rel_rmse"], m["mean_lum_ratio"]))
PY
done
"$dvsgi" render "$out/window-room.gltf" --width 640 --height 360 --voxels 128 --out "$out/window-room-640.exr" \
    --png "$out/window-room-640.png" --quiet
/usr/bin/python3 - "$out/window-room-640.png" "$out/window-room-ceiling.png" <<'PY'
import sys
import numpy as np
import OpenImageIO as oiio
inp = oiio.ImageInput.open(sys.argv[1])
img = np.asarray(inp.read_image(format="uint8"))
inp.close()
crop = np.clip((img[0:200, 60:460].astype(np.float64) - 20.0) * 3.0, 0, 255).astype(np.uint8)
out = oiio.ImageOutput.create(sys.argv[2])
out.open(sys.argv[2], oiio.ImageSpec(crop.shape[1], crop.shape[0], crop.shape[2], "uint8"))
out.write_image(crop)
out.close()
PY
