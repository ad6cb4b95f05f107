"""Polygons with holes on the command line: `.xy` loops separated by '>'
lines (GMT's multi-segment convention), OBJ files with several closed 'l'
loops or one 'l a b' line per edge, the outputs (loops bit-identical, the
report's hole count, Euler characteristic 1 - h), bad input named by file,
line, loop and vertex, and the morph and sweep of polygons with holes (the
holes stay empty in every frame and the volume is a tube)."""
import json
import math
import os
import random

import pytest

from polygons import BOUNDARY, check_pictures, leftovers, paths_of


def circle(cx, cy, r, m, direction=1):
    return [(cx + r * math.cos(direction * 2 * math.pi * i / m),
             cy + r * math.sin(direction * 2 * math.pi * i / m)) for i in range(m)]


def square(cx, cy, h, m, direction=1):
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    if direction < 0:
        corners = [(-1, -1), (-1, 1), (1, 1), (1, -1)]
    side = m // 4
    points = []
    for c in range(4):
        (ax, ay), (bx, by) = corners[c], corners[(c + 1) % 4]
        for i in range(side):
            t = i / side
            points.append((cx + h * ((1 - t) * ax + t * bx), cy + h * ((1 - t) * ay + t * by)))
    return points


def xy_text(loops):
    return "> outer loop\n" + "> hole\n".join(
        "".join(f"{x!r} {y!r}\n" for x, y in loop) for loop in loops)


def obj_text(loops, edges=False):
    lines, first = [], 1
    for loop in loops:
        lines += [f"v {x!r} {y!r} 0" for x, y in loop]
    for loop in loops:
        idx = list(range(first, first + len(loop)))
        if edges:
            lines += [f"l {a} {b}" for a, b in zip(idx, idx[1:] + idx[:1])]
        else:
            lines.append("l " + " ".join(map(str, idx + idx[:1])))
        first += len(loop)
    return "\n".join(lines) + "\n"


SQUARE_WITH_HOLE = [square(0, 0, 1, 16), square(0, 0, 0.4, 8, -1)]
DISC_WITH_HOLE = [circle(0, 0, 1, 16), circle(0.3, 0.2, 0.35, 8, -1)]


def read_off(path):
    with open(path) as f:
        assert f.readline().strip() == "OFF"
        nv, nt, _ = map(int, f.readline().split())
        vertices = [tuple(map(float, f.readline().split()[:2])) for _ in range(nv)]
        triangles = [tuple(map(int, f.readline().split()[1:4])) for _ in range(nt)]
    return vertices, triangles


def check_output(out, names, inputs, holes):
    """Loops first and bit-identical; boundary = the loops; V - E + F = 1 - h."""
    report = json.loads((out / "report.json").read_text())
    assert report["holes"] == holes and report["bridges"] == 2 * holes
    n = sum(len(loop) for loop in inputs[0])
    assert report["n"] == n
    faces = None
    for name, loops in zip(names, inputs):
        vertices, triangles = read_off(out / f"{name}.off")
        assert vertices[:n] == [p for loop in loops for p in loop]
        assert faces is None or faces == triangles
        faces = triangles
    edges = {}
    for a, b, c in faces:
        for e in ((a, b), (b, c), (c, a)):
            edges[e] = edges.get(e, 0) + 1
    undirected = {tuple(sorted(e)) for e in edges}
    boundary = {tuple(sorted(e)) for e in edges if (e[1], e[0]) not in edges}
    loop_edges, first = set(), 0
    for loop in inputs[0]:
        m = len(loop)
        loop_edges |= {tuple(sorted((first + i, first + (i + 1) % m))) for i in range(m)}
        first += m
    assert boundary == loop_edges
    assert len(vertices) - len(undirected) + len(faces) == 1 - holes
    return report


