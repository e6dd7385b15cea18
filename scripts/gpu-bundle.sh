#!/usr/bin/env bash
# Packs what scripts/gpu-check.sh needs on a GPU machine that cannot build dvsgi
# itself (no glslc, assimp or Vulkan headers there, and no network): the built
# dvsgi and GoogleTest executables, their shared libraries (glibc in a separate
# folder, used only where the machine's own glibc is older), the Khronos
# validation layer, and the benchmark scenes.
#
#   scripts/gpu-bundle.sh [BUILD_DIR] [SHARED_DIR] [BUNDLE_DIR]
# defaults: build-tests ../shared .gpu
#
# The bundle must stay under the device tool's 64 MiB transfer limit, so the
# Crytek Sponza textures are halved in each dimension (the geometry, materials
# and lights are unchanged; gpu-check.sh records this in its log). Binaries
# are stripped and packed into one xz archive.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-tests}
shared=${2:-../shared}
bundle=${3:-.gpu}

[ -x "$build/dvsgi" ] || { echo "gpu-bundle: $build/dvsgi not found; build first (scripts/test.sh)" >&2; exit 1; }
[ -d "$shared/scenes" ] || { echo "gpu-bundle: $shared/scenes not found" >&2; exit 1; }

rm -rf "$bundle"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib" "$stage/glibc" "$stage/layers" "$bundle"

bins=("$build/dvsgi")
while IFS= read -r t; do bins+=("$t"); done < <(find "$build/tests" -maxdepth 2 -type f -executable -name '*_tests' | sort)
for b in "${bins[@]}"; do
  cp "$b" "$stage/bin/"
  strip "$stage/bin/$(basename "$b")"
done

# Shared libraries of every executable and of the validation layer.
layer=/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so
libs=$( (for b in "${bins[@]}" "$layer"; do ldd "$b"; done) | awk '/=> \//{print $3}' | sort -u)
for l in $libs; do
  case "$(basename "$l")" in
    libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|libresolv.so.*) cp -L "$l" "$stage/glibc/" ;;
    *) cp -L "$l" "$stage/lib/" ;;
  esac
done
cp -L /lib64/ld-linux-x86-64.so.2 "$stage/glibc/"
strip --strip-unneeded "$stage"/lib/*.so* 2>/dev/null || true
cp "$layer" "$stage/layers/"
strip --strip-unneeded "$stage/layers/libVkLayer_khronos_validation.so"
sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' \
  /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json > "$stage/layers/VkLayer_khronos_validation.json"
/usr/bin/python3 - "$build" > "$stage/build-info.txt" <<'EOF'
import subprocess, sys
rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], capture_output=True, text=True).stdout.strip()
print("commit", rev + ("+local changes" if dirty else ""))
print("build", sys.argv[1])
EOF
tar -C "$stage" -cJf "$bundle/dvsgi-bin.tar.xz" .

# Scenes: Cornell box, Sibenik, Sponza (textures halved), the bunny.
mkdir -p "$bundle/shared/scenes"
cp -r "$shared/scenes/cornell-box" "$shared/scenes/sibenik" "$bundle/shared/scenes/"
cp -r "$shared/reference" "$bundle/shared/"
mkdir -p "$bundle/shared/scenes/stanford-bunny"
cp "$shared/scenes/stanford-bunny/bun_zipper.ply" "$bundle/shared/scenes/stanford-bunny/"
# The dragon and the buddha of `dvsgi bench --pv-tables` (3.3 MiB each; the
# conference room, 12 MiB, stays out of the 64 MiB a device run may carry).
for m in stanford-dragon/dragon.obj stanford-buddha/buddha.obj; do
  mkdir -p "$bundle/shared/scenes/$(dirname "$m")"
  cp "$shared/scenes/$m" "$bundle/shared/scenes/$m"
done
rm -f "$bundle/shared/scenes/sibenik/sibenik.obj"
mkdir -p "$bundle/shared/scenes/crytek-sponza/textures"
cp "$shared/scenes/crytek-sponza/sponza-sun.gltf" "$shared/scenes/crytek-sponza/sponza-sun.bin" \
   "$bundle/shared/scenes/crytek-sponza/"
/usr/bin/python3 - "$shared/scenes/crytek-sponza" "$bundle/shared/scenes/crytek-sponza" <<'EOF'
import json, os, sys
import OpenImageIO as oiio
src, dst = sys.argv[1], sys.argv[2]
gltf = json.load(open(os.path.join(src, "sponza-sun.gltf")))
for img in gltf.get("images", []):
    uri = img.get("uri")
    if not uri:
        continue
    buf = oiio.ImageBuf(os.path.join(src, uri))
    spec = buf.spec()
    roi = oiio.ROI(0, max(1, spec.width // 2), 0, max(1, spec.height // 2), 0, 1, 0, spec.nchannels)
    half = oiio.ImageBufAlgo.resize(buf, roi=roi)
    if not half.write(os.path.join(dst, uri)):
        sys.exit("gpu-bundle: could not write " + uri + ": " + half.geterror())
EOF
# The GL vendor-neutral dispatch libraries (glvnd) and the Vulkan loader as
# Debian packages: NVIDIA's Vulkan driver (libGLX_nvidia) needs glvnd, which
# bare GPU machines may lack. gpu-check.sh unpacks them only where missing.
mkdir -p "$bundle/gl"
o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64)
(cd "$bundle/gl" && apt-get "${o[@]}" download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null 2>&1) ||
  echo "gpu-bundle: warning: could not download the glvnd packages (apt-get download); the bundle relies on the machine's own" >&2
chmod -R u+w "$bundle"
echo "gpu-bundle: $(du -sh "$bundle" | cut -f1) in $bundle"
