"""MeshLab plugin tests: meshlabserver (through build/bin/meshlabserver-compatmesh)
runs the .mlx scripts of docs/meshlab on PLY and OBJ inputs made here; the
saved layers are checked with exact arithmetic.

Usage: meshlab_cases.py WRAPPER DOCS_DIR CASE
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
from fractions import Fraction

import meshio
import numpy as np

WRAPPER, DOCS, CASE = sys.argv[1], sys.argv[2], sys.argv[3]


# ---- inputs -------------------------------------------------------------

def as_float32(p):
    """The point as MeshLab stores it; 9 digits print a float exactly."""
    return tuple(float(np.float32(v)) for v in p)


def write_ply(path, points, edges=(), faces=()):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\n" % len(points))
        f.write("property float x\nproperty float y\nproperty float z\n")
        if edges:
            f.write("element edge %d\nproperty int vertex1\nproperty int vertex2\n" % len(edges))
        if faces:
            f.write("element face %d\nproperty list uchar int vertex_indices\n" % len(faces))
        f.write("end_header\n")
        for p in points:
            f.write("%.9g %.9g %.9g\n" % as_float32(p))
        for e in edges:
            f.write("%d %d\n" % tuple(e))
        for t in faces:
            f.write("%d %s\n" % (len(t), " ".join(map(str, t))))


def write_obj_polyline(path, points):
    """One `l` element per edge: MeshLab 2020.09 reads only the first edge
    of a longer `l` line."""
    with open(path, "w") as f:
        for p in points:
            f.write("v %.9g %.9g %.9g\n" % as_float32(p))
        for a, b in loop_edges(len(points)):
            f.write("l %d %d\n" % (a + 1, b + 1))


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            f.write("%.9g %.9g %.9g\n" % as_float32(p))
        for t in faces:
            f.write("%d %s\n" % (len(t), " ".join(map(str, t))))


def loop_edges(n, start=0):
    return [(start + i, start + (i + 1) % n) for i in range(n)]


def star(n, r0, r1, z=0.0, phase=0.0, scale=(1.0, 1.0)):
    """A star-shaped polygon with n vertices (r alternates r0, r1)."""
    return [(scale[0] * (r0 if i % 2 == 0 else r1) * math.cos(phase + 2 * math.pi * i / n),
             scale[1] * (r0 if i % 2 == 0 else r1) * math.sin(phase + 2 * math.pi * i / n), z)
            for i in range(n)]


def fan_disk(points):
    """A disk mesh: centre vertex plus a fan (the polygon is star-shaped about its centroid)."""
    c = np.mean(np.array(points), axis=0)
    n = len(points)
    return list(points) + [tuple(c)], [(i, (i + 1) % n, n) for i in range(n)]


def tilt(points, angle):
    """Rotate about the x axis: a plane that is not a coordinate plane."""
    ca, sa = math.cos(angle), math.sin(angle)
    return [(x, ca * y - sa * z, sa * y + ca * z + 1.0) for x, y, z in points]


def twisted_solid(m=24, levels=12, height=1.2, twist=math.pi / 3):
    """A closed solid: an ellipse-like star section swept up and twisted, capped."""
    pts, faces = [], []
    for k in range(levels + 1):
        z = height * k / levels
        for p in star(m, 1.0, 0.8, z, twist * z / height, (1.0, 0.7)):
            pts.append(p)
    for k in range(levels):
        for i in range(m):
            a, b = k * m + i, k * m + (i + 1) % m
            faces += [(a, b, b + m), (a, b + m, a + m)]
    bottom, top = len(pts), len(pts) + 1
    pts += [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
    for i in range(m):
        faces.append((bottom, (i + 1) % m, i))
        faces.append((top, levels * m + i, levels * m + (i + 1) % m))
    return pts, faces


# ---- running meshlabserver ------------------------------------------------

def run(workdir, inputs, script, outputs):
    """outputs: {layer: filename}. Returns (exit code, log text)."""
    log = os.path.join(workdir, "log.txt")
    args = [WRAPPER, "-l", log, "-i"] + inputs + ["-s", script]
    for layer, name in outputs.items():
        args += ["-o", os.path.join(workdir, name), "-l", str(layer), "-m", "vq"]
    proc = subprocess.run(args, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          timeout=300)
    text = open(log).read() if os.path.exists(log) else ""
    return proc.returncode, text + proc.stdout.decode(errors="replace")


def script_with(workdir, name, replacements):
    text = open(os.path.join(DOCS, name)).read()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = os.path.join(workdir, "script.mlx")
    open(path, "w").write(text)
    return path


# ---- checks ---------------------------------------------------------------

def exact_cross_dot(a, b, c, normal):
    """Sign of ((b - a) x (c - a)) . normal, exactly (floats are rationals)."""
    A, B, C = ([Fraction(float(v)) for v in p] for p in (a, b, c))
    N = [Fraction(float(v)) for v in normal]
    u = [B[i] - A[i] for i in range(3)]
    v = [C[i] - A[i] for i in range(3)]
    w = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    s = sum(w[i] * N[i] for i in range(3))
    return (s > 0) - (s < 0)


def boundary_loop(triangles):
    """The boundary edges (used by one triangle) chained into loops."""
    count = {}
    for t in triangles:
        for i in range(3):
            a, b = int(t[i]), int(t[(i + 1) % 3])
            count[(a, b)] = count.get((a, b), 0) + 1
    boundary = [(a, b) for (a, b) in count if (b, a) not in count]
    assert all(count[e] == 1 for e in count), "an edge is used twice in one direction"
    nxt = dict(boundary)
    assert len(nxt) == len(boundary), "boundary vertex with two outgoing edges"
    start = boundary[0][0]
    loop, v = [start], nxt[start]
    while v != start:
        loop.append(v)
        v = nxt[v]
    assert len(loop) == len(boundary), "the boundary has %d loops" % (1 + len(boundary) - len(loop))
    return loop


def newell_normal(points):
    n = np.zeros(3)
    for i in range(len(points)):
        p, q = points[i], points[(i + 1) % len(points)]
        n += np.cross(p, q)
    return n


def on_polyline(p, poly, tol):
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        d = b - a
        t = np.clip(np.dot(p - a, d) / np.dot(d, d), 0, 1)
        if np.linalg.norm(a + t * d - p) <= tol:
            return True
    return False


def check_layer(path, input_points, min_angle_bound=None):
    """A saved output layer: one boundary loop equal to the input polygon
    (every input vertex present bit for bit as float, every other boundary
    vertex on it), every triangle strictly positive about the boundary's
    normal (exact), Steiner flags (quality 1) exactly on interior vertices.
    Returns (points, triangles, quality)."""
    mesh = meshio.read(path)
    pts = mesh.points.astype(np.float64)
    tris = mesh.cells_dict["triangle"]
    q = mesh.point_data.get("quality")
    loop = boundary_loop(tris)
    inp = np.array(input_points, dtype=np.float32).astype(np.float64)
    have = {tuple(p) for p in pts[loop]}
    missing = [i for i, p in enumerate(inp) if tuple(p) not in have]
    assert not missing, "%s: input vertices %s are not on the boundary" % (path, missing[:5])
    tol = 1e-5 * np.linalg.norm(inp.max(0) - inp.min(0))
    for v in loop:
        assert on_polyline(pts[v], inp, tol), "%s: boundary vertex %d is off the input" % (path, v)
    normal = newell_normal(pts[loop])
    if np.dot(newell_normal(pts[loop]), normal) < 0:
        normal = -normal
    signs = [exact_cross_dot(pts[a], pts[b], pts[c], normal) for a, b, c in tris]
    # Boundary loops chain against the faces (half-edges of boundary edges
    # run the other way round), so the positive side is -normal if the
    # loop turns clockwise about it: all triangles must share one sign.
    assert all(s == signs[0] for s in signs) and signs[0] != 0, \
        "%s: %d triangles are flat or inverted" % (path, sum(1 for s in signs if s != signs[0]))
    interior = set(range(len(pts))) - set(loop)
    assert q is not None and {i for i in range(len(pts)) if q[i] == 1.0} == interior, \
        "%s: Steiner flags wrong" % path
    if min_angle_bound is not None:
        worst = min(min_angle(pts[t]) for t in tris)
        assert worst >= min_angle_bound, "%s: smallest angle %.2f < %.2f" % (path, worst, min_angle_bound)
    return pts, tris, q


def min_angle(tri):
    angles = []
    for i in range(3):
        a, b, c = tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]
        u, v = b - a, c - a
        angles.append(math.degrees(math.acos(np.clip(np.dot(u, v) / np.linalg.norm(u) / np.linalg.norm(v), -1, 1))))
    return min(angles)


def check_pair(workdir, out_a, out_b, in_a, in_b, min_angle_bound):
    pa, ta, _ = check_layer(os.path.join(workdir, out_a), in_a, min_angle_bound)
    pb, tb, _ = check_layer(os.path.join(workdir, out_b), in_b, min_angle_bound)
    assert len(pa) == len(pb) and np.array_equal(ta, tb), "the two layers' faces differ"
    return pa, pb, ta


def check_log_numbers(log, pa, pb, triangles):
    """The filter's log gives the Steiner count, the smallest angle of each
    layer and the certified ceiling with its correspondence bound, in
    agreement with the saved layers."""
    m = re.search(r"compatible triangulation: (\d+) boundary vertices, (\d+) Steiner vertices "
                  r"\(vertex quality 1\), (\d+) triangles", log)
    assert m, log
    boundary = len(boundary_loop(triangles))
    assert (int(m.group(1)), int(m.group(2)), int(m.group(3))) == (boundary, len(pa) - boundary, len(triangles))
    m = re.search(r"smallest angle: ([\d.]+) deg in '[^']*', ([\d.]+) deg in '[^']*'", log)
    assert m, log
    for logged, pts in zip(m.groups(), (pa, pb)):  # the layers are float: 0.01 degrees apart at most
        assert abs(float(logged) - min(min_angle(pts[t]) for t in triangles)) < 0.02, (logged, log)
    m = re.search(r"no compatible triangulation of this pair can have a smallest angle above ([\d.]+) "
                  r"degrees \(corner fan ([\d.]+), correspondence bound ([\d.]+)", log)
    assert m, log
    ceiling, fan, bound = map(float, m.groups())
    # the ceiling bounds the pair's smallest angle, the lower of the layers'
    # (one layer alone may stand above it)
    assert ceiling == min(fan, bound) and ceiling >= min(float(x) for x in
                                                          re.findall(r"([\d.]+) deg in", log)), log


def expect_ok(code, log):
    assert code == 0 and "Problem with filter" not in log, "meshlabserver failed:\n" + log[-3000:]


def expect_error(code, log, message, workdir, outputs):
    assert code != 0 or "Problem with filter" in log, "the filter did not fail:\n" + log[-2000:]
    assert "Error: " in log and message in log, "message %r not in the log:\n%s" % (message, log[-2000:])
    for name in outputs:
        assert not os.path.exists(os.path.join(workdir, name)), "output %s was written" % name


# ---- cases ------------------------------------------------------------------

def star_polylines(w):
    """Closed polylines (PLY edge elements) of 16 and 22 vertices in
    parallel planes, written to a.ply and b.ply; returns their points."""
    a = star(16, 1.0, 0.6)
    b = [(x + 0.3, y, 1.5) for x, y, _ in star(22, 1.2, 0.9, phase=0.2, scale=(1.0, 0.6))]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(len(a)))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(len(b)))
    return a, b


def case_ply_polylines(w):
    # The star polylines: the default correspondence (auto) pairs them by arc
    # length, every input vertex kept; the conformal correspondence allows
    # the higher ceiling and is the one kept (the log says which).
    a, b = star_polylines(w)
    code, log = run(w, ["a.ply", "b.ply"], os.path.join(DOCS, "pair.mlx"), {2: "out_a.ply", 3: "out_b.ply"})
    expect_ok(code, log)
    assert "correspondence: auto, made: conformal (16 and 22 input vertices" in log, log
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", a, b, 10.0)
    check_log_numbers(log, pa, pb, ta)
    print("PLY polylines: %d vertices, %d triangles" % (len(pa), len(ta)))


def case_max_edge(w):
    # MaxEdge splits the boundary compatibly: no boundary edge longer than
    # it in either layer, every input vertex kept, the added points on the
    # input polylines.
    a, b = star_polylines(w)
    script = script_with(w, "pair.mlx", [('value="0" name="MaxEdge"', 'value="0.15" name="MaxEdge"')])
    code, log = run(w, ["a.ply", "b.ply"], script, {2: "out_a.ply", 3: "out_b.ply"})
    expect_ok(code, log)
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", a, b, 10.0)
    loop = boundary_loop(ta)
    for p in (pa, pb):
        longest = max(np.linalg.norm(p[loop[i]] - p[loop[i - 1]]) for i in range(len(loop)))
        assert longest <= 0.15 * (1 + 1e-6), "a boundary edge of %.4f" % longest
    assert len(loop) > 16 + 22, len(loop)
    print("MaxEdge 0.15: %d boundary vertices, longest boundary edge within the bound" % len(loop))


def case_time_limit(w):
    # TimeLimit spent before remeshing starts: the filter still writes a
    # valid pair (the construction, cleaned), and the log says the limit
    # was reached.
    a, b = star_polylines(w)
    script = script_with(w, "pair.mlx", [('value="0" name="TimeLimit"', 'value="1e-06" name="TimeLimit"')])
    code, log = run(w, ["a.ply", "b.ply"], script, {2: "out_a.ply", 3: "out_b.ply"})
    expect_ok(code, log)
    assert "s reached: remeshing stopped early" in log, log
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", a, b, 0.0)
    print("TimeLimit 1e-6: %d vertices, %d triangles, the limit logged" % (len(pa), len(ta)))


def case_obj_polylines(w):
    # OBJ polylines with 18 and 15 vertices, the second in a tilted plane
    # and stored clockwise (the core walks it the other way round), paired by
    # arc length with its 4th vertex pinned to the first's vertex 0.
    a = star(18, 1.0, 0.7)
    b = tilt([(x, y, 0.0) for x, y, _ in star(15, 1.1, 0.8, phase=0.3)], 0.5)[::-1]
    write_obj_polyline(os.path.join(w, "a.obj"), a)
    write_obj_polyline(os.path.join(w, "b.obj"), b)
    script = script_with(w, "pair.mlx", [('value="2" name="Correspondence"', 'value="1" name="Correspondence"'), ('value="" name="Pins"', 'value="0,3" name="Pins"')])
    code, log = run(w, ["a.obj", "b.obj"], script, {2: "out_a.ply", 3: "out_b.ply"})
    expect_ok(code, log)
    assert "correspondence: arc length, made: arclength (18 and 15 input vertices" in log, log
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", a, b, 10.0)
    # Vertex 0 of the first is paired with vertex 3 of the second.
    a32 = np.array(a, dtype=np.float32).astype(np.float64)
    b32 = np.array(b, dtype=np.float32).astype(np.float64)
    i0 = [i for i in range(len(pa)) if np.array_equal(pa[i], a32[0])][0]
    assert np.array_equal(pb[i0], b32[3]), "the pin is not honoured"
    print("OBJ polylines: %d vertices, %d triangles" % (len(pa), len(ta)))


def case_off_disks(w):
    # Disk meshes (OFF faces), equal counts; the second lies in a tilted
    # plane and is paired from its 3rd vertex on. (Not OBJ: Debian's meshlab
    # 2020.09 aborts on reading any OBJ with faces, Debian bug #1054006, and
    # writes OBJ coordinates with 6 decimals.) Pinned by index: vertex 0
    # with vertex 2.
    a, fa = fan_disk(star(14, 1.0, 0.55))
    b, fb = fan_disk(tilt(star(14, 0.9, 0.6, phase=0.1, scale=(1.3, 0.8)), 0.6))
    write_off(os.path.join(w, "a.off"), a, fa)
    write_off(os.path.join(w, "b.off"), b, fb)
    script = script_with(w, "pair.mlx", [('value="2" name="Correspondence"', 'value="1" name="Correspondence"'), ('value="" name="Pins"', 'value="0,2" name="Pins"')])
    code, log = run(w, ["a.off", "b.off"], script, {2: "out_a.ply", 3: "out_b.ply"})
    expect_ok(code, log)
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", a[:-1], b[:-1], 10.0)
    # The pin pairs vertex 0 of the first with vertex 2 of the second.
    b32 = np.array(b, dtype=np.float32).astype(np.float64)
    a32 = np.array(a, dtype=np.float32).astype(np.float64)
    i0 = [i for i in range(len(pa)) if np.array_equal(pa[i], a32[0])][0]
    assert np.array_equal(pb[i0], b32[2]), "the pin is not honoured"
    print("OFF disks: %d vertices, %d triangles" % (len(pa), len(ta)))


def case_sweep(w):
    a = star(12, 1.0, 0.7)
    b = [(x, y, 2.0) for x, y, _ in star(12, 0.8, 0.5, phase=0.5, scale=(1.4, 0.7))]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(len(a)))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(len(b)))
    outs = {2: "pair_a.ply", 3: "pair_b.ply", 4: "s1.ply", 5: "s2.ply", 6: "s3.ply", 7: "lateral.ply"}
    code, log = run(w, ["a.ply", "b.ply"], os.path.join(DOCS, "pair_and_sweep.mlx"), outs)
    expect_ok(code, log)
    # The similarity fit pairs the stars corner to corner: a higher ceiling
    # than the conformal pairing, so auto keeps it.
    assert "correspondence: auto, made: similarity (12 and 12 input vertices" in log, log[-2000:]
    pa, pb, ta = check_pair(w, "pair_a.ply", "pair_b.ply", a, b, 10.0)
    worst = check_sections(w, ta, 0.0, 2.0, 3)
    assert "intermediate sections by convex-combination morph" in log, log[-2000:]
    # Measured 32.8 degrees (intrinsic weights; 32.4 with mean value weights).
    assert worst >= 28.0, "smallest section angle %.2f" % worst
    lateral = meshio.read(os.path.join(w, "lateral.ply"))
    assert len(lateral.cells_dict["triangle"]) == 2 * 12 * 4, len(lateral.cells_dict["triangle"])
    assert lateral_flux(os.path.join(w, "lateral.ply")) > 0, "lateral surface faces inward"
    print("sweep: 3 sections valid, smallest angle %.2f, lateral surface of %d triangles"
          % (worst, len(lateral.cells_dict["triangle"])))


def lateral_flux(path):
    """Flux of the horizontal field (x, y) through the lateral surface:
    twice the swept volume when its triangles face outward (the caps, flat
    and horizontal, carry none), minus that when they face inward."""
    mesh = meshio.read(path)
    p = mesh.points[mesh.cells_dict["triangle"]]
    normal = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    centroid = p.mean(axis=1)
    return float(np.sum(normal[:, :2] * centroid[:, :2]))


def case_sweep_reversed_layers(w):
    # The upper layer first: the sections run downwards, and the lateral
    # surface still faces outward.
    a = star(12, 1.0, 0.7)
    b = [(x, y, 2.0) for x, y, _ in star(12, 0.8, 0.5, phase=0.5, scale=(1.4, 0.7))]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(len(a)))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(len(b)))
    script = script_with(w, "pair_and_sweep.mlx", [('value="2" name="FirstMesh"', 'value="3" name="FirstMesh"'),
                                                    ('value="3" name="SecondMesh"', 'value="2" name="SecondMesh"')])
    outs = {2: "pair_a.ply", 3: "pair_b.ply", 4: "s1.ply", 5: "s2.ply", 6: "s3.ply", 7: "lateral.ply"}
    code, log = run(w, ["a.ply", "b.ply"], script, outs)
    expect_ok(code, log)
    _, _, ta = check_pair(w, "pair_a.ply", "pair_b.ply", a, b, 10.0)
    check_sections(w, ta, 2.0, 0.0, 3)
    flux = lateral_flux(os.path.join(w, "lateral.ply"))
    assert flux > 0, "lateral surface faces inward (flux %g)" % flux
    print("reversed sweep: lateral flux %.4f (outward)" % flux)


def check_sections(w, ta, z0, z1, count):
    """Sections s1.ply ... of a sweep between parallel planes z0 and z1: the
    pair's faces, flat at the blended height (1 - t) z0 + t z1, valid (exact
    orientation, simple boundary loop, Steiner flags). Returns the smallest
    angle over all sections."""
    worst = 180.0
    for k in range(1, count + 1):
        t = k / (count + 1)
        mesh = meshio.read(os.path.join(w, "s%d.ply" % k))
        assert np.array_equal(mesh.cells_dict["triangle"], ta), "section %d: faces differ" % k
        assert np.allclose(mesh.points[:, 2], (1 - t) * z0 + t * z1, atol=1e-6), "section %d: not at t = %g" % (k, t)
        ring = [tuple(p) for p in mesh.points[boundary_loop(ta)]]
        pts, tris, _ = check_layer(os.path.join(w, "s%d.ply" % k), ring)  # Steiner flags carried over
        assert len(set(ring)) == len(ring), "section %d: boundary vertices coincide" % k
        assert not polygon_self_intersects(np.array(ring)[:, :2]), "section %d: boundary not simple" % k
        worst = min(worst, min(min_angle(pts[t]) for t in tris))
    return worst


def polygon_self_intersects(p):
    """Exact test (floats as rationals) of a closed 2D polyline's
    non-adjacent edges for any common point."""
    P = [(Fraction(float(x)), Fraction(float(y))) for x, y in p]
    n = len(P)

    def orient(a, b, c):
        d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (d > 0) - (d < 0)

    def on(a, b, c):
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1])

    for i in range(n):
        a, b = P[i], P[(i + 1) % n]
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            c, d = P[j], P[(j + 1) % n]
            o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
            if o1 != o2 and o3 != o4:
                return True
            if (o1 == 0 and on(a, b, c)) or (o2 == 0 and on(a, b, d)) or \
               (o3 == 0 and on(c, d, a)) or (o4 == 0 and on(c, d, b)):
                return True
    return False


def case_planar_sections(w):
    # The real workflow: a closed solid, two sections cut by MeshLab's own
    # Compute Planar Section (one tilted), paired by the plugin.
    pts, faces = twisted_solid()
    write_ply(os.path.join(w, "solid.ply"), pts, faces=faces)
    outs = {1: "sect_a.ply", 2: "sect_b.ply", 3: "out_a.ply", 4: "out_b.ply", 6: "mid.ply", 8: "lateral.ply"}
    code, log = run(w, ["solid.ply"], os.path.join(DOCS, "sections_and_pair.mlx"), outs)
    expect_ok(code, log)
    sections = []
    for name in ("sect_a.ply", "sect_b.ply"):
        # MeshLab's PLY writer drops the section's edges; the solid's
        # sections are star-shaped about the z axis, so the angle orders them.
        pts = meshio.read(os.path.join(w, name)).points
        order = np.argsort(np.arctan2(pts[:, 1], pts[:, 0]))
        sections.append([tuple(p) for p in pts[order]])
    assert len(sections[0]) != len(sections[1]), "the sections happen to have equal counts"
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", sections[0], sections[1], 10.0)
    # The sweep between the two (non-parallel) sections: the middle one is
    # planar (an affine image of the morph's 2D section) and a valid disk.
    mid = meshio.read(os.path.join(w, "mid.ply"))
    assert np.array_equal(mid.cells_dict["triangle"], ta)
    centred = mid.points - mid.points.mean(0)
    flatness = np.linalg.svd(centred, compute_uv=False)
    assert flatness[2] <= 1e-5 * flatness[0], "the middle section is not planar: %s" % flatness
    check_layer(os.path.join(w, "mid.ply"), [tuple(p) for p in mid.points[boundary_loop(ta)]])
    n_lateral = len(meshio.read(os.path.join(w, "lateral.ply")).cells_dict["triangle"])
    assert n_lateral == 2 * len(boundary_loop(ta)) * 4, n_lateral
    print("planar sections of %d and %d vertices paired: %d vertices, %d triangles; swept"
          % (len(sections[0]), len(sections[1]), len(pa), len(ta)))


GMSH_DEMOS = "/usr/share/doc/gmsh-doc/doc/gmsh/demos/api"  # Debian package gmsh-doc

SECTION = """ <filter name="Compute Planar Section">
  <Param type="RichEnum" value="2" name="planeAxis" enum_val0="X Axis" enum_val1="Y Axis" enum_val2="Z Axis" enum_val3="Custom Axis" enum_cardinality="4"/>
  <Param type="RichPoint3f" x="0" y="0" z="1" name="customAxis"/>
  <Param type="RichFloat" value="%r" name="planeOffset"/>
  <Param type="RichEnum" value="2" name="relativeTo" enum_val0="Bounding box center" enum_val1="Bounding box min" enum_val2="Origin" enum_cardinality="3"/>
  <Param type="RichBool" value="false" name="createSectionSurface"/>
  <Param type="RichBool" value="false" name="splitSurfaceWithSection"/>
 </filter>
