#!/usr/bin/env python3
"""Writes the bundled cornell_spheres scene as OBJ + MTL, every vertex translated by (D, D, D)
and printed with 17 significant digits (a double exactly), for issue 23 item 2's measurement:
the same scene at the origin and 10^k away, rendered with the camera moved alike.

    cornell_spheres_obj.py D OUT_DIR     -> OUT_DIR/cornell_spheres.obj, .mtl, camera.txt

camera.txt holds the --eye/--target/--fov arguments (the scene's camera plus D, also %.17g).
The spheres are icospheres of 5 subdivisions computed here in double (the C++ generator's
construction: the 12 icosahedron vertices, midpoints pushed to the unit sphere), smooth-shaded.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scenes"))
import generate_scenes as g  # noqa: E402


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


def main():
    d = float(sys.argv[1])
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    scene = g.cornell_spheres()
    fmt = "%.17g"
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
    lines = ["mtllib cornell_spheres.mtl"]
    nv = nn = 0
    sphere_v, sphere_f = icosphere(5)
    for obj in scene["objects"]:
        mesh = scene["meshes"][obj["mesh"]]
        xf = obj["transform"]
        s = xf["scale"]
        tr = xf.get("translate", [0.0, 0.0, 0.0])
        lines.append(f"usemtl {obj['material']}")
        if mesh["type"] == "sphere":
            for p in sphere_v:
                lines.append("v " + " ".join(fmt % (s * c + t + d) for c, t in zip(p, tr)))
            for p in sphere_v:
                lines.append("vn " + " ".join(fmt % c for c in p))
            for a, b, c in sphere_f:
                lines.append("f " + " ".join(f"{nv + i + 1}//{nn + i + 1}" for i in (a, b, c)))
            nv += len(sphere_v)
            nn += len(sphere_v)
        else:
            for p in mesh["vertices"]:
                lines.append("v " + " ".join(fmt % (s * c + t + d) for c, t in zip(p, tr)))
            for q in mesh["quads"]:
                lines.append("f " + " ".join(str(nv + i + 1) for i in q))
            nv += len(mesh["vertices"])
    with open(os.path.join(out, "cornell_spheres.obj"), "w") as obj:
        obj.write("\n".join(lines) + "\n")
    cam = scene["camera"]
    with open(os.path.join(out, "camera.txt"), "w") as c:
        c.write("--eye %s --target %s --fov %r\n" % (
            ",".join(fmt % (x + d) for x in cam["eye"]),
            ",".join(fmt % (x + d) for x in cam["target"]), cam["fov"]))


if __name__ == "__main__":
    main()
