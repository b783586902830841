"""kappa.load_mesh and the checks of (V, F) arrays: errors raise, with the command line's messages."""
import numpy as np
import pytest

import kappa
from conftest import run_kappa, shared_mesh, torus


def cli_error(*args):
    status, out = run_kappa(*args)
    assert status == 1, out
    assert out.startswith("kappa: ") and out.count("\n") == 1, out
    return out[len("kappa: "):].strip()


def test_load_mesh_gives_the_vertices_and_faces_kappa_reads(tmp_path):
    V, F = kappa.load_mesh(shared_mesh("bunny.ply"))
    assert V.dtype == np.float32 and V.shape == (35947, 3) and V.flags.c_contiguous
    assert F.dtype == np.uint32 and F.shape == (69451, 3)
    assert F.max() < len(V)
    # The positions are those kappa curvature writes (x, y, z columns, %.9g: exact for float32).
    assert run_kappa("curvature", shared_mesh("bunny.ply"), "-o", tmp_path / "b.csv", "-q")[0] == 0
    xyz = np.loadtxt(tmp_path / "b.csv", delimiter=",", skiprows=1, usecols=(0, 1, 2)).astype(np.float32)
    assert np.array_equal(V, xyz)
    V2, F2 = kappa.load_mesh(shared_mesh("fandisk.obj"))  # OBJ, any path-like or str
    assert V2.shape[1] == 3 and F2.shape[1] == 3 and F2.max() < len(V2)


@pytest.mark.parametrize("name,content", [
    ("missing.ply", None),
    ("garbage.ply", b"ply\nformat nonsense 1.0\nend_header\n"),
    ("random.off", bytes(range(256)) * 4),
    ("nan.obj", b"v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"),
    ("badindex.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"),
    ("empty.stl", b""),
])
def test_bad_files_raise_mesh_error_with_the_cli_message(tmp_path, name, content):
    path = tmp_path / name
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(kappa.MeshError) as error:
        kappa.load_mesh(path)
    assert isinstance(error.value, ValueError)
    assert str(error.value) == cli_error("info", path)
    assert str(path) in str(error.value)


def test_bad_arrays_raise_instead_of_crashing():
    V, F = torus(nu=8, nv=6)
    cases = [
        (np.where(np.arange(len(V))[:, None] == 5, np.nan, V), F, "V: vertex 5 has a non-finite coordinate"),
        (np.where(np.arange(len(V))[:, None] == 2, np.inf, V), F, "V: vertex 2 has a non-finite coordinate"),
        (V, np.where(F == F.max(), len(V), F), f"refers to vertex {len(V)} but V has {len(V)} vertices"),
        (V, F - 1, "refers to vertex -1"),
        (np.zeros((0, 3), np.float32), np.zeros((0, 3), np.int32), "V is empty"),
        (V[:, :2], F, f"V must have shape (N, 3), got ({len(V)}, 2)"),
        (V, F[:, :2], f"F must have shape (M, 3), got ({len(F)}, 2)"),
        (V, F.astype(np.float64), "F must hold integers"),
        ("not an array", F, "V must"),
    ]
    for bad_V, bad_F, message in cases:
        for call in (kappa.curvature, kappa.render, kappa.strokes):
            with pytest.raises(kappa.MeshError, match=None) as error:
                call(bad_V, bad_F)
            assert message in str(error.value), (call.__name__, str(error.value))
    # Faces are optional for curvature (every vertex isolated), required to draw.
    fields = kappa.curvature(V, np.zeros((0, 3), np.int32))
    assert np.all(fields["flags"] & 1) and np.all(np.isfinite(fields["k1"]))
    for call in (kappa.render, kappa.strokes):
        with pytest.raises(kappa.MeshError, match="F is empty: the mesh has no faces"):
            call(V, np.zeros((0, 3), np.int32))
    # The interpreter is still fine.
    assert kappa.curvature(V, F)["k1"].shape == (len(V),)
