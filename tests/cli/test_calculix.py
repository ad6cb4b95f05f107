"""The sweep's Abaqus deck solved by a real finite-element solver
(CalculiX's ccx, which reads Abaqus input): the bottom fixed and the top
pulled through the node sets the tool writes. Pulled with Poisson's ratio
0, a straight tube's displacement is linear in z, which linear prisms and
tetrahedra reproduce exactly, so the reaction must be E A delta / L to the
solver's precision; a tapered pipe must be solved too, its reaction
between the stiffnesses of its narrowest and widest sections."""
import math
import re
import shutil
import subprocess

import pytest

from test_sweep import reported, ring, write_boundary_pair

E, DELTA, HEIGHT = 1000.0, 0.01, 2.0


def polygon_area(points):
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1])))


def solve(tmp_path, deck):
    """Runs ccx on deck (a file in tmp_path); returns the bottom set's
    reaction (fx, fy, fz)."""
    ccx = shutil.which("ccx")
    assert ccx, "CalculiX's ccx is missing (Debian package calculix-ccx, which `make deps` installs)"
    (tmp_path / "job.inp").write_text(
        f"*INCLUDE, INPUT={deck}\n*MATERIAL, NAME=SOLID\n*ELASTIC\n{E}, 0.0\n"
        "*SOLID SECTION, ELSET=sweep, MATERIAL=SOLID\n*STEP\n*STATIC\n*BOUNDARY\n"
        f"bottom, 1, 3\ntop, 3, 3, {DELTA}\n*NODE PRINT, NSET=bottom, TOTALS=ONLY\nRF\n*END STEP\n")
    run = subprocess.run([ccx, "-i", "job"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0 and "ERROR" not in run.stdout.upper(), run.stdout[-2000:]
    text = (tmp_path / "job.dat").read_text()
    m = re.search(r"total force \(fx,fy,fz\) for set BOTTOM.*\n\s*\n\s*(\S+)\s+(\S+)\s+(\S+)", text)
    assert m, text
    return [float(v) for v in m.groups()]


@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_straight_tube_pulled(cm, tmp_path, kind):
    write_boundary_pair(tmp_path, "pipe")
    shutil.copy(tmp_path / "a.xy", tmp_path / "b.xy")
    extra = ["--tets"] if kind == "tet" else []
    result = cm("sweep", "a.xy", "b.xy", "--height", HEIGHT, "-o", "tube.inp", *extra, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    outer, hole = ring(1.0, 0.4, 0.0)
    area = polygon_area(outer) - polygon_area(hole)
    fx, fy, fz = solve(tmp_path, "tube.inp")
    assert fz == pytest.approx(-E * area * DELTA / HEIGHT, rel=1e-6)
    assert abs(fx) < 1e-9 and abs(fy) < 1e-9


@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_tapered_pipe_pulled(cm, tmp_path, kind):
    write_boundary_pair(tmp_path, "pipe")
    extra = ["--tets"] if kind == "tet" else []
    result = cm("sweep", "a.xy", "b.xy", "--height", HEIGHT, "-o", "pipe.inp", *extra, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    areas = [polygon_area(outer) - polygon_area(hole) for outer, hole in (ring(1.0, 0.4, 0.0), ring(1.2, 0.3, 0.2))]
    _, _, fz = solve(tmp_path, "pipe.inp")
    assert E * min(areas) * DELTA / HEIGHT < -fz < E * max(areas) * DELTA / HEIGHT
