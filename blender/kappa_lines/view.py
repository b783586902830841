"""The view kappa draws, from Blender's camera or 3D view, in kappa's terms (no bpy here: tests/python
checks it without Blender).

kappa's camera (kappa.strokes' camera dict) is a look-at camera with a vertical field of view:
eye, target, up and fov in degrees. Blender's camera looks down its local -z with +y up; its
field of view comes from the lens and the sensor, fitted to the image's width or height
(sensor_fit: AUTO fits the larger side, HORIZONTAL the width, VERTICAL the height).
"""
import math


def vertical_fov(lens, sensor_width, sensor_height, sensor_fit, width, height):
    """Vertical field of view in degrees of a Blender perspective camera over a width x height image."""
    if sensor_fit == "VERTICAL":
        half_height = sensor_height / 2
    elif sensor_fit == "HORIZONTAL" or (sensor_fit == "AUTO" and width >= height):
        half_height = sensor_width / 2 * height / width
    else:  # AUTO on a portrait image: the sensor width spans the height
        half_height = sensor_width / 2
    return math.degrees(2 * math.atan(half_height / lens))


def look_at(matrix_world, fov_deg):
    """kappa's camera dict from a camera's 4x4 world matrix (rows, as mathutils gives them; scale and
    shear are ignored): eye at its translation, looking down its -z, its +y up."""
    m = [list(map(float, row)) for row in matrix_world]
    eye = [m[0][3], m[1][3], m[2][3]]
    back = _unit([m[0][2], m[1][2], m[2][2]])
    up = _unit([m[0][1], m[1][1], m[2][1]])
    target = [e - b for e, b in zip(eye, back)]
    return {"eye": tuple(eye), "target": tuple(target), "up": tuple(up), "fov": fov_deg}


def viewport_fov(window_matrix):
    """Vertical field of view in degrees from a 3D view's perspective projection matrix (rows)."""
    return math.degrees(2 * math.atan(1 / float(window_matrix[1][1])))


def _unit(v):
    n = math.sqrt(sum(x * x for x in v))
    if n == 0:
        raise ValueError("the camera's matrix has a zero axis")
    return [x / n for x in v]
