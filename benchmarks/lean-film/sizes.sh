#!/bin/bash
# Bytes of the default EXR (Sobol, the lean film), of `--sampler random` and of `--film full`
# (every channel, the layout Sobol renders had before the lean film) per bundled scene, at
# 256x256 and the scenes' own 64 spp, seed 0: BENCHMARKS.md section `lean-film` (issue 36:
# default <= 1.5x random; docs/sampling.md, "What the file keeps"). Sizes depend on the image,
# not on the machine or its load. Prints the section as markdown.
# Usage: benchmarks/lean-film/sizes.sh [TWINPATH]   (default build/bin/twinpath)
set -euo pipefail
tp=${1:-build/bin/twinpath}
scenes=(cornell cornell_glossy cornell_spheres furnace spheres gltf_materials)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
render() { "$tp" render "$1" --width 256 --height 256 --threads 2 -o "$2" "${@:3}" >/dev/null; }
bytes() { stat -c %s "$1"; }
commas() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta' <<<"$1"; }
ratio() { printf '%.2f×' "$(bc -l <<<"$1/$2")"; }

echo '## `lean-film`: bytes of the default EXR against `--sampler random` and `--film full`'
echo
echo '| | |'
echo '|---|---|'
echo "| command | \`benchmarks/lean-film/sizes.sh\`: \`twinpath render SCENE --width 256 --height 256 --threads 2 -o X.exr\` with no option (the default: sobol, lean film), \`--sampler random\`, \`--film full\` |"
echo "| commit | $(git describe --always --dirty 2>/dev/null || echo unknown) |"
echo "| when | $(date -u +%Y-%m-%dT%H:%MZ) |"
echo
echo '| scene | `--sampler random` | default (sobol, lean) | default / random | `--film full` | full / random |'
echo '|---|---|---|---|---|---|'
for s in "${scenes[@]}"; do
  render "$s" "$dir/r.exr" --sampler random
  render "$s" "$dir/l.exr"
  render "$s" "$dir/f.exr" --film full
  r=$(bytes "$dir/r.exr") l=$(bytes "$dir/l.exr") f=$(bytes "$dir/f.exr")
  echo "| $s | $(commas "$r") | $(commas "$l") | $(ratio "$l" "$r") | $(commas "$f") | $(ratio "$f" "$r") |"
done
