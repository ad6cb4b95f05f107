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
- In log coordinates (s, angle), s in (0, S), S = ln(1 / rho), take for
  a slope m the helices s -> (s, a + m s), a in [0, 2 pi). Each is
  S sqrt(1 + m^2) long; its image joins (0, a) to (S, a + m S + t'), t' =
  theta + 2 pi k (the same k for all a), so it is at least
  sqrt(S^2 + (m S + t')^2) long. Along each helix Cauchy-Schwarz and
  |Dg u|^2 <= K J for a unit vector u (J the Jacobian); over a, the shear
  (s, a) -> (s, a + m s) has unit Jacobian, so J integrates to the
  image's area 2 pi S. Hence K >= (1 + (m + gamma)^2) / (1 + m^2), gamma =
  t' / S, for the largest dilatation K of f (the length-area argument;
  m = 0 is the radial segments, K >= 1 + gamma^2).
- The largest over m is the largest eigenvalue of [[1 + gamma^2, gamma],
  [gamma, 1]] (the quotient is its Rayleigh quotient at (1, m)), of
  trace 2 + gamma^2 and determinant 1: K + 1/K = 2 + gamma^2. That is the affine twist's own
  dilatation, so no family of curves does better. It grows with |t'|, so
  the least turn t = the distance from theta to the nearest multiple of
  2 pi binds.
- S has two upper bounds, the smaller taken:
  - D lies in the round annulus between the largest circle about c inside
    the hole and the smallest about c holding the outer loop, so S is at
    most the log of their radii's ratio, ln(R / r) (a sub-annulus has the
    smaller modulus).
  - S = 2 pi / cap, cap the condenser capacity of D (the Dirichlet energy
    of the harmonic u, 0 on the hole and 1 on the outer loop). By
    Thomson's principle cap >= 1 / integral |sigma|^2 for every
    divergence-free field sigma in D with a unit flux around the hole,
    whatever its normal component on the loops. sigma = rot psi is one for
    psi continuous and linear on each triangle of a mesh of D but for a
    jump of exactly 1 across a chain of edges from the hole to the outer
    loop (sigma's normal component on an edge is psi's tangential
    derivative, the same on both sides, the cut's too; the jump is the
    flux), and integral |sigma|^2 is psi's Dirichlet energy E. So
    S <= 2 pi E for every such psi: the least E (a sparse solve) makes it
    tight, and the solve's accuracy does not matter, since E is summed
    triangle by triangle for the psi it returns. The mesh (gmsh) has the
    polygon's vertices among its nodes and straight edges, and is checked
    to tile D (every triangle positive, the boundary edges on the loops,
    the areas summing to D's to 1e-12). The bound is 2 pi E (1 + 1e-9),
    the slack for rounding (in the sums, and the nodes gmsh puts on the
    edges, off them by about 1e-16).
  - The other side, for the bracket printed: u piecewise linear on the
    same mesh, 0 on the hole and 1 on the outer loop, has an energy E_u >=
    cap (Dirichlet's principle), so S >= 2 pi / E_u.
- Some triangle's affine map has dilatation at least K, and two triangles
  whose angles are all at least alpha are related by dilatation at most
  K(alpha) (correspondence_bound.dilatation_bound): the smallest angle is
  at most angle_bound(K).

usage: twist_bound.py A.xy B.xy  (loops separated by lines beginning with
'>', the outer loop first)
prints: the turn, the bracket on S (finite elements) and ln(R/r), the
dilatation bound and the ceiling (one line; about 1.5 s)
"""
import collections
import math
import sys

import gmsh
import numpy as np
import scipy.sparse
import scipy.sparse.csgraph
import scipy.sparse.linalg

from correspondence_bound import angle_bound

TOLERANCE = 1e-9
# the flow bound's mesh: its size as a fraction of the outer loop's width,
# finer at the hole's corners (reflex in D, where the flow is singular)
MESH_SIZE = 0.005
CORNER_SIZE = 0.05
CORNER_REACH = 8
# the relative slack on the flow bound, for rounding
SLACK = 1e-9
TILING = 1e-12

# S bracketed by the two finite element bounds (s_low, s_flow) and bounded
# by ln(R/r) (s_ring); the ceiling from the smaller upper bound, s_bound
Bound = collections.namedtuple("Bound", "theta s_low s_flow s_ring s_bound k_bound ceiling")


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


def twist_dilatation(gamma):
    """The K >= 1 with K + 1/K = 2 + gamma^2 (the affine twist (s, a) ->
    (s, a + gamma s)), in a form that adds positive terms only."""
    return (abs(gamma) / 2 + math.sqrt(1 + gamma * gamma / 4)) ** 2


def signed_area(loop):
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def loop_distance(points, loop):
    """The distance from each point to the loop's nearest edge."""
    a, b = loop, np.roll(loop, -1, axis=0)
    ab, ap = b - a, points[:, None, :] - a[None, :, :]
    t = np.clip((ap * ab).sum(axis=2) / (ab * ab).sum(axis=1), 0.0, 1.0)
    return np.linalg.norm(ap - t[:, :, None] * ab, axis=2).min(axis=1)


def mesh_domain(outer, hole, size):
    """Nodes, counterclockwise triangles and the nodes on the outer loop and
    on the hole of a gmsh mesh of D of about `size` (the outer loop's width
    times it), or ValueError where it does not tile D."""
    scale = float(np.ptp(outer, axis=0).max())
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("domain")
        loops = []
        for loop in (outer, hole):
            points = [gmsh.model.geo.addPoint(x, y, 0) for x, y in loop]
            lines = [gmsh.model.geo.addLine(p, q) for p, q in zip(points, points[1:] + points[:1])]
            loops.append((points, lines, gmsh.model.geo.addCurveLoop(lines)))
        gmsh.model.geo.addPlaneSurface([loops[0][2], loops[1][2]])
        gmsh.model.geo.synchronize()
        field = gmsh.model.mesh.field
        distance = field.add("Distance")
        field.setNumbers(distance, "PointsList", loops[1][0])
        threshold = field.add("Threshold")
        field.setNumber(threshold, "InField", distance)
        field.setNumber(threshold, "SizeMin", CORNER_SIZE * size * scale)
        field.setNumber(threshold, "SizeMax", size * scale)
        field.setNumber(threshold, "DistMin", 0.0)
        field.setNumber(threshold, "DistMax", CORNER_REACH * size * scale)
        field.setAsBackgroundMesh(threshold)
        for option in ("MeshSizeExtendFromBoundary", "MeshSizeFromPoints", "MeshSizeFromCurvature"):
            gmsh.option.setNumber("Mesh." + option, 0)
        gmsh.model.mesh.generate(2)
        tags, xyz, _ = gmsh.model.mesh.getNodes()
        index = np.zeros(int(tags.max()) + 1, dtype=int)
        index[tags.astype(int)] = np.arange(len(tags))
        nodes = xyz.reshape(-1, 3)[:, :2]
        types, _, corners = gmsh.model.mesh.getElements(2)
        triangles = index[corners[list(types).index(2)].astype(int)].reshape(-1, 3)
        on_loop = []
        for _, lines, _ in loops:
            on = set()
            for line in lines:
                line_tags, _, _ = gmsh.model.mesh.getNodes(1, line, includeBoundary=True)
                on.update(index[line_tags.astype(int)].tolist())
            on_loop.append(np.array(sorted(on)))
    except Exception as error:  # gmsh's own errors are plain Exceptions
        raise ValueError(f"gmsh could not mesh the domain ({error})") from error
    finally:
        gmsh.finalize()
    areas = triangle_areas(nodes, triangles)
    if areas.sum() < 0:
        triangles, areas = triangles[:, ::-1], -areas
    # a tiling: triangles positive, each edge in one or two, the edges in
    # one on a loop (both ends on it, those within rounding of its edges),
    # and the areas summing to D's
    edges = np.sort(np.r_[triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]], axis=1)
    edges, uses = np.unique(edges, axis=0, return_counts=True)
    loop_of = np.full(len(nodes), -1)
    for k, on in enumerate(on_loop):
        loop_of[on] = k
    rim = edges[uses == 1]
    domain_area = abs(signed_area(outer)) - abs(signed_area(hole))
    if (areas.min() <= 0 or uses.max() > 2 or (loop_of[rim[:, 0]] < 0).any()
            or (loop_of[rim[:, 0]] != loop_of[rim[:, 1]]).any()
            or loop_distance(nodes[on_loop[0]], outer).max() > TILING * scale
            or loop_distance(nodes[on_loop[1]], hole).max() > TILING * scale
            or abs(math.fsum(areas) - domain_area) > TILING * domain_area):
        raise ValueError("the domain's mesh does not tile it")
    return nodes, triangles, on_loop[0], on_loop[1]


def triangle_areas(nodes, triangles):
    a, b, c = (nodes[triangles[:, k]] for k in range(3))
    return 0.5 * ((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])


def stiffness(nodes, triangles, areas):
    """Each triangle's 3 x 3 Dirichlet energy matrix of its corner values,
    and the assembled sparse matrix."""
    opposite = [nodes[triangles[:, (k + 2) % 3]] - nodes[triangles[:, (k + 1) % 3]] for k in range(3)]
    local = np.stack([np.stack([(opposite[i] * opposite[j]).sum(axis=1) / (4 * areas) for j in range(3)], axis=1)
                      for i in range(3)], axis=1)
    rows = np.repeat(triangles, 3, axis=1).ravel()
    cols = np.tile(triangles, (1, 3)).ravel()
    matrix = scipy.sparse.csr_matrix((local.ravel(), (rows, cols)), shape=(len(nodes), len(nodes)))
    return local, matrix


def energy(nodes, triangles, areas, values):
    """The Dirichlet energy of the function linear on each triangle with
    the given corner values, from its gradients (not the solver's)."""
    gradient = np.zeros((len(triangles), 2))
    for k in range(3):
        edge = nodes[triangles[:, (k + 2) % 3]] - nodes[triangles[:, (k + 1) % 3]]
        gradient += values[:, [k]] * np.c_[-edge[:, 1], edge[:, 0]]
    gradient /= 2 * areas[:, None]
    return math.fsum(areas * (gradient * gradient).sum(axis=1))


def cut_jump(nodes, triangles, outer_nodes, hole_nodes):
    """1 at the corners on a cut of the triangles on one side of it, 0
    elsewhere: the cut is the shortest chain of edges from a hole node to
    the outer loop through interior nodes."""
    count = len(nodes)
    loop = np.zeros(count, dtype=int)
    loop[outer_nodes], loop[hole_nodes] = 1, 2
    start = hole_nodes[0]
    edges = np.unique(np.sort(np.r_[triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]], axis=1),
                      axis=0)
    a, b = edges[:, 0], edges[:, 1]
    free_a, free_b = loop[a] == 0, loop[b] == 0
    keep = ((free_a | (a == start) | (loop[a] == 1)) & (free_b | (b == start) | (loop[b] == 1))
            & (free_a | free_b))
    a, b = a[keep], b[keep]
    graph = scipy.sparse.csr_matrix((np.linalg.norm(nodes[a] - nodes[b], axis=1), (a, b)), shape=(count, count))
    distance, previous = scipy.sparse.csgraph.dijkstra(graph, directed=False, indices=start,
                                                       return_predecessors=True)
    path = [int(outer_nodes[np.argmin(distance[outer_nodes])])]
    if not np.isfinite(distance[path[0]]):
        raise ValueError("no cut from the hole to the outer loop")
    while path[-1] != start:
        path.append(int(previous[path[-1]]))
    on_cut = set(path)
    cut_edges = {frozenset(e) for e in zip(path, path[1:])}
    # the triangles at the cut's nodes, joined across their edges at a cut
    # node but not across the cut: two sides
    near = np.flatnonzero(np.isin(triangles, path).any(axis=1)).tolist()
    parent = {t: t for t in near}

    def root(t):
        while parent[t] != t:
            parent[t] = parent[parent[t]]
            t = parent[t]
        return t

    by_edge = {}
    for t in near:
        for k in range(3):
            edge = frozenset((int(triangles[t, k]), int(triangles[t, (k + 1) % 3])))
            if edge not in cut_edges and on_cut.intersection(edge):
                by_edge.setdefault(edge, []).append(t)
    for pair in by_edge.values():
        for t in pair[1:]:
            parent[root(t)] = root(pair[0])
    sides = sorted({root(t) for t in near})
    if len(sides) != 2:
        raise ValueError("the cut does not split its triangles in two sides")
    jump = np.zeros(triangles.shape)
    for t in near:
        if root(t) == sides[0]:
            jump[t] = [1.0 if int(v) in on_cut else 0.0 for v in triangles[t]]
    return jump


def stream_function(nodes, triangles, local, matrix, outer_nodes, hole_nodes):
    """psi = phi + jump, the least-energy piecewise-linear function with a
    unit jump across a cut from the hole to the outer loop: phi single
    valued at the nodes (its first node 0: the energy does not see
    constants), jump (per triangle corner) 1 at the cut's nodes on one
    side, 0 elsewhere. (phi, jump)."""
    jump = cut_jump(nodes, triangles, outer_nodes, hole_nodes)
    load = np.zeros(len(nodes))
    np.add.at(load, triangles.ravel(), np.einsum("tij,tj->ti", local, jump).ravel())
    phi = np.zeros(len(nodes))
    phi[1:] = scipy.sparse.linalg.spsolve(matrix[1:, 1:].tocsc(), -load[1:])
    return phi, jump


def modulus_bracket(outer, hole, size=MESH_SIZE):
    """(lower, upper) bounds on S = 2 pi / cap of D: 2 pi over the energy of
    the piecewise-linear u, 0 on the hole and 1 on the outer loop, and
    2 pi times the energy of the piecewise-linear psi with a unit jump
    across a cut (with SLACK), each the least on a mesh of D."""
    nodes, triangles, outer_nodes, hole_nodes = mesh_domain(outer, hole, size)
    areas = triangle_areas(nodes, triangles)
    local, matrix = stiffness(nodes, triangles, areas)
    u = np.zeros(len(nodes))
    u[outer_nodes] = 1.0
    fixed = np.zeros(len(nodes), dtype=bool)
    fixed[outer_nodes] = fixed[hole_nodes] = True
    free = ~fixed
    u[free] = scipy.sparse.linalg.spsolve(matrix[free][:, free].tocsc(), -(matrix[free][:, fixed] @ u[fixed]))
    primal = energy(nodes, triangles, areas, u[triangles])
    phi, jump = stream_function(nodes, triangles, local, matrix, outer_nodes, hole_nodes)
    flow = energy(nodes, triangles, areas, phi[triangles] + jump)
    return 2 * math.pi / primal * (1 - SLACK), 2 * math.pi * flow * (1 + SLACK)


def twist_bound(outer_a, hole_a, outer_b, hole_b, mesh_size=MESH_SIZE):
    """A Bound for the pair (the angle ceiling in degrees), or ValueError
    where it is not an outer loop kept and a hole turned about a centre of
    symmetry of the domain. mesh_size: the flow bound's, as a fraction of
    the outer loop's width (any mesh gives a certified bound)."""
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
    s_ring = math.log(outer_radius / inner_radius)
    s_low, s_flow = modulus_bracket(outer_a, hole_a, mesh_size)
    s_bound = min(s_ring, s_flow)
    least_turn = abs(math.remainder(theta, 2 * math.pi))
    k_bound = twist_dilatation(least_turn / s_bound)
    return Bound(theta, s_low, s_flow, s_ring, s_bound, k_bound, angle_bound(k_bound))


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    loops = [read_loops(path) for path in argv[1:]]
    try:
        if any(len(each) != 2 for each in loops):
            raise ValueError("each polygon must have one outer loop and one hole")
        bound = twist_bound(*loops[0], *loops[1])
    except ValueError as error:
        sys.exit(f"twist_bound: {error}")
    print(f"turn {math.degrees(bound.theta):.6g} degrees, {bound.s_low:.6g} <= S <= {bound.s_flow:.6g} "
          f"(ln(R/r) = {bound.s_ring:.6g}), dilatation >= {bound.k_bound:.6g}: "
          f"no compatible triangulation has a smallest angle above {bound.ceiling:.4f} degrees")


if __name__ == "__main__":
    main(sys.argv)
