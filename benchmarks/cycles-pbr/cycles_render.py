"""Blender (bpy) script: imports the .glb with Blender's glTF importer and renders it with Cycles
as a reference: path tracing without the shortcuts that bias it (no light or caustic clamping,
no denoising, no adaptive sampling), a one-pixel box filter as twinpath's, Standard view, linear
float EXR.
    blender -b --factory-startup -P cycles_render.py -- IN.glb OUT.exr SPP THREADS
"""
import sys

import numpy as np

np.bool = bool  # Blender 3.4's glTF importer uses np.bool, gone from Debian 12's NumPy
import bpy  # noqa: E402

glb, out, spp, threads = sys.argv[sys.argv.index("--") + 1:][:4]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
scene = bpy.context.scene
scene.camera = next(o for o in scene.objects if o.type == "CAMERA")
scene.render.engine = "CYCLES"
c = scene.cycles
c.device = "CPU"
c.samples = int(spp)
c.use_adaptive_sampling = False
c.use_denoising = False
c.sample_clamp_direct = 0.0
c.sample_clamp_indirect = 0.0
c.caustics_reflective = True
c.caustics_refractive = True
c.blur_glossy = 0.0
c.max_bounces = 64
c.diffuse_bounces = 64
c.glossy_bounces = 64
c.transmission_bounces = 64
c.transparent_max_bounces = 64
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
scene.world = bpy.data.worlds.new("black")
scene.world.color = (0.0, 0.0, 0.0)
scene.render.threads_mode = "FIXED"
scene.render.threads = int(threads)
scene.render.resolution_x = 256
scene.render.resolution_y = 256
scene.render.resolution_percentage = 100
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
