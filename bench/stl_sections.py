"""Planar sections of the STL models Gmsh ships (Debian package gmsh-doc)
as polygon pairs for remesh_bench.py: the outer loop of the section, resampled
by arc length from its bottom-left point, the rule of resample_arclength in
glyph_outline.h, so the pair corresponds by arc length like the glyph pairs.

    pair_names(ns)          the pair names, without reading anything
    write_pairs(dir, ns)    writes them: [(name, [a.xy, b.xy]), ...]
    write_resampled(dir, name, loops, ns)   any loops so, as name_n<n>
"""
import gzip
import os
import shutil
from fractions import Fraction

import meshio
import numpy as np

MODELS = "/usr/share/doc/gmsh-doc"
OBJECT = os.path.join(MODELS, "doc/gmsh/demos/api/object.stl.gz")
LEVER = os.path.join(MODELS, "converters/stl_to_cartesian/lever.stl.gz")
# (name, (model, axis, height), (model, axis, height)): the same model at two
# heights, as a user pairs two sections of one part, and two different parts.
PAIRS = [("object_z-6_z6", (OBJECT, 2, -6.0), (OBJECT, 2, 6.0)),
         ("object_x0_lever_z5", (OBJECT, 0, 0.0), (LEVER, 2, 5.0)),
         ("lever_z40_object_z0", (LEVER, 2, 40.0), (OBJECT, 2, 0.0))]


def read_stl(path, workdir):
    """Points and triangles of an STL file, gzipped (unpacked into workdir)
    or not (meshio reads it)."""
    plain = path
    if path.endswith(".gz"):
        plain = os.path.join(workdir, os.path.basename(path)[:-3])
        if not os.path.exists(plain):
            with gzip.open(path, "rb") as src, open(plain, "wb") as dst:
                shutil.copyfileobj(src, dst)
    mesh = meshio.read(plain)
    return mesh.points.astype(float), mesh.cells_dict["triangle"]


def section_loops(points, triangles, axis, height, closed_only=False):
    """The loops where the plane {x[axis] = height} cuts the surface, in the
    plane's other two coordinates. Each crossing mesh edge gives one point;
    the two points of a cut triangle are joined. closed_only: None unless
    every crossing edge joins exactly two cut triangles (the surface is
    closed and manifold along the cut, so every chain is a loop)."""
    side = points[:, axis] > height
    keep = [d for d in range(3) if d != axis]
    where, links = {}, {}
    for tri in triangles:
        cut = []
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            if side[a] != side[b]:
                key = (min(a, b), max(a, b))
                w = (height - points[a, axis]) / (points[b, axis] - points[a, axis])
                where[key] = (points[a] + w * (points[b] - points[a]))[keep]
                cut.append(key)
        if len(cut) == 2:
            links.setdefault(cut[0], []).append(cut[1])
            links.setdefault(cut[1], []).append(cut[0])
    if closed_only and (not links or any(len(v) != 2 for v in links.values())):
        return None
    loops, seen = [], set()
    for start in links:
        if start in seen:
            continue
        loop, prev, cur = [start], None, start
        seen.add(start)
        while True:
            nxt = [k for k in links[cur] if k != prev]
            if not nxt or nxt[0] in seen:
                break
            prev, cur = cur, nxt[0]
            seen.add(cur)
            loop.append(cur)
        loops.append(np.array([where[k] for k in loop]))
    return loops


