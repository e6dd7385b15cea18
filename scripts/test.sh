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
# Everything, validate_scenes included (label "validation": every shared scene
# under the validation layer, 15 s on the 2-core machine since the compute
# voxelizer; it took 205-507 s while Sibenik was rasterized). DVSGI_VALIDATE_SCENES=0
# leaves it out.
exclude=()
[ "${DVSGI_VALIDATE_SCENES:-1}" = 0 ] && exclude=(-LE validation)
ctest --test-dir "$build" --output-on-failure --timeout 900 "${exclude[@]}" "$@" 2>&1 | tee "$log"
# A skipped test checked nothing: the suite fails on any skip, not only on failures.
if grep -q "The following tests did not run" "$log"; then
  echo "test.sh: some tests were skipped (listed above); the suite counts that as a failure" >&2
  exit 1
fi