"""


def read_obj_loop(path):
    """The closed polyline of an OBJ file of `l a b` lines (MeshLab's
    section output: undirected edges in no particular order), in loop order."""
    loops = read_obj_loops(path)
    assert len(loops) == 1, "%s: several loops" % path
    return loops[0]


def case_gmsh_sections(w):
    # Two different real models from gmsh-doc, each cut at two heights by
    # MeshLab's Compute Planar Section (one closed loop each), then paired
    # by the unchanged docs/meshlab/pair.mlx: the filter's defaults
    # (correspondence auto) must do for both, with no start or direction
    # chosen by hand.
    import gzip
    for model, heights in (("object", (-4.9, 2.2)), ("aneurysm_data", (27.0, 29.9))):
        d = os.path.join(w, model)
        os.mkdir(d)
        stl = os.path.join(d, model + ".stl")
        with gzip.open(os.path.join(GMSH_DEMOS, model + ".stl.gz")) as f:
            open(stl, "wb").write(f.read())
        cut = os.path.join(d, "cut.mlx")
        open(cut, "w").write("<!DOCTYPE FilterScript>\n<FilterScript>\n" + SECTION % heights[0] +
                             ' <filter name="Change the current layer">\n  <Param type="RichMesh" value="0" name="layer"/>\n </filter>\n' +
                             SECTION % heights[1] + "</FilterScript>\n")
        code, log = run(d, [stl], cut, {1: "a.obj", 2: "b.obj"})
        expect_ok(code, log)
        sections = [read_obj_loop(os.path.join(d, name)) for name in ("a.obj", "b.obj")]
        for r in ("pa.ply", "pb.ply", "log.txt"):
            if os.path.exists(os.path.join(d, r)):
                os.remove(os.path.join(d, r))
        code, log = run(d, ["a.obj", "b.obj"], os.path.join(DOCS, "pair.mlx"), {2: "pa.ply", 3: "pb.ply"})
        expect_ok(code, log)
        assert re.search(r"correspondence: auto, made: (conformal|similarity|affine) \(%d and %d input vertices"
                         % tuple(map(len, sections)), log), log[-2000:]
        pa, _, ta = check_pair(d, "pa.ply", "pb.ply", sections[0], sections[1], 10.0)
        # The command line reads the same OBJ sections (one `l a b` line per edge).
        cli = subprocess.run([os.path.join(os.path.dirname(WRAPPER), "compatmesh"), "triangulate", "a.obj",
                              "b.obj", "-o", "cli"], cwd=d, capture_output=True, text=True, timeout=300)
        assert cli.returncode == 0, cli.stderr
        report = json.load(open(os.path.join(d, "cli", "report.json")))
        assert report["correspondence"] == "auto" and report["n"] >= max(map(len, sections)), report["n"]
        print("%s: sections of %d and %d vertices at z = %g and %g paired: %d vertices, %d triangles; "
              "the command line: smallest angles %s" % (model, len(sections[0]), len(sections[1]), heights[0],
                                                        heights[1], len(pa), len(ta),
                                                        [round(m["min_angle_deg"], 1) for m in report["meshes"]]))


def boundary_loops(triangles):
    """The boundary edges (used by one triangle) chained into loops, each
    following the triangles."""
    count = {}
    for t in triangles:
        for i in range(3):
            e = (int(t[i]), int(t[(i + 1) % 3]))
            count[e] = count.get(e, 0) + 1
    assert all(c == 1 for c in count.values()), "an edge is used twice in one direction"
    nxt = {a: b for (a, b) in count if (b, a) not in count}
    loops, left = [], set(nxt)
    while left:
        start = min(left)
        loop, v = [start], nxt[start]
        while v != start:
            loop.append(v)
            v = nxt[v]
        left -= set(loop)
        loops.append(loop)
    return loops


def check_layer_with_holes(path, input_loops):
    """A saved layer of a polygon with holes: every input vertex on the
    boundary (bit for bit as float), one boundary loop per input loop,
    every triangle strictly counter-clockwise about the outer loop's normal
    (exact), Euler characteristic 1 - holes, Steiner flags exactly on the
    interior vertices. Returns (points, triangles, boundary loops)."""
    mesh = meshio.read(path)
    pts = mesh.points.astype(np.float64)
    tris = mesh.cells_dict["triangle"]
    q = mesh.point_data.get("quality")
    loops = boundary_loops(tris)
    holes = len(input_loops) - 1
    assert len(loops) == len(input_loops), "%s: %d boundary loops, expected %d" % (path, len(loops), len(input_loops))
    on_boundary = {tuple(pts[v]) for loop in loops for v in loop}
    for inp in input_loops:
        inp32 = np.array(inp, dtype=np.float32).astype(np.float64)
        missing = [i for i, p in enumerate(inp32) if tuple(p) not in on_boundary]
        assert not missing, "%s: input vertices %s are not on the boundary" % (path, missing[:5])
    edges = {frozenset((int(t[i]), int(t[(i + 1) % 3]))) for t in tris for i in range(3)}
    euler = len(pts) - len(edges) + len(tris)
    assert euler == 1 - holes, "%s: Euler characteristic %d, expected %d" % (path, euler, 1 - holes)
    outer = max(loops, key=lambda l: np.linalg.norm(newell_normal(pts[l])))
    normal = newell_normal(pts[outer])  # the outer loop follows the triangles
    signs = [exact_cross_dot(pts[a], pts[b], pts[c], normal) for a, b, c in tris]
    assert all(s > 0 for s in signs), "%s: %d triangles are flat or inverted" % (path, sum(1 for s in signs if s <= 0))
    interior = set(range(len(pts))) - {v for loop in loops for v in loop}
    assert q is not None and {i for i in range(len(pts)) if q[i] == 1.0} == interior, "%s: Steiner flags wrong" % path
    return pts, tris, loops


def read_obj_loops(path):
    """The closed polylines of an OBJ file of `l a b` lines (MeshLab's
    section output), each in loop order, the loop of largest area first."""
    points, neighbours = [], {}
    for line in open(path):
        t = line.split()
        if t and t[0] == "v":
            points.append(tuple(float(x) for x in t[1:4]))
        elif t and t[0] == "l":
            a, b = int(t[1]) - 1, int(t[2]) - 1
            neighbours.setdefault(a, []).append(b)
            neighbours.setdefault(b, []).append(a)
    assert len(neighbours) == len(points) and all(len(v) == 2 for v in neighbours.values()), \
        "%s: not closed polylines" % path
    loops, left = [], set(neighbours)
    while left:
        loop, prev = [min(left)], None
        while True:
            nxt = [v for v in neighbours[loop[-1]] if v != prev][0]
            if nxt == loop[0]:
                break
            prev = loop[-1]
            loop.append(nxt)
        left -= set(loop)
        loops.append([points[i] for i in loop])
    loops.sort(key=lambda l: -np.linalg.norm(newell_normal(np.array(l))))
    return loops


LEVER = "/usr/share/doc/gmsh-doc/converters/stl_to_cartesian/lever.stl.gz"  # Debian package gmsh-doc


def cut_lever(w):
    """gmsh-doc's lever.stl cut by MeshLab's Compute Planar Section across
    the base plate at z = 2 and by a tilted plane (normal (0.02, 0, 1))
    through z = 4, saved as a.obj and b.obj; returns their loops (6 each:
    the plate's outline and its 5 bolt holes)."""
    import gzip
    stl = os.path.join(w, "lever.stl")
    with gzip.open(LEVER) as f:
        open(stl, "wb").write(f.read())
    tilted = SECTION.replace('value="2" name="planeAxis"', 'value="3" name="planeAxis"') \
                    .replace('x="0" y="0" z="1" name="customAxis"', 'x="0.02" y="0" z="1" name="customAxis"')
    cut = os.path.join(w, "cut.mlx")
    open(cut, "w").write("<!DOCTYPE FilterScript>\n<FilterScript>\n" + SECTION % 2.0 +
                         ' <filter name="Change the current layer">\n  <Param type="RichMesh" value="0" name="layer"/>\n </filter>\n' +
                         tilted % 4.0 + "</FilterScript>\n")
    code, log = run(w, [stl], cut, {1: "a.obj", 2: "b.obj"})
    expect_ok(code, log)
    sections = [read_obj_loops(os.path.join(w, name)) for name in ("a.obj", "b.obj")]
    for loops in sections:
        assert len(loops) == 6, "a section has %d loops, expected the outline and 5 holes" % len(loops)
    os.remove(os.path.join(w, "log.txt"))
    return sections


def case_lever_sections(w):
    # gmsh-doc's lever.stl, a bracket whose base plate has five bolt holes,
    # cut by MeshLab's Compute Planar Section across the plate at z = 2 and
    # by a tilted plane (normal (0.02, 0, 1)) through z = 4: each section is
    # 6 closed polylines, the plate's outline and its 5 holes. The unchanged
    # docs/meshlab/pair.mlx pairs them (auto correspondence, loop by loop),
    # then pair_and_sweep.mlx sweeps the pair: every section keeps the 5
    # holes and the lateral surface has a ring per loop facing away from
    # the material (into each hole).
    sections = cut_lever(w)
    code, log = run(w, ["a.obj", "b.obj"], os.path.join(DOCS, "pair.mlx"), {2: "pa.ply", 3: "pb.ply"})
    expect_ok(code, log)
    assert "the outer loop and 5 holes" in log, log[-2000:]
    pa, ta, _ = check_layer_with_holes(os.path.join(w, "pa.ply"), sections[0])
    pb, tb, _ = check_layer_with_holes(os.path.join(w, "pb.ply"), sections[1])
    assert len(pa) == len(pb) and np.array_equal(ta, tb), "the two layers' faces differ"
    m = re.search(r"compatible triangulation: (\d+) boundary vertices, (\d+) Steiner vertices", log)
    angles = re.search(r"smallest angle: ([\d.]+) deg in '[^']*', ([\d.]+) deg", log)
    assert m and angles, log[-2000:]
    print("lever sections of %d and %d vertices (6 loops each) paired: %s boundary, %s Steiner vertices, "
          "%d triangles, smallest angles %s and %s" % (sum(map(len, sections[0])), sum(map(len, sections[1])),
                                                      m.group(1), m.group(2), len(ta), *angles.groups()))

    # The sweep: three sections, each with the pair's faces and holes, and
    # the lateral surface.
    os.remove(os.path.join(w, "log.txt"))
    outs = {2: "pair_a.ply", 3: "pair_b.ply", 4: "s1.ply", 5: "s2.ply", 6: "s3.ply", 7: "lateral.ply"}
    code, log = run(w, ["a.obj", "b.obj"], os.path.join(DOCS, "pair_and_sweep.mlx"), outs)
    expect_ok(code, log)
    assert "in 6 rings" in log, log[-2000:]
    n = None
    for k in (1, 2, 3):
        mesh = meshio.read(os.path.join(w, "s%d.ply" % k))
        assert np.array_equal(mesh.cells_dict["triangle"], ta), "section %d: faces differ" % k
        loops = boundary_loops(ta)
        pts, _, _ = check_layer_with_holes(os.path.join(w, "s%d.ply" % k),
                                           [[tuple(mesh.points[v]) for v in l] for l in loops])
        for l in loops:
            assert not polygon_self_intersects(pts[l][:, :2]), "section %d: a loop is not simple" % k
        n = sum(map(len, loops))
    lateral = meshio.read(os.path.join(w, "lateral.ply"))
    lt = lateral.cells_dict["triangle"]
    assert len(lt) == 2 * n * 4, (len(lt), n)
    # Rings: the lateral surface's parts. Each faces away from the material:
    # the outline's ring outward (positive flux of the horizontal field from
    # its centre), every hole's ring into the hole (negative flux).
    p = lateral.points
    parent = list(range(len(p)))

    def find(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v
    for a, b, c in lt:
        parent[find(b)] = find(a)
        parent[find(c)] = find(a)
    rings = {}
    for t in lt:
        rings.setdefault(find(int(t[0])), []).append(t)
    assert len(rings) == 6, "%d rings" % len(rings)
    signs = []
    for ring in rings.values():
        q = p[np.array(ring)]
        centre = q.reshape(-1, 3).mean(0)
        normal = 0.5 * np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0])
        flux = float(np.sum(normal[:, :2] * (q.mean(1)[:, :2] - centre[:2])))
        area = float(np.sum(np.linalg.norm(normal, axis=1)))
        signs.append((area, flux))
    signs.sort(reverse=True)  # the outline's ring is the largest
    assert signs[0][1] > 0 and all(f < 0 for _, f in signs[1:]), signs
    print("lever sweep: 3 sections with 5 holes each valid, lateral surface of %d triangles in 6 rings, "
          "the outline's facing out and the 5 holes' facing into the holes" % len(lt))


