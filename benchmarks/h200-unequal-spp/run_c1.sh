#!/usr/bin/env bash
# Device run C1 (issue 22): the table on the H200. cornell_spheres 256x256, max depth
# 1000 (the scene's), CPU at 64/256/2048/4096 spp, Vulkan compute and pipeline at 16384 spp;
# compare (the new rule) on the pairs. Images come back for the old compare here.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b && tar -C /tmp/b -xJf .carry/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
scene=/tmp/b/twinpath-bundle/scenes/cornell_spheres.json
w=/tmp/c1; mkdir -p $w
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
$tp info | head -20
common="--width 256 --height 256"
r() { local name=$1; shift; /usr/bin/time -f "$name %e s" $tp render $scene $common -o $w/$name.exr --stats $w/$name.json "$@" 2>&1 | tail -2; }
r cpu64 --spp 64 --seed 3
r cpu256 --spp 256 --seed 5
r cpu2048 --spp 2048 --seed 14
r cpu4096 --spp 4096 --seed 15
r compute16384 --backend vulkan --vk-mode compute --spp 16384 --seed 21
r pipeline16384 --backend vulkan --vk-mode pipeline --spp 16384 --seed 21
c() { echo "== $1 vs $2"; $tp compare $w/$1.exr $w/$2.exr --json $w/cmp-$1-$2.json; echo "exit $?"; }
c cpu256 cpu2048
c cpu64 cpu4096
c cpu256 compute16384
c cpu2048 compute16384
c cpu4096 compute16384
c cpu2048 pipeline16384
c compute16384 pipeline16384
tar -C $w -czf $OUT/c1.tar.gz .
ls -la $OUT
