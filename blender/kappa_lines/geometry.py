"""Checks on the scene's triangles before kappa draws them (numpy only, no bpy)."""
import numpy as np


def point_inside(V, F, point):
    """Whether `point` lies inside the closed surface (V, F): the parity of the faces crossed by rays
    from it, by the majority of three rays in skew directions (a ray through an edge may count a
    crossing twice or not at all; three rarely all do)."""
    V = np.asarray(V, np.float64)
    F = np.asarray(F, np.int64)
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    e1, e2 = b - a, c - a
    o = np.asarray(point, np.float64)
    inside_votes = 0
    for d in ((0.5773, 0.5774, 0.5775), (-0.8017, 0.2673, 0.5345), (0.1826, -0.3651, -0.9129)):
        d = np.asarray(d) / np.linalg.norm(d)
        # Moller-Trumbore, every face at once.
        p = np.cross(d, e2)
        det = np.einsum("ij,ij->i", e1, p)
        ok = np.abs(det) > 1e-12
        inv = np.where(ok, 1 / np.where(ok, det, 1), 0)
        s = o - a
        u = np.einsum("ij,ij->i", s, p) * inv
        q = np.cross(s, e1)
        v = (q @ d) * inv
        t = np.einsum("ij,ij->i", e2, q) * inv
        hits = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        inside_votes += int(np.count_nonzero(hits)) % 2
    return inside_votes >= 2
