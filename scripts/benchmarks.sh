#!/usr/bin/env bash
# Regenerates BENCHMARKS.md (docs/bench.md, "Regenerating BENCHMARKS.md") in one command:
#
#   scripts/benchmarks.sh [--quick] [--no-local] [GPU_RESULT.json ...]
#
# 1. The sections measured here at the default size, each a bench result rendered and merged
#    by `twinpath-lab markdown`:
#      local-ladder  error against time, CPU (Embree) and Vulkan (every mode of the device:
#                    compute on Mesa lavapipe on a machine without a GPU);
#      local-table   rays/s and time over depth and spp (thesis Table 5.3), CPU;
#      local-peer    time per spp next to Embree's path tracer tutorial (/usr/bin/pathtracer)
#                    and time to error next to Cycles (`twinpath-lab peer`);
#      local-sizes   rays/s against image size, CPU and Vulkan, up to 512x512 (lavapipe takes
#                    seconds per pass beyond; the GPU machine measures up to 3840x2160).
# 2. The sections of results brought back from other machines (the GPU rows): each argument is
#    a bench.json; it is copied to $BENCH_RESULTS/<its section id>/bench.json, its CSV and plots
#    are rendered there again, and its section is merged.
# Each section sits between markers in the markdown file and is replaced in place when it is
# generated again; the text around the sections is kept. --no-local merges results only;
# --quick runs the local sections at the CI smoke size (to check this script, not to publish).
#
# Environment: TWINPATH (default build/bin/twinpath), TWINPATH_LAB (default
# build/bin/twinpath-lab), BENCH_MARKDOWN (default BENCHMARKS.md), BENCH_RESULTS (default
# benchmarks: the JSON, CSV and SVG plots the markdown links to), TWINPATH_ASSETS (the shared
# test meshes, default ../shared/assets), TWINPATH_CACHE (the reference cache, default
# ~/.cache/twinpath).
set -euo pipefail
cd "$(dirname "$0")/.."

twinpath=${TWINPATH:-build/bin/twinpath}
lab=${TWINPATH_LAB:-build/bin/twinpath-lab}
markdown=${BENCH_MARKDOWN:-BENCHMARKS.md}
results=${BENCH_RESULTS:-benchmarks}
quick=()
local_sections=1
gpu_results=()
for arg in "$@"; do
  case "$arg" in
    --quick) quick=(--quick) ;;
    --no-local) local_sections=0 ;;
    -h | --help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "benchmarks.sh: unknown option $arg (see --help)" >&2; exit 2 ;;
    *)
      [[ -f "$arg" ]] || { echo "benchmarks.sh: $arg: no such file" >&2; exit 2; }
      gpu_results+=("$arg") ;;
  esac
done
for exe in "$twinpath" "$lab"; do
  if [[ ! -x "$exe" ]]; then
    echo "benchmarks.sh: $exe is not built (make build, or set TWINPATH and TWINPATH_LAB)" >&2
    exit 2
  fi
done

# local_section SECTION COMMAND [OPTION ...]: `twinpath bench` or `twinpath-lab peer` into
# $results/SECTION, then its files and its section of the markdown.
local_section() {
  local section=$1
  shift
  "$@" "${quick[@]}" --section "$section" --out "$results/$section"
  "$lab" markdown "$results/$section/bench.json" --markdown "$markdown"
}

if ((local_sections)); then
  local_section local-ladder "$twinpath" bench --ladder --backends cpu,vulkan
  local_section local-table "$twinpath" bench --table --backends cpu
  local_section local-peer "$lab" peer --scenes cornell,bunny --width 512 --height 512
  sizes=(--sizes-list 32,64,128,256,512)
  ((${#quick[@]})) && sizes=() # --quick's own smoke sizes
  local_section local-sizes "$twinpath" bench --sizes --scenes cornell,bunny --backends cpu,vulkan \
    "${sizes[@]}"
fi

for json in "${gpu_results[@]}"; do
  section=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["section"])' "$json")
  mkdir -p "$results/$section"
  if [[ ! "$json" -ef "$results/$section/bench.json" ]]; then
    cp "$json" "$results/$section/bench.json"
    chmod u+w "$results/$section/bench.json"
  fi
  "$lab" markdown "$results/$section/bench.json" --markdown "$markdown"
done
echo "benchmarks.sh: $markdown updated (results in $results/)"
