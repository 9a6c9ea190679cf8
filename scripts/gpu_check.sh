#!/usr/bin/env bash
# The GPU machine's checks of the Vulkan backend (docs/gpu.md "Running on a GPU
# machine"), run from an unpacked gpu bundle on a node that has only a driver:
#   1. `twinpath info --json`: the devices and the modes each offers;
#   2. every bundled scene rendered on the CPU, in compute mode and in pipeline mode with
#      independent seeds, and all three pairs compared (`twinpath compare`, alpha = 0.01);
#   3. with the Khronos validation layer (when a layer folder is given): one short render per
#      scene and mode with TWINPATH_VALIDATION=1, which fails on any message;
#   4. throughput at 1920x1080 (`twinpath bench`), CPU next to both GPU modes in one run, on
#      cornell, the bunny and four Happy Buddhas (unique and instanced).
# Every step logs to OUT and the script goes on after a failed step; the summary at the end
# lists each step's exit code, and the script's exit code is the number of failed steps.
#
# usage: scripts/gpu_check.sh BUNDLE_DIR OUT_DIR [--assets DIR] [--layer DIR] [--spp N]
#                             [--perf-spp N] [--skip-perf]
#   BUNDLE_DIR  unpacked twinpath-bundle (bin/twinpath, lib/, scenes/)
#   --assets    the shared test meshes (bunny/, buddha/, ...) for the throughput step
#   --layer     a folder with libVkLayer_khronos_validation.so and its manifest
set -uo pipefail

bundle=$1
out=$2
shift 2
assets=""
layer=""
spp=256
perf_spp=64
perf=1
while (($#)); do
  case $1 in
    --assets) assets=$2; shift 2 ;;
    --layer) layer=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --perf-spp) perf_spp=$2; shift 2 ;;
    --skip-perf) perf=0; shift ;;
    *) echo "gpu_check: unknown option $1" >&2; exit 2 ;;
  esac
done

tp="$bundle/bin/twinpath"
scenes=("$bundle"/scenes/*.json "$bundle"/scenes/*.gltf)
mkdir -p "$out/renders" "$out/compare" "$out/logs"
summary="$out/summary.txt"
: >"$summary"
failed=0

# step NAME CMD...: runs CMD with its output in logs/NAME.log, records the exit code.
step() {
  local name=$1
  shift
  local t0=$SECONDS
  "$@" >"$out/logs/$name.log" 2>&1
  local rc=$?
  printf '%-48s exit %d  %4d s\n' "$name" "$rc" $((SECONDS - t0)) | tee -a "$summary"
  return $rc
}
# expect_ok NAME CMD...: a step that must succeed.
expect_ok() { step "$@" || failed=$((failed + 1)); }

expect_ok info "$tp" info --json
cp "$out/logs/info.log" "$out/info.json"

modes=(cpu compute pipeline)
for scene in "${scenes[@]}"; do
  name=$(basename "${scene%.*}")
  seed=1
  for mode in "${modes[@]}"; do
    backend=(--backend vulkan --vk-mode "$mode")
    [[ $mode == cpu ]] && backend=(--backend cpu)
    expect_ok "render_${name}_${mode}" "$tp" render "$scene" "${backend[@]}" --spp "$spp" \
      --seed "$seed" --width 256 --height 256 -o "$out/renders/${name}_${mode}.exr" \
      --stats "$out/renders/${name}_${mode}.json"
    seed=$((seed + 1))
  done
  for pair in cpu:compute cpu:pipeline compute:pipeline; do
    a=${pair%%:*}
    b=${pair##*:}
    expect_ok "compare_${name}_${a}_${b}" "$tp" compare "$out/renders/${name}_${a}.exr" \
      "$out/renders/${name}_${b}.exr" --json "$out/compare/${name}_${a}_${b}.json"
  done
done

if [[ -n $layer ]]; then
  for scene in "${scenes[@]}"; do
    name=$(basename "${scene%.*}")
    for mode in compute pipeline; do
      expect_ok "validation_${name}_${mode}" env TWINPATH_VALIDATION=1 VK_LAYER_PATH="$layer" \
        LD_LIBRARY_PATH="$layer:${LD_LIBRARY_PATH:-}" "$tp" render "$scene" --backend vulkan \
        --vk-mode "$mode" --spp 16 --width 128 --height 128 -o "$out/renders/val_${name}_${mode}.exr"
    done
  done
fi

if ((perf)) && [[ -n $assets ]]; then
  expect_ok perf_1080p "$tp" bench --ladder --scenes cornell bunny buddhas buddhas_instanced \
    --backends cpu vulkan:compute vulkan:pipeline --width 1920 --height 1080 \
    --max-spp "$perf_spp" --ref-spp "$perf_spp" --assets "$assets" --section h200-1080p \
    --out "$out/perf_1080p"
fi

echo "gpu_check: $failed failed step(s)" | tee -a "$summary"
exit "$failed"
