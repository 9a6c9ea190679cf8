#!/usr/bin/env bash
# BENCHMARKS.md table `verify-false-alarms`: the false-alarm rate of `twinpath verify` as a whole
# on an unmodified build (docs/debugging.md, "verify"): N seeds per scene, each run with its own
# pilots, plan, independent images (CPU reference against the GPU's default mode) and compare at
# alpha = 0.01. A valid verdict says "different" in at most alpha of the runs: the count must
# stay at or below the upper end of the central 99 % binomial interval of Binomial(N, alpha).
# Prints the table; each run's verify.json stays in OUT_DIR.
#   benchmarks/verify-false-alarms.sh [N] [OUT_DIR]   (TWINPATH: default build/bin/twinpath;
#   SCENES: default "cornell cornell_spheres"; SIZE: default 64)
# About 10 s per run on 2 shared cores with lavapipe: 60 seeds of two scenes take 20 minutes.
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
n=${1:-60}
out=${2:-out/verify-false-alarms}
size=${SIZE:-64}
mkdir -p "$out"
: >"$out/runs.txt"
for scene in ${SCENES:-cornell cornell_spheres}; do
  for ((seed = 0; seed < n; seed++)); do
    dir=$out/$scene-$seed
    start=$(date +%s.%N)
    "$tp" verify "$scene" --width "$size" --height "$size" --seed "$seed" --report "$dir" \
      >"$dir.log" 2>&1
    echo "$scene $seed $? $(bc -l <<<"$(date +%s.%N) - $start")" >>"$out/runs.txt"
  done
done
python3 - "$out" "$n" <<'PY'
import json, math, os, statistics, sys
out, n = sys.argv[1], int(sys.argv[2])
def binom_upper99(n, p):
    # the smallest k with P(X > k) <= 0.005 for X ~ Binomial(n, p)
    pmf = [math.comb(n, k) * p**k * (1 - p)**(n - k) for k in range(n + 1)]
    tail = 1.0
    for k in range(n + 1):
        tail -= pmf[k]
        if tail <= 0.005:
            return k
    return n
runs = {}
for line in open(os.path.join(out, "runs.txt")):
    scene, seed, code, secs = line.split()
    runs.setdefault(scene, []).append((int(seed), int(code), float(secs)))
print("| scene | runs | different (exit 1) | bound at alpha 0.01 | other exits | spp cpu / gpu, median | wall s, median |")
print("|---|---|---|---|---|---|---|")
for scene, rs in runs.items():
    rs = [r for r in rs if r[0] < n]
    diff = sum(1 for r in rs if r[1] == 1)
    other = sum(1 for r in rs if r[1] not in (0, 1))
    spp = []
    for seed, code, _ in rs:
        path = os.path.join(out, f"{scene}-{seed}", "verify.json")
        if os.path.exists(path):
            spp.append(json.load(open(path))["plan"]["spp"])
    med = lambda xs: statistics.median(xs) if xs else float("nan")
    print(f"| {scene} | {len(rs)} | {diff} | {binom_upper99(len(rs), 0.01)} | {other} | "
          f"{med([s[0] for s in spp]):.0f} / {med([s[1] for s in spp]):.0f} | "
          f"{med([r[2] for r in rs]):.1f} |")
PY
