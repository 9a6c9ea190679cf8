#!/usr/bin/env bash
# BENCHMARKS.md table `lavapipe-fill`: compute mode on Mesa lavapipe (a CPU-only machine's
# Vulkan device) beside BASE, the twinpath of 01f88eb, whose render loop traced one item per
# invocation: the five bundled JSON scenes at 128x128, 32 spp, seed 7, --sampler random, both
# builds interleaved ROUNDS times (default 3). Same seed and sampler, so both trace the same
# rays. Per scene, best against best: GPU time (the device's timer: launch and resolve) and the
# process's user CPU time (lavapipe's threads and pipeline creation included), which a loaded
# machine disturbs less than wall time; then pipeline creation at 64x64, 1 spp (--stats
# extra.pipeline_create_ms, best of ROUNDS).
#   BASE=TWINPATH_OF_01F88EB [NEW=build/bin/twinpath] [ROUNDS=3] benchmarks/lavapipe-fill.sh
set -uo pipefail
: "${BASE:?BASE: the twinpath binary of 01f88eb}"
NEW=${NEW:-build/bin/twinpath}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
TIMEFORMAT=%U
for _ in $(seq "${ROUNDS:-3}"); do
  for s in cornell cornell_glossy cornell_spheres spheres furnace; do
    for b in base new; do
      tp=$BASE; [ $b = new ] && tp=$NEW
      { time "$tp" render $s --backend vulkan --vk-mode compute --width 128 --height 128 \
        --spp 32 --seed 7 --sampler random -o "$out/x.exr" --stats "$out/s.json" \
        >/dev/null 2>&1; } 2>"$out/user" || { echo "render failed: $b $s" >&2; continue; }
      echo "$b $s $(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["gpu_time_s"])' \
        "$out/s.json") $(cat "$out/user")" >>"$out/rows"
      "$tp" render $s --backend vulkan --vk-mode compute --width 64 --height 64 --spp 1 \
        -o "$out/x.exr" --stats "$out/p.json" >/dev/null 2>&1 &&
        echo "$b $(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["extra"]["pipeline_create_ms"])' \
          "$out/p.json")" >>"$out/create"
    done
  done
done
python3 - "$out/rows" "$out/create" <<'PY'
import sys
best = {}
for line in open(sys.argv[1]):
    b, s, gpu, user = line.split()
    for k, v in (("gpu", float(gpu)), ("user", float(user))):
        best[(b, s, k)] = min(best.get((b, s, k), 1e9), v)
print("| scene | GPU time, new ÷ base | user CPU time, new ÷ base |\n|---|---:|---:|")
for s in dict.fromkeys(s for _, s, _ in best):
    print(f"| {s} | {best[('new', s, 'gpu')] / best[('base', s, 'gpu')]:.2f} | "
          f"{best[('new', s, 'user')] / best[('base', s, 'user')]:.2f} |")
create = {}
for line in open(sys.argv[2]):
    b, ms = line.split()
    create.setdefault(b, []).append(float(ms))
print("\npipeline creation, ms: " + "; ".join(f"{b} {min(v):.0f}-{max(v):.0f}" for b, v in create.items()))
PY
