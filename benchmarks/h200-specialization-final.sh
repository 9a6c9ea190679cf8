#!/usr/bin/env bash
# BENCHMARKS.md section `h200-specialization-final`: time per spp of the GPU path loop with every
# feature compiled in over the loop specialized to the scene's features (docs/gpu.md,
# "Specialization to the scene's features"), both GPU modes, with the driver's register counts.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes (the bunny), then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-specialization-final.sh [OUT_DIR]
# About a minute. Bring OUT_DIR/bench.json back and merge it here:
# scripts/benchmarks.sh --no-local OUT_DIR/bench.json
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/h200-specialization-final}}
"$tp" bench --specialization --pipeline-stats \
  --scenes cornell,cornell_glossy,spheres,furnace,bunny --backends vulkan:compute,vulkan:pipeline \
  --width 1920 --height 1080 --spec-spp 64 --spec-rounds 3 ${ASSETS:+--assets "$ASSETS"} \
  --section h200-specialization-final --out "$out"
