#!/usr/bin/env bash
# BENCHMARKS.md section `h200-frame-loop`: the viewer's frame loop without a window (bench
# --frame-loop: docs/bench.md) at 1920x1080 and at 256x256, 1, 4 and 16 spp per frame, in both
# GPU modes, on cornell and the bunny: ms per frame, its split into trace, resolve, display and
# host, and the fixed cost of a frame.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes, then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-frame-loop.sh [OUT_DIR]
# 2 scenes x 2 modes x 2 sizes x 3 points of 300 frames: under 2 minutes on the H200. Bring
# OUT_DIR/1080/bench.json and OUT_DIR/256/bench.json back and merge them here:
#   scripts/benchmarks.sh --no-local OUT_DIR/1080/bench.json OUT_DIR/256/bench.json
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
: "${ASSETS:?ASSETS: the shared test meshes (bunny/)}"
out=${1:-${OUT:-out/h200-frame-loop}}
for size in 1920x1080 256x256; do
  w=${size%x*} h=${size#*x}
  "$tp" bench --frame-loop --frame-loop-spp 1,4,16 --frame-loop-frames 300 \
    --backends vulkan:compute,vulkan:pipeline \
    --scenes "cornell,$ASSETS/bunny/stanford-bunny.obj" --width "$w" --height "$h" \
    --section "h200-frame-loop-$h" --out "$out/$h"
done
