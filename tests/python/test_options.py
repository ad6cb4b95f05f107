"""Keyword options map by name to the C options; progress and cancelling."""
import numpy as np
import pytest

import compatmesh
from conftest import signed_areas


def test_unknown_keyword_is_a_type_error(octagon, star):
    with pytest.raises(TypeError, match="unexpected keyword argument 'min_angel'"):
        compatmesh.triangulate([octagon, star], min_angel=30)


@pytest.mark.parametrize("name", ["overlay", "partition"])
def test_method_by_enum_int_and_name(octagon, star, name):
    enum = getattr(compatmesh.Method, name.upper())
    faces = [
        compatmesh.triangulate([octagon, star], method=m, remesh=False).faces.tolist()
        for m in (enum, int(enum), name)
    ]
    assert faces[0] == faces[1] == faces[2]


def test_remesh_off_returns_the_construction(octagon, star):
    result = compatmesh.triangulate([octagon, star], remesh=False)
    s = result.stats
    assert s["remesh_iterations"] == 0 and s["seconds_remesh"] == 0
    assert s["steiner"] == s["steiner_before_remesh"]
    assert s["quality"] == s["quality_before_remesh"]


def test_remesh_raises_the_smallest_angle_over_all_geometries(octagon, star):
    s = compatmesh.triangulate([octagon, star]).stats
    after = min(q["min_angle_deg"] for q in s["quality"])
    before = min(q["min_angle_deg"] for q in s["quality_before_remesh"])
    assert after > before


def test_max_steiner_zero_adds_no_vertices(octagon, star):
    s = compatmesh.triangulate([octagon, star], max_steiner=0).stats
    assert s["steiner"] <= s["steiner_before_remesh"]


@pytest.mark.parametrize("remesher", ["greedy", "map"])
def test_remesher_by_name_and_enum(octagon, star, remesher):
    by_name = compatmesh.triangulate([octagon, star], remesher=remesher)
    by_enum = compatmesh.triangulate([octagon, star], remesher=getattr(compatmesh.Remesher, remesher.upper()))
    assert np.array_equal(by_name.faces, by_enum.faces)
    with pytest.raises(ValueError, match="unknown remesher 'lazy'"):
        compatmesh.triangulate([octagon, star], remesher="lazy")


@pytest.mark.parametrize("smoothing", ["laplacian", "angle", "weighted", "combined"])
def test_smoothing_by_name_and_enum(octagon, star, smoothing):
    by_name = compatmesh.triangulate([octagon, star], smoothing=smoothing)
    by_enum = compatmesh.triangulate([octagon, star], smoothing=getattr(compatmesh.Smoothing, smoothing.upper()))
    assert np.array_equal(by_name.faces, by_enum.faces)


def test_numeric_options_reach_the_core(octagon, star):
    compatmesh.triangulate([octagon, star], min_angle_deg=20, k_split=1, area_every=2, max_iterations=5)
    for name, value in [("min_angle_deg", 70), ("k_split", -1), ("max_steiner", -5), ("area_every", -1),
                        ("max_iterations", -1), ("smoothing", 9), ("method", 99),
                        ("remesher", 7), ("time_limit", -1.0)]:
        with pytest.raises(ValueError, match=name) as info:
            compatmesh.triangulate([octagon, star], **{name: value})
        assert info.value.status == "invalid argument"


def test_time_limit_reaches_the_core(octagon, star):
    """A limit spent before the remesher starts: no refinement round, and
    the stats say so; without one nothing is said."""
    free = compatmesh.triangulate([octagon, star])
    assert free.stats["time_limit_reached"] is False and free.stats["remesh_iterations"] > 0
    spent = compatmesh.triangulate([octagon, star], time_limit=1e-6)
    assert spent.stats["time_limit_reached"] is True and spent.stats["remesh_iterations"] == 0
    assert all(signed_areas(v, spent.faces).min() > 0 for v in spent.vertices)


def test_numeric_options_check_types(octagon, star):
    with pytest.raises(TypeError, match="k_split must be an int"):
        compatmesh.triangulate([octagon, star], k_split=1.5)
    with pytest.raises(TypeError, match="min_angle_deg must be a number"):
        compatmesh.triangulate([octagon, star], min_angle_deg="25")
    compatmesh.triangulate([octagon, star], min_angle_deg=25)  # an int is a number


def test_bad_names(octagon, star):
    with pytest.raises(ValueError, match="unknown method 'magic'"):
        compatmesh.triangulate([octagon, star], method="magic")
    with pytest.raises(ValueError, match="unknown smoothing 'gentle'"):
        compatmesh.triangulate([octagon, star], smoothing="gentle")


def test_progress_is_called_in_order(octagon, star):
    calls = []
    compatmesh.triangulate([octagon, star], progress=lambda f, stage: calls.append((f, stage)))
    fractions = [f for f, _ in calls]
    assert calls and fractions == sorted(fractions)
    assert all(0.0 <= f <= 1.0 and isinstance(s, str) and s for f, s in calls)


def test_progress_returning_true_cancels(octagon, star):
    with pytest.raises(compatmesh.Cancelled):
        compatmesh.triangulate([octagon, star], progress=lambda f, stage: f >= 0.5)


def test_progress_exception_propagates(octagon, star):
    def fails(fraction, stage):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        compatmesh.triangulate([octagon, star], progress=fails)


def test_progress_must_be_callable(octagon, star):
    with pytest.raises(TypeError, match="callable"):
        compatmesh.triangulate([octagon, star], progress=3)
    compatmesh.triangulate([octagon, star], progress=None)


def test_progress_user_is_not_for_python(octagon, star):
    with pytest.raises(TypeError, match="closure"):
        compatmesh.triangulate([octagon, star], progress_user=object())


def test_planarity_tolerance_keyword(octagon, star):
    bent = np.c_[octagon, np.zeros(8)]
    bent[3, 2] = 1e-3  # off the plane by 1e-3 of a polygon about 4 across
    flat = np.c_[star, np.zeros(8)]
    with pytest.raises(ValueError, match="not planar"):
        compatmesh.triangulate([bent, flat])
    compatmesh.triangulate([bent, flat], planarity_tolerance=1e-3)


def test_ceiling_in_stats_and_off_by_keyword():
    # A 5 x 1 rectangle against the unit square, corners corresponding: the
    # four corners' moduli are 5 and 1, so the certified distortion is at
    # most 5 and the bound near K^-1(5), 35.0 degrees.
    rectangle = np.array([[0.0, 0.0], [5.0, 0.0], [5.0, 1.0], [0.0, 1.0]])
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    s = compatmesh.triangulate([rectangle, square]).stats
    assert 4.5 < s["modulus_distortion"] <= 5
    assert 35.0 < s["correspondence_bound_deg"] < 36.7
    assert s["corner_fan_cap_deg"] == pytest.approx(45)
    assert s["ceiling_deg"] == min(s["corner_fan_cap_deg"], s["correspondence_bound_deg"])
    assert sorted(s["distortion_quad"]) == [0, 1, 2, 3]
    assert s["correspondence_bound_before_deg"] is None
    assert min(q["min_angle_deg"] for q in s["quality"]) <= s["ceiling_deg"]
    off = compatmesh.triangulate([rectangle, square], ceiling=False).stats
    assert off["ceiling_deg"] == 0 and off["seconds_ceiling"] == 0


def test_ceiling_before_and_after_auto(octagon, star):
    s = compatmesh.triangulate([octagon, star[::-1][:-1]], correspondence="auto").stats
    assert 0 < s["correspondence_bound_before_deg"] <= 60
    assert 0 < s["correspondence_bound_deg"] <= 60
