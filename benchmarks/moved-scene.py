#!/usr/bin/env python3
"""BENCHMARKS.md table `moved-scene`: a scene moved far from the origin with its camera renders the
image it renders at the origin (docs/stress.md, "Camera-relative world").

    benchmarks/moved-scene.py [RENDER FLAGS...]   e.g. --backend vulkan --vk-mode pipeline

cornell_spheres (scenes/generate_scenes.py) is written as OBJ + MTL with every vertex moved by
(d, d, d), d = 0, 1e2, 1e4, 1e6, and printed with 17 significant digits (the double exactly;
the spheres are icospheres of 5 subdivisions computed here in double), the camera moved alike
through --eye/--target. Each is rendered at 64x64, 256 spp, max depth 1000, with seeds 1 and 2
($TWINPATH, default build/bin/twinpath), and every moved render is compared with the origin's:
the same seed with `compare --exact` (expected: equal but for the rounding of the decimal
coordinates), seed 2 with `compare` (expected: consistent). Prints the table.
"""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scenes"))
import generate_scenes  # noqa: E402

FMT = "%.17g"


def icosphere(subdivisions):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(p):
        n = math.sqrt(sum(c * c for c in p))
        return tuple(c / n for c in p)

    v = [unit(p) for p in v]
    for _ in range(subdivisions):
        mid = {}

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                v.append(unit(tuple(x + y for x, y in zip(v[a], v[b]))))
                mid[key] = len(v) - 1
            return mid[key]

        nf = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return v, f


def write_scene(d, out):
    """cornell_spheres moved by (d, d, d) as OUT/cornell_spheres.obj and .mtl; its camera flags."""
    scene = generate_scenes.cornell_spheres()
    with open(os.path.join(out, "cornell_spheres.mtl"), "w") as mtl:
        for name, m in scene["materials"].items():
            mtl.write(f"newmtl {name}\n")
            if "Kd" in m:
                mtl.write("Kd %r %r %r\n" % tuple(m["Kd"]))
            if "Ke" in m:
                mtl.write("Ke %r %r %r\n" % tuple(m["Ke"]))
            if m["type"] == "mirror":
                mtl.write("Ks %r %r %r\nillum 3\n" % tuple(m["Ks"]))
            if m["type"] == "dielectric":
                mtl.write("Ni %r\nTf %r %r %r\nillum 7\n" % (m["Ni"], *m["Tf"]))
    lines, nv, nn = ["mtllib cornell_spheres.mtl"], 0, 0
    sphere_v, sphere_f = icosphere(5)
    for obj in scene["objects"]:
        mesh = scene["meshes"][obj["mesh"]]
        s, tr = obj["transform"]["scale"], obj["transform"].get("translate", [0.0, 0.0, 0.0])
        move = lambda p: "v " + " ".join(FMT % (s * c + t + d) for c, t in zip(p, tr))
        lines.append(f"usemtl {obj['material']}")
        if mesh["type"] == "sphere":
            lines += [move(p) for p in sphere_v]
            lines += ["vn " + " ".join(FMT % c for c in p) for p in sphere_v]
            lines += ["f " + " ".join(f"{nv + i + 1}//{nn + i + 1}" for i in t) for t in sphere_f]
            nv, nn = nv + len(sphere_v), nn + len(sphere_v)
        else:
            lines += [move(p) for p in mesh["vertices"]]
            lines += ["f " + " ".join(str(nv + i + 1) for i in q) for q in mesh["quads"]]
            nv += len(mesh["vertices"])
    with open(os.path.join(out, "cornell_spheres.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")
    cam = scene["camera"]
    return ["--eye", ",".join(FMT % (x + d) for x in cam["eye"]),
            "--target", ",".join(FMT % (x + d) for x in cam["target"]), "--fov", repr(cam["fov"])]


def main():
    twinpath = os.environ.get("TWINPATH", os.path.join(ROOT, "build/bin/twinpath"))
    flags = sys.argv[1:]
    with tempfile.TemporaryDirectory() as tmp:
        for d in ("0", "1e2", "1e4", "1e6"):
            folder = os.path.join(tmp, d)
            os.makedirs(folder)
            camera = write_scene(float(d), folder)
            for seed in ("1", "2"):
                subprocess.run([twinpath, "render", os.path.join(folder, "cornell_spheres.obj"),
                                *camera, "--width", "64", "--height", "64", "--spp", "256",
                                "--max-depth", "1000", "--seed", seed,
                                "-o", os.path.join(tmp, f"d{d}-s{seed}.exr"), *flags],
                               check=True, capture_output=True)

        def compare(*args):
            r = subprocess.run([twinpath, "compare", *args], capture_output=True, text=True)
            return (r.stdout + r.stderr).splitlines()[0]

        print("| moved by | same seed (`compare --exact`) | seed 2 (`compare`) |\n|---|---|---|")
        for d in ("1e2", "1e4", "1e6"):
            exact = compare("--exact", os.path.join(tmp, "d0-s1.exr"), os.path.join(tmp, f"d{d}-s1.exr"))
            stat = compare(os.path.join(tmp, "d0-s1.exr"), os.path.join(tmp, f"d{d}-s2.exr"))
            print(f"| {d} | {exact} | {stat} |")


if __name__ == "__main__":
    main()
