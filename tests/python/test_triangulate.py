"""The output contract of compatmesh.triangulate: shapes, order, orientation,
half-edges, stats."""
import numpy as np
import pytest

import compatmesh
from conftest import ring, signed_areas


def test_shapes_and_types(octagon, star):
    result = compatmesh.triangulate([octagon, star])
    n, m = 8, len(result.faces)
    assert result.faces.shape == (m, 3) and result.faces.dtype == np.int32
    assert len(result.vertices) == 2
    nv = result.stats["vertices"]
    for v in result.vertices:
        assert v.shape == (nv, 2) and v.dtype == np.float64
    # Euler: a triangulated disk with n boundary and s interior vertices.
    assert m == n + 2 * result.stats["steiner"] - 2 == result.stats["triangles"]
    assert nv == n + result.stats["steiner"]
    assert result.faces.min() == 0 and result.faces.max() == nv - 1
    assert "2 geometries" in repr(result)


def test_input_vertices_first_and_identical(octagon, star):
    result = compatmesh.triangulate([octagon, star])
    assert np.array_equal(result.vertices[0][:8], octagon)
    assert np.array_equal(result.vertices[1][:8], star)


def test_every_triangle_counter_clockwise(octagon, star):
    result = compatmesh.triangulate([octagon, star])
    for v in result.vertices:
        assert (signed_areas(v, result.faces) > 0).all()


def test_clockwise_input_is_reversed_internally(octagon, star):
    cw = [p[[0, *range(7, 0, -1)]] for p in (octagon, star)]
    result = compatmesh.triangulate(cw)
    assert result.stats["reversed_input"] is True
    assert np.array_equal(result.vertices[0][:8], cw[0])
    for v in result.vertices:
        assert (signed_areas(v, result.faces) > 0).all()


def test_halfedges_match_faces(octagon, star):
    result = compatmesh.triangulate([octagon, star])
    he = result.halfedges
    nxt, to, face = he["next"], he["to_vertex"], he["face"]
    nh = len(nxt)
    assert nh % 2 == 0 and all(a.dtype == np.int32 for a in he.values())
    h = np.arange(nh)
    frm = to[h ^ 1]
    # next continues where h ends, and a face's half-edges cycle in 3 steps.
    assert (frm[nxt] == to).all()
    inner = face >= 0
    assert (nxt[nxt[nxt[h[inner]]]] == h[inner]).all()
    assert (face[nxt[h[inner]]] == face[inner]).all()
    # face_halfedge runs from corner 0 to corner 1.
    fh = he["face_halfedge"]
    assert (frm[fh] == result.faces[:, 0]).all() and (to[fh] == result.faces[:, 1]).all()
    assert (face[fh] == np.arange(len(result.faces))).all()
    # Boundary: exactly the n polygon edges, run clockwise (i+1 -> i).
    boundary = h[~inner]
    assert len(boundary) == 8
    assert sorted(zip(frm[boundary], to[boundary])) == sorted(((i + 1) % 8, i) for i in range(8))
    # vertex_halfedge leaves the vertex; for polygon vertices it is on the boundary.
    vh = he["vertex_halfedge"]
    assert (frm[vh] == np.arange(len(vh))).all()
    assert (face[vh[:8]] == -1).all()


def test_stats_and_quality(octagon, star):
    result = compatmesh.triangulate([octagon, star])
    s = result.stats
    assert (s["n"], s["k"]) == (8, 2)
    for key in ("fallback_count", "seconds_validate", "seconds_build", "seconds_check"):
        assert s[key] >= 0
    assert len(s["quality"]) == 2
    for q in s["quality"]:
        assert 0 < q["min_angle_deg"] <= 60 <= q["max_angle_deg"] < 180
        for key in ("pct_below_10deg", "pct_below_15deg", "pct_below_20deg"):
            assert 0 <= q[key] <= 100


def test_more_than_two_polygons():
    polygons = [ring(10, inner) for inner in (1.0, 0.7, 0.5)]
    result = compatmesh.triangulate(polygons)
    assert len(result.vertices) == 3 and len(result.stats["quality"]) == 3
    for v in result.vertices:
        assert (signed_areas(v, result.faces) > 0).all()


def test_accepts_sequences_and_integer_arrays():
    square = [[0, 0], [2, 0], [2, 2], [0, 2]]
    kite = np.array([[0, 0], [3, 1], [2, 2], [1, 3]], dtype=np.int64)
    result = compatmesh.triangulate((square, kite))
    assert result.vertices[1].dtype == np.float64
    assert np.array_equal(result.vertices[1][:4], kite)


def test_result_arrays_are_independent_copies(octagon, star):
    first = compatmesh.triangulate([octagon, star])
    faces = first.faces.copy()
    second = compatmesh.triangulate([octagon, star])
    second.faces[:] = 0
    assert np.array_equal(first.faces, faces)


def test_module_metadata():
    assert compatmesh.__version__.count(".") == 2
    assert int(compatmesh.Method.OVERLAY) == 0
    assert issubclass(compatmesh.InputError, ValueError)


if __name__ == "__main__":
    raise SystemExit(pytest.main([__file__]))
