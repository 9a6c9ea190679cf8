#!/usr/bin/env bash
# Device run (issue 34 item 3): compute mode's BVH layouts, binary, wide and auto, timed side by
# side on every bundled scene, the bunny and the Happy Buddha (their OBJ files) at 256x256 and
# 1920x1080 by `twinpath bench --sizes` (Mrays/s: every ray over GPU time, best of 2 rounds of at
# least 0.5 s each, in one process), then per scene and layout one 64x64 render whose --stats give
# the BVH's bytes, the layout auto chose and both layouts' estimated work per ray.
# 7 scenes x 3 layouts x 2 sizes x 2 rounds x >= 0.5 s: about 1.5 minutes with the setups.
# CARRY names the carried folder (assets/ in it: the layout of ../shared/assets); SCENES (bundled
# or bench catalogue scenes by name, files by path; $A is the assets folder), SIZES_LIST,
# BACKENDS and SECTION replace the scenes, bench's size list, backends and section name (the
# whole curve, 64x64 to 3840x2160, with pipeline mode beside: SIZES_LIST=64,128,256,512,1024,
# 1920x1080,3840x2160 BACKENDS=vulkan:compute,vulkan:compute-wide,vulkan:compute-auto,
# vulkan:pipeline SECTION=h200-sizes; 7 scenes x 4 x 7 x 2 rounds: about 9 minutes). A
# catalogue scene has no stats render (render does not know its name).
#
# Run from the repository root on the GPU machine, with carried:
#   .carry/34/new.tar.xz   the bundle under test (scripts/make_gpu_bundle.sh); BUNDLE=... for another
#   .carry/34/assets/bunny/stanford-bunny.obj, .carry/34/assets/buddha/happy_buddha_112k.obj
# Output in $OUT: device.txt, bench.json (merge here with scripts/benchmarks.sh --no-local),
# stats.tar.gz (the small renders' stats) and table.md (table.py beside this script).
set -uo pipefail
C=${CARRY:-.carry/34}
if [ -d .gl ]; then for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig; fi
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json}
W=/tmp/wide-auto
mkdir -p $W/stats && tar -C $W -xJf "${BUNDLE:-$C/new.tar.xz}" || exit 1
tp=$W/twinpath-bundle/bin/twinpath
A=$PWD/$C/assets
SCENES=${SCENES:-"cornell cornell_glossy cornell_spheres spheres furnace
  $A/bunny/stanford-bunny.obj $A/buddha/happy_buddha_112k.obj"}
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $OUT/device.txt
$tp bench --sizes --sizes-list "${SIZES_LIST:-256,1920x1080}" --sizes-rounds 2 \
  --backends "${BACKENDS:-vulkan:compute,vulkan:compute-wide,vulkan:compute-auto}" \
  --scenes "$(echo $SCENES | tr ' ' ,)" --assets "$A" --section "${SECTION:-h200-wide-auto}" --out $W/bench || exit 1
cp $W/bench/bench.json $OUT/bench.json
for s in $SCENES; do
  n=$(basename "${s%.*}")
  for l in binary wide auto; do
    $tp render "$s" --backend vulkan --vk-mode compute --bvh $l --width 64 --height 64 --spp 1 \
      -o $W/x.exr --stats $W/stats/$n-$l.json > $W/log 2>&1 || { echo "FAIL $n $l"; tail -3 $W/log; }
  done
done
tar -C $W -czf $OUT/stats.tar.gz stats
python3 benchmarks/wide-bvh-collapse/table.py $OUT/bench.json $W/stats | tee $OUT/table.md
