"""bpy.ops.kappa.draw_lines and bake_frames: the Grease Pencil strokes, projected by Blender's own
camera (world_to_camera_view), agree with `kappa render` of the same view, the lines, the hatching and
the dashed hidden lines; objects hide each other's lines; a camera orbit bakes one matching frame per
frame."""
import math
import os
import sys

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_test as bt  # noqa: E402
from kappa_lines import settings  # noqa: E402

# At least 0.95 of each drawing's ink lies within 2 px of the other's (issue 28). The strokes are the
# lines kappa render rasterises, so they only differ by the raster's pixel grid and line width.
AGREE, RADIUS = 0.95, 2


def check_agreement(scene, objects, frame_number=None):
    strokes_in_render, render_in_strokes, stroke_ink, ink = bt.agreement(scene, objects, frame_number, RADIUS)
    print(f"  ink: strokes {stroke_ink} px, render {ink} px; within {RADIUS} px: "
          f"{strokes_in_render:.3f} and {render_in_strokes:.3f}")
    assert ink > 500 and stroke_ink > 500, "too little drawn to compare"
    assert strokes_in_render >= AGREE and render_in_strokes >= AGREE


def selected_monkey_in_view(scene, levels=2):
    """A subdivided Suzanne, selected alone, seen by the scene camera from its front left."""
    monkey = bt.suzanne(scene, levels=levels)
    bt.add_camera(scene, (2.2, -3.4, 1.4), (0, 0, 0.1))
    bt.select_only(monkey)
    return monkey


def test_suzanne_strokes_agree_with_kappa_render():
    scene = bpy.context.scene
    monkey = selected_monkey_in_view(scene)
    assert bpy.ops.kappa.draw_lines() == {"FINISHED"}
    layers = bt.gp_strokes()
    assert {"contours", "suggestive", "creases"} <= set(layers), layers.keys()
    assert len(layers["contours"]) > 0 and len(layers["suggestive"]) > 0
    assert "hatching" not in layers and "hidden" not in layers  # both off by default
    check_agreement(scene, [monkey])


def test_hatching_strokes_agree_with_kappa_render():
    scene = bpy.context.scene
    monkey = selected_monkey_in_view(scene)
    props = scene.kappa_lines
    for kind in settings.chosen_lines(props, bt.kappa):
        setattr(props, settings.line_property(kind), False)  # the hatching alone, drawn and rendered
    props.hatching = "cross"
    assert bpy.ops.kappa.draw_lines() == {"FINISHED"}
    layers = bt.gp_strokes()
    assert set(layers) == {"hatching"} and len(layers["hatching"]) > 100, {k: len(v) for k, v in layers.items()}
    # Measured 0.984 and 1.000 (the strokes 1 px lines, kappa's 1.25 px wide).
    check_agreement(scene, [monkey])


def test_hidden_lines_on_their_layer_where_kappa_render_draws_them():
    scene = bpy.context.scene
    monkey = selected_monkey_in_view(scene)
    props = scene.kappa_lines
    props.hidden_lines = True
    assert bpy.ops.kappa.draw_lines() == {"FINISHED"}
    hidden = bt.gp_strokes()["hidden"]
    assert abs(bpy.data.objects["kappa lines"].data.layers["hidden"].opacity - 0.35) < 1e-6
    check_agreement(scene, [monkey])  # the visible lines, on their own layers
    # kappa render's hidden lines: the pixels its dashes (35% ink, not ink to the measure) darken.
    with_hidden = bt.kappa_render_of_view(scene, [monkey])[..., :3].min(-1).astype(int)
    props.hidden_lines = False
    without = bt.kappa_render_of_view(scene, [monkey])[..., :3].min(-1).astype(int)
    rendered = without - with_hidden > 40  # a dash darkens white by 0.35 * 255 = 89
    drawn = bt.stroke_ink(scene, hidden)
    on_render, on_strokes = bt.kappa.ink_agreement(drawn, rendered, RADIUS)
    print(f"  hidden: strokes {drawn.sum()} px, render {rendered.sum()} px; within {RADIUS} px: "
          f"{on_render:.3f} and {on_strokes:.3f}")
    assert drawn.sum() > 300 and rendered.sum() > 300
    # Measured 0.993 and 0.990 (the dashes' phases differ: kappa's start at each mesh segment).
    assert on_render >= AGREE and on_strokes >= AGREE
    # Dashed: the strokes are pieces at most 6 px long on the image.
    longest = max(np.linalg.norm(np.diff(bt.camera_pixels(scene, p), axis=0), axis=1).sum() for p, _, _ in hidden)
    assert longest < 6.5, longest
    # Turned off, the next drawing empties the hidden layer's frame.
    bpy.ops.kappa.draw_lines()
    assert bt.gp_strokes()["hidden"] == []


