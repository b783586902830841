"""kappa.ink_agreement: render/image/ink_agreement's measure from Python, on masks, images and PNGs."""
import numpy as np
import pytest

import kappa


def dot(x, y, size=(40, 30)):
    mask = np.zeros(size[::-1], bool)
    mask[y, x] = True
    return mask


def test_distance_between_pixel_centres_against_the_radius():
    a, b = dot(10, 10), dot(12, 11)  # sqrt(5) = 2.24 px apart
    assert kappa.ink_agreement(a, b, radius=2) == (0.0, 0.0)
    assert kappa.ink_agreement(a, b, radius=2.25) == (1.0, 1.0)
    assert kappa.ink_agreement(dot(10, 10), dot(10, 12)) == (1.0, 1.0)  # 2 px: within the default radius 2


def test_fractions_each_way_and_no_ink():
    a = dot(5, 5) | dot(30, 20)  # two ink pixels, one near b's single one
    assert kappa.ink_agreement(a, dot(6, 5), radius=1) == (0.5, 1.0)
    empty = np.zeros((30, 40), bool)
    assert kappa.ink_agreement(empty, a) == (1.0, 0.0)


def test_images_use_kappas_ink_and_agree_with_masks():
    image = np.full((30, 40, 4), 255, np.uint8)
    image[10, 10, :3] = (200, 127, 200)  # ink: the darkest channel below 128
    image[20, 30, :3] = 128  # not ink
    ink = dot(10, 10)
    assert kappa.ink_agreement(image, ink, radius=0) == (1.0, 1.0)
    assert kappa.ink_agreement(image[..., :3], dot(30, 20), radius=0) == (0.0, 0.0)


def test_png_paths(tmp_path):
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], np.float32)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    path = tmp_path / "tet.png"
    kappa.write(V, F, path, size=(64, 48), shading="none")
    image = kappa.render(V, F, size=(64, 48), shading="none")
    assert (image[..., :3].min(-1) < 128).sum() > 50
    assert kappa.ink_agreement(path, image, radius=0) == (1.0, 1.0)


def test_bad_drawings_raise_one_clear_line():
    with pytest.raises(ValueError, match=r"^ink_agreement: the drawings differ in size \(40x30 and 20x30\)$"):
        kappa.ink_agreement(dot(1, 1), np.zeros((30, 20), bool))
    with pytest.raises(ValueError, match=r"^ink_agreement: b must be an \(h, w\) ink mask, .* got shape \(30, 40, 2\)"):
        kappa.ink_agreement(dot(1, 1), np.zeros((30, 40, 2), np.uint8))
    with pytest.raises(ValueError, match=r"got shape \(30, 40, 3\) of dtype float64"):
        kappa.ink_agreement(np.zeros((30, 40, 3)), dot(1, 1))
    with pytest.raises(ValueError, match="radius must be 0 or more"):
        kappa.ink_agreement(dot(1, 1), dot(1, 1), radius=-1)
    with pytest.raises(RuntimeError, match="missing.png"):
        kappa.ink_agreement("missing.png", dot(1, 1))
