#!/usr/bin/env bash
# Device run for issue 28 (sampler speed): relMSE against time, random vs sobol in the same
# run, CPU (all 16 threads) and Vulkan compute, on cornell, cornell_glossy, spheres, furnace and
# the bunny at 256x256. The CPU references (1024 spp) are rendered once and cached; the compute
# ladders use the same references. Then, for the CPU, time per sample without the ladder's
# snapshots: render at 256 spp, random and sobol alternating, twice each (the bundled scenes).
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b /tmp/res && tar -C /tmp/b -xJf .carry/28b/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; nproc; lscpu | grep -E "Model name|Thread|Core|Socket"; } > /tmp/res/machine.txt
common="--scenes cornell,cornell_glossy,spheres,furnace,bunny --samplers random,sobol --width 256 --height 256 --ref-spp 1024 --assets $PWD/.carry/28b/assets --cache /tmp/cache"
$tp bench --ladder $common --backends cpu --max-spp 256 --section h200-sampler-cpu --out /tmp/res/cpu 2>&1 | grep "ladder:\|wrote"
$tp bench --ladder $common --backends vulkan:compute --max-spp 512 --section h200-sampler-compute --out /tmp/res/compute 2>&1 | grep "ladder:\|wrote"
for rep in 1 2; do
  for scene in cornell cornell_glossy spheres furnace; do
    for s in random sobol; do
      $tp render $scene --sampler $s --spp 256 --width 256 --height 256 --seed 3 -o /tmp/x.exr --stats /tmp/res/render-$scene-$s-$rep.json >/dev/null 2>&1
      echo "render $scene $s rep $rep: $(grep -o '"wall_time_s": *[0-9.e-]*' /tmp/res/render-$scene-$s-$rep.json)"
    done
  done
done | tee /tmp/res/render_times.txt
tar -C /tmp/res -czf $OUT/h200-sampler.tar.gz .
ls -la $OUT
