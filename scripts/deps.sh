#!/usr/bin/env bash
# Installs the Debian packages twinpath needs, or says exactly how to.
#   scripts/deps.sh build   packages to build and run (make demo)
#   scripts/deps.sh test    build packages plus what the test suite drives (make test)
set -euo pipefail

# Each package is here because the build, the demo or a CMake package config needs it; a
# debootstrapped minimal Debian 12 (scripts/fresh_machine_check.sh) proves the list.
build_pkgs=(
  cmake ninja-build g++ pkg-config
  libembree-dev libtbb-dev libglm-dev libboost-dev
  # Textures and glTF images (common/image/): PNG and JPEG in every build, the GPU bundle too.
  libpng-dev libjpeg62-turbo-dev
  libvulkan-dev glslang-tools mesa-vulkan-drivers vulkan-validationlayers
  libopenimageio-dev libopenexr-dev
  # CMake packages that check that every file they list exists: OpenImageIO's lists its
  # tools (an error), Imath's (through OpenEXR) its Python module (a warning).
  openimageio-tools python3-imath
  nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libfmt-dev
  embree-tools
  # scripts/demo.sh reads `twinpath info --json` with python3.
  python3
  # twinpath view: the window and its overlay (libimgui-dev carries the GLFW and Vulkan back
  # ends).
  libglfw3-dev libimgui-dev
)
# Only the test suite needs these (make test): Catch2, headless Chromium for the HTML report
# test, spirv-val/spirv-opt for the SPIR-V checks, a one-node Slurm cluster with its munge
# authentication for the farm test (tests/farm/slurm_test.cpp), and a virtual X display for
# the view tests (xvfb-run needs xauth).
test_pkgs=(catch2 chromium spirv-tools slurm-wlm munge xvfb xauth)

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
echo "twinpath: installing ${missing[*]} and their dependencies" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# A fresh machine installs some 500 packages: show apt's totals, then a count every 50 rather
# than a line per package (errors still come through on stderr; pipefail keeps apt's status).
apt-get install -y -q --no-install-recommends "${missing[@]}" | awk '
  /newly installed|^Need to get|^After this operation/ { print "twinpath:   " $0; fflush() }
  /^Get:/ && ++got % 50 == 0 { print "twinpath:   downloaded " got " packages"; fflush() }
  /^Setting up / && ++set % 50 == 0 { print "twinpath:   set up " set " packages"; fflush() }
  END { print "twinpath:   installed: " set + 0 " packages set up" }' >&2
