"""Planar sections of the STL models Gmsh ships (Debian package gmsh-doc)
as polygon pairs for remesh_bench.py: the outer loop of the section, resampled
by arc length from its bottom-left point, the rule of resample_arclength in
glyph_outline.h, so the pair corresponds by arc length like the glyph pairs.

    pair_names(ns)          the pair names, without reading anything
    write_pairs(dir, ns)    writes them: [(name, [a.xy, b.xy]), ...]
"""
import gzip
import os
import shutil

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


def crosses(p, q, r, s):
    """Segments pq and rs meet (touching counts)."""
    def orient(a, b, c):
        return np.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
    return orient(p, q, r) != orient(p, q, s) and orient(r, s, p) != orient(r, s, q)


def is_simple(xy):
    """No two non-adjacent edges meet (brute force; n is small here)."""
    n = len(xy)
    for i in range(n):
        for j in range(i + 2, n - (i == 0)):
            if crosses(xy[i], xy[(i + 1) % n], xy[j], xy[(j + 1) % n]):
                return False
    return True


def pair_name(name, n):
    return "hold_section_%s_n%d" % (name, n)


def pair_names(ns):
    return [pair_name(name, n) for name, *_ in PAIRS for n in ns]


def write_pairs(directory, ns):
    """Writes every section pair at every n; returns (name, files) pairs.
    A section that resamples to a polygon that is not simple is an error."""
    os.makedirs(directory, exist_ok=True)
    models, out = {}, []
    for name, *cuts in PAIRS:
        loops = []
        for model, axis, height in cuts:
            if model not in models:
                models[model] = read_stl(model, directory)
            loops.append(outer_loop(section_loops(*models[model], axis, height)))
        for n in ns:
            files = []
            for g, loop in enumerate(loops):
                xy = resample_arclength(loop, n)
                path = os.path.join(directory, "%s_%s.xy" % (pair_name(name, n), "ab"[g]))
                if not is_simple(xy):
                    raise RuntimeError("%s: section %d resampled to %d points is not simple" % (name, g, n))
                np.savetxt(path, xy, fmt="%.17g")
                files.append(path)
            out.append((pair_name(name, n), files))
    return out
