#!/usr/bin/env python3
"""Writes the bundled scenes (scenes/*.json) from the data below; `make test` checks that the
committed files are what this script writes.

cornell, cornell_glossy: the Cornell box from the measurements published by the Cornell
University Program of Computer Graphics ("Cornell Box Data": geometry in millimetres, y up,
camera at (278, 273, -800) looking down +z, focal length 35 mm on a 25 mm film, so the vertical
field of view is 2 atan(12.5 / 35) = 39.3077 degrees). The measured spectral reflectances are
represented by RGB values (white 0.725/0.71/0.68, red 0.63/0.065/0.05, green 0.14/0.45/0.091)
and the light by radiance (17, 12, 4): the values commonly used for RGB renderings of this box.

gltf_materials: a glTF 2.0 example (docs/scene-format.md, "glTF 2.0") of glTF's own material:
two rows of metallic-roughness spheres (one sphere mesh stored once), a floor with a base colour
(under KHR_texture_transform), metallic-roughness and normal texture, a leaf cut out of a quad by
its alpha (MASK) under a spot light, a blue pane with alpha BLEND, a glass sphere with
KHR_materials_volume absorption, an emissive panel whose stripes come from its second uv set,
a camera node and KHR_lights_punctual lights in photometric units; textures embedded as PNGs,
everything in one .gltf file.
"""
import base64
import json
import math
import os
import struct
import sys
import zlib

FLOOR = [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]
CEILING = [[556.0, 548.8, 0], [556.0, 548.8, 559.2], [0, 548.8, 559.2], [0, 548.8, 0]]
BACK = [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556.0, 548.8, 559.2]]
RIGHT = [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]  # green
LEFT = [[552.8, 0, 0], [549.6, 0, 559.2], [556.0, 548.8, 559.2], [556.0, 548.8, 0]]  # red
# In the data the light is a patch of the ceiling plane (y = 548.8). It is lowered by 0.5 mm
# so that light and ceiling never tie in an intersection test.
LIGHT = [[343.0, 548.3, 227.0], [343.0, 548.3, 332.0], [213.0, 548.3, 332.0], [213.0, 548.3, 227.0]]
SHORT_BLOCK = [
    [[130, 165, 65], [82, 165, 225], [240, 165, 272], [290, 165, 114]],
    [[290, 0, 114], [290, 165, 114], [240, 165, 272], [240, 0, 272]],
    [[130, 0, 65], [130, 165, 65], [290, 165, 114], [290, 0, 114]],
    [[82, 0, 225], [82, 165, 225], [130, 165, 65], [130, 0, 65]],
    [[240, 0, 272], [240, 165, 272], [82, 165, 225], [82, 0, 225]],
]
TALL_BLOCK = [
    [[423, 330, 247], [265, 330, 296], [314, 330, 456], [472, 330, 406]],
    [[423, 0, 247], [423, 330, 247], [472, 330, 406], [472, 0, 406]],
    [[472, 0, 406], [472, 330, 406], [314, 330, 456], [314, 0, 456]],
    [[314, 0, 456], [314, 330, 456], [265, 330, 296], [265, 0, 296]],
    [[265, 0, 296], [265, 330, 296], [423, 330, 247], [423, 0, 247]],
]
MM = {"scale": 0.001}


def quads(faces):
    vertices, indices = [], []
    for q in faces:
        base = len(vertices)
        vertices += q
        indices.append([base, base + 1, base + 2, base + 3])
    return {"type": "triangles", "vertices": vertices, "quads": indices}


