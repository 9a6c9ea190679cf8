#!/usr/bin/env python3
"""Markdown table of raw/*.jsonl (run.sh): per scene and ray kind, per-ray work of both layouts,
and the bytes each ray fetches under the paper's cost model (Ylitie et al. 2017, sec. 5: node
visits x node bytes + triangle tests x triangle bytes; 64-byte binary nodes, 80-byte wide nodes,
64-byte BvhTriangles in both)."""
import json, pathlib, sys

raw = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "raw")
order = ["cornell", "cornell_spheres", "furnace", "bunny", "buddhas", "buddhas_instanced", "rtxon", "sponza"]
rows = {}
for f in raw.glob("*.jsonl"):
    for line in f.read_text().splitlines():
        r = json.loads(line)
        rows[(r["scene"], r["rays"], r["layout"])] = r
print("| scene | rays | layout | nodes | box tests (slots) | box hits | triangles | pushes | instances | bytes/ray | wide ÷ binary bytes | BVH MB |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for s in order:
    for k in ["camera", "extension", "shadow", "all"]:
        b, w = rows.get((s, k, "binary")), rows.get((s, k, "wide"))
        if not b or not w:
            continue
        for name, r in (("binary", b), ("wide", w)):
            ratio = f"{w['bytes_per_ray'] / b['bytes_per_ray']:.2f}" if name == "wide" else ""
            print(f"| {s if name == 'binary' and k == 'camera' else ''} | {k if name == 'binary' else ''} | {name} | "
                  f"{r['nodes']:.1f} | {r['box_tests']:.1f} ({r['box_slots']:.1f}) | {r['box_hits']:.1f} | "
                  f"{r['triangles']:.1f} | {r['pushes']:.2f} | {r['instance_entries']:.2f} | {r['bytes_per_ray']:.0f} | {ratio} | "
                  f"{r['bvh_bytes'] / 1e6:.2f} |")
        for r in (b, w):
            if r["mismatch_fraction"] > 1e-3:
                print(f"<!-- {s} {k} {r['layout']}: {r['mismatch_fraction']:.4f} of the rays disagree with the CPU path -->")
