"""bench/twist_bound.py: the certified ceiling of an annulus whose hole is
turned, on the fixtures of tests/core/hole_fixtures.h (a 24-gon of radius
1 around a 12-gon of radius 0.6 turned half a turn, and 12 around 6), and
never below what compatmesh reaches on them; the extremal dilatation of a
twist, and the finite element bracket of the modulus S."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
from correspondence_bound import angle_bound  # noqa: E402
from twist_bound import modulus_bracket, twist_bound, twist_dilatation  # noqa: E402

# a coarse mesh for the flow bound keeps the tests quick: the bound is
# certified on any mesh, and the fixtures' ceilings stay below 15 on it
MESH = 0.02


def circle(radius, count, clockwise=False):
    a = 2 * math.pi * np.arange(count) / count * (-1 if clockwise else 1)
    return np.c_[radius * np.cos(a), radius * np.sin(a)]


def turned_annulus(outer, hole, theta=math.pi):
    o, h = circle(1.0, outer), circle(0.6, hole, clockwise=True)
    c, s = math.cos(theta), math.sin(theta)
    return o, h, o.copy(), h @ np.array([[c, s], [-s, c]])


@pytest.mark.parametrize("outer, hole", [(24, 12), (12, 6)])
def test_turned_hole_ceiling(outer, hole):
    """ln(R/r) with R the outer circumradius and r the hole's inradius; S
    at most the smaller of it and the flow bound; K + 1/K = 2 + (pi / S)^2;
    the ceiling is angle_bound(K)."""
    bound = twist_bound(*turned_annulus(outer, hole), mesh_size=MESH)
    expected_s = math.log(1 / (0.6 * math.cos(math.pi / hole)))
    assert abs(abs(bound.theta) - math.pi) < 1e-12 and bound.s_ring == pytest.approx(expected_s, rel=1e-12)
    # the flow bound is the sharper one here, and brackets S with the primal
    assert bound.s_low <= bound.s_flow == bound.s_bound < bound.s_ring
    # the annulus about the centre inside D: S at least the log of its radii
    assert bound.s_bound > math.log(math.cos(math.pi / outer) / 0.6)
    assert bound.k_bound == pytest.approx(twist_dilatation(math.pi / bound.s_bound), rel=1e-12)
    assert bound.ceiling == pytest.approx(angle_bound(bound.k_bound), abs=1e-9)
    # neither fixture can reach min(15, c / 3) = 15 degrees
    assert bound.ceiling < 15


@pytest.mark.parametrize("gamma", [0.0, 0.3, 1.0, -2.5, 5.97, 40.0])
def test_twist_dilatation_is_the_affine_twists(gamma):
    """K + 1/K = 2 + gamma^2 is the ratio of the singular values of the
    twist (s, a) -> (s, a + gamma s), and the largest over the helices'
    slopes m of (1 + (m + gamma)^2) / (1 + m^2)."""
    singular = np.linalg.svd(np.array([[1.0, 0.0], [gamma, 1.0]]), compute_uv=False)
    k = twist_dilatation(gamma)
    assert k == pytest.approx(singular[0] / singular[1], rel=1e-12)
    assert k + 1 / k == pytest.approx(2 + gamma * gamma, rel=1e-12)
    m = np.linspace(-3 * abs(gamma) - 3, 3 * abs(gamma) + 3, 200001)
    family = (1 + (m + gamma) ** 2) / (1 + m * m)
    assert family.max() <= k * (1 + 1e-12) and family.max() == pytest.approx(k, rel=1e-6)
    # m = 0, the radial segments: the bound before
    assert k >= 1 + gamma * gamma


def test_twist_dilatation_grows_with_the_turn():
    """So the least |theta + 2 pi k| binds."""
    gammas = np.linspace(0, 30, 301)
    assert np.all(np.diff([twist_dilatation(g) for g in gammas]) > 0)
    assert twist_dilatation(-3.0) == twist_dilatation(3.0)


def test_round_annulus_bracket():
    """A 256-gon of radius 1 around a 128-gon of radius 0.6: S lies between
    the logs of the round annuli inside and around D, and the bracket holds
    ln(1 / 0.6) to 2e-4 on the coarse mesh."""
    lower, upper = modulus_bracket(circle(1.0, 256), circle(0.6, 128, clockwise=True), MESH)
    inside_log = math.log(math.cos(math.pi / 256) / 0.6)
    around_log = math.log(1 / (0.6 * math.cos(math.pi / 128)))
    assert inside_log < lower < upper < around_log
    assert upper - lower < 2e-4 and lower < math.log(1 / 0.6) + 2e-4 and upper > math.log(1 / 0.6) - 2e-4


@pytest.mark.parametrize("outer, hole, ceiling", [(24, 12, 13.84), (12, 6, 14.87)])
def test_bracket_tightens_with_the_mesh(outer, hole, ceiling):
    """Both meshes' brackets hold the same S (each lower bound under the
    other's upper), the finer one narrower (S about 0.5266 for 24 + 12,
    0.5693 for 12 + 6), and the ceiling moves by less than 0.01 degree."""
    o, h, ob, hb = turned_annulus(outer, hole)
    coarse, fine = modulus_bracket(o, h, 2 * MESH), modulus_bracket(o, h, MESH)
    assert coarse[0] < fine[1] and fine[0] < coarse[1]
    assert fine[1] - fine[0] < coarse[1] - coarse[0] < 2e-3
    assert twist_bound(o, h, ob, hb, mesh_size=MESH).ceiling == pytest.approx(ceiling, abs=0.01)


def test_no_turn_no_bound():
    *_, ceiling = twist_bound(*turned_annulus(24, 12, theta=0.0), mesh_size=MESH)
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
    *_, ceiling = twist_bound(o, h, ob, hb, mesh_size=MESH)
    assert 0 < reached <= ceiling


def test_command_line(tmp_path):
    """The 12 + 6 pair through the command line (the default, finer mesh):
    one line with the bracket on S, K and a ceiling below 15."""
    o, h, ob, hb = turned_annulus(12, 6)
    for name, loops in (("a.xy", (o, h)), ("b.xy", (ob, hb))):
        (tmp_path / name).write_text(">\n".join("".join(f"{x:.17g} {y:.17g}\n" for x, y in loop) for loop in loops))
    script = os.path.join(os.path.dirname(__file__), "..", "..", "bench", "twist_bound.py")
    run = subprocess.run([sys.executable, script, "a.xy", "b.xy"], cwd=tmp_path, capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stderr
    words = run.stdout.split()
    low, high = float(words[3]), float(words[7])
    assert words[4:7] == ["<=", "S", "<="] and 0.569 < low < high < 0.5695
    assert float(words[-2]) == pytest.approx(14.867, abs=0.002)
