#!/usr/bin/env bash
# BENCHMARKS.md table `h200-cpu-sampler`: sobol against random on cornell_glossy (the scene where
# sobol gains least, docs/sampling.md) on the CPU, at THREADS threads (default 2).
#   1. relMSE at equal spp, and the ladder's own time: three `twinpath bench --ladder` runs,
#      seeds 1-3, the samplers' order alternating, against one cached 1024-spp reference;
#   2. the cost per sample as CPU time (user + system, which other work on the machine
#      disturbs less than wall time): `render` with each sampler alternately, ROUNDS rounds;
#   3. one row of the table: relMSE random / sobol per seed (and their mean), the median of the
#      rounds' CPU-time ratios sobol / random, ε sobol / random = the mean relMSE ratio over
#      it, and the ladders' own ε ratio (their wall times).
# Usage: [THREADS=2] [ROUNDS=5] [TWINPATH=build/bin/twinpath] benchmarks/h200-cpu-sampler.sh [OUT_DIR]
# The table's machine is the GPU machine's idle 16-core Xeon, run from the unpacked gpu bundle
# (docs/gpu.md, "Running on a GPU machine") with THREADS=16 and THREADS=2; any idle machine
# will do. Bash's own timer, so /usr/bin/time need not be there.
set -euo pipefail
tp=${TWINPATH:-build/bin/twinpath}
threads=${THREADS:-2}
out=${1:-${OUT:-out/h200-cpu-sampler}}/t$threads
mkdir -p "$out"
for run in "1 random,sobol" "2 sobol,random" "3 random,sobol"; do
  set -- $run
  "$tp" bench --ladder --scenes cornell_glossy --samplers "$2" --backends cpu --threads "$threads" \
    --width 256 --height 256 --ref-spp 1024 --max-spp 256 --seed "$1" --cache "$out/cache" \
    --out "$out/ladder-$1" --section h200-cpu-sampler >/dev/null
done
: >"$out/cpu_times.txt"
for r in $(seq "${ROUNDS:-5}"); do
  order=(random sobol)
  [ $((r % 2)) -eq 0 ] && order=(sobol random)
  for s in "${order[@]}"; do
    TIMEFORMAT="$r $s %U %S %R"
    { time "$tp" render cornell_glossy --sampler "$s" --spp 64 --width 256 --height 256 \
      --threads "$threads" --seed 7 -o "$out/render.exr" >/dev/null 2>&1; } 2>>"$out/cpu_times.txt"
  done
done
python3 - "$out" "$threads" <<'PY'
import json, os, statistics, sys
out, threads = sys.argv[1], sys.argv[2]
err, eff = [], []
for seed in (1, 2, 3):
    ladder = json.load(open(os.path.join(out, f"ladder-{seed}", "bench.json")))["scenes"][0]["ladder"]
    last = {run["sampler"]: run["points"][-1] for run in ladder}
    err.append(last["random"]["relmse_excess"] / last["sobol"]["relmse_excess"])
    eff.append(last["sobol"]["efficiency"] / last["random"]["efficiency"])
cpu = {}
for line in open(os.path.join(out, "cpu_times.txt")):
    r, s, user, system, _ = line.split()
    cpu.setdefault(r, {})[s] = float(user) + float(system)
ratios = sorted(v["sobol"] / v["random"] for v in cpu.values() if len(v) == 2)
t = statistics.median(ratios)
mean = statistics.mean(err)
print(f"| {threads} | {', '.join(f'{e:.2f}' for e in err)} (mean {mean:.2f}) | {t:.3f} "
      f"({ratios[0]:.3f}-{ratios[-1]:.3f}) | **{mean / t:.2f}** | {', '.join(f'{e:.2f}' for e in eff)} |")
PY
