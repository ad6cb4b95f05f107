"""`compatmesh triangulate` on valid input: what it writes and how."""
import json
import math
import os
import re
import xml.etree.ElementTree as ET
from collections import Counter

import meshio
import numpy as np
import pytest

from polygons import (BOUNDARY, EDGES, KITE, POOR, SQUARE, STEINER, WORST, caption_lines, check_pictures,
                      drawn_paths, leftovers, paths_of, orientation, read_vertex_text, signed_area,
                      snapshot, spiral_pair, star, write_xy)

def strict_json(path):
    def reject(constant):
        raise ValueError(f"{path}: non-finite number {constant} in JSON")
    with open(path) as f:
        return json.load(f, parse_constant=reject)


def smallest_angles(points, triangles):
    """Smallest angle of every triangle, in degrees."""
    p = points[triangles]  # (t, 3, 2)
    angles = []
    for i in range(3):
        u = p[:, (i + 1) % 3] - p[:, i]
        v = p[:, (i + 2) % 3] - p[:, i]
        cross = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
        angles.append(np.degrees(np.arctan2(cross, (u * v).sum(axis=1))))
    return np.min(angles, axis=0)


def check_mesh_geometry(points, triangles, polygon):
    """The mesh triangulates the polygon: every triangle counter-clockwise,
    the boundary edges exactly the polygon's, the areas adding up."""
    n = len(polygon)
    for a, b, c in triangles:
        assert orientation(points[a], points[b], points[c]) > 0
    edges = Counter()
    for t in triangles:
        for i in range(3):
            edges[frozenset((int(t[i]), int(t[(i + 1) % 3])))] += 1
    assert set(edges.values()) <= {1, 2}
    boundary = {e for e, count in edges.items() if count == 1}
    assert boundary == {frozenset((i, (i + 1) % n)) for i in range(n)}
    area = sum(signed_area([tuple(points[v]) for v in t]) for t in triangles)
    assert math.isclose(area, abs(signed_area(polygon)), rel_tol=1e-9)


