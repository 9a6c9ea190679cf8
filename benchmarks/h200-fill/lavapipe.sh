#!/usr/bin/env bash
# lavapipe beside 01f88eb (issue 34's "no scene slower than today"): the five bundled JSON
# scenes in compute mode, 128x128, 32 spp, seed 7, --sampler random, base and new interleaved
# ROUNDS times; prints round,build,scene,rays,gpu_s,user_s: the device's own timer, and the
# process's user CPU time (lavapipe's threads included, pipeline creation too), which a loaded
# machine disturbs less than wall or GPU time. Same seed, same sampler: both builds trace the
# same rays, so the rays column is equal and the times compare.
#   BASE=path/to/twinpath-of-01f88eb NEW=build/bin/twinpath benchmarks/h200-fill/lavapipe.sh
set -uo pipefail
: "${BASE:?BASE: the twinpath binary of 01f88eb}"
NEW=${NEW:-build/bin/twinpath}
out=$(mktemp -d)
echo "round,build,scene,rays,gpu_s,user_s"
TIMEFORMAT=%U
for r in $(seq "${ROUNDS:-3}"); do
  for s in cornell cornell_glossy cornell_spheres spheres furnace; do
    for b in base new; do
      tp=$BASE; [ $b = new ] && tp=$NEW
      { time "$tp" render $s --backend vulkan --vk-mode compute --width 128 --height 128 \
        --spp 32 --seed 7 --sampler random -o "$out/x.exr" --stats "$out/s.json" \
        >/dev/null 2>&1; } 2>"$out/user" || { echo "FAIL $b $s" >&2; continue; }
      python3 -c "import json, sys; d = json.load(open(sys.argv[1]))
print(f\"$r,$b,$s,{d['rays']['total']},{d['gpu_time_s']},{open(sys.argv[2]).read().strip()}\")" \
        "$out/s.json" "$out/user"
    done
  done
done
rm -rf "$out"
