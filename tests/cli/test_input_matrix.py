"""The bad-input matrix (tests/bad_input/cases.txt) through
`compatmesh triangulate`, `morph` and `sweep`, each polygon an .xy file: exit 2 with one line
naming the file (and the line of the vertex the core located) and no output
for the bad cases, exit 0 with every output file for the legal ones. Then
what only the command line meets: truncated and unreadable inputs, and
output directories no one, root included, can write."""
import os
import re
import sys

import pytest

from polygons import KITE, SQUARE, leftovers, snapshot, write_xy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bad_input"))
import cases as matrix  # noqa: E402

CASES = matrix.load()


def one_line(result):
    return result.stdout == "" and result.stderr.endswith("\n") and result.stderr.count("\n") == 1


# Every command that starts from polygons, with what it writes on success.
COMMANDS = {
    "triangulate": (["--out-dir", "out"],
                    lambda k: [f"p{g}.off" for g in range(k)] + ["report.json", "preview.svg", "preview.png"]),
    "morph": (["--out-dir", "out", "--frames", "3"],
              lambda k: [f"frame_{f:03d}.off" for f in range(3)] + ["report.json", "frames.svg", "frames.png"]),
    "sweep": (["-o", "out/sweep.msh", "--sections", "3"], lambda k: ["sweep.msh"]),
}


# Legal input a command cannot take, with the one-line error (exit 1) it
# gives: the morph's common enclosure is the same in every geometry, so a
# polygon 1e600 times smaller than another sits in an annulus too thin for
# double precision.
LIMITS = {
    ("huge and tiny in one call", "morph"): r"compatmesh: morph: mean value weight .* too flat",
    ("huge and tiny in one call", "sweep"): r"compatmesh: sweep: morph: mean value weight .* too flat",
}


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_case(cm, tmp_path, case, command):
    names = []
    for g, polygon in enumerate(case.polygons):
        write_xy(tmp_path / f"p{g}.xy", polygon)
        names.append(f"p{g}.xy")
    arguments, outputs = COMMANDS[command]
    if command == "sweep":
        (tmp_path / "out").mkdir()
    # The matrix states the index correspondence's contract (equal counts);
    # by default the tool pairs different counts by arc length instead.
    result = cm(command, *names, *arguments, "--correspondence", "index")
    if (case.name, command) in LIMITS:
        assert result.returncode == 1 and one_line(result), result.stderr
        assert re.match(LIMITS[case.name, command], result.stderr), result.stderr
        assert leftovers(tmp_path) == [] and not os.listdir(tmp_path / "out") \
            if command == "sweep" else not (tmp_path / "out").exists()
        return
    if case.status == "ok":
        assert result.returncode == 0, result.stderr
        assert sorted(os.listdir(tmp_path / "out")) == sorted(outputs(len(names)))
        return
    assert result.returncode == 2, (result.stdout, result.stderr)
    assert one_line(result), result.stderr
    assert result.stderr.startswith("compatmesh: ")
    if case.polygon is not None and case.polygon >= 0:
        where = re.escape(f"p{case.polygon}.xy")
        if case.vertex is not None and case.vertex >= 0:
            where += f":{case.vertex + 1}:"  # one vertex per line
        assert re.search(where, result.stderr), result.stderr
    if command == "sweep":
        assert os.listdir(tmp_path / "out") == []
    else:
        assert not (tmp_path / "out").exists()
    assert leftovers(tmp_path) == []


SQUARE_TEXT = "".join(f"{x!r} {y!r}\n" for x, y in SQUARE)

# name: (content of b.xy or b.obj, file name, exit status, stderr pattern)
FILE_CASES = {
    "truncated_xy": ("0 0\n1 0\n1 1\n0", "b.xy", 2, r"b\.xy:4: expected 2 or 3 numbers"),
    "truncated_number": ("0 0\n1 0\n1 1\n0 1e", "b.xy", 2, r"b\.xy:4: '1e' is not a number"),
    "truncated_obj": ("v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3", "b.obj", 2, r"b\.obj:5: .*not closed"),
    "obj_cut_before_l": ("v 0 0\nv 1 0\nv 1 1\nv 0", "b.obj", 2, r"b\.obj:4: expected 'v x y \[z\]'"),
    "empty_obj": ("", "b.obj", 2, r"b\.obj: no 'l' line"),
    "utf16_text": ("0 0\n1 0\n1 1\n0 1\n".encode("utf-16"), "b.xy", 2, r"b\.xy:1: binary data"),
}


