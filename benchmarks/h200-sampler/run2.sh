#!/usr/bin/env bash
# Second device run for issue 28 (sampler speed), the same bundle as run.sh: time per sample
# of random and sobol, repeated, without the ladder's snapshots. Compute mode: 1024 spp at
# 256x256 after one warm-up render, three rounds, the sampler order alternating per round; the
# GPU time from timestamp queries and the wall time. CPU (16 threads): 256 spp, two more rounds
# after run.sh's two, order alternating. The bundled scenes (the bunny is a scene of bench only).
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b /tmp/res && tar -C /tmp/b -xJf .carry/28b/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
scenes="cornell cornell_glossy spheres furnace"
size="--width 256 --height 256 --seed 3"
$tp render cornell --backend vulkan --vk-mode compute --spp 256 $size -o /tmp/x.exr >/dev/null 2>&1
for rep in 1 2 3; do
  order="random sobol"; [ $((rep % 2)) = 0 ] && order="sobol random"
  for scene in $scenes; do for s in $order; do
    $tp render $scene --backend vulkan --vk-mode compute --sampler $s --spp 1024 $size -o /tmp/x.exr --stats /tmp/res/compute-$scene-$s-$rep.json >/dev/null 2>&1
    echo "compute $scene $s rep $rep: $(grep -o '"gpu_time_s": *[0-9.e-]*' /tmp/res/compute-$scene-$s-$rep.json) $(grep -o '"wall_time_s": *[0-9.e-]*' /tmp/res/compute-$scene-$s-$rep.json)"
  done; done
done | tee /tmp/res/compute_times.txt
for rep in 3 4; do
  order="random sobol"; [ $((rep % 2)) = 1 ] && order="sobol random"
  for scene in $scenes; do for s in $order; do
    $tp render $scene --sampler $s --spp 256 $size -o /tmp/x.exr --stats /tmp/res/cpu-$scene-$s-$rep.json >/dev/null 2>&1
    echo "cpu $scene $s rep $rep: $(grep -o '"wall_time_s": *[0-9.e-]*' /tmp/res/cpu-$scene-$s-$rep.json)"
  done; done
done | tee /tmp/res/cpu_times.txt
tar -C /tmp/res -czf $OUT/h200-sampler-times.tar.gz .
ls -la $OUT
