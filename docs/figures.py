"""Makes every figure and table of the README from what the tool writes, and
puts the numbers into the README, so text and pictures agree with the tool:

- docs/us_remeshed.png: `compatmesh triangulate` on the demo's U and S
  (cm_gen_pairs --set demo, pair U_S), its own preview.png; the caption and
  the paragraph under it get its Steiner counts and smallest angles, and the
  pair's correspondence bound (bench/correspondence_bound.py);
- docs/morph_frames.png: `compatmesh morph --frames 6` on the U and S strokes
  of the CLI tests (glyph_pair(28) in tests/cli/polygons.py), its own
  frames.png;
- docs/sweep.png: `compatmesh sweep --sections 13 --height 3` on the same
  pair, read back from its .msh by meshio and drawn by Pillow (lateral
  surface shaded, top section's triangles outlined);
- the sweep's counts and file-size table: `compatmesh sweep` on glyph_pair()
  (40 vertices) with default options, with and without --tets, into every
  format, counted from its --report.

The README's generated parts sit between `<!-- figures.py: NAME -->` and
`<!-- end figures.py -->`; the rest of it is not touched.

    /usr/bin/python3 docs/figures.py build
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import meshio
import numpy as np
from PIL import Image, ImageDraw, ImageFont

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "cli"))
from polygons import glyph_pair, write_xy  # noqa: E402

FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"  # fonts-dejavu-core
FORMATS = [(".msh", "`.msh` 4.1", []), (".msh", "`.msh` 2.2", ["--msh-version", "2.2"]),
           (".vtk", "`.vtk`", []), (".vtu", "`.vtu`", []), (".inp", "`.inp`", []),
           (".bdf", "`.bdf`", []), (".unv", "`.unv`", [])]


def run(*args, cwd):
    subprocess.run([str(a) for a in args], cwd=cwd, check=True, stdout=subprocess.DEVNULL)


def us_figure(build, work, docs):
    """The demo's U and S: the tool's preview, and the README block."""
    run(os.path.join(build, "bin", "cm_gen_pairs"), "--out", "demo", "--set", "demo", cwd=work)
    pair = [os.path.join("demo", "U_S_a.xy"), os.path.join("demo", "U_S_b.xy")]
    run(os.path.join(build, "bin", "compatmesh"), "triangulate", *pair, "-o", "us", cwd=work)
    shutil.copyfile(os.path.join(work, "us", "preview.png"), os.path.join(docs, "us_remeshed.png"))
    with open(os.path.join(work, "us", "report.json")) as f:
        report = json.load(f)
    bound = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "correspondence_bound.py"),
                            os.path.join(build, "bin", "compatmesh"), *pair], cwd=work, check=True,
                           capture_output=True, text=True).stdout.split()[0]
    angles = [f"{m['min_angle_deg']:.1f}" for m in report["meshes"]]
    steiner, before = report["steiner"], report["steiner_before_remesh"]
    partition = ("the partition needs no Steiner vertex, remeshing adds" if before == 0 else
                 f"the partition needs {before} Steiner vertices, remeshing ends with")
    return (f"![U and S from DejaVu Sans: one connectivity, {steiner} Steiner vertices, smallest "
            f"angles {angles[0]} and {angles[1]} degrees](docs/us_remeshed.png)\n\n"
            "The letters U and S of the paper's Figure 8 (`make demo`, pair `U_S`):\n"
            f"{partition} {steiner} and lifts the\n"
            f"smallest angles to {angles[0]} and {angles[1]} degrees (the paper: 17.1 and 17.6; no\n"
            f"compatible triangulation of this pair can pass {float(bound):.1f} degrees, see\n"
            "\"How good can a compatible triangulation be?\").")


def morph_figure(binary, work, docs):
    run(binary, "morph", "u.xy", "s.xy", "--frames", 6, "-o", "frames", cwd=work)
    shutil.copyfile(os.path.join(work, "frames", "frames.png"), os.path.join(docs, "morph_frames.png"))


WIDTH, HEIGHT, SUPERSAMPLE = 900, 640, 3
YAW, PITCH = np.radians(35), np.radians(28)
TOWARDS_VIEWER = -np.array([np.sin(YAW) * np.cos(PITCH), np.cos(YAW) * np.cos(PITCH),
                            -np.sin(PITCH) / 1.2])


def project(points):
    """Oblique view from the front right and above; returns x, y, depth."""
    x, y, z = points[:, 0], points[:, 1], points[:, 2] * 1.2
    u = x * np.cos(YAW) - y * np.sin(YAW)
    v = x * np.sin(YAW) + y * np.cos(YAW)
    screen_y = z * np.cos(PITCH) + v * np.sin(PITCH)
    depth = v * np.cos(PITCH) - z * np.sin(PITCH)
    return np.c_[u, -screen_y], depth


def sweep_figure(binary, work, docs, n):
    """The lateral surface, far faces first, shaded by a light from the
    viewer's upper right, then the top section; drawn large and scaled down
    for smooth edges."""
    run(binary, "sweep", "u.xy", "s.xy", "--sections", 13, "--height", 3, "-o", "sweep.msh", cwd=work)
    mesh = meshio.read(os.path.join(work, "sweep.msh"))
    nodes, prisms = mesh.points, mesh.cells_dict["wedge"]
    nv = len(nodes) // len(np.unique(nodes[:, 2]))
    xy, depth = project(nodes)
    s = SUPERSAMPLE
    scale = 0.9 * min(WIDTH / np.ptp(xy[:, 0]), HEIGHT / np.ptp(xy[:, 1]))
    xy = ((xy - xy.min(axis=0)) * scale + [0.05 * WIDTH, 0.05 * HEIGHT]) * s
    light = TOWARDS_VIEWER + [0.5, 0.0, 0.3]
    light /= np.linalg.norm(light)
    faces = []  # (depth, corners, colour)
    for p in prisms:
        for i in range(3):
            lo, hi = p[i], p[(i + 1) % 3]
            if lo % nv >= n or hi % nv >= n or (hi % nv - lo % nv) % n != 1:
                continue  # not a boundary edge of the polygon
            quad = [lo, hi, p[3 + (i + 1) % 3], p[3 + i]]
            q = nodes[quad]
            normal = np.cross(q[1] - q[0], q[3] - q[0])
            normal /= np.linalg.norm(normal)
            if normal @ TOWARDS_VIEWER <= 0:
                continue  # faces away: hidden behind the front
            shade = 0.3 + 0.7 * max(0.0, float(normal @ light))
            colour = tuple(int(255 * shade * c) for c in (0.55, 0.75, 1.0))
            faces.append((depth[quad].mean(), [tuple(xy[v]) for v in quad], colour))
    faces.sort(key=lambda f: -f[0])  # far first
    image = Image.new("RGB", (WIDTH * s, HEIGHT * s), "white")
    draw = ImageDraw.Draw(image)
    for _, corners, colour in faces:
        draw.polygon(corners, fill=colour, outline=colour, width=max(1, round(0.6 * s)))
    top = len(nodes) // nv - 1
    for p in prisms[: len(prisms) // top]:
        corners = [tuple(xy[top * nv + v % nv]) for v in p[:3]]
        draw.polygon(corners, fill="#e8eef7", outline="#333333", width=max(1, round(0.5 * s)))
    caption = (f"compatmesh sweep u.xy s.xy --sections 13 --height 3: {len(prisms)} prisms "
               "from a U (bottom) to an S (top)")
    draw.text((12 * s, (HEIGHT - 12) * s), caption, fill="black", anchor="ls",
              font=ImageFont.truetype(FONT, 14 * s))
    image.resize((WIDTH, HEIGHT), Image.LANCZOS).save(os.path.join(docs, "sweep.png"), optimize=True)


def size_table(binary, work, a, b):
    """The sweep of a and b into every format, prisms and tetrahedra."""
    write_xy(os.path.join(work, "ga.xy"), a)
    write_xy(os.path.join(work, "gb.xy"), b)
    counts, sizes = {}, {}
    for cells in ("prisms", "tets"):
        extra = ["--tets"] if cells == "tets" else []
        for ext, label, options in FORMATS:
            out = f"{cells}{len(sizes)}{ext}"
            run(binary, "sweep", "ga.xy", "gb.xy", *extra, *options, "-o", out, "--report",
                "report.json", cwd=work)
            sizes[cells, label] = os.path.getsize(os.path.join(work, out))
            with open(os.path.join(work, "report.json")) as f:
                report = json.load(f)
            counts[cells] = (report["sections"], report["nodes"], report["cells"])
    (ps, pn, pc), (ts, tn, tc) = counts["prisms"], counts["tets"]
    inserted = ts - ps
    added = "" if inserted == 0 else f" ({inserted} inserted)" if inserted > 1 else " (one inserted)"
    lines = ["Sizes of the files for the glyph pair of the tests (`glyph_pair()` in",
             f"`tests/cli/polygons.py`, {len(a)} vertices) with default options: {ps} sections,",
             f"{pn} nodes and {pc} prisms, or with `--tets` {ts} sections{added},",
             f"{tn} nodes and {tc} tetrahedra:", "",
             "| format | prisms | tetrahedra |", "| --- | ---: | ---: |"]
    for _, label, _ in FORMATS:
        lines.append(f"| {label} | {round(sizes['prisms', label] / 1000)} KB | "
                     f"{round(sizes['tets', label] / 1000)} KB |")
    return "\n".join(lines)


def replace_block(text, name, body):
    pattern = re.compile(rf"(<!-- figures.py: {name} -->\n).*?(\n<!-- end figures.py -->)", re.S)
    if not pattern.search(text):
        raise SystemExit(f"README.md: no block <!-- figures.py: {name} -->")
    return pattern.sub(lambda m: m.group(1) + body + m.group(2), text)


def main(build, docs=os.path.join(ROOT, "docs"), readme=os.path.join(ROOT, "README.md")):
    build = os.path.abspath(build)
    binary = os.path.join(build, "bin", "compatmesh")
    with tempfile.TemporaryDirectory() as work:
        a, b = glyph_pair(28)
        write_xy(os.path.join(work, "u.xy"), a)
        write_xy(os.path.join(work, "s.xy"), b)
        us = us_figure(build, work, docs)
        morph_figure(binary, work, docs)
        sweep_figure(binary, work, docs, len(a))
        table = size_table(binary, work, *glyph_pair())
    with open(readme) as f:
        text = f.read()
    text = replace_block(replace_block(text, "us", us), "sweep sizes", table)
    with open(readme, "w") as f:
        f.write(text)


if __name__ == "__main__":
    if len(sys.argv) not in (2, 4):
        raise SystemExit("usage: docs/figures.py BUILD_DIR [DOCS_DIR README]")
    main(*sys.argv[1:])
