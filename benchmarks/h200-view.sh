#!/usr/bin/env bash
# BENCHMARKS.md table `h200-view`: the view's frame loop without a window (docs/view.md,
# `--headless`) at 1920x1080, 1 spp per frame, 300 frames, in both GPU modes, on cornell, the
# bunny on a floor under sun and sky, and Sponza (Dabrovic's atrium, 38 materials) under a sun
# through the roof and a sky, camera inside.
#
# Two steps. Here, where oiiotool is installed, write the scenes to carry (the gpu bundle reads
# no JPEG, so Sponza's diffuse textures become half-float EXR files; its other maps are left out):
#   ASSETS=MESHES benchmarks/h200-view.sh prepare SCENES_DIR
# Then on the GPU machine (docs/gpu.md, "Running on a GPU machine"), with the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and SCENES_DIR carried:
#   TWINPATH=BUNDLE/bin/twinpath benchmarks/h200-view.sh run SCENES_DIR
# Under a minute. Prints the table. benchmarks/h200-device-all.sh renders the same scenes.
set -euo pipefail
step=${1:?usage: h200-view.sh prepare|run SCENES_DIR}
dir=${2:?usage: h200-view.sh prepare|run SCENES_DIR}
if [ "$step" = prepare ]; then
  : "${ASSETS:?ASSETS: the shared test meshes (bunny/, sponza-dabrovic/)}"
  src=$ASSETS/sponza-dabrovic
  mkdir -p "$dir/bunny" "$dir/sponza"
  cp "$ASSETS/bunny/stanford-bunny.obj" "$dir/bunny/"
  cp "$src/sponza.obj" "$dir/sponza/"
  grep -viE '^\s*(map_ka|map_bump|bump)\s' "$src/sponza.mtl" |
    sed -E 's/^(\s*map_Kd\s+)(.*)\.[A-Za-z]+\s*$/\1\2.exr/' >"$dir/sponza/sponza.mtl"
  for t in $(awk '$1 == "map_Kd" { print $2 }' "$src/sponza.mtl" | tr -d '\r' | sort -u); do
    oiiotool "$src/$t" -d half -o "$dir/sponza/${t%.*}.exr"
  done
  cat >"$dir/bunny/bunny.json" <<'JSON'
{"camera": {"eye": [0.4, 0.9, 2.0], "target": [0.0, 0.55, 0.0], "fov": 40.0},
 "render": {"max_depth": 8, "min_depth": 3},
 "environment": {"type": "constant", "radiance": [0.3, 0.35, 0.45]},
 "lights": [{"type": "directional", "direction": [-0.4, -1.0, -0.5], "irradiance": [2.5, 2.5, 2.375]}],
 "materials": {"bunny": {"type": "phong", "Kd": [0.75, 0.72, 0.68], "Ks": [0, 0, 0], "Ns": 1.0},
               "floor": {"type": "phong", "Kd": [0.5, 0.5, 0.5], "Ks": [0, 0, 0], "Ns": 1.0}},
 "meshes": {"bunny": {"type": "obj", "file": "stanford-bunny.obj"}, "floor": {"type": "quad"}},
 "objects": [{"mesh": "floor", "material": "floor", "transform": {"scale": [4.0, 1.0, 4.0]}},
             {"mesh": "bunny", "material": "bunny",
              "transform": {"scale": 8.0, "translate": [0.134724, -0.263896, 0.012296]}}]}
JSON
  cat >"$dir/sponza/sponza.json" <<'JSON'
{"camera": {"eye": [-11.0, 2.2, -0.6], "target": [4.0, 4.5, 0.3], "fov": 60},
 "render": {"max_depth": 8, "min_depth": 3},
 "meshes": {"sponza": {"type": "obj", "file": "sponza.obj"}}, "objects": [{"mesh": "sponza"}],
 "lights": [{"type": "directional", "direction": [-0.25, -1.0, -0.2], "irradiance": [6, 5.8, 5.3]}],
 "environment": {"type": "constant", "radiance": [0.35, 0.4, 0.5]}}
JSON
  exit 0
fi
tp=${TWINPATH:-build/bin/twinpath}
echo "| scene | mode | mean ms/frame | median | p95 | frames/s | Mrays/s |"
echo "|---|---|---:|---:|---:|---:|---:|"
for s in cornell "$dir/bunny/bunny.json" "$dir/sponza/sponza.json"; do
  for m in compute pipeline; do
    # "view --headless: 300 frames: mean 1.730 ms, median 1.700 ms, p95 1.966 ms, 578.2 frames/s; 300 spp; 3658.3 Mrays/s"
    "$tp" view "$s" --headless --vk-mode $m --width 1920 --height 1080 --spp-per-frame 1 \
      --frames 300 2>&1 | awk -v s="$(basename "${s%.json}")" -v m=$m '/^view --headless/ {
        gsub(/,|;/, ""); printf "| %s | %s | %s | %s | %s | %s | %s |\n", s, m, $6, $9, $12, $14, $18 }'
  done
done