def case_lever_cli(w):
    # The lever's two sections as MeshLab saves them (cut_lever: one across
    # the plate at z = 2, one in the tilted plane through z = 4) given to
    # the command line as they are: triangulate writes each mesh in its
    # section's plane, its own vertices as MeshLab wrote them; sweep lofts
    # between the planes, and Gmsh reads every tetrahedron positive, the
    # nodes of the first plane exactly on z = 2.
    import gmsh
    sections = cut_lever(w)
    tool = os.path.join(os.path.dirname(WRAPPER), "compatmesh")
    out = subprocess.run([tool, "triangulate", "a.obj", "b.obj", "-o", "pair", "--no-preview"], cwd=w,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    normal = np.array([0.02, 0, 1]) / np.linalg.norm([0.02, 0, 1])
    for name, loops in zip(("a", "b"), sections):
        points = meshio.read(os.path.join(w, "pair", name + ".off")).points
        given = {tuple(p) for loop in loops for p in loop}
        assert given <= {tuple(p) for p in points}, "%s: the section's own vertices are not all in its mesh" % name
        plane = normal if name == "b" else np.array([0, 0, 1.0])
        off = np.abs((points - points[0]) @ plane).max()
        assert off < 1e-4, "%s: a vertex %g off the section's plane" % (name, off)
    out = subprocess.run([tool, "sweep", "a.obj", "b.obj", "-o", "lever.msh", "--tets", "--sections", "auto"],
                         cwd=w, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(os.path.join(w, "lever.msh"))
        types, tags, _ = gmsh.model.mesh.getElements(3)
        _, dets, _ = gmsh.model.mesh.getJacobians(4, [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.25, 0.25, 0.25])
        _, coords, _ = gmsh.model.mesh.getNodes()
    finally:
        gmsh.finalize()
    dets, xyz = np.array(dets), np.array(coords).reshape(-1, 3)
    assert list(types) == [4] and len(dets) == 5 * len(tags[0]) and np.all(dets > 0), \
        "%d of %d Jacobians not positive" % (int(np.sum(dets <= 0)), len(dets))
    at_bottom = int(np.sum(xyz[:, 2] == 2.0))
    assert at_bottom >= sum(len(loop) for loop in sections[0]), at_bottom
    print("lever through the command line: meshes in their planes; loft of %d tetrahedra, all %d Jacobians "
          "positive (smallest %.3g), %d nodes on z = 2" % (len(tags[0]), len(dets), float(dets.min()), at_bottom))


def case_lever_volume(w):
    # The lever's two sections (cut_lever: one horizontal, one tilted)
    # paired by the unchanged pair.mlx and saved, as a user exports the
    # pair; then the saved pair swept by the sweep filter with its volume
    # file set. Gmsh reads the .msh and every tetrahedron's Jacobian is
    # positive at its corners and centre; its boundary is named surfaces
    # (bottom, top, side, hole_1 .. hole_5) that close around it outward; the volume's end faces are the
    # layers' faces (the first layer's plane z = 2 holds exactly one node per
    # layer vertex), and they fill the solid the layers and the lateral
    # surface bound.
    import gmsh
    sections = cut_lever(w)
    code, log = run(w, ["a.obj", "b.obj"], os.path.join(DOCS, "pair.mlx"), {2: "pa.ply", 3: "pb.ply"})
    expect_ok(code, log)
    pa, ta, _ = check_layer_with_holes(os.path.join(w, "pa.ply"), sections[0])
    check_layer_with_holes(os.path.join(w, "pb.ply"), sections[1])
    os.remove(os.path.join(w, "log.txt"))
    volume = os.path.join(w, "lever.msh")
    script = sweep_only_script(w, [('value="" name="VolumeFile"', 'value="%s" name="VolumeFile"' % volume)])
    code, log = run(w, ["pa.ply", "pb.ply"], script, {5: "lateral.ply"})
    expect_ok(code, log)
    m = re.search(r"volume: (\d+) tetrahedra, (\d+) nodes in (\d+) sections, each positive \(exact\), smallest "
                  r"dihedral angle ([0-9.]+) degrees", log)
    assert m and os.path.exists(volume), log[-2000:]
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(volume)
        types, tags, _ = gmsh.model.mesh.getElements(3)
        assert list(types) == [4] and len(tags[0]) == int(m.group(1)), (types, m.group(1))
        points = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.25, 0.25, 0.25]  # corners and centre
        _, dets, _ = gmsh.model.mesh.getJacobians(4, points)
        dets = np.array(dets)
        assert len(dets) == 5 * len(tags[0]) and np.all(dets > 0), "%d of %d Jacobians not positive" % (
            int(np.sum(dets <= 0)), len(dets))
        node_tags, coords, _ = gmsh.model.mesh.getNodes()
        xyz = np.array(coords).reshape(-1, 3)
        total = float(np.sum(dets[4::5])) / 6  # a linear tetrahedron's volume is det J / 6
        # The logged smallest dihedral angle is the tetrahedra's where they
        # are, between the two sections' planes (not in the plane and the
        # morph's time).
        _, _, tet_nodes = gmsh.model.mesh.getElements(3)
        where = dict(zip(node_tags, xyz))
        t = np.array([where[n] for n in tet_nodes[0]]).reshape(-1, 4, 3)
        smallest = 180.0
        for i, j, k, l in ((0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)):
            e = t[:, j] - t[:, i]
            u, v = t[:, k] - t[:, i], t[:, l] - t[:, i]
            u = u - e * (np.einsum("ij,ij->i", u, e) / np.einsum("ij,ij->i", e, e))[:, None]
            v = v - e * (np.einsum("ij,ij->i", v, e) / np.einsum("ij,ij->i", e, e))[:, None]
            c = np.einsum("ij,ij->i", u, v) / np.linalg.norm(u, axis=1) / np.linalg.norm(v, axis=1)
            smallest = min(smallest, float(np.degrees(np.arccos(np.clip(c, -1, 1))).min()))
        assert abs(float(m.group(4)) - smallest) <= 0.006, (m.group(4), smallest)
        # The boundary as named surfaces: the two layers, the outline's wall
        # and one wall per bolt hole, closing outward around the tetrahedra
        # (the flux of x / 3 through them is their volume).
        position = dict(zip(node_tags, xyz))
        groups = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
        assert sorted(groups) == sorted(["sweep", "bottom", "top", "side"] + ["hole_%d" % j for j in range(1, 6)]), groups
        flux, caps = 0.0, {}
        for name, (d, t) in groups.items():
            if d != 2:
                continue
            (entity,) = gmsh.model.getEntitiesForPhysicalGroup(d, t)
            face_types, _, face_nodes = gmsh.model.mesh.getElements(2, entity)
            assert list(face_types) == [2], (name, face_types)
            p = np.array([position[n] for n in face_nodes[0]]).reshape(-1, 3, 3)
            flux += float(np.sum(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])))) / 6
            caps[name] = len(p)
        assert abs(flux - total) < 1e-9 * total, (flux, total)
        assert caps["bottom"] == len(ta), (caps["bottom"], len(ta))
    finally:
        gmsh.finalize()
    assert len(node_tags) == int(m.group(2)), (len(node_tags), m.group(2))
    at_bottom = int(np.sum(np.abs(xyz[:, 2] - 2.0) < 1e-5))
    assert at_bottom == len(pa), "%d nodes on z = 2, the layer has %d vertices" % (at_bottom, len(pa))
    # The tetrahedra fill the solid the filter's own layers bound: the two
    # paired layers and the lateral surface (layer 5), whose enclosed
    # volume (divergence theorem; the lateral quads' other diagonal and the
    # layers' float rounding aside) is the tetrahedra's sum.
    def signed(mesh):
        p, t = mesh.points.astype(np.float64), mesh.cells_dict["triangle"]
        return float(np.sum(np.einsum("ij,ij->i", p[t[:, 0]], np.cross(p[t[:, 1]], p[t[:, 2]])))) / 6
    bounded = signed(meshio.read(os.path.join(w, "lateral.ply"))) + signed(meshio.read(os.path.join(w, "pb.ply"))) \
        - signed(meshio.read(os.path.join(w, "pa.ply")))
    assert abs(total - bounded) < 2e-3 * bounded, (total, bounded)
    print("lever volume: %s tetrahedra, %s nodes, %s sections; Gmsh: all %d Jacobians positive (corners and "
          "centres, smallest %.3g), volume %.6g (bounded by the layers and the lateral surface: %.6g); boundary "
          "groups %s" % (m.group(1), m.group(2), m.group(3), len(dets), float(dets.min()), total, bounded,
                         ", ".join("%s %d" % kv for kv in sorted(caps.items()))))


