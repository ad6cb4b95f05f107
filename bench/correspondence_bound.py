"""The largest smallest angle that any compatible triangulation of a polygon
pair can have, whatever its Steiner vertices: an upper bound from the
distortion the vertex correspondence forces. Polygons may have holes
('>' lines between the loops, outer loop first; loop j of each polygon
corresponds to loop j).

usage: correspondence_bound.py COMPATMESH A.xy B.xy [C.xy ...]
prints: bound_deg K family (one line; bound_deg is 60 when nothing binds;
family: the quadruple a,b,c,d without holes, else the two sides E/F of the
curve family, each "o" or "hN" (the outer loop or hole N, whole) or
"o:i-j" / "hN:i-j" (its arc from vertex i to vertex j))

Why it holds. A compatible triangulation of polygons A and B defines a
piecewise-linear homeomorphism f: A -> B that takes vertex i to vertex i.
On each triangle f is affine; if every triangle has all angles >= alpha
in both geometries, each affine piece has dilatation at most K(alpha),
the largest dilatation of an affine map between two triangles whose
angles are all >= alpha: the dilatation between triangle shapes is exp of
their hyperbolic distance (a triangle 0, 1, z as the point z of the upper
half-plane), and the region of shapes with angles >= alpha has its
diameter between two of its corners, the triangles (alpha, alpha, pi - 2
alpha) and (alpha, pi - 2 alpha, alpha) (core/src/correspond/bound.c has
the proof). So f is K(alpha)-quasiconformal, and no
quasiconformal map distorts a conformal invariant of a curve family by
more than its dilatation. Here the family is that of the curves in the
polygon joining two boundary sets E and F, each a loop's arc between two
marked vertices or a whole loop; its capacity C(E, F) (the reciprocal of
its extremal length) obeys C(f(E), f(F)) <= K C(E, F) and the reverse,
and f(E), f(F) are the same arcs of the same loops in B, since f keeps
vertex i, the outer loop and every hole. Without holes, with E the arc
a..b and F the arc c..d, C is the modulus M(Q) of the quadrilateral
Q(a, b, c, d). Any family whose capacities in A and B differ by a factor
r > K(alpha) thus rules out alpha.

The capacities are bracketed by linear finite elements (on compatmesh's
mesh of each polygon alone, refined; scipy solves):
- above (Dirichlet's principle): C = min of the Dirichlet energy over u
  with u = 0 on E, 1 on F, free elsewhere (the holes too); the finite
  element functions are admissible, so their least energy is >= C;
- below (Thomson's principle): 1/C = min of the energy of a
  divergence-free flow J carrying a unit flux from E to F and tangent to
  every other part of the boundary. For a continuous P1 function psi,
  J = rot grad psi is such a flow when psi is constant along each of
  those parts (the Neumann arcs), changes by 1 along E (and F), and the
  energy of J is the Dirichlet energy of psi, so 1/C <= the least P1
  energy over such psi. E and F on one loop: psi = 0 on one Neumann
  arc of that loop, 1 on the other. Every loop that carries neither E
  nor F is a Neumann arc of its own with a free constant (one unknown for
  all its nodes; fixing it would restrict the flows, not bound them). E
  and F on different loops: the flux leaves E's loop and enters F's, so
  psi changes by 1 around each; psi is taken on the mesh cut along a
  chain of interior edges from E's loop to F's (from an end of an arc,
  so that no Neumann arc is cut), with a jump of exactly 1 across the
  chain (J stays divergence-free across it: the tangential derivatives
  agree), every Neumann arc a free constant. E the whole hole and F the
  whole outer loop gives the ring capacity 2 pi / ln(R / r) on the
  annulus of radii r < R, and psi the angle over 2 pi.
The ratio used is a lower bound over an upper bound, so the bound stays
on the safe side of the discretisation.

The family is found by a search: without holes, a coarse search over
quadruples of evenly spaced vertices and a local search around the best;
with holes also every pair of loops (whole, or arcs between a few evenly
spaced marks) on a coarser mesh, the best few moved one mark at a time,
then certified on the fine mesh. Another family may distort more, in
which case the true bound is lower still.
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
import scipy.sparse.csgraph
import scipy.sparse.linalg

from make_results import read_loops

# compatmesh's mesh of each polygon is split into four until it has at
# least this many triangles.
MIN_TRIANGLES = 4000
# With holes the search runs on a mesh of at least this many triangles.
SEARCH_TRIANGLES = 1000
# The coarse search tries every quadruple of this many evenly spaced vertices.
COARSE_MARKS = 10
# With holes: marks per loop for the arcs the search tries, and how many of
# its best families are moved mark by mark and certified.
OUTER_MARKS, HOLE_MARKS, CERTIFIED = 6, 4, 4


class Polygon:
    """A fine triangle mesh of a polygon (with holes), its P1 stiffness
    matrix and, per loop and per vertex i of the loop, the mesh nodes on
    the boundary edge from i to i + 1.

    The mesh is compatmesh's own triangulation of the polygon paired with
    itself (checked exactly, boundary = the input loops, their vertices
    first, outer loop then holes), split into four until fine enough. Any
    valid triangulation keeps the bound safe; a finer one only makes it
    tighter."""

    def __init__(self, cli, path, workdir, min_triangles=MIN_TRIANGLES):
        work = tempfile.mkdtemp(dir=workdir)
        out = os.path.join(work, "mesh")
        copies = [os.path.join(work, name) for name in ("a.xy", "b.xy")]
        for copy in copies:
            shutil.copyfile(path, copy)
        run = subprocess.run([cli, "triangulate", *copies, "--out-dir", out],
                             capture_output=True, text=True)
        if run.returncode != 0:
            raise RuntimeError("%s: %s" % (path, run.stderr.strip()))
        mesh = meshio.read(os.path.join(out, "a.off"))
        shutil.rmtree(work)
        xy, tri = mesh.points[:, :2].astype(float), mesh.cells_dict["triangle"].astype(np.int64)
        self.sizes = [len(loop) for loop in read_loops(path)]
        self.n = self.sizes[0]
        # per loop, per edge, its nodes in order from vertex i to i + 1
        loops, at = [], 0
        for m in self.sizes:
            loops.append([[at + i, at + (i + 1) % m] for i in range(m)])
            at += m
        self._mesh(xy, tri, loops, min_triangles)

    def _mesh(self, xy, tri, loops, min_triangles):
        while len(tri) < min_triangles:
            flat = [e for loop in loops for e in loop]
            xy, tri, flat = subdivide(xy, tri, flat)
            it = iter(flat)
            loops = [[next(it) for _ in loop] for loop in loops]
        self.xy, self.tri, self.loop_edges = xy, tri, loops
        self.edge_nodes = [np.array(e) for e in loops[0]]
        self.local = local_stiffness(xy, tri)
        self.stiffness = assemble(tri, self.local, len(xy))
        self.nodes = len(xy)

    def refined(self, min_triangles):
        """The same polygon on a mesh split until it has min_triangles."""
        finer = object.__new__(Polygon)
        finer.sizes, finer.n = self.sizes, self.n
        finer._mesh(self.xy, self.tri, self.loop_edges, min_triangles)
        return finer

    def arc(self, i, j, loop=0):
        """Mesh nodes on the boundary of a loop from its vertex i to j."""
        edges, m = self.loop_edges[loop], self.sizes[loop]
        parts, k = [], i
        while k != j:
            parts.append(edges[k])
            k = (k + 1) % m
        return np.unique(np.concatenate(parts))

    def side(self, s):
        """Mesh nodes of a family's side (loop, i, j): an arc, or the whole
        loop when i is None."""
        loop, i, j = s
        if i is None:
            return np.unique(np.concatenate(self.loop_edges[loop]))
        return self.arc(i, j, loop)

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
        return self.capacity_range(((0, a, b), (0, c, d)))

    def capacity(self, family):
        """Upper bound of the capacity of the curves joining E to F."""
        E, F = family
        return self.energy(self.side(E), self.side(F))

    def capacity_range(self, family):
        """Certified [lower, upper] bounds of the capacity of the curves
        joining E to F."""
        return 1.0 / self.flow_energy(family), self.capacity(family)

    def flow_energy(self, family):
        """The least energy of a P1 stream function psi of a unit flow from
        E to F (the docstring's conditions): an upper bound of 1/C."""
        E, F = family
        # Neumann arcs: (side, psi's value there or None for a free constant)
        neumann = []
        for loop in range(len(self.sizes)):
            on = [s for s in family if s[0] == loop]
            if not on:
                neumann.append(((loop, None, None), None))
            elif len(on) == 2:
                (_, a, b), (_, c, d) = on
                neumann += [((loop, b, c), 0.0), ((loop, d, a), 1.0)]
            elif on[0][1] is not None:
                _, a, b = on[0]
                neumann.append(((loop, b, a), None))
        if E[0] == F[0] and all(value is not None for _, value in neumann):
            return self.energy(self.side(neumann[0][0]), self.side(neumann[1][0]))
        jump = np.zeros(self.tri.shape)  # psi - phi per triangle corner
        if E[0] != F[0]:
            jump = self.cut_jump(E, F)
        # phi = T x + phi0 over the unknowns x: free nodes, free constants
        phi0 = np.zeros(self.nodes)
        column = np.full(self.nodes, -1)
        constants = 0
        for s, value in neumann:
            nodes, offset = self.neumann_offsets(s, jump)
            if value is None:
                column[nodes] = self.nodes + constants
                constants += 1
            else:
                column[nodes] = -2
                phi0[nodes] = value
            phi0[nodes] -= offset
        free_nodes = np.flatnonzero(column == -1)
        column[free_nodes] = free_nodes
        # psi only changes by a constant if no value is fixed: pin one unknown
        if not any(value is not None for _, value in neumann):
            pinned = self.nodes if constants else free_nodes[0]
            column[column == pinned] = -2
        used = np.unique(column[column >= 0])
        rows = np.flatnonzero(column >= 0)
        T = scipy.sparse.csr_matrix((np.ones(len(rows)), (rows, np.searchsorted(used, column[rows]))),
                                    shape=(self.nodes, len(used)))
        K = self.stiffness
        g = np.zeros(self.nodes)
        np.add.at(g, self.tri, np.einsum("tij,tj->ti", self.local, jump))
        A = (T.T @ K @ T).tocsc()
        x = scipy.sparse.linalg.spsolve(A, -(T.T @ (K @ phi0 + g)))
        psi = (T @ x + phi0)[self.tri] + jump
        return float(np.einsum("ti,tij,tj->", psi, self.local, psi))

    def neumann_offsets(self, s, jump):
        """The nodes of a Neumann arc and, per node, psi - phi on the
        triangles along the arc (psi is constant there, so phi + it is): 0
        but at an end of the cut."""
        loop, i, j = s
        m = self.sizes[loop]
        edges = range(m) if i is None else [(i + k) % m for k in range((j - i) % m)]
        offset = {}
        for e in edges:
            chain = self.loop_edges[loop][e]
            for v, w in zip(chain, chain[1:]):
                t = self.boundary_triangle[frozenset((v, w))]
                for node in (v, w):
                    o = jump[t, list(self.tri[t]).index(node)]
                    if offset.setdefault(node, o) != o:
                        raise RuntimeError("the cut splits the Neumann arc %s" % (s,))
        nodes = np.array(sorted(offset))
        return nodes, np.array([offset[v] for v in nodes])

    @property
    def boundary_triangle(self):
        """The triangle on each boundary edge (a frozenset of its nodes)."""
        if not hasattr(self, "_boundary_triangle"):
            edges = {frozenset(p) for loop in self.loop_edges for e in loop for p in zip(e, e[1:])}
            self._boundary_triangle = {}
            for t, corners in enumerate(self.tri):
                for k in range(3):
                    e = frozenset((corners[k], corners[(k + 1) % 3]))
                    if e in edges:
                        self._boundary_triangle[e] = t
        return self._boundary_triangle

    def cut_jump(self, E, F):
        """psi - phi per triangle corner for a cut from E's loop to F's: 1 at
        the cut's nodes on the triangles of one side, 0 elsewhere. The cut
        is the shortest chain of edges through interior nodes from an end
        of E (any node of a whole loop) to an end of F."""
        ends = []
        for loop, i, j in (E, F):
            if i is None:
                ends.append(self.side((loop, None, None)))
            else:
                ends.append(np.array([self.loop_edges[loop][i][0], self.loop_edges[loop][j][0]]))
        boundary = np.zeros(self.nodes, dtype=bool)
        boundary[np.concatenate([e for loop in self.loop_edges for e in loop])] = True
        allowed = ~boundary
        allowed[ends[0]] = allowed[ends[1]] = True
        u, v = np.concatenate([self.tri[:, [0, 1]], self.tri[:, [1, 2]], self.tri[:, [2, 0]]]).T
        keep = allowed[u] & allowed[v]
        length = np.hypot(*(self.xy[u[keep]] - self.xy[v[keep]]).T)
        graph = scipy.sparse.csr_matrix((length, (u[keep], v[keep])), shape=(self.nodes, self.nodes))
        dist, pred, _ = scipy.sparse.csgraph.dijkstra(graph, directed=False, indices=ends[0],
                                                       return_predecessors=True, min_only=True)
        target = ends[1][np.argmin(dist[ends[1]])]
        if not np.isfinite(dist[target]):
            raise RuntimeError("no cut between loops %d and %d" % (E[0], F[0]))
        path = [target]
        while pred[path[-1]] >= 0:
            path.append(pred[path[-1]])
        on_cut = set(path)
        cut_edges = {frozenset(e) for e in zip(path, path[1:])}
        # triangles around the cut, joined across their edges at a cut node
        # but not across the cut: two sides
        star = np.flatnonzero(np.isin(self.tri, path).any(axis=1))
        across = {}
        for t in star:
            for k in range(3):
                e = frozenset((self.tri[t, k], self.tri[t, (k + 1) % 3]))
                if e not in cut_edges and on_cut.intersection(e):
                    across.setdefault(e, []).append(t)
        neighbours = {t: [] for t in star}
        for ts in across.values():
            if len(ts) == 2:
                neighbours[ts[0]].append(ts[1])
                neighbours[ts[1]].append(ts[0])
        first = frozenset(path[:2])
        left, right = [t for t in star if first <= set(self.tri[t])]
        side = {left}
        stack = [left]
        while stack:
            for s in neighbours[stack.pop()]:
                if s not in side:
                    side.add(s)
                    stack.append(s)
        if right in side:
            raise RuntimeError("the cut between loops %d and %d does not split its star" % (E[0], F[0]))
        jump = np.zeros(self.tri.shape)
        for t in side:
            for k in range(3):
                if self.tri[t, k] in on_cut:
                    jump[t, k] = 1.0
        return jump


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


def local_stiffness(xy, tri):
    """Per triangle, its 3 x 3 P1 stiffness matrix."""
    p = xy[tri]
    d = np.stack([p[:, 2] - p[:, 1], p[:, 0] - p[:, 2], p[:, 1] - p[:, 0]], axis=1)
    area = 0.5 * np.abs(d[:, 0, 0] * d[:, 1, 1] - d[:, 0, 1] * d[:, 1, 0])
    return np.einsum("tik,tjk->tij", d, d) / (4 * area)[:, None, None]


def assemble(tri, local, nodes):
    rows = np.repeat(tri, 3, axis=1).ravel()
    cols = np.tile(tri, (1, 3)).ravel()
    return scipy.sparse.csr_matrix((local.ravel(), (rows, cols)), shape=(nodes, nodes))


def dilatation_bound(alpha):
    """K(alpha): the largest dilatation of an affine map between two
    triangles whose angles are all at least alpha (radians), vertex to
    vertex: exp of the hyperbolic distance between the shapes 1/2 + i
    tan(alpha) / 2 and 1 + cos 2 alpha + i sin 2 alpha."""
    x, u, v = 0.5 + math.cos(2 * alpha), math.sin(2 * alpha), 0.5 * math.tan(alpha)
    mu = math.sqrt((x * x + (u - v) ** 2) / (x * x + (u + v) ** 2))
    return (1 + mu) / (1 - mu)


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


def arcs(m, marks, loop):
    """The sides on a loop of m vertices the search tries: the whole loop
    and the arcs between `marks` evenly spaced vertices."""
    ends = sorted({round(i * m / marks) % m for i in range(marks)})
    return [(loop, None, None)] + [(loop, i, j) for i in ends for j in ends if i != j]


def valid(family, sizes):
    """Two sides on distinct loops, or two disjoint arcs in order on one."""
    (l, a, b), (k, c, d) = family
    if any(i is not None and i == j for _, i, j in family):
        return False
    if l != k:
        return True
    if a is None or c is None:
        return False
    m = sizes[l]
    return 0 < (b - a) % m < (c - a) % m < (d - a) % m


def hole_families(sizes):
    """What the search tries with holes: a whole loop or an arc against
    another loop's, and two arcs of one hole (the outer loop's quadruples
    are best_quadruple's)."""
    sides = [arcs(m, OUTER_MARKS if loop == 0 else HOLE_MARKS, loop) for loop, m in enumerate(sizes)]
    families = []
    for l, k in itertools.combinations(range(len(sizes)), 2):
        # many holes: hole against hole by whole loops only
        left = sides[l] if l == 0 or len(sizes) <= 3 else sides[l][:1]
        families += [(E, F) for E in left for F in sides[k] if l == 0 or len(sizes) <= 3 or F[1] is None]
    for loop in range(1, len(sizes)):
        ends = [i for _, i, _ in sides[loop][1:]]
        families += [((loop, a, b), (loop, c, d)) for a, b, c, d in itertools.combinations(sorted(set(ends)), 4)]
    return families


def spread(polys, family):
    """Estimated capacity ratio of a family over every pair of polygons."""
    c = [p.capacity(family) for p in polys]
    return max(c) / min(c)


def improve(polys, family, ratio):
    """The family moved one arc end at a time by halving steps while the
    ratio grows."""
    sizes = polys[0].sizes
    step = max(1, max(sizes) // 8)
    while step >= 1:
        improved = True
        while improved:
            improved = False
            for side, end in itertools.product(range(2), (1, 2)):
                if family[side][1] is None:
                    continue
                m = sizes[family[side][0]]
                for s in (-step, step):
                    moved = [list(x) for x in family]
                    moved[side][end] = (moved[side][end] + s) % m
                    moved = tuple(tuple(x) for x in moved)
                    if not valid(moved, sizes):
                        continue
                    r = spread(polys, moved)
                    if r > ratio * (1 + 1e-9):
                        family, ratio, improved = moved, r, True
        step //= 2
    return family, ratio


def best_with_holes(coarse):
    """The certified ratio and the family of the best few a search on the
    coarse meshes finds, every family certified on the fine mesh."""
    polys = [p.refined(MIN_TRIANGLES) for p in coarse]
    found = []
    q = best_quadruple(coarse)
    found.append((spread(coarse, ((0, q[0], q[1]), (0, q[2], q[3]))), ((0, q[0], q[1]), (0, q[2], q[3]))))
    found += [(spread(coarse, f), f) for f in hole_families(polys[0].sizes)]
    found.sort(key=lambda rf: -rf[0])
    best, best_family = 0.0, None
    for r, family in found[:CERTIFIED]:
        family, _ = improve(coarse, family, r)
        ranges = [p.capacity_range(family) for p in polys]
        K = max(lo_i / hi_j for lo_i, _ in ranges for _, hi_j in ranges)
        if K > best:
            best, best_family = K, family
    return best, best_family


def family_name(family):
    return "/".join(("o" if loop == 0 else "h%d" % loop) + ("" if i is None else ":%d-%d" % (i, j))
                    for loop, i, j in family)


def main(argv):
    if len(argv) < 4:
        print(next(l for l in __doc__.splitlines() if l.startswith("usage")), file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as workdir:
        polys = [Polygon(argv[1], path, workdir, SEARCH_TRIANGLES) for path in argv[2:]]
    if any(p.sizes != polys[0].sizes for p in polys):
        print("correspondence_bound.py: the loops' sizes differ: %s" % " against ".join(
            ",".join(map(str, p.sizes)) for p in polys), file=sys.stderr)
        return 2
    if len(polys[0].sizes) == 1:
        polys = [p.refined(MIN_TRIANGLES) for p in polys]
        q = best_quadruple(polys)
        K, name = certified_ratio(polys, q), ",".join(map(str, q))
    else:
        K, family = best_with_holes(polys)
        name = family_name(family)
    print("%.3f %.4g %s" % (angle_bound(K), K, name))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
