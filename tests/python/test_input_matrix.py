"""The bad-input matrix (tests/bad_input/cases.txt) through the Python
module, as n x 2 and as n x 3 arrays: compatmesh.InputError (a ValueError) with the core's status, message
and location for every bad case; a result that keeps the input vertices
bit-identical and has positive triangles in every geometry for the legal
ones (each triangle counter-clockwise, checked exactly)."""
import os
from fractions import Fraction
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bad_input"))
import cases as matrix  # noqa: E402

import compatmesh  # noqa: E402

CASES = matrix.load()


@pytest.mark.parametrize("columns", [2, 3], ids=["xy", "xyz"])
@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_case(case, columns):
    # n x 3 in the plane z = 0 goes through the plane fit first; it must
    # answer exactly like n x 2.
    polygons = [np.array(p, dtype=float).reshape(-1, 2) for p in case.polygons]
    if columns == 3:
        polygons = [np.c_[p, np.zeros(len(p))] for p in polygons]
    if case.status == "ok":
        result = compatmesh.triangulate(polygons)
        assert len(result.faces) > 0
        for g, p in enumerate(polygons):
            v = np.asarray(result.vertices[g])
            assert np.array_equal(v[:len(p)], p)
            v = v[:, :2]
            for face in result.faces:  # exact orientation, any magnitude
                (ax, ay), (bx, by), (cx, cy) = (map(Fraction, v[i]) for i in face)
                assert (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0
        return
    with pytest.raises(ValueError) as info:  # the matrix states the index contract
        compatmesh.triangulate(polygons, correspondence="index")
    error = info.value
    assert case.fragment in str(error) and "\n" not in str(error)
    assert isinstance(error, compatmesh.InputError)
    assert error.status == case.status
    if case.polygon is not None:
        assert error.polygon == case.polygon
    if case.vertex is not None:
        assert error.vertex == case.vertex
