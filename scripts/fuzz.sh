#!/usr/bin/env bash
# Builds one libFuzzer target in build-fuzz/ (clang-14, ASan + UBSan) and runs
# it for SECONDS with a corpus seeded from tests/corpus/generate.py and the
# small files of ../shared. Usage:
#
#   scripts/fuzz.sh fuzz_gltf|fuzz_objply|fuzz_image|fuzz_exr SECONDS [extra libFuzzer flags]
#
# The growing corpus stays in build-fuzz/corpus/TARGET, crashing inputs land
# in build-fuzz/artifacts/TARGET/, the log in build-fuzz/logs/TARGET.log.
# Needs clang-14 and libclang-rt-14-dev (libFuzzer) from Debian.
set -euo pipefail

if [[ $# -lt 2 ]]; then
    echo "usage: scripts/fuzz.sh fuzz_gltf|fuzz_objply|fuzz_image|fuzz_exr SECONDS [libFuzzer flags]" >&2
    exit 2
fi
target=$1
seconds=$2
shift 2
case "$target" in
    fuzz_gltf) patterns=("*.gltf" "*.glb") ;;
    fuzz_objply) patterns=("*.obj" "*.ply") ;;
    fuzz_image) patterns=("*.png" "*.jpg" "*.jpeg" "*.bmp" "*.tga") ;;
    fuzz_exr) patterns=() ;;
    *) echo "fuzz.sh: unknown target '$target' (fuzz_gltf, fuzz_objply, fuzz_image or fuzz_exr)" >&2; exit 2 ;;
esac

root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
cxx=${CXX_FUZZ:-clang++-14}
command -v "$cxx" >/dev/null || { echo "fuzz.sh: $cxx not found (apt-get install clang-14)" >&2; exit 1; }

if [[ ! -f $build/build.ninja ]]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$cxx" \
        -DDVSGI_FUZZ=ON -DDVSGI_BUILD_TESTS=OFF >/dev/null
fi
nice -n 10 cmake --build "$build" -j1 --target "$target"

# Seeds: every matching file of a freshly generated corpus (for images, the
# external texture files), plus the small files of the shared scenes. EXR
# seeds come from the project's own writer instead (float, half, layers).
seeds=$build/seeds/$target
rm -rf "$seeds" "$build/seeds/cases"
mkdir -p "$seeds" "$build/corpus/$target" "$build/artifacts/$target" "$build/logs"
if [[ $target == fuzz_exr ]]; then
    nice -n 10 cmake --build "$build" -j1 --target exr_seeds
    "$build/fuzz/exr_seeds" "$seeds"
fi
# The system python carries the OpenImageIO bindings the generator uses for JPEG.
py=/usr/bin/python3
[[ -x $py ]] || py=python3
"$py" "$root/tests/corpus/generate.py" "$build/seeds/cases" >/dev/null
n=$(find "$seeds" -type f | wc -l)
for p in "${patterns[@]}"; do
    while IFS= read -r -d '' f; do
        size=$(stat -c %s "$f")
        # Huge generated cases (the 200k-node chain) only slow the fuzzer down.
        if [[ $size -le 262144 ]]; then
            cp "$f" "$seeds/$(printf '%04d' $n)_$(basename "$f")"
            n=$((n + 1))
        fi
    done < <(find "$build/seeds/cases" "$root/../shared/scenes" -name "$p" -type f -print0 2>/dev/null)
done
echo "fuzz.sh: $n seed files for $target"

# Leak checking stays on: a leak in the loaders would grow a long viewer
# session. One suppression: assimp 5.2.4 (the system library, not ours)
# leaks its partly built meshes when its OBJ importer throws "vertex index
# out of range" on some files the pre-check accepts; the input is kept as
# tests/corpus/regressions/obj_assimp_index_error_leak.obj.
printf 'leak:libassimp.so\n' > "$build/lsan.supp"
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$build/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
cd "$build"
set +e
nice -n 15 "$build/fuzz/$target" "$build/corpus/$target" "$seeds" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=3072 -max_len=262144 -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$target/" "$@" 2>&1 | tee "$build/logs/$target.log" | grep -E "^#|ERROR|SUMMARY|stat::|crash-|timeout-|leak-|oom-" | tail -40
status=${PIPESTATUS[0]}
set -e
echo "fuzz.sh: $target exited $status; log in $build/logs/$target.log"
exit "$status"
