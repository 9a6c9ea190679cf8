#!/usr/bin/env bash
# Device run for issue 28 after the CPU sampler savings: (1) the ladder, random vs sobol, CPU
# (16 threads) and compute, five scenes at 256x256 (as benchmarks/h200-sampler/run.sh);
# (2) time per sample by repeated renders, order alternating: CPU 256 spp at 256x256 (4 rounds),
# compute 1024 spp at 256x256 and 64 spp at 1920x1080 (3 rounds each, GPU timestamps), the
# bundled scenes. The 1080p rounds fill the GPU (8.3x the threads of 256x256).
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b /tmp/res && tar -C /tmp/b -xJf .carry/28d/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
t0=$(date +%s)
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; nproc; lscpu | grep -E "Model name|Thread|Core|Socket"; } > /tmp/res/machine.txt
common="--scenes cornell,cornell_glossy,spheres,furnace,bunny --samplers random,sobol --width 256 --height 256 --ref-spp 1024 --assets $PWD/.carry/28d/assets --cache /tmp/cache"
$tp bench --ladder $common --backends cpu --max-spp 256 --section h200-sampler-cpu --out /tmp/res/cpu 2>&1 | grep "ladder:\|wrote"
echo "cpu ladder done at $(( $(date +%s) - t0 )) s"
$tp bench --ladder $common --backends vulkan:compute --max-spp 512 --section h200-sampler-compute --out /tmp/res/compute 2>&1 | grep "ladder:\|wrote"
echo "compute ladder done at $(( $(date +%s) - t0 )) s"
scenes="cornell cornell_glossy spheres furnace"
$tp render cornell --backend vulkan --vk-mode compute --spp 256 --width 256 --height 256 -o /tmp/x.exr >/dev/null 2>&1
for rep in 1 2 3; do
  order="random sobol"; [ $((rep % 2)) = 0 ] && order="sobol random"
  for scene in $scenes; do for s in $order; do
    for size in "256 256 1024" "1920 1080 64"; do set -- $size
      j=/tmp/res/compute-$1-$scene-$s-$rep.json
      $tp render $scene --backend vulkan --vk-mode compute --sampler $s --spp $3 --width $1 --height $2 --seed 3 -o /tmp/x.exr --stats $j >/dev/null 2>&1
      echo "compute ${1}x$2 $scene $s rep $rep: $(grep -o '"gpu_time_s": *[0-9.e-]*' $j) $(grep -o '"wall_time_s": *[0-9.e-]*' $j)"
    done
  done; done
done | tee /tmp/res/compute_times.txt
echo "compute rounds done at $(( $(date +%s) - t0 )) s"
for rep in 1 2 3 4; do
  order="random sobol"; [ $((rep % 2)) = 0 ] && order="sobol random"
  for scene in $scenes; do for s in $order; do
    j=/tmp/res/cpu-$scene-$s-$rep.json
    $tp render $scene --sampler $s --spp 256 --width 256 --height 256 --seed 3 -o /tmp/x.exr --stats $j >/dev/null 2>&1
    echo "cpu $scene $s rep $rep: $(grep -o '"wall_time_s": *[0-9.e-]*' $j)"
  done; done
done | tee /tmp/res/cpu_times.txt
echo "all done at $(( $(date +%s) - t0 )) s"
rm -f /tmp/res/*.json
tar -C /tmp/res -czf $OUT/h200-sampler.tar.gz .