@pytest.mark.parametrize("case", sorted(FILE_CASES))
def test_file_case(cm, tmp_path, case):
    content, name, code, pattern = FILE_CASES[case]
    (tmp_path / "a.xy").write_text(SQUARE_TEXT)
    path = tmp_path / name
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    result = cm("triangulate", "a.xy", name, "--out-dir", "out")
    assert result.returncode == code and one_line(result), result.stderr
    assert re.match("compatmesh: " + pattern, result.stderr), result.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("path, pattern", [
    ("/proc/self/mem", r"/proc/self/mem: cannot read: Input/output error"),
    ("x" * 300 + ".xy", r"x+\.xy: cannot open: File name too long"),
    ("/proc/self/fd/", r"/proc/self/fd/: not a file name"),
])
def test_unreadable_input(cm, tmp_path, path, pattern):
    write_xy(tmp_path / "a.xy", SQUARE)
    result = cm("triangulate", "a.xy", path, "--out-dir", "out")
    assert result.returncode == 2 and one_line(result), result.stderr
    assert re.match("compatmesh: " + pattern, result.stderr), result.stderr
    assert not (tmp_path / "out").exists()


# Directories that cannot be written even by root: /proc takes no new
# entries, and a path below a regular file cannot exist.
@pytest.mark.parametrize("out_dir, pattern", [
    ("/proc", r"cannot create a temporary directory in or beside /proc: "),
    ("/proc/compatmesh-out", r"cannot create a temporary directory in or beside /proc/compatmesh-out: "),
    ("/proc/self/compatmesh-out", r"cannot write to /proc/self: "),
    ("a.xy/out", r"cannot create output directory a\.xy/out: "),
])
def test_unwritable_out_dir(cm, tmp_path, out_dir, pattern):
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    before = snapshot(tmp_path)
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", out_dir)
    assert result.returncode == 1 and one_line(result), result.stderr
    assert re.match("compatmesh: " + pattern, result.stderr), result.stderr
    assert snapshot(tmp_path) == before
    assert not any(name.endswith(".off") for name in os.listdir("/proc"))


def test_existing_out_dir_keeps_no_staging(cm, tmp_path):
    # The temporary directory lives inside an existing output directory (it
    # may be a mount point, where renames from its parent would fail).
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    (tmp_path / "out").mkdir()
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    assert sorted(os.listdir(tmp_path / "out")) == ["a.off", "b.off", "preview.png", "preview.svg", "report.json"]
    assert leftovers(tmp_path) == []


def test_extreme_magnitudes_give_a_valid_result(cm, tmp_path):
    # Found by fuzzing: magnitudes 1e-322 to 1e294 inside one polygon. The
    # construction used to give up here (rounded Steiner positions inverted
    # a triangle); the overlay now moves such vertices to valid doubles, and
    # the core checks the result exactly before anything is written.
    write_xy(tmp_path / "a.xy", [(0.0, 0.0), (1.8623734600510786e-289, -1.5935549557357777e+294),
                                 (-2.6126088269340293e+260, 1.6541803121167156e+221), (6.23e-322, 0.0)])
    write_xy(tmp_path / "b.xy", [(-6.765728953191907e+46, -6.765728953192395e+46),
                                 (4.0328889982143946e-11, 4.513438807777116e+70),
                                 (1.34645866811137e-309, 0.0), (0.0, 0.0)])
    result = cm("triangulate", "a.xy", "b.xy", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    assert sorted(os.listdir(tmp_path / "out")) == ["a.off", "b.off", "preview.png", "preview.svg", "report.json"]
    assert leftovers(tmp_path) == []
