"""`compatmesh morph`: every frame a valid triangulation (checked exactly),
the straight-line morph's inversions reported, bad input refused."""
import json
import os

import meshio
import numpy as np
import pytest

from polygons import (BOUNDARY, check_pictures, glyph_pair, leftovers, orientation, paths_of, read_vertex_text,
                      snapshot, spiral_pair, twisted_pair, write_xy)

PAIRS = {"twisted": twisted_pair, "spiral": spiral_pair, "glyph": glyph_pair}
FRAMES = 11


def read_off_faces(path):
    with open(path) as f:
        lines = f.read().splitlines()
    vertices, faces = map(int, lines[1].split()[:2])
    return [tuple(int(v) for v in line.split()[1:4])
            for line in lines[2 + vertices:2 + vertices + faces]]


def write_pair(tmp_path, pair):
    a, b = pair
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    return a, b


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_every_frame_is_valid(cm, tmp_path, name):
    a, b = write_pair(tmp_path, PAIRS[name]())
    result = cm("morph", "a.xy", "b.xy", "--frames", FRAMES, "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    out = tmp_path / "out"
    report = json.loads((out / "report.json").read_text())
    assert report["morph"] == "convex"
    assert len(report["frames"]) == FRAMES
    faces = None
    for f, frame in enumerate(report["frames"]):
        path = out / f"frame_{f:03d}.off"
        assert frame["file"] == str(path.relative_to(tmp_path))
        assert frame["t"] == pytest.approx(f / (FRAMES - 1), abs=1e-12)
        assert frame["inverted"] == 0
        assert 0 < frame["min_angle_deg"] < 60
        points = read_vertex_text(path, "off")
        assert len(points) == report["vertices"]
        assert all(z == 0 for _, _, z in points)
        frame_faces = read_off_faces(path)
        assert faces is None or frame_faces == faces  # one connectivity
        faces = frame_faces
        assert len(faces) == report["triangles"]
        # Exactly counter-clockwise: Fractions of the coordinates as read.
        xy = [(x, y) for x, y, _ in points]
        for t in faces:
            assert orientation(xy[t[0]], xy[t[1]], xy[t[2]]) > 0, (f, t)
        # The end frames are the inputs, bit for bit.
        if f == 0:
            assert xy[:len(a)] == [tuple(p) for p in a]
        if f == FRAMES - 1:
            assert xy[:len(b)] == [tuple(p) for p in b]
    assert report["inverted_total"] == 0
    svg = check_pictures(out / "frames.png", out / "frames.svg")
    assert len(paths_of(svg, stroke=BOUNDARY)) == FRAMES  # one panel per frame
    assert leftovers(tmp_path) == []


def test_linear_morph_reports_inversions(cm, tmp_path):
    write_pair(tmp_path, twisted_pair())
    linear = cm("morph", "a.xy", "b.xy", "--frames", FRAMES, "--morph", "linear", "-o", "lin")
    convex = cm("morph", "a.xy", "b.xy", "--frames", FRAMES, "-o", "cvx")
    assert linear.returncode == 0 and convex.returncode == 0, linear.stderr + convex.stderr
    lin = json.loads((tmp_path / "lin" / "report.json").read_text())
    cvx = json.loads((tmp_path / "cvx" / "report.json").read_text())
    assert lin["morph"] == "linear"
    assert lin["inverted_total"] == sum(f["inverted"] for f in lin["frames"]) > 0
    # The end frames are the valid inputs; the folds are in between.
    assert lin["frames"][0]["inverted"] == lin["frames"][-1]["inverted"] == 0
    # The count is what the frames show, by exact orientation.
    for f, frame in enumerate(lin["frames"]):
        path = tmp_path / "lin" / f"frame_{f:03d}.off"
        xy = [(x, y) for x, y, _ in read_vertex_text(path, "off")]
        bad = sum(orientation(xy[a], xy[b], xy[c]) <= 0 for a, b, c in read_off_faces(path))
        assert bad == frame["inverted"]
    assert cvx["inverted_total"] == 0


def test_three_inputs_pass_through_the_middle_one(cm, tmp_path):
    a, b = twisted_pair()
    c, _ = glyph_pair(8)  # 16 vertices like the stars
    for name, points in (("a", a), ("b", b), ("c", c)):
        write_xy(tmp_path / f"{name}.xy", points)
    result = cm("morph", "a.xy", "b.xy", "c.xy", "--frames", 5, "-o", "out")
    assert result.returncode == 0, result.stderr
    middle = read_vertex_text(tmp_path / "out" / "frame_002.off", "off")
    assert [(x, y) for x, y, _ in middle[:len(b)]] == [tuple(p) for p in b]


def test_time_limit_reaches_the_triangulation(cm, tmp_path):
    """The morph's triangulation takes --time-limit: spent before remeshing
    starts, the frames come from the construction, cleaned, and are as
    valid; the report says the limit was reached."""
    write_pair(tmp_path, twisted_pair())
    result = cm("morph", "a.xy", "b.xy", "--frames", 4, "-o", "out", "--time-limit", "1e-6")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["time_limit_reached"] is True
    assert [frame["inverted"] for frame in report["frames"]] == [0] * 4


@pytest.mark.parametrize("args, code, words", [
    (("--frames", "1"), 2, "--frames '1'"),
    (("--frames", "x"), 2, "--frames 'x'"),
    (("--picture-frames", "1"), 2, "--picture-frames '1' is not a whole number from 2 to 1000"),
    (("--morph", "bezier"), 2, "unknown --morph 'bezier'"),
    (("--format", "stl"), 2, "unknown --format 'stl'"),
])
def test_bad_options(cm, tmp_path, args, code, words):
    write_pair(tmp_path, twisted_pair())
    result = cm("morph", "a.xy", "b.xy", "-o", "out", *args)
    assert result.returncode == code
    assert result.stderr.count("\n") == 1 and words in result.stderr
    assert not os.path.exists(tmp_path / "out")


def test_mismatched_counts(cm, tmp_path):
    a, _ = twisted_pair(16)
    _, b = twisted_pair(12)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("morph", "a.xy", "b.xy", "-o", "out", "--correspondence", "index")
    assert result.returncode == 2
    assert result.stderr == ("compatmesh: b.xy has 12 vertices but a.xy has 16; with --correspondence "
                             "index the vertices correspond by index, so the counts must be equal\n")
    assert not os.path.exists(tmp_path / "out")
    assert leftovers(tmp_path) == []


def test_unwritable_output(cm, tmp_path):
    # Tests run as root, which ignores permissions; a regular file in the
    # path makes the directory impossible to create for anyone.
    write_pair(tmp_path, twisted_pair())
    (tmp_path / "blocker").write_text("a file")
    result = cm("morph", "a.xy", "b.xy", "-o", "blocker/out")
    assert result.returncode == 1
    assert result.stderr.startswith("compatmesh: cannot create output directory blocker/out")
    assert result.stderr.count("\n") == 1
    assert (tmp_path / "blocker").read_text() == "a file"


def test_failure_while_writing_leaves_the_directory_as_it_was(cm, tmp_path):
    # A directory in the way of the last frame is only found when moving
    # the frames in; none may have been moved by then.
    write_pair(tmp_path, twisted_pair())
    (tmp_path / "out" / "frame_004.off").mkdir(parents=True)
    (tmp_path / "out" / "keep.txt").write_text("keep me")
    before = snapshot(tmp_path / "out")
    result = cm("morph", "a.xy", "b.xy", "--frames", 5, "-o", "out")
    assert result.returncode == 1
    assert result.stderr == "compatmesh: cannot replace out/frame_004.off: it is a directory\n"
    assert snapshot(tmp_path / "out") == before
    assert leftovers(tmp_path) == []


def test_a_second_morph_replaces_the_first_ones_frames(cm, tmp_path):
    """A morph into a folder holding an earlier morph leaves only its own
    frames there (the earlier ones past its count, or in another format,
    removed), so report.json describes every frame beside it; files that
    are not frames stay."""
    write_pair(tmp_path, twisted_pair())
    out = tmp_path / "out"
    first = cm("morph", "a.xy", "b.xy", "--frames", 6, "-o", "out")
    assert first.returncode == 0, first.stderr
    obj = cm("morph", "a.xy", "b.xy", "--frames", 2, "--format", "obj", "-o", "out")
    assert obj.returncode == 0, obj.stderr
    (out / "frame_notes.txt").write_text("mine")
    (out / "frame_0001.off").write_text("not a name morph writes")
    second = cm("morph", "a.xy", "b.xy", "--frames", 3, "-o", "out")
    assert second.returncode == 0, second.stderr
    frames = sorted(p.name for p in out.iterdir() if p.name.startswith("frame_"))
    assert frames == ["frame_000.off", "frame_0001.off", "frame_001.off", "frame_002.off", "frame_notes.txt"]
    report = json.loads((out / "report.json").read_text())
    assert [os.path.basename(f["file"]) for f in report["frames"]] == frames[:1] + frames[2:4]


@pytest.mark.parametrize("fmt", ["obj", "ply"])
def test_frames_in_other_formats(cm, tmp_path, fmt):
    write_pair(tmp_path, glyph_pair())
    result = cm("morph", "a.xy", "b.xy", "--frames", 3, "--format", fmt, "-o", "out")
    assert result.returncode == 0, result.stderr
    off = cm("morph", "a.xy", "b.xy", "--frames", 3, "-o", "off")
    assert off.returncode == 0, off.stderr
    for f in range(3):
        mesh = meshio.read(tmp_path / "out" / f"frame_{f:03d}.{fmt}")
        reference = meshio.read(tmp_path / "off" / f"frame_{f:03d}.off")
        assert np.array_equal(mesh.cells_dict["triangle"], reference.cells_dict["triangle"])
        assert np.array_equal(mesh.points, reference.points)


def test_many_frames_wrap_into_rows(cm, tmp_path):
    write_pair(tmp_path, twisted_pair())
    result = cm("morph", "a.xy", "b.xy", "--frames", 60, "--picture-frames", 60, "-o", "out",
                "--quiet")
    assert result.returncode == 0, result.stderr
    out = tmp_path / "out"
    svg = check_pictures(out / "frames.png", out / "frames.svg")
    assert len(paths_of(svg, stroke=BOUNDARY)) == 60
    # 60 panels at least 240 pixels wide do not fit in one 8192-pixel row.
    assert int(svg.get("width")[:-2]) <= 8192 and int(svg.get("height")[:-2]) > 2 * 420


def test_picture_shows_evenly_spaced_frames(cm, tmp_path):
    """Of 60 frames the picture draws 12 by default; every frame is still
    written."""
    write_pair(tmp_path, twisted_pair())
    result = cm("morph", "a.xy", "b.xy", "--frames", 60, "-o", "out", "--quiet")
    assert result.returncode == 0, result.stderr
    out = tmp_path / "out"
    assert len(list(out.glob("frame_*.off"))) == 60
    svg = check_pictures(out / "frames.png", out / "frames.svg")
    panels = paths_of(svg, stroke=BOUNDARY)
    assert len(panels) == 12