def test_bunny_strokes_agree_with_kappa_render():
    scene = bpy.context.scene
    bunny = bt.import_ply("bunny.ply")
    bunny.rotation_euler = (math.radians(90), 0, math.radians(30))  # its +y up becomes Blender's +z
    bunny.scale = (10, 10, 10)
    bt.add_camera(scene, (1.0, -2.6, 1.5), (0, 0, 1.0), lens=60)
    bt.select_only(bunny)
    assert bpy.ops.kappa.draw_lines() == {"FINISHED"}
    check_agreement(scene, [bunny])


def test_points_sit_on_the_surface_pulled_toward_the_camera():
    scene = bpy.context.scene
    monkey = bt.suzanne(scene, levels=1)
    cam = bt.add_camera(scene, (0, -4, 0.5), (0, 0, 0))
    bt.select_only(monkey)
    scene.kappa_lines.pull = 0.01
    bpy.ops.kappa.draw_lines()
    points = np.concatenate([p for layer in bt.gp_strokes().values() for p, _, _ in layer])
    # Each point moved 1% of the way to the camera from the surface: 1% of its distance in front of the
    # nearest surface point seen along its line of sight.
    from mathutils.bvhtree import BVHTree
    depsgraph = bpy.context.evaluated_depsgraph_get()
    tree = BVHTree.FromObject(monkey, depsgraph)
    eye = np.array(cam.location)
    offsets = []
    for p in points[::5]:
        hit, _, _, distance = tree.ray_cast(p, p - eye)  # away from the camera, onto the surface
        if hit is not None:
            offsets.append(distance / np.linalg.norm(eye - p) * (1 - 0.01) / 0.01)
    offsets = np.array(offsets)
    # Contour points graze the surface, so a few rays miss. kappa draws the surface at the contour
    # scale: on a mesh it reads as noisy (this Suzanne: modelled creases read as a noise floor of
    # 0.15 units) the drawn positions are smoothed there, and the strokes sit on that surface, which
    # lies up to about 0.35% of the camera distance behind Blender's (measured: 27 of 32 rays hit,
    # median offset 0.67 of the pull). The strokes must still be in front of Blender's surface.
    print("  rays hit", len(offsets), "of", len(points[::5]), "median offset", np.median(offsets))
    assert len(offsets) > 0.75 * len(points[::5])
    assert 0.5 < np.median(offsets) < 1.02, np.median(offsets)