def cornell_room(meshes, objects, materials):
    all_meshes = {"floor": quads([FLOOR]), "ceiling": quads([CEILING]), "back": quads([BACK]),
                  "right": quads([RIGHT]), "left": quads([LEFT]), "light": quads([LIGHT])}
    all_meshes.update(meshes)
    all_materials = {
        "white": {"type": "phong", "Kd": [0.725, 0.71, 0.68]},
        "red": {"type": "phong", "Kd": [0.63, 0.065, 0.05]},
        "green": {"type": "phong", "Kd": [0.14, 0.45, 0.091]},
        "light": {"type": "phong", "Kd": [0.78, 0.78, 0.78], "Ke": [17.0, 12.0, 4.0]},
    }
    all_materials.update(materials)
    room = [{"mesh": m, "material": mat, "transform": MM} for m, mat in
            [("floor", "white"), ("ceiling", "white"), ("back", "white"), ("right", "green"),
             ("left", "red"), ("light", "light")]]
    return {
        "camera": {"eye": [0.278, 0.273, -0.8], "target": [0.278, 0.273, 0.0], "up": [0, 1, 0],
                   "fov": 39.3077},
        "film": {"width": 512, "height": 512},
        "render": {"spp": 64, "max_depth": 8, "min_depth": 3},
        "materials": all_materials,
        "meshes": all_meshes,
        "objects": room + objects,
    }


def cornell():
    return cornell_room(
        {"short_block": quads(SHORT_BLOCK), "tall_block": quads(TALL_BLOCK)},
        [{"mesh": "short_block", "material": "white", "transform": MM},
         {"mesh": "tall_block", "material": "white", "transform": MM}], {})


def cornell_glossy():
    # Five 90 mm Phong cubes, exponents 1 to 10^4, Kd + Ks = 0.9.
    objects, materials = [], {}
    for k, ns in enumerate([1, 10, 100, 1000, 10000]):
        name = f"phong_{ns}"
        materials[name] = {"type": "phong", "Kd": [0.1, 0.1, 0.1], "Ks": [0.8, 0.8, 0.8], "Ns": ns}
        objects.append({"name": name, "mesh": "cube", "material": name, "transform": {
            "translate": [0.08 + 0.1 * k, 0.045, 0.30 + 0.04 * (k % 2)],
            "rotate": {"axis": [0, 1, 0], "degrees": 25}, "scale": 0.045}})
    return cornell_room({"cube": {"type": "box"}}, objects, materials)


def cornell_spheres():
    # The caustic scene: the empty box with a mirror sphere (back, left in the image) and a
    # glass sphere (front, right), 100 mm in radius, lit only by the box's small light. Light
    # reaches the floor and walls through the glass and off the mirror, and a path tracer finds
    # those paths only when a BSDF-sampled direction happens to hit the light through the
    # specular chain (next-event estimation cannot see the light through glass): rare, large
    # samples, the heavy-tailed pixel estimates compare must stay calibrated on
    # (docs/compare.md). Glass needs many bounces, hence the high maximum depth; Russian
    # roulette ends paths long before it.
    scene = cornell_room(
        {"ball": {"type": "sphere", "subdivisions": 5}},
        [{"name": "mirror", "mesh": "ball", "material": "mirror",
          "transform": {"translate": [0.39, 0.1, 0.37], "scale": 0.1}},
         {"name": "glass", "mesh": "ball", "material": "glass",
          "transform": {"translate": [0.17, 0.1, 0.18], "scale": 0.1}}],
        {"mirror": {"type": "mirror", "Ks": [0.95, 0.95, 0.95]},
         "glass": {"type": "dielectric", "Ni": 1.5, "Tf": [1, 1, 1]}})
    scene["render"]["max_depth"] = 1000
    return scene


