#!/usr/bin/env bash
# Per-ray traversal work of both BVH layouts on the scenes of benchmarks/h200-wide-bvh (issue 25),
# counted on the host by work_counts (see its header), at W x H with SPP paths per pixel, seed 1.
# Writes raw/SCENE.jsonl (one JSON object per layout and ray kind) and prints the table.
#   bash benchmarks/wide-bvh-work-counts/run.sh        (after building tp_cpu and tp_vulkan)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
A=${ASSETS:-/work/shared/assets}
W=${W:-160}; H=${H:-90}; SPP=${SPP:-2}
"$here/build.sh"
bin=${OUTBIN:-$root/build/work_counts}
tmp=$(mktemp -d)
for f in "$here"/scenes/*.json; do sed "s|@ASSETS@|$A|g" "$f" > "$tmp/$(basename "$f")"; done
# Sponza as in h200-wide-bvh: its OBJ without textures, the same camera.
mkdir -p "$tmp/sponza"
cp "$A/sponza-dabrovic/sponza.obj" "$tmp/sponza/"
grep -v "map_" "$A/sponza-dabrovic/sponza.mtl" > "$tmp/sponza/sponza.mtl"
mkdir -p "$here/raw"
for s in ${SCENES:-cornell cornell_spheres furnace bunny buddhas buddhas_instanced rtxon sponza}; do
  case $s in
    cornell|cornell_spheres|furnace) "$bin" "$root/scenes/$s.json" $W $H $SPP ;;
    sponza) "$bin" "$tmp/sponza/sponza.obj" $W $H $SPP --eye -12,2.5,0 --target 6,4.5,0 --fov 70 ;;
    *) "$bin" "$tmp/$s.json" $W $H $SPP ;;
  esac | sed "s|\"scene\": \"[^\"]*\"|\"scene\": \"$s\"|" > "$here/raw/$s.jsonl"
  echo "$s done" >&2
done
rm -rf "$tmp"
python3 "$here/table.py" "$here/raw"
