"""bench/remesh_scale.py on the real sections at two small sizes, index
mode, without CGAL: every run valid (the script stops otherwise), a row
per pair written, a growth exponent per section, and peak memories that
are compatmesh's own (far below this Python process's); and the
simplicity test its resampling relies on (bench/stl_sections.py)."""
import os
import re
import subprocess
import sys

import numpy as np

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
sys.path.insert(0, BENCH)
import stl_sections  # noqa: E402

SCRIPT = os.path.join(BENCH, "remesh_scale.py")
CLI = os.environ["COMPATMESH"]


def test_simple_polygons_are_told_exactly():
    """A straight stretch resampled into 60 points whose coordinates round
    off the line (doubles judged the 59 collinear edges as crossing) is
    simple; a vertex touching an edge, a bow tie, and a stretch that runs
    back over itself are not."""
    k = np.arange(60)
    stretch = np.vstack([np.column_stack([k * 0.1, 0.3 + k * 0.1 / 3]), [[0.0, 5.0]]])
    assert stl_sections.is_simple(stretch)
    assert stl_sections.is_simple([[0, 0], [1, 0], [1, 1], [0, 1]])
    assert not stl_sections.is_simple([[0, 0], [2, 0], [2, 2], [1, 0], [0, 2]])
    assert not stl_sections.is_simple([[0, 0], [1, 1], [1, 0], [0, 1]])
    assert not stl_sections.is_simple([[0, 0], [3, 0], [3, 1], [2, 0], [1, 0], [0, 1]])


def test_two_sizes_give_rows_and_exponents():
    run = subprocess.run([sys.executable, SCRIPT, "--compatmesh", CLI, "--ns", "64,128", "--modes", "index"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    left_out = len(re.findall(r"left out", run.stderr))
    rows = [line.split("|") for line in run.stdout.splitlines() if re.match(r"\| hold_section_\S+ \| \d+ \| index", line)]
    assert len(rows) == 3 * 2 - left_out and len(rows) >= 4
    for row in rows:
        cpu, mb, triangles, steiner = float(row[4]), float(row[5]), int(row[6]), int(row[7])
        assert cpu > 0 and 0 < mb < 40 and triangles == 2 * steiner + int(row[2]) - 2
    exponents = [line for line in run.stdout.splitlines() if re.match(r"\| hold_section_\S+ \| index \| -?\d", line)]
    assert len(exponents) >= 1
