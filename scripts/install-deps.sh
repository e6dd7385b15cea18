#!/usr/bin/env bash
# Installs every Debian 12 package that building, testing and running dvsgi needs,
# including Mesa's software Vulkan driver (lavapipe) for machines without a GPU.
# Idempotent: packages already present are skipped, so a second run does nothing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  glslc spirv-tools
  libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers vulkan-tools
  libassimp-dev nlohmann-json3-dev libstb-dev libglm-dev libcli11-dev
  libglfw3-dev libimgui-dev xvfb xauth
  libgtest-dev zlib1g-dev libjpeg-dev libopenexr-dev libimath-dev
  python3 python3-numpy python3-openimageio
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and sudo is missing; install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