def check_success(tmp_path, result, inputs, fmt="off", out="out", preview=True, z=None):
    """Checks everything a successful run promises (the pictures when
    preview); returns the report. z: each input's plane z = constant by
    name, where its file gave one (the meshes are written there), else 0."""
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    out_dir = tmp_path / out
    stems = [os.path.splitext(os.path.basename(name))[0] for name in inputs]
    k, n = len(inputs), len(next(iter(inputs.values())))

    report = strict_json(out_dir / "report.json")
    assert report["valid"] is True
    assert (report["n"], report["k"]) == (n, k)
    steiner = report["steiner"]
    assert steiner >= 0
    assert report["vertices"] == n + steiner
    assert report["triangles"] == n + 2 * steiner - 2
    assert report["method"] in ("partition", "overlay")
    assert report["remesh"] in (True, False)
    assert report["steiner_before_remesh"] >= 0 and report["remesh_iterations"] >= 0
    if report["remesh"]:
        assert 0 < report["remesh_aim_deg"] <= 25
    else:
        assert report["remesh_aim_deg"] == 0
    assert isinstance(report["reversed_input"], bool)
    assert report["fallback_count"] >= 0
    ceiling = report["ceiling"]
    assert set(ceiling) >= {"ceiling_deg", "corner_fan_cap_deg", "correspondence_bound_deg",
                            "modulus_distortion", "distortion_quad"}
    assert ceiling["ceiling_deg"] == min(ceiling["corner_fan_cap_deg"], ceiling["correspondence_bound_deg"])
    assert 0 < ceiling["ceiling_deg"] <= 60 and ceiling["modulus_distortion"] >= 1
    # certified: the smallest angle over all meshes never exceeds it
    assert min(m["min_angle_deg"] for m in report["meshes"]) <= ceiling["ceiling_deg"]
    assert set(report["seconds"]) >= {"validate", "build", "remesh", "check", "ceiling", "total"}
    assert all(value >= 0 for value in report["seconds"].values())
    assert report["seconds"]["total"] >= report["seconds"]["build"]
    assert re.fullmatch(r"\d+\.\d+\.\d+", report["version"])
    assert len(report["meshes"]) == k

    faces = None
    angles_per_mesh = []
    for (name, polygon), stem, entry in zip(inputs.items(), stems, report["meshes"]):
        path = out_dir / f"{stem}.{fmt}"
        assert entry["input"] == name
        assert entry["output"] == f"{out}/{stem}.{fmt}"
        mesh = meshio.read(path, file_format=fmt)
        triangles = mesh.cells_dict["triangle"]
        if faces is None:
            faces = triangles
        assert np.array_equal(triangles, faces), "meshes must share one triangle list"
        assert len(triangles) == report["triangles"]
        assert len(mesh.points) == report["vertices"]
        assert np.all(mesh.points[:, 2] == (z or {}).get(name, 0))

        text = read_vertex_text(path, fmt)
        assert [(x.hex(), y.hex()) for x, y, _ in text[:n]] == \
               [(x.hex(), y.hex()) for x, y in polygon], "input vertices must be bit-identical"
        points = np.array([(x, y) for x, y, _ in text])
        check_mesh_geometry([tuple(p) for p in points], triangles, polygon)

        angles = smallest_angles(points, triangles)
        angles_per_mesh.append(angles)
        assert entry["min_angle_deg"] == pytest.approx(angles.min(), abs=1e-6)
        assert 0 < entry["min_angle_deg"] <= 60 <= entry["max_angle_deg"] < 180
        shares = [entry[f"pct_triangles_below_{d}deg"] for d in (10, 15, 20)]
        assert 0 <= shares[0] <= shares[1] <= shares[2] <= 100
        assert shares[2] == pytest.approx(100 * np.mean(angles < 20), abs=1e-6)
        before = entry["before_remesh"]
        assert 0 < before["min_angle_deg"] <= 60 <= before["max_angle_deg"] < 180
        if not report["remesh"]:
            assert before == {key: entry[key] for key in before}

    if preview:
        svg = check_pictures(out_dir / "preview.png", out_dir / "preview.svg")
        check_svg(svg, inputs, report, angles_per_mesh)
    assert leftovers(tmp_path) == []
    return report


def check_svg(svg, inputs, report, angles_per_mesh):
    """What the SVG draws, by colour: per mesh its worst triangle in red,
    its edges, its boundary in black (n segments, one closed loop), its
    Steiner vertices as blue dots, and every other triangle below 20
    degrees in orange."""
    k = len(inputs)
    worst = paths_of(svg, fill=WORST)
    assert len(worst) == k and all(d.count("Z") == 1 for d in worst)
    assert len(paths_of(svg, stroke=EDGES)) == k
    boundary = paths_of(svg, stroke=BOUNDARY)
    assert len(boundary) == k
    assert all(d.count("L") == report["n"] - 1 and d.count("Z") == 1 for d in boundary)
    poor = sum(np.sum(angles < 20) - (angles.min() < 20) for angles in angles_per_mesh)
    assert sum(d.count("Z") for d in paths_of(svg, fill=POOR)) == poor
    # A dot is a zero-length segment: one move per Steiner vertex per mesh.
    assert sum(d.count("M") for d in paths_of(svg, stroke=STEINER)) == k * report["steiner"]
    known = {WORST, EDGES, BOUNDARY, POOR, STEINER}
    assert all(f in known or s in known for f, s, _, _ in drawn_paths(svg)), "nothing else drawn"
    # The captions, a glyph per character: the input's file name, then
    # "n=.., Steiner .., min angle ..°".
    captions = [(os.path.basename(name),
                 f"n={report['n']}, Steiner {report['steiner']}, min angle {angles.min():.1f}\u00b0")
                for name, angles in zip(inputs, angles_per_mesh)]
    assert [len(xs) for _, xs in caption_lines(svg)] == [len(t) for pair in captions for t in pair]


def test_pair_of_stars_default_off(cm, tmp_path):
    a, b = star(12, seed=1), star(12, seed=2, scale=3.0)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    report = check_success(tmp_path, result, {"a.xy": a, "b.xy": b})
    assert report["steiner"] > 0, "this pair needs Steiner vertices"
    assert sorted(os.listdir(tmp_path / "out")) == \
        ["a.off", "b.off", "preview.png", "preview.svg", "report.json"]