def check_loops_kept(out, report, inputs, holes):
    """Where the loops got the other inputs' points (auto): every input
    vertex of each file among its mesh's boundary vertices, one triangle
    list, V - E + F = 1 - holes."""
    faces = None
    for name, loops in inputs:
        vertices, triangles = read_off(out / f"{name}.off")
        boundary = set(vertices[:report["n"]])
        assert all(p in boundary for loop in loops for p in loop)
        assert faces is None or faces == triangles
        faces = triangles
    edges = {tuple(sorted(e)) for a, b, c in faces for e in ((a, b), (b, c), (c, a))}
    assert len(vertices) - len(edges) + len(faces) == 1 - holes


@pytest.mark.parametrize("fmt", ["xy", "obj", "obj-edges"])
def test_square_and_disc(cm, tmp_path, fmt):
    ext = "xy" if fmt == "xy" else "obj"
    write = (lambda loops: xy_text(loops)) if fmt == "xy" else \
        (lambda loops: obj_text(loops, edges=fmt == "obj-edges"))
    (tmp_path / f"a.{ext}").write_text(write(SQUARE_WITH_HOLE))
    (tmp_path / f"b.{ext}").write_text(write(DISC_WITH_HOLE))
    result = cm("triangulate", f"a.{ext}", f"b.{ext}", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    report = check_output(tmp_path / "out", ["a", "b"], [SQUARE_WITH_HOLE, DISC_WITH_HOLE], 1)
    assert min(m["min_angle_deg"] for m in report["meshes"]) >= 20
    svg = check_pictures(tmp_path / "out" / "preview.png", tmp_path / "out" / "preview.svg")
    boundaries = paths_of(svg, stroke=BOUNDARY)
    assert [d.count("Z") for d in boundaries] == [2, 2]  # the outer loop and the hole's, per mesh


def test_closed_rings_with_holes(cm, tmp_path):
    """Every loop of an .xy file may close its ring by repeating its first
    vertex: each is read without the repeat."""
    (tmp_path / "a.xy").write_text(xy_text([loop + loop[:1] for loop in SQUARE_WITH_HOLE]))
    (tmp_path / "b.xy").write_text(xy_text([DISC_WITH_HOLE[0] + DISC_WITH_HOLE[0][:1], DISC_WITH_HOLE[1]]))
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    check_output(tmp_path / "out", ["a", "b"], [SQUARE_WITH_HOLE, DISC_WITH_HOLE], 1)


def test_obj_outer_found_by_containment(cm, tmp_path):
    """The hole's 'l' line first: the outer loop is the one of largest area."""
    (tmp_path / "a.obj").write_text(obj_text(SQUARE_WITH_HOLE[::-1]))
    (tmp_path / "b.obj").write_text(obj_text(DISC_WITH_HOLE[::-1]))
    result = cm("triangulate", "a.obj", "b.obj", "--out-dir", "out", "--no-remesh")
    assert result.returncode == 0, result.stderr
    check_output(tmp_path / "out", ["a", "b"], [SQUARE_WITH_HOLE, DISC_WITH_HOLE], 1)


PLATE = [square(0, 0, 2, 24)] + [circle(cx, cy, 0.45, 10, -1)
                                 for cx, cy in ((-1, -1), (1, -0.8), (0, 1))]


# The plate sheared and turned by 0.5 radians.
PLATE_MOVED = [[(math.cos(0.5) * (x + 0.4 * y) - math.sin(0.5) * y,
                 math.sin(0.5) * (x + 0.4 * y) + math.cos(0.5) * y) for x, y in loop] for loop in PLATE]


def test_plate_three_bolt_holes(cm, tmp_path):
    (tmp_path / "plate.xy").write_text(xy_text(PLATE))
    (tmp_path / "moved.xy").write_text(xy_text(PLATE_MOVED))
    result = cm("triangulate", "plate.xy", "moved.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    check_output(tmp_path / "out", ["plate", "moved"], [PLATE, PLATE_MOVED], 3)


# A plate with three bolt holes whose outline no affine map takes onto
# itself (a square's turns would pair its outline four ways alike), and
# that plate sheared and turned.
BLOB_PLATE = [[((2 + 0.3 * math.cos(3 * t) + 0.2 * math.sin(2 * t)) * math.cos(t),
                (2 + 0.3 * math.cos(3 * t) + 0.2 * math.sin(2 * t)) * math.sin(t))
               for t in (2 * math.pi * i / 30 for i in range(30))]] + \
    [circle(cx, cy, 0.3, 10, -1) for cx, cy in ((-0.7, -0.6), (0.7, -0.5), (0, 0.8))]
BLOB_PLATE_MOVED = [[(math.cos(0.5) * (x + 0.4 * y) - math.sin(0.5) * y,
                      math.sin(0.5) * (x + 0.4 * y) + math.cos(0.5) * y) for x, y in loop] for loop in BLOB_PLATE]


def test_auto_pairs_holes_by_position(cm, tmp_path):
    """A section's loops come in no particular order: with auto, the moved
    plate's bolt holes listed in another order pair with the plate's holes
    at the same places, and the meshes are the very ones the matching
    order gives (the second's output lists its holes in the first's
    order; report.json's boundary_source names each vertex's input loop)."""
    (tmp_path / "plate.xy").write_text(xy_text(BLOB_PLATE))
    (tmp_path / "moved.xy").write_text(xy_text(BLOB_PLATE_MOVED))
    shuffled = [BLOB_PLATE_MOVED[0], BLOB_PLATE_MOVED[3], BLOB_PLATE_MOVED[1], BLOB_PLATE_MOVED[2]]
    (tmp_path / "shuffled.xy").write_text(xy_text(shuffled))
    runs = {}
    for second in ("moved", "shuffled"):
        result = cm("triangulate", "plate.xy", f"{second}.xy", "--out-dir", second, "--correspondence", "auto")
        assert result.returncode == 0, result.stderr
        assert ("holes paired by position: 3 " in result.stdout) == (second == "shuffled")
        runs[second] = json.loads((tmp_path / second / "report.json").read_text())
    assert runs["moved"]["holes_moved"] == 0 and runs["shuffled"]["holes_moved"] == 3
    assert (tmp_path / "moved" / "plate.off").read_bytes() == (tmp_path / "shuffled" / "plate.off").read_bytes()
    assert (tmp_path / "moved" / "moved.off").read_bytes() == (tmp_path / "shuffled" / "shuffled.off").read_bytes()
    starts = [0]
    for loop in shuffled:
        starts.append(starts[-1] + len(loop))
    loop_of = lambda e: max(l for l in range(4) if starts[l] <= e)  # noqa: E731
    sources = runs["shuffled"]["meshes"][1]["boundary_source"]
    places = []  # the shuffled input loop of each output loop, in output order
    for e, _ in sources:
        if not places or places[-1] != loop_of(e):
            places.append(loop_of(e))
    assert places == [0, 2, 3, 1]
    assert min(m["min_angle_deg"] for m in runs["shuffled"]["meshes"]) >= 20


GLYPH_PAIRS = os.path.join(os.path.dirname(__file__), "glyph_pairs")


@pytest.mark.parametrize("pair, least", [("FreeSerif_o_e", 22), ("DejaVuSansOblique_D_P", 24)])
def test_auto_pairs_one_hole_polygons_through_the_annulus(cm, tmp_path, pair, least):
    """Glyph pairs with one hole (cm_glyph_holes --auto --font F --dump:
    outer loops of 64 vertices, holes of 24). FreeSerif 'o' against 'e':
    every pairing of the filled outlines, the hole started from there,
    sends the e's mouth into the o's ring where the hole is near, 6.8
    degrees after every rescue. DejaVu Sans Oblique 'D' against 'P': the
    conformal pairing of the outlines remeshes below 0.6 of its aim of 25,
    and the outer loops' rescues of polygons without holes reached 22.4.
    Paired through the conformal maps onto round annuli (both loops at
    once, the first of auto's rescues for one hole): 26 degrees each.
    Expected: valid, the annulus pairing kept, at least `least` degrees in
    both meshes; with --max-edge 0.02 too (o/e), and no boundary edge
    longer than that."""
    a, b = (os.path.join(GLYPH_PAIRS, pair + "_holes_" + s + ".xy") for s in "ab")
    runs = (("out", []), ("short", ["--max-edge", "0.02"])) if pair == "FreeSerif_o_e" else (("out", []),)
    for out, extra in runs:
        result = cm("triangulate", a, b, "--out-dir", out, "--correspondence", "auto", *extra)
        assert result.returncode == 0, result.stderr
        report = json.loads((tmp_path / out / "report.json").read_text())
        assert report["valid"] and report["holes"] == 1
        assert report["correspondence_choice"] == "annulus"
        assert min(m["min_angle_deg"] for m in report["meshes"]) >= least
    meshes = sorted((tmp_path / "short").glob("*.off"))
    assert len(meshes) == (2 if len(runs) == 2 else 0)
    for mesh in meshes:
        vertices, triangles = read_off(mesh)
        sides = {(t[i], t[(i + 1) % 3]) for t in triangles for i in range(3)}
        longest = max(math.dist(vertices[p], vertices[q]) for p, q in sides if (q, p) not in sides)
        assert longest <= 0.02 * (1 + 1e-12), (mesh.name, longest)


def bad(cm, tmp_path, a_loops, b_text, pattern, *extra):
    import re
    (tmp_path / "a.xy").write_text(xy_text(a_loops))
    (tmp_path / "b.xy").write_text(b_text)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out", *extra)
    assert result.returncode == 2, result.stderr
    assert result.stderr.count("\n") == 1
    assert re.search(pattern, result.stderr), result.stderr
    assert leftovers(tmp_path) == [] and not (tmp_path / "out").exists()


def test_bad_hole_count(cm, tmp_path):
    bad(cm, tmp_path, SQUARE_WITH_HOLE, xy_text(DISC_WITH_HOLE[:1] + [square(0, 0, 0.4, 8, -1)] * 0),
        r"b\.xy: polygon 1 has 0 holes but polygon 0 has 1|b\.xy has 16 vertices")


def test_bad_loop_size(cm, tmp_path):
    bad(cm, tmp_path, SQUARE_WITH_HOLE, xy_text([circle(0, 0, 1, 17), circle(0, 0, 0.3, 7, -1)]),
        r"^compatmesh: b\.xy: the outer loop \(loop 0\) has 17 vertices but in polygon 0 it has 16",
        "--correspondence", "index")


def test_loops_of_different_sizes_pair_by_default(cm, tmp_path):
    """Loops of different sizes (and a hole running the other way) take the
    auto correspondence loop by loop: valid, one hole, every input vertex of
    each file among its mesh's boundary vertices, bit-identical; V - E + F =
    1 - h."""
    other = [circle(0, 0, 1, 23), circle(0.3, 0.2, 0.35, 11)]
    (tmp_path / "a.xy").write_text(xy_text(SQUARE_WITH_HOLE))
    (tmp_path / "b.xy").write_text(xy_text(other))
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["holes"] == 1 and report["n"] >= 23 + 11
    check_loops_kept(tmp_path / "out", report, (("a", SQUARE_WITH_HOLE), ("b", other)), 1)
    assert min(m["min_angle_deg"] for m in report["meshes"]) >= 10


# A comb (five teeth, notched between them) with two bolt holes in its
# back, and a disc with two holes: the correspondence must squeeze the
# teeth into the disc's rim.
COMB_WITH_TWO_HOLES = [[(0, 0), (10, 0), (10, 8), (9, 8), (9, 2), (8, 8), (7, 8), (7, 2), (6, 8), (5, 8), (5, 2),
                        (4, 8), (3, 8), (3, 2), (2, 8), (0, 8)],
                       circle(3, 1, 0.4, 8, -1), circle(7, 1, 0.4, 8, -1)]
DISC_WITH_TWO_HOLES = [circle(5, 4, 5, 60), circle(3, 4, 0.8, 10, -1), circle(7, 4, 0.8, 10, -1)]


def test_auto_rescues_the_outer_loops_with_two_holes(cm, tmp_path):
    """Polygons with two holes or more take auto's rescues of the outer
    loops (the annulus pairing is for one hole): the comb against the disc
    ends its first pairing below 0.6 of the aim of 25 degrees, so a second
    pairing is built and remeshed (22.5 degrees kept). Expected: valid, two
    holes, at least two pairings built and remeshed, every input vertex of
    each file among its mesh's boundary vertices, one triangle list,
    V - E + F = 1 - 2, and both meshes at the floor min(15, c/3) = 15."""
    (tmp_path / "comb.xy").write_text(xy_text(COMB_WITH_TWO_HOLES))
    (tmp_path / "disc.xy").write_text(xy_text(DISC_WITH_TWO_HOLES))
    result = cm("triangulate", "comb.xy", "disc.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["valid"] and report["holes"] == 2 and report["correspondence"] == "auto"
    assert report["pairings_built"] >= 2 and report["pairings_remeshed"] >= 2
    check_loops_kept(tmp_path / "out", report, (("comb", COMB_WITH_TWO_HOLES), ("disc", DISC_WITH_TWO_HOLES)), 2)
    assert min(m["min_angle_deg"] for m in report["meshes"]) >= 15


def test_bad_hole_outside(cm, tmp_path):
    # line 1 is the '>' header, the outer loop lines 2-17, '>' on 18, the hole from line 19
    bad(cm, tmp_path, SQUARE_WITH_HOLE, xy_text([circle(0, 0, 1, 16), circle(3, 0, 0.3, 8, -1)]),
        r"^compatmesh: b\.xy:19: hole 1 \(loop 1\) lies outside the outer loop")


def test_bad_hole_crossing(cm, tmp_path):
    bad(cm, tmp_path, SQUARE_WITH_HOLE, xy_text([circle(0, 0, 1, 16), circle(0.8, 0, 0.3, 8, -1)]),
        r"^compatmesh: b\.xy:\d+: edge \d+-\d+ of the outer loop \(loop 0\) and edge \d+-\d+ of "
        r"hole 1 \(loop 1\) cross or touch")


def test_bad_short_loop(cm, tmp_path):
    bad(cm, tmp_path, SQUARE_WITH_HOLE, "0 0\n1 0\n1 1\n0 1\n>\n0.2 0.2\n0.3 0.3\n",
        r"^compatmesh: b\.xy:6: loop 1 has 2 vertices, needs at least 3")


def test_bad_obj_edges_not_closed(cm, tmp_path):
    (tmp_path / "a.obj").write_text(obj_text(SQUARE_WITH_HOLE, edges=True))
    text = obj_text(DISC_WITH_HOLE, edges=True).replace("l 24 17\n", "")
    (tmp_path / "b.obj").write_text(text)
    result = cm("triangulate", "a.obj", "b.obj", "--out-dir", "out")
    assert result.returncode == 2
    assert "b.obj:" in result.stderr and "not closed" in result.stderr


def shoelace(points):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))


def test_morph_with_holes(cm, tmp_path):
    """Every frame: every triangle counter-clockwise, the boundary the loops
    (so the holes stay empty), the area the outer loop's minus the hole's."""
    (tmp_path / "a.xy").write_text(xy_text(SQUARE_WITH_HOLE))
    (tmp_path / "b.xy").write_text(xy_text(DISC_WITH_HOLE))
    result = cm("morph", "a.xy", "b.xy", "--out-dir", "out", "--frames", "5")
    assert result.returncode == 0, result.stderr
    for f in range(5):
        vertices, triangles = read_off(tmp_path / "out" / f"frame_{f:03d}.off")
        areas = [shoelace([vertices[a], vertices[b], vertices[c]]) for a, b, c in triangles]
        assert min(areas) > 0
        outer, hole = vertices[:16], vertices[16:24]
        assert math.isclose(sum(areas), abs(shoelace(outer)) - abs(shoelace(hole)), rel_tol=1e-9)


def test_sweep_with_holes(cm, tmp_path):
    """A tube: tetrahedra only in the material (each section's cells cover
    the outer loop's area minus the hole's), every one positive, read back
    by meshio."""
    meshio = pytest.importorskip("meshio")
    import numpy as np
    (tmp_path / "a.xy").write_text(xy_text(SQUARE_WITH_HOLE))
    (tmp_path / "b.xy").write_text(xy_text(DISC_WITH_HOLE))
    result = cm("sweep", "a.xy", "b.xy", "-o", "tube.vtu", "--sections", "3")
    assert result.returncode == 0, result.stderr
    mesh = meshio.read(tmp_path / "tube.vtu")
    prisms = mesh.cells_dict["wedge"]
    p = mesh.points
    bottom = prisms[np.isclose(p[prisms[:, 0], 2], 0.0)]
    e1, e2 = p[bottom[:, 1], :2] - p[bottom[:, 0], :2], p[bottom[:, 2], :2] - p[bottom[:, 0], :2]
    areas = 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    assert areas.min() > 0
    square_area = 4.0 - 0.8 * 0.8
    assert math.isclose(areas.sum(), square_area, rel_tol=1e-9)


def test_obj_empty_loop_line(cm, tmp_path):
    """An 'l' line without indices beside a closed loop: refused, one line."""
    (tmp_path / "a.obj").write_text(obj_text(SQUARE_WITH_HOLE))
    (tmp_path / "b.obj").write_text("l \t\n" + obj_text(DISC_WITH_HOLE))
    result = cm("triangulate", "a.obj", "b.obj", "--out-dir", "out")
    assert result.returncode == 2 and result.stderr.count("\n") == 1
    assert result.stderr.startswith("compatmesh: b.obj:1: an 'l' line needs at least 2 vertices")


def spiky_star(n, seed, scale, clockwise=False):
    """A star-shaped polygon: random angular gaps in [1, 2) (relative, so
    every gap is below pi) and radii in [0.3, 1) times scale."""
    rng = random.Random(seed)
    gaps = [1.0 + rng.random() for _ in range(n)]
    angle, points = 0.0, []
    for gap in gaps:
        angle += 2 * math.pi * gap / sum(gaps)
        radius = scale * (0.3 + 0.7 * rng.random())
        points.append((radius * math.cos(angle), radius * math.sin(angle)))
    return points[::-1] if clockwise else points


QUAD = [(0.0, 0.0), (1.0, 0.3), (0.7, 1.3), (-0.3, 1.0)]


def on_one_input_edge(source, loops, u, w):
    """Do boundary vertices u and w (report.json boundary_source, whole-array
    input edges) lie on one input edge of the loops? An input vertex lies on
    the edges before and after it along its loop, a point inside an edge on
    that edge alone."""
    starts = [sum(len(loop) for loop in loops[:l]) for l in range(len(loops))]

    def edges_of(v):
        e, t = source[v]
        l = max(i for i, start in enumerate(starts) if start <= e)
        before = e - 1 if e > starts[l] else starts[l] + len(loops[l]) - 1
        return {e, before} if t == 0 else {e}
    return bool(edges_of(u) & edges_of(w))


@pytest.mark.parametrize("seed", [5, 12, 14, 20])
def test_no_construction_edge_along_an_input_edge(cm, tmp_path, seed):
    """A slanted quadrilateral with a quadrilateral hole against a star with
    an off-centre star hole (auto, no remeshing): the quadrilateral's loops
    get the stars' vertices on their edges, rounded off the lines, so a
    segment between two on one input edge can pass as a diagonal with a
    sliver beside it (seeds 12, 14 and 20 join two on one edge of the hole
    loop, seed 5 two on the outer loop, when the partition is not told where
    they lie). Expected: points added on the hole loop's edges; no edge of
    the construction but the loops' joins two boundary vertices on one input
    edge of either polygon, on any loop."""
    a = [QUAD, [(0.35 + 0.3 * (x - 0.35), 0.65 + 0.3 * (y - 0.65)) for x, y in reversed(QUAD)]]
    b = [spiky_star(40, seed, 1.0), [(0.12 + x, y) for x, y in spiky_star(24, seed + 50, 0.12, clockwise=True)]]
    (tmp_path / "a.xy").write_text(xy_text(a))
    (tmp_path / "b.xy").write_text(xy_text(b))
    result = cm("triangulate", "a.xy", "b.xy", "-o", "out", "--correspondence", "auto", "--no-remesh")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    n, sources = report["n"], [m["boundary_source"] for m in report["meshes"]]
    hole = [v for v in range(n) if sources[0][v][0] >= 4]
    assert sum(sources[0][v][1] != 0 for v in hole) >= 12
    loop_of = [0 if v < hole[0] else 1 for v in range(n)]
    ring = {(hole[0] - 1, 0), (n - 1, hole[0])}  # each loop's closing edge
    _, triangles = read_off(tmp_path / "out" / "a.off")
    along = []
    for tri in triangles:
        for u, w in zip(tri, tri[1:] + tri[:1]):
            if u >= n or w >= n:
                continue
            if loop_of[u] == loop_of[w] and (abs(u - w) == 1 or (max(u, w), min(u, w)) in ring):
                continue
            if any(on_one_input_edge(source, loops, u, w) for source, loops in zip(sources, (a, b))):
                along.append((u, w))
    assert along == []


@pytest.mark.parametrize("mode", ["index", "auto"])
def test_capped_hole_edges_split(cm, tmp_path, mode):
    """A 10 x 3 rectangle (unit edges, 26 vertices) with an 8 x 1 hole 1
    from either long side (input vertices 26 to 29 clockwise from (1, 1):
    edges 27 and 29 the long ones), against a copy scaled by 2 and moved. A
    triangle on a long hole edge has its apex at most 1 from it, so its
    smallest angle is at most atan(1 / 4) = 14.04 degrees: index keeps the
    loops and stays below that; auto halves the long hole edges twice in
    both meshes (t = 1/4, 1/2, 3/4 on edges 27 and 29; the hole in
    input order, the new points between) and passes it. Both:
    the loops' input vertices bit-identical, V - E + F = 0."""
    outer = ([(float(i), 0.0) for i in range(10)] + [(10.0, float(i)) for i in range(3)] +
             [(float(i), 3.0) for i in range(10, 0, -1)] + [(0.0, float(i)) for i in range(3, 0, -1)])
    a = [outer, [(1.0, 1.0), (1.0, 2.0), (9.0, 2.0), (9.0, 1.0)]]
    b = [[(2 * x + 5, 2 * y - 1) for x, y in loop] for loop in a]
    (tmp_path / "a.xy").write_text(xy_text(a))
    (tmp_path / "b.xy").write_text(xy_text(b))
    result = cm("triangulate", "a.xy", "b.xy", "-o", "out", "--correspondence", mode)
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    least = min(m["min_angle_deg"] for m in report["meshes"])
    bound = math.degrees(math.atan(0.25))
    if mode == "index":
        assert report["n"] == 30 and least <= bound
    else:
        hole = [[26, 0], [27, 0], [27, 0.25], [27, 0.5], [27, 0.75], [28, 0], [29, 0], [29, 0.25], [29, 0.5],
                [29, 0.75]]
        expected = [[i, 0] for i in range(26)] + hole
        assert report["n"] == 36 and least > bound
        assert [m["boundary_source"] for m in report["meshes"]] == [expected, expected]
    for name, loops in (("a", a), ("b", b)):
        vertices, triangles = read_off(tmp_path / "out" / f"{name}.off")
        boundary = vertices[:report["n"]]
        assert all(p in boundary for loop in loops for p in loop)
        edges = {tuple(sorted(e)) for x, y, z in triangles for e in ((x, y), (y, z), (z, x))}
        assert len(vertices) - len(edges) + len(triangles) == 0
