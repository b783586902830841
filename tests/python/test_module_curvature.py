"""kappa.curvature gives exactly what `kappa curvature` writes."""
import numpy as np
import pytest

import kappa
from conftest import run_kappa, shared_mesh, torus, write_obj

COLUMNS = {"normals": (3, 6), "k1": (6, 7), "k2": (7, 8), "d1": (8, 11), "d2": (11, 14), "C": (14, 18)}


def cli_fields(tmp_path, mesh, *options):
    csv, ply = tmp_path / "out.csv", tmp_path / "out.ply"
    for out in (csv, ply):
        status, text = run_kappa("curvature", mesh, "-o", out, "-q", *options)
        assert status == 0, text
    table = np.loadtxt(csv, delimiter=",", skiprows=1, dtype=np.float64).astype(np.float32)
    fields = {name: table[:, a:b].squeeze() for name, (a, b) in COLUMNS.items()}
    fields["flags"] = read_ply_vertex_property(ply, "flags")
    return fields


def read_ply_vertex_property(path, name):
    """One property of the vertex element of a binary little-endian PLY (kappa's output)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    assert "format binary_little_endian 1.0" in header
    types = {"float": "<f4", "uchar": "u1", "int": "<i4", "uint": "<u4", "double": "<f8"}
    element, count, props = None, 0, []
    for words in (line.split() for line in header):
        if words[0] == "element":
            element = words[1]
            if element == "vertex":
                count = int(words[2])
        elif words[0] == "property" and element == "vertex":
            props.append((words[2], types[words[1]]))
    table = np.frombuffer(data, np.dtype(props), count, end)
    return table[name]


@pytest.mark.parametrize("mesh,options", [
    ("bunny.ply", {}),
    ("fandisk.obj", {"smooth": "auto"}),
    ("spot.obj", {"estimator": "jet"}),
    ("bunny.ply", {"smooth_normals": 0.002, "smooth_dcurv": 0.004}),
])
def test_fields_equal_the_command_lines_output(tmp_path, mesh, options):
    V, F = kappa.load_mesh(shared_mesh(mesh))
    fields = kappa.curvature(V, F, **options)
    words = []
    for key, value in options.items():
        words += ["--" + key.replace("_", "-"), str(value)]
    expected = cli_fields(tmp_path, shared_mesh(mesh), *words)
    for name, values in expected.items():
        assert fields[name].dtype == values.dtype, name
        assert np.array_equal(fields[name], values), name  # bit for bit (CSV %.9g round-trips float32)


def test_generated_arrays_equal_the_same_mesh_read_from_a_file(tmp_path):
    V, F = torus()
    write_obj(tmp_path / "torus.obj", V, F)
    fields = kappa.curvature(V, F)
    expected = cli_fields(tmp_path, tmp_path / "torus.obj")
    for name in COLUMNS:
        assert np.array_equal(fields[name], expected[name]), name
    # Convex outer equator (vertex (u=0, v=0) at x = R + r): k1 = 1/r, k2 = 1/(R + r) within a few percent.
    assert abs(fields["k1"][0] - 1 / 0.4) < 0.05 / 0.4
    assert abs(fields["k2"][0] - 1 / 1.4) < 0.05 / 1.4
    assert fields["normals"][0][0] > 0.99


def test_threads_do_not_change_the_numbers_and_smooth_takes_three_widths():
    V, F = kappa.load_mesh(shared_mesh("bunny.ply"))
    one, many = kappa.curvature(V, F, threads=1), kappa.curvature(V, F, threads=2)
    for name in COLUMNS:
        assert np.array_equal(one[name], many[name])
    a = kappa.curvature(V, F, smooth=(0.002, 0.0, 0.004))
    b = kappa.curvature(V, F, smooth_normals=0.002, smooth_dcurv=0.004)
    assert np.array_equal(a["k1"], b["k1"]) and not np.array_equal(a["k1"], one["k1"])
    assert a["smoothing"] == pytest.approx((0.002, 0.0, 0.004))


def test_bad_options_raise_with_the_command_lines_words():
    V, F = torus(nu=8, nv=6)
    with pytest.raises(ValueError, match="^estimator expects one of rusinkiewicz, jet"):
        kappa.curvature(V, F, estimator="magic")
    with pytest.raises(ValueError, match="^smooth expects"):
        kappa.curvature(V, F, smooth="sometimes")
    with pytest.raises(ValueError, match="^smooth_normals expects"):
        kappa.curvature(V, F, smooth_normals=-1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'smooth_normal'; did you mean 'smooth_normals'"):
        kappa.curvature(V, F, smooth_normal=1)
    with pytest.raises(ValueError, match="threads expects"):
        kappa.curvature(V, F, threads=-2)
