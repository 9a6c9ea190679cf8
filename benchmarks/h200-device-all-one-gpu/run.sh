#!/usr/bin/env bash
# Issue 29 on the one H200 that is lent: render --device all against --device 0 at 1920x1080,
# 1024 spp, compute and pipeline; compare (statistical and --exact) each pair.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /tmp/b && tar -C /tmp/b -xJf .carry/29/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
S=/tmp/b/twinpath-bundle/scenes
w=$OUT/r; mkdir -p $w
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $w/gpu.txt
$tp info > $w/info.txt 2>&1
common="--backend vulkan --width 1920 --height 1080 --spp 1024 --seed 7"
sp="--eye -12,2.5,0 --target 6,4.5,0 --fov 70"
run() { # name scene mode device extra...
  local name=$1 scene=$2 mode=$3 dev=$4; shift 4
  /usr/bin/time -f "$name wall %e s" $tp render $scene $common --vk-mode $mode --device $dev \
    -o $w/$name.exr --stats $w/$name.json "$@" > $w/$name.log 2>&1; echo "$name rc=$?" >> $w/$name.log
}
for sc in cornell cornell_spheres bunny sponza; do
  case $sc in bunny) file=.carry/29/bunny/bunny.json; extra=();; sponza) file=.carry/29/sponza/sponza.json; extra=();; *) file=$S/$sc.json; extra=();; esac
  modes="compute pipeline"; [ $sc = sponza ] && modes=compute
  for m in $modes; do
    run $sc-$m-one $file $m 0 "${extra[@]}"
    run $sc-$m-all $file $m all "${extra[@]}"
    { echo "== $sc $m: one vs all"; $tp compare $w/$sc-$m-one.exr $w/$sc-$m-all.exr; echo "exit $?";
      $tp compare --exact $w/$sc-$m-one.exr $w/$sc-$m-all.exr; echo "exact exit $?"; } > $w/$sc-$m-compare.txt 2>&1
  done
done
rm -f $w/*.exr
tar -C $OUT -czf $OUT/r29.tar.gz r && rm -rf $w
