"""kappa.render and kappa.strokes: the command line's pixels and strokes, on one reused GL context."""
import threading

import numpy as np
import pytest

import kappa
from conftest import read_png, run_kappa, shared_mesh, torus, write_obj


def cli_png(tmp_path, mesh, *options):
    out = tmp_path / "cli.png"
    status, text = run_kappa("render", mesh, "-o", out, "-q", *options)
    assert status == 0, text
    return read_png(out)


@pytest.mark.parametrize("camera,settings,words", [
    (None, {"size": (160, 120)}, ["--size", "160x120"]),
    ({"view": (90, 10)}, {"size": "160x120", "shading": "none", "lines": ["contours", "suggestive", "ridges"],
                          "line_width": 1.5, "fade": False},
     ["--view", "90,10", "--size", "160x120", "--shading", "none", "--lines", "contours,suggestive,ridges",
      "--line-width", "1.5", "--fade", "off"]),
    ({"eye": (0, 0.1, 0.3), "target": (0, 0.1, 0), "fov": 40}, {"size": (128, 96), "hatching": "cross",
                                                                "colorbar": True, "colormap": "mean"},
     ["--eye", "0,0.1,0.3", "--target", "0,0.1,0", "--fov", "40", "--size", "128x96", "--hatching", "cross",
      "--colorbar", "--colormap", "mean"]),
])
def test_render_gives_the_command_lines_pixels(tmp_path, camera, settings, words):
    V, F = kappa.load_mesh(shared_mesh("bunny.ply"))
    image = kappa.render(V, F, camera=camera, **settings)
    w, h = map(int, words[words.index("--size") + 1].split("x"))
    assert image.dtype == np.uint8 and image.shape == (h, w, 4)
    assert np.array_equal(image, cli_png(tmp_path, shared_mesh("bunny.ply"), *words))


def test_ink_lies_where_the_model_is():
    V, F = torus(R=1.0, r=0.35)
    w, h = 160, 160
    # From straight above (the torus lies in the xz plane): a ring around an empty hole.
    image = kappa.render(V, F, camera={"view": (0, 90)}, size=(w, h), background="transparent")
    alpha = image[..., 3] > 0
    ys, xs = np.nonzero(alpha)
    cx, cy = xs.mean(), ys.mean()
    assert abs(cx - (w - 1) / 2) < 2 and abs(cy - (h - 1) / 2) < 2
    radius = np.hypot(xs - cx, ys - cy)
    outer = radius.max()
    assert not alpha[int(cy), int(cx)]                                  # the hole
    assert radius.min() == pytest.approx(outer * 0.65 / 1.35, rel=0.08)  # inner edge at (R - r) / (R + r)
    # Lines: dark ink only on or at the model (contours straddle the outline), none in the hole.
    ink = (image[..., :3].max(-1) < 100) & alpha
    assert ink.sum() > 2 * np.pi * outer  # at least the outer contour
    near = np.hypot(*np.nonzero(ink)[::-1] - np.array([[cx], [cy]]))
    assert near.min() > radius.min() - 2 and near.max() < outer + 2


def test_one_gl_context_serves_every_call_and_any_thread():
    V, F = torus(nu=24, nv=12)
    first = kappa.render(V, F, size=(96, 64))
    before = kappa.gl_context()
    assert before["contexts_created"] == 1 and "OpenGL" in before["description"]
    results = []
    thread = threading.Thread(target=lambda: results.append(kappa.render(V, F, size=(96, 64))))
    thread.start()
    thread.join()
    again = kappa.render(V, F, size=(96, 64))
    after = kappa.gl_context()
    assert after["contexts_created"] == 1
    assert after["drawings"] == before["drawings"] + 2
    assert np.array_equal(results[0], first) and np.array_equal(again, first)


def test_strokes_lie_on_the_rendered_lines():
    V, F = kappa.load_mesh(shared_mesh("bunny.ply"))
    settings = dict(size=(256, 192), shading="none", lines="contours,suggestive", fade=False)
    strokes = kappa.strokes(V, F, camera={"view": (30, 20)}, **settings)
    image = kappa.render(V, F, camera={"view": (30, 20)}, **settings)
    assert {s["type"] for s in strokes} <= {"contours", "suggestive"}
    assert any(s["type"] == "contours" for s in strokes)
    points = np.concatenate([s["points"] for s in strokes])
    assert points.dtype == np.float32 and points.shape[1] == 2
    assert all(len(s["opacity"]) == len(s["points"]) for s in strokes)
    assert points.min() >= 0 and points[:, 0].max() <= 256 and points[:, 1].max() <= 192
    # The pixels of the stroke points within 2 px of the raster's ink, 95% of them.
    at_points = np.zeros(image.shape[:2], bool)
    at_points[np.clip(points[:, 1].astype(int), 0, 191), np.clip(points[:, 0].astype(int), 0, 255)] = True
    on_ink, _ = kappa.ink_agreement(at_points, image, radius=2)
    assert on_ink > 0.95, on_ink  # measured 1.000


def test_bad_settings_raise_with_the_keyword_spelling():
    V, F = torus(nu=8, nv=6)
    with pytest.raises(TypeError, match="unexpected keyword argument 'line_widht'; did you mean 'line_width'"):
        kappa.render(V, F, line_widht=2)
    with pytest.raises(ValueError, match=r"^line_width expects a number in \[0.1, 64\], got 'abc'$"):
        kappa.render(V, F, line_width="abc")
    with pytest.raises(ValueError, match="^lines expects"):
        kappa.render(V, F, lines=["contours", "squiggles"])
    with pytest.raises(ValueError, match="^view cannot be combined with eye/target$"):
        kappa.render(V, F, camera={"view": (0, 0), "eye": (1, 2, 3)})
    with pytest.raises(TypeError, match="camera has no key 'position'"):
        kappa.render(V, F, camera={"position": (1, 2, 3)})
    with pytest.raises(ValueError, match="eye and target must differ"):
        kappa.render(V, F, camera={"eye": (1, 1, 1), "target": (1, 1, 1)})
    with pytest.raises(ValueError, match="size"):
        kappa.render(V, F, size=(0, 10))
    assert kappa.render(V, F, size=(8, 8)).shape == (8, 8, 4)  # still fine afterwards
