#!/usr/bin/env bash
# Device run for issue 34: Mrays/s of the same renders at 256x256 and 1920x1080 with the bundle
# of 01f88eb ("base") and the bundle under test, whose variants are named by extra render
# arguments (VARIANTS below), in compute and pipeline mode. Run from the repository root on the
# GPU machine with the bundles and assets carried in .carry/34 (or $CARRY; NEWS below):
#   .carry/34/base.tar.xz, .carry/34/new.tar.xz   (scripts/make_gpu_bundle.sh of each commit)
#   .carry/34/assets/{bunny,buddha}/...           (from ../shared/assets)
#   .carry/34/scenes/{bunny,buddhas}.json         (bench catalogue scenes, @ASSETS@ for the path)
# Each render: --spp 1024 at 256x256, --spp 64 at 1920x1080, seed 7, --time-limit 4; Mrays/s is
# the render's rays over its wall time (`--stats`: rays.total / wall_time_s), as in the issue.
# Output: $OUT/times.csv, one row per render; $OUT/table.md from table.py.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
c=${CARRY:-.carry/34}
# The builds under test: $c/NAME.tar.xz for each NAME (rows named by the variant, prefixed with
# NAME unless it is the one default build, `new`).
NEWS=${NEWS:-new}
for b in base $NEWS; do mkdir -p /tmp/$b && tar -C /tmp/$b -xJf $c/$b.tar.xz; done
mkdir -p /tmp/scenes
for s in $c/scenes/*.json; do sed "s#@ASSETS@#$PWD/$c/assets#g" "$s" > /tmp/scenes/$(basename "$s"); done
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $OUT/device.txt
# bunny_obj, buddha_obj: the OBJ files themselves, framed automatically (as the issue measured).
scene() {
  case $1 in
    bunny_obj) echo $PWD/$c/assets/bunny/stanford-bunny.obj ;;
    buddha_obj) echo $PWD/$c/assets/buddha/happy_buddha_112k.obj ;;
    *) [ -f /tmp/scenes/$1.json ] && echo /tmp/scenes/$1.json || echo /tmp/base/twinpath-bundle/scenes/$1.json ;;
  esac
}
SCENES=${SCENES:-"cornell cornell_glossy cornell_spheres spheres furnace bunny_obj buddha_obj"}
MODES=${MODES:-"compute pipeline"}
SIZES=${SIZES:-"256x256:1024 1920x1080:64"}
ROUNDS=${ROUNDS:-1}
# name=ARG,ARG ...: the build under test once per variant with those render arguments (the base
# build runs without any; 01f88eb's compute mode has the binary tree and --wide-bvh).
VARIANTS=${VARIANTS:-"binary=--bvh,binary wide=--bvh,wide auto=--bvh,auto"}
# Variants in pipeline mode.
VARIANTS_PIPELINE=${VARIANTS_PIPELINE:-"new="}
EXTRA=${EXTRA:-}
echo "round,build,scene,depth,size,mode,spp,rays,wall_s,gpu_s,submissions" > $OUT/times.csv
r() { # round build variant-args scene depth size spp mode name
  local tp=/tmp/$2/twinpath-bundle/bin/twinpath
  local w=${6%x*} h=${6#*x} dargs=""
  [ "$5" != "-" ] && dargs="--max-depth $5"
  TWINPATH_CACHE=/tmp/cache-$2 $tp render $(scene $4) --backend vulkan --vk-mode $8 \
    --width $w --height $h --spp $7 --seed 7 --sampler random --time-limit 4 $dargs ${3//,/ } $EXTRA \
    -o /tmp/x.exr --stats /tmp/s.json > /tmp/l.log 2>&1 || { echo "FAIL $*"; tail -3 /tmp/l.log; return; }
  python3 - "$@" >> $OUT/times.csv <<'PY'
import json, sys
a = sys.argv[1:]
d = json.load(open('/tmp/s.json'))
print(','.join([a[0], a[8], a[3], a[4], a[5], a[7], str(d['spp']), str(d['rays']['total']),
                str(d['wall_time_s']), str(d.get('gpu_time_s', -1)), d['extra'].get('submissions', '')]))
PY
}
for round in $(seq $ROUNDS); do
  for sc in $SCENES; do
    depths="-"; [ $sc = cornell_spheres ] && depths="- 8"
    for d in $depths; do
      for sz in $SIZES; do
        for m in $MODES; do
          r $round base "" $sc $d ${sz%:*} ${sz#*:} $m base
          vs=$VARIANTS; [ $m = pipeline ] && vs=$VARIANTS_PIPELINE
          for nb in $NEWS; do
            for v in $vs; do
              n=${v%%=*}; [ "$nb" = new ] || n=$nb$n
              r $round $nb "${v#*=}" $sc $d ${sz%:*} ${sz#*:} $m "$n"
            done
          done
        done
      done
    done
  done
done
python3 benchmarks/h200-fill/table.py $OUT/times.csv | tee $OUT/table.md
