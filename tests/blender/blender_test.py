"""Shared pieces of the add-on's tests, run inside Blender:
    blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_FILE.py
with KAPPA_PYTHON_DIR (the folder of kappa's module, build/python) and KAPPA_MESH_DIR in the
environment (tests/CMakeLists.txt sets both). Each test_ function of the file runs on an empty
scene; the process exits 1 when any fails."""
import math
import os
import sys
import time
import traceback

import bpy
import numpy as np
from bpy_extras.object_utils import world_to_camera_view
from mathutils import Vector

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../blender"))
MESH_DIR = os.environ.get("KAPPA_MESH_DIR", os.path.join(HERE, "../../../shared/meshes"))

import kappa_lines  # noqa: E402  (the add-on, from this checkout)
from kappa_lines import kappa_module  # noqa: E402

kappa_module.load(os.environ.get("KAPPA_PYTHON_DIR", ""))
kappa_lines.register()
kappa = kappa_module.module()
assert kappa is not None, kappa_module.problem()


def empty_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for gp in list(bpy.data.grease_pencils):
        bpy.data.grease_pencils.remove(gp)
    scene = bpy.context.scene
    props = scene.kappa_lines
    for p in props.bl_rna.properties:
        if p.identifier != "rna_type":
            props.property_unset(p.identifier)  # back to kappa's defaults
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 480, 360, 100
    scene.frame_set(1)
    return scene


def add_camera(scene, location, target, lens=50):
    data = bpy.data.cameras.new("camera")
    data.lens = lens
    cam = bpy.data.objects.new("camera", data)
    scene.collection.objects.link(cam)
    aim(cam, location, target)
    scene.camera = cam
    return cam


def aim(cam, location, target):
    cam.location = location
    cam.rotation_euler = (Vector(target) - Vector(location)).to_track_quat("-Z", "Y").to_euler()
    bpy.context.view_layer.update()


def select_only(*objects):
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in objects)
    if objects:
        bpy.context.view_layer.objects.active = objects[0]


def suzanne(scene, levels=2, location=(0, 0, 0)):
    bpy.ops.mesh.primitive_monkey_add(location=location)
    obj = bpy.context.active_object
    mod = obj.modifiers.new("subdivision", "SUBSURF")
    mod.levels = levels
    return obj


def import_ply(name):
    path = os.path.join(MESH_DIR, name)
    assert os.path.exists(path), f"missing shared mesh {path} (KAPPA_MESH_DIR)"
    bpy.ops.import_mesh.ply(filepath=path)
    return bpy.context.selected_objects[0]


def gp_strokes(frame_number=None):
    """The `kappa lines` object's strokes at a frame (default: the current one): {layer: [(points (n, 3),
    strength (n,), pressure (n,))]}."""
    obj = bpy.data.objects["kappa lines"]
    frame_number = bpy.context.scene.frame_current if frame_number is None else frame_number
    out = {}
    for layer in obj.data.layers:
        frames = [f for f in layer.frames if f.frame_number == frame_number]
        out[layer.info] = []
        for frame in frames:
            for s in frame.strokes:
                n = len(s.points)
                co, strength, pressure = (np.empty(n * 3, np.float32), np.empty(n, np.float32),
                                          np.empty(n, np.float32))
                s.points.foreach_get("co", co)
                s.points.foreach_get("strength", strength)
                s.points.foreach_get("pressure", pressure)
                out[layer.info].append((co.reshape(-1, 3), strength, pressure))
    return out


def camera_pixels(scene, points):
    """Pixels (x right, y down) of world points through the scene camera, by Blender's own projection."""
    w = scene.render.resolution_x * scene.render.resolution_percentage / 100
    h = scene.render.resolution_y * scene.render.resolution_percentage / 100
    out = np.empty((len(points), 2))
    for i, p in enumerate(points):
        v = world_to_camera_view(scene, scene.camera, Vector(p))
        out[i] = (v.x * w, (1 - v.y) * h)
    return out


