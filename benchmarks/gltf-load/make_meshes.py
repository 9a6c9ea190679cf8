#!/usr/bin/env python3
"""Writes one triangle mesh as a plain OBJ and as a GLB with the same data, for the load-time
benchmark (run.py): positions as float32 (the OBJ prints them with the 9 significant digits that
identify a float) and triangles as uint32 indices, no normals, uvs or materials in either.

    make_meshes.py MESH.ply OUT_DIR NAME [--split]

MESH.ply is an ASCII PLY of vertices (x y z) and faces (a count then indices, triangulated as a
fan). --split replaces every triangle by four (edge midpoints), as a larger mesh of the same
shape. Writes OUT_DIR/NAME.obj and OUT_DIR/NAME.glb and prints the triangle count."""
import json
import struct
import sys


def read_ply(path):
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline().decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
        if "format ascii 1.0" not in header:
            sys.exit(f"{path}: only ASCII PLY is read")
        counts = {l.split()[1]: int(l.split()[2]) for l in header if l.startswith("element")}
        lines = f.read().split(b"\n")
    vertices = [tuple(float(v) for v in lines[i].split()[:3]) for i in range(counts["vertex"])]
    triangles = []
    for line in lines[counts["vertex"]:counts["vertex"] + counts["face"]]:
        face = [int(v) for v in line.split()]
        for k in range(2, face[0]):
            triangles.append((face[1], face[k], face[k + 1]))
    return vertices, triangles


def split(vertices, triangles):
    vertices = list(vertices)
    midpoint = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            midpoint[key] = len(vertices)
            vertices.append(tuple((p + q) / 2 for p, q in zip(vertices[a], vertices[b])))
        return midpoint[key]
    out = []
    for a, b, c in triangles:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return vertices, out


def main():
    ply, out, name = sys.argv[1], sys.argv[2], sys.argv[3]
    vertices, triangles = read_ply(ply)
    if "--split" in sys.argv[4:]:
        vertices, triangles = split(vertices, triangles)
    positions = struct.pack(f"<{3 * len(vertices)}f", *[c for v in vertices for c in v])
    floats = struct.unpack(f"<{3 * len(vertices)}f", positions)  # as float32, exactly
    with open(f"{out}/{name}.obj", "w") as f:
        for i in range(0, len(floats), 3):
            f.write("v %.9g %.9g %.9g\n" % floats[i:i + 3])
        for a, b, c in triangles:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")
    indices = struct.pack(f"<{3 * len(triangles)}I", *[i for t in triangles for i in t])
    lo = [min(floats[k::3]) for k in range(3)]
    hi = [max(floats[k::3]) for k in range(3)]
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(vertices),
                          "type": "VEC3", "min": lo, "max": hi},
                         {"bufferView": 1, "componentType": 5125, "count": 3 * len(triangles),
                          "type": "SCALAR"}],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                           {"buffer": 0, "byteOffset": len(positions),
                            "byteLength": len(indices)}],
           "buffers": [{"byteLength": len(positions) + len(indices)}]}
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    data = positions + indices  # both multiples of 4 bytes
    with open(f"{out}/{name}.glb", "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(data)))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(data), 0x004E4942) + data)
    print(len(triangles))


if __name__ == "__main__":
    main()
