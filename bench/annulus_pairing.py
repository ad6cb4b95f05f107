"""A pairing of two polygons with one hole each through the conformal map
onto a round annulus, measured with the index pipeline (a bench prototype:
the library's auto pairs the filled outer loops instead, and starts the
hole radially from there).

In each polygon, u is harmonic, 0 on the hole and 1 on the outer loop, and
psi its conjugate, normalised to period 1 (twist_bound.py's stream
function: P1 on a gmsh mesh, a unit jump across a cut). psi runs
monotonically along both loops and is the angle of the conformal map onto
the round annulus over 2 pi: a point of the hole and a point of the outer
loop with the same psi lie on one gradient line of u. So psi pairs both
loops of one polygon with those of another at once, and the map between
them through the annuli is conformal but for the radial stretch of their
moduli. One turn alpha (psi_b = psi_a + alpha) is left free.

For each alpha the loops are merged: every loop of each polygon keeps its
own vertices and gets the other polygon's at the same psi (the common
refinement, as the arc-length correspondences make it), and the pair is
run through `compatmesh triangulate` (index). Prints, for each alpha, the
smallest angle and Steiner count (or the reason a run failed).

usage: annulus_pairing.py COMPATMESH A.xy B.xy [TURNS] [WORK]
  TURNS: how many alphas, evenly spaced (default 24)
  WORK: folder for the merged loops and the runs (default a temporary one)

Measured (2026-12-01, the glyph loops `cm_glyph_holes --auto --no-remesh
--dump` writes; against the library's auto on the same loops, which ends
below 15 degrees on each): FreeSerif o/e 6.8 -> 20.2 degrees at alpha
0.25 (12 turns: 6.9 to 20.2 where the run goes through, 5 of 12 refused
for a vertex placed twice in the e's crowded mouth); at the turn whose
merged loops fit best by a similarity (least Procrustes residual, among
48): FreeSerif o/e 14.3, FreeSerifBold o/e 12.2 -> 18.9,
LiberationSans-Italic o/e 14.8 -> 20.7, FreeSerif a/e 14.4 -> 17.9, but
DejaVuSerifCondensed o/e 13.5 -> 12.6 and LiberationSerif o/e 12.5 ->
11.1 (14.6 at the next turn). The turn decides; the crowding needs the
tempering the library's disk map has.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

from twist_bound import mesh_domain, read_loops, signed_area, stiffness, stream_function, triangle_areas

def conjugate(outer, hole, size=0.004):
    """psi along the outer loop and along the hole (LoopPsi each), psi
    increasing counter-clockwise (twist_bound.stream_function's phi: psi
    but for the cut's jump, which psi mod 1 does not see)."""
    nodes, triangles, on_outer, on_hole = mesh_domain(outer, hole, size)
    local, matrix = stiffness(nodes, triangles, triangle_areas(nodes, triangles))
    psi, _ = stream_function(nodes, triangles, local, matrix, on_outer, on_hole)
    along_outer = loop_psi(outer, nodes, psi, on_outer)
    if along_outer.direction * signed_area(outer) < 0:
        psi = -psi
        along_outer = loop_psi(outer, nodes, psi, on_outer)
    return along_outer, loop_psi(hole, nodes, psi, on_hole)


class LoopPsi:
    """psi along one loop: at the mesh nodes on it, by arc length from the
    loop's vertex 0, unwrapped (direction +1 where it grows along the loop)."""

    def __init__(self, loop, s, psi):
        self.loop = loop
        self.edge = np.roll(loop, -1, axis=0) - loop
        self.cum = np.r_[0, np.cumsum(np.linalg.norm(self.edge, axis=1))]
        self.direction = 1 if psi[-1] > psi[0] else -1
        total = self.cum[-1]
        s_ext, p_ext = np.r_[s - total, s, s + total], np.r_[psi - self.direction, psi, psi + self.direction]
        order = np.argsort(p_ext)
        self.s_of_psi, self.psi_sorted = s_ext[order], p_ext[order]
        self.first = psi[0]

    def vertex_params(self):
        """psi at the loop's own vertices, mod 1."""
        return np.interp(self.cum[:-1], *self._psi_of_s()) % 1.0

    def _psi_of_s(self):
        order = np.argsort(self.s_of_psi)
        return self.s_of_psi[order], self.psi_sorted[order]

    def point(self, t):
        """The point of the loop where psi = t (mod 1)."""
        t = self.first + ((t - self.first) % 1.0)
        s = np.interp(t, self.psi_sorted, self.s_of_psi) % self.cum[-1]
        i = min(int(np.searchsorted(self.cum, s, side="right")) - 1, len(self.loop) - 1)
        a = (s - self.cum[i]) / (self.cum[i + 1] - self.cum[i])
        return self.loop[i] + a * self.edge[i]


def loop_psi(loop, nodes, psi, on):
    edge = np.roll(loop, -1, axis=0) - loop
    length = np.linalg.norm(edge, axis=1)
    cum = np.r_[0, np.cumsum(length)]
    s = np.empty(len(on))
    for k, p in enumerate(nodes[on]):
        t = np.clip(((p - loop) * edge).sum(axis=1) / length ** 2, 0, 1)
        i = int(np.argmin(np.linalg.norm(loop + t[:, None] * edge - p, axis=1)))
        s[k] = cum[i] + t[i] * length[i]
    order = np.argsort(s)
    return LoopPsi(loop, s[order], np.unwrap(psi[on][order] * 2 * np.pi) / (2 * np.pi))


def merged(a, b, alpha):
    """Loop a's and loop b's vertices together, ordered by a's psi, each
    placed on both loops (b's psi = a's + alpha). Harmonic measure crowds
    exponentially into a dead end (the mouth of an e: vertices 1e-17 apart
    in psi), where two placed points may coincide: the run then names the
    repeated vertex. The library's disk map tempers that crowding; this
    prototype does not."""
    items = [(t, 0, i) for i, t in enumerate(a.vertex_params())]
    items += [((t - alpha) % 1.0, 1, i) for i, t in enumerate(b.vertex_params())]
    items.sort(key=lambda item: item[0] * a.direction)
    first = next(k for k, item in enumerate(items) if item[1] == 0 and item[2] == 0)
    items = items[first:] + items[:first]
    on_a = [a.loop[i] if who == 0 else a.point(t) for t, who, i in items]
    on_b = [b.loop[i] if who == 1 else b.point((t + alpha) % 1.0) for t, who, i in items]
    if b.direction != a.direction:
        raise ValueError("psi runs the other way on the second polygon")
    return np.array(on_a), np.array(on_b)


def write_loops(path, loops):
    with open(path, "w") as f:
        for l, loop in enumerate(loops):
            f.write("> %s\n" % ("outer loop" if l == 0 else "hole"))
            f.writelines("%.17g %.17g\n" % (x, y) for x, y in loop)


def run(compatmesh, a, b, out):
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([compatmesh, "triangulate", a, b, "-o", out, "--quiet", "--no-preview"],
                          capture_output=True, text=True)
    if done.returncode:
        return done.stderr.strip()
    report = json.load(open(os.path.join(out, "report.json")))
    return min(m["min_angle_deg"] for m in report["meshes"]), report["steiner"]


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    compatmesh, a_path, b_path = argv[1:4]
    turns = int(argv[4]) if len(argv) > 4 else 24
    work = argv[5] if len(argv) > 5 else tempfile.mkdtemp()
    polygons = [read_loops(path) for path in (a_path, b_path)]
    if any(len(loops) != 2 for loops in polygons):
        sys.exit("annulus_pairing: each polygon needs one outer loop and one hole")
    params = []
    for outer, hole in polygons:
        params.append(conjugate(outer, hole))
    for j in range(turns):
        alpha = j / turns
        loops = [merged(params[0][l], params[1][l], alpha) for l in range(2)]
        a, b = os.path.join(work, "a.xy"), os.path.join(work, "b.xy")
        write_loops(a, [loop[0] for loop in loops])
        write_loops(b, [loop[1] for loop in loops])
        result = run(compatmesh, a, b, os.path.join(work, "out"))
        print("alpha %.4f: %s" % (alpha, result if isinstance(result, str) else
                                  "%.2f degrees, %d Steiner vertices" % result), flush=True)


if __name__ == "__main__":
    main(sys.argv)
