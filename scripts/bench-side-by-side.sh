#!/usr/bin/env bash
# Issue #14's targets, measured against an earlier commit built side by side:
# builds BASE_REV (default 4c8f3ef, the code before the occupied-voxel list and
# the compute voxelizer) in a worktree and this checkout, both Release, then
# runs `dvsgi bench` with each binary on the same scenes, one after the other
# in the same run, and writes the JSONs and a comparison table under OUT_DIR.
#
#   scripts/bench-side-by-side.sh [OUT_DIR] [BASE_REV]
#   DVSGI_SBS_SCENES="cornell-box/cornell-lights.gltf crytek-sponza/sponza-sun.gltf"
#   DVSGI_SBS_VOXELS=128 DVSGI_SBS_FRAMES=2 DVSGI_SBS_SIZE=640x360 DVSGI_SHARED=../shared
#   DVSGI_SBS_OPTIONS="--bounces 1"   (render options for both; the default's first frame
#                                      converges the bounces, minutes per scene on lavapipe)
#
# The base bench forced static voxelization inside every measured frame; the
# current one times it in a submission of its own, so the table compares the
# per-frame work: base frame - (clear all voxels + voxelize static) against
# the current frame.
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:-out/side-by-side}")
base_rev=${2:-4c8f3ef}
shared=${DVSGI_SHARED:-../shared}
scenes=${DVSGI_SBS_SCENES:-"cornell-box/cornell-lights.gltf crytek-sponza/sponza-sun.gltf"}
voxels=${DVSGI_SBS_VOXELS:-128}
frames=${DVSGI_SBS_FRAMES:-2}
size=${DVSGI_SBS_SIZE:-640x360}
read -r -a options <<< "${DVSGI_SBS_OPTIONS:---bounces 1}"
mkdir -p "$out"

base_dir=$(realpath -m "${DVSGI_SBS_BASE_DIR:-../dvsgi-base-$base_rev}")
if [ ! -d "$base_dir" ]; then git worktree add --detach "$base_dir" "$base_rev" >/dev/null; fi
for d in "$base_dir" "$PWD"; do
  cmake -S "$d" -B "$d/build-rel" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDVSGI_BUILD_TESTS=OFF >/dev/null
  cmake --build "$d/build-rel" --target dvsgi >/dev/null
done
current_rev=$(git rev-parse --short HEAD)
w=${size%x*}; h=${size#*x}
for scene in $scenes; do
  name=$(basename "$scene" .gltf)
  common=("$shared/scenes/$scene" --bench-voxels "$voxels" --bench-frames "$frames" --bench-warmup 1
          --width "$w" --height "$h" --shared "$shared" --quiet "${options[@]}")
  echo "== $name ${voxels}^3: base $base_rev" >&2
  "$base_dir/build-rel/dvsgi" bench "${common[@]}" --bench-out "$out/$name-base.json" || true
  echo "== $name ${voxels}^3: current $current_rev" >&2
  build-rel/dvsgi bench "${common[@]}" --bench-out "$out/$name-current.json" || true
  echo "== $name ${voxels}^3: current $current_rev, --voxelizer compute" >&2
  build-rel/dvsgi bench "${common[@]}" --voxelizer compute --bench-out "$out/$name-current-compute.json" || true
done
python3 scripts/side-by-side-table.py "$out" "$base_rev" "$current_rev" > "$out/table.md"
cat "$out/table.md"
