#!/usr/bin/env bash
# dvsgi on the shared Sponza and Sibenik scenes, on a room lit through a window or
# by a spot light (scripts/window-room-scene.py [--spot]) and on blocks outdoors
# (scripts/outdoor-scene.py)
# against the Cycles references in
# docs/quality/cycles/ (scripts/cycles-reference.py), split by bounce
# (scripts/scene-compare.py), and on the Cornell box turned about the vertical,
# whose path-traced image is the unturned reference (nothing in the scene but the
# voxel grid's axes moves with the turn).
#
#   scripts/scenes-vs-cycles.sh DVSGI OUT_DIR [SHARED_DIR] [-- extra dvsgi options]
# Writes OUT_DIR/table.md, each render's AOV and JSON, and a panel (dvsgi, Cycles,
# error) per scene. VOXELS (default 128) sets the grid. About 3 minutes on lavapipe.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: scripts/scenes-vs-cycles.sh DVSGI OUT_DIR [SHARED_DIR] [-- options]" >&2; exit 2; }
dvsgi=$1
out=$2
shift 2
shared=../shared
if [ $# -gt 0 ] && [ "$1" != "--" ]; then shared=$1; shift; fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
extra=("$@")
voxels=${VOXELS:-128}
refs=docs/quality/cycles
[ -x "$dvsgi" ] || { echo "scenes-vs-cycles: $dvsgi is not an executable" >&2; exit 2; }
[ -d "$shared/scenes" ] || { echo "scenes-vs-cycles: no scenes under $shared" >&2; exit 2; }
mkdir -p "$out"
table=$out/table.md
{
  echo "<!-- written by scripts/scenes-vs-cycles.sh $dvsgi $out $shared ${extra[*]} (VOXELS=$voxels) on $(date -u +%F) -->"
  echo "| scene (320x180, ${voxels}³) | direct | indirect | first bounce | later bounces | indirect where no direct light |"
  echo "|---|---|---|---|---|---|"
} > "$table"
for n in window-room outdoor; do /usr/bin/python3 "scripts/$n-scene.py" "$out/$n.gltf"; done
/usr/bin/python3 scripts/window-room-scene.py "$out/window-room-spot.gltf" --spot
for s in crytek-sponza/sponza-sun crytek-sponza/sponza-point sibenik/sibenik-point window-room window-room-spot \
         outdoor; do
  n=$(basename "$s")
  scene=$shared/scenes/$s.gltf
  [ "$s" = "$n" ] && scene=$out/$n.gltf  # generated above (no folder under scenes/)
  common=(render "$scene" --width 320 --height 180 --voxels "$voxels" --png none --quiet "${extra[@]}")
  "$dvsgi" "${common[@]}" --out "$out/$n.exr" --aov "$out/$n-aov.exr" --metrics "$out/$n.json"
  "$dvsgi" "${common[@]}" --bounces 0 --out "$out/$n-first.exr" --aov "$out/$n-first-aov.exr"
  /usr/bin/python3 scripts/scene-compare.py "$refs/$n" "$out/$n-aov.exr" "$out/$n-first-aov.exr" \
      --json "$out/$n-compare.json" --row "$n" >> "$table"
  # dvsgi | Cycles | signed error, to look at (docs/quality.md shows some).
  /usr/bin/python3 "$shared/tools/compare.py" "$out/$n.exr" "$refs/$n.exr" --panel-png "$out/panel-$n.png" \
      --json "$out/$n-image.json" > /dev/null
done
# The Cornell box turned about its vertical axis (the camera and lights with it).
{
  echo
  echo "| Cornell box turned about the vertical (256², 64³), mean luminance / reference | 0° | 30° | 45° |"
  echo "|---|---|---|---|"
} >> "$table"
for n in cornell-lights cornell-emissive; do
  row="| $n"
  for deg in 0 30 45; do
    scene=$out/$n-turn$deg.gltf
    /usr/bin/python3 scripts/turn-scene.py "$shared/scenes/cornell-box/$n.gltf" "$scene" "$deg"
    "$dvsgi" render "$scene" --allow-outside-references --width 256 --height 256 --voxels 64 --png none --quiet \
        "${extra[@]}" --out "$out/$n-turn$deg.exr"
    ratio=$(/usr/bin/python3 scripts/lum-ratio.py "$out/$n-turn$deg.exr" "$shared/reference/cornell-box/$n.exr")
    row="$row | $ratio"
  done
  echo "$row |" >> "$table"
done
cat "$table"
