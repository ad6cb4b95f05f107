"""Polygons and file helpers shared by the CLI tests."""
import math
import os
import random
from fractions import Fraction

# Vertices with awkward binary expansions, -0.0 and a huge and a tiny
# magnitude: they only come back unchanged if the output is bit-exact.
SQUARE = [(-0.0, 0.1), (1.0 / 3.0, 0.0), (1.0 / 3.0, 2.0 / 3.0), (-0.0, 2.0 / 3.0)]
KITE = [(0.0, 0.0), (2.5, -0.5), (3.0, 1.7), (0.2, 1.1)]


def star(n, seed, scale=1.0, clockwise=False):
    """A star-shaped polygon with n vertices at random radii, in order."""
    rng = random.Random(seed)
    points = []
    for i in range(n):
        radius = scale * (1.0 + 0.6 * rng.random())
        angle = 2.0 * math.pi * i / n
        points.append((radius * math.cos(angle), radius * math.sin(angle)))
    return points[::-1] if clockwise else points


def write_xy(path, points, header=""):
    """Writes one 'x y' line per vertex (repr round-trips exactly) after the
    header text. Returns the 1-based line number of every vertex."""
    lines = header.splitlines()
    vertex_lines = []
    for x, y in points:
        lines.append(f"{x!r} {y!r}")
        vertex_lines.append(len(lines))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return vertex_lines


def signed_area(points):
    return 0.5 * sum(x0 * y1 - x1 * y0
                     for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))


def orientation(a, b, c):
    """Exact sign of the turn a -> b -> c."""
    ax, ay, bx, by, cx, cy = map(Fraction, (*a, *b, *c))
    value = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (value > 0) - (value < 0)


def read_vertex_text(path, fmt):
    """The vertex coordinates of a mesh file, parsed from its text with
    float() so that bit-exactness can be checked (meshio may round)."""
    with open(path) as f:
        lines = f.read().splitlines()
    if fmt == "obj":
        rows = [line.split()[1:] for line in lines if line.startswith("v ")]
    elif fmt == "off":
        count = int(lines[1].split()[0])
        rows = [line.split() for line in lines[2:2 + count]]
    else:
        start = lines.index("end_header") + 1
        count = next(int(line.split()[2]) for line in lines if line.startswith("element vertex"))
        rows = [line.split() for line in lines[start:start + count]]
    return [tuple(float(v) for v in row) for row in rows]


def snapshot(directory):
    """Everything observable about a directory tree (None if it is absent),
    to show that a failed run left it exactly as it was."""
    if not os.path.lexists(directory):
        return None
    state = {}
    for root, dirs, files in os.walk(directory):
        for name in dirs + files:
            path = os.path.join(root, name)
            info = os.lstat(path)
            content = None
            if os.path.isfile(path):
                with open(path, "rb") as f:
                    content = f.read()
            state[os.path.relpath(path, directory)] = (info.st_mode, info.st_mtime_ns, content)
    return state


def leftovers(parent):
    """Temporary directories a run may have left beside its output."""
    return [name for name in os.listdir(parent) if ".compatmesh-" in name]
