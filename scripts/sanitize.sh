#!/usr/bin/env bash
# The sanitizer run: builds everything with gcc -fsanitize=address,undefined
# in build-asan/ and runs the `sanitize` ctest label (the CPU tests, a subset
# of the GPU tests on lavapipe, a render of the Cornell box and the malformed-
# input corpus; tests/sanitizers/). Any ASan, LSan or UBSan report fails the
# test it happens in. Suppressions, each with its reason, are in
# tests/sanitizers/*.supp. Not part of scripts/test.sh (it takes longer).
#
#   scripts/sanitize.sh [extra ctest arguments, e.g. -R san_gpu]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${DVSGI_ASAN_BUILD_DIR:-build-asan}
jobs=${DVSGI_ASAN_JOBS:-$(nproc)}
# -O0 -g1: reports still name file and line, and the instrumented build
# (nlohmann::json and GoogleTest under ASan+UBSan) compiles without the
# optimizer's time on the project's 2-core machines; the tests' own CPU work
# is small next to lavapipe's, which is not instrumented.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDVSGI_BUILD_TESTS=ON \
    -DCMAKE_CXX_COMPILER="${CXX_ASAN:-g++}" -DDVSGI_SANITIZE=address,undefined \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g1 -DNDEBUG"
# gtest_discover_tests runs each test binary at build time: it must not fail
# on a leak report from the driver before the suppressions apply.
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
cmake --build "$build" -j "$jobs"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
set +e
ctest --test-dir "$build" -L sanitize --output-on-failure "$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
set -e
if grep -q "The following tests did not run" "$log"; then
  echo "sanitize.sh: some tests were skipped (listed above); that counts as a failure" >&2
  exit 1
fi
exit "$status"
