#!/usr/bin/env bash
# Issue 23 item 2: cornell_spheres as OBJ (cornell_spheres_obj.py) at the origin and moved by
# 1e2, 1e4 and 1e6 along every axis together with its camera, 64x64, 256 spp, max depth 1000.
# Each translation is rendered with the origin's seed (expected: the same image, compare --exact)
# and with another seed (expected: compare consistent); the last column is the image's mean over
# the origin's (oiiotool, where installed).
#   measure.sh TWINPATH OUT_DIR [render flags, e.g. --backend vulkan --vk-mode pipeline]
set -u
here=$(cd "$(dirname "$0")" && pwd)
tp=$1
out=$2
shift 2
mkdir -p "$out"
for d in 0 1e2 1e4 1e6; do
    python3 "$here/cornell_spheres_obj.py" "$d" "$out/scene-$d"
    for seed in 1 2; do
        # shellcheck disable=SC2046
        "$tp" render "$out/scene-$d/cornell_spheres.obj" $(cat "$out/scene-$d/camera.txt") \
            --width 64 --height 64 --spp 256 --max-depth 1000 --seed "$seed" \
            -o "$out/d$d-s$seed.exr" "$@" >"$out/d$d-s$seed.log" 2>&1 ||
            echo "render failed: d=$d seed=$seed ($(tail -1 "$out/d$d-s$seed.log"))"
    done
done
mean() {
    command -v oiiotool >/dev/null || { echo "-"; return; }
    oiiotool --stats "$1" | awk '/Stats Avg/ {print ($3 + $4 + $5) / 3}'
}
m0=$(mean "$out/d0-s1.exr")
echo "| moved by | same seed (compare --exact) | seed 2 (compare) | mean / origin's |"
echo "|---|---|---|---|"
for d in 1e2 1e4 1e6; do
    exact=$("$tp" compare --exact "$out/d0-s1.exr" "$out/d$d-s1.exr" 2>&1 | head -1)
    stat=$("$tp" compare "$out/d0-s1.exr" "$out/d$d-s2.exr" 2>&1 | head -1)
    m=$(mean "$out/d$d-s1.exr")
    ratio=$(awk -v a="$m" -v b="$m0" 'BEGIN { if (a == "-" || b == "-") print "-"; else printf "%.4f", a / b }')
    echo "| $d | $exact | $stat | $ratio |"
done
