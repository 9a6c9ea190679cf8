#!/usr/bin/env bash
# Runs the whole test suite N times on a loaded machine and counts each test's failures
# (docs/testing.md, "The suite under load"). A suite that passes only on an idle machine is red
# for a new user, whose first `make test` may share two cores with a build or a browser.
#
#   scripts/loaded_suite.sh [--runs N] [--load build|stress|none] [--preset P]
#                           [--timeout S] [--out DIR] [--summary FILE]
#
#   --runs N      whole ctest runs, one after another (default 1)
#   --load build  (default) a parallel build of this source tree beside the tests: a second
#                 build directory, ccache off, rebuilt from clean with -j$(nproc) over and over
#                 until the runs end; the condition the suite must pass under
#   --load stress `stress-ng --cpu $(nproc)`: one busy process per core (Debian package
#                 stress-ng, a developer tool, not a dependency of make test)
#   --load none   no load: the idle baseline
#   --preset P    the CMake preset whose tests run (default release; ctest runs with its
#                 settings: 2 jobs)
#   --timeout S   ctest's limit per test without one of its own (default 1500 s): a hang is
#                 counted as a failure instead of stopping the script
#   --out DIR     logs, the load's build tree (removed at the end) and, unless --summary
#                 says otherwise, the summary (default out/loaded-suite, git-ignored)
#   --summary FILE  where the summary goes (default DIR/summary.txt); it is printed too. The
#                 record kept in the repository: --summary benchmarks/loaded-suite.txt
#
# It configures and builds the tests first (as make test does, without installing packages),
# then starts the load, then runs `ctest --preset P` N times. Each run's output is in
# DIR/run-K.log; the summary holds the machine, the commit, one line per run and the failures
# per test. Exit status 0 when every run passed.
set -euo pipefail
cd "$(dirname "$0")/.."

runs=1
load=build
preset=release
timeout=1500
out=out/loaded-suite
summary=
while [[ $# -gt 0 ]]; do
  case $1 in
    --runs) runs=${2:?--runs needs a number}; shift 2 ;;
    --load) load=${2:?--load needs build, stress or none}; shift 2 ;;
    --preset) preset=${2:?--preset needs a name}; shift 2 ;;
    --timeout) timeout=${2:?--timeout needs seconds}; shift 2 ;;
    --out) out=${2:?--out needs a directory}; shift 2 ;;
    --summary) summary=${2:?--summary needs a file}; shift 2 ;;
    -h | --help) sed -n '2,28p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "loaded_suite.sh: unknown argument '$1' (--help lists them)" >&2; exit 2 ;;
  esac
done
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "loaded_suite.sh: --runs $runs: expected a positive integer" >&2; exit 2; }
[[ $timeout =~ ^[1-9][0-9]*$ ]] || { echo "loaded_suite.sh: --timeout $timeout: expected seconds" >&2; exit 2; }
case $load in
  build | none) ;;
  stress)
    command -v stress-ng >/dev/null || {
      echo "loaded_suite.sh: --load stress needs stress-ng, a Debian package:" >&2
      echo "  sudo apt-get install stress-ng     (or use --load build, which needs nothing more)" >&2
      exit 1
    } ;;
  *) echo "loaded_suite.sh: --load $load: expected build, stress or none" >&2; exit 2 ;;
esac

build_dir=build
[[ $preset == release ]] || build_dir=build-$preset
summary=${summary:-$out/summary.txt}
mkdir -p "$out" "$(dirname "$summary")"
# Read before the summary is rewritten: a summary kept in the repository is a tracked file, and
# rewriting it would mark the commit under test as modified.
commit="$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- . 2>/dev/null || echo ' (with uncommitted changes)')"
say() { echo "$*" | tee -a "$summary"; }
: >"$summary"

echo "loaded_suite.sh: configuring and building the tests ($preset)" >&2
cmake --preset "$preset" -DTWINPATH_TESTS=ON >"$out/build.log" 2>&1 &&
  cmake --build --preset "$preset" >>"$out/build.log" 2>&1 ||
  { echo "loaded_suite.sh: the build failed; see $out/build.log" >&2; exit 1; }

