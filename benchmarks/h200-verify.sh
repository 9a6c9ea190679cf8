#!/usr/bin/env bash
# BENCHMARKS.md table `h200-verify`: `twinpath verify` on the GPU machine (H200, its 16-core
# CPU): cornell_spheres at 256x256 with --detect 1% (the default), the first run with cold caches
# then three more, one with --vk-mode both, and the four planted bugs in compute mode (their
# modules are compute shaders). While each runs, every 0.2 s: the busy share of all CPU cores
# (/proc/stat) and the GPU's utilization (nvidia-smi); a sample with the CPU over 50 % and the GPU
# over 0 % counts as both busy.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the gpu bundle
# (scripts/make_gpu_bundle.sh) and, for the bugs, build/tests/gpu/bug_spirv of a test build; then
#   TWINPATH=BUNDLE/bin/twinpath BUGS=build/tests/gpu/bug_spirv benchmarks/h200-verify.sh [OUT_DIR]
# About 2 minutes. Prints the table; each run's stdout and report stay in OUT_DIR.
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
bugs=${BUGS:-build/tests/gpu/bug_spirv}
out=${1:-out/h200-verify}
mkdir -p "$out"

# One line per 0.2 s: seconds since the epoch, CPU busy %, GPU utilization %.
sample() {
  local u n s i w x y z idle total prev_idle prev_total gpu
  read -r _ u n s i w x y z _ </proc/stat
  prev_idle=$((i + w)) prev_total=$((u + n + s + i + w + x + y + z))
  while :; do
    sleep 0.2
    read -r _ u n s i w x y z _ </proc/stat
    idle=$((i + w)) total=$((u + n + s + i + w + x + y + z))
    gpu=$(nvidia-smi --query-gpu=utilization.gpu --format=csv,noheader,nounits 2>/dev/null | head -1)
    echo "$(date +%s.%N) $((100 * ((total - prev_total) - (idle - prev_idle)) / (total - prev_total))) ${gpu:-0}"
    prev_idle=$idle prev_total=$total
  done
}

echo "| run | exit | wall s | plan: spp cpu / gpu | pilots s | images s | triage s | first divergence | samples both busy / CPU busy / GPU busy |"
echo "|---|---|---|---|---|---|---|---|---|"
run() { # name, then env assignments and verify arguments
  local name=$1 start end code
  shift
  sample >"$out/$name.samples" &
  local sampler=$!
  start=$(date +%s.%N)
  env "$@" --report "$out/$name" >"$out/$name.txt" 2>&1
  code=$?
  end=$(date +%s.%N)
  kill "$sampler"
  wait "$sampler" 2>/dev/null
  local busy info
  busy=$(awk '{ both += ($2 > 50 && $3 > 0); cpu += ($2 > 50); gpu += ($3 > 0) }
              END { printf "%d / %d / %d", both, cpu, gpu }' "$out/$name.samples")
  info=$(python3 - "$out/$name/verify.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
w = j["wall_s"]
f = (j["pairs"][0].get("triage") or {}).get("first_divergence")
print(" / ".join(map(str, j["plan"]["spp"])),
      "| %.2f | %.2f | %.2f |" % (w["pilots"], w["images"], w["triage"]), f["field"] if f else "-")
PY
  )
  printf '| %s | %d | %s | %s | %s |\n' "$name" "$code" \
    "$(awk -v a="$end" -v b="$start" 'BEGIN { printf "%.1f", a - b }')" "$info" "$busy"
}

scene=(cornell_spheres --width 256 --height 256 --detect 1%)
run cold "$tp" verify "${scene[@]}"
for seed in 1 2 3; do run "warm-$seed" "$tp" verify "${scene[@]}" --seed "$seed"; done
run both "$tp" verify "${scene[@]}" --vk-mode both
for pair in RNG_DIM:cornell LIGHT_PDF:cornell SWAP_BARY:spheres FRESNEL_SIGN:spheres; do
  bug=${pair%%:*} bscene=${pair##*:}
  run "$bug" "TWINPATH_DEBUG_SPIRV=$bugs/$bug.spv" "$tp" verify "$bscene" --vk-mode compute \
    --width 256 --height 256
done
