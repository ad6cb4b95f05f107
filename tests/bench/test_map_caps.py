"""bench/map_caps.py: the cap a compatible mesh's own affine maps allow,
checked on stretches worked out by hand and against random triangles."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
import correspondence_bound as cb  # noqa: E402
from map_caps import map_caps  # noqa: E402


def smallest_angles(points, tri):
    """Each triangle's smallest angle (degrees)."""
    p = points[tri]
    out = []
    for i in range(3):
        u, w = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        cross = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]
        out.append(np.degrees(np.arctan2(np.abs(cross), (u * w).sum(axis=1))))
    return np.min(out, axis=0)


@pytest.mark.parametrize("s", [1.0, 1.5, 2.0, 3.0, 5.0])
def test_map_caps_of_a_stretch(s):
    """Every triangle of a mesh and its image under diag(s, 1 / s) has the
    cap of dilatation s^2, however it is shaped or turned."""
    rng = np.random.default_rng(7)
    a = rng.uniform(-1, 1, (30, 3, 2))
    a = a[np.abs(np.cross(a[:, 1] - a[:, 0], a[:, 2] - a[:, 0])) > 0.05].reshape(-1, 2)
    tri = np.arange(len(a)).reshape(-1, 3)
    caps = map_caps(a, a * [s, 1 / s], tri)
    assert np.allclose(caps, cb.angle_bound(s * s), atol=1e-9)


def test_map_caps_bound_both_images():
    """No triangle's smallest angle in both meshes exceeds its map's cap,
    and the best triangle for a stretch reaches it (to the bisection's
    tolerance)."""
    rng = np.random.default_rng(11)
    a, b = rng.uniform(-1, 1, (2, 300, 2))
    tri = np.arange(300).reshape(-1, 3)
    caps = map_caps(a, b, tri)
    both = np.minimum(smallest_angles(a, tri), smallest_angles(b, tri))
    assert np.all(both <= caps + 1e-9) and np.all((caps > 0) & (caps <= 60))
    # the shapes (alpha, alpha, pi - 2 alpha) and (alpha, pi - 2 alpha, alpha),
    # vertex to vertex, are K(alpha) apart: their map's cap is alpha itself
    for degrees in (5, 20, 40):
        alpha = math.radians(degrees)
        first = np.array([[0, 0], [1, 0], [0.5, 0.5 * math.tan(alpha)]])
        second = np.array([[0, 0], [1, 0], [1 + math.cos(2 * alpha), math.sin(2 * alpha)]])
        assert map_caps(first, second, [[0, 1, 2]])[0] == pytest.approx(degrees, abs=1e-9)


SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "bench", "map_caps.py")


def test_command_on_a_compatmesh_output(tmp_path):
    """On a real output: the least cap is at least the smallest angle, the
    picture is written, a missing directory is a one-line error."""
    import json
    import subprocess

    square = tmp_path / "a.xy"
    square.write_text("0 0\n1 0\n1 1\n0 1\n0.5 0.9\n")
    other = tmp_path / "b.xy"
    other.write_text("0 0\n4 0\n4 1\n0 1\n2 0.5\n")
    out = tmp_path / "out"
    subprocess.run([os.environ["COMPATMESH"], "triangulate", str(square), str(other), "-o", str(out)],
                   check=True, capture_output=True)
    png = tmp_path / "caps.png"
    run = subprocess.run([sys.executable, SCRIPT, str(out), "--png", str(png)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    words = run.stdout.split()
    least, angle = float(words[2]), float(words[8])
    report = json.loads((out / "report.json").read_text())
    assert angle == pytest.approx(min(m["min_angle_deg"] for m in report["meshes"]), abs=1e-3)
    assert angle <= least * (1 + 1e-6) and png.stat().st_size > 1000
    bad = subprocess.run([sys.executable, SCRIPT, str(tmp_path / "none")], capture_output=True, text=True)
    assert bad.returncode != 0 and len(bad.stderr.strip().splitlines()) == 1 and "none" in bad.stderr
