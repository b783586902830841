"""Shared pieces of the Python module's tests (run by ctest: tests/CMakeLists.txt sets
PYTHONPATH to build/python, KAPPA_EXE and KAPPA_MESH_DIR)."""
import os
import struct
import subprocess
import zlib

import numpy as np
import pytest

import kappa

KAPPA_EXE = os.environ.get("KAPPA_EXE", "kappa")
MESH_DIR = os.environ.get("KAPPA_MESH_DIR", os.path.join(os.path.dirname(__file__), "../../../shared/meshes"))


def shared_mesh(name):
    path = os.path.join(MESH_DIR, name)
    if not os.path.exists(path):
        pytest.fail(f"missing shared mesh {path} (configure with -DKAPPA_MESH_DIR=...)")
    return path


def run_kappa(*args):
    """Runs the kappa executable; returns (exit status, stdout + stderr)."""
    r = subprocess.run([KAPPA_EXE, *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return r.returncode, r.stdout


def torus(R=1.0, r=0.4, nu=48, nv=24):
    """A torus around the y axis: (V float32, F int64), faces counter-clockwise from outside."""
    u, v = np.meshgrid(np.arange(nu) * 2 * np.pi / nu, np.arange(nv) * 2 * np.pi / nv, indexing="ij")
    V = np.stack([(R + r * np.cos(v)) * np.cos(u), r * np.sin(v), (R + r * np.cos(v)) * np.sin(u)], -1)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a, b = i * nv + j, ((i + 1) % nu) * nv + j
    c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
    F = np.concatenate([np.stack([a, d, c], -1).reshape(-1, 3), np.stack([a, c, b], -1).reshape(-1, 3)])
    return V.reshape(-1, 3).astype(np.float32), F


def write_obj(path, V, F):
    with open(path, "w") as f:
        f.writelines(f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in V)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F)


def read_png(path):
    """An 8-bit RGBA, non-interlaced PNG (what kappa writes) as an (h, w, 4) uint8 array."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, color, interlace) == (8, 6, 0)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * 4
    out = np.zeros((h, stride), np.int32)
    prev = np.zeros(stride, np.int32)
    for y in range(h):
        kind, row = raw[y * (stride + 1)], np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        if kind == 0:
            cur = row
        elif kind == 2:
            cur = (row + prev) & 255
        else:  # Sub, Average, Paeth depend on the pixel to the left: per byte
            cur = np.zeros(stride, np.int32)
            for x in range(stride):
                left = cur[x - 4] if x >= 4 else 0
                up, ul = prev[x], (prev[x - 4] if x >= 4 else 0)
                if kind == 1:
                    pred = left
                elif kind == 3:
                    pred = (left + up) // 2
                else:
                    p = left + up - ul
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - ul)
                    pred = left if pa <= pb and pa <= pc else (up if pb <= pc else ul)
                cur[x] = (row[x] + pred) & 255
        out[y], prev = cur, cur
    return out.reshape(h, w, 4).astype(np.uint8)


@pytest.fixture
def bunny():
    return kappa.load_mesh(shared_mesh("bunny.ply"))
