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

# Against the H200 run (benchmarks/h200-wide-bvh/raw): per-ray work weighted by that run's mix
# of camera, extension and shadow rays, the bytes each ray fetches, and the fetch rate those
# bytes make at the measured rays/s (what the SMs request from L1/L2, not DRAM traffic).
h200 = pathlib.Path(__file__).resolve().parent.parent / "h200-wide-bvh" / "raw"
kinds = ["camera", "extension", "shadow"]


def weighted(s, layout, field, mix):
    return sum(mix[k] * rows[(s, k, layout)][field] for k in kinds) / sum(mix.values())


print()
print("| scene | H200 wide ÷ binary speed | nodes w/b | box evaluations w/b (8 per wide node) | "
      "occupied-slot tests w/b | triangles w/b | bytes/ray binary | bytes/ray wide | bytes w/b | "
      "fetch TB/s binary | fetch TB/s wide | BVH MB binary / wide |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
pairs = []
for s in order:
    if (s, "camera", "binary") not in rows:
        continue
    st = {v: json.loads((h200 / f"{s}-{v}.json").read_text()) for v in ("binary", "wide")}
    mix = {k: st["binary"]["rays"][k] for k in kinds}
    speed = (st["binary"]["gpu_time_s"] / st["binary"]["spp"]) / (st["wide"]["gpu_time_s"] / st["wide"]["spp"])
    r = {f: weighted(s, "wide", f, mix) / weighted(s, "binary", f, mix)
         for f in ("nodes", "box_slots", "box_tests", "triangles", "bytes_per_ray")}
    bb, bw = weighted(s, "binary", "bytes_per_ray", mix), weighted(s, "wide", "bytes_per_ray", mix)
    tb = {v: (bb if v == "binary" else bw) * st[v]["rays_per_second"] / 1e12 for v in st}
    pairs.append((speed, r["box_slots"]))
    print(f"| {s} | {speed:.2f} | {r['nodes']:.2f} | {r['box_slots']:.2f} | {r['box_tests']:.2f} | "
          f"{r['triangles']:.2f} | {bb:.0f} | {bw:.0f} | {r['bytes_per_ray']:.2f} | {tb['binary']:.2f} | "
          f"{tb['wide']:.2f} | {st['binary']['accel_bytes'] / 1e6:.2f} / {st['wide']['accel_bytes'] / 1e6:.2f} |")


def ranks(xs):
    return [sorted(xs).index(x) for x in xs]


a, b = ranks([p[0] for p in pairs]), ranks([p[1] for p in pairs])
n = len(pairs)
rho = 1 - 6 * sum((x - y) ** 2 for x, y in zip(a, b)) / (n * (n * n - 1))
print(f"\nSpearman rank correlation of the H200 speed ratio with the box-evaluation ratio: {rho:.2f} (n = {n})")
