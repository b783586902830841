#!/usr/bin/env bash
# Installs the Debian 12 packages kappa needs to build, test and run.
# Uses sudo when not run as root. Safe to run repeatedly.
set -euo pipefail
PACKAGES=(
  cmake g++ ninja-build pkg-config
  libglm-dev libtinyobjloader-dev libtinygltf-dev catch2 libpng-dev libstb-dev libcairo2-dev
  libglfw3-dev libimgui-dev python3-glad
  libegl-dev libegl1-mesa-dev libgl-dev libgl1-mesa-dri
  xvfb xauth
  librsvg2-bin poppler-utils inkscape
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed python3-dask
  blender
  emscripten nlohmann-json3-dev chromium
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
