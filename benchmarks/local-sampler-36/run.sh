#!/bin/bash
# sobol against random on cornell_glossy, 2 threads (issue 36: sobol >= 1.1x random in time to
# error): BENCHMARKS.md section `local-sampler-36` (and `h200-cpu-sampler-36`: the same script
# on the GPU machine's idle CPU, THREADS 16 and 2).
# 1. relMSE at equal spp (and the ladder's own time): three `bench --ladder` runs, seeds 1-3,
#    the samplers' order alternating, against one cached 1024-spp reference.
# 2. The cost per sample as CPU time (user + system, which a shared machine's load inflates
#    less than wall time): `render` with each sampler alternately, ROUNDS rounds.
# Usage: benchmarks/local-sampler-36/run.sh [TWINPATH [OUT [ROUNDS [THREADS]]]]
set -euo pipefail
tp=${1:-build/bin/twinpath}
out=${2:-out/local-sampler-36}
rounds=${3:-5}
threads=${4:-2}
mkdir -p "$out"
uptime | tee "$out/load.txt"
for run in "1 random,sobol" "2 sobol,random" "3 random,sobol"; do
  set -- $run
  "$tp" bench --ladder --scenes cornell_glossy --samplers "$2" --backends cpu --threads "$threads" \
    --width 256 --height 256 --ref-spp 1024 --max-spp 256 --seed "$1" \
    --out "$out/ladder-$1" --section local-sampler-36 | tee "$out/ladder-$1.log"
done
uptime | tee -a "$out/load.txt"
: >"$out/cpu_times.txt"
for r in $(seq "$rounds"); do
  order=(random sobol)
  [ $((r % 2)) -eq 0 ] && order=(sobol random)
  for s in "${order[@]}"; do
    # bash's own timer (a machine may lack /usr/bin/time): user, system and wall seconds.
    TIMEFORMAT="$r $s %U %S %R"
    { time "$tp" render cornell_glossy --sampler "$s" --spp 64 --width 256 --height 256 \
      --threads "$threads" --seed 7 -o "$out/render.exr" >/dev/null 2>&1; } 2>>"$out/cpu_times.txt"
  done
done
uptime | tee -a "$out/load.txt"
# Per round: CPU seconds of sobol over random; the median of those ratios.
awk '{cpu[$1" "$2] = $3 + $4} END {
  for (k in cpu) { split(k, a, " "); if (a[2] == "sobol") print cpu[k] / cpu[a[1]" random"] }
}' "$out/cpu_times.txt" | sort -g | awk '{v[NR] = $1} END {
  printf "CPU time sobol / random per round:"; for (i = 1; i <= NR; ++i) printf " %.3f", v[i]
  printf "; median %.3f\n", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