def spheres():
    # Mirror, glass and Phong spheres on a checkered floor, lit by a point light, a sun and a
    # dim sky.
    return {
        "camera": {"eye": [0, 1.6, 4.5], "target": [0, 0.45, 0], "up": [0, 1, 0], "fov": 40},
        "film": {"width": 512, "height": 384},
        "render": {"spp": 64, "max_depth": 10, "min_depth": 3},
        "textures": {"checker": {"generator": "checker", "size": 512, "checks": 16,
                                 "colors": [[0.8, 0.8, 0.8], [0.15, 0.15, 0.15]]}},
        "materials": {
            "floor": {"type": "phong", "Kd": [1, 1, 1], "map_Kd": "checker"},
            "mirror": {"type": "mirror", "Ks": [0.95, 0.95, 0.95]},
            "glass": {"type": "dielectric", "Ni": 1.5, "Tf": [1, 1, 1]},
            "phong": {"type": "phong", "Kd": [0.35, 0.1, 0.05], "Ks": [0.5, 0.5, 0.5], "Ns": 200},
        },
        "meshes": {"floor": {"type": "quad"}, "ball": {"type": "sphere", "subdivisions": 5}},
        "objects": [
            {"mesh": "floor", "material": "floor", "transform": {"scale": 4}},
            {"name": "mirror", "mesh": "ball", "material": "mirror",
             "transform": {"translate": [-1.2, 0.5, 0], "scale": 0.5}},
            {"name": "glass", "mesh": "ball", "material": "glass",
             "transform": {"translate": [0, 0.5, 0.3], "scale": 0.5}},
            {"name": "phong", "mesh": "ball", "material": "phong",
             "transform": {"translate": [1.2, 0.5, 0], "scale": 0.5}},
        ],
        "lights": [
            {"type": "point", "position": [1.5, 3.0, 2.0], "intensity": [12, 12, 12]},
            {"type": "directional", "direction": [-0.4, -1.0, -0.3], "irradiance": [2.0, 1.9, 1.7]},
        ],
        "environment": {"type": "constant", "radiance": [0.10, 0.12, 0.15]},
    }


def furnace(rho=0.8):
    # A closed sphere that emits radiance 1 everywhere inwards and reflects diffusely with
    # albedo rho: L = 1 + rho L, so every pixel is exactly 1 / (1 - rho). Flat-shaded: with
    # interpolated normals, directions sampled about the shading normal that fall below a
    # facet are lost, and the image comes out ~1 % dark at rho = 0.95.
    return {
        "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "up": [0, 1, 0], "fov": 90},
        "film": {"width": 64, "height": 64},
        "render": {"spp": 64, "max_depth": 100000, "min_depth": 0},
        "materials": {"wall": {"type": "phong", "Kd": [rho] * 3, "Ke": [1, 1, 1]}},
        "meshes": {"room": {"type": "sphere", "subdivisions": 3, "inward": True, "smooth": False}},
        "objects": [{"mesh": "room", "material": "wall"}],
    }


def png_stored(width, height, rgb_rows, channels=3):
    """An 8-bit RGB (or, with channels=4, RGBA) PNG whose zlib stream uses stored (uncompressed)
    deflate blocks, so that its bytes do not depend on the zlib version."""
    raw = b"".join(b"\0" + bytes(row) for row in rgb_rows)
    blocks = b""
    for i in range(0, len(raw), 65535):
        part = raw[i:i + 65535]
        final = 1 if i + 65535 >= len(raw) else 0
        blocks += struct.pack("<BHH", final, len(part), 0xFFFF ^ len(part)) + part
    stream = b"\x78\x01" + blocks + struct.pack(">I", zlib.adler32(raw))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data)))
    header = struct.pack(">IIBBBBB", width, height, 8, 2 if channels == 3 else 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", stream) +
            chunk(b"IEND", b""))


