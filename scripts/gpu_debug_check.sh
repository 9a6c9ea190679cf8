#!/usr/bin/env bash
# Path logs and AOVs in pipeline mode (docs/debugging.md), for the GPU machine: lavapipe
# cannot run the ray-tracing pipeline, so CI only compiles and validates its debug stage.
# For every bundled scene and a few pixels (centre, corners, a quarter in), the pipeline-mode
# path log is held against the CPU's and the compute mode's with `twinpath pathdiff`, and the
# pipeline-mode AOVs against the CPU's with `twinpath compare --exact`. With a validation layer
# folder (--layer), TWINPATH_VALIDATION=1 is set, so any validation message fails the render.
# Exit code: the number of failed checks; every command and its output go to OUT/log.txt.
#
# usage: scripts/gpu_debug_check.sh TWINPATH OUT_DIR [--layer DIR]
#   TWINPATH  the executable (build/bin/twinpath, or BUNDLE/bin/twinpath of a gpu bundle)
set -uo pipefail

tp=$1
out=$2
shift 2
if [[ ${1:-} == --layer ]]; then
  export VK_LAYER_PATH=$2 TWINPATH_VALIDATION=1
fi
mkdir -p "$out"
log=$out/log.txt
: >"$log"
failed=0

check() { # name, expected exit code, command...
  local name=$1 want=$2
  shift 2
  echo "\$ $*" >>"$log"
  "$@" >>"$log" 2>&1
  local rc=$?
  if [[ $rc -eq $want ]]; then
    echo "ok    $name"
  else
    echo "FAIL  $name (exit $rc, expected $want)"
    failed=$((failed + 1))
  fi
}

size="--width 64 --height 64"
for scene in cornell cornell_glossy spheres furnace; do
  for px in 32,32 16,48 48,16 5,60; do
    base=$out/$scene-${px/,/-}
    common="$size --spp 4 --seed 3 --debug-pixel $px"
    check "$scene $px cpu log" 0 "$tp" render "$scene" $common -o "$base-cpu.exr" --debug-log "$base-cpu.json"
    check "$scene $px compute log" 0 "$tp" render "$scene" --backend vulkan --vk-mode compute $common -o "$base-compute.exr" --debug-log "$base-compute.json"
    check "$scene $px pipeline log" 0 "$tp" render "$scene" --backend vulkan --vk-mode pipeline $common -o "$base-pipeline.exr" --debug-log "$base-pipeline.json"
    # Pipeline mode offsets new rays 4 times as far (shared/offset.h, TP_OFFSET_INTERSECTOR_SLACK):
    # its origins drift from the CPU's by up to 3 offset bounds per bounce, 1.1e-4 in t after 8
    # furnace bounces on the H200, past pathdiff's default 1e-4. 1e-3 still separates a
    # divergence (another triangle, lobe or light) from that drift.
    check "$scene $px pathdiff cpu pipeline" 0 "$tp" pathdiff --geometry-tolerance 1e-3 "$base-cpu.json" "$base-pipeline.json"
    check "$scene $px pathdiff compute pipeline" 0 "$tp" pathdiff --geometry-tolerance 1e-3 "$base-compute.json" "$base-pipeline.json"
  done
  check "$scene cpu aov" 0 "$tp" render "$scene" $size --spp 1 --aov all -o "$out/$scene-aov-cpu.exr"
  check "$scene pipeline aov" 0 "$tp" render "$scene" --backend vulkan --vk-mode pipeline $size --spp 1 --aov all -o "$out/$scene-aov-pipeline.exr"
  check "$scene aov exact" 0 "$tp" compare --exact "$out/$scene-aov-cpu.exr" "$out/$scene-aov-pipeline.exr"
  for view in normals albedo depth; do
    check "$scene pipeline view $view" 0 "$tp" render "$scene" --backend vulkan --vk-mode pipeline $size --spp 4 --integrator $view -o "$out/$scene-$view.exr" --png "$out/$scene-$view.png"
  done
done
# Pipeline mode has no traversal counts: the cost view must refuse with exit 2.
check "pipeline cost view refused" 2 "$tp" render cornell --backend vulkan --vk-mode pipeline $size --spp 1 --integrator cost -o "$out/cost.exr"

echo "$failed failed check(s); log: $log"
exit "$failed"
