#!/usr/bin/env bash
# The main job: install what is missing, build, and render the built-in default
# scene (the Cornell box) into out/. Reads nothing from ../shared.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DDVSGI_BUILD_TESTS=OFF
cmake --build build --target dvsgi
mkdir -p out
# The defaults' 128^3 voxels: the converged bounces (--bounces auto, 24 of
# them, over occupied voxels only) and the image take about 16 s on a 2-core lavapipe
# machine (2026-12-07, `time` of this command); a GPU does this in milliseconds.
./build/dvsgi render --width 512 --height 512 --voxels 128 \
  --out out/cornell.exr --png out/cornell.png --metrics out/cornell-metrics.json