def bad_case(w, inputs, message, replacements=()):
    script = script_with(w, "pair.mlx", replacements) if replacements else os.path.join(DOCS, "pair.mlx")
    code, log = run(w, inputs, script, {2: "out_a.ply", 3: "out_b.ply"})
    expect_error(code, log, message, w, ["out_a.ply", "out_b.ply"])
    print("rejected with: " + [l for l in log.splitlines() if "Error: " in l][0])


def good_polyline(w, name="good.ply"):
    write_ply(os.path.join(w, name), star(10, 1.0, 0.6), edges=loop_edges(10))
    return name


def case_bad_open_polyline(w):
    pts = star(10, 1.0, 0.6)
    write_ply(os.path.join(w, "bad.ply"), pts, edges=loop_edges(10)[:-1])
    bad_case(w, [good_polyline(w), "bad.ply"], "layer 'bad.ply': the edges are not closed polylines: vertex 0 has one edge (an open end)")


def case_bad_two_loops(w):
    pts = star(8, 1.0, 0.6) + [(x + 5, y, z) for x, y, z in star(8, 1.0, 0.6)]
    write_ply(os.path.join(w, "bad.ply"), pts, edges=loop_edges(8) + loop_edges(8, 8))
    # Read as an outline with a hole beside it: the core refuses the hole.
    bad_case(w, ["bad.ply", "bad.ply"], "lies outside")


