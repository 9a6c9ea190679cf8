#!/usr/bin/env python3
"""Writes the bundled scenes (scenes/*.json) from the data below; `make test` checks that the
committed files are what this script writes.

cornell, cornell_glossy: the Cornell box from the measurements published by the Cornell
University Program of Computer Graphics ("Cornell Box Data": geometry in millimetres, y up,
camera at (278, 273, -800) looking down +z, focal length 35 mm on a 25 mm film, so the vertical
field of view is 2 atan(12.5 / 35) = 39.3077 degrees). The measured spectral reflectances are
represented by RGB values (white 0.725/0.71/0.68, red 0.63/0.065/0.05, green 0.14/0.45/0.091)
and the light by radiance (17, 12, 4): the values commonly used for RGB renderings of this box.
"""
import json
import os
import sys

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


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for name, make in SCENES.items():
        with open(os.path.join(out, name + ".json"), "w") as f:
            f.write(encode(make()) + "\n")


if __name__ == "__main__":
    main()
