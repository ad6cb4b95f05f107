"""bench/affine_bench.py: the best lattice triangle for a stretch, found by
a numeric search, against the closed-form cap of correspondence_bound.py
(two independent ways to the same number), and the remesher on a disc
against its affine image: never above the exact cap, and at the share of
it the bench recorded (bench/REMESH.md, "Affine pairs")."""
import os
import sys

import pytest

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
sys.path.insert(0, BENCH)
import affine_bench as ab  # noqa: E402
from correspondence_bound import angle_bound  # noqa: E402


@pytest.mark.parametrize("s", [1.5, 3.0, 5.0, 7.0])
def test_lattice_reaches_the_cap_and_no_more(s):
    # K(alpha) is the largest dilatation between two alpha-triangles, so the
    # best triangle for a map of dilatation s^2 has the cap's angle exactly
    assert ab.lattice_angle(s) == pytest.approx(angle_bound(s * s), abs=1e-6)


@pytest.mark.parametrize("s, share", [(3.0, 0.75), (5.0, 0.65)])
def test_remesher_stays_under_the_exact_cap(tmp_path, s, share):
    angle, steiner, _ = ab.run(os.environ["COMPATMESH"], s, 48, str(tmp_path))
    cap = min(25.0, angle_bound(s * s))
    assert angle <= angle_bound(s * s) + 1e-9  # above it the cap or the result check would be wrong
    assert angle >= share * cap, (angle, cap)
    assert 0 < steiner < 200