def case_bad_hole(w):
    outer, inner = star(8, 2.0, 2.0), star(8, 0.5, 0.5)
    faces = []
    for i in range(8):
        j = (i + 1) % 8
        faces += [(i, j, 8 + j), (i, 8 + j, 8 + i)]
    write_ply(os.path.join(w, "bad.ply"), outer + inner, faces=faces)
    # A disk with a hole against a polygon without: one line naming the
    # layer and both counts.
    bad_case(w, ["bad.ply", good_polyline(w)], "layer 'good.ply' has 1 boundary loop but layer 'bad.ply' has 2; need the same number")


def case_bad_not_planar(w):
    pts = [(x, y, 0.3 * (i % 2)) for i, (x, y, _) in enumerate(star(10, 1.0, 0.6))]
    write_ply(os.path.join(w, "bad.ply"), pts, edges=loop_edges(10))
    bad_case(w, [good_polyline(w), "bad.ply"], "not planar")


def case_bad_too_few(w):
    write_ply(os.path.join(w, "bad.ply"), [(0, 0, 0), (1, 0, 0)], edges=[(0, 1), (1, 0)])
    bad_case(w, [good_polyline(w), "bad.ply"], "vertices; need at least 3")


def case_bad_opposite_directions(w):
    # Only the index correspondence keeps the directions as given.
    write_ply(os.path.join(w, "cw.ply"), star(10, 1.2, 0.5)[::-1], edges=loop_edges(10))
    bad_case(w, [good_polyline(w), "cw.ply"], "(with Correspondence 'auto' the boundaries need not agree)",
             [('value="2" name="Correspondence"', 'value="0" name="Correspondence"')])


