"""Fixtures shared by the compatmesh tests: small polygons with known answers."""
import numpy as np
import pytest


def ring(n=8, inner=1.0, jitter=True):
    """n vertices counter-clockwise around the origin; odd ones at radius
    `inner`. The jitter keeps diagonals from meeting by symmetry."""
    i = np.arange(n)
    angles = 2 * np.pi * (i + (0.1 * (i % 3) if jitter else 0)) / n
    radii = np.where(i % 2, inner, 1.0) * (1 + (0.03 * i if jitter else 0))
    return np.c_[radii * np.cos(angles), radii * np.sin(angles)]


@pytest.fixture
def octagon():
    return ring(8)


@pytest.fixture
def star():
    return ring(8, inner=0.3)


def signed_areas(vertices, faces):
    """Signed area of every face in a geometry (n x 2)."""
    a, b, c = (vertices[faces[:, i]] for i in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]))
