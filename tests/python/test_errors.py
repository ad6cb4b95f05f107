"""Bad input raises ValueError (compatmesh.InputError) with the core's message."""
import numpy as np
import pytest

import compatmesh


def test_self_intersection_is_located(octagon):
    crossing = octagon[[0, 2, 1, 3, 4, 5, 6, 7]]  # chords 0-2 and 1-3 cross
    with pytest.raises(ValueError, match="polygon 1") as info:
        compatmesh.triangulate([octagon, crossing])
    error = info.value
    assert isinstance(error, compatmesh.InputError)
    assert error.status == "self-intersection"  # the core's cm_status_string
    assert error.polygon == 1 and error.vertex >= 0 and error.other_vertex >= 0


def test_count_mismatch(octagon):
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([octagon, octagon[:7]], correspondence="index")
    assert info.value.status == "vertex count mismatch"


def test_too_few_polygons(octagon):
    with pytest.raises(ValueError, match="at least 2"):
        compatmesh.triangulate([octagon])
    with pytest.raises(ValueError):
        compatmesh.triangulate([])


def test_too_few_vertices():
    tiny = np.array([[0.0, 0.0], [1.0, 0.0]])
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([tiny, tiny])
    assert info.value.status == "too few vertices"


def test_repeated_vertex(octagon):
    repeated = octagon.copy()
    repeated[4] = repeated[3]
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([octagon, repeated])
    assert info.value.status == "repeated vertex" and info.value.polygon == 1


def test_closed_ring_named(octagon):
    """A closing repeat (shapely's exterior.coords) is refused by name."""
    ring = np.vstack([octagon, octagon[:1]])
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([ring, ring])
    assert info.value.status == "repeated vertex"
    assert (info.value.polygon, info.value.vertex) == (0, 8)
    assert "a closed ring: give each vertex once" in str(info.value)


def test_not_finite(octagon):
    bad = octagon.copy()
    bad[2, 1] = np.nan
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([bad, octagon])
    assert info.value.status == "non-finite coordinate"
    assert (info.value.polygon, info.value.vertex) == (0, 2)


def test_orientation_mismatch(octagon, star):
    clockwise = star[[0, *range(7, 0, -1)]]
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([octagon, clockwise])
    assert info.value.status == "orientation mismatch"


def test_message_is_the_cores(octagon):
    crossing = octagon[[0, 2, 1, 3, 4, 5, 6, 7]]
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([octagon, crossing])
    assert str(info.value).startswith("polygon 1:")


@pytest.mark.parametrize("shape", [(8,), (8, 4), (2, 8, 2)])
def test_bad_shapes(octagon, shape):
    with pytest.raises(ValueError, match=r"polygon 1: expected an n x 2 or n x 3 array"):
        compatmesh.triangulate([octagon, np.zeros(shape)])


def test_not_numbers(octagon):
    with pytest.raises((TypeError, ValueError)):
        compatmesh.triangulate([octagon, [["a", "b"]] * 8])
