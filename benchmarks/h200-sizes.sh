#!/usr/bin/env bash
# BENCHMARKS.md section `h200-sizes`: rays per second against image size, 64x64 to 3840x2160,
# compute mode with both BVH layouts (and --bvh auto) and pipeline mode, on the bundled scenes
# and the bunny and the Happy Buddha as OBJ files.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes, then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-sizes.sh [OUT_DIR]
# 7 scenes x 4 backends x 7 sizes x 2 rounds of at least 0.5 s: about 9 minutes. Bring
# OUT_DIR/bench.json back and merge it here: scripts/benchmarks.sh --no-local OUT_DIR/bench.json
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
: "${ASSETS:?ASSETS: the shared test meshes (bunny/, buddha/)}"
out=${1:-${OUT:-out/h200-sizes}}
"$tp" bench --sizes --sizes-list 64,128,256,512,1024,1920x1080,3840x2160 --sizes-rounds 2 \
  --backends vulkan:compute,vulkan:compute-wide,vulkan:compute-auto,vulkan:pipeline \
  --scenes "cornell,cornell_glossy,cornell_spheres,spheres,furnace,$ASSETS/bunny/stanford-bunny.obj,$ASSETS/buddha/happy_buddha_112k.obj" \
  --section h200-sizes --out "$out"
