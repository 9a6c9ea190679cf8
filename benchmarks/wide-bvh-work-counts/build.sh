#!/usr/bin/env bash
# Builds work_counts against a configured and built twinpath tree (default ../../build: needs
# the targets tp_cpu and tp_vulkan), the way cli/twinpath links.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
B=${BUILD:-$root/build}
L=/usr/lib/x86_64-linux-gnu
g++ -std=c++20 -O2 -I"$root" -I"$root/common" -isystem /usr/include/OpenEXR -isystem /usr/include/Imath \
  "$here/work_counts.cpp" -o "${OUTBIN:-$B/work_counts}" \
  "$B/cpu_ref/libtp_cpu.a" "$B/vulkan_rt/libtp_vulkan.a" "$B/common/libtp_common.a" \
  -lembree3 -lvulkan -lpng -lOpenImageIO -lOpenImageIO_Util -lOpenEXR-3_1 -lIlmThread-3_1 -lIex-3_1 \
  -lImath-3_1 -ltbb -lfmt -lz -lm
