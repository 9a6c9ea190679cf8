#!/usr/bin/env bash
# Device run (issue 25): compute mode with the binary and the compressed 8-wide BVH, and
# pipeline mode, side by side at 1920x1080 on eight scenes; each render runs passes until
# T seconds have gone (--time-limit), the stats JSON gives GPU time, spp, rays, BVH bytes and
# build time. Then same-seed images of both layouts, compared bit for bit.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
C=$PWD/.carry/25
mkdir -p /tmp/b && tar -C /tmp/b -xJf $C/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
S=/tmp/b/twinpath-bundle/scenes
mkdir -p /tmp/sc
for f in $C/scenes/*.json; do sed "s|@ASSETS@|$C/assets|g" $f > /tmp/sc/$(basename $f); done
# Sponza without its textures: the bundle reads no JPEG (no OpenImageIO); traversal is the same.
mkdir -p /tmp/sponza && cp $C/assets/sponza-dabrovic/sponza.obj /tmp/sponza/
grep -v "map_" $C/assets/sponza-dabrovic/sponza.mtl > /tmp/sponza/sponza.mtl
R=/tmp/raw; mkdir -p $R
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $R/gpu.txt
scene_path() { case $1 in cornell|cornell_spheres|furnace) echo $S/$1.json;; sponza) echo /tmp/sponza/sponza.obj;; *) echo /tmp/sc/$1.json;; esac; }
scene_args() { if [ $1 = sponza ]; then echo "--eye -12,2.5,0 --target 6,4.5,0 --fov 70"; fi; }
T=${T:-2.5}
SCENES=${SCENES:-cornell cornell_spheres furnace bunny buddhas buddhas_instanced rtxon sponza}
for s in $SCENES; do
  for v in ${VARIANTS:-binary wide pipeline}; do
    if [ $v = pipeline ]; then m="--vk-mode pipeline"; else m="--vk-mode compute --bvh $v"; fi
    /usr/bin/time -f "%e" -o $R/$s-$v.time $tp render $(scene_path $s) $(scene_args $s) --backend vulkan $m \
      --width 1920 --height 1080 --spp 100000 --time-limit $T --seed 1 -o /tmp/$s-$v.exr --stats $R/$s-$v.json > $R/$s-$v.log 2>&1
    echo "$s $v rc=$? wall $(cat $R/$s-$v.time) s"
  done
done
for s in ${IDENTITY:-cornell_spheres buddhas_instanced rtxon sponza}; do
  for v in binary wide; do
    $tp render $(scene_path $s) $(scene_args $s) --backend vulkan --vk-mode compute --bvh $v --width 320 --height 180 --spp 4 --seed 7 -o /tmp/id-$s-$v.exr > /dev/null 2>&1
  done
  $tp compare /tmp/id-$s-binary.exr /tmp/id-$s-wide.exr --exact > $R/identity-$s.txt 2>&1
  echo "identity $s rc=$? $(tail -1 $R/identity-$s.txt)"
done
tar -C /tmp -czf $OUT/raw.tar.gz raw
