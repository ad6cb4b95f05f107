"""bench/holes_table.py (without the MeshLab run): one row per pair with
holes, every pair valid, the summary counting the rows, and c as worked by
hand on fixtures whose smallest corner is known."""
import math
import os
import subprocess
import sys

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "bench", "holes_table.py")


def test_table():
    run = subprocess.run([sys.executable, SCRIPT, os.environ["CM_BUILD"], "--no-meshlab"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    rows = [line.split(" | ") for line in run.stdout.splitlines() if line.startswith("| ") and "---" not in line]
    header, rows = rows[0], rows[1:]
    assert header[1] == "pair" and header[5] == "c"
    # 12 glyph pairs twice, 11 of tests/core, the command line's and Python's plates
    assert len(rows) == 12 * 2 + 11 + 2
    assert all(r[-2] == "yes" for r in rows), [r[1] for r in rows if r[-2] != "yes"]
    good = sum(r[-1] == "yes |" for r in rows)
    assert "%d pairs with holes: %d valid, %d " % (len(rows), len(rows), good) in run.stdout
    c = {r[1]: float(r[5]) for r in rows if r[0].startswith("| tests")}
    assert c["square/disc"] == 90.0  # the square's corners; the disc's and the holes' are wider
    # the sheared plate's corner: between (1, 0) and (0.4, 1)
    assert c["plate"] == round(math.degrees(math.atan2(1, 0.4)), 1) == 68.2
    assert c["turned hole"] == 165.0  # the 24-gon's corner; the 12-gon hole's is 360 - 150
    assert c["five triangle holes"] == 90.0  # a triangle hole's corner in the material is 300
    for r in rows:
        assert float(r[6]) == round(min(15, float(r[5]) / 3), 2)
