#!/usr/bin/env bash
# BENCHMARKS.md table `h200-gpu-check`: the p-values of scripts/gpu_check.sh (docs/gpu.md,
# "Running on a GPU machine": every bundled scene at 256x256, 256 spp on the CPU (seed 1), in
# compute mode (seed 2) and in pipeline mode (seed 3), each pair compared at alpha = 0.01), and of
# compute against pipeline mode at 2048 spp, where a bias of 2-3 % would show.
#
# Runs on the GPU machine: carry the unpacked gpu bundle (scripts/make_gpu_bundle.sh), the
# shared test meshes and a folder with Debian's Khronos validation layer (docs/gpu.md), then
#   BUNDLE=BUNDLE_DIR ASSETS=MESHES LAYER=LAYER_DIR benchmarks/h200-gpu-check.sh [OUT_DIR]
# About 3 minutes. Prints the table; gpu_check's own summary is OUT_DIR/summary.txt.
set -uo pipefail
: "${BUNDLE:?BUNDLE: the unpacked gpu bundle (bin/twinpath, lib/, scenes/)}"
out=${1:-${OUT:-out/h200-gpu-check}}
here=$(dirname "$0")
"$here/../scripts/gpu_check.sh" "$BUNDLE" "$out" ${ASSETS:+--assets "$ASSETS"} \
  ${LAYER:+--layer "$LAYER"} --skip-perf
tp=$BUNDLE/bin/twinpath
for scene in "$BUNDLE"/scenes/*.json "$BUNDLE"/scenes/*.gltf; do
  name=$(basename "${scene%.*}")
  for mode in compute pipeline; do
    seed=4; [ $mode = pipeline ] && seed=5
    "$tp" render "$scene" --backend vulkan --vk-mode $mode --spp 2048 --seed $seed --width 256 \
      --height 256 -o "$out/renders/${name}_${mode}_2048.exr" >/dev/null 2>&1
  done
  "$tp" compare "$out/renders/${name}_compute_2048.exr" "$out/renders/${name}_pipeline_2048.exr" \
    --json "$out/compare/${name}_2048.json" >/dev/null 2>&1
done
python3 - "$out/compare" <<'PY'
import glob, json, os, sys
d = sys.argv[1]
p = lambda f: (f"{json.load(open(f))['p_value']:.2g}" if os.path.exists(f) else "–")
print("| scene | CPU vs compute | CPU vs pipeline | compute vs pipeline | compute vs pipeline, 2048 spp |")
print("|---|---:|---:|---:|---:|")
for f in sorted(glob.glob(os.path.join(d, "*_cpu_compute.json"))):
    n = os.path.basename(f)[:-len("_cpu_compute.json")]
    cells = [p(os.path.join(d, f"{n}_{pair}.json"))
             for pair in ("cpu_compute", "cpu_pipeline", "compute_pipeline", "2048")]
    print(f"| {n} | " + " | ".join(cells) + " |")
PY
