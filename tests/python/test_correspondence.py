"""correspondence= and pins=: polygons of different counts pair by arc
length, each keeping its own vertices; pins are honoured; bad pins raise."""
import numpy as np
import pytest

import compatmesh
from conftest import ring


def test_different_counts_pair_by_arc_length():
    a, b = ring(12), ring(19, inner=0.4)
    r = compatmesh.triangulate([a, b])
    n = r.stats["n"]
    assert 19 <= n <= 12 + 19 - 1
    for points, vertices, source in zip((a, b), r.vertices, r.boundary_source):
        own = source["t"] == 0
        assert sorted(source["edge"][own]) == list(range(len(points)))
        assert np.array_equal(vertices[:n][own], points[source["edge"][own]])  # bit-identical


def test_spatial_input_keeps_its_points():
    a = np.c_[ring(12), np.full(12, 2.5)]
    b = np.c_[ring(17, inner=0.4), np.full(17, 7.0)]
    r = compatmesh.triangulate([a, b], correspondence="arclength", pins=[(3, 5)])
    n = r.stats["n"]
    for points, vertices, source in zip((a, b), r.vertices, r.boundary_source):
        own = source["t"] == 0
        assert np.array_equal(vertices[:n][own], points[source["edge"][own]])
        assert np.all(vertices[:, 2] == points[0, 2])
    pinned = [i for i in range(n) if r.boundary_source[0]["edge"][i] == 3 and r.boundary_source[0]["t"][i] == 0]
    assert len(pinned) == 1 and r.boundary_source[1]["edge"][pinned[0]] == 5


def test_equal_counts_keep_index():
    r = compatmesh.triangulate([ring(10), ring(10, inner=0.4)])
    assert r.stats["n"] == 10
    assert list(r.boundary_source[1]["edge"]) == list(range(10))
    assert r.stats["correspondence_choice"] == "index"


@pytest.mark.parametrize("kwargs, error, message", [
    (dict(pins=[(0, 1, 2)]), ValueError, "pin 0 has 3 vertices for 2 polygons"),
    (dict(pins=[(0, 40)]), compatmesh.InputError, "out of range"),
    (dict(pins=[(0, -1)]), ValueError, "must not be negative"),
    (dict(pins="0,1"), TypeError, "pins must be a sequence"),
    (dict(correspondence="index"), compatmesh.InputError, "vertex count mismatch|has 19 vertices"),
    (dict(correspondence="nearest"), ValueError, "unknown correspondence 'nearest'"),
])
def test_bad_pins_and_modes(kwargs, error, message):
    with pytest.raises(error, match=message):
        compatmesh.triangulate([ring(12), ring(19, inner=0.4)], **kwargs)


def test_pin_corners():
    """Two rectangles numbered from different points: pin_corners_deg ties
    each corner to the same corner (arc length, the default with it)."""
    def rectangle(w, h, per_side, start):
        corners = [(0, 0), (w, 0), (w, h), (0, h)]
        pts = [np.add(corners[i], j / per_side[i] * np.subtract(corners[(i + 1) % 4], corners[i]))
               for i in range(4) for j in range(per_side[i])]
        starts = np.cumsum([0] + per_side[:3])
        return np.roll(np.array(pts, dtype=float), -start, axis=0), (starts - start) % len(pts)
    a, ca = rectangle(4.0, 2.0, [5, 3, 5, 3], 2)
    b, cb = rectangle(6.0, 2.5, [4, 2, 3, 2], 1)
    r = compatmesh.triangulate([a, b], pin_corners_deg=30)
    sa, sb = r.boundary_source
    both = (sa["t"] == 0) & (sb["t"] == 0)
    assert set(zip(ca, cb)) <= set(zip(sa["edge"][both], sb["edge"][both]))
    assert r.stats["correspondence_choice"] == "corners"
    with pytest.raises(compatmesh.InputError, match="polygon 1 has no corner to pin"):
        compatmesh.triangulate([a, ring(20, jitter=False)], pin_corners_deg=30)
    with pytest.raises(compatmesh.InputError, match="corner pins need the arclength or auto"):
        compatmesh.triangulate([a, a], pin_corners_deg=30, correspondence="index")


def test_max_edge():
    """Boundary edges split to at most max_edge in both polygons, also with
    the index correspondence (vertex i stays on vertex i)."""
    a, b = ring(10), ring(10, inner=0.5) * 1.5
    r = compatmesh.triangulate([a, b], correspondence="index", max_edge=0.3)
    n = r.stats["n"]
    assert n > 10
    for points, vertices, source in zip((a, b), r.vertices, r.boundary_source):
        own = source["t"] == 0
        assert list(source["edge"][own]) == list(range(10))
        assert np.array_equal(vertices[:n][own], points)
        edges = np.linalg.norm(np.roll(vertices[:n], -1, axis=0) - vertices[:n], axis=1)
        assert edges.max() <= 0.3 * (1 + 1e-12)
    assert np.array_equal(r.boundary_source[0]["t"] == 0, r.boundary_source[1]["t"] == 0)
    with pytest.raises(compatmesh.InputError, match="max_edge is -1"):
        compatmesh.triangulate([a, b], max_edge=-1)