def stroke_ink(scene, strokes, min_strength=0.5, project=None, size=None):
    """The strokes' ink over the render's pixels: every pixel a stroke passes through (segments sampled
    every quarter pixel) where its strength is at least min_strength (kappa's raster counts ink from
    half opacity: ink is a channel below 128). project: world points to pixels (default: the scene
    camera's camera_pixels) over an image of `size` (default: the render's)."""
    w, h = size or (round(scene.render.resolution_x * scene.render.resolution_percentage / 100),
                    round(scene.render.resolution_y * scene.render.resolution_percentage / 100))
    project = project or (lambda points: camera_pixels(scene, points))
    ink = np.zeros((h, w), bool)
    for points, strength, _ in strokes:
        p = project(points)
        for i in range(len(p) - 1):
            if min(strength[i], strength[i + 1]) < min_strength:
                continue
            n = max(1, int(math.ceil(4 * np.linalg.norm(p[i + 1] - p[i]))))
            t = np.linspace(0, 1, n + 1)[:, None]
            q = np.floor(p[i] + (p[i + 1] - p[i]) * t).astype(int)
            ok = (q[:, 0] >= 0) & (q[:, 0] < w) & (q[:, 1] >= 0) & (q[:, 1] < h)
            ink[q[ok, 1], q[ok, 0]] = True
    return ink


def render_ink(image):
    """kappa's ink convention (kappa.ink_agreement's): a pixel whose darkest channel is below 128."""
    return image[..., :3].min(-1) < 128


def kappa_render_of_view(scene, objects):
    """`kappa render` of the scene camera's view of these objects (kappa.render gives the command
    line's pixels: tests/python/test_module_render.py), with the add-on's settings, as the add-on
    would call kappa: the same triangles, camera and keywords, and a plain white surface."""
    from kappa_lines import scene_view, settings
    select_only(*objects)
    mesh = scene_view.SceneMesh(bpy.context)
    view = scene_view.scene_camera_view(scene)
    keywords = settings.keywords(scene.kappa_lines, kappa)
    return kappa.render(mesh.V, mesh.F, camera=view.camera, size=view.size, shading="none", **keywords)


def agreement(scene, objects, frame_number=None, radius=2):
    """(strokes' ink within radius of the render's, the render's within radius of the strokes'), the
    dashed hidden lines (35% ink, not ink to kappa's measure) left out."""
    strokes = [s for name, layer in gp_strokes(frame_number).items() if name != "hidden" for s in layer]
    a = stroke_ink(scene, strokes)
    image = kappa_render_of_view(scene, objects)
    return (*kappa.ink_agreement(a, image, radius), int(a.sum()), int(render_ink(image).sum()))


def draw_error(operator, **keywords):
    """The one-line report of an operator that is expected to fail (RuntimeError in scripts)."""
    try:
        operator(**keywords)
    except RuntimeError as e:
        return str(e)
    raise AssertionError(f"{operator} did not fail")


def region_pixels(region, region_3d, points):
    """Pixels (x right, y down) of world points in a 3D view, by its own perspective matrix."""
    M = np.array(region_3d.perspective_matrix)
    c = np.c_[np.asarray(points, np.float64), np.ones(len(points))] @ M.T
    ndc = c[:, :2] / c[:, 3:]
    return np.stack([(ndc[:, 0] + 1) / 2 * region.width, (1 - ndc[:, 1]) / 2 * region.height], -1)


def run(tests):
    """Runs the test_ functions of a test file's globals, each on an empty scene; exits 1 on a failure."""
    failed = ran = 0
    for name, test in list(tests.items()):
        if not name.startswith("test_") or not callable(test):
            continue
        ran += 1
        empty_scene()
        start = time.perf_counter()
        try:
            test()
            print(f"PASS {name} ({time.perf_counter() - start:.2f} s)", flush=True)
        except Exception:
            failed += 1
            traceback.print_exc()
            print(f"FAIL {name}", flush=True)
    print(f"{failed} of {ran} failed" if failed else f"all {ran} passed", flush=True)
    sys.exit(1 if failed or ran == 0 else 0)
