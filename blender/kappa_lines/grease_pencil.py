"""kappa's strokes as the Grease Pencil object `kappa lines`: one layer per line type, named as
kappa names them (contours, suggestive, ...), one Grease Pencil frame per drawn scene frame, 3D
points on the surface moved a little toward the camera (along the line of sight, so the picture
does not change), opacity and width following kappa's fading. Hidden parts of lines (hidden_lines)
go to the layer `hidden`, dashed and light as kappa's SVG draws them."""
import math

import bpy
import numpy as np

OBJECT_NAME = "kappa lines"
HIDDEN_LAYER = "hidden"
# kappa's hidden lines: dashes 6 px long every 10 px, at 35% ink (render/vector/svg_writer.cpp).
DASH_ON, DASH_PERIOD, HIDDEN_OPACITY = 6.0, 10.0, 0.35


def lines_object(scene):
    """The `kappa lines` Grease Pencil object, made (and linked to the scene) when missing."""
    obj = bpy.data.objects.get(OBJECT_NAME)
    if obj is not None and obj.type != "GPENCIL":
        obj.name = OBJECT_NAME + " (not Grease Pencil)"
        obj = None
    if obj is None:
        data = bpy.data.grease_pencils.new(OBJECT_NAME)
        data.stroke_depth_order = "3D"  # strokes hide behind the surfaces in front of them
        data.stroke_thickness_space = "SCREENSPACE"  # line widths in pixels, as kappa's
        obj = bpy.data.objects.new(OBJECT_NAME, data)
    if scene.collection.objects.get(obj.name) is None and obj.name not in scene.objects:
        scene.collection.objects.link(obj)
    obj.matrix_world.identity()  # points are written in world space
    return obj


def line_material(obj, color):
    name = OBJECT_NAME
    mat = bpy.data.materials.get(name)
    if mat is None or not mat.is_grease_pencil:
        mat = bpy.data.materials.new(name)
        bpy.data.materials.create_gpencil_data(mat)
    mat.grease_pencil.color = (*color, 1.0)
    if mat.name not in obj.data.materials:
        obj.data.materials.append(mat)
    return obj.data.materials.find(mat.name)


def empty_frame(layer, frame_number):
    for frame in layer.frames:
        if frame.frame_number == frame_number:
            layer.frames.remove(frame)
            break
    return layer.frames.new(frame_number)


def layer_of(stroke):
    return HIDDEN_LAYER if stroke["hidden"] else stroke["type"]


def dashes(pixels, values):
    """Cuts a polyline into dashes DASH_ON pixels long every DASH_PERIOD pixels along its image
    length: a list of the dashes' `values` (n, k) per point, interpolated at the cuts."""
    pixels = np.asarray(pixels, np.float64)
    length = np.r_[0, np.cumsum(np.linalg.norm(np.diff(pixels, axis=0), axis=1))]
    out = []
    for start in np.arange(0, length[-1], DASH_PERIOD):
        end = min(start + DASH_ON, length[-1])
        inside = (length > start) & (length < end)
        at = np.r_[start, length[inside], end]
        if at[-1] - at[0] <= 0:
            continue
        out.append(np.stack([np.interp(at, length, v) for v in values.T], axis=-1))
    return out


def pieces(s):
    """A kappa stroke as the (model points (n, 3), opacity (n,)) it draws: itself, or its dashes."""
    points = np.asarray(s["model_points"], np.float64)
    fade = np.asarray(s["opacity"], np.float64)
    if not s["hidden"]:
        return [(points, fade)]
    return [(d[:, :3], d[:, 3]) for d in dashes(s["points"], np.c_[points, fade])]


def write_frame(obj, frame_number, strokes, eye, layer_names, pull, line_width, width_by_strength, material):
    """Replaces frame `frame_number` of the layers in layer_names (and of any layer a stroke's type
    names) with `strokes` (kappa.strokes(..., space='model') in
    world space)."""
    data = obj.data
    names = list(dict.fromkeys(list(layer_names) + [layer_of(s) for s in strokes]))
    frames = {}
    for name in names:
        layer = data.layers.get(name)
        if layer is None:
            layer = data.layers.new(name, set_active=False)
            layer.use_lights = False
            if name == HIDDEN_LAYER:
                layer.opacity = HIDDEN_OPACITY  # the user may change it after

        frames[name] = empty_frame(layer, frame_number)
    # Grease Pencil widths are whole pixels: the rest goes into the points' pressure.
    for s in strokes:
        if len(s["model_points"]) < 2:
            continue
        width = s["width"] or line_width
        for points, fade in pieces(s):
            write_stroke(frames[layer_of(s)], points + (eye - points) * pull, fade.astype(np.float32), width,
                         width_by_strength, material)
    data.update_tag()


def write_stroke(frame, points, fade, width, width_by_strength, material):
    """One Grease Pencil stroke through world points, faded by `fade` as opacity or as width."""
    gp_width = max(1, math.ceil(width))
    stroke = frame.strokes.new()
    stroke.display_mode = "3DSPACE"
    stroke.line_width = gp_width
    stroke.material_index = material
    stroke.points.add(len(points))
    stroke.points.foreach_set("co", points.astype(np.float32).ravel())
    scale = np.float32(width / gp_width)
    pressure = scale * (fade if width_by_strength else np.ones_like(fade))
    stroke.points.foreach_set("pressure", pressure)
    stroke.points.foreach_set("strength", np.ones_like(fade) if width_by_strength else fade)
