#!/usr/bin/env python3
"""Table of run.sh's stats files: --device 0 against --device all on one H200."""
import json, os, re

print("| scene | mode | GPU s, device 0 | GPU s, all | all ÷ one | wall s, one / all | ranges (all) | compare --exact |")
print("|---|---|---|---|---|---|---|---|")
for sc in ["cornell", "cornell_spheres", "bunny", "sponza"]:
    for m in ["compute", "pipeline"]:
        one, al = f"{sc}-{m}-one.json", f"{sc}-{m}-all.json"
        if not os.path.exists(one):
            continue
        a, b = json.load(open(one)), json.load(open(al))
        txt = open(f"{sc}-{m}-compare.txt").read()
        exact = txt.split("exit 3\n")[-1].splitlines()[0]
        exact = exact.replace("|diff|", "abs diff")
        exact = re.sub(r", first at .*?\)\)", ")", exact)
        print(f"| {sc} | {m} | {a['gpu_time_s']:.2f} | {b['gpu_time_s']:.2f} | "
              f"{b['gpu_time_s'] / a['gpu_time_s']:.3f} | {a['wall_time_s']:.2f} / {b['wall_time_s']:.2f} | "
              f"{len(b['devices'][0]['sample_ranges'])} | {exact} |")