def signed_area(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def outer_loop(loops):
    """The loop enclosing the most area, counter-clockwise."""
    loop = max(loops, key=lambda l: abs(signed_area(l)))
    return loop if signed_area(loop) > 0 else loop[::-1]


def bottom_left(xy):
    """The point nearest the bottom-left corner of the box, in box units."""
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    return int(np.argmin(((xy - lo) / (hi - lo)).sum(axis=1)))


def resample_arclength(loop, n):
    """n points at equal arc length along the closed loop from its
    bottom-left point."""
    loop = np.roll(loop, -bottom_left(loop), axis=0)
    closed = np.vstack([loop, loop[:1]])
    s = np.concatenate([[0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
    t = s[-1] * np.arange(n) / n
    return np.column_stack([np.interp(t, s, closed[:, 0]), np.interp(t, s, closed[:, 1])])


def _meet_exactly(p, q, r, s):
    """Segments pq and rs meet (touching counts), in exact arithmetic."""
    p, q, r, s = ([Fraction(float(c)) for c in point] for point in (p, q, r, s))

    def orient(a, b, c):
        d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (d > 0) - (d < 0)

    def within(a, b, c):  # c, on the line ab, lies on the segment ab
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1])
    o = orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q)
    if o[0] * o[1] < 0 and o[2] * o[3] < 0:
        return True
    return any(x == 0 and within(a, b, c) for x, (a, b, c) in zip(o, ((p, q, r), (p, q, s), (r, s, p), (r, s, q))))


def is_simple(xy):
    """No two non-adjacent edges meet, touching counting as meeting: every
    pair of edges whose boxes meet, in doubles with a margin for the
    rounding; the pairs that margin leaves in doubt (nearly collinear ones,
    as resampling a straight stretch makes) in exact arithmetic."""
    xy = np.asarray(xy, dtype=float)
    n = len(xy)
    p, q = xy, np.roll(xy, -1, axis=0)  # edge i runs from p[i] to q[i]

    def orient(a, b, c):  # the sign, 0 where the rounding could flip it
        u = (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1])
        v = (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])
        return np.where(np.abs(u - v) > 1e-12 * (np.abs(u) + np.abs(v)), np.sign(u - v), 0)
    for i in range(n):
        j = np.arange(i + 2, n - (i == 0))
        if not len(j):
            continue
        o1, o2 = orient(p[i], q[i], p[j]), orient(p[i], q[i], q[j])
        o3, o4 = orient(p[j], q[j], p[i]), orient(p[j], q[j], q[i])
        lo, hi = np.minimum(p[j], q[j]), np.maximum(p[j], q[j])
        near = np.all((np.maximum(lo, np.minimum(p[i], q[i])) <=
                       np.minimum(hi, np.maximum(p[i], q[i])) + 1e-12 * (1 + np.abs(hi))), axis=1)
        doubt = near & ~((o1 == o2) & (o1 != 0)) & ~((o3 == o4) & (o3 != 0))
        if any(_meet_exactly(p[i], q[i], p[k], q[k]) for k in j[doubt]):
            return False
    return True


def sized(name, n):
    """A pair's name at n points per loop."""
    return "%s_n%d" % (name, n)


# The section pairs' names: held out, as every real section
PREFIX = "hold_section_"


def pair_name(name, n):
    return sized(PREFIX + name, n)


def pair_names(ns):
    return [pair_name(name, n) for name, *_ in PAIRS for n in ns]


def write_resampled(directory, name, loops, ns, skip=None):
    """Writes the loops (one polygon each) resampled to every n as the pair
    named name_n<n> (files name_n<n>_a.xy, _b.xy, ...); returns (name,
    files) pairs. A loop that resamples to a polygon that is not simple is
    an error, or with skip (a function of the pair's name and the message)
    that pair at that n is left out and skip told."""
    os.makedirs(directory, exist_ok=True)
    out = []
    for n in ns:
        named, files = sized(name, n), []
        for g, loop in enumerate(loops):
            xy = resample_arclength(loop, n)
            if not is_simple(xy):
                message = "%s: polygon %d resampled to %d points is not simple" % (name, g, n)
                if skip is None:
                    raise RuntimeError(message)
                skip(named, message)
                break
            files.append(os.path.join(directory, "%s_%s.xy" % (named, "ab"[g])))
            np.savetxt(files[-1], xy, fmt="%.17g")
        else:
            out.append((named, files))
    return out


def write_pairs(directory, ns, skip=None):
    """Writes every section pair at every n (write_resampled); returns
    (name, files) pairs."""
    os.makedirs(directory, exist_ok=True)
    models, out = {}, []
    for name, *cuts in PAIRS:
        loops = []
        for model, axis, height in cuts:
            if model not in models:
                models[model] = read_stl(model, directory)
            loops.append(outer_loop(section_loops(*models[model], axis, height)))
        out += write_resampled(directory, PREFIX + name, loops, ns, skip)
    return out
