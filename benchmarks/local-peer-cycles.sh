#!/usr/bin/env bash
# BENCHMARKS.md section `local-peer-cycles`: time to error of the CPU engine, with each sampler,
# next to Blender's Cycles on cornell at 2 threads, and its rays/s next to Embree's path tracer
# tutorial (docs/bench.md, "Peer comparisons"). Needs Debian's `blender` and `embree-tools`.
#   [TWINPATH_LAB=build/bin/twinpath-lab] benchmarks/local-peer-cycles.sh [OUT_DIR]
# About 3 minutes on 2 cores (the Cycles reference included). Merges the section into
# BENCHMARKS.md (BENCH_MARKDOWN to name another file).
set -euo pipefail
lab=${TWINPATH_LAB:-build/bin/twinpath-lab}
out=${1:-${OUT:-out/local-peer-cycles}}
"$lab" peer --scenes cornell --samplers random,sobol --peer-threads 2 --width 256 --height 256 \
  --ref-spp 1024 --section local-peer-cycles --out "$out"
"$lab" markdown "$out/bench.json" --markdown "${BENCH_MARKDOWN:-BENCHMARKS.md}"
