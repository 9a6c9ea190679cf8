#!/usr/bin/env bash
# Regenerates the examples of docs/debugging.md from real runs, so that their numbers cannot
# drift from what the commands print: every block between `<!-- example:NAME -->` and
# `<!-- /example:NAME -->` is replaced by the commands of NAME and their output.
#
#   scripts/debugging_example.sh [--check] [TWINPATH] [BUG_DIR]
#     TWINPATH  default build/bin/twinpath
#     BUG_DIR   the planted bugs' modules, default build/tests/gpu/bug_spirv
#     --check   rewrite nothing: exit 1 (with a diff) when a deterministic block differs
#
# The manual example (compare, aov, pathdiff, pathdiff-clean) renders with fixed seeds and spp,
# so on one machine and driver (lavapipe on the CI machine) its output is the same on every run:
# --check holds it (CTest: debugging_example_up_to_date). The verify examples plan their spp
# from measured times, so their numbers move with the machine's load: they are regenerated, not
# checked.
set -euo pipefail
check=0
if [ "${1:-}" = --check ]; then
  check=1
  shift
fi
root=$(cd "$(dirname "$0")/.." && pwd)
tp=$(realpath "${1:-$root/build/bin/twinpath}")
bugs=$(realpath "${2:-$root/build/tests/gpu/bug_spirv}")
doc=$root/docs/debugging.md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

bug="TWINPATH_DEBUG_SPIRV=$bugs/LIGHT_PDF.spv"
size=(--width 64 --height 64)
# Runs a command line as the docs show it (twinpath for the binary, $bugs shortened), appends the
# line and its stdout to block NAME; the exit code is shown where it is not 0 or the block asks.
block() {
  local name=$1 shown=$2 show_exit=$3
  shift 3
  local code=0 output
  output=$(env "$@" 2>/dev/null) || code=$?
  {
    echo "\$ $shown"
    [ -n "$output" ] && echo "$output"
    if [ "$show_exit" = yes ] || [ $code -ne 0 ]; then echo "exit $code"; fi
  } >>"$work/$name.txt"
}
quiet() { env "$@" >/dev/null 2>&1; }

# 1. The image is wrong: the bugged GPU image against an independent CPU image.
quiet "$bug" "$tp" render cornell --backend vulkan "${size[@]}" --spp 64 --seed 1 -o gpu.exr
quiet "$tp" render cornell "${size[@]}" --spp 64 --seed 2 -o cpu.exr
{
  echo "\$ TWINPATH_DEBUG_SPIRV=build/tests/gpu/bug_spirv/LIGHT_PDF.spv \\"
  echo "    twinpath render cornell --backend vulkan ${size[*]} --spp 64 --seed 1 -o gpu.exr"
  echo "\$ twinpath render cornell ${size[*]} --spp 64 --seed 2 -o cpu.exr"
} >"$work/compare.txt"
block compare "twinpath compare gpu.exr cpu.exr" no "$tp" compare gpu.exr cpu.exr

# 2. The geometry is right: the AOVs agree.
quiet "$bug" "$tp" render cornell --backend vulkan "${size[@]}" --spp 1 --aov all -o gpu_aov.exr
quiet "$tp" render cornell "${size[@]}" --spp 1 --aov all -o cpu_aov.exr
{
  echo "\$ TWINPATH_DEBUG_SPIRV=... twinpath render cornell --backend vulkan ${size[*]} --spp 1 --aov all -o gpu_aov.exr"
  echo "\$ twinpath render cornell ${size[*]} --spp 1 --aov all -o cpu_aov.exr"
} >"$work/aov.txt"
block aov "twinpath compare --exact cpu_aov.exr gpu_aov.exr" no \
  "$tp" compare --exact cpu_aov.exr gpu_aov.exr

# 3. One path on both engines: the same seed, pixel and samples.
log=("${size[@]}" --spp 4 --seed 1 --debug-pixel "32,48")
quiet "$bug" "$tp" render cornell --backend vulkan "${log[@]}" -o g.exr --debug-log gpu.json
quiet "$tp" render cornell "${log[@]}" -o c.exr --debug-log cpu.json
{
  echo "\$ TWINPATH_DEBUG_SPIRV=... twinpath render cornell --backend vulkan ${log[*]} -o g.exr --debug-log gpu.json"
  echo "\$ twinpath render cornell ${log[*]} -o c.exr --debug-log cpu.json"
} >"$work/pathdiff.txt"
block pathdiff "twinpath pathdiff cpu.json gpu.json" yes "$tp" pathdiff cpu.json gpu.json

# Without the bug: the glass sphere of spheres.
clean=(spheres --width 48 --height 48 --spp 4 --seed 1 --debug-pixel "20,36")
quiet "$tp" render "${clean[@]}" --backend vulkan -o g.exr --debug-log gpu.json
quiet "$tp" render "${clean[@]}" -o c.exr --debug-log cpu.json
{
  echo "\$ twinpath render ${clean[*]} --backend vulkan -o g.exr --debug-log gpu.json"
  echo "\$ twinpath render ${clean[*]} -o c.exr --debug-log cpu.json"
} >"$work/pathdiff-clean.txt"
block pathdiff-clean "twinpath pathdiff cpu.json gpu.json" yes "$tp" pathdiff cpu.json gpu.json

deterministic=(compare aov pathdiff pathdiff-clean)
if [ $check = 0 ]; then
  # verify on the same bug, and on the unmodified shader.
  : >"$work/verify-bug.txt"
  block verify-bug "TWINPATH_DEBUG_SPIRV=build/tests/gpu/bug_spirv/LIGHT_PDF.spv twinpath verify cornell ${size[*]} --report report" yes \
    "$bug" "$tp" verify cornell "${size[@]}" --report report
  : >"$work/verify-clean.txt"
  block verify-clean "twinpath verify cornell ${size[*]}" yes "$tp" verify cornell "${size[@]}"
fi

# Replaces the body of every block the runs made (a fenced code block) in the document.
python3 - "$doc" "$work" "$check" "${deterministic[@]}" <<'PY'
import os, re, sys, difflib
doc, work, check, deterministic = sys.argv[1], sys.argv[2], sys.argv[3] == "1", sys.argv[4:]
text = open(doc).read()
new = text
for name in sorted(f[:-4] for f in os.listdir(work) if f.endswith(".txt")):
    if check and name not in deterministic:
        continue
    body = open(os.path.join(work, name + ".txt")).read().rstrip("\n")
    pattern = re.compile(r"(<!-- example:%s -->\n```\n)(?:.*?\n)??(```\n<!-- /example:%s -->)" %
                         (re.escape(name), re.escape(name)), re.S)
    if not pattern.search(new):
        sys.exit(f"{doc}: no block <!-- example:{name} -->")
    new = pattern.sub(lambda m: m.group(1) + body + "\n" + m.group(2), new)
if check:
    if new != text:
        sys.stdout.writelines(difflib.unified_diff(text.splitlines(True), new.splitlines(True),
                                                   doc, "regenerated"))
        sys.exit(1)
    print(f"{doc}: the examples match a run")
else:
    open(doc, "w").write(new)
    print(f"{doc}: examples regenerated")
PY
