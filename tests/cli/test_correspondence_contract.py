"""The output contract of the arc-length and auto correspondences and of
--max-edge, checked exactly on the files written: every input keeps all of
its vertices, bit-identical and in its order, on the boundary; every other
boundary point is P[e] + t (P[e+1] - P[e]) for the [e, t] the report gives,
bit for bit, inside that input edge (exact rational comparisons) and on its
line to within the rounding of that expression (exactly on it where the
edge is horizontal or vertical); the points follow each input around."""
import json
import math
from fractions import Fraction

import pytest

from polygons import read_vertex_text, star, write_xy


def affine(points, shift, matrix=((2.0, 0.5), (0.3, 1.5)), offset=(3.0, -1.0)):
    (a, b), (c, d) = matrix
    image = [(a * x + b * y + offset[0], c * x + d * y + offset[1]) for x, y in points]
    return image[shift:] + image[:shift]


def check_contract(out, report, inputs, stems, max_edge=None):
    n = report["n"]
    for points, stem, mesh in zip(inputs, stems, report["meshes"]):
        got = read_vertex_text(out / f"{stem}.off", "off")
        boundary = [(x, y) for x, y, _ in got[:n]]
        sources = mesh["boundary_source"]
        m = len(points)
        own = [e for e, t in sources if t == 0]
        # Every input vertex once, in cyclic order (either way round).
        assert sorted(own) == list(range(m)), "input vertices missing or repeated"
        k = own.index(min(own))
        rotated = own[k:] + own[:k]
        assert rotated in (list(range(m)), [0] + list(range(m - 1, 0, -1))), "input vertices out of order"
        step = 1 if rotated == list(range(m)) or m < 3 else -1
        for i, (e, t) in enumerate(sources):
            a, b = points[e], points[(e + 1) % m]
            if t == 0:
                assert boundary[i] == tuple(a), f"{stem}: boundary vertex {i} is not input vertex {e} bit for bit"
                continue
            assert 0 < t < 1
            # Reproduced bit for bit from the report.
            assert boundary[i] == (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])), f"{stem}: point {i}"
            # Inside the edge's box, exactly; on its line up to rounding.
            X, A, B = ([Fraction(v) for v in p] for p in (boundary[i], a, b))
            for c in range(2):
                assert min(A[c], B[c]) <= X[c] <= max(A[c], B[c]), f"{stem}: point {i} outside edge {e}"
            cross = (B[0] - A[0]) * (X[1] - A[1]) - (B[1] - A[1]) * (X[0] - A[0])
            if A[0] == B[0] or A[1] == B[1]:
                assert cross == 0, f"{stem}: point {i} off the axis-parallel edge {e}"
            else:
                length = math.hypot(b[0] - a[0], b[1] - a[1])
                scale = max(map(abs, (*a, *b)))
                assert abs(cross) <= Fraction(length) * Fraction(4 * scale * 2.0 ** -52), \
                    f"{stem}: point {i} off edge {e} by more than rounding"
        # Around the input in one direction: (edge, t) advances.
        def walked(e, t):  # how far along the walk from the first vertex
            if step == 1 or t == 0:
                return (e - own[0]) * step % m + (t if step == 1 else 0)
            return (own[0] - e - 1) % m + (1 - t)  # edge e runs from e + 1 back to e
        keys = [walked(e, t) for e, t in sources]
        assert all(keys[i] < keys[i + 1] for i in range(n - 1)), f"{stem}: the boundary goes back"
        if max_edge is not None:
            for i in range(n):
                (x0, y0), (x1, y1) = boundary[i], boundary[(i + 1) % n]
                assert math.hypot(x1 - x0, y1 - y0) <= max_edge * (1 + 1e-12), f"{stem}: edge {i} too long"


def run(cm, tmp_path, a, b, *args):
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    r = cm("triangulate", "a.xy", "b.xy", "-o", "out", *args)
    assert r.returncode == 0, r.stderr
    return json.loads((tmp_path / "out" / "report.json").read_text())


@pytest.mark.parametrize("seed, shift", [(3, 7), (8, 1), (21, 30)])
def test_affine_image_with_a_shifted_start_is_the_identity(cm, tmp_path, seed, shift):
    """auto finds vertex i of a against vertex i - shift of its affine
    image: a one-to-one boundary and no Steiner vertex at all."""
    a = star(37, seed)
    report = run(cm, tmp_path, a, affine(a, shift), "--correspondence", "auto", "--no-remesh")
    assert report["n"] == 37 and report["steiner"] == 0
    assert report["meshes"][1]["boundary_source"] == [[(i - shift) % 37, 0] for i in range(37)]


def rectangle(w, h, per_side):
    corners = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]
    return [(x0 + j / per_side[i] * (x1 - x0), y0 + j / per_side[i] * (y1 - y0))
            for i, ((x0, y0), (x1, y1)) in enumerate(zip(corners, corners[1:] + corners[:1]))
            for j in range(per_side[i])]


