#!/usr/bin/env bash
# BENCHMARKS.md table `h200-stress`: the numerical stress suite (docs/stress.md) at full size on
# the CPU, in compute mode and in pipeline mode, with the C++/GLSL function sweeps.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes, then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-stress.sh [OUT_DIR]
# About 2 minutes. OUT_DIR/stress.md is the report with every case's measurement.
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/h200-stress}}
"$tp" bench --stress --backends cpu,vulkan ${ASSETS:+--assets "$ASSETS"} --out "$out"
grep -E "passed, " "$out/stress.md" || true