def test_no_preview(cm, tmp_path):
    """--no-preview writes the same meshes and no pictures, removes the
    pictures an earlier run left in the folder (report.json would sit beside
    them without describing them) and says what it wrote."""
    a, b = star(12, seed=1), star(12, seed=2, scale=3.0)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    assert cm("triangulate", "a.xy", "b.xy", "-o", "with").returncode == 0
    assert cm("triangulate", "a.xy", "b.xy", "-o", "out").returncode == 0
    result = cm("triangulate", "a.xy", "b.xy", "-o", "out", "--no-preview")
    check_success(tmp_path, result, {"a.xy": a, "b.xy": b}, preview=False)
    assert sorted(os.listdir(tmp_path / "out")) == ["a.off", "b.off", "report.json"]
    for name in ("a.off", "b.off"):
        assert (tmp_path / "out" / name).read_bytes() == (tmp_path / "with" / name).read_bytes()
    assert result.stdout.splitlines()[-1] == "wrote out/report.json"


def test_time_limit(cm, tmp_path):
    """--time-limit: a limit already spent when the remesher starts leaves
    the construction's cleanup only (no refinement round, no vertex added)
    and says so; the result is as valid as any. A limit that is never
    reached changes nothing, byte for byte."""
    a, b = star(40, seed=3), star(40, seed=4, scale=3.0)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    inputs = {"a.xy": a, "b.xy": b}
    full = check_success(tmp_path, cm("triangulate", "a.xy", "b.xy", "-o", "full"), inputs, out="full")
    assert full["time_limit_reached"] is False and "time_limit" not in full
    assert full["remesh_iterations"] > 0, "this pair refines without a limit"
    spent = check_success(tmp_path, cm("triangulate", "a.xy", "b.xy", "-o", "spent", "--time-limit", "1e-6"),
                          inputs, out="spent")
    assert spent["time_limit_reached"] is True and spent["time_limit"] == 1e-6
    assert spent["remesh_iterations"] == 0
    assert spent["steiner"] <= spent["steiner_before_remesh"]
    ample = check_success(tmp_path, cm("triangulate", "a.xy", "b.xy", "-o", "ample", "--time-limit", "1e6"),
                          inputs, out="ample")
    assert ample["time_limit_reached"] is False
    for name in ("a.off", "b.off"):
        assert (tmp_path / "ample" / name).read_bytes() == (tmp_path / "full" / name).read_bytes()


def test_time_limit_ends_auto_s_pairings(cm, tmp_path):
    """Auto remeshes a second pairing for a spiral against a bar; with its
    time spent it keeps the first and adds nothing to it."""
    spiral, bar = spiral_pair()
    write_xy(tmp_path / "s.xy", spiral)
    write_xy(tmp_path / "b.xy", bar)
    args = ("triangulate", "s.xy", "b.xy", "--correspondence", "auto", "--no-preview")
    result = cm(*args, "-o", "full")
    assert result.returncode == 0, result.stderr
    full = json.loads((tmp_path / "full" / "report.json").read_text())
    assert full["pairings_remeshed"] > 1
    result = cm(*args, "-o", "spent", "--time-limit", "1e-6")
    assert result.returncode == 0, result.stderr
    spent = json.loads((tmp_path / "spent" / "report.json").read_text())
    assert spent["valid"] is True and spent["time_limit_reached"] is True
    assert spent["pairings_remeshed"] == 1 and spent["remesh_iterations"] == 0


@pytest.mark.parametrize("fmt", ["off", "obj", "ply"])
def test_each_format(cm, tmp_path, fmt):
    write_xy(tmp_path / "square.xy", SQUARE)
    write_xy(tmp_path / "kite.xy", KITE)
    result = cm("triangulate", "square.xy", "kite.xy", "--out-dir", "out", "--format", fmt)
    check_success(tmp_path, result, {"square.xy": SQUARE, "kite.xy": KITE}, fmt=fmt)
    assert (tmp_path / "out" / f"square.{fmt}").exists()


