"""kappa.strokes(..., space='model'): each stroke point's place on the surface, in V's coordinates;
kappa.write; kappa.settings and kappa.line_groups (the settings table for other front ends)."""
import math

import numpy as np
import pytest

import kappa
from conftest import run_kappa, shared_mesh, torus

SIZE = (320, 240)
CAMERA = {"eye": (0.3, 0.25, 0.45), "target": (-0.02, 0.1, 0.0), "up": (0, 1, 0), "fov": 35}


def project(points, camera, size):
    """Pixels (x right, y down) of model points through a look-at camera with a vertical fov (numpy,
    the textbook construction, not kappa's code)."""
    eye, target, up = (np.array(camera[k], np.float64) for k in ("eye", "target", "up"))
    back = (eye - target) / np.linalg.norm(eye - target)
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    true_up = np.cross(back, right)
    d = np.asarray(points, np.float64) - eye
    x, y, z = d @ right, d @ true_up, d @ back
    f = 1 / math.tan(math.radians(camera["fov"]) / 2)
    w, h = size
    return np.stack([(x / -z * f * h / w + 1) / 2 * w, (1 - y / -z * f) / 2 * h], -1)


def nearest_vertex_distance(points, V):
    """Distance from each point to the nearest vertex (brute force in blocks)."""
    V = np.asarray(V, np.float64)
    out = []
    for block in np.array_split(np.asarray(points, np.float64), max(1, len(points) // 256)):
        out.append(np.sqrt(((block[:, None, :] - V[None, :, :]) ** 2).sum(-1).min(1)))
    return np.concatenate(out)


@pytest.fixture(scope="module")
def bunny_strokes():
    V, F = kappa.load_mesh(shared_mesh("bunny.ply"))
    strokes = kappa.strokes(V, F, camera=CAMERA, size=SIZE, space="model", lines="contours,suggestive,ridges",
                            hatching="cross")
    return V, F, strokes


def test_model_points_project_to_the_pixels(bunny_strokes):
    V, F, strokes = bunny_strokes
    assert {"contours", "suggestive", "hatching"} <= {s["type"] for s in strokes}
    for s in strokes:
        assert s["model_points"].dtype == np.float32 and s["model_points"].shape == (len(s["points"]), 3)
    points = np.concatenate([s["points"] for s in strokes])
    projected = project(np.concatenate([s["model_points"] for s in strokes]), CAMERA, SIZE)
    # float32 points through two float32 matrix products: well within a hundredth of a pixel.
    assert np.abs(projected - points).max() < 0.01


def test_model_points_lie_on_the_surface(bunny_strokes):
    V, F, strokes = bunny_strokes
    edges = np.linalg.norm(V[F[:, 0]] - V[F[:, 1]], axis=1)
    for kind, limit in (("lines", edges.max()), ("hatching", 2 * edges.max())):
        chosen = [s for s in strokes if (s["type"] == "hatching") == (kind == "hatching")]
        points = np.concatenate([s["model_points"] for s in chosen])[::7]
        # A point on a triangle lies within its longest edge of a vertex; hatching is read back from the
        # depth buffer (24 bits over the bunny's depth range, well under an edge) and its pixel's grid.
        assert nearest_vertex_distance(points, V).max() < limit, kind


def test_model_points_keep_the_models_units():
    V, F = torus(nu=24, nv=12)
    shift, scale = np.array([3e13, -1e13, 5e12]), 1e14  # far from unit size: drawn in drawing units
    camera = {"eye": (2.0, 1.5, 3.0), "target": (0, 0, 0), "up": (0, 1, 0), "fov": 30}
    big_camera = {k: (tuple(np.array(v) * scale + shift) if k in ("eye", "target") else v) for k, v in camera.items()}
    small = kappa.strokes(V, F, camera=camera, size=(160, 120), space="model", lines="contours")
    big = kappa.strokes(V.astype(np.float64) * scale + shift, F, camera=big_camera, size=(160, 120), space="model",
                        lines="contours")
    assert len(small) == len(big) > 0
    for a, b in zip(small, big):
        back = (b["model_points"].astype(np.float64) - shift) / scale
        assert np.abs(back - a["model_points"]).max() < 1e-3  # float32 of 1e14: 1e7 units, 1e-7 of a unit


def test_image_space_has_no_model_points_and_space_is_checked():
    V, F = torus(nu=8, nv=6)
    assert all("model_points" not in s for s in kappa.strokes(V, F, size=(64, 48)))
    with pytest.raises(ValueError, match="space expects 'image' or 'model', got 'world'"):
        kappa.strokes(V, F, space="world")


def test_write_gives_the_command_lines_svg(tmp_path):
    mesh = shared_mesh("bunny.ply")
    V, F = kappa.load_mesh(mesh)
    kappa.write(V, F, tmp_path / "module.svg", camera={"view": (30, 20)}, size=(200, 150), shading="none")
    status, out = run_kappa("render", mesh, "--view", "30,20", "--size", "200x150", "--shading", "none",
                            "-o", tmp_path / "cli.svg")
    assert status == 0, out
    assert (tmp_path / "module.svg").read_bytes() == (tmp_path / "cli.svg").read_bytes()
    with pytest.raises(RuntimeError, match="no-such-dir"):
        kappa.write(V, F, tmp_path / "no-such-dir" / "x.svg", size=(64, 48))


def test_settings_table_gives_names_ranges_and_defaults():
    table = {s["name"]: s for s in kappa.settings()}
    assert table["line_width"]["kind"] == "number" and table["line_width"]["default"] == 2
    assert table["line_width"]["min"] < 2 < table["line_width"]["max"]
    assert table["detail"]["can_be_off"] and table["detail"]["default"] == 12
    assert table["fade"] == {**table["fade"], "kind": "switch", "default": True}
    assert table["lines"]["default"] == ["contours", "suggestive", "creases"]
    assert table["isophotes"]["kind"] == "integer" and table["isophotes"]["default"] == 4
    assert "help" in table["sc_threshold"] and "0.05" in table["sc_threshold"]["help"]
    # Every default is a value kappa takes back (colours as '#rrggbb').
    V, F = torus(nu=8, nv=6)
    given = {}
    for name, s in table.items():
        if s["kind"] in ("number", "integer", "switch", "choice", "lines"):
            given[name] = s["default"]
    kappa.strokes(V, F, size=(64, 48), **given)
    groups = kappa.line_groups()
    kinds = [line["kind"] for g in groups for line in g["lines"]]
    assert set(kinds) <= set(table["lines"]["choices"]) and "suggestive" in kinds
    assert all(line["setting"] in table for g in groups for line in g["lines"] if line["setting"])
