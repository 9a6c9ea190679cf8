#!/usr/bin/env bash
# BENCHMARKS.md table `h200-unequal-spp`: `twinpath compare` at unequal spp (docs/compare.md)
# on the caustic scene, cornell_spheres at 256x256 (max depth 1000, `--sampler random`: six
# channels, R, G, B and the variance of the mean): the CPU at 64, 256, 2048 and
# 4096 spp, compute and pipeline mode at 16384 spp, each pair compared; then, where oiiotool is
# installed, one image of a pair scaled by 1.01 (mean by f, variance of the mean by f²), which
# compare must find.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh), then
#   TWINPATH=BUNDLE/bin/twinpath benchmarks/h200-unequal-spp.sh [OUT_DIR]
# About 1.5 minutes. Prints one line per pair; the images stay in OUT_DIR (bring them back to
# scale them here, where oiiotool is).
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/h200-unequal-spp}}
mkdir -p "$out"
r() { local name=$1; shift; "$tp" render cornell_spheres --sampler random --width 256 --height 256 -o "$out/$name.exr" "$@" >/dev/null 2>&1 || echo "render failed: $name" >&2; }
[ -f "$out/cpu64.exr" ] || {
  r cpu64 --spp 64 --seed 3
  r cpu256 --spp 256 --seed 5
  r cpu2048 --spp 2048 --seed 14
  r cpu4096 --spp 4096 --seed 15
  r compute16384 --backend vulkan --vk-mode compute --spp 16384 --seed 21
  r pipeline16384 --backend vulkan --vk-mode pipeline --spp 16384 --seed 21
}
c() { echo "$1 against $2: $("$tp" compare "$out/$1.exr" "$out/$2.exr" 2>&1 | head -1)"; }
for pair in "cpu256 cpu2048" "cpu64 cpu4096" "cpu256 compute16384" "cpu2048 compute16384" \
  "cpu4096 compute16384" "cpu2048 pipeline16384" "compute16384 pipeline16384"; do c $pair; done
command -v oiiotool >/dev/null || exit 0
for name in cpu256 cpu2048 compute16384; do
  oiiotool "$out/$name.exr" --mulc 1.01,1.01,1.01,1.0201,1.0201,1.0201 -o "$out/${name}x.exr"
done
for pair in "cpu256 cpu2048x" "cpu256x cpu2048" "cpu2048x compute16384" "cpu2048 compute16384x"; do c $pair; done
