"""The largest smallest angle that any compatible triangulation of a polygon
pair can have, whatever its Steiner vertices: an upper bound from the
distortion the vertex correspondence forces.

usage: correspondence_bound.py COMPATMESH A.xy B.xy [C.xy ...]
prints: bound_deg K quadruple (one line; bound_deg is 60 when nothing binds)

Why it holds. A compatible triangulation of polygons A and B defines a
piecewise-linear homeomorphism f: A -> B that takes vertex i to vertex i.
On each triangle f is affine; if every triangle has all angles >= alpha
in both geometries, each affine piece has dilatation at most D(alpha)^2,
where D(alpha) is the largest dilatation of an affine map from the
equilateral triangle onto a triangle with angles >= alpha. For the map
from the equilateral triangle onto a triangle T, K + 1/K = (2/sqrt(3))
(cot A + cot B + cot C), largest over the allowed angles at (alpha,
alpha, pi - 2 alpha). So f is D(alpha)^2-quasiconformal, and no
quasiconformal map distorts the conformal modulus of a quadrilateral by
more than its dilatation: for the quadrilateral Q(a, b, c, d) (the
polygon with four marked vertices a < b < c < d), M(f(Q)) <= K M(Q) and
M(Q) <= K M(f(Q)). Any marked quadruple whose moduli in A and B differ by
a factor r > D(alpha)^2 thus rules out alpha.

The moduli are computed by linear finite elements (on compatmesh's mesh
of each polygon alone, refined; scipy solves): M(Q) is the Dirichlet
energy of the function equal to 0 on the boundary arc a..b, 1 on c..d,
free elsewhere. The finite
element energy is at least the true one, and the energy of the conjugate
problem (0 on b..c, 1 on d..a) is 1/M(Q), so 1/(its finite element
energy) is at most M(Q): the ratio reported uses a lower bound over an
upper bound, so the bound stays on the safe side of the discretisation.
The quadruple is found by a coarse search over evenly spaced vertices
and a local search around the best; another quadruple may distort more,
in which case the true bound is lower still.
"""
import itertools
import math
import os
import shutil
import subprocess
import sys
import tempfile

import meshio
import numpy as np
import scipy.sparse
import scipy.sparse.linalg

from make_results import read_xy

# compatmesh's mesh of each polygon is split into four until it has at
# least this many triangles.
MIN_TRIANGLES = 4000
# The coarse search tries every quadruple of this many evenly spaced vertices.
COARSE_MARKS = 10


class Polygon:
    """A fine triangle mesh of a polygon, its P1 stiffness matrix and, per
    polygon vertex i, the mesh nodes on the boundary edge from i to i + 1.

    The mesh is compatmesh's own triangulation of the polygon paired with
    itself (checked exactly, boundary = the input polygon, vertices 0..n-1
    first), split into four until fine enough. Any valid triangulation
    keeps the bound safe; a finer one only makes it tighter."""

    def __init__(self, cli, path, workdir):
        out = os.path.join(workdir, "mesh")
        copies = [os.path.join(workdir, name) for name in ("a.xy", "b.xy")]
        for copy in copies:
            shutil.copyfile(path, copy)
        run = subprocess.run([cli, "triangulate", *copies, "--out-dir", out],
                             capture_output=True, text=True)
        if run.returncode != 0:
            raise RuntimeError("%s: %s" % (path, run.stderr.strip()))
        mesh = meshio.read(os.path.join(out, "a.off"))
        shutil.rmtree(out)
        xy, tri = mesh.points[:, :2].astype(float), mesh.cells_dict["triangle"].astype(np.int64)
        self.n = len(read_xy(path))
        # per polygon edge, its nodes in order from vertex i to i + 1
        edges = [[i, (i + 1) % self.n] for i in range(self.n)]
        while len(tri) < MIN_TRIANGLES:
            xy, tri, edges = subdivide(xy, tri, edges)
        self.edge_nodes = [np.array(e) for e in edges]
        self.xy, self.tri = xy, tri
        self.stiffness = assemble(xy, tri)
        self.nodes = len(xy)

    def arc(self, i, j):
        """Mesh nodes on the boundary from polygon vertex i to vertex j."""
        parts, k = [], i
        while k != j:
            parts.append(self.edge_nodes[k])
            k = (k + 1) % self.n
        return np.unique(np.concatenate(parts))

    def energy(self, zero, one):
        """Finite element Dirichlet energy: 0 on nodes `zero`, 1 on `one`."""
        fixed = np.zeros(self.nodes, dtype=bool)
        fixed[zero] = fixed[one] = True
        u = np.zeros(self.nodes)
        u[one] = 1.0
        free = ~fixed
        K = self.stiffness
        rhs = -K[free][:, fixed] @ u[fixed]
        u[free] = scipy.sparse.linalg.spsolve(K[free][:, free].tocsc(), rhs)
        return float(u @ (K @ u))

    def modulus(self, q):
        a, b, c, d = q
        return self.energy(self.arc(a, b), self.arc(c, d))

    def modulus_range(self, q):
        """Certified [lower, upper] bounds of the modulus of Q(q)."""
        a, b, c, d = q
        upper = self.modulus(q)
        lower = 1.0 / self.energy(self.arc(b, c), self.arc(d, a))
        return lower, upper


