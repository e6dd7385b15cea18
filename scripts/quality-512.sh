#!/bin/bash
# Issue #15's image-quality renders at the size the issue names (512x512,
# 128^3) and the resolution/step independence of cornell-lights' indirect
# light (64^3, 128^3, 256^3 and beta = 1 at 128^3): EXRs and metrics JSONs in
# OUT, tabulated by scripts/gpu-quality-table.py OUT. scripts/gpu-check.sh runs
# it on a GPU; on lavapipe it takes about 20 minutes.
# Usage: scripts/quality-512.sh OUT SHARED_DIR -- DVSGI_COMMAND...
# (DVSGI_QUALITY_TIMEOUT: seconds per render, default 120)
set -u
out=$(realpath -m "$1")
shared=$2
shift 2
[ "${1:-}" = "--" ] && shift
[ $# -gt 0 ] || { echo "usage: scripts/quality-512.sh OUT SHARED_DIR -- DVSGI_COMMAND..." >&2; exit 2; }
limit=${DVSGI_QUALITY_TIMEOUT:-120}
mkdir -p "$out"
status=0
qrender() {  # NAME SCENE ARGS...
  local name=$1 scene=$2
  shift 2
  if ! timeout "$limit" "${dvsgi[@]}" render "$shared/scenes/cornell-box/$scene.gltf" --width 512 --height 512 \
      --png none --quiet --out "$out/$name.exr" --metrics "$out/$name.json" "$@" >> "$out/log.txt" 2>&1; then
    echo "quality render $name failed" | tee -a "$out/log.txt" >&2
    status=1
  fi
}
dvsgi=("$@")
for sc in cornell-lights cornell-emissive; do
  qrender "$sc-128" "$sc" --voxels 128
  qrender "$sc-128-cones" "$sc" --voxels 128 --gather-trace cones
done
for n in 64 128 256; do qrender "indirect-$n" cornell-lights --voxels "$n" --output indirect; done
qrender indirect-128-beta1 cornell-lights --voxels 128 --output indirect --cone-step 1
exit $status
