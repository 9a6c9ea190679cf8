#!/usr/bin/env bash
# BENCHMARKS.md table `h200-fill`: Mrays/s of the same renders at 256x256 and 1920x1080, the
# sizes people verify at and publish at, in compute mode (binary BVH) and pipeline mode, with
# each size's rate over the 1920x1080 one. As a user sees it: `render --spp 1024` at 256x256,
# `--spp 64` at 1920x1080, seed 7, `--sampler random`, `--time-limit 4`, Mrays/s = the render's
# rays over its wall time (--stats: rays.total / wall_time_s), best of ROUNDS. cornell_spheres
# (a glass and a mirror sphere, max depth 1000) also runs at --max-depth 8. BASE, the twinpath
# of another build (the table's 01f88eb columns), adds its 256x256 / 1920x1080 ratios.
#
# Runs on the GPU machine (docs/gpu.md, "Running on a GPU machine"): carry the unpacked gpu
# bundle (scripts/make_gpu_bundle.sh; BASE: a second one) and the shared test meshes, then
#   TWINPATH=BUNDLE/bin/twinpath ASSETS=MESHES [BASE=...] [ROUNDS=1] benchmarks/h200-fill.sh [OUT_DIR]
# About 3 minutes per round with BASE. Prints the table; the rows are in OUT_DIR/times.csv.
set -uo pipefail
tp=${TWINPATH:-build/bin/twinpath}
: "${ASSETS:?ASSETS: the shared test meshes (bunny/, buddha/)}"
out=${1:-${OUT:-out/h200-fill}}
mkdir -p "$out"
builds="new"; [ -n "${BASE:-}" ] && builds="base new"
scene() {
  case $1 in
    bunny) echo "$ASSETS/bunny/stanford-bunny.obj" ;;
    buddha) echo "$ASSETS/buddha/happy_buddha_112k.obj" ;;
    *) echo "$1" ;;
  esac
}
echo "round,build,scene,depth,size,mode,spp,rays,wall_s" >"$out/times.csv"
for round in $(seq "${ROUNDS:-1}"); do
  for sc in cornell cornell_glossy cornell_spheres spheres furnace bunny buddha; do
    depths="-"; [ $sc = cornell_spheres ] && depths="- 8"
    for d in $depths; do
      for sz in 256x256:1024 1920x1080:64; do
        size=${sz%:*}
        for m in compute pipeline; do
          for b in $builds; do
            bin=$tp; args=(--bvh binary); [ $b = base ] && { bin=$BASE; args=(); }
            [ $m = pipeline ] && args=()
            [ "$d" != - ] && args+=(--max-depth "$d")
            "$bin" render "$(scene $sc)" --backend vulkan --vk-mode $m --width ${size%x*} \
              --height ${size#*x} --spp ${sz#*:} --seed 7 --sampler random --time-limit 4 \
              "${args[@]}" -o "$out/x.exr" --stats "$out/s.json" >"$out/render.log" 2>&1 ||
              { echo "render failed: $b $sc $size $m" >&2; continue; }
            python3 -c 'import json, sys; d = json.load(open(sys.argv[1]))
print(",".join(sys.argv[2:] + [str(d["spp"]), str(d["rays"]["total"]), str(d["wall_time_s"])]))' \
              "$out/s.json" "$round" $b $sc "$d" $size $m >>"$out/times.csv"
          done
        done
      done
    done
  done
done
python3 - "$out/times.csv" <<'PY'
import csv, sys
best, rows = {}, []
for r in csv.DictReader(open(sys.argv[1])):
    key = (r["scene"], r["depth"])
    rows += [key] if key not in rows else []
    k = key + (r["build"], r["mode"], r["size"])
    best[k] = max(best.get(k, 0), int(r["rays"]) / float(r["wall_s"]) / 1e6)
base = any(k[2] == "base" for k in best)
head = ["scene"] + [f"{m} {s}" for m in ("compute", "pipeline") for s in ("256²", "1080p", "ratio")]
head += ["01f88eb ratio, compute / pipeline"] if base else []
print("| " + " | ".join(head) + " |\n|---|" + "---:|" * (len(head) - 1))
for scene, depth in rows:
    cells = [scene if depth == "-" else f"{scene}, depth {depth}"]
    ratio = lambda b, m: (best.get((scene, depth, b, m, "256x256"), 0) /
                          best.get((scene, depth, b, m, "1920x1080"), float("inf")))
    for m in ("compute", "pipeline"):
        for s in ("256x256", "1920x1080"):
            cells.append(f"{best.get((scene, depth, 'new', m, s), 0):.0f}")
        cells.append(f"{ratio('new', m):.2f}")
    if base:
        cells.append(f"{ratio('base', 'compute'):.2f} / {ratio('base', 'pipeline'):.2f}")
    print("| " + " | ".join(cells) + " |")
PY
