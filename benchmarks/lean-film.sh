#!/usr/bin/env bash
# BENCHMARKS.md table `lean-film`: bytes of the default EXR (sobol, the lean film) against
# `--sampler random` and `--film full` (every channel) per bundled scene, at 256x256 and each
# scene's own 64 spp, seed 0 (docs/sampling.md, "What the file keeps"). Sizes depend on the
# image, not on the machine or its load. Prints the table.
#   benchmarks/lean-film.sh [TWINPATH]   (default build/bin/twinpath)
set -euo pipefail
tp=${1:-build/bin/twinpath}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
render() { "$tp" render "$1" --width 256 --height 256 --threads 2 -o "$2" "${@:3}" >/dev/null; }
bytes() { stat -c %s "$1"; }
commas() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta' <<<"$1"; }
ratio() { printf '%.2f×' "$(bc -l <<<"$1/$2")"; }
echo '| scene | `--sampler random` | default (sobol, lean) | default / random | `--film full` | full / random |'
echo '|---|---|---|---|---|---|'
for s in cornell cornell_glossy cornell_spheres furnace spheres gltf_materials; do
  render "$s" "$dir/r.exr" --sampler random
  render "$s" "$dir/l.exr"
  render "$s" "$dir/f.exr" --film full
  r=$(bytes "$dir/r.exr") l=$(bytes "$dir/l.exr") f=$(bytes "$dir/f.exr")
  echo "| $s | $(commas "$r") | $(commas "$l") | $(ratio "$l" "$r") | $(commas "$f") | $(ratio "$f" "$r") |"
done
