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
    assert header[1] == "pair" and header[5] == "c" and header[9] == "bound"
    # 12 glyph pairs twice, 17 of tests/core, the command line's and Python's plates
    assert len(rows) == 12 * 2 + 17 + 2
    assert all(r[-2] == "yes" for r in rows), [r[1] for r in rows if r[-2] != "yes"]
    good = sum(r[-1] == "yes |" for r in rows)
    assert "%d pairs with holes: %d valid, %d " % (len(rows), len(rows), good) in run.stdout
    c = {r[1]: float(r[5]) for r in rows if r[0].startswith("| tests")}
    assert c["square/disc"] == 90.0  # the square's corners; the disc's and the holes' are wider
    # the sheared plate's corner: between (1, 0) and (0.4, 1)
    assert c["plate"] == round(math.degrees(math.atan2(1, 0.4)), 1) == 68.2
    assert c["turned hole"] == 165.0  # the 24-gon's corner; the 12-gon hole's is 360 - 150
    assert c["five triangle holes"] == 90.0  # a triangle hole's corner in the material is 300
    assert c["ring and stem"] == 90.0  # the square's and the stem's corners; the hole's are 270
    for r in rows:
        assert float(r[6]) == round(min(15, float(r[5]) / 3), 2)
        assert r[9] == ""  # the bounds only with --bounds


def test_auto_pair_reads_the_correspondence_back(tmp_path):
    # a square with a square hole against a disc with a round hole, loops
    # of other sizes: the auto run's loops come back as one size per loop,
    # the same in both files, each point on its own polygon's loop
    sys.path.insert(0, os.path.dirname(SCRIPT))
    import holes_table as ht
    from make_results import read_loops
    square = [[(0, 0), (1, 0), (2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (0, 1)],
              [(0.5, 0.5), (0.5, 1.5), (1.5, 1.5), (1.5, 0.5)]]
    disc = [[(1 + math.cos(t), 1 + math.sin(t)) for t in (2 * math.pi * i / 13 for i in range(13))],
            [(1 + 0.4 * math.cos(-t), 1 + 0.4 * math.sin(-t)) for t in (2 * math.pi * i / 7 for i in range(7))]]
    files = [ht.write_loops(str(tmp_path / name), loops) for name, loops in (("s.xy", square), ("d.xy", disc))]
    paired = [read_loops(f) for f in ht.auto_pair(os.path.join(os.environ["CM_BUILD"], "bin", "compatmesh"),
                                                   files, str(tmp_path))]
    sizes = [[len(loop) for loop in p] for p in paired]
    assert sizes[0] == sizes[1] and len(sizes[0]) == 2 and sizes[0][0] >= 13 and sizes[0][1] >= 7
    # every point on its loop: the square's on the lines x or y in {0, 2}
    # (outer) and {0.5, 1.5} (hole), the disc's on the chords of its circles
    for loop, values in zip(paired[0], ((0, 2), (0.5, 1.5))):
        assert all(min(abs(c - v) for c in p for v in values) < 1e-12 for p in loop)
    for loop, r, m in zip(paired[1], (1, 0.4), (13, 7)):
        assert all(r * math.cos(math.pi / m) - 1e-12 < math.hypot(x - 1, y - 1) < r + 1e-12 for x, y in loop)
