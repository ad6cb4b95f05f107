"""bench/correspondence_bound.py: the upper bound on the smallest angle of
any compatible triangulation, checked against what can be worked out by
hand and against compatmesh's own results (a result above the bound would
mean the bound, or the result check, is wrong)."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
sys.path.insert(0, BENCH)
import correspondence_bound as cb  # noqa: E402

CLI = os.environ["COMPATMESH"]
GEN = os.environ["CM_GEN_PAIRS"]
SCRIPT = os.path.join(BENCH, "correspondence_bound.py")

SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]
RECT4 = [(0, 0), (4, 0), (4, 1), (0, 1)]


def write_xy(path, points):
    path.write_text("".join("%r %r\n" % p for p in points))
    return str(path)


def bound_of(paths):
    run = subprocess.run([sys.executable, SCRIPT, CLI, *paths], capture_output=True,
                         text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    angle, K, quad = run.stdout.split()
    return float(angle), float(K), quad


def triangle(angles):
    """A triangle with these angles (radians), unit first side."""
    a, b, _ = angles
    apex = math.sin(b) / math.sin(a + b)
    return np.array([[0, 0], [1, 0], [apex * math.cos(a), apex * math.sin(a)]])


def affine_dilatation(p, q):
    A = np.linalg.solve(np.column_stack([p[1] - p[0], p[2] - p[0]]).T,
                        np.column_stack([q[1] - q[0], q[2] - q[0]]).T).T
    s = np.linalg.svd(A, compute_uv=False)
    return s[0] / s[1]


@pytest.mark.parametrize("alpha_deg", [10, 20, 25, 30, 45])
def test_dilatation_bound_is_the_largest_between_triangles(alpha_deg):
    alpha = math.radians(alpha_deg)
    K = cb.dilatation_bound(alpha)
    rng = np.random.default_rng(alpha_deg)
    worst = 0.0
    for _ in range(3000):
        pair = []
        for _ in range(2):
            a = alpha + rng.random() * (math.pi - 3 * alpha)
            b = alpha + rng.random() * (math.pi - 2 * alpha - a)
            # every angle >= alpha by construction; the order is random
            pair.append(triangle(rng.permutation([a, b, math.pi - a - b])))
        worst = max(worst, affine_dilatation(*pair))
    assert worst <= K * (1 + 1e-9)
    # reached, so no smaller number would do: between two corners of the
    # region of allowed shapes
    corners = [triangle([alpha, alpha, math.pi - 2 * alpha]),
               triangle([alpha, math.pi - 2 * alpha, alpha])]
    assert affine_dilatation(*corners) == pytest.approx(K, rel=1e-9)
    # and below D(alpha)^2, the square of the largest dilatation from the
    # equilateral triangle
    s = (2 / math.sqrt(3)) * (2 / math.tan(alpha) - 1 / math.tan(2 * alpha))
    D = 0.5 * (s + math.sqrt(s * s - 4))
    assert K < D * D


def test_angle_bound_inverts_the_dilatation_bound():
    for K in (1.5, 4.0, 13.8, 100.0):
        alpha = math.radians(cb.angle_bound(K))
        assert cb.dilatation_bound(alpha) == pytest.approx(K, rel=1e-6)
    assert cb.angle_bound(1.0) == 60.0


def test_square_against_a_four_to_one_rectangle(tmp_path):
    # Corners correspond, so the moduli are 1 and 4 exactly: K = 4, and
    # K(alpha) = 4 at 38.35 degrees.
    angle, K, quad = bound_of([write_xy(tmp_path / "s.xy", SQUARE),
                               write_xy(tmp_path / "r.xy", RECT4)])
    assert K == pytest.approx(4.0, rel=0.02) and K <= 4.0 * (1 + 1e-9)
    assert angle == pytest.approx(38.35, abs=0.3)
    assert quad == "0,1,2,3"


def test_identical_polygons_bind_nothing(tmp_path):
    star = [(math.cos(t) * (1 + 0.4 * (i % 2)), math.sin(t) * (1 + 0.4 * (i % 2)))
            for i, t in enumerate(np.linspace(0, 2 * math.pi, 10, endpoint=False))]
    angle, K, _ = bound_of([write_xy(tmp_path / "a.xy", star), write_xy(tmp_path / "b.xy", star)])
    assert K <= 1.0 + 1e-9 and angle == 60.0


def test_certified_range_brackets_the_modulus(tmp_path):
    # An L whose mirror image in y = x swaps the quadrilateral with its
    # conjugate: its modulus is exactly 1. The reflex corner keeps the
    # finite element values a few percent off, on either side.
    ell = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    poly = cb.Polygon(CLI, write_xy(tmp_path / "l.xy", ell), str(tmp_path))
    lo, hi = poly.modulus_range((0, 1, 3, 5))
    assert lo < 1 < hi < 1.15 * lo
    rect = cb.Polygon(CLI, write_xy(tmp_path / "r.xy", RECT4), str(tmp_path))
    lo, hi = rect.modulus_range((0, 1, 2, 3))
    assert lo <= hi * (1 + 1e-9)
    assert lo == pytest.approx(4.0, rel=0.01) and hi == pytest.approx(4.0, rel=0.01)


def smallest_angle(tmp_path, inputs, *options):
    """compatmesh's smallest angle over the meshes of inputs."""
    run = subprocess.run([CLI, "triangulate", *inputs, *options, "-o", str(tmp_path / "out")],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    return min(m["min_angle_deg"] for m in report["meshes"])


@pytest.fixture(scope="module")
def pairs(tmp_path_factory):
    out = tmp_path_factory.mktemp("pairs")
    subprocess.run([GEN, "--out", str(out), "--set", "bench"], check=True,
                   capture_output=True, timeout=300)
    return out


# No compatible triangulation can beat the bound, compatmesh's included;
# on the L/T pair the bound is below the remeshing target of 25 degrees.
@pytest.mark.parametrize("name,below", [("glyph_U_S_n40", None), ("glyph_L_T_n40", 25.0)])
def test_results_never_beat_the_bound(pairs, tmp_path, name, below):
    inputs = [str(pairs / f"{name}_{g}.xy") for g in "ab"]
    angle, _, _ = bound_of(inputs)
    if below is not None:
        assert angle < below
    assert smallest_angle(tmp_path, inputs) <= angle


def test_results_never_beat_the_bound_square_rectangle(tmp_path):
    inputs = [write_xy(tmp_path / "s.xy", SQUARE), write_xy(tmp_path / "r.xy", RECT4)]
    angle, _, _ = bound_of(inputs)
    assert smallest_angle(tmp_path, inputs, "--min-angle", "45") <= angle


# Polygons with holes: the capacity of the curves joining two boundary
# sides, bracketed by the primal (Dirichlet) and the dual (stream function)
# finite element problems.

def regular(cx, cy, r, m):
    return [(cx + r * math.cos(2 * math.pi * i / m), cy + r * math.sin(2 * math.pi * i / m)) for i in range(m)]


def write_loops(path, loops):
    path.write_text("> outer loop\n" + "> hole\n".join("".join("%r %r\n" % p for p in loop) for loop in loops))
    return str(path)


def ring_capacity(r, R):
    return 2 * math.pi / math.log(R / r)


@pytest.fixture(scope="module")
def annulus(tmp_path_factory):
    # a 96-gon of radius 1 with a 48-gon hole of radius 0.4: it contains the
    # round annulus 0.4 < |z| < cos(pi / 96) and lies in 0.4 cos(pi / 48) < |z| < 1
    work = tmp_path_factory.mktemp("annulus")
    path = write_loops(work / "ring.xy", [regular(0, 0, 1, 96), regular(0, 0, 0.4, 48)])
    return cb.Polygon(CLI, path, str(work))


def test_ring_capacity_is_bracketed(annulus):
    lo, hi = annulus.capacity_range(((1, None, None), (0, None, None)))
    # the polygon's ring between the two round rings around it: a larger
    # ring has the smaller capacity
    below = ring_capacity(0.4 * math.cos(math.pi / 48), 1)
    above = ring_capacity(0.4, math.cos(math.pi / 96))
    assert below < above < below * 1.005
    # the dual below, the primal above, both within 0.5 % of the truth: a
    # hole pinned to a constant or a missing jump across the cut is not
    assert lo <= hi and lo <= above and hi >= below
    assert hi < 1.005 * lo


@pytest.mark.parametrize("family", [
    ((1, 0, 12), (0, 0, 24)),    # a hole's arc and the outer arc facing it
    ((1, 0, 12), (0, 48, 72)),   # ... and the outer arc opposite
    ((1, None, None), (0, 10, 30)),  # the whole hole against an arc
    ((1, 0, 12), (1, 24, 36)),   # two arcs of the hole (the outer loop a free constant)
    ((0, 0, 24), (0, 48, 72)),   # two outer arcs (the hole a free constant)
])
def test_capacity_bracket_every_kind_of_family(annulus, family):
    lo, hi = annulus.capacity_range(family)
    # within a few per cent: the arcs' ends are singular, the mesh fixed
    assert lo <= hi < 1.06 * lo


def test_facing_arcs_have_the_larger_capacity(annulus):
    # the hole turned by half a turn takes the facing arcs to opposite ones:
    # a certified factor between the two families
    near = annulus.capacity_range(((1, 0, 12), (0, 0, 24)))
    far = annulus.capacity_range(((1, 0, 12), (0, 48, 72)))
    assert near[0] > 2 * far[1]


def test_square_with_a_square_hole_against_itself_binds_nothing(tmp_path):
    loops = [[(0, 0), (3, 0), (3, 3), (0, 3)], [(1, 1), (1, 2), (2, 2), (2, 1)]]
    paths = [write_loops(tmp_path / "a.xy", loops), write_loops(tmp_path / "b.xy", loops)]
    angle, K, _ = bound_of(paths)
    assert K <= 1.0 + 1e-9 and angle == 60.0


def test_offset_hole_against_a_concentric_one(tmp_path):
    # the same loops, the hole moved off centre: the ring capacity grows
    # (a ring's modulus is largest when concentric), so K > 1 is certified
    # by the whole hole against the whole outer loop alone
    outer = regular(0, 0, 1, 32)
    paths = [write_loops(tmp_path / "a.xy", [outer, regular(0, 0, 0.3, 16)]),
             write_loops(tmp_path / "b.xy", [outer, regular(0.4, 0, 0.3, 16)])]
    polys = [cb.Polygon(CLI, p, str(tmp_path)) for p in paths]
    (lo_a, hi_a), (lo_b, hi_b) = [p.capacity_range(((1, None, None), (0, None, None))) for p in polys]
    assert lo_a == pytest.approx(ring_capacity(0.3, 1), rel=0.02)
    ring = lo_b / hi_a
    # the round rings' ratio: z -> (z - s) / (1 - s z) takes the disc with
    # the hole of centre 0.4, radius 0.3 to a concentric annulus
    lo, hi = 0.0, 1.0
    for _ in range(60):
        s = 0.5 * (lo + hi)
        left, right = (0.1 - s) / (1 - 0.1 * s), (0.7 - s) / (1 - 0.7 * s)
        lo, hi = (s, hi) if left + right > 0 else (lo, s)
    exact = ring_capacity(right, 1) / ring_capacity(0.3, 1)
    assert ring > 1.1 and ring == pytest.approx(exact, rel=0.03)


# The twist: the curves that wind around a hole a given number of times,
# in the covering that records the winding, the least over every number
# of turns the map may add.

def twist_of(tmp_path, loops_a, loops_b):
    paths = [write_loops(tmp_path / "ta.xy", loops_a), write_loops(tmp_path / "tb.xy", loops_b)]
    rough = [cb.Polygon(CLI, p, str(tmp_path), cb.TWIST_SEARCH_TRIANGLES) for p in paths]
    return cb.twist_bound(rough, [p.refined(cb.SEARCH_TRIANGLES) for p in rough], 1)


# an outer loop and an off-centre hole, no symmetry between them
LOPSIDED = [[(0, 0), (3, 0), (3.5, 1.5), (2.5, 3), (0.3, 2.6)],
            regular(1.2, 1.3, 0.5, 8)[::-1]]


@pytest.fixture
def quick_twist(monkeypatch):
    # a smaller search (fewer periods and hole arcs) than the bench's: the
    # upper checks below hold for any family, the turned hole's is met by it
    monkeypatch.setattr(cb, "TWIST_PERIODS", 1)
    monkeypatch.setattr(cb, "TWIST_STARTS", 4)


def test_twist_of_a_polygon_against_itself_binds_nothing(tmp_path, quick_twist):
    # also what fails if A's and B's coverings were numbered opposite ways
    K, _ = twist_of(tmp_path, LOPSIDED, LOPSIDED)
    assert K <= 1.0 + 1e-9


def test_twist_never_exceeds_an_affine_maps_dilatation(tmp_path, quick_twist):
    # the affine stretch by 1.6 is a compatible map of dilatation 1.6
    stretched = [[(1.6 * x, y) for x, y in loop] for loop in LOPSIDED]
    K, _ = twist_of(tmp_path, LOPSIDED, stretched)
    assert 1.0 < K <= 1.6


def test_a_hole_turned_half_a_turn(tmp_path, quick_twist):
    # the fixture of tests/core: every map turns the hole by half a turn;
    # the curves from a hole arc to an outer arc, all together, distort by
    # a few times at most, the winding ones by more
    outer, hole = regular(0, 0, 1, 24), regular(0, 0, 0.6, 12)[::-1]
    turned = [(-x, -y) for x, y in hole]
    K, family = twist_of(tmp_path, [outer, hole], [outer, turned])
    paths = [write_loops(tmp_path / "a.xy", [outer, hole]), write_loops(tmp_path / "b.xy", [outer, turned])]
    polys = [cb.Polygon(CLI, p, str(tmp_path), cb.SEARCH_TRIANGLES) for p in paths]
    plain = max(cb.certified_family(polys, f) for f in (family, ((1, 0, 6), (0, 0, 12)), ((1, 3, 9), (0, 6, 18))))
    assert K > 2 * plain and K > 10