def test_three_inputs_short_options(cm, tmp_path):
    polygons = {f"p{i}.xy": star(9, seed=10 + i, scale=1 + i) for i in range(3)}
    for name, points in polygons.items():
        write_xy(tmp_path / name, points)
    result = cm("triangulate", "-o", "out", "-f", "ply", "-m", "overlay", *polygons)
    check_success(tmp_path, result, polygons, fmt="ply")


def test_stdout_summary(cm, tmp_path):
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "res/")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert re.fullmatch(r"wrote res/a\.off \(n=4, steiner=\d+, min angle [\d.]+ deg\)", lines[0])
    assert re.fullmatch(r"wrote res/b\.off \(n=4, steiner=\d+, min angle [\d.]+ deg\)", lines[1])
    assert "res/report.json" in lines[2] and "res/preview.svg" in lines[2]
    assert "res/preview.png" in lines[2]
    assert len(lines) == 3


def test_ceiling_below_target_is_said(cm, tmp_path):
    # A 5 x 1 rectangle against the unit square, corners corresponding: the
    # quadrilateral of the four corners has moduli 5 and 1, so no
    # compatible triangulation can reach 40 degrees (K(alpha) = 5 at about
    # 35.0; the finite elements certify a little less distortion).
    rectangle = [(0.0, 0.0), (5.0, 0.0), (5.0, 1.0), (0.0, 1.0)]
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    write_xy(tmp_path / "a.xy", rectangle)
    write_xy(tmp_path / "b.xy", square)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out", "--min-angle", "40")
    report = check_success(tmp_path, result, {"a.xy": rectangle, "b.xy": square})
    ceiling = report["ceiling"]
    assert ceiling["corner_fan_cap_deg"] == pytest.approx(45)
    assert 35.0 < ceiling["correspondence_bound_deg"] < 36.7
    assert 4.5 < ceiling["modulus_distortion"] <= 5
    assert sorted(ceiling["distortion_quad"]) == [0, 1, 2, 3]
    assert report["remesh_aim_deg"] <= ceiling["ceiling_deg"]
    said = [line for line in result.stdout.splitlines() if line.startswith("no compatible")]
    assert said == ["no compatible triangulation of this pair can have a smallest angle above "
                    f"{ceiling['ceiling_deg']:.1f} degrees (target 40)"]

    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "off", "--min-angle", "40", "--no-ceiling")
    assert result.returncode == 0, result.stderr
    report = strict_json(tmp_path / "off" / "report.json")
    assert report["ceiling"] is None and report["seconds"]["ceiling"] == 0
    assert "no compatible" not in result.stdout


def test_obj_polyline_follows_l_order(cm, tmp_path):
    # v lines out of polygon order, z constant but not 0, extra statements.
    order = [2, 0, 3, 1]  # polygon vertex i is v line order[i]
    v_lines = [None] * 4
    for i, v in enumerate(order):
        v_lines[v] = KITE[i]
    text = "# polyline\no kite\n" + "".join(f"v {x!r} {y!r} 5\n" for x, y in v_lines)
    text += "l " + " ".join(str(v + 1) for v in order + order[:1]) + "\n"
    (tmp_path / "kite.obj").write_text(text)
    write_xy(tmp_path / "square.xy", SQUARE)
    result = cm("triangulate", "kite.obj", "square.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"kite.obj": KITE, "square.xy": SQUARE}, z={"kite.obj": 5})


def test_obj_negative_indices(cm, tmp_path):
    text = "".join(f"v {x!r} {y!r}\n" for x, y in SQUARE) + "l -4 -3 -2 -1 -4\n"
    (tmp_path / "sq.obj").write_text(text)
    write_xy(tmp_path / "kite.xy", KITE)
    result = cm("triangulate", "sq.obj", "kite.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"sq.obj": SQUARE, "kite.xy": KITE})


def test_commas_comments_blank_lines(cm, tmp_path):
    (tmp_path / "a.xy").write_text(
        "# a kite, written every way the format allows\n"
        "\n"
        "0, 0\n"
        "2.5,-0.5   # trailing comment\n"
        "   \t\n"
        "3.0 ,1.7\r\n"
        "  0.2 \t 1.1  \n"
        "# end\n")
    write_xy(tmp_path / "b.xy", SQUARE)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"a.xy": KITE, "b.xy": SQUARE})


