"""The largest smallest angle that any compatible triangulation of a polygon
pair can have, whatever its Steiner vertices: an upper bound from the
distortion the vertex correspondence forces. Polygons may have holes
('>' lines between the loops, outer loop first; loop j of each polygon
corresponds to loop j).

usage: correspondence_bound.py COMPATMESH A.xy B.xy [C.xy ...] [--twist]
prints: bound_deg K family (one line; bound_deg is 60 when nothing binds;
family: the quadruple a,b,c,d without holes, else the two sides E/F of the
curve family, each "o" or "hN" (the outer loop or hole N, whole) or
"o:i-j" / "hN:i-j" (its arc from vertex i to vertex j), "@twist" after
it when the bound is a hole's twist, below; --twist (two polygons with
holes) adds that search, about 10 s a hole)

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

A family of all the curves from E to F sees a hole's turn against the
outer loop only weakly: a half turn of the hole gives facing arcs a
capacity a few times that of opposite ones (the curves go round either
side), not the square of the turn over the ring's width. With --twist
every hole is also bounded by the curves that wind around it a given
number of times, in the covering that records the winding; which number
the map takes to which is not fixed by the correspondence, so the bound
is the least over all of them (twist_bound). It needs the map to keep
the orientation: the loops run the same ways in both polygons (as the
command line requires).

The family is found by a search: without holes, a coarse search over
quadruples of evenly spaced vertices and a local search around the best,
and one around the quadruple compatmesh's own ceiling search found (a
finer coarse search on a conformal map of each polygon), the larger
certified ratio kept;
with holes also every pair of loops (whole, or arcs between a few evenly
spaced marks) on a coarser mesh, the best few moved one mark at a time,
then certified on the fine mesh. Another family may distort more, in
which case the true bound is lower still.
"""
import itertools
import json
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
# The twist search: the mesh the windows copy (at least this many
# triangles), the periods of the outer arc's lift tried (-P..P), and the
# turns tau checked one by one (|tau| <= R; the rest together).
TWIST_SEARCH_TRIANGLES, TWIST_PERIODS, TWIST_RANGE = 250, 2, 1
# The twist search's hole arcs start at this many evenly spaced vertices.
TWIST_STARTS = 8


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
        # per split, each old edge's midpoint: to carry chains of edges over
        self.midpoints = []
        while len(tri) < min_triangles:
            flat = [e for loop in loops for e in loop]
            xy, tri, flat, midpoints = subdivide(xy, tri, flat)
            self.midpoints.append(midpoints)
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
            jump, _ = self.cut_jump(E, F)
        groups = [(*self.neumann_offsets(side, jump), value) for side, value in neumann]
        return least_energy(self.tri, self.local, self.stiffness, groups, jump)

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

    def carried(self, path):
        """A chain of edges of the mesh this one was refined from, as a chain
        of this one's edges."""
        for midpoints in self.midpoints:
            path = [path[0]] + [w for u, v in zip(path, path[1:]) for w in (midpoints[(min(u, v), max(u, v))], v)]
        return path

    def shortest_cut(self, E, F):
        """The shortest chain of edges through interior nodes from an end of
        E (any node of a whole loop) to an end of F."""
        ends = [self.side(s) if s[1] is None else
                np.array([self.loop_edges[s[0]][s[1]][0], self.loop_edges[s[0]][s[2]][0]]) for s in (E, F)]
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
        path.reverse()
        return path

    def cut_jump(self, E, F, flip=False, path=None):
        """psi - phi per triangle corner for a cut from E's loop to F's: 1 at
        the cut's nodes on the triangles of one side (the other if flip), 0
        elsewhere; and the cut's nodes from E's loop to F's. The cut is the
        given path or the shortest_cut."""
        if path is None:
            path = self.shortest_cut(E, F)
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
        sides = []
        for seed in (left, right):
            side, stack = {seed}, [seed]
            while stack:
                for s in neighbours[stack.pop()]:
                    if s not in side:
                        side.add(s)
                        stack.append(s)
            sides.append(side)
        if sides[0] & sides[1] or len(sides[0]) + len(sides[1]) != len(star):
            raise RuntimeError("the cut between loops %d and %d does not split its star in two" % (E[0], F[0]))
        side = sides[1 if flip else 0]
        jump = np.zeros(self.tri.shape)
        for t in side:
            for k in range(3):
                if self.tri[t, k] in on_cut:
                    jump[t, k] = 1.0
        return jump, path


