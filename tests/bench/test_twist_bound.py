"""bench/twist_bound.py: the certified ceiling of an annulus whose hole is
turned, on the fixtures of tests/core/hole_fixtures.h (a 24-gon of radius
1 around a 12-gon of radius 0.6 turned half a turn, and 12 around 6), and
never below what compatmesh reaches on them."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
from correspondence_bound import angle_bound  # noqa: E402
from twist_bound import twist_bound  # noqa: E402


def circle(radius, count, clockwise=False):
    a = 2 * math.pi * np.arange(count) / count * (-1 if clockwise else 1)
    return np.c_[radius * np.cos(a), radius * np.sin(a)]


def turned_annulus(outer, hole, theta=math.pi):
    o, h = circle(1.0, outer), circle(0.6, hole, clockwise=True)
    c, s = math.cos(theta), math.sin(theta)
    return o, h, o.copy(), h @ np.array([[c, s], [-s, c]])


@pytest.mark.parametrize("outer, hole", [(24, 12), (12, 6)])
def test_turned_hole_ceiling(outer, hole):
    """ln(R/r) with R the outer circumradius and r the hole's inradius; K
    at least 1 + (pi / ln(R/r))^2; the ceiling is angle_bound(K)."""
    theta, s_bound, k_bound, ceiling = twist_bound(*turned_annulus(outer, hole))
    expected_s = math.log(1 / (0.6 * math.cos(math.pi / hole)))
    assert abs(abs(theta) - math.pi) < 1e-12 and s_bound == pytest.approx(expected_s, rel=1e-12)
    assert k_bound == pytest.approx(1 + (math.pi / expected_s) ** 2, rel=1e-12)
    assert ceiling == pytest.approx(angle_bound(k_bound), abs=1e-9)
    # the 24 / 12 fixture cannot reach min(15, c / 3) = 15 degrees
    assert (ceiling < 15) == (outer == 24)


def test_no_turn_no_bound():
    *_, ceiling = twist_bound(*turned_annulus(24, 12, theta=0.0))
    assert ceiling == 60.0


@pytest.mark.parametrize("change, message", [
    (lambda o, h, ob, hb: (o, h, ob * 1.01, hb), "outer loops differ"),
    (lambda o, h, ob, hb: (o, h + [0.05, 0], ob, hb + [0.05, 0]), "not symmetric"),
    (lambda o, h, ob, hb: (o, h, ob, hb[:-1]), "different vertex counts"),
    (lambda o, h, ob, hb: (o, h, ob, hb * 0.9), "not the first turned"),
])
def test_refused_where_the_argument_does_not_hold(change, message):
    with pytest.raises(ValueError, match=message):
        twist_bound(*change(*turned_annulus(24, 12)))


@pytest.mark.parametrize("outer, hole", [(24, 12), (12, 6)])
def test_compatmesh_stays_under_the_ceiling(tmp_path, outer, hole):
    """A certified ceiling is never beaten: compatmesh's result on the pair
    (index correspondence, the default remeshing) is at most it."""
    o, h, ob, hb = turned_annulus(outer, hole)
    for name, loops in (("a.xy", (o, h)), ("b.xy", (ob, hb))):
        (tmp_path / name).write_text(">\n".join("".join(f"{x:.17g} {y:.17g}\n" for x, y in loop) for loop in loops))
    run = subprocess.run([os.environ["COMPATMESH"], "triangulate", "a.xy", "b.xy", "--out-dir", "out",
                          "--no-preview", "--quiet"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    reached = min(m["min_angle_deg"] for m in report["meshes"])
    *_, ceiling = twist_bound(o, h, ob, hb)
    assert 0 < reached <= ceiling