def test_xy_with_z(cm, tmp_path):
    """A third column is the section's z, the same on every line; the
    meshes are those of the x y columns alone, written in the plane."""
    (tmp_path / "a.xy").write_text("".join(f"{x!r} {y!r} -2.5\n" for x, y in KITE))
    (tmp_path / "b.xy").write_text("".join(f"{x!r},{y!r},-2.5\n" for x, y in SQUARE))
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"a.xy": KITE, "b.xy": SQUARE}, z={"a.xy": -2.5, "b.xy": -2.5})
    write_xy(tmp_path / "c.xy", KITE)
    write_xy(tmp_path / "d.xy", SQUARE)
    assert cm("triangulate", "c.xy", "d.xy", "--out-dir", "flat").returncode == 0
    in_plane = (tmp_path / "out" / "a.off").read_text().replace(" -2.5\n", " 0\n")
    assert in_plane == (tmp_path / "flat" / "c.off").read_text()


def test_closed_rings_read_without_the_repeat(cm, tmp_path):
    """A last vertex repeating the first exactly closes the ring (GMT, WKT
    and shapefiles write polygons so): read without it, in one file and
    not the other alike; the outputs have the polygon's vertices only."""
    write_xy(tmp_path / "a.xy", KITE + KITE[:1])
    write_xy(tmp_path / "b.xy", SQUARE)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"a.xy": KITE, "b.xy": SQUARE})
    # A repeat of another vertex, or of the first in a file of three lines,
    # is still a repeated vertex.
    write_xy(tmp_path / "c.xy", KITE + KITE[1:2])
    write_xy(tmp_path / "d.xy", KITE[:2] + KITE[:1])
    for bad, line, vertex, of in (("c.xy", 5, 4, 1), ("d.xy", 3, 2, 0)):
        result = cm("triangulate", bad, "b.xy", "--out-dir", "bad")
        assert result.returncode == 2
        assert f"{bad}:{line}: vertex {vertex} repeats vertex {of}" in result.stderr
        assert not (tmp_path / "bad").exists()


def test_header_line_skipped(cm, tmp_path):
    """A first line of words only ('x,y', as spreadsheets and CSV exports
    write) is a header: the run is byte-identical to the one without it."""
    write_xy(tmp_path / "a.csv", KITE, header="# exported\nx,y")
    write_xy(tmp_path / "b.xy", SQUARE, header="X Y")
    result = cm("triangulate", "a.csv", "b.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"a.csv": KITE, "b.xy": SQUARE})
    (tmp_path / "plain").mkdir()
    write_xy(tmp_path / "plain" / "a.csv", KITE)
    write_xy(tmp_path / "plain" / "b.xy", SQUARE)
    plain = cm("triangulate", "plain/a.csv", "plain/b.xy", "--out-dir", "plain_out")
    assert plain.returncode == 0, plain.stderr
    for name in ("a.off", "b.off"):
        assert (tmp_path / "out" / name).read_bytes() == (tmp_path / "plain_out" / name).read_bytes()


@pytest.mark.parametrize("name, text", [
    ("a.xy", "".join(f"{x!r} {y!r}\n" for x, y in KITE)),
    ("a.csv", "x,y\n" + "".join(f"{x!r},{y!r}\n" for x, y in KITE)),
    ("a.obj", "".join(f"v {x!r} {y!r} 0\n" for x, y in KITE) + "l 1 2 3 4 1\n"),
    ("a.geojson", json.dumps({"type": "Polygon", "coordinates": [[list(p) for p in KITE + KITE[:1]]]})),
])
def test_byte_order_mark_skipped(cm, tmp_path, name, text):
    """A UTF-8 byte order mark before a text file (Notepad, spreadsheets'
    "CSV UTF-8") is not part of its first line: the run is byte-identical
    to the one without it (before, an OBJ file lost its first vertex and
    every 'l' index named the next one)."""
    write_xy(tmp_path / "b.xy", SQUARE)
    for folder, mark in (("plain", b""), ("marked", b"\xef\xbb\xbf")):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / name).write_bytes(mark + text.encode())
        result = cm("triangulate", f"{folder}/{name}", "b.xy", "--out-dir", f"{folder}_out")
        assert result.returncode == 0, result.stderr
    check_success(tmp_path, result, {f"marked/{name}": KITE, "b.xy": SQUARE}, out="marked_out")
    for mesh in ("a.off", "b.off"):
        assert (tmp_path / "marked_out" / mesh).read_bytes() == (tmp_path / "plain_out" / mesh).read_bytes()


