#!/usr/bin/env bash
# Third device run for issue 28, the same bundle: why compute mode's cornell is slower with
# random than with sobol. The driver's pipeline statistics of the cornell and cornell_glossy
# specializations, and 1024-spp renders of both scenes with the scene-specialized path loop and
# with --features all, random and sobol, two rounds.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b /tmp/res && tar -C /tmp/b -xJf .carry/28b/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
size="--width 256 --height 256 --seed 3 --backend vulkan --vk-mode compute"
for scene in cornell cornell_glossy; do
  $tp render $scene $size --spp 16 -o /tmp/x.exr --pipeline-stats /tmp/res/pipeline-$scene.json >/dev/null 2>&1
  $tp render $scene $size --spp 16 --features all -o /tmp/x.exr --pipeline-stats /tmp/res/pipeline-$scene-all.json >/dev/null 2>&1
done
for rep in 1 2; do
  for scene in cornell cornell_glossy; do for f in scene all; do for s in random sobol; do
    $tp render $scene $size --features $f --sampler $s --spp 1024 -o /tmp/x.exr --stats /tmp/res/t-$scene-$f-$s-$rep.json >/dev/null 2>&1
    echo "compute $scene features=$f $s rep $rep: $(grep -o '"gpu_time_s": *[0-9.e-]*' /tmp/res/t-$scene-$f-$s-$rep.json)"
  done; done; done
done | tee /tmp/res/features_times.txt
tar -C /tmp/res -czf $OUT/h200-sampler-diag.tar.gz .