# The load runs in a session of its own, so that ending it ends every compiler it started. A
# watchdog in that session ends it too when this script is gone without running its EXIT trap
# (killed with SIGKILL), so that no load outlives the check.
load_pid=
load_dir=
start_load() { # COMMAND ARGS...; its output appended to $out/load.log
  setsid bash -c '
    parent=$1; shift
    "$@" &
    while kill -0 "$parent" 2>/dev/null; do sleep 5; done
    kill -TERM -- "-$$"' watchdog "$$" "$@" >>"$out/load.log" 2>&1 &
  load_pid=$!
}
stop_load() {
  if [[ -n $load_pid ]]; then
    # Each may fail (the group already gone, the watchdog ended by the signal): set -e must not
    # end this trap before the tree is removed.
    kill -TERM -- "-$load_pid" 2>/dev/null || true
    wait "$load_pid" 2>/dev/null || true
    # The compilers it started end on their own time; the tree is removed after them (10 s at
    # most, then KILL).
    for _ in $(seq 50); do kill -0 -- "-$load_pid" 2>/dev/null || break; sleep 0.2; done
    kill -KILL -- "-$load_pid" 2>/dev/null || true
  fi
  load_pid=
  # The load's build tree is as large as the tests' one: not left behind.
  [[ -n $load_dir ]] && rm -rf "$load_dir" 2>/dev/null
  return 0
}
trap stop_load EXIT
trap 'exit 130' INT TERM
cores=$(nproc)
rm -f "$out/load-passes"
case $load in
  build)
    # Configured once here, out of the way of the tests' build; ccache off, so that every
    # pass compiles for real. load-pass.log holds the last pass's output.
    load_dir=$(realpath -m "$out/load-build")
    env -u CMAKE_CXX_COMPILER_LAUNCHER -u CMAKE_C_COMPILER_LAUNCHER \
      cmake --preset "$preset" -B "$load_dir" -DTWINPATH_TESTS=ON >"$out/load.log" 2>&1
    start_load bash -c '
      passes=0
      while :; do
        CCACHE_DISABLE=1 cmake --build "$1" --clean-first -j "$2" >"$3" 2>&1 || true
        passes=$((passes + 1)); echo "$passes" >"$4"
      done' load "$load_dir" "$cores" "$out/load-pass.log" "$out/load-passes"
    load_text="a parallel build beside it (cmake --build --clean-first -j$cores, ccache off, in a loop)" ;;
  stress)
    start_load stress-ng --cpu "$cores" --quiet
    load_text="stress-ng --cpu $cores" ;;
  none) load_text="none" ;;
esac

say "twinpath loaded suite: $runs run(s) of ctest --preset $preset (--timeout $timeout)"
say "commit:  $commit"
say "machine: $cores cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')), $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo), $(. /etc/os-release && echo "$PRETTY_NAME")"
say "load:    $load_text"
say "started: $(date -u '+%Y-%m-%d %H:%M UTC')"
say ""

declare -A failures=()
failed_runs=0
failed_list=$build_dir/Testing/Temporary/LastTestsFailed.log
for k in $(seq "$runs"); do
  rm -f "$failed_list"
  load_before=$(cut -d' ' -f1 /proc/loadavg)
  t0=$(date +%s)
  status=0
  ctest --preset "$preset" --timeout "$timeout" >"$out/run-$k.log" 2>&1 || status=$?
  seconds=$(($(date +%s) - t0))
  total=$(sed -n 's/.*tests passed, [0-9]* tests failed out of \([0-9]*\).*/\1/p' "$out/run-$k.log" | tail -n 1)
  names=()
  [[ -f $failed_list ]] && mapfile -t names < <(cut -d: -f2- "$failed_list")
  if [[ $status -ne 0 && ${#names[@]} -eq 0 ]]; then
    names=("(ctest itself failed with status $status: see $out/run-$k.log)")
  fi
  [[ ${#names[@]} -gt 0 ]] && failed_runs=$((failed_runs + 1))
  say "run $k/$runs: ${total:-?} tests, ${#names[@]} failed, $((seconds / 60)) min $((seconds % 60)) s, load average $load_before -> $(cut -d' ' -f1 /proc/loadavg)"
  for name in "${names[@]}"; do
    say "  failed: $name"
    failures[$name]=$((${failures[$name]:-0} + 1))
  done
done

say ""
if [[ $load == build && -f $out/load-passes ]]; then
  say "load: $(cat "$out/load-passes") whole clean build(s) finished beside the tests"
fi
say "finished: $(date -u '+%Y-%m-%d %H:%M UTC')"
if [[ $failed_runs -eq 0 ]]; then
  say "every run passed: $runs/$runs"
  exit 0
fi
say "runs with a failure: $failed_runs/$runs; failures per test:"
for name in "${!failures[@]}"; do
  say "  ${failures[$name]}/$runs  $name"
done
exit 1
