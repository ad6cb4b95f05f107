"""Fixtures for the compatmesh command-line tests.

Run as `python3 -m pytest tests/cli --compatmesh build/bin/compatmesh`.
"""
import os
import subprocess

import pytest

DEFAULT_BINARY = os.path.join(
    os.path.dirname(__file__), "..", "..", "build", "bin", "compatmesh")
DEFAULT_PROBE = os.path.join(os.path.dirname(DEFAULT_BINARY), "report_probe")


def pytest_addoption(parser):
    parser.addoption("--compatmesh", default=os.environ.get("COMPATMESH", DEFAULT_BINARY),
                     help="path of the compatmesh executable under test")
    parser.addoption("--report-probe", default=os.environ.get("REPORT_PROBE", DEFAULT_PROBE),
                     help="path of the report writer's probe (tests/cli/report_probe.c)")


@pytest.fixture(scope="session")
def compatmesh_path(request):
    path = os.path.abspath(request.config.getoption("--compatmesh"))
    if not os.access(path, os.X_OK):
        pytest.fail(f"compatmesh executable not found at {path} (build it, or pass --compatmesh)")
    return path


@pytest.fixture(scope="session")
def report_probe(request):
    path = os.path.abspath(request.config.getoption("--report-probe"))
    if not os.access(path, os.X_OK):
        pytest.fail(f"report_probe not found at {path} (build it, or pass --report-probe)")
    return path


@pytest.fixture
def cm(compatmesh_path, tmp_path):
    """Runs compatmesh with the given arguments in tmp_path."""
    def run(*args, cwd=None):
        return subprocess.run([compatmesh_path, *map(str, args)], cwd=cwd or tmp_path,
                              capture_output=True, timeout=120,
                              encoding="utf-8", errors="replace")
    return run


@pytest.fixture
def gmsh_session():
    """Gmsh's Python API, initialised quietly for one test."""
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    yield gmsh
    gmsh.finalize()
