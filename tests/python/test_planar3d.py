"""Planar polygons in 3D: fitted, mapped to 2D and back."""
import numpy as np
import pytest

import compatmesh
from conftest import signed_areas


def rotation():
    a, b = 0.7, 0.4
    rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
    return ry @ rx


def lift(polygon, offset=(10.0, -3.0, 5.0)):
    return np.c_[polygon, np.zeros(len(polygon))] @ rotation().T + offset


def test_tilted_plane_round_trip(octagon, star):
    a, b = lift(octagon), lift(star)
    result = compatmesh.triangulate([a, b])
    normal = rotation()[:, 2]
    for given, v in zip((a, b), result.vertices):
        assert v.shape == (result.stats["vertices"], 3)
        assert np.array_equal(v[:8], given)  # input vertices untouched
        assert np.abs((v - given[0]) @ normal).max() < 1e-12  # all on the plane
        corners = [v[result.faces[:, i]] for i in range(3)]
        normals = np.cross(corners[1] - corners[0], corners[2] - corners[0])
        assert (normals @ normal > 0).all()  # the winding is kept


def test_tilted_plane_matches_2d(octagon, star):
    # The construction alone (the remesher's floating-point path may differ
    # with the rounding of the rigid motion): the 2D answer, moved.
    result = compatmesh.triangulate([lift(octagon), lift(star)], remesh=False)
    flat = compatmesh.triangulate([octagon, star], remesh=False)
    assert np.array_equal(result.faces, flat.faces)
    for spatial, planar in zip(result.vertices, flat.vertices):
        back = (spatial - (10.0, -3.0, 5.0)) @ rotation()
        assert np.allclose(back[:, :2], planar, atol=1e-12)
        assert np.abs(back[:, 2]).max() < 1e-12


def test_coordinate_plane_is_exact(octagon, star):
    # x = 5: the 2D coordinates are (y, z) copied, so the answer is the 2D one.
    a = np.c_[np.full(8, 5.0), octagon]
    b = np.c_[np.full(8, 5.0), star]
    result = compatmesh.triangulate([a, b])
    flat = compatmesh.triangulate([octagon, star])
    assert np.array_equal(result.faces, flat.faces)
    assert np.array_equal(result.vertices[1][:, 1:], flat.vertices[1])
    assert (result.vertices[1][:, 0] == 5.0).all()


def test_winding_reaches_the_core(octagon, star):
    # Seen from +z one polygon turns clockwise: mismatch, as in 2D.
    clockwise = star[[0, *range(7, 0, -1)]]
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([np.c_[octagon, np.ones(8)], np.c_[clockwise, np.ones(8)]])
    assert info.value.status == "orientation mismatch"


def test_mixing_2d_and_3d(octagon, star):
    result = compatmesh.triangulate([octagon, lift(star)])
    assert result.vertices[0].shape[1] == 2 and result.vertices[1].shape[1] == 3
    assert (signed_areas(result.vertices[0], result.faces) > 0).all()


def test_not_planar(octagon, star):
    bent = lift(octagon)
    bent[5] += rotation()[:, 2] * 0.05
    with pytest.raises(ValueError, match="polygon 0: the polygon is not planar: vertex 5"):
        compatmesh.triangulate([bent, lift(star)])


def test_not_finite_3d(octagon, star):
    bad = lift(octagon)
    bad[2, 2] = np.inf
    with pytest.raises(ValueError, match="vertex 2 has a coordinate that is not finite"):
        compatmesh.triangulate([bad, lift(star)])


def pipe_section(z, radius, tilt_x, tilt_y, n=40):
    """A circle of radius about the z axis in the plane z + tilt_x x +
    tilt_y y: a pipe cut slightly askew."""
    t = 2 * np.pi * np.arange(n) / n
    x, y = radius * np.cos(t), radius * np.sin(t)
    return np.c_[x, y, z + tilt_x * x + tilt_y * y]


@pytest.mark.parametrize("correspondence", ["auto", "arclength"])
def test_sections_of_a_pipe_pair_without_a_twist(correspondence):
    """Two sections of a pipe cut askew in different directions: fitted
    frames take their axes from each polygon's spread (a quarter turn apart
    here); with the second plane's axes carried from the first's, the
    pairing chosen in the plane is the one in space: vertex 0 of one
    meets vertex 0 of the other (a quarter-turn twist before)."""
    a, b = pipe_section(0, 1.0, 0.03, 0), pipe_section(3, 1.05, 0, 0.03)
    result = compatmesh.triangulate([a, b], correspondence=correspondence)
    va, vb = result.vertices
    at = np.flatnonzero((va == a[0]).all(axis=1))[0]
    assert np.array_equal(vb[at], b[0])
