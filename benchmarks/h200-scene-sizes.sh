#!/usr/bin/env bash
# BENCHMARKS.md table `h200-scene-sizes`: compute mode (binary, wide and --bvh auto's BVH) and
# pipeline mode as the scene grows: N = 1, 10, 30 and 100 distinct Happy Buddhas (112k
# triangles each, no instancing: the bench catalogue's buddhas_N) on a floor, at 1920x1080 and
# 256 spp, best of 2 rounds (the first render after an idle spell runs at low clocks). Each row
# gives Mrays/s (every ray over GPU time) and the acceleration structure's build in seconds;
# bench.json keeps compute mode's seconds per build stage, the upload's seconds and the peak
# device memory of each render.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes (buddha/ is all it reads), then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-scene-sizes.sh [OUT_DIR]
# 4 scenes x 4 backends x 2 rounds = 32 renders of 256 spp at 1080p, each with its build, plus
# loading 141 OBJ files: a few minutes, within one command's 10. SIZES replaces the list of N.
# Bring OUT_DIR/bench.json back and merge it here:
# scripts/benchmarks.sh --no-local OUT_DIR/bench.json
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
: "${ASSETS:?ASSETS: the shared test meshes (buddha/)}"
out=${1:-${OUT:-out/h200-scene-sizes}}
"$tp" bench --sizes --scene-sizes "${SIZES:-1,10,30,100}" --scene-sizes-family buddhas \
  --sizes-list 1920x1080 --sizes-spp 256 --sizes-rounds 2 \
  --backends vulkan:compute,vulkan:compute-wide,vulkan:compute-auto,vulkan:pipeline \
  --assets "$ASSETS" --section h200-scene-sizes --out "$out"
