#!/usr/bin/env bash
# Installs the Debian packages twinpath needs, or says exactly how to.
#   scripts/deps.sh build   packages to build and run (make demo)
#   scripts/deps.sh test    build packages plus what the test suite drives (make test)
set -euo pipefail

build_pkgs=(
  cmake ninja-build g++ pkg-config
  libembree-dev libtbb-dev libglm-dev libboost-dev
  libvulkan-dev glslang-tools mesa-vulkan-drivers vulkan-validationlayers
  libopenimageio-dev libopenexr-dev
  nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libfmt-dev
  embree-tools
)
test_pkgs=(catch2 chromium spirv-tools)

case "${1:-build}" in
  build) pkgs=("${build_pkgs[@]}") ;;
  test) pkgs=("${build_pkgs[@]}" "${test_pkgs[@]}") ;;
  *) echo "usage: $0 build|test" >&2; exit 2 ;;
esac

missing=()
for p in "${pkgs[@]}"; do
  # dpkg-query prints "install ok installed" only for a fully installed package.
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

line="apt-get install -y --no-install-recommends ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "twinpath: missing Debian packages. Install them as root, then run make again:" >&2
  echo "  sudo apt-get update && sudo $line" >&2
  exit 1
fi
echo "twinpath: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
