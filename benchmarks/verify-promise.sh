#!/usr/bin/env bash
# BENCHMARKS.md table `verify-promise`: the plan's promise (docs/debugging.md, "The plan"): at
# the spp verify plans, a uniform bias of --detect (1 %) is found with probability 0.9. The
# test tests/verify/promise_test.cpp with N trials instead of 10: two CPU engines render the lower
# part of cornell (32x32, no emitter in view), one with every emitter 1 % brighter; each trial is
# a whole verify with its own seeds. Prints the table row.
#   benchmarks/verify-promise.sh [N]   (TESTS: default build/bin/verify_tests)
set -euo pipefail
tests=${TESTS:-build/bin/verify_tests}
n=${1:-60}
found=$(TWINPATH_TEST_TRIALS=$n "$tests" "verify finds a planted uniform 1% bias*" |
  sed -n 's/^verify promise: \([0-9]*\) of .*/\1/p')
python3 - "$found" "$n" <<'PY'
import math, sys
k, n = int(sys.argv[1]), int(sys.argv[2])
# Clopper-Pearson 95 % interval of the detection probability, by bisection on the binomial tails.
def tail_le(k, n, p): return sum(math.comb(n, i) * p**i * (1 - p)**(n - i) for i in range(k + 1))
def solve(f):
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if f(mid) else (lo, mid)
    return lo
low = 0.0 if k == 0 else solve(lambda p: tail_le(k - 1, n, p) > 0.975)
high = 1.0 if k == n else solve(lambda p: tail_le(k, n, p) > 0.025)
print("| trials | found | rate | 95 % interval |")
print("|---|---|---|---|")
print(f"| {n} | {k} | {k / n:.3f} | [{low:.3f}, {high:.3f}] |")
PY
