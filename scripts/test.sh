#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs the whole test suite
# (lavapipe is enough; GPU tests run one at a time with validation on).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build=${DVSGI_TEST_BUILD_DIR:-build-tests}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDVSGI_BUILD_TESTS=ON
cmake --build "$build" -j "$(nproc)"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# validate_scenes (label "validation": every shared scene under the validation
# layer: 205 s on the 2-core machine beside one build, 507 s at load 10, most of it Sibenik's
# voxelization) runs with
# `ctest -L validation` or DVSGI_VALIDATE_SCENES=1, keeping this suite near 10 min.
exclude=(-LE validation)
[ "${DVSGI_VALIDATE_SCENES:-0}" = 1 ] && exclude=()
ctest --test-dir "$build" --output-on-failure --timeout 900 "${exclude[@]}" "$@" 2>&1 | tee "$log"
# A skipped test checked nothing: the suite fails on any skip, not only on failures.
if grep -q "The following tests did not run" "$log"; then
  echo "test.sh: some tests were skipped (listed above); the suite counts that as a failure" >&2
  exit 1
fi
