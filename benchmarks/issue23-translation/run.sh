#!/usr/bin/env bash
# Device run for issue 23 item 2 (pipeline mode on the H200): the stress suite at CI size in
# pipeline mode (its position group: the reference scene moved by 1e2, 1e4, 1e6, the same image
# bit for bit), and the measurement (cornell_spheres as OBJ moved with its camera) in
# pipeline and compute mode.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b && tar -C /tmp/b -xJf .carry/23/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
$tp info | head -8
mkdir -p $OUT/stress
t0=$(date +%s)
$tp bench --stress --quick --backends vulkan:pipeline --out $OUT/stress > $OUT/stress/log.txt 2>&1
echo "bench --stress exit $? in $(( $(date +%s) - t0 )) s"
grep -E "position|passed, " $OUT/stress/stress.md | cut -c1-400
for mode in pipeline compute; do
  t0=$(date +%s)
  bash .carry/23/measure.sh $tp /tmp/m-$mode --backend vulkan --vk-mode $mode > $OUT/measure-$mode.md 2>&1
  echo "measure $mode in $(( $(date +%s) - t0 )) s"; cat $OUT/measure-$mode.md
  tail -1 /tmp/m-$mode/d1e4-s1.log
done
