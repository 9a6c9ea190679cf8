#!/usr/bin/env python3
"""The table of h200.sh: compute mode's BVH layouts side by side, per scene and image size.

    python3 benchmarks/wide-bvh-collapse/table.py BENCH.json STATS_DIR

BENCH.json: `twinpath bench --sizes` with the backends vulkan:compute, vulkan:compute-wide and
vulkan:compute-auto (Mrays/s: every ray over GPU time, best of its rounds). STATS_DIR:
SCENE-LAYOUT.json, the `--stats` of one render per scene (its bench name) and layout (binary,
wide, auto): accel_bytes, and with auto the layout built (extra.bvh_layout) and both layouts'
estimated work per ray (extra.bvh_estimate, extra.bvh_estimate_binary or _wide: "nodes N boxes
B triangles T instances I", vulkan_rt/compute_mode/bvh_estimate.h). Prints Markdown.
"""
import json
import os
import sys

MODES = {"compute": "binary", "compute-wide": "wide", "compute-auto": "auto"}


def boxes(estimate):
    words = estimate.split()
    return float(words[words.index("boxes") + 1])


def estimated_box_ratio(auto):
    """The estimated box evaluations per ray, wide / binary, that auto chose by."""
    extra = auto["extra"]
    built = extra["bvh_layout"]
    other = "binary" if built == "wide" else "wide"
    b = {built: boxes(extra["bvh_estimate"]), other: boxes(extra["bvh_estimate_" + other])}
    return b["wide"] / b["binary"]


def main():
    bench_path, stats_dir = sys.argv[1:3]
    with open(bench_path) as f:
        bench = json.load(f)

    def stats(scene, layout):
        path = os.path.join(stats_dir, f"{scene}-{layout}.json")
        if not os.path.exists(path):
            return None
        with open(path) as f:
            return json.load(f)

    print("| scene | size | binary Mrays/s | wide | auto | wide ÷ binary | auto ÷ binary | "
          "auto chose | estimated boxes wide ÷ binary | bytes wide ÷ binary |")
    print("|---|---|---:|---:|---:|---:|---:|---|---:|---:|")
    for scene in bench["scenes"]:
        name = scene["name"]
        rate = {}  # (layout, size) -> Mrays/s
        for run in scene.get("sizes", []):
            layout = MODES.get(run["mode"])
            for p in run["points"] if layout else []:
                rate[(layout, f"{p['width']}×{p['height']}")] = p["mrays_s"]
        sizes = sorted({s for _, s in rate}, key=lambda s: int(s.split("×")[0]))
        b, w, a = (stats(name, l) for l in ("binary", "wide", "auto"))
        chose = a["extra"]["bvh_layout"] if a else ""
        est = f"{estimated_box_ratio(a):.2f}" if a else ""
        mem = f"{w['accel_bytes'] / b['accel_bytes']:.3f}" if b and w else ""
        for size in sizes:
            r = {l: rate.get((l, size)) for l in ("binary", "wide", "auto")}
            cells = " | ".join(f"{r[l]:.4g}" if r[l] else "" for l in r)
            ratio = {l: f"{r[l] / r['binary']:.2f}" if r[l] and r["binary"] else ""
                     for l in ("wide", "auto")}
            print(f"| {name} | {size} | {cells} | {ratio['wide']} | {ratio['auto']} | {chose} | "
                  f"{est} | {mem} |")


if __name__ == "__main__":
    main()