def subdivide(xy, tri, edges):
    """Every triangle split into four at its edge midpoints; `edges` (node
    lists along the polygon's edges) gain the new boundary nodes."""
    pairs = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    unique, inverse = np.unique(pairs, axis=0, return_inverse=True)
    mid = len(xy) + inverse.reshape(3, -1).T  # midpoints of (01, 12, 20)
    new_xy = np.vstack([xy, 0.5 * (xy[unique[:, 0]] + xy[unique[:, 1]])])
    a, b, c = tri.T
    m01, m12, m20 = mid.T
    new_tri = np.vstack([np.column_stack(t) for t in
                         ((a, m01, m20), (m01, b, m12), (m20, m12, c), (m01, m12, m20))])
    index = {tuple(e): len(xy) + i for i, e in enumerate(unique)}
    new_edges = []
    for e in edges:
        chain = [e[0]]
        for u, v in zip(e, e[1:]):
            chain += [index[(min(u, v), max(u, v))], v]
        new_edges.append(chain)
    return new_xy, new_tri, new_edges


def assemble(xy, tri):
    p = xy[tri]
    d = np.stack([p[:, 2] - p[:, 1], p[:, 0] - p[:, 2], p[:, 1] - p[:, 0]], axis=1)
    area = 0.5 * np.abs(d[:, 0, 0] * d[:, 1, 1] - d[:, 0, 1] * d[:, 1, 0])
    local = np.einsum("tik,tjk->tij", d, d) / (4 * area)[:, None, None]
    rows = np.repeat(tri, 3, axis=1).ravel()
    cols = np.tile(tri, (1, 3)).ravel()
    return scipy.sparse.csr_matrix((local.ravel(), (rows, cols)), shape=(len(xy), len(xy)))


def dilatation_bound(alpha):
    """D(alpha)^2: the largest dilatation of an affine map between two
    triangles whose angles are all at least alpha (radians)."""
    s = (2 / math.sqrt(3)) * (2 / math.tan(alpha) - 1 / math.tan(2 * alpha))
    d = 0.5 * (s + math.sqrt(max(s * s - 4, 0.0)))
    return d * d


def angle_bound(K):
    """The largest alpha (degrees) with dilatation_bound(alpha) >= K."""
    if K <= 1.0:
        return 60.0
    lo, hi = 1e-6, math.pi / 3
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if dilatation_bound(mid) >= K:
            lo = mid
        else:
            hi = mid
    return math.degrees(lo)


def distortion(polys, q):
    """Estimated modulus ratio of quadruple q over every pair of polygons."""
    m = [p.modulus(q) for p in polys]
    return max(m) / min(m)


def best_quadruple(polys):
    """The marked vertices (a < b < c < d) whose modulus differs most
    between the polygons: the best of a coarse grid, then moved one mark at
    a time by halving steps while the ratio grows."""
    n = polys[0].n
    marks = sorted({round(i * n / COARSE_MARKS) % n for i in range(COARSE_MARKS)})
    best, best_q = 0.0, None
    for q in itertools.combinations(marks, 4):
        r = distortion(polys, q)
        if r > best:
            best, best_q = r, q
    step = max(1, n // (2 * COARSE_MARKS))
    while step >= 1:
        improved = True
        while improved:
            improved = False
            for i in range(4):
                for s in (-step, step):
                    q = list(best_q)
                    q[i] = (q[i] + s) % n
                    if len(set(q)) < 4:
                        continue
                    # keep the marks in boundary order, starting anywhere
                    start = q.index(min(q))
                    if q[start:] + q[:start] != sorted(q):
                        continue
                    q = tuple(sorted(q))
                    r = distortion(polys, q)
                    if r > best * (1 + 1e-9):
                        best, best_q, improved = r, q, True
        step //= 2
    return best_q


def certified_ratio(polys, q):
    ranges = [p.modulus_range(q) for p in polys]
    return max(lo_i / hi_j for lo_i, _ in ranges for _, hi_j in ranges)


def main(argv):
    if len(argv) < 4:
        print(__doc__.splitlines()[3], file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as workdir:
        polys = [Polygon(argv[1], path, workdir) for path in argv[2:]]
    q = best_quadruple(polys)
    K = certified_ratio(polys, q)
    print("%.3f %.4g %s" % (angle_bound(K), K, ",".join(map(str, q))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
