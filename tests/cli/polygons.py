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


def rotated(points, degrees):
    """The polygon turned about the origin; vertex i stays vertex i, so a
    morph to it has to twist."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [(c * x - s * y, s * x + c * y) for x, y in points]


def twisted_pair(n=16, degrees=160.0):
    """A star and another star turned by `degrees`: straight vertex paths
    pass near the centre and fold triangles over (the second is not an
    affine image of the first, else straight paths would stay valid)."""
    return star(n, seed=5), rotated(star(n, seed=6), degrees)


def _stroke(centreline, width):
    """A polygon around a polyline: its left offset forward, its right offset
    back, counter-clockwise. Corners of the offsets use the bisector."""
    left, right = [], []
    for i, (x, y) in enumerate(centreline):
        x0, y0 = centreline[max(i - 1, 0)]
        x1, y1 = centreline[min(i + 1, len(centreline) - 1)]
        dx, dy = x1 - x0, y1 - y0
        length = math.hypot(dx, dy)
        nx, ny = -dy / length * width / 2, dx / length * width / 2
        left.append((x + nx, y + ny))
        right.append((x - nx, y - ny))
    outline = right + left[::-1]
    return outline if signed_area(outline) > 0 else outline[::-1]


def spiral_pair(m=24):
    """A thick spiral of 2 turns and a thick straight bar, both strokes of
    m centreline points (2 m vertices)."""
    spiral = []
    for i in range(m):
        angle = 2.0 * math.pi * 2.0 * i / (m - 1)
        radius = 1.0 + 0.45 * angle
        spiral.append((radius * math.cos(angle), radius * math.sin(angle)))
    bar = [(-4.0 + 8.0 * i / (m - 1), -0.5) for i in range(m)]
    return _stroke(spiral, 0.6), _stroke(bar, 0.9)


def glyph_pair(m=20):
    """Two letter-like strokes of m centreline points each: a U and an S."""
    u, s = [], []
    for i in range(m):
        f = i / (m - 1)
        # U: down the left side, round the bottom, up the right side.
        if f < 0.3:
            u.append((-1.0, 2.0 - 2.0 * f / 0.3))
        elif f < 0.7:
            a = math.pi + math.pi * (f - 0.3) / 0.4
            u.append((math.cos(a), math.sin(a)))
        else:
            u.append((1.0, 2.0 * (f - 0.7) / 0.3))
        # S: over the top of the upper circle to the middle, then round the
        # lower circle the other way.
        if f < 0.5:
            a = math.pi / 6 + 4 * math.pi / 3 * f / 0.5
            s.append((math.cos(a), 1.0 + math.sin(a)))
        else:
            a = math.pi / 2 - 4 * math.pi / 3 * (f - 0.5) / 0.5
            s.append((math.cos(a), -1.0 + math.sin(a)))
    return _stroke(u, 0.5), _stroke(s, 0.5)


def is_simple(points):
    """No two non-adjacent edges meet (exact), for checking generators."""
    n = len(points)
    def cross(a, b, c, d):
        o1, o2 = orientation(a, b, c), orientation(a, b, d)
        o3, o4 = orientation(c, d, a), orientation(c, d, b)
        if o1 == o2 == o3 == o4 == 0:  # on one line: do the spans overlap?
            return all(max(min(a[k], b[k]), min(c[k], d[k])) <=
                       min(max(a[k], b[k]), max(c[k], d[k])) for k in (0, 1))
        return o1 * o2 <= 0 and o3 * o4 <= 0
    for i in range(n):
        for j in range(i + 1, n):
            if j == i + 1 or (i == 0 and j == n - 1):
                continue
            if cross(points[i], points[(i + 1) % n], points[j], points[(j + 1) % n]):
                return False
    return True


SVG = "{http://www.w3.org/2000/svg}"


def check_pictures(png_path, svg_path):
    """The PNG and SVG pictures of one run. The PNG: a real PNG (signature,
    IHDR), read back by Pillow, white with the black boundary and the red
    worst triangle drawn. The SVG: well-formed XML of the PNG's size in
    pixels that librsvg (rsvg-convert, as image viewers and browsers on
    Linux use) renders to the same picture, up to anti-aliasing. Returns
    the SVG's root element. Both have the captions (check_captions)."""
    import struct
    import subprocess
    import tempfile
    import xml.etree.ElementTree as ET

    import numpy as np
    from PIL import Image

    data = open(png_path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "PNG signature"
    length, kind, width, height = struct.unpack(">I4sII", data[8:24])
    assert kind == b"IHDR" and length == 13
    svg = ET.parse(svg_path).getroot()
    assert svg.tag == f"{SVG}svg"
    assert (svg.get("width"), svg.get("height")) == (f"{width}px", f"{height}px")
    assert svg.get("viewBox") == f"0 0 {width} {height}"
    assert 200 <= width <= 100000 and 200 <= height <= 2000
    with Image.open(png_path) as image:
        image.load()  # decodes every row: a truncated file raises here
        assert image.format == "PNG" and image.size == (width, height)
        png = np.asarray(image.convert("RGB"), dtype=int)
    colours = dict((rgb, count) for count, rgb in Image.fromarray(png.astype(np.uint8))
                   .getcolors(width * height))
    assert max(colours, key=colours.get) == (255, 255, 255), "white background"
    assert (0, 0, 0) in colours, "black boundary and captions"
    assert (0xd7, 0x19, 0x1c) in colours, "the worst triangle in red"
    with tempfile.TemporaryDirectory() as work:
        rendered = os.path.join(work, "svg.png")
        subprocess.run(["rsvg-convert", "-b", "white", "-o", rendered, str(svg_path)], check=True)
        with Image.open(rendered) as image:
            assert image.size == (width, height)
            drawn = np.asarray(image.convert("RGB"), dtype=int)
    differ = np.abs(drawn - png).max(axis=2) > 64
    assert differ.mean() < 0.02, f"{differ.mean():.1%} of the SVG's pixels differ from the PNG's"
    check_captions(png, svg)
    return svg


# The captions' size in pixels (cli/picture.h), and how far their glyphs
# reach above and below the baseline at that size, with room to spare.
CAPTION_PIXELS = 12
CAPTION_ASCENT, CAPTION_DESCENT = 12, 4


def caption_lines(svg):
    """The caption lines as the SVG draws them: cairo writes each line's
    glyphs as one group of <use> elements at the glyphs' origins. Returns
    [(baseline y, [origin x, ...]), ...] in drawing order."""
    lines = []
    for group in svg.iter(f"{SVG}g"):
        uses = [u for u in group if u.tag == f"{SVG}use"]
        if uses:
            assert len({u.get("y") for u in uses}) == 1, "one caption line per group"
            lines.append((float(uses[0].get("y")), [float(u.get("x")) for u in uses]))
    return lines


def check_captions(png, svg):
    """Every panel has its two caption lines (name, then numbers) in the
    SVG, and the PNG shows each where the SVG places it: grey ink in the
    line's band, from its first glyph to its last, and no colour there."""
    import numpy as np

    lines = caption_lines(svg)
    assert len(lines) >= 2 and len(lines) % 2 == 0, f"{len(lines)} caption lines"
    for (y, xs), (next_y, next_xs) in zip(lines[::2], lines[1::2]):
        assert next_y == y + 16 and next_xs[0] == xs[0], "the numbers' line under the name's"
    for y, xs in lines:
        assert xs == sorted(xs)
        band = png[round(y) - CAPTION_ASCENT:round(y) + CAPTION_DESCENT,
                   max(0, round(xs[0]) - CAPTION_PIXELS):round(xs[-1]) + 2 * CAPTION_PIXELS]
        ink = band.max(axis=2) < 160
        assert ink.any(), f"no caption in the PNG at y={y}"
        columns = np.flatnonzero(ink.any(axis=0)) + max(0, round(xs[0]) - CAPTION_PIXELS)
        assert columns[0] <= xs[0] + CAPTION_PIXELS and columns[-1] >= xs[-1] - CAPTION_PIXELS, \
            f"the PNG's caption at y={y} spans {columns[0]}..{columns[-1]}, the SVG's {xs[0]}..{xs[-1]}"
        assert np.all(band[ink].max(axis=1) - band[ink].min(axis=1) <= 8), "captions are black"


def drawn_paths(svg):
    """What the SVG draws outside its definitions (cairo keeps the captions'
    glyph outlines there), as (fill, stroke, stroke width, d) per path;
    colours as 0xRRGGBB, None for none."""
    def colour(value):
        if value in (None, "none"):
            return None
        channels = value[value.index("(") + 1:value.index(")")].split(",")
        rgb = [round(float(c.rstrip("%")) * 255 / 100) for c in channels]
        return rgb[0] << 16 | rgb[1] << 8 | rgb[2]

    defs = {id(p) for d in svg.iter(f"{SVG}defs") for p in d.iter(f"{SVG}path")}
    paths = []
    for p in svg.iter(f"{SVG}path"):
        if id(p) in defs:
            continue
        style = dict(item.split(":", 1) for item in p.get("style", "").replace(" ", "").split(";")
                     if ":" in item)
        paths.append((colour(style.get("fill")), colour(style.get("stroke")),
                      float(style.get("stroke-width", 0)), p.get("d")))
    return paths


# The picture's paints (cli/picture.c): what each path is, by its colours.
POOR, WORST, EDGES, BOUNDARY, STEINER = 0xfdae61, 0xd7191c, 0x555555, 0x000000, 0x2166ac


def paths_of(svg, fill=None, stroke=None):
    """The d attributes of the paths filled or stroked in one colour."""
    return [d for f, s, _, d in drawn_paths(svg)
            if (fill is not None and f == fill) or (stroke is not None and s == stroke)]