def uv_sphere(segments=32, rings=16):
    """Unit sphere: positions, normals (the same vectors) and counter-clockwise triangles seen
    from outside. Coordinates are rounded to 6 decimals so that the file does not depend on the
    last bit of the C library's sin and cos."""
    points, tris = [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            points.append([round(math.sin(theta) * math.sin(phi), 6), round(math.cos(theta), 6),
                           round(math.sin(theta) * math.cos(phi), 6)])
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            if r > 0:
                tris.append([a, b, a + 1])
            if r < rings - 1:
                tris.append([a + 1, b, b + 1])
    return points, tris


def turn_minus_z_to(d):
    """The unit quaternion [x, y, z, w] of the shortest rotation that turns -z (where glTF
    cameras look and lights shine) to the direction d, rounded to 9 decimals."""
    n = math.sqrt(sum(c * c for c in d))
    d = [c / n for c in d]
    q = [d[1], -d[0], 0.0, 1.0 - d[2]]  # (cross(-z, d), 1 + dot(-z, d))
    n = math.sqrt(sum(c * c for c in q))
    return [round(c / n, 9) + 0.0 for c in q]


def tile_height(u, v):
    """Height field of the floor's normal map: raised tiles with bevelled grout between them,
    4 tiles per texture, periodic in u and v."""
    def bevel(t):
        d = abs((t * 4.0) % 1.0 - 0.5)  # 0.5 at a tile's centre line, 0 on the grout
        return min(1.0, max(0.0, (0.5 - d) / 0.08))
    return min(bevel(u + 0.5 / 4), bevel(v + 0.5 / 4))


def floor_images(n=64):
    """Base colour (RGB), metallic-roughness (G roughness, B metallic) and tangent-space normal
    rows of the floor, n x n."""
    color, mr, normal = [], [], []
    for y in range(n):
        crow, mrow, nrow = [], [], []
        for x in range(n):
            u, v = (x + 0.5) / n, (y + 0.5) / n
            tile = (x * 4 // n + y * 4 // n) % 2
            crow += [200, 196, 186] if tile == 0 else [70, 74, 90]
            mrow += [255, 80 if tile == 0 else 230, 0]
            # n = normalize(-dh/du, -dh/dv, 1/k): tangent x along +u, bitangent y along +v.
            e = 0.5 / n
            du = (tile_height(u + e, v) - tile_height(u - e, v)) / (2 * e)
            dv = (tile_height(u, v + e) - tile_height(u, v - e)) / (2 * e)
            k = 0.04
            vec = [-du * k, -dv * k, 1.0]
            length = math.sqrt(sum(c * c for c in vec))
            nrow += [round(255 * (0.5 + 0.5 * c / length)) for c in vec]
        color.append(crow)
        mr.append(mrow)
        normal.append(nrow)
    return color, mr, normal


def leaf_image(n=64):
    """An RGBA leaf: an ellipse (alpha 255 inside, 0 outside) with a darker midrib, pointing
    along +v."""
    rows = []
    for y in range(n):
        row = []
        for x in range(n):
            u, v = (x + 0.5) / n * 2 - 1, (y + 0.5) / n * 2 - 1
            inside = (u / 0.45) ** 2 + (v / 0.95) ** 2 <= 1.0 or (abs(u) < 0.04 and v > 0.8)
            rib = abs(u) < 0.04 or abs(abs(u) - (0.9 - abs(v)) * 0.3) < 0.03
            green = [40, 110, 30] if rib else [70, 160, 45]
            row += green + [255 if inside else 0]
        rows.append(row)
    return rows


def gltf_materials():
    buffer = bytearray()
    views, accessors = [], []

    def add(data, kind, component, count, extra=None):
        while len(buffer) % 4:
            buffer.append(0)
        views.append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(data)})
        buffer.extend(data)
        accessor = {"bufferView": len(views) - 1, "componentType": component, "count": count,
                    "type": kind}
        accessor.update(extra or {})
        accessors.append(accessor)
        return len(accessors) - 1

    def vec3s(points):
        lo = [min(p[k] for p in points) for k in range(3)]
        hi = [max(p[k] for p in points) for k in range(3)]
        return add(b"".join(struct.pack("<3f", *p) for p in points), "VEC3", 5126, len(points),
                   {"min": lo, "max": hi})

    def vec2s(points):
        return add(b"".join(struct.pack("<2f", *p) for p in points), "VEC2", 5126, len(points))

    def indices(tris):
        flat = [i for t in tris for i in t]
        return add(struct.pack(f"<{len(flat)}H", *flat), "SCALAR", 5123, len(flat))

    def png_uri(png):
        return "data:image/png;base64," + base64.b64encode(png).decode()

    points, tris = uv_sphere()
    sphere = {"POSITION": vec3s(points), "NORMAL": vec3s(points)}
    sphere_indices = indices(tris)
    quad = [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]  # facing +y
    up = [[0, 1, 0]] * 4
    quad_indices = indices([[0, 1, 2], [0, 2, 3]])
    # The floor: glTF's uv (0, 0) is the image's top-left corner; 4 repeats across the floor.
    # No TANGENT: twinpath generates the normal map's tangents (docs/scene-format.md).
    floor_attrs = {"POSITION": vec3s(quad), "NORMAL": vec3s(up),
                   "TEXCOORD_0": vec2s([[0, 0], [0, 4], [4, 4], [4, 0]])}
    # The panel and the pane: uv set 0 over the quad, set 1 three stripes' periods across it.
    panel_attrs = {"POSITION": floor_attrs["POSITION"],
                   "TEXCOORD_0": vec2s([[0, 0], [0, 1], [1, 1], [1, 0]]),
                   "TEXCOORD_1": vec2s([[0, 0], [0, 1], [3, 1], [3, 0]])}
    color, mr, normal = floor_images()
    stripes = [[255, 240, 220] * 4 + [40, 30, 20] * 4 for _ in range(2)]
    images = [png_stored(64, 64, color), png_stored(64, 64, mr), png_stored(64, 64, normal),
              png_stored(64, 64, leaf_image(), channels=4), png_stored(8, 2, stripes)]

    materials = [
        {"name": "floor", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {
                "offset": [0.125, 0.0], "rotation": 0.1, "scale": [1.0, 1.0]}}},
            "metallicRoughnessTexture": {"index": 1},
            "metallicFactor": 1.0, "roughnessFactor": 1.0},
         "normalTexture": {"index": 2, "scale": 1.0}},
        {"name": "panel", "emissiveFactor": [1.0, 0.9, 0.8],
         "emissiveTexture": {"index": 4, "texCoord": 1},
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 6.0}},
         "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0}},
        # Glass with a volume: it refracts and absorbs, reddish over a 0.5 m path.
        {"name": "glass", "pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 0.0},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                        "KHR_materials_ior": {"ior": 1.5},
                        "KHR_materials_volume": {"thicknessFactor": 0.6,
                                                 "attenuationColor": [0.95, 0.6, 0.5],
                                                 "attenuationDistance": 0.5}}},
        {"name": "leaf", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 3}, "metallicFactor": 0.0,
                                  "roughnessFactor": 0.6}},
        {"name": "pane", "alphaMode": "BLEND", "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.3, 1.0, 0.5],
                                  "metallicFactor": 0.0, "roughnessFactor": 0.2}},
    ]

    def mesh(name, attrs, index, material):
        return {"name": name, "primitives": [{"attributes": attrs, "indices": index,
                                              "material": material}]}
    meshes = [mesh("floor", floor_attrs, quad_indices, 0),
              mesh("panel", panel_attrs, quad_indices, 1),
              mesh("glass", sphere, sphere_indices, 2),
              mesh("leaf", {"POSITION": floor_attrs["POSITION"], "NORMAL": floor_attrs["NORMAL"],
                            "TEXCOORD_0": panel_attrs["TEXCOORD_0"]}, quad_indices, 3),
              mesh("pane", {"POSITION": floor_attrs["POSITION"]}, quad_indices, 4)]
    nodes = [{"name": "floor", "mesh": 0, "scale": [4, 1, 4]},
             # The panel faces down: turned 180 degrees about x.
             {"name": "panel", "mesh": 1, "translation": [0, 3, 0.5], "rotation": [1, 0, 0, 0],
              "scale": [1.5, 1, 0.5]},
             {"name": "glass", "mesh": 2, "translation": [1.5, 0.3, 1.6], "scale": [0.3] * 3},
             # The leaf floats above the floor's front left, tilted, under the spot light.
             {"name": "leaf", "mesh": 3, "translation": [-1.2, 0.9, 2.2],
              "rotation": [0.0871557, 0.0, 0.0, 0.9961947], "scale": [0.3, 1, 0.3]},
             # The pane stands upright in front of the plastic row, facing the camera.
             {"name": "pane", "mesh": 4, "translation": [0.5, 0.45, 1.8],
              "rotation": [0.7071068, 0.0, 0.0, 0.7071068], "scale": [0.45, 1, 0.45]}]
    # Two rows of spheres: plastic (metallic 0) and gold-coloured metal (metallic 1), roughness
    # 0 to 1 from left to right. Each material needs its own glTF mesh; they all name the same
    # accessors, and twinpath stores the sphere once.
    for row, (metallic, color, z) in enumerate([(0.0, [0.8, 0.1, 0.05, 1], 0.5),
                                                (1.0, [1.0, 0.78, 0.34, 1], -0.7)]):
        for k, roughness in enumerate([0.0, 0.25, 0.5, 0.75, 1.0]):
            materials.append({"name": f"{'metal' if metallic else 'plastic'}_{roughness}",
                              "pbrMetallicRoughness": {"baseColorFactor": color,
                                                       "metallicFactor": metallic,
                                                       "roughnessFactor": roughness}})
            meshes.append(mesh(materials[-1]["name"], sphere, sphere_indices,
                               len(materials) - 1))
            nodes.append({"name": materials[-1]["name"], "mesh": len(meshes) - 1,
                          "translation": [-2.0 + k, 0.4, z], "scale": [0.4] * 3})
    # The camera at (0, 3.4, 5.5) looks at (0, 0.2, -0.2); the sun shines from (3, 5, 2); the
    # spot light hangs above the leaf.
    nodes.append({"name": "camera", "camera": 0, "translation": [0, 3.4, 5.5],
                  "rotation": turn_minus_z_to([0, -3.2, -5.7])})
    nodes.append({"name": "sun", "rotation": turn_minus_z_to([-3, -5, -2]),
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"name": "spot", "translation": [-1.1, 3.0, 2.3],
                  "rotation": turn_minus_z_to([0.05, -1, -0.05]),
                  "extensions": {"KHR_lights_punctual": {"light": 1}}})
    return {
        "asset": {"version": "2.0", "generator": "twinpath scenes/generate_scenes.py"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength",
                           "KHR_materials_ior", "KHR_materials_transmission",
                           "KHR_materials_volume", "KHR_texture_transform"],
        # Photometric units (docs/scene-format.md: 683 lm/W): a sun of 1000 lux is 1.46 W/m^2,
        # a spot of 20000 cd 29 W/sr.
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "sun", "type": "directional", "color": [1.0, 0.95, 0.85], "intensity": 1000},
            {"name": "spot", "type": "spot", "color": [1.0, 0.9, 0.7], "intensity": 20000,
             "spot": {"innerConeAngle": 0.25, "outerConeAngle": 0.45}}]}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.6, "aspectRatio": 1.5, "znear": 0.1}}],
        "meshes": meshes,
        "materials": materials,
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0},
                     {"source": 2, "sampler": 0}, {"source": 3, "sampler": 1},
                     {"source": 4, "sampler": 2}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497},
                     {"magFilter": 9729, "wrapS": 33071, "wrapT": 33071},
                     {"magFilter": 9728, "wrapS": 33648, "wrapT": 10497}],
        "images": [{"uri": png_uri(p)} for p in images],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," +
                            base64.b64encode(bytes(buffer)).decode()}],
    }


SCENES = {"cornell": cornell, "cornell_glossy": cornell_glossy,
          "cornell_spheres": cornell_spheres, "spheres": spheres, "furnace": furnace}


def encode(value, indent=0):
    """JSON with short number arrays kept on one line."""
    pad = "  " * indent
    if isinstance(value, dict):
        items = [f'{pad}  {json.dumps(k)}: {encode(v, indent + 1)}' for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list) and value and all(isinstance(v, (dict, list)) for v in value) \
            and not all(isinstance(v, list) and all(isinstance(x, (int, float)) for x in v) for v in value):
        return "[\n" + ",\n".join(pad + "  " + encode(v, indent + 1) for v in value) + "\n" + pad + "]"
    return json.dumps(value)


GLTF_SCENES = {"gltf_materials": gltf_materials}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for name, make in SCENES.items():
        with open(os.path.join(out, name + ".json"), "w") as f:
            f.write(encode(make()) + "\n")
    for name, make in GLTF_SCENES.items():
        with open(os.path.join(out, name + ".gltf"), "w") as f:
            f.write(encode(make()) + "\n")


if __name__ == "__main__":
    main()
