#!/usr/bin/env bash
# BENCHMARKS.md section `h200-pbr`: what glTF's material costs on the GPU and whether both GPU
# modes render it as the CPU reference does.
#  1. Rays per second at 1920x1080 in compute and pipeline mode: the bundled scenes without a
#     glTF material, on this build and (BASE) on the build before glTF's material came, and
#     cornell_spheres with its materials as glTF's (`pbr` twins of the same look: Lambert walls,
#     metal mirror, volume glass) next to the same geometry with its Phong, mirror and glass.
#     Each render twice, the second kept: a first render after a pause runs at low clocks.
#  2. compare: the CPU reference (this host's cores) against compute and pipeline mode on
#     gltf_materials (textures, a normal map, alpha MASK and BLEND, a volume, a spot light) and on
#     the pbr twin, independent seeds.
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundles, then
#   TWINPATH=BUNDLE/bin/twinpath [BASE=OLD_BUNDLE/bin/twinpath] benchmarks/h200-pbr.sh [OUT_DIR]
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
base=${BASE:-}
out=${1:-${OUT:-out/h200-pbr}}
scenes=$(cd "$(dirname "$tp")/../scenes" && pwd)
mkdir -p "$out"

# cornell_spheres with glTF's material in place of each of its materials.
python3 - "$scenes/cornell_spheres.json" "$out/cornell_spheres_pbr.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
for name, m in s["materials"].items():
    if m["type"] == "phong":
        pbr = {"type": "pbr", "base_color": m["Kd"], "metallic": 0.0, "roughness": 1.0}
        if "Ke" in m:
            pbr["Ke"] = m["Ke"]
    elif m["type"] == "mirror":
        pbr = {"type": "pbr", "base_color": m["Ks"], "metallic": 1.0, "roughness": 0.0}
    else:
        pbr = {"type": "pbr", "base_color": m.get("Tf", [1, 1, 1]), "metallic": 0.0,
               "roughness": 0.0, "transmission": 1.0, "ior": m.get("Ni", 1.5), "thickness": 1.0}
    s["materials"][name] = pbr
json.dump(s, open(sys.argv[2], "w"), indent=1)
PY

rate() { # binary scene mode spp: Mrays/s of the second of two renders
  local bin=$1 scene=$2 mode=$3 spp=$4
  for i in 1 2; do
    "$bin" render "$scene" --backend vulkan --vk-mode "$mode" --width 1920 --height 1080 \
      --spp "$spp" --max-depth 8 -o /dev/null --stats "$out/stats.json" > /dev/null 2>&1
  done
  python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(f"{s[\"rays_per_second\"]/1e6:.0f}")' \
    "$out/stats.json"
}

echo "| scene | mode | this build, Mrays/s | before glTF's material | ratio |"
echo "|---|---|---|---|---|"
for scene in cornell cornell_glossy cornell_spheres spheres furnace; do
  for mode in compute pipeline; do
    n=$(rate "$tp" "$scenes/$scene.json" $mode 64)
    if [[ -n "$base" ]]; then
      b=$(rate "$base" "$scenes/$scene.json" $mode 64)
      echo "| $scene | $mode | $n | $b | $(python3 -c "print(f'{$n/$b:.2f}')") |"
    else
      echo "| $scene | $mode | $n | | |"
    fi
  done
done
echo
echo "| cornell_spheres geometry | mode | Phong, mirror, glass: Mrays/s | glTF's material | ratio |"
echo "|---|---|---|---|---|"
for mode in compute pipeline; do
  p=$(rate "$tp" "$scenes/cornell_spheres.json" $mode 64)
  g=$(rate "$tp" "$out/cornell_spheres_pbr.json" $mode 64)
  echo "| cornell_spheres | $mode | $p | $g | $(python3 -c "print(f'{$g/$p:.2f}')") |"
done
echo
echo "compare (CPU reference, seed 1, against each GPU mode, seed 2):"
for scene in "$scenes/gltf_materials.gltf" "$out/cornell_spheres_pbr.json"; do
  name=$(basename "$scene")
  "$tp" render "$scene" --width 256 --height 256 --spp 4096 --max-depth 16 --seed 1 \
    -o "$out/cpu_$name.exr" > /dev/null 2>&1
  for mode in compute pipeline; do
    "$tp" render "$scene" --backend vulkan --vk-mode $mode --width 256 --height 256 \
      --spp 16384 --max-depth 16 --seed 2 -o "$out/${mode}_$name.exr" > /dev/null 2>&1
    echo "$name $mode: $("$tp" compare "$out/cpu_$name.exr" "$out/${mode}_$name.exr" | tail -1)"
  done
done
