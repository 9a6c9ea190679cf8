#!/usr/bin/env bash
# BENCHMARKS.md table `verify-planted-bugs`: `twinpath verify` with its defaults on each planted
# shader bug of tests/gpu/debug_tests.cmake (docs/debugging.md, "Planted bugs and the test
# hook"), at 64x64 on the scene the bug changes: the verdict, the field the triage names with
# both values, the planned spp and the wall time of the whole command. Needs a build with the
# tests (the bug modules are build/tests/gpu/bug_spirv/*.spv). Prints the table.
#   benchmarks/verify-planted-bugs.sh [OUT_DIR]   (TWINPATH: default build/bin/twinpath;
#   BUGS: default build/tests/gpu/bug_spirv)
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
bugs=${BUGS:-build/tests/gpu/bug_spirv}
out=${1:-out/verify-planted-bugs}
mkdir -p "$out"
echo "| bug | scene | exit | field named (cpu, vulkan) | spp cpu / gpu | wall s |"
echo "|---|---|---|---|---|---|"
for pair in RNG_DIM:cornell LIGHT_PDF:cornell SWAP_BARY:spheres FRESNEL_SIGN:spheres; do
  bug=${pair%%:*} scene=${pair##*:}
  start=$(date +%s.%N)
  TWINPATH_DEBUG_SPIRV=$bugs/$bug.spv "$tp" verify "$scene" --width 64 --height 64 \
    --report "$out/$bug" >"$out/$bug.log" 2>&1
  code=$?
  secs=$(bc -l <<<"$(date +%s.%N) - $start")
  python3 - "$out/$bug/verify.json" "$bug" "$scene" "$code" "$secs" <<'PY'
import json, sys
path, bug, scene, code, secs = sys.argv[1:]
j = json.load(open(path))
first = (j["pairs"][0].get("triage") or {}).get("first_divergence")
named = f'`{first["field"]}` ({first["value_a"]}, {first["value_b"]})' if first else "none"
spp = j["plan"]["spp"]
print(f"| {bug} | {scene} | {code} | {named} | {spp[0]} / {spp[1]} | {float(secs):.1f} |")
PY
done