CASES = {
    "auto": (star(17, 1), star(29, 2, scale=2.5), []),
    "auto_clockwise": (star(17, 1), star(23, 2, scale=2.5, clockwise=True), []),
    "arclength_pins": (star(20, 4), star(31, 5), ["--pin", "0,3", "--pin", "10,20"]),
    "pin_corners": (rectangle(4.0, 2.0, [5, 3, 5, 3]), rectangle(6.0, 2.5, [4, 2, 3, 2]), ["--pin-corners", "30"]),
    "max_edge_auto": (star(12, 6), star(9, 7, clockwise=True), ["--max-edge", "0.3"]),
    "max_edge_index": (star(10, 6), star(10, 8, scale=1.5), ["--correspondence", "index", "--max-edge", "0.4"]),
    "max_edge_rectangles": (rectangle(4.0, 2.0, [2, 1, 2, 1]), rectangle(3.0, 3.0, [1, 1, 1, 1]),
                            ["--pin-corners", "45", "--max-edge", "0.35"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_output_contract_exactly(cm, tmp_path, case):
    a, b, args = CASES[case]
    report = run(cm, tmp_path, a, b, *args)
    max_edge = float(args[args.index("--max-edge") + 1]) if "--max-edge" in args else None
    check_contract(tmp_path / "out", report, [a, b], ["a", "b"], max_edge)
    if max_edge is not None:
        assert report["max_edge"] == max_edge
    if case == "max_edge_index":  # vertex i stays on vertex i, between them the splits
        a_src, b_src = (m["boundary_source"] for m in report["meshes"])
        assert [e for e, t in a_src if t == 0] == list(range(10))
        assert all((ea, ta == 0) == (eb, tb == 0) for (ea, ta), (eb, tb) in zip(a_src, b_src))


def test_max_edge_errors(cm, tmp_path):
    write_xy(tmp_path / "a.xy", star(10, 1))
    write_xy(tmp_path / "b.xy", star(10, 2))
    for value, message in (("0", "--max-edge needs a positive length, got '0'"),
                           ("-1", "--max-edge needs a positive length"),
                           ("1e-9", "max_edge 1e-09 would put more than 16777216 vertices on the boundary")):
        r = cm("triangulate", "a.xy", "b.xy", "-o", "out", "--max-edge", value)
        assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and message in r.stderr, r.stderr
        assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("mode", ["index", "arclength", "auto"])
def test_capped_long_sides_are_halved(cm, tmp_path, mode):
    """An 8 x 1 rectangle against a copy scaled by 2: a triangle on a long
    side has its apex at most 1 from it, so no angle above atan(1/4) = 14.04
    degrees while the side is whole. index keeps the four vertices; arclength
    and auto halve the long sides at the same parameter in both (pieces of
    2, t = 1/4, 1/2, 3/4, where the edge cap reaches the target 25) and go
    past it, within the output contract; auto's polish may then slide the
    added points along their edges, in order."""
    a = [(0.0, 0.0), (8.0, 0.0), (8.0, 1.0), (0.0, 1.0)]
    b = [(1.0, 2.0), (17.0, 2.0), (17.0, 4.0), (1.0, 4.0)]
    report = run(cm, tmp_path, a, b, "--correspondence", mode)
    least = min(m["min_angle_deg"] for m in report["meshes"])
    bound = math.degrees(math.atan(0.25))
    if mode == "index":
        assert report["n"] == 4 and least <= bound
        return
    check_contract(tmp_path / "out", report, [a, b], ["a", "b"])
    assert report["n"] == 10 and least > bound
    expected = [[0, 0], [0, 0.25], [0, 0.5], [0, 0.75], [1, 0], [2, 0], [2, 0.25], [2, 0.5], [2, 0.75], [3, 0]]
    sources = [m["boundary_source"] for m in report["meshes"]]
    if mode == "arclength":
        assert sources == [expected, expected]
        return
    for got in sources:
        assert [e for e, _ in got] == [e for e, _ in expected]
        for (e, t), (_, t_expected), (e_before, t_before) in zip(got, expected, [[-1, 0]] + got):
            assert t == 0 if t_expected == 0 else t_before < t < 1 if e_before == e else 0 < t < 1


def off_triangles(path):
    tokens = path.read_text().split()
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4 + 3 * nv
    return [tuple(int(v) for v in tokens[at + 4 * f + 1:at + 4 * f + 4]) for f in range(nf)]


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_no_diagonal_along_an_input_edge(cm, tmp_path, seed):
    """A slanted quadrilateral gets a star's vertices on its edges, rounded
    off their lines, so a segment between two of them can pass as a
    diagonal with a sliver beside it; the construction joins no two boundary
    vertices that lie on one input edge of either polygon."""
    a = [(0.0, 0.0), (1.0, 0.3), (0.7, 1.3), (-0.3, 1.0)]
    b = star(40, seed)
    report = run(cm, tmp_path, a, b, "--correspondence", "arclength", "--no-remesh")
    n = report["n"]
    along = []
    for (count, mesh) in zip((4, 40), report["meshes"]):
        source = mesh["boundary_source"]

        def edges_of(v):  # an input vertex lies on two input edges, a point on one
            e, t = source[v]
            return {e, (e - 1) % count} if t == 0 else {e}
        for tri in off_triangles(tmp_path / "out" / "a.off"):
            for u, w in zip(tri, tri[1:] + tri[:1]):
                if u < n and w < n and (u - w) % n not in (1, n - 1) and edges_of(u) & edges_of(w):
                    along.append((u, w))
    assert along == []
