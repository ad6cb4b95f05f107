"""`compatmesh triangulate` on bad input: exit code, one-line message, and
no output at all (the output directory absent, or unchanged if it existed)."""
import re

import pytest

from polygons import KITE, SQUARE, leftovers, snapshot, write_xy

PENTAGON = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (5.0, 12.0), (0.0, 10.0)]
SQUARE_TEXT = "".join(f"{x!r} {y!r}\n" for x, y in SQUARE)
KITE_TEXT = "".join(f"{x!r} {y!r}\n" for x, y in KITE)

# name: (files to create, arguments before --out-dir, stderr pattern)
CASES = {
    "missing_file": ({"a.xy": SQUARE_TEXT}, ["a.xy", "missing.xy"],
                     r"missing\.xy: cannot open: No such file"),
    "directory_as_input": ({"a.xy": SQUARE_TEXT, "d.xy/": None}, ["a.xy", "d.xy"],
                           r"d\.xy: cannot read"),
    "empty_file": ({"a.xy": SQUARE_TEXT, "b.xy": ""}, ["a.xy", "b.xy"],
                   r"b\.xy: no vertices"),
    "only_comments": ({"a.xy": SQUARE_TEXT, "b.xy": "# x y\n\n  # none\n"}, ["a.xy", "b.xy"],
                      r"b\.xy: no vertices"),
    "truncated_line": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0\n1.0\n0 1\n"}, ["a.xy", "b.xy"],
                       r"b\.xy:3: expected 2 or 3 numbers"),
    "four_numbers": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0 0 1\n1 1\n0 1\n"}, ["a.xy", "b.xy"],
                     r"b\.xy:2: expected 2 or 3 numbers 'x y \[z\]', found 4 fields"),
    "xy_z_not_constant": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0 1\n1 0 1\n1 1 2\n0 1 1\n"}, ["a.xy", "b.xy"],
                          r"b\.xy:[1-4]: the polygon is not planar"),
    "xy_z_on_some_lines": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0 1\n1 0\n1 1 1\n0 1 1\n"}, ["a.xy", "b.xy"],
                           r"b\.xy:2: no z here, while line 1 gives one; give z on every line or on none"),
    "xy_z_missing_last": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0 5\n10 0 5\n10 10 5\n0 10\n"}, ["a.xy", "b.xy"],
                          r"b\.xy:4: no z here, while line 1 gives one"),
    "xy_z_only_later": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0\n1 1 0\n0 1\n"}, ["a.xy", "b.xy"],
                        r"b\.xy:3: a z here, while line 1 gives none"),
    "obj_z_on_some_lines": ({"a.xy": SQUARE_TEXT, "b.obj": "v 0 0 1\nv 1 0 1\nv 1 1\nv 0 1 1\nl 1 2 3 4 1\n"},
                            ["a.xy", "b.obj"], r"b\.obj:3: no z here, while line 1 gives one"),
    "hexadecimal": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0\n0x10 1\n0 1\n"}, ["a.xy", "b.xy"],
                    r"b\.xy:3: '0x10' is not a number"),
    "garbage_text": ({"a.xy": SQUARE_TEXT, "b.xy": "hello world\nthis is text\n"}, ["a.xy", "b.xy"],
                     r"b\.xy:2: 'this' is not a number"),
    "header_only": ({"a.xy": SQUARE_TEXT, "b.xy": "x,y\n"}, ["a.xy", "b.xy"], r"b\.xy: no vertices"),
    "header_not_first": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\nx y\n1 1\n0 1\n"}, ["a.xy", "b.xy"],
                         r"b\.xy:2: 'x' is not a number"),
    "header_with_a_number": ({"a.xy": SQUARE_TEXT, "b.xy": "x,1\n0 0\n1 0\n1 1\n"}, ["a.xy", "b.xy"],
                             r"b\.xy:1: 'x' is not a number"),
    "number_with_junk": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0\n1 1x\n0 1\n"}, ["a.xy", "b.xy"],
                         r"b\.xy:3: '1x' is not a number"),
    "doubled_comma": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1,,0\n1 1\n0 1\n"}, ["a.xy", "b.xy"],
                      r"b\.xy:2: misplaced ','"),
    "binary_garbage": ({"a.xy": SQUARE_TEXT, "b.xy": b"\x89PNG\r\n\x1a\n\x00\x00\xff" * 20},
                       ["a.xy", "b.xy"], r"b\.xy:3: binary data"),
    "binary_without_nul": ({"a.xy": SQUARE_TEXT, "b.xy": bytes(range(1, 256)) * 3},
                           ["a.xy", "b.xy"], r"b\.xy:\d+: "),
    "nan": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0\nnan 1\n0 1\n"}, ["a.xy", "b.xy"],
            r"b\.xy:3: 'nan' is not a finite number"),
    "infinity": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1 0\n1 -inf\n0 1\n"}, ["a.xy", "b.xy"],
                 r"b\.xy:3: '-inf' is not a finite number"),
    "overflow": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n1e999 0\n1 1\n0 1\n"}, ["a.xy", "b.xy"],
                 r"b\.xy:2: '1e999' is too large"),
    "mismatched_counts": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n2 0\n3 1\n1 2\n0 1\n"},
                          ["a.xy", "b.xy", "--correspondence", "index"], r"b\.xy has 5 vertices but a\.xy has 4"),
    "too_few_vertices": ({"a.xy": "0 0\n1 0\n", "b.xy": "0 0\n2 0\n"}, ["a.xy", "b.xy"],
                         r"a\.xy: .*3"),
    "repeated_vertex": ({"a.xy": "0 0\n4 0\n4 4\n2 5\n0 4\n",
                         "b.xy": "# repeated\n0 0\n4 0\n4 4\n0 4\n4 0\n"}, ["a.xy", "b.xy"],
                        r"b\.xy:(3|6): "),
    "mixed_orientation": ({"a.xy": SQUARE_TEXT, "b.xy": "0 0\n0 1\n1 1\n1 0\n"},
                          ["a.xy", "b.xy"], r"b\.xy: .*clockwise"),
    "obj_not_closed": ({"a.xy": SQUARE_TEXT, "b.obj": "v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 4\n"},
                       ["a.xy", "b.obj"], r"b\.obj:5: .*not closed"),
    "obj_two_polylines": ({"a.xy": SQUARE_TEXT,
                           "b.obj": "v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 4 1\nl 1 2 3 1\n"},
                          ["a.xy", "b.obj"], r"b\.obj:6: the edge 1-2 is given twice \(also at line 5\)"),
    "obj_no_polyline": ({"a.xy": SQUARE_TEXT, "b.obj": "v 0 0\nv 1 0\nv 1 1\n"},
                        ["a.xy", "b.obj"], r"b\.obj: no 'l' line"),
    "obj_index_out_of_range": ({"a.xy": SQUARE_TEXT,
                                "b.obj": "v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 7 1\n"},
                               ["a.xy", "b.obj"], r"b\.obj:5: vertex index 7 is out of range"),
    "obj_z_not_constant": ({"a.xy": SQUARE_TEXT,
                            "b.obj": "v 0 0 1\nv 1 0 1\nv 1 1 2\nv 0 1 1\nl 1 2 3 4 1\n"},
                           ["a.xy", "b.obj"], r"b\.obj:[1-4]: the polygon is not planar"),
    "duplicate_stems": ({"a.xy": SQUARE_TEXT, "sub/a.xy": KITE_TEXT}, ["a.xy", "sub/a.xy"],
                        r"a\.xy and sub/a\.xy would both be written to a\.off"),
    "duplicate_stems_across_formats": ({"a.xy": SQUARE_TEXT,
                                        "a.obj": "v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 4 1\n"},
                                       ["a.xy", "a.obj"], r"a\.xy and a\.obj would both be written to a\.off"),
    "same_file_twice": ({"a.xy": SQUARE_TEXT}, ["a.xy", "a.xy"], r"a\.xy and a\.xy would both be written"),
    "unknown_option": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                       ["a.xy", "b.xy", "--frobnicate"], r"triangulate: unknown option '--frobnicate'"),
    "unknown_short_option": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                             ["-x", "a.xy", "b.xy"], r"triangulate: unknown option '-x'"),
    "value_for_a_flag": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                         ["a.xy", "b.xy", "--no-remesh=yes"], r"triangulate: option '--no-remesh' takes no value"),
    "unknown_format": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                       ["a.xy", "b.xy", "--format", "stl"], r"triangulate: unknown --format 'stl'"),
    "unknown_method": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                       ["a.xy", "b.xy", "--method", "magic"], r"triangulate: unknown --method 'magic'"),
    "min_angle_too_big": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                          ["a.xy", "b.xy", "--min-angle", "60"],
                          r"triangulate: --min-angle needs degrees in \(0, 60\), got '60'"),
    "min_angle_not_a_number": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                               ["a.xy", "b.xy", "--min-angle", "nan"],
                               r"triangulate: --min-angle needs degrees in \(0, 60\), got 'nan'"),
    "negative_max_steiner": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                             ["a.xy", "b.xy", "--max-steiner", "-1"],
                             r"triangulate: --max-steiner needs a whole number in \[0, \d+\], got '-1'"),
    "time_limit_zero": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                        ["a.xy", "b.xy", "--time-limit", "0"],
                        r"triangulate: --time-limit needs positive seconds, got '0'"),
    "time_limit_not_a_number": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                                ["a.xy", "b.xy", "--time-limit", "1s"],
                                r"triangulate: --time-limit needs positive seconds, got '1s'"),
    "time_limit_infinite": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                            ["a.xy", "b.xy", "--time-limit", "inf"],
                            r"triangulate: --time-limit needs positive seconds, got 'inf'"),
    "k_split_not_whole": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                          ["a.xy", "b.xy", "--k-split", "2.5"],
                          r"triangulate: --k-split needs a whole number in \[0, \d+\], got '2\.5'"),
    "unknown_smoothing": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                          ["a.xy", "b.xy", "--smoothing", "magic"],
                          r"triangulate: unknown --smoothing 'magic'"),
    "unknown_remesher": ({"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT},
                         ["a.xy", "b.xy", "--remesher", "magic"],
                         r"triangulate: unknown --remesher 'magic' \(known: greedy, map\)"),
    "one_input": ({"a.xy": SQUARE_TEXT}, ["a.xy"], r"triangulate: needs at least two input polygons, got 1"),
    "no_input": ({}, [], r"triangulate: needs at least two input polygons, got 0"),
}


