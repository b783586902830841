"""docs/blender.png: a Blender render (Workbench, headless) of Suzanne and the Stanford bunny with
their kappa lines as Grease Pencil strokes, drawn by the add-on (blender/kappa_lines).
    blender -b --factory-startup --python scripts/blender-figure.py -- OUT.png [KAPPA_PYTHON_DIR [MESH_DIR]]
(defaults: docs/blender.png, build/python, ../shared/meshes)."""
import math
import os
import sys

import bpy
from mathutils import Vector

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
out = os.path.abspath(args[0] if args else os.path.join(ROOT, "docs/blender.png"))
module_dir = args[1] if len(args) > 1 else os.path.join(ROOT, "build/python")
mesh_dir = args[2] if len(args) > 2 else os.path.join(ROOT, "../shared/meshes")

sys.path.insert(0, os.path.join(ROOT, "blender"))
import kappa_lines  # noqa: E402
from kappa_lines import kappa_module  # noqa: E402

kappa_module.load(module_dir)
kappa_lines.register()

scene = bpy.context.scene
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

bpy.ops.mesh.primitive_monkey_add(location=(0.55, 1.0, 1.05), rotation=(0, 0, math.radians(-25)))
monkey = bpy.context.active_object
monkey.modifiers.new("subdivision", "SUBSURF").levels = 2
bpy.ops.object.shade_smooth()
bpy.ops.import_mesh.ply(filepath=os.path.join(mesh_dir, "bunny.ply"))
bunny = bpy.context.selected_objects[0]
bunny.rotation_euler = (math.radians(90), 0, math.radians(10))
bunny.scale = (12, 12, 12)
bunny.location = (-0.5, -0.3, -0.4)
bpy.ops.object.shade_smooth()

cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(cam)
cam.data.lens = 62
cam.location = (0.6, -7.4, 2.6)
cam.rotation_euler = (Vector((0.25, 0, 0.95)) - cam.location).to_track_quat("-Z", "Y").to_euler()
scene.camera = cam

scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 960, 600, 100
for obj in bpy.context.view_layer.objects:
    obj.select_set(obj in (monkey, bunny))
props = scene.kappa_lines
props.line_width = 2.5
print(bpy.ops.kappa.draw_lines())

scene.render.engine = "BLENDER_WORKBENCH"
shading = scene.display.shading
shading.light, shading.color_type = "STUDIO", "SINGLE"
shading.single_color = (0.8, 0.78, 0.74)
scene.world.color = (1, 1, 1)
scene.view_settings.view_transform = "Standard"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
print("wrote", out)
