"""Help, version and the top-level command line."""
import re

import pytest

TRIANGULATE_OPTIONS = ["--out-dir", "--format", "--method", "--no-remesh", "--min-angle",
                       "--max-steiner", "--k-split", "--area-every", "--smoothing", "--remesher",
                       "--max-iterations", "--progress", "--quiet", "--help"]


def check_exit_codes_documented(text):
    for code in ("0", "1", "2"):
        assert re.search(rf"^\s+{code}\s+\S", text, re.MULTILINE), f"exit code {code}"


@pytest.mark.parametrize("flag", ["--help", "-h"])
def test_main_help(cm, flag):
    result = cm(flag)
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.startswith("Usage: compatmesh COMMAND")
    assert re.search(r"^\s+triangulate\s", result.stdout, re.MULTILINE)
    check_exit_codes_documented(result.stdout)


@pytest.mark.parametrize("flag", ["--help", "-h"])
def test_triangulate_help(cm, flag):
    result = cm("triangulate", flag)
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.startswith("Usage: compatmesh triangulate IN1 IN2")
    for option in TRIANGULATE_OPTIONS:
        assert re.search(rf"^\s+(-\w, )?{option}\b", result.stdout, re.MULTILINE), option
    for word in ("off", "obj", "ply", "partition", "overlay", "report.json", "preview.svg",
                 "preview.png"):
        assert word in result.stdout
    check_exit_codes_documented(result.stdout)


def test_help_wins_over_missing_arguments(cm):
    assert cm("triangulate", "--help", "--format", "off").returncode == 0


def test_version(cm):
    result = cm("--version")
    assert result.returncode == 0
    assert re.fullmatch(r"compatmesh \d+\.\d+\.\d+\n", result.stdout)


@pytest.mark.parametrize("args, pattern", [
    ([], r"compatmesh: missing command"),
    (["frobnicate"], r"compatmesh: unknown command 'frobnicate'"),
    (["--frobnicate"], r"compatmesh: unknown option '--frobnicate'"),
])
def test_usage_errors(cm, args, pattern):
    result = cm(*args)
    assert result.returncode == 2
    assert re.match(pattern, result.stderr) and result.stderr.count("\n") == 1


@pytest.mark.parametrize("command, options, words", [
    ("morph", ["--out-dir", "--frames", "--morph", "--format", "--method", "--no-remesh",
               "--progress", "--quiet", "--help"],
     ["convex", "linear", "frame_000", "frames.svg", "frames.png", "report.json"]),
    ("sweep", ["--output", "--sections", "--height", "--heights", "--tets", "--msh-version",
               "--method", "--no-remesh", "--progress", "--quiet", "--help"],
     [".msh", ".vtk", ".inp", ".bdf", ".unv", "2.2", "4.1"]),
])
def test_morph_and_sweep_help(cm, command, options, words):
    result = cm(command, "--help")
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.startswith(f"Usage: compatmesh {command} IN1 IN2")
    for option in options:
        assert re.search(rf"^\s+(-\w, )?{option}\b", result.stdout, re.MULTILINE), option
    for word in words:
        assert word in result.stdout
    check_exit_codes_documented(result.stdout)
    main = cm("--help").stdout
    assert re.search(rf"^\s+{command}\s", main, re.MULTILINE)
