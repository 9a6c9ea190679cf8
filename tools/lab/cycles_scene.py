# Renders a twinpath bench scene with Blender's Cycles on the CPU (tools/lab/peer_cycles.h):
#   blender -b --factory-startup -noaudio --python-exit-code 2 -P cycles_scene.py -- \
#       SCENE.json OUT.exr SPP SEED THREADS
# (THREADS 0: every core).
# SCENE.json (written by peer_cycles.cpp) names the OBJ of the world-space triangles (one material
# per `usemtl mK`), the materials, lights, environment, camera, film and path length. Everything
# that would make Cycles compute a different estimator than a plain path tracer is off: adaptive
# sampling, denoising, light clamping, caustic filtering; the pixel filter is a 1-pixel box, as
# twinpath's. Materials are the nearest Cycles closures (see material()), so the images are close
# to twinpath's but not equal: each renderer is judged against its own converged render.
import json
import math
import sys

import bpy
from mathutils import Matrix, Vector

argv = sys.argv[sys.argv.index("--") + 1:]
scene_file, out_file, spp, seed, threads = argv[0], argv[1], int(argv[2]), int(argv[3]), int(argv[4])
desc = json.load(open(scene_file))

for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
scene = bpy.context.scene


def material(m):
    mat = bpy.data.materials.new(m["name"])
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    kind = m["type"]
    if kind == "mirror":
        shader = nodes.new("ShaderNodeBsdfGlossy")
        shader.distribution = "SHARP"
        shader.inputs["Color"].default_value = (*m["ks"], 1.0)
    elif kind == "dielectric":
        shader = nodes.new("ShaderNodeBsdfGlass")
        shader.distribution = "SHARP"
        shader.inputs["Color"].default_value = (*m["tf"], 1.0)
        shader.inputs["IOR"].default_value = m["ior"]
    else:
        # Modified Phong: Lambert with Kd plus a Beckmann lobe with Ks whose roughness matches the
        # Phong exponent (Walter et al. 2007, sec. 5.2: alpha_b = sqrt(2 / (n + 2)); Cycles'
        # roughness r is alpha = r^2).
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (*m["kd"], 1.0)
        if m.get("texture"):
            tex = nodes.new("ShaderNodeTexImage")
            tex.image = bpy.data.images.load(m["texture"])
            tex.image.colorspace_settings.name = "Non-Color"  # linear texels, as twinpath's
            tex.interpolation = "Closest"
            links.new(tex.outputs["Color"], diffuse.inputs["Color"])
        shader = diffuse
        if max(m["ks"]) > 0.0:
            glossy = nodes.new("ShaderNodeBsdfGlossy")
            glossy.distribution = "BECKMANN"
            glossy.inputs["Color"].default_value = (*m["ks"], 1.0)
            glossy.inputs["Roughness"].default_value = (2.0 / (m["ns"] + 2.0)) ** 0.25
            add = nodes.new("ShaderNodeAddShader")
            links.new(diffuse.outputs[0], add.inputs[0])
            links.new(glossy.outputs[0], add.inputs[1])
            shader = add
    if max(m["ke"]) > 0.0:
        # Front-face emission of radiance Ke: black seen from the back.
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = (*m["ke"], 1.0)
        emit.inputs["Strength"].default_value = 1.0
        add = nodes.new("ShaderNodeAddShader")
        links.new(shader.outputs[0], add.inputs[0])
        links.new(emit.outputs[0], add.inputs[1])
        geometry = nodes.new("ShaderNodeNewGeometry")
        back = nodes.new("ShaderNodeMixShader")
        links.new(geometry.outputs["Backfacing"], back.inputs["Fac"])
        links.new(add.outputs[0], back.inputs[1])
        links.new(shader.outputs[0], back.inputs[2])
        shader = back
    links.new(shader.outputs[0], out.inputs["Surface"])
    return mat


materials = {m["name"]: material(m) for m in desc["materials"]}

# The OBJ is in the scene's own axes: identity import (no Y-up to Z-up turn).
bpy.ops.wm.obj_import(filepath=desc["obj"], forward_axis="Y", up_axis="Z")
for obj in bpy.context.selected_objects:
    for slot in obj.material_slots:
        name = slot.material.name.split(".")[0] if slot.material else None
        if name in materials:
            slot.material = materials[name]
    if obj.type == "MESH":
        for poly in obj.data.polygons:
            poly.use_smooth = obj.data.has_custom_normals

for i, light in enumerate(desc["lights"]):
    if light["type"] == "point":
        data = bpy.data.lights.new(f"point{i}", "POINT")
        data.shadow_soft_size = 0.0
        # Cycles' point light of power P has radiant intensity P / (4 pi) W/sr per unit colour.
        power = max(light["value"])
        data.energy = 4.0 * math.pi * power
        data.color = [c / power for c in light["value"]]
        obj = bpy.data.objects.new(f"point{i}", data)
        obj.location = light["position"]
    else:
        data = bpy.data.lights.new(f"sun{i}", "SUN")
        data.angle = 0.0
        power = max(light["value"])
        data.energy = power  # irradiance, W/m^2
        data.color = [c / power for c in light["value"]]
        obj = bpy.data.objects.new(f"sun{i}", data)
        # A sun shines along its -Z: turn -Z onto the direction the light travels.
        obj.rotation_euler = (-Vector(light["direction"])).to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(obj)

world = bpy.data.worlds.new("world")
world.use_nodes = True
background = world.node_tree.nodes["Background"]
background.inputs["Color"].default_value = (*desc["environment"], 1.0)
background.inputs["Strength"].default_value = 1.0
scene.world = world

cam = desc["camera"]
camera = bpy.data.cameras.new("camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = math.radians(cam["fov_y"])
camera.clip_start = 1e-4
camera.clip_end = 1e6
camera_obj = bpy.data.objects.new("camera", camera)
forward = Vector(cam["forward"]).normalized()
right = forward.cross(Vector(cam["up"])).normalized()
up = right.cross(forward)
rotation = Matrix((right, up, -forward)).transposed()  # columns: camera x, y, z in the world
camera_obj.matrix_world = Matrix.Translation(Vector(cam["eye"])) @ rotation.to_4x4()
scene.collection.objects.link(camera_obj)
scene.camera = camera_obj

scene.render.engine = "CYCLES"
c = scene.cycles
c.device = "CPU"
c.samples = spp
c.seed = seed
c.use_adaptive_sampling = False
c.use_denoising = False
c.use_preview_denoising = False
c.sample_clamp_direct = 0.0
c.sample_clamp_indirect = 0.0
c.blur_glossy = 0.0
c.caustics_reflective = True
c.caustics_refractive = True
c.max_bounces = desc["max_depth"]
c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = desc["max_depth"]
c.transparent_max_bounces = c.volume_bounces = desc["max_depth"]
c.min_light_bounces = 0
c.min_transparent_bounces = 0
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
c.use_auto_tile = False
if threads > 0:
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
scene.render.resolution_x, scene.render.resolution_y = desc["width"], desc["height"]
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = out_file
scene.render.use_file_extension = False
bpy.ops.render.render(write_still=True)
