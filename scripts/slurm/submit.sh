#!/usr/bin/env bash
# Renders one image on a Slurm cluster, split by sample ranges (docs/farm.md):
#   scripts/slurm/submit.sh --scene SCENE --spp N --parts P --out DIR [--seed S]
#       [--twinpath PATH] [--sbatch "SBATCH OPTIONS"] [-- RENDER OPTIONS]
# submits an array job of the parts not yet in DIR (render_part.sbatch: part i renders samples
# [i N / P, (i + 1) N / P) into DIR/part_NNNN.exr) and a merge job that runs when all of them
# succeeded (merge.sbatch: DIR/merged.exr). Run it again after a failure and only the missing
# parts are rendered. DIR must be on a file system every node sees.
set -euo pipefail

usage() {
  sed -n '2,5p' "$0" >&2
  exit 2
}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene="" spp="" parts="" out="" seed=0 sbatch_args="" render_args=""
twinpath=$(command -v twinpath || true)
while [[ $# -gt 0 ]]; do
  case $1 in
    --scene) scene=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --parts) parts=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --twinpath) twinpath=$2; shift 2 ;;
    --sbatch) sbatch_args=$2; shift 2 ;;
    --) shift; render_args="$*"; break ;;
    *) echo "submit.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
[[ -n $scene && -n $spp && -n $parts && -n $out ]] || usage
[[ $spp =~ ^[0-9]+$ && $parts =~ ^[0-9]+$ && $parts -ge 1 && $spp -ge $parts ]] ||
  { echo "submit.sh: --spp and --parts must be whole numbers with 1 <= parts <= spp" >&2; exit 2; }
[[ -x $twinpath ]] || { echo "submit.sh: no twinpath executable (give --twinpath)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
twinpath=$(cd "$(dirname "$twinpath")" && pwd)/$(basename "$twinpath")

missing=()
for ((i = 0; i < parts; i++)); do
  [[ -f $(printf '%s/part_%04d.exr' "$out" "$i") ]] || missing+=("$i")
done
export TP_TWINPATH=$twinpath TP_SCENE=$scene TP_SPP=$spp TP_PARTS=$parts TP_SEED=$seed \
  TP_OUT=$out TP_RENDER_ARGS=$render_args
dependency=()
if [[ ${#missing[@]} -gt 0 ]]; then
  list=$(IFS=,; echo "${missing[*]}")
  # shellcheck disable=SC2086 # sbatch_args is a list of options
  array=$(sbatch --parsable --export=ALL --array="$list" -o "$out/part_%a.log" $sbatch_args \
    "$here/render_part.sbatch")
  array=${array%%;*}
  echo "twinpath farm: rendering parts $list of $parts as job $array"
  dependency=(--dependency=afterok:"$array")
else
  echo "twinpath farm: all $parts parts are in $out"
fi
# shellcheck disable=SC2086
merge=$(sbatch --parsable --export=ALL "${dependency[@]}" -o "$out/merge.log" $sbatch_args \
  "$here/merge.sbatch")
echo "twinpath farm: merging into $out/merged.exr as job ${merge%%;*}"
