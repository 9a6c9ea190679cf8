#!/usr/bin/env bash
# BENCHMARKS.md table `h200-wide-auto`: compute mode's two BVH layouts side by side and what
# `--bvh auto` builds (docs/gpu.md, "Choosing a layout"), on every bundled scene, the bench
# catalogue's scenes and five OBJ meshes, at 256x256 and 1920x1080.
#   1. `twinpath bench --sizes` with the backends vulkan:compute, vulkan:compute-wide and
#      vulkan:compute-auto (Mrays/s: every ray over GPU time, best of 2 rounds of >= 0.5 s);
#   2. per scene that `render` opens (bundled names and files; not the catalogue's names) one
#      64x64 render per layout, whose --stats give the bytes (accel_bytes), the layout auto
#      built and the binary tree's expected node visits per ray (extra.bvh_estimate*);
#   3. the table, printed and written to OUT_DIR/table.md.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes, then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-wide-auto.sh [OUT_DIR]
# 15 scenes x 3 layouts x 2 sizes x 2 rounds: about 4 minutes. SCENES replaces the scene list.
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
: "${ASSETS:?ASSETS: the shared test meshes}"
out=${1:-${OUT:-out/h200-wide-auto}}
A=$ASSETS
SCENES=${SCENES:-"cornell cornell_glossy cornell_spheres spheres furnace
  $A/bunny/stanford-bunny.obj $A/buddha/happy_buddha_112k.obj monkeys bunny buddhas
  buddhas_instanced rtxon $A/suzanne/suzanne.obj $A/teapot/teapot.obj $A/spot/spot_triangulated.obj"}
mkdir -p "$out/stats"
"$tp" bench --sizes --sizes-list 256,1920x1080 --sizes-rounds 2 \
  --backends vulkan:compute,vulkan:compute-wide,vulkan:compute-auto \
  --scenes "$(echo $SCENES | tr ' ' ,)" --assets "$A" --section h200-wide-auto --out "$out/bench" || exit 1
for s in $SCENES; do
  case $s in monkeys | bunny | buddhas | buddhas_instanced | rtxon) continue ;; esac
  n=$(basename "${s%.*}")
  for l in binary wide auto; do
    "$tp" render "$s" --backend vulkan --vk-mode compute --bvh $l --width 64 --height 64 --spp 1 \
      -o "$out/x.exr" --stats "$out/stats/$n-$l.json" >/dev/null 2>&1 || echo "render failed: $n $l" >&2
  done
done
python3 - "$out/bench/bench.json" "$out/stats" <<'PY' | tee "$out/table.md"
import json, os, sys
bench, stats_dir = json.load(open(sys.argv[1])), sys.argv[2]
layout_of = {"compute": "binary", "compute-wide": "wide", "compute-auto": "auto"}

def stats(scene, layout):
    path = os.path.join(stats_dir, f"{scene}-{layout}.json")
    return json.load(open(path)) if os.path.exists(path) else None

def binary_visits(auto):  # "nodes N boxes B triangles T instances I" of the binary tree
    e = auto["extra"]
    text = e["bvh_estimate"] if e["bvh_layout"] == "binary" else e["bvh_estimate_binary"]
    words = text.split()
    return float(words[words.index("nodes") + 1])

print("| scene | binary visits per ray (SAH) | wide ÷ binary, 256² | wide ÷ binary, 1080p | "
      "wide bytes ÷ binary | auto builds |")
print("|---|---:|---:|---:|---:|---|")
for scene in bench["scenes"]:
    name, rate = scene["name"], {}
    for run in scene.get("sizes", []):
        for p in run["points"] if run["mode"] in layout_of else []:
            rate[(layout_of[run["mode"]], p["width"])] = p["mrays_s"]
    ratio = [f"{rate[('wide', w)] / rate[('binary', w)]:.2f}"
             if ("wide", w) in rate and ("binary", w) in rate else "" for w in (256, 1920)]
    b, w, a = (stats(name, l) for l in ("binary", "wide", "auto"))
    visits = f"{binary_visits(a):.1f}" if a else ""
    mem = f"{w['accel_bytes'] / b['accel_bytes']:.3f}" if b and w else ""
    chose = a["extra"]["bvh_layout"] if a else ""
    print(f"| {name} | {visits} | {ratio[0]} | {ratio[1]} | {mem} | {chose} |")
PY
