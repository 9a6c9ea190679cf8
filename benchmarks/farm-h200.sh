#!/usr/bin/env bash
# BENCHMARKS.md table `farm-h200`: the CPU reference split by sample ranges (docs/farm.md, "A
# farm on Slurm") on one 16-core machine: cornell at 960x540, 256 spp in all, as P = 1, 2, 4, 8
# concurrent processes of 16/P threads (`render --spp 256/P --sample-offset i*256/P --film full`,
# each loading the scene, building its BVH and writing its EXR, as
# scripts/slurm/render_part.sbatch does), then `twinpath merge`, against one process of 16 threads; two repetitions. Every merged
# image is checked against the unsplit one (`compare --exact --tolerance 1e-5`). Then the merge
# of 64 parts at 1920x1080 (1 spp each), twice, with its peak memory where /usr/bin/time is.
#   [TWINPATH=build/bin/twinpath] benchmarks/farm-h200.sh [OUT_DIR]
# The table's machine is the GPU machine's idle 16-core Xeon, run from the unpacked gpu bundle
# (docs/gpu.md, "Running on a GPU machine"); any idle 16-core machine will do. About 3 minutes.
# Prints the rows (OUT_DIR/results.csv: wall and merge milliseconds).
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/farm-h200}}
mkdir -p "$out"
res=$out/results.csv
echo "experiment,processes,threads_each,repeat,wall_ms,merge_ms" >"$res"
now() { date +%s%N; }
ms() { echo $((($2 - $1) / 1000000)); }
W=960 H=540 SPP=256
for rep in 1 2; do
  t0=$(now)
  "$tp" render cornell --width $W --height $H --spp $SPP --threads 16 --film full -o "$out/single.exr" >/dev/null 2>&1
  echo "single,1,16,$rep,$(ms $t0 "$(now)"),0" >>"$res"
  for P in 1 2 4 8; do
    rm -f "$out"/part_*.exr
    t0=$(now)
    for ((i = 0; i < P; i++)); do
      b=$((i * SPP / P)) e=$(((i + 1) * SPP / P))
      "$tp" render cornell --width $W --height $H --spp $((e - b)) --sample-offset $b \
        --threads $((16 / P)) --film full -o "$out/part_$i.exr" >/dev/null 2>&1 &
    done
    wait
    t1=$(now)
    "$tp" merge "$out"/part_*.exr -o "$out/merged_$P.exr" >/dev/null 2>&1
    echo "split,$P,$((16 / P)),$rep,$(ms $t0 $t1),$(ms $t1 "$(now)")" >>"$res"
    [ $rep = 1 ] && echo "P=$P: $("$tp" compare --exact "$out/merged_$P.exr" "$out/single.exr" --tolerance 1e-5 2>&1 | head -1)"
  done
done
# 64 parts of 1 spp at 1920x1080 (max depth 2: the merge is what is timed), 8 at a time.
for ((i = 0; i < 64; i++)); do
  "$tp" render cornell --width 1920 --height 1080 --spp 1 --max-depth 2 --sample-offset $i \
    --threads 2 --film full -o "$(printf "$out/p64_%02d.exr" $i)" >/dev/null 2>&1 &
  (((i + 1) % 8 == 0)) && wait
done
wait
timer=(); [ -x /usr/bin/time ] && timer=(/usr/bin/time -f "merge of 64: peak resident %M KB")
for rep in 1 2; do
  t0=$(now)
  "${timer[@]}" "$tp" merge "$out"/p64_*.exr -o "$out/m64.exr" 2>&1 >/dev/null | grep -i peak
  echo "merge64,64,1,$rep,0,$(ms $t0 "$(now)")" >>"$res"
done
rm -f "$out"/*.exr
cat "$res"
