#!/usr/bin/env bash
# Installs the Debian packages twinpath needs, or says exactly how to.
#   scripts/deps.sh build   packages to build and run (make demo)
#   scripts/deps.sh test    build packages plus what the test suite drives (make test)
set -euo pipefail

# Each package is here because the build, the demo or a CMake package config needs it; a
# debootstrapped minimal Debian 12 (scripts/fresh_machine_check.sh) proves the list.
build_pkgs=(
  cmake ninja-build g++ pkg-config
  libembree-dev libtbb-dev libglm-dev libboost-dev libpng-dev
  libvulkan-dev glslang-tools mesa-vulkan-drivers vulkan-validationlayers
  libopenimageio-dev libopenexr-dev
  # OpenImageIO's CMake package (OpenImageIOTargets.cmake) checks that its tools exist.
  openimageio-tools
  nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libfmt-dev
  embree-tools
  # scripts/demo.sh reads `twinpath info --json` with python3.
  python3
)
# Only the test suite needs these (make test): Catch2, headless Chromium for the HTML report
# test, spirv-val/spirv-opt for the SPIR-V checks.
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