def test_affine_image_is_the_identity():
    a = ring(15)
    b = np.roll(a @ np.array([[2.0, 0.5], [0.3, 1.5]]).T + [3.0, -1.0], -4, axis=0)
    r = compatmesh.triangulate([a, b], correspondence="auto", remesh=False)
    assert r.stats["n"] == 15 and r.stats["steiner"] == 0
    assert list(r.boundary_source[1]["edge"]) == [(i - 4) % 15 for i in range(15)]
    assert r.stats["correspondence_choice"] == "affine"


def test_similarity_mode():
    # A ring against a turned, scaled copy with every edge split: the
    # similarity choice pairs them by arc length from the start it finds,
    # the copy's even vertices on the ring's own (by name or enum alike).
    a = ring(12)
    turned = np.roll(0.5 * a @ np.array([[0.6, -0.8], [0.8, 0.6]]).T + [2.0, 1.0], -5, axis=0)
    b = np.empty((24, 2))
    b[0::2], b[1::2] = turned, 0.5 * (turned + np.roll(turned, -1, axis=0))
    for mode in ("similarity", compatmesh.Correspondence.SIMILARITY):
        r = compatmesh.triangulate([a, b], correspondence=mode, remesh=False)
        assert r.stats["n"] == 24
        ea, eb = r.boundary_source[0]["edge"], r.boundary_source[1]["edge"]
        assert (r.boundary_source[1]["t"] == 0).all()
        even = eb % 2 == 0
        assert (r.boundary_source[0]["t"][even] == 0).all()
        assert list(ea[even]) == [(e // 2 + 5) % 12 for e in eb[even]]


def lobes(n):
    t = 2 * np.pi * np.arange(n) / n
    r = 1 + 0.4 * np.cos(3 * t)
    return np.c_[r * np.cos(t), r * np.sin(t)]


def twelve_star(r0, r1, phase=0.0, sx=1.0, sy=1.0):
    t, r = phase + np.pi * np.arange(12) / 6, np.where(np.arange(12) % 2, r1, r0)
    return np.c_[sx * r * np.cos(t), sy * r * np.sin(t)]


def test_stats_name_the_correspondence_made():
    # auto keeps the conformal pairing of a three-lobed outline and an
    # ellipse (ceiling 45.0 degrees against the similarity choice's 40.9),
    # the similarity choice for two 12-pointed stars (41.6 against 23.6);
    # pins make it arc length between them; with one hole both loops at
    # once through the annulus; with two holes the outer loops' pairing
    # (conformal or similarity, the holes' places weighing in).
    t = 2 * np.pi * np.arange(36) / 36
    ellipse = np.c_[2 * np.cos(t), 0.5 * np.sin(t)]
    cases = [
        (dict(correspondence="auto"), [lobes(40), ellipse], "conformal"),
        (dict(correspondence="auto"), [twelve_star(1.0, 0.7), twelve_star(0.8, 0.5, 0.5, 1.4, 0.7)], "similarity"),
        (dict(correspondence="similarity"), [lobes(40), ellipse], "similarity"),
        (dict(correspondence="arclength"), [lobes(40), ellipse], "arclength"),
        (dict(pins=[(0, 0), (20, 18)]), [lobes(40), ellipse], "arclength"),
    ]
    for kwargs, polygons, choice in cases:
        r = compatmesh.triangulate(polygons, remesh=False, **kwargs)
        assert r.stats["correspondence_choice"] == choice, (kwargs, choice)
    for polygons in ([lobes(40), ellipse], [twelve_star(1.0, 0.7), twelve_star(0.8, 0.5, 0.5, 1.4, 0.7)]):
        one_hole = [[p, 0.1 * p[::-1] + p.mean(axis=0)] for p in polygons]
        r = compatmesh.triangulate(one_hole, correspondence="auto", remesh=False)
        assert r.stats["holes"] == 1 and r.stats["correspondence_choice"] == "annulus"
        two_holes = [[p] + [0.1 * p[::-1] + p.mean(axis=0) + (dx, 0) for dx in (-0.3, 0.3)] for p in polygons]
        r = compatmesh.triangulate(two_holes, correspondence="auto", remesh=False)
        assert r.stats["holes"] == 2 and r.stats["correspondence_choice"] in ("conformal", "similarity")
