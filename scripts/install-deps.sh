#!/usr/bin/env bash
# Installs the Debian 12 packages fxview needs, only those that are missing (idempotent, quiet when
# everything is there). Runs as root, or through sudo when it is available.
set -euo pipefail

packages=(
  build-essential cmake pkg-config make python3-glad
  libglfw3-dev libimgui-dev libglm-dev libstb-dev libeigen3-dev doctest-dev libcli11-dev
  libtinyobjloader-dev libtinyexr-dev nlohmann-json3-dev glslang-dev libspirv-cross-c-shared-dev
  libegl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6 libosmesa6-dev
  libglx-mesa0 colord-data fonts-dejavu-core xvfb xauth libxtst-dev
  clang libclang-rt-14-dev
)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "install-deps: installing ${missing[*]}"
as_root=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
