#!/usr/bin/env bash
# BENCHMARKS.md table `h200-device-all`: `render --device all` (docs/farm.md) against
# `--device 0` on a machine with one GPU: what sharing the sample ranges costs when there is one
# device, and whether the image is the plain render's. 1920x1080, 1024 spp, seed 7, both modes
# (Sponza: compute), then `compare --exact` on each pair.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the scenes of `benchmarks/h200-view.sh prepare`, then
#   TWINPATH=BUNDLE/bin/twinpath benchmarks/h200-device-all.sh SCENES_DIR [OUT_DIR]
# About 2 minutes. Prints the table.
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
dir=${1:?usage: h200-device-all.sh SCENES_DIR [OUT_DIR]}
out=${2:-${OUT:-out/h200-device-all}}
mkdir -p "$out"
echo "| scene | mode | GPU s, device 0 | GPU s, all | all ÷ one | ranges (all) | compare --exact |"
echo "|---|---|---:|---:|---:|---:|---|"
for s in cornell cornell_spheres "$dir/bunny/bunny.json" "$dir/sponza/sponza.json"; do
  n=$(basename "${s%.json}")
  modes="compute pipeline"; [ $n = sponza ] && modes=compute
  for m in $modes; do
    for d in 0 all; do
      "$tp" render "$s" --backend vulkan --vk-mode $m --device $d --width 1920 --height 1080 \
        --spp 1024 --seed 7 -o "$out/$n-$m-$d.exr" --stats "$out/$n-$m-$d.json" >/dev/null 2>&1 ||
        echo "render failed: $n $m --device $d" >&2
    done
    exact=$("$tp" compare --exact "$out/$n-$m-0.exr" "$out/$n-$m-all.exr" 2>&1 | head -1)
    python3 - "$out/$n-$m-0.json" "$out/$n-$m-all.json" "$n" "$m" "${exact%% (*}" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
one, all_ = a["gpu_time_s"], b["gpu_time_s"]
ranges = len(b["devices"][0]["sample_ranges"])
print(f"| {sys.argv[3]} | {sys.argv[4]} | {one:.2f} | {all_:.2f} | {all_ / one:.3f} | {ranges} | {sys.argv[5]} |")
PY
  done
done
