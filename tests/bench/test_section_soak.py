"""bench/section_soak.py: its regions and corners worked out by hand, and
the script run on Gmsh's lever at three heights per axis."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
sys.path.insert(0, BENCH)
import section_soak as ss  # noqa: E402

CLI = os.environ["COMPATMESH"]


def square(x, y, s):
    return np.array([(x, y), (x + s, y), (x + s, y + s), (x, y + s)], dtype=float)


def test_region_keeps_the_holes_inside_the_largest_loop():
    outer, hole, apart = square(0, 0, 10), square(2, 2, 3)[::-1], square(20, 0, 4)
    loops = ss.region([hole, apart, outer[::-1]])
    assert len(loops) == 2
    assert np.array_equal(loops[0], outer)             # counter-clockwise
    assert np.array_equal(loops[1], hole)              # clockwise
    assert ss.region([outer, square(2, 2, 6), square(3, 3, 1)]) is None  # an island in a hole


def test_smallest_corner_sees_the_material_side():
    # A square's corners are 90 degrees; a square hole's are 270 from the material.
    assert ss.smallest_corner([square(0, 0, 10)]) == pytest.approx(90)
    octagon = np.array([(np.cos(t), np.sin(t)) for t in np.arange(8) * np.pi / 4]) * 10
    assert ss.smallest_corner([octagon, square(-1, -1, 2)[::-1]]) == pytest.approx(135)


@pytest.mark.parametrize("space", [[], ["--in-space"]])
def test_lever_sections(tmp_path, space):
    """The lever's sections through the command line, in the cut plane's two
    coordinates and (--in-space) as points in space in their cut planes, as
    MeshLab saves them: every run valid."""
    out = tmp_path / "soak.json"
    r = subprocess.run([sys.executable, os.path.join(BENCH, "section_soak.py"), CLI, "--heights", "3",
                        "--only", "^lever$", "--json", str(out)] + space, capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 0, r.stderr
    runs = json.loads(out.read_text())["runs"]
    assert len(runs) >= 4 and {x["kind"] for x in runs} <= {"outer", "holes"}
    assert all(x["status"] == 0 and x["valid"] for x in runs)
    assert "| outer loops |" in r.stdout