def case_bad_same_layer(w):
    bad_case(w, [good_polyline(w), good_polyline(w, "other.ply")], "the same layer",
             [('value="1" name="SecondMesh"', 'value="0" name="SecondMesh"')])


def case_bad_counts_by_index(w):
    write_ply(os.path.join(w, "b.ply"), star(12, 1.0, 0.6), edges=loop_edges(12))
    bad_case(w, [good_polyline(w), "b.ply"], "polygon 1 has 12 vertices but polygon 0 has 10", [('value="2" name="Correspondence"', 'value="0" name="Correspondence"')])


def case_bad_pins(w):
    # Each in its own directory: the log of one run must not answer for the next.
    cases = [("Pins: '0,x' is not a pair 'I,J' of vertex numbers", "0,x", "2"),
             ("Pins: '3,12': vertex 12 of layer 'b.ply' is not on its boundary", "0,0; 3,12", "2"),
             ("pins 1 and 2 cross", "0,0;4,6;6,2", "2"),
             ("Pins need the correspondence 'arc length' or 'auto'", "0,0", "0")]
    for k, (message, pins, mode) in enumerate(cases):
        d = os.path.join(w, str(k))
        os.mkdir(d)
        write_ply(os.path.join(d, "b.ply"), star(12, 1.0, 0.6), edges=loop_edges(12))
        bad_case(d, [good_polyline(d), "b.ply"], message,
                 [('value="2" name="Correspondence"', 'value="%s" name="Correspondence"' % mode),
                  ('value="" name="Pins"', 'value="%s" name="Pins"' % pins)])


