"""A certified ceiling for an annulus whose hole is turned: no compatible
triangulation of the pair can have a smallest angle above it.

The pair: two polygons with one hole each, the same outer loop (vertex i on
vertex i), the second's hole the first's turned by theta about a centre c
under which the whole domain D (outer loop minus hole) is symmetric. A
compatible triangulation is a piecewise-affine homeomorphism f of D, the
identity on the outer loop and the turn on the hole.

- A conformal map phi of D onto a round annulus rho < |w| < 1 conjugates
  the turn to a rotation by theta (it keeps the rotation number), so
  g = phi f phi^-1 has f's dilatation at every point, is the identity on
  the outer circle and turns the inner one by theta + 2 pi k for some
  integer k.
- In log coordinates (s, angle), s in (0, S), S = ln(1 / rho), each radial
  segment goes to a curve at least sqrt(S^2 + t^2) long, t = |theta + 2 pi
  k| >= the distance from theta to the nearest multiple of 2 pi. Integrated
  over the angle, with Cauchy-Schwarz and |dg/ds|^2 <= K J (J the
  Jacobian, whose integral is the area 2 pi S): K >= 1 + t^2 / S^2 for the
  largest dilatation K of f (the length-area argument).
- D lies in the round annulus between the largest circle about c inside
  the hole and the smallest about c holding the outer loop, so S is at
  most the log of their radii's ratio (a sub-annulus has the smaller
  modulus).
- Some triangle's affine map has dilatation at least K, and two triangles
  whose angles are all at least alpha are related by dilatation at most
  K(alpha) (correspondence_bound.dilatation_bound): the smallest angle is
  at most angle_bound(K).

usage: twist_bound.py A.xy B.xy  (loops separated by lines beginning with
'>', the outer loop first)
"""
import math
import sys

import numpy as np

from correspondence_bound import angle_bound

TOLERANCE = 1e-9


def read_loops(path):
    """The loops of an .xy file, as arrays."""
    loops, current = [], []
    with open(path) as text:
        for line in text:
            if line.startswith(">"):
                if current:
                    loops.append(np.array(current))
                current = []
            elif line.strip():
                current.append([float(v) for v in line.split()[:2]])
    if current:
        loops.append(np.array(current))
    return loops


def turn(points, centre, theta):
    c, s = math.cos(theta), math.sin(theta)
    d = points - centre
    return centre + np.c_[c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]]


def same_set(p, q, scale):
    """Every point of p on a point of q and back (to TOLERANCE * scale)."""
    d = np.linalg.norm(p[:, None, :] - q[None, :, :], axis=2)
    return d.min(axis=1).max() <= TOLERANCE * scale and d.min(axis=0).max() <= TOLERANCE * scale


def inside(point, loop):
    """Is point inside the loop (crossings of a ray to +x)?"""
    x, y = point
    crossings = 0
    for (x0, y0), (x1, y1) in zip(loop, np.roll(loop, -1, axis=0)):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            crossings += 1
    return crossings % 2 == 1


def segment_distance(centre, a, b):
    """The distance from centre to the segment a b."""
    ab, ac = b - a, centre - a
    t = min(1.0, max(0.0, float(ab @ ac) / float(ab @ ab)))
    return float(np.linalg.norm(ac - t * ab))


def twist_bound(outer_a, hole_a, outer_b, hole_b):
    """(theta, S bound, K bound, angle ceiling in degrees) for the pair, or
    ValueError where it is not an outer loop kept and a hole turned about
    a centre of symmetry of the domain."""
    scale = float(np.ptp(outer_a, axis=0).max())
    if outer_a.shape != outer_b.shape or np.abs(outer_a - outer_b).max() > TOLERANCE * scale:
        raise ValueError("the outer loops differ: the bound needs the same outer loop, vertex on vertex")
    if hole_a.shape != hole_b.shape:
        raise ValueError("the holes have different vertex counts")
    centre = hole_a.mean(axis=0)
    # the turn taking hole vertex 0 to its place in the second polygon
    da, db = hole_a[0] - centre, hole_b[0] - centre
    theta = math.atan2(da[0] * db[1] - da[1] * db[0], float(da @ db))
    if np.abs(turn(hole_a, centre, theta) - hole_b).max() > TOLERANCE * scale:
        raise ValueError("the second hole is not the first turned about its centroid")
    if not (same_set(turn(outer_a, centre, theta), outer_a, scale) and same_set(hole_b, hole_a, scale)):
        raise ValueError("the domain is not symmetric under the turn")
    if not inside(centre, hole_a):
        raise ValueError("the turn's centre is not inside the hole")
    outer_radius = float(np.linalg.norm(outer_a - centre, axis=1).max())
    inner_radius = min(segment_distance(centre, hole_a[i], hole_a[(i + 1) % len(hole_a)])
                       for i in range(len(hole_a)))
    s_bound = math.log(outer_radius / inner_radius)
    least_turn = abs(math.remainder(theta, 2 * math.pi))
    k_bound = 1 + (least_turn / s_bound) ** 2
    return theta, s_bound, k_bound, angle_bound(k_bound)


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    loops = [read_loops(path) for path in argv[1:]]
    try:
        if any(len(each) != 2 for each in loops):
            raise ValueError("each polygon must have one outer loop and one hole")
        theta, s_bound, k_bound, ceiling = twist_bound(*loops[0], *loops[1])
    except ValueError as error:
        sys.exit(f"twist_bound: {error}")
    print(f"turn {math.degrees(theta):.6g} degrees, ln(R/r) <= {s_bound:.6g}, dilatation >= {k_bound:.6g}: "
          f"no compatible triangulation has a smallest angle above {ceiling:.4f} degrees")


if __name__ == "__main__":
    main(sys.argv)