class Window:
    """2m + 1 copies of a polygon's mesh, cut along a chain of edges from a
    hole to the outer loop, glued in a row, copy k's side of the cut where
    psi jumps to copy k + 1's other side: a piece of the covering space in
    which a curve's lift records how often it winds around the hole. The
    copies are numbered so that walking once forward along the outer loop
    moves one copy up."""

    def __init__(self, poly, hole, m, path=None):
        """The cut: `path` (a chain of nodes), or the shortest from the hole
        to the outer loop; a window on a refinement follows the same cut
        (carried), so that the copies are numbered alike."""
        self.poly, self.hole, self.m = poly, hole, m
        for flip in (False, True):
            self.jump, self.path = poly.cut_jump((hole, None, None), (0, None, None), flip, path=path)
            path = self.path
            self.s = self.jump.astype(np.int64)
            if self.turn(0) == 1:
                break
        # which way a walk forward along the hole turns (the same in every
        # polygon whose loops run the same ways)
        self.hole_turn = self.turn(hole)
        N = poly.nodes
        raw = np.concatenate([(k + m + self.s) * N + poly.tri for k in range(-m, m + 1)])
        self.index = np.full((2 * m + 2) * N, -1)
        used, tri = np.unique(raw, return_inverse=True)
        self.index[used] = np.arange(len(used))
        self.tri = tri.reshape(-1, 3)
        self.local = np.tile(poly.local, (2 * m + 1, 1, 1))
        self.stiffness = assemble(self.tri, self.local, len(used))
        # the window's two ends: the cut's first side in copy -m, its second in copy m
        self.ends = [self.index[np.array(self.path) + (k + m) * N] for k in (-m, m + 1)]
        pairs = np.sort(np.concatenate([self.tri[:, [0, 1]], self.tri[:, [1, 2]], self.tri[:, [2, 0]]]), axis=1)
        edges, count = np.unique(pairs, axis=0, return_counts=True)
        self.boundary = edges[count == 1]

    def walk(self, loop, copy, count):
        """The lifted boundary segments (raw node numbers: copy * nodes + node,
        copies from -m) of `count` edges of a loop forward from its vertex 0,
        the first segment in `copy`; per polygon edge a list, and the copy
        the walk ends in."""
        poly, edges, c = self.poly, [], copy
        chains = poly.loop_edges[loop]
        for e in range(count):
            chain, segments = chains[e % len(chains)], []
            for v, w in zip(chain, chain[1:]):
                t = poly.boundary_triangle[frozenset((v, w))]
                corners = list(poly.tri[t])
                sv, sw = self.s[t, corners.index(v)], self.s[t, corners.index(w)]
                if segments or edges:
                    c -= sv  # continue from the node the last segment ended at
                segments.append(((c + sv + self.m) * poly.nodes + v, (c + sw + self.m) * poly.nodes + w))
                c += sw
            edges.append(segments)
        return edges, c

    def turn(self, loop):
        """How many copies one walk forward around a loop moves."""
        edges, _ = self.walk(loop, 0, self.poly.sizes[loop] + 1)
        return (edges[-1][0][0] - edges[0][0][0]) // self.poly.nodes

    def lift(self, side, period, clip=False):
        """The lift of an arc (loop, i, j) whose vertex i is reached from
        vertex 0's lift in `period` (copy) walking forward: its segments as
        window nodes; None where it leaves the window or touches its ends
        (with clip: the segments inside the window, maybe none)."""
        loop, i, j = side
        m = self.poly.sizes[loop]
        edges, _ = self.walk(loop, period, i + (j - i) % m)
        raw = np.array([p for segments in edges[i:] for p in segments])
        inside = ((raw >= 0) & (raw < len(self.index))).all(axis=1)
        inside[inside] = (self.index[raw[inside]] >= 0).all(axis=1)
        if clip:
            return self.index[raw[inside]].reshape(-1, 2)
        if not inside.all():
            return None
        nodes = self.index[raw]
        if np.isin(nodes, np.concatenate(self.ends)).any():
            return None
        return nodes

    def capacity_range(self, E, F, union=False, upper_only=False):
        """[lower, upper] bounds of the capacity of the curves joining the
        lift E to the lift F in the covering (segment arrays); with union,
        F a list of lifts and the upper bound alone, of the curves joining E
        to any of them or to anything beyond the window's ends."""
        zero = np.unique(E)
        if union:
            one = np.unique(np.concatenate([np.ravel(f) for f in F] + self.ends))
            if np.isin(zero, one).any():
                raise RuntimeError("E touches a lift of F or the window's ends")
            return 0.0, least_energy(self.tri, self.local, self.stiffness, [(zero, 0, 0.0), (one, 0, 1.0)])
        one = np.unique(F)
        ends = [(end, 0, None) for end in self.ends]
        upper = least_energy(self.tri, self.local, self.stiffness, [(zero, 0, 0.0), (one, 0, 1.0)] + ends)
        if upper_only:
            return 0.0, upper
        # the dual: psi 0 on the boundary after E, 1 before it, a free
        # constant on every other piece of the boundary (other holes)
        taken = {frozenset(e) for e in np.concatenate([E, F])}
        rest = [e for e in self.boundary if frozenset(e) not in taken]
        parent = {}

        def root(v):
            while parent.setdefault(v, v) != v:
                v = parent[v]
            return v
        for u, v in rest:
            parent[root(u)] = root(v)
        pieces = {}
        for u, v in rest:
            pieces.setdefault(root(u), set()).update((u, v))
        after, before = root(E[-1][1]), root(E[0][0])
        if after == before:
            raise RuntimeError("E and F are not on one boundary cycle of the window")
        groups = [(np.array(sorted(nodes)), 0, 0.0 if r == after else 1.0 if r == before else None)
                  for r, nodes in pieces.items()]
        lower = 1.0 / least_energy(self.tri, self.local, self.stiffness, groups)
        return lower, upper


