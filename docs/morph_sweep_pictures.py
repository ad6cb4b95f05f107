"""Draws the README's pictures of a U and an S stroke (the glyph-like pair of
the CLI tests): docs/morph_frames.png, six frames of their morph (the tool's
frames.svg), and docs/sweep.png, their sweep with its lateral surface shaded
and the top section's triangles drawn. The tool writes the mesh (Gmsh .msh),
meshio reads it, rsvg-convert (librsvg2-bin) turns SVG into PNG.

    /usr/bin/python3 docs/morph_sweep_pictures.py build/bin/compatmesh docs
"""
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "cli"))
from polygons import glyph_pair, write_xy  # noqa: E402

WIDTH, HEIGHT = 900, 640
YAW, PITCH = np.radians(35), np.radians(28)
TOWARDS_VIEWER = -np.array([np.sin(YAW) * np.cos(PITCH), np.cos(YAW) * np.cos(PITCH),
                            -np.sin(PITCH) / 1.2])


def project(points):
    """Oblique view from the front right and above; returns x, y, depth."""
    yaw, pitch = YAW, PITCH
    x, y, z = points[:, 0], points[:, 1], points[:, 2] * 1.2
    u = x * np.cos(yaw) - y * np.sin(yaw)
    v = x * np.sin(yaw) + y * np.cos(yaw)
    screen_y = z * np.cos(pitch) + v * np.sin(pitch)
    depth = v * np.cos(pitch) - z * np.sin(pitch)
    return np.c_[u, -screen_y], depth


def main(binary, docs):
    binary, docs = os.path.abspath(binary), os.path.abspath(docs)
    with tempfile.TemporaryDirectory() as work:
        a, b = glyph_pair(28)
        write_xy(os.path.join(work, "u.xy"), a)
        write_xy(os.path.join(work, "s.xy"), b)
        subprocess.run([binary, "morph", "u.xy", "s.xy", "--frames", "6", "-o", "frames"],
                       cwd=work, check=True, stdout=subprocess.DEVNULL)
        subprocess.run(["rsvg-convert", "-w", "1400", "-o",
                        os.path.join(docs, "morph_frames.png"),
                        os.path.join(work, "frames", "frames.svg")], check=True)
        subprocess.run([binary, "sweep", "u.xy", "s.xy", "--sections", "13", "--height", "3",
                        "-o", "sweep.msh"], cwd=work, check=True, stdout=subprocess.DEVNULL)
        mesh = meshio.read(os.path.join(work, "sweep.msh"))
        n = len(a)
        nodes, prisms = mesh.points, mesh.cells_dict["wedge"]
        nv = len(nodes) // len(np.unique(nodes[:, 2]))
        xy, depth = project(nodes)
        scale = 0.9 * min(WIDTH / np.ptp(xy[:, 0]), HEIGHT / np.ptp(xy[:, 1]))
        xy = (xy - xy.min(axis=0)) * scale + [0.05 * WIDTH, 0.05 * HEIGHT]
        light = TOWARDS_VIEWER + [0.5, 0.0, 0.3]
        light /= np.linalg.norm(light)
        faces = []  # (depth, svg)
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
                colour = "#%02x%02x%02x" % tuple(int(255 * shade * c) for c in (0.55, 0.75, 1.0))
                points = " ".join(f"{xy[v, 0]:.1f},{xy[v, 1]:.1f}" for v in quad)
                faces.append((depth[quad].mean(), f'<polygon points="{points}" fill="{colour}" '
                                                  f'stroke="{colour}" stroke-width="0.6"/>'))
        faces.sort(key=lambda f: -f[0])  # far first
        top = len(nodes) // nv - 1
        cap = []  # the top section, filled, its triangles outlined
        for p in prisms[: len(prisms) // top]:
            tri = [top * nv + v % nv for v in p[:3]]
            points = " ".join(f"{xy[v, 0]:.1f},{xy[v, 1]:.1f}" for v in tri)
            cap.append(f'<polygon points="{points}" fill="#e8eef7" stroke="#333" '
                       f'stroke-width="0.5" stroke-linejoin="round"/>')
        svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}">',
               '<rect width="100%" height="100%" fill="#fff"/>',
               *[f for _, f in faces], *cap,
               f'<text x="12" y="{HEIGHT - 12}" font-family="sans-serif" font-size="14">'
               f'compatmesh sweep u.xy s.xy --sections 13 --height 3: {len(prisms)} prisms '
               f'from a U (bottom) to an S (top)</text>', "</svg>"]
        svg_path = os.path.join(work, "sweep.svg")
        with open(svg_path, "w") as f:
            f.write("\n".join(svg) + "\n")
        subprocess.run(["rsvg-convert", "-o", os.path.join(docs, "sweep.png"), svg_path],
                       check=True)


if __name__ == "__main__":
    main(*sys.argv[1:])
