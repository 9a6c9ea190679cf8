#!/usr/bin/env bash
# BENCHMARKS.md section `h200-cpu-specialization`: time per spp of the CPU path loop with every
# feature compiled in over the loop compiled for the scene's features, on the GPU machine's
# idle 16-core CPU (any idle machine will do; the section names the one it ran on).
#
# On the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu bundle
# (scripts/make_gpu_bundle.sh) and the shared test meshes (the bunny), then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-cpu-specialization.sh [OUT_DIR]
# Under a minute. Bring OUT_DIR/bench.json back and merge it here:
# scripts/benchmarks.sh --no-local OUT_DIR/bench.json
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/h200-cpu-specialization}}
"$tp" bench --specialization --scenes cornell,cornell_glossy,spheres,furnace,bunny --backends cpu \
  --width 512 --height 512 --spec-spp 16 --spec-rounds 7 ${ASSETS:+--assets "$ASSETS"} \
  --section h200-cpu-specialization --out "$out"