def least_energy(tri, local, stiffness, groups, jump=None):
    """The least P1 energy of psi = phi + jump (jump: per triangle corner,
    a cut's unit jump, or none) over continuous phi, with psi tied on each
    group (nodes, psi - phi there, value): to the value, or where the value
    is None to one free constant for all the group's nodes; phi free
    elsewhere. Without a given value psi is pinned at one unknown."""
    nodes = stiffness.shape[0]
    if jump is None:
        jump = np.zeros(tri.shape)
    # phi = T x + phi0 over the unknowns x: free nodes, free constants
    phi0 = np.zeros(nodes)
    column = np.full(nodes, -1)
    constants = 0
    for group, offset, value in groups:
        if value is None:
            column[group] = nodes + constants
            constants += 1
        else:
            column[group] = -2
            phi0[group] = value
        phi0[group] -= offset
    free_nodes = np.flatnonzero(column == -1)
    column[free_nodes] = free_nodes
    # psi only changes by a constant if no value is fixed: pin one unknown
    if not any(value is not None for _, _, value in groups):
        pinned = nodes if constants else free_nodes[0]
        column[column == pinned] = -2
    used = np.unique(column[column >= 0])
    rows = np.flatnonzero(column >= 0)
    T = scipy.sparse.csr_matrix((np.ones(len(rows)), (rows, np.searchsorted(used, column[rows]))),
                                shape=(nodes, len(used)))
    g = np.zeros(nodes)
    np.add.at(g, tri, np.einsum("tij,tj->ti", local, jump))
    A = (T.T @ stiffness @ T).tocsc()
    x = scipy.sparse.linalg.spsolve(A, -(T.T @ (stiffness @ phi0 + g)))
    psi = (T @ x + phi0)[tri] + jump
    return float(np.einsum("ti,tij,tj->", psi, local, psi))


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
    return new_xy, new_tri, new_edges, index


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
    return climb(polys, best_q, best, max(1, n // (2 * COARSE_MARKS)))


def climb(polys, best_q, best, step):
    """Quadruple best_q (ratio best) moved one mark at a time by halving
    steps from `step` while the ratio grows."""
    n = polys[0].n
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


def library_quadruple(cli, paths, workdir):
    """The quadruple compatmesh's own ceiling search (core/src/correspond/
    bound.c: twenty marks, its best three refined, on a coarser mesh) found
    for the polygons, or None: a second start for the search here, whose
    result is certified here all the same."""
    out = os.path.join(tempfile.mkdtemp(dir=workdir), "pair")
    run = subprocess.run([cli, "triangulate", *paths, "--out-dir", out, "--no-remesh", "--no-preview", "--quiet"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        return None
    with open(os.path.join(out, "report.json")) as f:
        quad = (json.load(f).get("ceiling") or {}).get("distortion_quad")
    return tuple(sorted(quad)) if quad and len(set(quad)) == 4 else None


def certified_family(polys, family):
    """The largest certified capacity ratio of a family between polygons."""
    ranges = [p.capacity_range(family) for p in polys]
    return max(lo_i / hi_j for lo_i, _ in ranges for _, hi_j in ranges)


def certified_ratio(polys, q):
    a, b, c, d = q
    return certified_family(polys, ((0, a, b), (0, c, d)))


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


def best_with_holes(rough, twist=False):
    """The certified ratio and the family's name, of the best few a search
    on the coarse meshes finds, every family certified on the fine mesh;
    with twist, also every hole's twist_bound (the name ends in "@twist")."""
    coarse = [p.refined(SEARCH_TRIANGLES) for p in rough]
    polys = [p.refined(MIN_TRIANGLES) for p in coarse]
    found = []
    q = best_quadruple(coarse)
    found.append((spread(coarse, ((0, q[0], q[1]), (0, q[2], q[3]))), ((0, q[0], q[1]), (0, q[2], q[3]))))
    found += [(spread(coarse, f), f) for f in hole_families(polys[0].sizes)]
    found.sort(key=lambda rf: -rf[0])
    best, best_family = 0.0, None
    for r, family in found[:CERTIFIED]:
        family, _ = improve(coarse, family, r)
        K = certified_family(polys, family)
        if K > best:
            best, best_family = K, family_name(family)
    if twist and len(polys) == 2:
        for hole in range(1, len(polys[0].sizes)):
            K, family = twist_bound(rough, coarse, hole)
            if K > best:
                best, best_family = K, family_name(family) + "@twist"
    return best, best_family


def twist_sides(polys, hole):
    """The arcs the twist search pairs: half of the hole from each of up to
    TWIST_STARTS evenly spaced vertices against the outer arc facing it,
    or its complement, as seen from the hole's centre in each polygon; and
    half of the hole against a quarter or a half of the outer loop, from
    four evenly spaced marks each."""
    sizes = polys[0].sizes
    m, n = sizes[hole], sizes[0]
    marks = [[round(i * size / 4) % size for i in range(4)] for size in (m, n)]
    families = {((hole, marks[0][i], marks[0][(i + 2) % 4]), (0, marks[1][j], marks[1][(j + k) % 4]))
                for i in range(4) for j in range(4) for k in (1, 2)}
    for start in sorted({round(k * m / TWIST_STARTS) % m for k in range(TWIST_STARTS)}):
        E = (hole, start, (start + m // 2) % m)
        for p in polys:
            outer = p.xy[:n]
            centre = p.xy[sum(sizes[:hole]):sum(sizes[:hole + 1])].mean(axis=0)
            angle = np.arctan2(*(outer - centre).T[::-1])
            ends = []
            for v in E[1:]:
                x, y = p.xy[sum(sizes[:hole]) + v] - centre
                ends.append(int(np.argmin(np.abs(np.angle(np.exp(1j * (angle - math.atan2(y, x))))))))
            if ends[0] != ends[1]:
                families.update({(E, (0, ends[0], ends[1])), (E, (0, ends[1], ends[0]))})
    return sorted(families)


def twist_bound(coarse, polys, hole):
    """A certified dilatation from the turn of a hole against the outer
    loop, and its witness.

    f lifts to the coverings in which a curve records how often it winds
    around the hole (Window; f keeps the hole and the orientation, so it
    keeps the winding), commuting with the shift by one copy (in both a
    forward walk around the outer loop moves one copy up). On the lifted
    outer loop f's lift takes the lifts of vertex i to lifts of vertex i,
    in order, so it moves every one by the same number of periods; on the
    lifted hole likewise, by another. So it takes the lift E_0 of a hole
    arc E and the lift F_d of an outer arc F (F's first vertex reached
    from vertex 0's lift in period d walking forward, E's from period 0)
    to E_0 and F_(d + tau) in B's covering, up to a shift, for one integer
    tau, the same for every E and F, that the correspondence does not fix
    (whole turns of the hole against the outer loop). f's lift is K-qc, so for
    that tau every family gives K >= C_A(E_0, F_d) / C_B(E_0, F_(d + tau))
    and the reverse, the capacities in the coverings, which a window
    bounds: from above, u fixed on E_0 and F_d and a free constant on each
    end of the window (extended by it beyond); from below, a flow inside
    the window, psi 0 and 1 on the boundary on either side of E_0 (the
    window's ends included), free constants on other holes. For |tau| >
    TWIST_RANGE: C_B(E_0, F_(d + tau)) is at most the capacity of the
    curves from E_0 to every F_b with |b - d| > TWIST_RANGE or beyond the
    window's ends (u = 1 on all of them), and the same with A and B
    swapped. K is at least the least over tau of the best family's."""
    span = TWIST_PERIODS
    windows = [Window(p, hole, span + 2) for p in coarse]
    if windows[0].hole_turn != windows[1].hole_turn:
        raise RuntimeError("hole %d runs the other way against the outer loop" % hole)
    estimates = []  # (family, upper bound per period d in A, in B)
    for family in twist_sides(coarse, hole):
        E, F = family
        caps = []
        for w in windows:
            e = w.lift(E, 0)
            lifts = [w.lift(F, d) for d in range(-span, span + 1)]
            if e is None or any(f is None for f in lifts):
                break
            caps.append([w.capacity_range(e, f, upper_only=True)[1] for f in lifts])
        if len(caps) == 2:
            estimates.append((family, caps))
    if not estimates:
        return 1.0, None
    fine = [Window(p, hole, span + 2, p.carried(w.path)) for p, w in zip(polys, windows)]

    def certified(family, d, shift):
        """max of lo_A / hi_B and lo_B / hi_A, A at period d, B at d + shift."""
        E, F = family
        (la, ha), (lb, hb) = [w.capacity_range(w.lift(E, 0), w.lift(F, p)) for w, p in zip(fine, (d, d + shift))]
        return max(la / hb, lb / ha)

    def union(family, d, source, ws):
        """lo (hi on the rough windows) in window `source` at period d over
        hi of the other's union."""
        E, F = family
        w, other = ws[source], ws[1 - source]
        lo, hi = w.capacity_range(w.lift(E, 0), w.lift(F, d), upper_only=ws is windows)
        far = [other.lift(F, b, clip=True) for b in range(-2 * span - 4, 2 * span + 5) if abs(b - d) > TWIST_RANGE]
        return (hi if ws is windows else lo) / other.capacity_range(other.lift(E, 0), far, union=True)[1]

    periods = range(-span, span + 1)
    worst, witness = math.inf, None
    for shift in range(-TWIST_RANGE, TWIST_RANGE + 1):
        ranked = sorted(((max(ca[d + span] / cb[d + shift + span], cb[d + shift + span] / ca[d + span]), f, d)
                         for f, (ca, cb) in estimates for d in periods if d + shift in periods), reverse=True)
        best = max((certified(f, d, shift), f) for _, f, d in ranked[:2])
        if best[0] < worst:
            worst, witness = best
    # every |tau| > TWIST_RANGE at once: a family's lift against all far lifts
    ranked = sorted(((caps[src][d + span] / max(caps[1 - src][b + span] for b in periods
                                                   if abs(b - d) > TWIST_RANGE), f, d, src)
                     for f, caps in estimates for d in periods for src in (0, 1)
                     if any(abs(b - d) > TWIST_RANGE for b in periods)), reverse=True)
    # the proxy above ranks, the unions on the rough windows choose
    ranked = sorted(((union(f, d, src, windows), f, d, src) for _, f, d, src in ranked[:6]), reverse=True)
    best = max((union(f, d, src, fine), f) for _, f, d, src in ranked[:2])
    if best[0] < worst:
        worst, witness = best
    return worst, witness


def family_name(family):
    return "/".join(("o" if loop == 0 else "h%d" % loop) + ("" if i is None else ":%d-%d" % (i, j))
                    for loop, i, j in family)


def main(argv):
    if len(argv) < 4:
        print(next(l for l in __doc__.splitlines() if l.startswith("usage")), file=sys.stderr)
        return 2
    twist = "--twist" in argv
    argv = [a for a in argv if a != "--twist"]
    with tempfile.TemporaryDirectory() as workdir:
        polys = [Polygon(argv[1], path, workdir, TWIST_SEARCH_TRIANGLES) for path in argv[2:]]
    if any(p.sizes != polys[0].sizes for p in polys):
        print("correspondence_bound.py: the loops' sizes differ: %s" % " against ".join(
            ",".join(map(str, p.sizes)) for p in polys), file=sys.stderr)
        return 2
    if len(polys[0].sizes) == 1:
        polys = [p.refined(MIN_TRIANGLES) for p in polys]
        starts = [best_quadruple(polys)]
        with tempfile.TemporaryDirectory() as workdir:
            q = library_quadruple(argv[1], argv[2:], workdir)
        if q is not None and q not in starts:
            starts.append(climb(polys, q, distortion(polys, q), 2))
        K, q = max((certified_ratio(polys, q), q) for q in starts)
        name = ",".join(map(str, q))
    else:
        K, name = best_with_holes(polys, twist)
    print("%.3f %.4g %s" % (angle_bound(K), K, name))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
