#!/usr/bin/env python3
"""Load time of one mesh as OBJ and as GLB (issue 37's goal: a 1M-triangle .glb loads in no more
than the time of the same mesh as OBJ). Regenerates the `gltf-load` section of BENCHMARKS.md:

    benchmarks/gltf-load/run.py [REPEATS]      (default 5)

The meshes are the Stanford dragon (../shared/assets/dragon, or $TWINPATH_ASSETS) and the dragon
with every triangle split in four, written by make_meshes.py to a temporary folder. Each file is
loaded REPEATS times by `twinpath info FILE --json` (build/bin/twinpath, or $TWINPATH), OBJ and
GLB alternating; the table gives the fastest `load_seconds` (reading the file into the scene
model) and the fastest wall time of the whole command (load, flatten, feature analysis).
"""
import datetime
import json
import os
import re
import subprocess
import sys
import tempfile
import textwrap
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)


def info(twinpath, path):
    t0 = time.perf_counter()
    out = subprocess.run([twinpath, "info", path, "--json"], check=True, capture_output=True,
                         text=True).stdout
    return json.loads(out)["load_seconds"], time.perf_counter() - t0


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    twinpath = os.environ.get("TWINPATH", os.path.join(ROOT, "build/bin/twinpath"))
    assets = os.environ.get("TWINPATH_ASSETS", os.path.join(ROOT, "../shared/assets"))
    ply = os.path.join(assets, "dragon/dragon_vrip.ply")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, args in [("dragon", []), ("dragon, split 1:4", ["--split"])]:
            stem = "mesh" + str(len(rows))
            tris = int(subprocess.run([sys.executable, os.path.join(HERE, "make_meshes.py"), ply,
                                       tmp, stem] + args, check=True, capture_output=True,
                                      text=True).stdout)
            best = {"obj": [1e9, 1e9], "glb": [1e9, 1e9]}
            for _ in range(repeats):
                for ext in ("obj", "glb"):
                    load, wall = info(twinpath, os.path.join(tmp, f"{stem}.{ext}"))
                    best[ext] = [min(best[ext][0], load), min(best[ext][1], wall)]
            size = {ext: os.path.getsize(os.path.join(tmp, f"{stem}.{ext}")) for ext in best}
            rows.append((name, tris, best, size))
    commit = subprocess.run(["git", "-C", ROOT, "log", "-1", "--format=%h"],
                            capture_output=True, text=True).stdout.strip()
    intro = ("Not a `twinpath bench` section: `benchmarks/gltf-load/run.py " + str(repeats) + "` "
             f"({datetime.date.today()}, commit {commit}, {os.cpu_count()} cores shared with "
             f"other work, load average {os.getloadavg()[0]:.1f} at the end). The same float32 "
             "positions and uint32 triangles written as a plain OBJ and as a GLB "
             f"(`make_meshes.py`), each loaded {repeats} times by `twinpath info FILE --json`, "
             "OBJ and GLB alternating; the fastest run of each. Load is `load_seconds` (the "
             "file into the scene model), info the whole command (load, flatten, feature "
             "analysis). Issue 37's goal is GLB / OBJ load <= 1 at 1M triangles.")
    lines = [
        "<!-- gltf-load:begin -->",
        "## `gltf-load`: one mesh as OBJ and as GLB (issue 37)",
        "",
    ] + textwrap.wrap(intro, 100, break_on_hyphens=False) + [
        "",
        "| mesh | triangles | OBJ MB | GLB MB | OBJ load s | GLB load s | GLB / OBJ load | "
        "OBJ info s | GLB info s |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, tris, best, size in rows:
        lines.append(f"| {name} | {tris:,} | {size['obj'] / 1e6:.1f} | {size['glb'] / 1e6:.1f} | "
                     f"{best['obj'][0]:.3f} | {best['glb'][0]:.3f} | "
                     f"{best['glb'][0] / best['obj'][0]:.3f} | {best['obj'][1]:.2f} | "
                     f"{best['glb'][1]:.2f} |")
    lines.append("<!-- gltf-load:end -->")
    section = "\n".join(lines) + "\n"
    path = os.path.join(ROOT, "BENCHMARKS.md")
    text = open(path).read()
    pattern = re.compile(r"<!-- gltf-load:begin -->.*?<!-- gltf-load:end -->\n", re.S)
    text = pattern.sub(lambda _: section, text) if pattern.search(text) else \
        text.rstrip("\n") + "\n\n" + section
    open(path, "w").write(text)
    print(section)


if __name__ == "__main__":
    main()
