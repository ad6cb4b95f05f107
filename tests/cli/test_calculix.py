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

import numpy as np
import pytest

from test_sweep import reported, ring, write_boundary_pair

E, DELTA, HEIGHT = 1000.0, 0.01, 2.0


def polygon_area(points):
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1])))


def solve(tmp_path, deck, restraints=(("bottom", 1, 3), ("top", 3, 3, DELTA)), loads=(), reacting="bottom"):
    """Runs ccx on deck (a file in tmp_path) with the node sets' restraints
    (set, first dof, last dof[, displacement]) and pressures on the
    element-face surfaces (surface, pressure); by default the bottom held
    and the top pulled by DELTA. Returns the reaction (fx, fy, fz) over the
    node set `reacting`."""
    ccx = shutil.which("ccx")
    assert ccx, "CalculiX's ccx is missing (Debian package calculix-ccx, which `make deps` installs)"
    (tmp_path / "job.inp").write_text(
        f"*INCLUDE, INPUT={deck}\n*MATERIAL, NAME=SOLID\n*ELASTIC\n{E}, 0.0\n"
        "*SOLID SECTION, ELSET=sweep, MATERIAL=SOLID\n*STEP\n*STATIC\n*BOUNDARY\n"
        + "".join(", ".join(str(v) for v in r) + "\n" for r in restraints)
        + ("*DSLOAD\n" + "".join(f"{name}, P, {p}\n" for name, p in loads) if loads else "")
        + f"*NODE PRINT, NSET={reacting}, TOTALS=ONLY\nRF\n*END STEP\n")
    run = subprocess.run([ccx, "-i", "job"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0 and "ERROR" not in run.stdout.upper(), run.stdout[-2000:]
    text = (tmp_path / "job.dat").read_text()
    m = re.search(rf"total force \(fx,fy,fz\) for set {reacting.upper()}.*\n\s*\n\s*(\S+)\s+(\S+)\s+(\S+)", text)
    assert m, text
    return [float(v) for v in m.groups()]


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_straight_tube_pulled(cm, tmp_path, kind, order):
    """Exact for first- and second-order cells alike (C3D6, C3D4, C3D15,
    C3D10), whose node sets hold every node of their faces."""
    write_boundary_pair(tmp_path, "pipe")
    shutil.copy(tmp_path / "a.xy", tmp_path / "b.xy")
    extra = (["--tets"] if kind == "tet" else []) + ["--order", order]
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


def rectangle(x0, y0, x1, y1, per_side):
    """A rectangle's outline, counter-clockwise, per_side points a side."""
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return [(a[0] + (b[0] - a[0]) * i / per_side, a[1] + (b[1] - a[1]) * i / per_side)
            for a, b in zip(corners, corners[1:] + corners[:1]) for i in range(per_side)]


def read_nodes_and_sets(path):
    """An Abaqus deck's nodes (row i: node i + 1) and node sets (name ->
    node indices from 0), read directly: meshio 5.0 cannot hold 15-node
    prisms."""
    points, sets, block = {}, {}, None
    for line in path.read_text().splitlines():
        if line.startswith("*"):
            head = line.upper().replace(" ", "")
            block = "node" if head == "*NODE" else line.split("=")[1].strip() if head.startswith("*NSET,") else None
            if block not in (None, "node"):
                sets[block] = []
        elif block == "node":
            number, *xyz = line.split(",")
            points[int(number)] = [float(v) for v in xyz]
        elif block:
            sets[block] += [int(v) - 1 for v in line.split(",") if v.strip()]
    assert sorted(points) == list(range(1, len(points) + 1))
    return np.array([points[i + 1] for i in range(len(points))]), sets


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_pressure_on_the_surfaces(cm, tmp_path, kind, order):
    """The deck's element-face surfaces carry pressures (*DSLOAD) where they
    belong: a rectangular tube, its walls split at the corners, pressed on
    the top with the bottom held, then on the wall at x = 2 with the wall
    at x = 0 held in x. Neither loaded surface touches the held nodes, so
    by equilibrium alone the reaction is the pressure times the face's
    area, along the face's inward normal; a face named wrongly would push
    elsewhere, or on an inner face of its cell."""
    outer, hole = rectangle(0, 0, 2, 1, 3), rectangle(0.7, 0.3, 1.3, 0.7, 2)
    text = "".join(f"{x:.17g} {y:.17g}\n" for x, y in outer) + ">\n" + \
        "".join(f"{x:.17g} {y:.17g}\n" for x, y in hole)
    (tmp_path / "a.xy").write_text(text)
    (tmp_path / "b.xy").write_text(text)
    extra = (["--tets"] if kind == "tet" else []) + ["--order", order]
    result = cm("sweep", "a.xy", "b.xy", "--sections", 3, "--height", HEIGHT, "--wall-corners", 45,
                "-o", "tube.inp", *extra, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    points, sets = read_nodes_and_sets(tmp_path / "tube.inp")
    walls = {name: points[nodes] for name, nodes in sets.items() if name.startswith("side_")}
    assert len(walls) == 4
    at = {round(float(p[:, 0].mean())): name for name, p in walls.items() if np.ptp(p[:, 0]) < 1e-9}
    assert sorted(at) == [0, 2]
    deck = (tmp_path / "tube.inp").read_text()
    for name in ["bottom", "top", *walls, *(f"hole_1_{j}" for j in range(1, 5))]:
        assert f"*SURFACE, NAME={name}, TYPE=ELEMENT\n" in deck, name
    area = 2 * 1 - 0.6 * 0.4
    fx, fy, fz = solve(tmp_path, "tube.inp", [("bottom", 1, 3)], [("top", 5.0)])
    assert fz == pytest.approx(5.0 * area, rel=1e-9) and abs(fx) < 1e-9 and abs(fy) < 1e-9
    fx, _, _ = solve(tmp_path, "tube.inp", [(at[0], 1, 1), ("bottom", 3, 3), ("side_1", 2, 2)], [(at[2], 3.0)],
                     at[0])
    assert fx == pytest.approx(3.0 * 1 * HEIGHT, rel=1e-9)
