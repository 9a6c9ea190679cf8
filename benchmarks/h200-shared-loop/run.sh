#!/usr/bin/env bash
# Device run for issue 24: time per spp before (739d6cf) and after (issue 24) on cornell and the
# bunny, CPU on the node's cores and Vulkan compute + pipeline on the H200, interleaved
# before/after, 3 rounds; then same-seed exact comparisons of the two builds per mode.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
c=.carry/24
for v in before after; do mkdir -p /tmp/$v && tar -C /tmp/$v -xJf $c/$v.tar.xz; done
w=$OUT/runs; mkdir -p $w
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $OUT/device.txt
nproc >> $OUT/device.txt
scene() { [ $1 = bunny ] && echo $c/bunny.json || echo /tmp/after/twinpath-bundle/scenes/$1.json; }
r() { # round build scene backend mode limit
  local tp=/tmp/$2/twinpath-bundle/bin/twinpath n=$1-$2-$3-$4-$5
  local args="--width 256 --height 256 --seed 7 --spp 100000 --time-limit $6"
  [ $4 = vulkan ] && args="$args --backend vulkan --vk-mode $5" || args="$args --backend cpu"
  $tp render $(scene $3) $args -o /tmp/x.exr --stats /tmp/s.json > /tmp/l.log 2>&1 || echo "FAIL $n"
  echo "$1,$2,$3,$4,$5,$(grep -o '"spp": [0-9]*' /tmp/s.json | grep -o '[0-9]*'),$(grep -o '"wall_time_s": [0-9.e-]*' /tmp/s.json | cut -d' ' -f2),$(grep -o '"gpu_time_s": [0-9.e-]*' /tmp/s.json | cut -d' ' -f2)" >> $OUT/times.csv
}
echo "round,build,scene,backend,mode,spp,wall_s,gpu_s" > $OUT/times.csv
for round in 1 2; do
  for sc in cornell bunny; do
    for b in before after; do r $round $b $sc cpu embree 3; done
    for m in compute pipeline; do for b in after before; do r $round $b $sc vulkan $m 2; done; done
  done
done
cat $OUT/times.csv
