#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs the whole test suite
# (lavapipe is enough; GPU tests run one at a time with validation on).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build=${DVSGI_TEST_BUILD_DIR:-build-tests}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDVSGI_BUILD_TESTS=ON
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure --timeout 900 "$@"
