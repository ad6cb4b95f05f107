"""Polygons with holes: a list of arrays per polygon, the outer loop first.
Each fixture states what it expects (valid, the hole count, Euler
characteristic 1 - h, the loops bit-identical and first, areas adding up to
the outer loop's minus the holes'); bad input raises InputError naming the
polygon and loop."""
from fractions import Fraction

import numpy as np
import pytest

import compatmesh


def circle(cx, cy, r, m, direction=1):
    a = direction * 2 * np.pi * np.arange(m) / m
    return np.c_[cx + r * np.cos(a), cy + r * np.sin(a)]


def square(h, m, direction=1):
    corners = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)], float)
    if direction < 0:
        corners = corners[[0, 3, 2, 1]]
    side = m // 4
    t = np.arange(side)[:, None] / side
    return h * np.vstack([(1 - t) * corners[c] + t * corners[(c + 1) % 4] for c in range(4)])


def exact_area2(points):
    """Twice the signed area, exactly (shoelace over Fractions)."""
    p = [(Fraction(x), Fraction(y)) for x, y in points]
    return sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(p, p[1:] + p[:1]))


def check(result, polygons):
    holes = len(polygons[0]) - 1
    n = sum(len(loop) for loop in polygons[0])
    faces = result.faces
    assert result.stats["holes"] == holes and result.stats["bridges"] == 2 * holes
    edges = {(a, b) for f in faces for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    undirected = {tuple(sorted(e)) for e in edges}
    assert len(result.vertices[0]) - len(undirected) + len(faces) == 1 - holes
    for loops, vertices in zip(polygons, result.vertices):
        assert np.array_equal(vertices[:n], np.vstack(loops))
        area = sum(abs(exact_area2(tri)) for tri in vertices[faces].tolist())
        outer, *inner = (abs(exact_area2(loop.tolist())) for loop in loops)
        assert area == outer - sum(inner)
        a, b, c = (vertices[faces[:, i]] for i in range(3))
        assert (((b - a)[:, 0] * (c - a)[:, 1] - (c - a)[:, 0] * (b - a)[:, 1]) > 0).all()


def test_square_and_disc():
    a = [square(1, 16), square(0.4, 8, -1)]
    b = [circle(0, 0, 1, 16), circle(0.3, 0.2, 0.35, 8, -1)]
    result = compatmesh.triangulate([a, b])
    check(result, [a, b])
    assert min(q["min_angle_deg"] for q in result.stats["quality"]) >= 20


# A plate with three bolt holes and its sheared, moved copy.
PLATE = [square(2, 24)] + [circle(x, y, 0.45, 10, -1) for x, y in ((-1, -1), (1, -0.8), (0, 1))]
PLATE_MOVED = [loop @ np.array([[1.0, 0.4], [0.0, 1.0]]).T + [0.3, -0.1] for loop in PLATE]


def test_plate_three_holes_as_lists():
    result = compatmesh.triangulate([[loop.tolist() for loop in PLATE], tuple(PLATE_MOVED)], remesh=False)
    check(result, [PLATE, PLATE_MOVED])


def test_auto_pairs_holes_by_position():
    """The moved plate's holes listed in another order: auto pairs each with
    the plate's hole at the same place (the output lists them in the
    plate's order) and says how many moved; the square plate's quarter
    turns take its outline onto itself, and the holes choose the turn: the
    corner (-2, -2) pairs with its own image."""
    shuffled = [PLATE_MOVED[0], PLATE_MOVED[2], PLATE_MOVED[3], PLATE_MOVED[1]]
    result = compatmesh.triangulate([PLATE, shuffled], correspondence="auto", remesh=False)
    assert result.stats["holes_moved"] == 3
    n = sum(len(loop) for loop in PLATE)
    assert np.array_equal(result.vertices[1][:n], np.vstack(PLATE_MOVED))
    assert np.array_equal(result.vertices[0][:n], np.vstack(PLATE))


def test_bad_input_names_polygon_and_loop():
    a = [square(1, 8), square(0.4, 4, -1)]
    with pytest.raises(compatmesh.InputError, match="hole 1 \\(loop 1\\) has 5 vertices") as info:
        compatmesh.triangulate([a, [circle(0, 0, 1, 8), circle(0, 0, 0.3, 5, -1)]], correspondence="index")
    assert info.value.status == "vertex count mismatch" and info.value.polygon == 1
    outside = [square(1, 8), square(0.4, 4, -1) + [3, 0]]
    with pytest.raises(compatmesh.InputError, match="polygon 1: hole 1 \\(loop 1\\) lies outside") as info:
        compatmesh.triangulate([a, outside])
    assert info.value.vertex == 8
    with pytest.raises(ValueError, match="polygon 1, loop 1: expected an n x 2 array"):
        compatmesh.triangulate([a, [square(1, 8), np.zeros((4, 3))]])
    with pytest.raises(compatmesh.InputError, match="polygon 1 has 0 holes but polygon 0 has 1"):
        compatmesh.triangulate([a, square(1, 12)])


def test_loops_of_different_sizes_pair_by_default():
    """Loops of different sizes take the auto correspondence loop by loop:
    every input vertex is a boundary vertex, bit-identical; one hole."""
    a = [square(1, 16), square(0.4, 8, -1)]
    b = [circle(0, 0, 1, 23), circle(0.3, 0.2, 0.35, 11)]
    result = compatmesh.triangulate([a, b])
    n = result.stats["n"]
    assert result.stats["holes"] == 1 and n >= 23 + 11
    for loops, vertices in zip((a, b), result.vertices):
        boundary = {tuple(p) for p in vertices[:n]}
        assert all(tuple(p) in boundary for loop in loops for p in loop)


def test_morph_and_sweep_with_holes():
    """The holes stay empty: every frame's triangles are counter-clockwise and
    cover the outer loop's area minus the hole's; the sweep's tetrahedra are
    positive."""
    a = [square(1, 16), square(0.4, 8, -1)]
    b = [circle(0, 0, 1, 16), circle(0.3, 0.2, 0.35, 8, -1)]
    morph = compatmesh.morph([a, b], frames=3)
    tri = morph.cells["triangle"]
    for frame in morph.points:
        e1, e2 = frame[tri[:, 1]] - frame[tri[:, 0]], frame[tri[:, 2]] - frame[tri[:, 0]]
        areas = 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
        outer, hole = (abs(exact_area2(frame[lo:hi].tolist())) / 2 for lo, hi in ((0, 16), (16, 24)))
        assert areas.min() > 0 and abs(areas.sum() - (outer - hole)) < 1e-9 * outer
    sweep = compatmesh.sweep([a, b], tets=True)
    assert sweep.quality["min_scaled_jacobian"] > 0 and len(sweep.cells["tetra"]) == 3 * len(sweep.cells["wedge"])


def crowded(r, m, dense):
    """A clockwise circle of m points, dense of them in its first 30 degrees."""
    a = -np.r_[np.linspace(0, np.pi / 6, dense, endpoint=False), np.linspace(np.pi / 6, 2 * np.pi, m - dense, endpoint=False)]
    return np.c_[r * np.cos(a), r * np.sin(a)]


def test_remesher_splits_hole_loop_edges():
    """Auto: arc length puts a crowded stretch of the first hole on one
    edge of the second's hexagon, and the remesher splits edges of the hole
    loop there (the run without remeshing has the same 24 hole vertices in
    the first polygon: the cap split adds none on this pair). Every boundary
    point is P[e] + t (P[e+1] - P[e]) of its own loop bit for bit, the
    loops come one after another (outer first), every input vertex once and
    in its loop's order, the outer loop counter-clockwise and the hole
    clockwise, and the meshes are valid."""
    a = [square(1, 16), crowded(0.5, 24, 16)]
    b = [circle(0, 0, 1, 20), circle(0.2, 0.1, 0.4, 6, -1)]
    r = compatmesh.triangulate([a, b], correspondence="auto")
    plain = compatmesh.triangulate([a, b], correspondence="auto", remesh=False)
    n = r.stats["n"]
    loop_of = [np.searchsorted(np.cumsum([len(x) for x in loops]), src["edge"], side="right")
               for loops, src in zip((a, b), r.boundary_source)]
    plain_hole = (np.searchsorted([16, 40], plain.boundary_source[0]["edge"], side="right") == 1).sum()
    assert (loop_of[0] == 1).sum() > plain_hole == 24
    for loops, vertices, source, loop in zip((a, b), r.vertices, r.boundary_source, loop_of):
        assert (np.diff(loop) >= 0).all() and list(loop) == list(loop_of[0])
        starts = np.r_[0, np.cumsum([len(x) for x in loops])]
        points = np.vstack(loops)
        for i in range(n):
            e, t, l = source["edge"][i], source["t"][i], loop[i]
            p, q = points[e], points[starts[l] + (e - starts[l] + 1) % len(loops[l])]
            assert tuple(vertices[i]) == (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])), i
        for l, lp in enumerate(loops):
            own = (loop == l) & (source["t"] == 0)
            order = list(source["edge"][own] - starts[l])
            m = len(lp)
            assert order in ([(order[0] + i) % m for i in range(m)], [(order[0] - i) % m for i in range(m)])
            ring = vertices[:n][loop == l]
            area2 = exact_area2(ring.tolist())
            assert area2 > 0 if l == 0 else area2 < 0
    faces = r.faces
    edges = {tuple(sorted(e)) for f in faces for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    assert len(r.vertices[0]) - len(edges) + len(faces) == 0 and r.stats["holes"] == 1
    for vertices in r.vertices:
        p, q, s = (vertices[faces[:, i]] for i in range(3))
        assert (((q - p)[:, 0] * (s - p)[:, 1] - (s - p)[:, 0] * (q - p)[:, 1]) > 0).all()
