"""The Blender add-on's pieces that need no Blender (blender/kappa_lines/view.py, geometry.py): a
Blender camera in kappa's terms, and the camera-inside-the-model check."""
import importlib.util
import math
import os

import numpy as np
import pytest

from conftest import torus

ADDON = os.path.join(os.path.dirname(__file__), "../../blender/kappa_lines")


def addon_module(name):
    spec = importlib.util.spec_from_file_location(f"kappa_lines_{name}", os.path.join(ADDON, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


view = addon_module("view")
geometry = addon_module("geometry")


@pytest.mark.parametrize("fit, width, height, expected", [
    # 50 mm lens, 36 x 24 mm sensor. Landscape: the width fits the sensor width (AUTO, HORIZONTAL).
    ("AUTO", 1920, 1080, 2 * math.atan(18 / 50 * 1080 / 1920)),
    ("HORIZONTAL", 1920, 1080, 2 * math.atan(18 / 50 * 1080 / 1920)),
    # Portrait: AUTO fits the height to the sensor width.
    ("AUTO", 1080, 1920, 2 * math.atan(18 / 50)),
    ("HORIZONTAL", 1080, 1920, 2 * math.atan(18 / 50 * 1920 / 1080)),
    ("VERTICAL", 1920, 1080, 2 * math.atan(12 / 50)),
])
def test_vertical_fov_follows_the_sensor_fit(fit, width, height, expected):
    assert view.vertical_fov(50, 36, 24, fit, width, height) == pytest.approx(math.degrees(expected), rel=1e-12)


def test_look_at_takes_the_cameras_axes():
    # A camera at (1, 2, 3) turned 90 degrees about z: its -z still looks down -z, its +y is -x.
    c, s = 0.0, 1.0
    m = [[c, -s, 0, 1], [s, c, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]
    cam = view.look_at(m, 40)
    assert cam["eye"] == (1, 2, 3) and cam["fov"] == 40
    assert np.allclose(np.subtract(cam["target"], cam["eye"]), (0, 0, -1))
    assert np.allclose(cam["up"], (-1, 0, 0))
    # Scale in the matrix is ignored.
    scaled = view.look_at([[2 * x for x in row[:3]] + [row[3]] for row in m[:3]] + [m[3]], 40)
    assert np.allclose(scaled["up"], cam["up"]) and np.allclose(scaled["target"], cam["target"])


def test_viewport_fov_from_the_projection():
    f = 1 / math.tan(math.radians(25))
    assert view.viewport_fov([[f * 0.75, 0, 0, 0], [0, f, 0, 0], [0, 0, -1, -0.2], [0, 0, -1, 0]]) == pytest.approx(50)


def test_point_inside_a_closed_surface():
    V, F = torus(R=1.0, r=0.4)
    assert geometry.point_inside(V, F, (1.0, 0.0, 0.0))      # in the tube
    assert geometry.point_inside(V, F, (0.0, 0.1, -1.2))
    assert not geometry.point_inside(V, F, (0.0, 0.0, 0.0))  # in the hole
    assert not geometry.point_inside(V, F, (3.0, 2.0, 1.0))
    assert not geometry.point_inside(V, F, (1.0, 0.5, 0.0))  # just above the tube
