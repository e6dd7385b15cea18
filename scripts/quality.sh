#!/usr/bin/env bash
# Renders every image-quality case of docs/quality.md, compares each with the
# path-traced reference (shared/tools/compare.py) and writes the table and a
# panel PNG per case (dvsgi | reference | signed error map: blue darker, red brighter) to docs/quality/.
#
#   scripts/quality.sh [BUILD_DIR] [SHARED_DIR] [SIZE] [VOXELS]
# defaults: build-tests ../shared 256 64. The references are 512x512 and are
# averaged over blocks when SIZE is smaller. On lavapipe the default run takes
# about 6 minutes (the converged renders iterate 30-60 bounces).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-tests}
shared=${2:-../shared}
size=${3:-256}
voxels=${4:-64}
out=docs/quality
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
table="$out/gi-${size}px-${voxels}.md"
{
  echo "<!-- written by scripts/quality.sh $build $shared $size $voxels on $(date -u +%F); do not edit -->"
  echo "| scene | options | bounces | relative RMSE | mean-luminance ratio | within 10 % | render s (lavapipe) |"
  echo "|---|---|---|---|---|---|---|"
} > "$table"
cases=(
  "defaults|"
  "paper: 1 bounce and the gather by cones, emitters by cones, every pixel traced, voxels lit every way, eq. 5 at voxels|--bounces 1 --bounce-trace cones --gather-trace cones --emitters cones --cone-spin off --voxel-backs-dark off --normal-weighted on --trace-scale 1"
  "defaults, the bounce by cones|--bounce-trace cones"
  "defaults, 32 rays per pixel|--gather-rays 32"
  "defaults, every pixel traced|--trace-scale 1"
  "the gather by the six cones|--gather-trace cones"
  "the gather by the six cones, not turned|--gather-trace cones --cone-spin off"
  "the gather by 16 cones|--gather-trace cones --cones 16"
)
for scene in cornell-lights cornell-emissive; do
  for c in "${cases[@]}"; do
    label=${c%%|*}
    args=${c#*|}
    tag=$(echo "$scene-$label" | tr -c 'a-zA-Z0-9\n' '-' | tr -s '-')
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$build/dvsgi" render "$shared/scenes/cornell-box/$scene.gltf" --width "$size" --height "$size" \
      --voxels "$voxels" --out "$tmp/$tag.exr" --png none --quiet --metrics "$tmp/$tag.json" $args
    secs=$(echo "$(date +%s.%N) - $start" | bc)
    /usr/bin/python3 - "$shared" "$scene" "$tmp/$tag.exr" "$tmp/$tag.json" "$size" "$out/panel-$tag.png" \
      "$label" "$args" "$secs" >> "$table" <<'PY'
import json, sys
shared, scene, exr, metrics, size, panel, label, args, secs = sys.argv[1:]
sys.path.insert(0, shared + "/tools")
import compare
size = int(size)
ref = compare.read_rgb(f"{shared}/reference/cornell-box/{scene}.exr")
f = ref.shape[0] // size
if f > 1:
    ref = ref.reshape(size, f, size, f, 3).mean(axis=(1, 3))
cand = compare.read_rgb(exr)
m, signed, bad = compare.compare(cand, ref)
top = __import__("numpy").concatenate(
    [compare.srgb8(cand), compare.srgb8(ref), compare.error_rgb(signed, bad, 0.5)], axis=1)
compare.write_png(panel, top)
b = json.load(open(metrics)).get("bounces", {})
n = b.get("first_frame", "?")
conv = "" if b.get("first_frame_change", -1) < 0 else (" (converged)" if b.get("converged") else " (not converged)")
print(f"| {scene} | {label}{' `' + args + '`' if args else ''} | {n}{conv} | {m['rel_rmse']:.3f} | "
      f"{m['mean_lum_ratio']:.3f} | {m['frac_within_tol']:.2f} | {float(secs):.0f} |")
PY
    echo "quality: $scene, $label done" >&2
  done
done
echo "wrote $table and the panels in $out/" >&2
