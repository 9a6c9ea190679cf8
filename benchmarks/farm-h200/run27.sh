#!/usr/bin/env bash
# Issue 27 benchmark on the GPU machine's CPU (16 cores): the CPU reference split by sample
# ranges over P = 1, 2, 4, 8 concurrent processes (16/P threads each, the Slurm-style split of
# scripts/slurm/render_part.sbatch) and merged, against one process with 16 threads, same total
# spp; then `twinpath merge` of 64 parts at 1920x1080.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig # the Vulkan loader twinpath links
mkdir -p /tmp/b && tar -C /tmp/b -xJf .carry/27/twinpath-bundle.tar.xz
tp=/tmp/b/twinpath-bundle/bin/twinpath
scene=/tmp/b/twinpath-bundle/scenes/cornell.json
w=/tmp/w27; mkdir -p $w
res=$OUT/results.csv
echo "experiment,processes,threads_each,repeat,spp,width,height,wall_ms,merge_ms" > $res
nproc; lscpu | grep -E "Model name|^CPU\(s\)"
$tp --help > /dev/null || exit 1
W=960; H=540; SPP=256
timer=""; [[ -x /usr/bin/time ]] && timer="/usr/bin/time -v"
now() { date +%s%N; }
ms() { echo $((($2 - $1) / 1000000)); }
for rep in 1 2; do
  t0=$(now)
  $tp render $scene --width $W --height $H --spp $SPP --threads 16 -o $w/single.exr --stats $w/single.json > $w/single.log 2>&1
  t1=$(now)
  echo "single,1,16,$rep,$SPP,$W,$H,$(ms $t0 $t1),0" >> $res
  for P in 1 2 4 8; do
    rm -f $w/part_*.exr
    t0=$(now)
    for ((i = 0; i < P; i++)); do
      b=$((i * SPP / P)); e=$(((i + 1) * SPP / P))
      $tp render $scene --width $W --height $H --spp $((e - b)) --sample-offset $b --threads $((16 / P)) -o $w/part_$i.exr > $w/part_${P}_$i.log 2>&1 &
    done
    wait
    t1=$(now)
    $tp merge $w/part_*.exr -o $w/merged_$P.exr > $w/merge_$P.log 2>&1
    t2=$(now)
    echo "split,$P,$((16 / P)),$rep,$SPP,$W,$H,$(ms $t0 $t1),$(ms $t1 $t2)" >> $res
    [[ $rep == 1 ]] && { $tp compare --exact $w/merged_$P.exr $w/single.exr --tolerance 1e-5 --json $OUT/exact_split_$P.json > $OUT/exact_split_$P.txt 2>&1; echo "exit $?" >> $OUT/exact_split_$P.txt; }
  done
done
cp $w/single.json $OUT/single_stats.json
# 64 parts of 1 spp at 1920x1080 (max depth 2: the merge is what is timed), 8 at a time.
rm -f $w/p64_*.exr
for ((i = 0; i < 64; i++)); do
  $tp render $scene --width 1920 --height 1080 --spp 1 --max-depth 2 --sample-offset $i --threads 2 -o $(printf "$w/p64_%02d.exr" $i) > /dev/null 2>&1 &
  (( (i + 1) % 8 == 0 )) && wait
done
wait
ls $w/p64_*.exr | wc -l
du -sh $w/p64_00.exr
for rep in 1 2; do
  t0=$(now)
  $timer $tp merge $w/p64_*.exr -o $w/m64.exr > $OUT/merge64_$rep.log 2>&1
  t1=$(now)
  echo "merge64,64,1,$rep,64,1920,1080,0,$(ms $t0 $t1)" >> $res
done
grep -E "Maximum resident|Elapsed" $OUT/merge64_1.log
cat $res
