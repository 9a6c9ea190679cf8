#!/usr/bin/env bash
# Device run for issue 26: twinpath view --headless at 1920x1080, 1 spp per frame, on cornell,
# the bunny and Sponza, compute and pipeline modes; plus a check that the refactored render
# loop still renders in both modes (compute vs pipeline compare on cornell).
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b && tar -C /tmp/b -xJf .carry/26/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
c=.carry/26
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $OUT/view.txt
declare -A scene=([cornell]=/tmp/b/twinpath-bundle/scenes/cornell.json [bunny]=$c/bunny/bunny.json [sponza]=$c/sponza/sponza.json)
for s in cornell bunny sponza; do
  for m in compute pipeline; do
    cmd="twinpath view ${scene[$s]} --headless --vk-mode $m --width 1920 --height 1080 --spp-per-frame 1 --frames 300"
    echo "== $s $m: $cmd" | tee -a $OUT/view.txt
    /usr/bin/time -f "wall %e s" timeout 60 $tp ${cmd#twinpath } 2>&1 | grep -v "^twinpath: warning" | tee -a $OUT/view.txt
  done
done
w=/tmp/r; mkdir -p $w
for m in compute pipeline; do
  timeout 60 $tp render ${scene[cornell]} --backend vulkan --vk-mode $m --width 256 --height 256 --spp 256 --seed $([ $m = compute ] && echo 1 || echo 2) -o $w/$m.exr 2>&1 | tail -1 | tee -a $OUT/view.txt
done
$tp compare $w/compute.exr $w/pipeline.exr > $w/cmp.txt 2>&1; echo "compare exit $?" | tee -a $OUT/view.txt
tail -3 $w/cmp.txt | tee -a $OUT/view.txt
