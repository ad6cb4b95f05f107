"""bench/same_output.py: a build against itself gives the same outputs
(exit 0, no run differs); against a build that meshes differently (here
the same one capped at no Steiner vertex) the runs are named DIFFERENT and
the exit code is 1; --args reaches every run (with --no-remesh the cap,
which binds only the remesher, changes nothing)."""
import os
import stat
import subprocess
import sys

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
CLI = os.environ["COMPATMESH"]
GEN = os.environ["CM_GEN_PAIRS"]
SCRIPT = os.path.join(BENCH, "same_output.py")
TINY = "^(twisted_star_n16|random_disc_n16)$"


def compare(new, *extra):
    return subprocess.run([sys.executable, SCRIPT, "--old", CLI, "--new", new, "--gen-pairs", GEN,
                           "--only", TINY, "--repeats", "1", *extra],
                          capture_output=True, text=True, timeout=300)


def test_same_build_is_the_same():
    run = compare(CLI)
    assert run.returncode == 0, run.stdout + run.stderr
    lines = run.stdout.splitlines()
    assert sum(" same" in line for line in lines) == 2  # two bench pairs, index mode only
    assert "runs that differ: 0; failed: 0" in run.stdout


def capped(tmp_path):
    other = tmp_path / "capped"
    other.write_text('#!/bin/sh\nexec "%s" "$@" --max-steiner 0\n' % CLI)
    other.chmod(other.stat().st_mode | stat.S_IXUSR)
    return str(other)


def test_a_different_mesh_is_found(tmp_path):
    run = compare(capped(tmp_path))
    assert run.returncode == 1, run.stdout + run.stderr
    assert "DIFFERENT" in run.stdout and "runs that differ: 2" in run.stdout


def test_args_reach_every_run(tmp_path):
    run = compare(capped(tmp_path), "--args", "--no-remesh --no-preview")
    assert run.returncode == 0, run.stdout + run.stderr
    assert "runs that differ: 0; failed: 0" in run.stdout
