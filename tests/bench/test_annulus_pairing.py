"""bench/annulus_pairing.py: psi, the conjugate of the annulus' harmonic
function, pairs both loops of one polygon with another's at once. An
annulus and its image under a similarity (scaled, turned, moved; the
vertices listed from elsewhere) pair point to point at the turn that undoes
the similarity's: the merged loops put every point of one on the image of
the other's, up to the mesh's psi."""
import math
import os
import sys

import numpy as np

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
sys.path.insert(0, BENCH)
from annulus_pairing import conjugate, merged  # noqa: E402


def ring(outer, hole, r=0.55, shift=0):
    a = 2 * math.pi * (np.arange(outer) + shift) / outer
    b = -2 * math.pi * np.arange(hole) / hole
    rr = 1 + 0.15 * np.cos(3 * a)  # not round: psi is not the polar angle
    return np.c_[rr * np.cos(a), rr * np.sin(a)], np.c_[r * np.cos(b) + 0.1, r * np.sin(b)]


def params(outer, hole):
    return conjugate(outer, hole, size=0.01)


def test_psi_runs_counter_clockwise_on_both_loops():
    outer, hole = ring(40, 16)
    p_outer, p_hole = params(outer, hole)
    assert p_outer.direction == 1 and p_hole.direction == -1  # the hole is listed clockwise
    for p in (p_outer, p_hole):
        v = p.vertex_params()
        steps = np.diff(np.r_[v, v[0] + p.direction]) * p.direction % 1.0
        assert np.all(steps > 0) and abs(steps.sum() - 1) < 1e-9  # one turn, in order


def test_similar_annuli_pair_vertex_to_vertex():
    outer, hole = ring(40, 16)
    turn, scale, move = 0.7, 1.8, np.array([3.0, -2.0])
    rot = np.array([[math.cos(turn), math.sin(turn)], [-math.sin(turn), math.cos(turn)]])
    image = [scale * np.roll(loop, -5, axis=0) @ rot + move for loop in (outer, hole)]  # b vertex 0 = a vertex 5
    pa, pb = params(outer, hole), params(*image)
    # the turn between their psi: where b's outer vertex 0 (a's vertex 5) sits
    alpha = (pb[0].vertex_params()[0] - pa[0].vertex_params()[5]) % 1.0
    for l in range(2):
        on_a, on_b = merged(pa[l], pb[l], alpha)
        mapped = scale * on_a @ rot + move
        assert np.abs(mapped - on_b).max() < 2e-3 * scale  # the same points, up to the mesh's psi