def test_clockwise_inputs_are_reversed(cm, tmp_path):
    a, b = star(10, seed=3, clockwise=True), star(10, seed=4, clockwise=True)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    report = check_success(tmp_path, result, {"a.xy": a, "b.xy": b})
    assert report["reversed_input"] is True


def test_existing_dir_keeps_other_files(cm, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    (out / "a.off").write_text("stale")
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"a.xy": SQUARE, "b.xy": KITE})
    assert (out / "notes.txt").read_text() == "mine"
    assert (out / "a.off").read_text().startswith("OFF")


def test_inputs_in_other_directories(cm, tmp_path):
    (tmp_path / "x").mkdir()
    (tmp_path / "y").mkdir()
    write_xy(tmp_path / "x" / "first.xy", SQUARE)
    write_xy(tmp_path / "y" / "second.xy", KITE)
    result = cm("triangulate", "x/first.xy", "y/second.xy", "--out-dir", "out")
    check_success(tmp_path, result, {"x/first.xy": SQUARE, "y/second.xy": KITE})


def test_options_after_double_dash_are_inputs(cm, tmp_path):
    write_xy(tmp_path / "-a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    result = cm("triangulate", "--out-dir", "out", "--", "-a.xy", "b.xy")
    check_success(tmp_path, result, {"-a.xy": SQUARE, "b.xy": KITE})


def test_large_input_svg_stays_compact(cm, tmp_path):
    a, b = star(2000, seed=5), star(2000, seed=6, scale=2.0)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    report = strict_json(tmp_path / "out" / "report.json")
    assert report["n"] == 2000 and report["triangles"] == 2000 + 2 * report["steiner"] - 2
    svg = tmp_path / "out" / "preview.svg"
    assert len(drawn_paths(ET.parse(svg).getroot())) <= 2 * 5, "one path per paint and mesh"
    size_per_triangle = os.path.getsize(svg) / (2 * report["triangles"])
    assert size_per_triangle < 200, "SVG should cost a few dozen bytes per triangle"
    text = read_vertex_text(tmp_path / "out" / "a.off", "off")
    assert [(x, y) for x, y, _ in text[:2000]] == a


def test_success_leaves_nothing_else(cm, tmp_path):
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    before = snapshot(tmp_path)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    assert result.returncode == 0
    after = snapshot(tmp_path)
    new = sorted(set(after) - set(before))
    assert new == ["out", "out/a.off", "out/b.off", "out/preview.png", "out/preview.svg",
                   "out/report.json"]


def test_awkward_file_names_keep_report_and_svg_valid(cm, tmp_path):
    # Markup characters, quotes, a backslash and a byte that is not UTF-8.
    odd = 'we"ird & <odd>\\ \udcff.xy'  # \udcff: the raw byte 0xff on disk
    write_xy(tmp_path / odd, SQUARE)
    write_xy(tmp_path / "plain.xy", KITE)
    result = cm("triangulate", odd, "plain.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    report = strict_json(tmp_path / "out" / "report.json")
    assert report["meshes"][0]["input"] == odd.replace("\udcff", "\ufffd")
    # cairo refuses text that is not UTF-8: drawn, the caption has U+FFFD for
    # the byte, and both pictures are complete.
    check_pictures(tmp_path / "out" / "preview.png", tmp_path / "out" / "preview.svg")
    assert (tmp_path / "out" / os.fsdecode(b'we"ird & <odd>\\ \xff.off')).exists()