def case_bad_float_rounding(w):
    # Spiky stars 10^7 away from the origin, where floats are 1 apart: the
    # core's triangulation (paired a quarter turn off, target angle 33) is
    # valid in double, but its Steiner vertices rounded to MeshLab's floats
    # are not, so the filter must refuse and add nothing.
    a = [(x + 1e7, y + 1e7, 0.0) for x, y, _ in star(24, 8, 2.4)]
    b = [(x + 1e7, y + 1e7, 1.0) for x, y, _ in star(24, 9.6, 4, phase=0.2)]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(24))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(24))
    bad_case(w, ["a.ply", "b.ply"], "valid in double precision but not after rounding to MeshLab's float",
             [('value="2" name="Correspondence"', 'value="1" name="Correspondence"'), ('value="" name="Pins"', 'value="0,5" name="Pins"'),
              ('value="25" name="MinAngle"', 'value="33" name="MinAngle"')])


def case_sweep_half_turn(w):
    # Regular 12-gons paired half a turn apart: the straight-line section at
    # t = 1/2 would collapse every boundary vertex onto the centre; the
    # convex-combination morph turns the polygon instead, every section valid.
    a = star(12, 1.0, 1.0)
    b = [(x, y, 1.0) for x, y, _ in a]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(12))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(12))
    script = script_with(w, "pair_and_sweep.mlx", [('value="2" name="Correspondence"', 'value="1" name="Correspondence"'), ('value="" name="Pins"', 'value="0,6" name="Pins"')])
    outs = {2: "pair_a.ply", 3: "pair_b.ply", 4: "s1.ply", 5: "s2.ply", 6: "s3.ply", 7: "lateral.ply"}
    code, log = run(w, ["a.ply", "b.ply"], script, outs)
    expect_ok(code, log)
    assert "compatible triangulation: 12 boundary vertices" in log, "the pairing step did not succeed"
    pa, pb, ta = check_pair(w, "pair_a.ply", "pair_b.ply", a, b, 10.0)
    loop = boundary_loop(ta)
    linear_mid = (pa[loop] + pb[loop]) / 2
    assert np.allclose(linear_mid[:, :2], 0, atol=1e-6), "the pair is not half a turn apart"
    worst = check_sections(w, ta, 0.0, 1.0, 3)
    # Measured 21.4 degrees (intrinsic weights; 4.7 with mean value
    # weights, whose stars shrink while they turn).
    assert worst >= 18.0, "smallest section angle %.2f" % worst
    print("half-turn sweep: 3 sections valid, smallest angle %.2f" % worst)


