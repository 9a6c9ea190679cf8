#!/usr/bin/env python3
"""The BENCHMARKS.md table of run.sh's stats files (raw/SCENE-VARIANT.json): ms/spp and
Mrays/s from GPU time, BVH bytes and build time per layout, and the ratios the issue asks for."""
import json, os, sys

raw = os.path.join(os.path.dirname(os.path.abspath(__file__)), "raw")
scenes = "cornell cornell_spheres furnace bunny buddhas buddhas_instanced rtxon sponza".split()
print("| scene | mode | spp | ms/spp | Mrays/s | BVH/AS MB | build ms | wide ÷ binary speed | "
      "pipeline ÷ wide time | memory wide ÷ binary |")
print("|---|---|---|---|---|---|---|---|---|---|")
for s in scenes:
    d = {v: json.load(open(f"{raw}/{s}-{v}.json")) for v in ("binary", "wide", "pipeline")}
    ms = {v: 1e3 * d[v]["gpu_time_s"] / d[v]["spp"] for v in d}
    for v in ("binary", "wide", "pipeline"):
        r = d[v]
        cells = [s if v == "binary" else "", "compute/" + v if v != "pipeline" else "pipeline",
                 str(r["spp"]), f"{ms[v]:.2f}", f"{r['rays']['total'] / r['gpu_time_s'] / 1e6:.0f}",
                 f"{r['accel_bytes'] / 1e6:.2f}", f"{1e3 * r['build_time_s']:.1f}", "", "", ""]
        if v == "wide":
            cells[7] = f"{ms['binary'] / ms['wide']:.2f}"
            cells[8] = f"{ms['pipeline'] / ms['wide']:.2f}"
            cells[9] = f"{d['wide']['accel_bytes'] / d['binary']['accel_bytes']:.2f}"
        print("| " + " | ".join(cells) + " |")
