#!/usr/bin/env bash
# BENCHMARKS.md section `h200`: error against time (the ladder) and rays per second over depth
# and samples (thesis Table 5.3), the CPU next to both GPU modes, six scenes at 512x512.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"; docs/bench.md, "GPU rows"):
# carry the unpacked gpu bundle (scripts/make_gpu_bundle.sh) and the shared test meshes, then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200.sh [OUT_DIR]
# About 7.5 minutes, the CPU reference (2048 spp) included. Bring OUT_DIR/bench.json back and
# merge it here: scripts/benchmarks.sh --no-local OUT_DIR/bench.json
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/h200}}
"$tp" bench --ladder --table --scenes cornell,monkeys,bunny,buddhas,buddhas_instanced,rtxon \
  --backends cpu,vulkan:compute,vulkan:pipeline --width 512 --height 512 --max-spp 256 \
  --ref-spp 2048 ${ASSETS:+--assets "$ASSETS"} --section h200 --out "$out"