def case_bad_sweep_folded(w):
    # Two disks with the same faces, but the second's centre lies outside
    # its polygon: a fan triangle is inverted, so the layers are not a
    # compatible pair and the sweep must refuse (and add no layer).
    a, faces = fan_disk(star(10, 1.0, 0.6))
    b = list(a)
    b[-1] = (2.0, 0.0, 1.0)
    b[:-1] = [(x, y, 1.0) for x, y, _ in b[:-1]]
    write_off(os.path.join(w, "a.off"), a, faces)
    write_off(os.path.join(w, "b.off"), b, faces)
    code, log = run(w, ["a.off", "b.off"], sweep_only_script(w), {2: "s1.ply"})
    expect_error(code, log, "are not a compatible pair (layer 'b.off'): geometry 1: triangle", w, ["s1.ply"])
    print("rejected with: " + [l for l in log.splitlines() if "Error: " in l][0])


def case_bad_sweep_crossing_planes(w):
    # The second star on the plane z = 0.2 + 0.5 x, which crosses the first
    # layer's plane z = 0 inside the polygons: the straight blend between
    # the planes folds there. The sweep filter refuses it whether or not
    # it writes the volume (before, without VolumeFile, it added a lateral
    # surface with 40 of its 96 triangles inside out).
    a = star(12, 1.0, 0.8)
    b = [(x, y, 0.2 + 0.5 * x) for x, y, _ in star(12, 1.0, 0.8, phase=0.1)]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(12))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(12))
    outs = {2: "pair_a.ply", 3: "pair_b.ply", 4: "s1.ply", 7: "lateral.ply"}
    code, log = run(w, ["a.ply", "b.ply"], os.path.join(DOCS, "pair_and_sweep.mlx"), outs)
    assert "compatible triangulation: 12 boundary vertices" in log, "the pairing step did not succeed"
    assert code != 0 and "the swept volume between the layers: " in log and "folds there" in log, log[-3000:]
    assert "nothing was added or written" in log, log[-3000:]
    for name in ("s1.ply", "lateral.ply"):
        assert not os.path.exists(os.path.join(w, name)), name
    print("rejected with: " + [l for l in log.splitlines() if "Error: " in l][0])


def case_log_angle_of_float_layers(w):
    # A star around (-100, -20) at z = 40 whose first edge is 4e-5 long, a
    # few float units there: rounded to MeshLab's floats, the triangles at
    # that edge lose about a sixth of a degree, and the log gives the
    # angles of the layers as saved (before, the double result's: 7.96
    # against 7.82 degrees saved).
    a = [(x - 100, y - 20, 40.0) for x, y, _ in star(16, 8, 5.6)]
    a.insert(1, (-92.0000381, -19.9999847, 40.0))
    b = [(x - 100, y - 20, 0.0) for x, y, _ in star(20, 9, 6.75, phase=0.1)]
    write_ply(os.path.join(w, "a.ply"), a, edges=loop_edges(len(a)))
    write_ply(os.path.join(w, "b.ply"), b, edges=loop_edges(len(b)))
    code, log = run(w, ["a.ply", "b.ply"], os.path.join(DOCS, "pair.mlx"), {2: "out_a.ply", 3: "out_b.ply"})
    expect_ok(code, log)
    pa, pb, ta = check_pair(w, "out_a.ply", "out_b.ply", a, b, None)
    m = re.search(r"smallest angle: ([\d.]+) deg in '[^']*', ([\d.]+) deg in '[^']*'", log)
    saved = [min(min_angle(p[t]) for t in ta) for p in (pa, pb)]
    assert m and all(abs(float(x) - y) < 0.006 for x, y in zip(m.groups(), saved)), (m and m.groups(), saved)
    print("log angles %s, saved layers %.3f / %.3f" % (m.groups(), *saved))


def sweep_only_script(w, replacements=()):
    """pair_and_sweep.mlx without the pairing step, sweeping layers 0 and 1."""
    text = open(os.path.join(DOCS, "pair_and_sweep.mlx")).read()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new, 1)
    sweep_only = text[:text.index(" <filter name=\"Compatible Triangulation")] + \
        text[text.index(" <filter name=\"Compatible Sweep"):]
    sweep_only = sweep_only.replace('value="2" name="FirstMesh"', 'value="0" name="FirstMesh"') \
                           .replace('value="3" name="SecondMesh"', 'value="1" name="SecondMesh"')
    path = os.path.join(w, "sweep.mlx")
    open(path, "w").write(sweep_only)
    return path


def case_bad_sweep_not_a_pair(w):
    good_polyline(w, "a.ply")
    good_polyline(w, "b.ply")
    code, log = run(w, ["a.ply", "b.ply"], sweep_only_script(w), {2: "s1.ply"})
    expect_error(code, log, "both layers need faces", w, ["s1.ply"])
    print("rejected with: " + [l for l in log.splitlines() if "Error: " in l][0])


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as workdir:
        globals()["case_" + CASE](workdir)
