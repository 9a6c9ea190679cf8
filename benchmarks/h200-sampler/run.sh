#!/usr/bin/env bash
# Device run for issue 28: relMSE against time, random vs sobol in the same run, CPU (16
# threads) and Vulkan compute, on cornell, cornell_glossy, spheres, furnace, bunny at 256x256.
# Run 1 renders the CPU references (1024 spp, cached) and the CPU ladders to 256 spp; run 2
# the compute ladders to 512 spp against the same cached references.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b && tar -C /tmp/b -xzf .carry/28/twinpath-bundle.tar.gz
tp=/tmp/b/twinpath-bundle/bin/twinpath
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
common="--scenes cornell,cornell_glossy,spheres,furnace,bunny --samplers random,sobol --width 256 --height 256 --ref-spp 1024 --assets $PWD/.carry/28/assets --cache /tmp/cache"
$tp bench --ladder $common --backends cpu --max-spp 256 --section h200-sampler-cpu --out $OUT/h200-sampler-cpu 2>&1 | grep -v "^\s*$" | tail -40
$tp bench --ladder $common --backends vulkan:compute --max-spp 512 --section h200-sampler-compute --out $OUT/h200-sampler-compute 2>&1 | grep -v "^\s*$" | tail -40
ls -la $OUT
