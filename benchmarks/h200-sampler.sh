#!/usr/bin/env bash
# BENCHMARKS.md table `h200-sampler`: sobol against random (docs/sampling.md) on the CPU (16
# threads) and in compute mode, five scenes at 256x256.
#   1. relMSE at equal spp: `twinpath bench --ladder --samplers random,sobol`, CPU to 256 spp and
#      compute mode to 512 spp, against one 1024-spp CPU reference per scene;
#   2. the time per sample: repeated renders, the samplers' order alternating: compute mode
#      1024 spp at 256x256 and 64 spp at 1920x1080 (3 rounds, GPU time), the CPU 256 spp at
#      256x256 (4 rounds, wall time), the bundled scenes (the bunny is bench's only: its time
#      is the ladder's);
#   3. the table: relMSE random / sobol at the ladder's last point, time sobol / random (the
#      ladder's wall time, and the median of the rounds' ratios), ε sobol / random = the first over the
#      second (the repeated renders' time where there are some: compute mode's at 1920x1080).
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh) and the shared test meshes (the bunny), then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES benchmarks/h200-sampler.sh [OUT_DIR]
# About 6 minutes. Prints the table; bench.json of both ladders and times.csv stay in OUT_DIR.
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
out=${1:-${OUT:-out/h200-sampler}}
mkdir -p "$out"
scenes=cornell,cornell_glossy,spheres,furnace,bunny samplers=random,sobol
common=(--scenes "$scenes" --samplers "$samplers" --width 256 --height 256 --ref-spp 1024
  --cache "$out/cache" ${ASSETS:+--assets "$ASSETS"})
"$tp" bench --ladder "${common[@]}" --backends cpu --max-spp 256 --section h200-sampler-cpu --out "$out/cpu" || exit 1
"$tp" bench --ladder "${common[@]}" --backends vulkan:compute --max-spp 512 --section h200-sampler-compute --out "$out/compute" || exit 1
echo "mode,size,scene,sampler,round,seconds" >"$out/times.csv"
time_of() { # mode size scene sampler round render-args...
  local j=$out/s.json
  "$tp" render "$3" --sampler "$4" --seed 3 "${@:6}" -o "$out/x.exr" --stats "$j" >/dev/null 2>&1 || return
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(",".join(sys.argv[2:] + [str(d.get("gpu_time_s") or d["wall_time_s"])]))' \
    "$j" "$1" "$2" "$3" "$4" "$5" >>"$out/times.csv"
}
for rep in 1 2 3 4; do
  order="random sobol"; [ $((rep % 2)) = 0 ] && order="sobol random"
  for scene in cornell cornell_glossy spheres furnace; do
    for s in $order; do
      if [ $rep -le 3 ]; then
        time_of compute 256 $scene $s $rep --backend vulkan --vk-mode compute --spp 1024 --width 256 --height 256
        time_of compute 1920 $scene $s $rep --backend vulkan --vk-mode compute --spp 64 --width 1920 --height 1080
      fi
      time_of cpu 256 $scene $s $rep --spp 256 --width 256 --height 256
    done
  done
done
python3 - "$out" <<'PY'
import csv, json, os, statistics, sys
out = sys.argv[1]
rounds = {}
for r in csv.DictReader(open(os.path.join(out, "times.csv"))):
    rounds.setdefault((r["mode"], r["size"], r["scene"], r["round"]), {})[r["sampler"]] = float(r["seconds"])
def repeated(mode, size, scene):
    ratios = [v["sobol"] / v["random"] for k, v in rounds.items()
              if k[:3] == (mode, size, scene) and len(v) == 2]
    return statistics.median(ratios) if ratios else None
print("| scene | mode | relMSE random / sobol | t sobol / random, ladder | "
      "t sobol / random, repeated renders | ε sobol / random |\n|---|---|---:|---:|---|---:|")
for mode, label in (("cpu", "cpu, 16 threads"), ("compute", "vulkan/compute")):
    for scene in json.load(open(os.path.join(out, mode, "bench.json")))["scenes"]:
        last = {run["sampler"]: run["points"][-1] for run in scene["ladder"]}
        err = last["random"]["relmse_excess"] / last["sobol"]["relmse_excess"]
        ladder = last["sobol"]["wall_s"] / last["random"]["wall_s"]
        sizes = ("1920", "256") if mode == "compute" else ("256",)
        rep = {s: repeated(mode, s, scene["name"]) for s in sizes}
        text = "; ".join(f"{v:.3f}" + (f" at {s}" if mode == "compute" else "")
                         for s, v in rep.items() if v) or "—"
        used = rep[sizes[0]] or ladder
        print(f"| {scene['name']} | {label} | {err:.2f} | {ladder:.3f} | {text} | {err / used:.2f} |")
PY