def create_files(root, files):
    for name, content in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if content is None:
            path.mkdir()
        elif isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)


def check_failure(result, code, pattern):
    assert result.returncode == code, (result.stdout, result.stderr)
    assert result.stdout == ""
    assert result.stderr.endswith("\n") and result.stderr.count("\n") == 1, \
        "exactly one line on stderr"
    assert re.match(r"compatmesh: " + pattern, result.stderr), result.stderr


def prepare_existing_out_dir(out):
    out.mkdir()
    (out / "keep.txt").write_text("keep me")
    (out / "a.off").write_text("an older result")
    (out / "report.json").write_text("{}")


@pytest.mark.parametrize("existing", [False, True], ids=["new_dir", "existing_dir"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_failure_writes_nothing(cm, tmp_path, case, existing):
    files, args, pattern = CASES[case]
    create_files(tmp_path, files)
    out = tmp_path / "out"
    if existing:
        prepare_existing_out_dir(out)
    before = snapshot(out)
    result = cm("triangulate", *args, "--out-dir", "out")
    check_failure(result, 2, pattern)
    assert snapshot(out) == before
    assert leftovers(tmp_path) == []


@pytest.mark.parametrize("existing", [False, True], ids=["new_dir", "existing_dir"])
def test_self_intersection_names_file_and_line(cm, tmp_path, existing):
    write_xy(tmp_path / "a.xy", PENTAGON)
    # Edges 0-1 and 3-4 cross; blank and comment lines shift every vertex
    # off line index + 1, so only a real line lookup gives line 4 for vertex 0.
    bad = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (5.0, 10.0), (5.0, -1.0)]
    lines = write_xy(tmp_path / "b.xy", bad, header="# twisted\n\n# pentagon")
    assert lines[0] == 4
    out = tmp_path / "out"
    if existing:
        prepare_existing_out_dir(out)
    before = snapshot(out)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_failure(result, 2, r"b\.xy:4: .*(cross|intersect)")
    assert snapshot(out) == before
    assert leftovers(tmp_path) == []


def test_missing_out_dir_option(cm, tmp_path):
    create_files(tmp_path, {"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT})
    check_failure(cm("triangulate", "a.xy", "b.xy"), 2, r"triangulate: --out-dir DIR is required")
    check_failure(cm("triangulate", "a.xy", "b.xy", "--out-dir"), 2,
                  r"triangulate: option '--out-dir' needs a value")


def test_out_dir_is_a_regular_file(cm, tmp_path):
    create_files(tmp_path, {"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT, "out": "a file"})
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_failure(result, 2, r"--out-dir: out exists and is not a directory")
    assert (tmp_path / "out").read_text() == "a file"
    assert leftovers(tmp_path) == []


def test_out_dir_below_a_regular_file(cm, tmp_path):
    # Tests run as root, which ignores permissions; a regular file in the path
    # makes the directory impossible to create for anyone.
    create_files(tmp_path, {"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT, "blocker": "a file"})
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "blocker/out")
    check_failure(result, 1, r"cannot create output directory blocker/out: .*blocker.*")
    assert (tmp_path / "blocker").read_text() == "a file"


def test_out_dir_parent_missing(cm, tmp_path):
    create_files(tmp_path, {"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT})
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "no/such/out")
    check_failure(result, 1, r"cannot create output directory no/such/out")
    assert not (tmp_path / "no").exists()


def test_directory_in_the_way_of_an_output(cm, tmp_path):
    # Found when moving the files in; must be found before moving any.
    create_files(tmp_path, {"a.xy": SQUARE_TEXT, "b.xy": KITE_TEXT, "out/b.off/": None})
    (tmp_path / "out" / "keep.txt").write_text("keep me")
    before = snapshot(tmp_path / "out")
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    check_failure(result, 1, r"cannot replace out/b\.off: it is a directory")
    assert snapshot(tmp_path / "out") == before
    assert leftovers(tmp_path) == []
