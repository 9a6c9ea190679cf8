#!/usr/bin/env python3
"""Bytes and per-ray traversal work of compute mode's BVH layouts, from the product's commands.

    python3 benchmarks/wide-bvh-collapse/counts.py TWINPATH ASSETS OUT
        [--layouts binary,wide,auto] [--scenes cornell,...]

For each scene (the bundled scenes in the repository's scenes/, the bunny and the Happy Buddha
from ASSETS) and each layout, one render with the cost view (`twinpath render SCENE --backend
vulkan --vk-mode compute --bvh LAYOUT --integrator cost --width 160 --height 90 --spp 2 --seed 1
--stats`, docs/debugging.md): the stats give the BVH's bytes (accel_bytes), its shape
(extra.bvh_levels) and the layout built (extra.bvh_layout: with auto, the one it chose); the
image's mean R and G (`oiiotool --printstats`) the nodes visited and triangles tested per
camera ray, counted by the traversal itself. Box evaluations follow from the node visits: both
children of a binary node, all eight slots of a wide node (shaders/trace_cwbvh.glsl). Any
device: no timings. Prints a Markdown table; raw stats and images stay in OUT, the rows in
OUT/counts.json.
"""
import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BOXES_PER_NODE = {"binary": 2, "wide": 8}


def scenes(assets, only):
    """(name, path) of the bundled scenes, the bunny and the Buddha; `only`: names to keep."""
    out = [(s, os.path.join(ROOT, "scenes", s + ".json"))
           for s in ("cornell", "cornell_glossy", "cornell_spheres", "spheres", "furnace")]
    out.append(("bunny", os.path.join(assets, "bunny/stanford-bunny.obj")))
    out.append(("buddha", os.path.join(assets, "buddha/happy_buddha_112k.obj")))
    return [s for s in out if not only or s[0] in only]


def mean_rg(exr):
    text = subprocess.run(["oiiotool", exr, "--printstats"], check=True, capture_output=True,
                          text=True).stdout
    avg = re.search(r"Stats Avg:\s*([-\d.eE+]+)\s+([-\d.eE+]+)", text)
    return float(avg.group(1)), float(avg.group(2))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("twinpath")
    p.add_argument("assets")
    p.add_argument("out")
    p.add_argument("--layouts", default="binary,wide,auto")
    p.add_argument("--size", default="160x90")
    p.add_argument("--spp", default="2")
    p.add_argument("--scenes", default="", help="comma-separated names; default: all")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    w, h = a.size.split("x")
    layouts = a.layouts.split(",")
    rows = []
    for name, path in scenes(a.assets, set(filter(None, a.scenes.split(",")))):
        base = None
        for layout in layouts:
            stem = os.path.join(a.out, f"{name}-{layout}")
            cmd = [a.twinpath, "render", path, "--backend", "vulkan", "--vk-mode", "compute",
                   "--bvh", layout, "--integrator", "cost", "--width", w, "--height", h,
                   "--spp", a.spp, "--seed", "1", "-o", stem + ".exr", "--stats", stem + ".json"]
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr}")
            with open(stem + ".json") as f:
                stats = json.load(f)
            nodes, tris = mean_rg(stem + ".exr")
            built = stats["extra"]["bvh_layout"]
            row = {"scene": name, "layout": layout, "built": built,
                   "levels": stats["extra"]["bvh_levels"], "bytes": stats["accel_bytes"],
                   "build_ms": 1e3 * stats["build_time_s"], "nodes": nodes,
                   "boxes": nodes * BOXES_PER_NODE[built], "triangles": tris}
            base = base or row
            row["bytes_ratio"] = row["bytes"] / base["bytes"]
            rows.append(row)
    with open(os.path.join(a.out, "counts.json"), "w") as f:
        json.dump(rows, f, indent=1)
    print(f"| scene | levels | --bvh | BVH bytes | ÷ {layouts[0]} | build ms | nodes/ray | "
          "box evaluations/ray | triangles/ray |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        layout = r["layout"] if r["built"] == r["layout"] else f"{r['layout']} ({r['built']})"
        print(f"| {r['scene']} | {r['levels']} | {layout} | {r['bytes']} | "
              f"{r['bytes_ratio']:.3f} | {r['build_ms']:.1f} | {r['nodes']:.2f} | "
              f"{r['boxes']:.1f} | {r['triangles']:.2f} |")


if __name__ == "__main__":
    main()