def test_fading_gives_strength_or_pressure():
    scene = bpy.context.scene
    monkey = selected_monkey_in_view(scene, levels=1)
    props = scene.kappa_lines
    props.line_width = 2.5  # Grease Pencil's whole pixels: width 3, pressure 2.5 / 3
    bpy.ops.kappa.draw_lines()
    suggestive = bt.gp_strokes()["suggestive"]
    strength = np.concatenate([s for _, s, _ in suggestive])
    pressure = np.concatenate([p for _, _, p in suggestive])
    print(f"  fade as opacity: strength {strength.min():.2f}..{strength.max():.2f}, pressure {pressure.min():.3f}")
    assert strength.min() < 0.5 and strength.max() > 0.9  # suggestive contours fade out at their ends
    assert np.allclose(pressure, 2.5 / 3)
    widths = {s.line_width for layer in bpy.data.objects["kappa lines"].data.layers for f in layer.frames
              for s in f.strokes}
    assert widths == {3}, widths
    props.width_by_strength = True
    bpy.ops.kappa.draw_lines()
    suggestive = bt.gp_strokes()["suggestive"]
    strength = np.concatenate([s for _, s, _ in suggestive])
    pressure = np.concatenate([p for _, _, p in suggestive])
    print(f"  fade as width: pressure {pressure.min():.2f}..{pressure.max():.2f}")
    assert np.all(strength == 1) and pressure.min() < 0.5 * 2.5 / 3 and pressure.max() > 0.9 * 2.5 / 3


def test_objects_hide_each_others_lines():
    scene = bpy.context.scene
    back = bt.suzanne(scene, levels=1, location=(0, 2, 0))
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.6, location=(0.3, -0.5, 0.1), segments=48, ring_count=24)
    front = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    bt.add_camera(scene, (0, -6, 0.3), (0, 1, 0))
    # The sphere's disc on the image, a few pixels inside its outline.
    V = np.array([front.matrix_world @ v.co for v in front.data.vertices])
    disc = bt.camera_pixels(scene, V)
    centre = disc.mean(0)
    radius = np.linalg.norm(disc - centre, axis=1).max() - 4

    def monkey_points_behind_sphere():
        points = np.concatenate([p for layer in bt.gp_strokes().values() for p, _, _ in layer])
        # Points on the monkey: its front is about 7 units from the camera, the sphere's back 6.1.
        on_monkey = np.linalg.norm(points - np.array(scene.camera.location), axis=1) > 6.5
        pixels = bt.camera_pixels(scene, points[on_monkey])
        return int((np.linalg.norm(pixels - centre, axis=1) < radius).sum()), int(on_monkey.sum())

    bt.select_only(back)
    bpy.ops.kappa.draw_lines()
    alone, _ = monkey_points_behind_sphere()
    bt.select_only(back, front)
    bpy.ops.kappa.draw_lines()
    together, total = monkey_points_behind_sphere()
    print(f"  monkey stroke points inside the sphere's disc: {alone} drawn alone, {together} of {total} with it")
    assert alone > 20  # the test could fail: drawn alone, the monkey has lines there
    assert together == 0 and total > 100
    check_agreement(scene, [back, front])


def test_camera_orbit_bakes_each_frame_as_its_render():
    scene = bpy.context.scene
    monkey = bt.suzanne(scene, levels=1)
    cam = bt.add_camera(scene, (0, -4, 1), (0, 0, 0))
    for frame, angle in zip((1, 2, 3), (0, 40, 80)):
        a = math.radians(angle)
        bt.aim(cam, (4 * math.sin(a), -4 * math.cos(a), 1), (0, 0, 0))
        cam.keyframe_insert("location", frame=frame)
        cam.keyframe_insert("rotation_euler", frame=frame)
        # The monkey moves and turns too: each frame is drawn from the scene at that frame.
        monkey.location = (0.15 * frame, 0, 0)
        monkey.rotation_euler = (0, 0, math.radians(-15 * frame))
        monkey.keyframe_insert("location", frame=frame)
        monkey.keyframe_insert("rotation_euler", frame=frame)
    bt.select_only(monkey)
    assert bpy.ops.kappa.bake_frames(frame_start=1, frame_end=3) == {"FINISHED"}
    layer = bpy.data.objects["kappa lines"].data.layers["contours"]
    assert sorted(f.frame_number for f in layer.frames) == [1, 2, 3]
    for frame in (1, 2, 3):
        scene.frame_set(frame)
        check_agreement(scene, [monkey], frame)


bt.run(globals())
