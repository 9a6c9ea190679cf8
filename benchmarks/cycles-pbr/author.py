"""Blender (bpy) script: authors the comparison scene in Blender and exports it as glTF 2.0 (.glb)
with Blender's own exporter, the way a user's asset is made: a closed box with a ceiling light
(an emissive quad; glTF has no area light), five spheres of Principled BSDF materials (gold metal
roughness 0.3, copper 0.6, blue plastic 0.4, glossy white 0.15, clear glass) and a camera.
    blender -b --factory-startup -P author.py -- OUT.glb
"""
import math
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def material(name, color, metallic, roughness, transmission=0.0, ior=1.5, emission=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    p = m.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = (*color, 1.0)
    p.inputs["Metallic"].default_value = metallic
    p.inputs["Roughness"].default_value = roughness
    p.inputs["Transmission"].default_value = transmission
    p.inputs["IOR"].default_value = ior
    if emission:
        p.inputs["Emission"].default_value = (*emission[0], 1.0)
        p.inputs["Emission Strength"].default_value = emission[1]
    return m


def add(obj, mat):
    obj.data.materials.append(mat)
    return obj


white = material("walls", (0.73, 0.71, 0.68), 0.0, 1.0)
# The box, 2 m wide, open towards the camera (+y), its faces turned inwards.
bpy.ops.mesh.primitive_cube_add(size=2.0, location=(0, 0, 1))
box = add(bpy.context.object, white)
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.mesh.flip_normals()
bpy.ops.object.mode_set(mode="OBJECT")
# Delete the face towards the camera (normal -y before flipping: now +y... the face at y = -1).
mesh = box.data
front = [f.index for f in mesh.polygons if f.center.y < -0.99]
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="DESELECT")
bpy.ops.object.mode_set(mode="OBJECT")
for i in front:
    mesh.polygons[i].select = True
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.delete(type="FACE")
bpy.ops.object.mode_set(mode="OBJECT")
# The light: a quad just under the ceiling, facing down.
light = material("light", (0.0, 0.0, 0.0), 0.0, 1.0, emission=((1.0, 0.95, 0.85), 12.0))
bpy.ops.mesh.primitive_plane_add(size=0.6, location=(0, 0, 1.995), rotation=(math.pi, 0, 0))
add(bpy.context.object, light)

spheres = [
    ("gold", (1.0, 0.766, 0.336), 1.0, 0.3, 0.0, (-0.6, 0.3, 0.25)),
    ("copper", (0.955, 0.638, 0.538), 1.0, 0.6, 0.0, (0.0, 0.35, 0.25)),
    ("blue_plastic", (0.05, 0.15, 0.7), 0.0, 0.4, 0.0, (0.6, 0.3, 0.25)),
    ("glossy_white", (0.8, 0.8, 0.8), 0.0, 0.15, 0.0, (-0.35, -0.3, 0.25)),
    ("glass", (1.0, 1.0, 1.0), 0.0, 0.0, 1.0, (0.35, -0.3, 0.25)),
]
for name, color, metallic, roughness, transmission, at in spheres:
    bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=0.25, location=at)
    bpy.ops.object.shade_smooth()
    add(bpy.context.object, material(name, color, metallic, roughness, transmission))

cam = bpy.data.cameras.new("camera")
cam.lens_unit = "FOV"
cam.angle = math.radians(45.0)
cam_obj = bpy.data.objects.new("camera", cam)
scene.collection.objects.link(cam_obj)
cam_obj.location = (0.0, -3.3, 1.0)
cam_obj.rotation_euler = (math.pi / 2, 0.0, 0.0)
scene.camera = cam_obj
scene.render.resolution_x = 256
scene.render.resolution_y = 256

bpy.ops.export_scene.gltf(filepath=out, export_format="GLB", export_cameras=True,
                          export_lights=False, export_apply=True)
