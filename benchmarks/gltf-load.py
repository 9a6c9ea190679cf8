#!/usr/bin/env python3
"""BENCHMARKS.md table `gltf-load`: the load time of one mesh as a plain OBJ and as a GLB.

    benchmarks/gltf-load.py [REPEATS]      (default 5)

The mesh is the Stanford dragon ($TWINPATH_ASSETS/dragon/dragon_vrip.ply, default
../shared/assets), and the dragon with every triangle split in four: the same float32 positions
and uint32 triangles written as an OBJ (positions with the 9 significant digits that identify a
float) and as a GLB, no normals, uvs or materials in either. Each file is loaded REPEATS times by
`twinpath info FILE --json` ($TWINPATH, default build/bin/twinpath), OBJ and GLB alternating;
the table gives the fastest `load_seconds` (the file into the scene model) and the fastest wall
time of the whole command (load, flatten, feature analysis). Prints the table.
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_ply(path):
    """Vertices and triangles (faces as fans) of an ASCII PLY."""
    with open(path, "rb") as f:
        header = []
        while not header or header[-1] != "end_header":
            header.append(f.readline().decode("ascii").strip())
        if "format ascii 1.0" not in header:
            sys.exit(f"{path}: only ASCII PLY is read")
        counts = {l.split()[1]: int(l.split()[2]) for l in header if l.startswith("element")}
        lines = f.read().split(b"\n")
    nv = counts["vertex"]
    vertices = [tuple(float(v) for v in lines[i].split()[:3]) for i in range(nv)]
    triangles = []
    for line in lines[nv:nv + counts["face"]]:
        face = [int(v) for v in line.split()]
        triangles += [(face[1], face[k], face[k + 1]) for k in range(2, face[0])]
    return vertices, triangles


def split(vertices, triangles):
    """Every triangle as four, through its edges' midpoints: a larger mesh of the same shape."""
    vertices, midpoint, out = list(vertices), {}, []

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            midpoint[key] = len(vertices)
            vertices.append(tuple((p + q) / 2 for p, q in zip(vertices[a], vertices[b])))
        return midpoint[key]
    for a, b, c in triangles:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return vertices, out


def write_meshes(vertices, triangles, stem):
    positions = struct.pack(f"<{3 * len(vertices)}f", *[c for v in vertices for c in v])
    floats = struct.unpack(f"<{3 * len(vertices)}f", positions)  # as float32, exactly
    with open(stem + ".obj", "w") as f:
        for i in range(0, len(floats), 3):
            f.write("v %.9g %.9g %.9g\n" % floats[i:i + 3])
        for a, b, c in triangles:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")
    indices = struct.pack(f"<{3 * len(triangles)}I", *[i for t in triangles for i in t])
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(vertices),
                          "type": "VEC3", "min": [min(floats[k::3]) for k in range(3)],
                          "max": [max(floats[k::3]) for k in range(3)]},
                         {"bufferView": 1, "componentType": 5125, "count": 3 * len(triangles),
                          "type": "SCALAR"}],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                           {"buffer": 0, "byteOffset": len(positions),
                            "byteLength": len(indices)}],
           "buffers": [{"byteLength": len(positions) + len(indices)}]}
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    data = positions + indices  # both multiples of 4 bytes
    with open(stem + ".glb", "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(data)))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(data), 0x004E4942) + data)


def info(twinpath, path):
    t0 = time.perf_counter()
    out = subprocess.run([twinpath, "info", path, "--json"], check=True, capture_output=True,
                         text=True).stdout
    return json.loads(out)["load_seconds"], time.perf_counter() - t0


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    twinpath = os.environ.get("TWINPATH", os.path.join(ROOT, "build/bin/twinpath"))
    assets = os.environ.get("TWINPATH_ASSETS", os.path.join(ROOT, "../shared/assets"))
    vertices, triangles = read_ply(os.path.join(assets, "dragon/dragon_vrip.ply"))
    print("| mesh | triangles | OBJ MB | GLB MB | OBJ load s | GLB load s | GLB / OBJ load | "
          "OBJ info s | GLB info s |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("dragon", "dragon, split 1:4"):
            if name != "dragon":
                vertices, triangles = split(vertices, triangles)
            stem = os.path.join(tmp, "mesh")
            write_meshes(vertices, triangles, stem)
            best = {"obj": [1e9, 1e9], "glb": [1e9, 1e9]}
            for _ in range(repeats):
                for ext in best:
                    load, wall = info(twinpath, f"{stem}.{ext}")
                    best[ext] = [min(best[ext][0], load), min(best[ext][1], wall)]
            mb = {ext: os.path.getsize(f"{stem}.{ext}") / 1e6 for ext in best}
            print(f"| {name} | {len(triangles):,} | {mb['obj']:.1f} | {mb['glb']:.1f} | "
                  f"{best['obj'][0]:.3f} | {best['glb'][0]:.3f} | "
                  f"{best['glb'][0] / best['obj'][0]:.3f} | {best['obj'][1]:.2f} | "
                  f"{best['glb'][1]:.2f} |")


if __name__ == "__main__":
    main()
