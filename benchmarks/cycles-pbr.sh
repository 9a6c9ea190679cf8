#!/usr/bin/env bash
# BENCHMARKS.md section `cycles-pbr`: glTF's material against Blender's Cycles, per material. Blender
# authors a scene with Principled BSDF materials (benchmarks/cycles-pbr/author.py) and exports it
# with its glTF exporter; Cycles renders the .glb imported back (cycles_render.py); twinpath
# renders the same .glb on the CPU with its material-id AOV; compare_materials.py prints the mean
# luminance of each material's pixels in both. Cycles 3.4's Principled BSDF is not glTF's
# Appendix B (Disney diffuse with retro-reflection, specular layered over diffuse with its own
# energy terms, multiple-scattering GGX for glass), so this is a look check with the size of each
# difference, not a test; docs/scene-format.md ("glTF materials against Cycles") explains them.
# Needs Debian's `blender` and OpenImageIO's `oiiotool` (a build dependency).
#   [TWINPATH=build/bin/twinpath] [SPP=1024] [TW_SPP=4096] [THREADS=2] benchmarks/cycles-pbr.sh [OUT]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-out/cycles-pbr}
spp=${SPP:-1024}
tw_spp=${TW_SPP:-4096}
threads=${THREADS:-2}
mkdir -p "$out"
blender=(blender -b --factory-startup -noaudio)
"${blender[@]}" -P "$here/cycles-pbr/author.py" -- "$out/scene.glb" > "$out/author.log" 2>&1
start=$(date +%s)
"${blender[@]}" -P "$here/cycles-pbr/cycles_render.py" -- "$out/scene.glb" "$out/cycles.exr" \
  "$spp" "$threads" > "$out/cycles.log" 2>&1
echo "cycles: $spp spp in $(($(date +%s) - start)) s"
"$tp" render "$out/scene.glb" --spp "$tw_spp" --threads "$threads" --width 256 --height 256 \
  --max-depth 64 -o "$out/twinpath.exr" --png "$out/twinpath.png" --exposure auto
"$tp" render "$out/scene.glb" --spp 1 --width 256 --height 256 --aov ids -o "$out/aov.exr"
# Plain RGB images for Blender's reader: the means, and the material ids in R, G and B.
oiiotool "$out/aov.exr" --ch R=id.material,G=id.material,B=id.material -o "$out/ids.exr"
oiiotool "$out/twinpath.exr" --ch R,G,B -o "$out/twinpath_rgb.exr"
oiiotool "$out/cycles.exr" --ch R,G,B -o "$out/cycles_rgb.exr"
names=$("$tp" info "$out/scene.glb" --json | python3 -c \
  'import json, sys; print(",".join(m["name"] for m in json.load(sys.stdin)["material_list"]))')
"${blender[@]}" -P "$here/cycles-pbr/compare_materials.py" -- "$out/cycles_rgb.exr" \
  "$out/twinpath_rgb.exr" "$out/ids.exr" "$names" 2>/dev/null | grep '^|'
