#!/usr/bin/env python3
"""BENCHMARKS.md table `wide-bvh-bytes`: bytes and per-ray traversal work of compute mode's two
BVH layouts, binary and wide (docs/gpu.md, "Compressed 8-wide BVH"), from the product's commands.

    benchmarks/wide-bvh-bytes.py [TWINPATH [ASSETS [OUT]]]
        (default build/bin/twinpath, $TWINPATH_ASSETS or ../shared/assets, a temporary folder)

For each scene (the bundled scenes, the bunny and the Happy Buddha as OBJ files) and layout, one
render with the cost view (`twinpath render SCENE --backend vulkan --vk-mode compute --bvh
LAYOUT --integrator cost --width 160 --height 90 --spp 2 --seed 1 --stats`, docs/debugging.md):
the stats give the BVH's bytes (accel_bytes) and its levels (extra.bvh_levels); the image's mean
R and G (`oiiotool --printstats`) the nodes visited and triangles tested per camera ray, as the
traversal counts them. Box evaluations follow from the visits: both children of a binary node,
all eight slots of a wide node. Any Vulkan device (lavapipe will do): counts, no timings.
Prints the table.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BOXES_PER_NODE = {"binary": 2, "wide": 8}


def mean_rg(exr):
    text = subprocess.run(["oiiotool", exr, "--printstats"], check=True, capture_output=True,
                          text=True).stdout
    avg = re.search(r"Stats Avg:\s*([-\d.eE+]+)\s+([-\d.eE+]+)", text)
    return float(avg.group(1)), float(avg.group(2))


def count(twinpath, scene, layout, out):
    stem = os.path.join(out, f"{os.path.basename(scene)}-{layout}")
    subprocess.run([twinpath, "render", scene, "--backend", "vulkan", "--vk-mode", "compute",
                    "--bvh", layout, "--integrator", "cost", "--width", "160", "--height", "90",
                    "--spp", "2", "--seed", "1", "-o", stem + ".exr", "--stats", stem + ".json"],
                   check=True, capture_output=True)
    stats = json.load(open(stem + ".json"))
    nodes, triangles = mean_rg(stem + ".exr")
    return {"levels": stats["extra"]["bvh_levels"], "bytes": stats["accel_bytes"],
            "nodes": nodes, "boxes": nodes * BOXES_PER_NODE[layout], "triangles": triangles}


def main():
    twinpath = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/bin/twinpath")
    assets = sys.argv[2] if len(sys.argv) > 2 else os.environ.get(
        "TWINPATH_ASSETS", os.path.join(ROOT, "../shared/assets"))
    out = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp()
    os.makedirs(out, exist_ok=True)
    scenes = [(s, os.path.join(ROOT, "scenes", s + ".json"))
              for s in ("cornell", "cornell_glossy", "cornell_spheres", "spheres", "furnace")]
    scenes += [("bunny (OBJ)", os.path.join(assets, "bunny/stanford-bunny.obj")),
               ("Buddha (OBJ)", os.path.join(assets, "buddha/happy_buddha_112k.obj"))]
    print("| scene | levels | binary bytes | wide bytes | wide ÷ binary | nodes/ray binary | "
          "wide | box evaluations binary | wide | triangles/ray binary | wide |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, path in scenes:
        b, w = (count(twinpath, path, layout, out) for layout in ("binary", "wide"))
        print(f"| {name} | {b['levels']} | {b['bytes']:,} | {w['bytes']:,} | "
              f"{w['bytes'] / b['bytes']:.3f} | {b['nodes']:.2f} | {w['nodes']:.2f} | "
              f"{b['boxes']:.1f} | {w['boxes']:.1f} | {b['triangles']:.2f} | "
              f"{w['triangles']:.2f} |")


if __name__ == "__main__":
    main()
