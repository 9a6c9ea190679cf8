#!/usr/bin/env bash
# `make demo`: renders the default scene (cornell) on both backends, compares them and writes
# the images, the statistics and a report into OUT_DIR.
# The two renders use different seeds, so the comparison is a real statistical test of two
# independent estimates of the same image (with equal seeds both engines trace the same
# paths and agree to float rounding, which `compare` would accept trivially).
# Defaults suit lavapipe (the CPU-only Vulkan driver); override with DEMO_SIZE / DEMO_SPP.
set -euo pipefail
twinpath=${1:?usage: demo.sh TWINPATH OUT_DIR}
out=${2:?usage: demo.sh TWINPATH OUT_DIR}
scene=${DEMO_SCENE:-cornell}
size=${DEMO_SIZE:-256}
spp=${DEMO_SPP:-128}
mkdir -p "$out"
common=(--width "$size" --height "$size" --spp "$spp")

echo "== CPU reference (Embree + TBB) =="
"$twinpath" render "$scene" --backend cpu "${common[@]}" --seed 1 -o "$out/$scene-cpu.exr" \
  --png "$out/$scene-cpu.png" --stats "$out/$scene-cpu.stats.json"

echo "== Vulkan ($("$twinpath" info --json | python3 -c 'import json,sys; d=json.load(sys.stdin); print(d["backends"].get("vulkan",{}).get("devices",[{}])[0].get("name","?"))' 2>/dev/null || echo default device)) =="
"$twinpath" render "$scene" --backend vulkan "${common[@]}" --seed 2 -o "$out/$scene-vulkan.exr" \
  --png "$out/$scene-vulkan.png" --stats "$out/$scene-vulkan.stats.json"

echo "== compare =="
status=0
"$twinpath" compare "$out/$scene-vulkan.exr" "$out/$scene-cpu.exr" --json "$out/compare.json" \
  --report "$out/report" || status=$?
echo "Images, statistics and the report ($out/report/index.html) are in $out/"
exit "$status"
