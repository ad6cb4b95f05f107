"""What a compatible mesh's own map allows: per triangle, the largest
smallest angle any two triangles related by that triangle's affine map can
both have. No moving of the mesh's vertices raises a triangle above the
cap of the map it then has, so a mesh whose smallest angle is near its
least cap is as good as its map lets it be; only a less distorted map
(another connectivity) can gain more.

usage: map_caps.py OUT_DIR [--png FILE]
  OUT_DIR: a `compatmesh triangulate` output directory (its report.json
  names the meshes). Prints the least and the median cap against the
  smallest angle; --png draws the first two meshes side by side, each
  triangle coloured by its cap (red: the least, blue: the 90th
  percentile and above), to see where the map is distorted.
"""
import argparse
import json
import math
import os
import sys

import meshio
import numpy as np

from correspondence_bound import dilatation_bound


def map_caps(a, b, tri):
    """Per triangle of a compatible mesh (vertex arrays a and b, triangles
    tri): the cap of its affine map a -> b in degrees, the angle alpha
    whose K(alpha) (correspondence_bound.dilatation_bound) is the map's
    dilatation, bisected for all triangles at once."""
    a, b, tri = np.asarray(a, float), np.asarray(b, float), np.asarray(tri)
    ea = np.stack([a[tri[:, 1]] - a[tri[:, 0]], a[tri[:, 2]] - a[tri[:, 0]]], axis=2)
    eb = np.stack([b[tri[:, 1]] - b[tri[:, 0]], b[tri[:, 2]] - b[tri[:, 0]]], axis=2)
    sigma = np.linalg.svd(eb @ np.linalg.inv(ea), compute_uv=False)
    K = sigma[:, 0] / sigma[:, 1]
    lo, hi = np.full(len(K), 1e-6), np.full(len(K), math.pi / 3)
    bound = np.vectorize(dilatation_bound)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        above = bound(mid) >= K
        lo, hi = np.where(above, mid, lo), np.where(above, hi, mid)
    return np.where(K <= 1.0, 60.0, np.degrees(lo))


def output_caps(paths):
    """The meshes in paths (a compatmesh output, one per polygon) and, per
    triangle, the least cap over every two of them."""
    meshes = [meshio.read(p) for p in paths]
    tri = meshes[0].cells_dict["triangle"]
    points = [m.points[:, :2] for m in meshes]
    caps = np.min([map_caps(a, b, tri) for i, a in enumerate(points) for b in points[i + 1:]], axis=0)
    return points, tri, caps


def draw(meshes, caps, path, width=600):
    """The meshes side by side, each triangle filled by its cap."""
    from PIL import Image, ImageDraw  # only the picture needs it

    low, high = float(caps.min()), float(np.percentile(caps, 90))
    span = max(high - low, 1e-12)
    image = Image.new("RGB", (len(meshes) * (width + 20), width + 30), "white")
    pen = ImageDraw.Draw(image)
    for k, (points, tri) in enumerate(meshes):
        origin, size = points.min(axis=0), max(np.ptp(points, axis=0).max(), 1e-300)
        xy = (points - origin) * ((width - 20) / size) + 10
        xy[:, 1] = width - xy[:, 1]
        xy[:, 0] += k * (width + 20)
        for t, cap in zip(tri, caps):
            s = min(1.0, (cap - low) / span)
            pen.polygon([tuple(xy[v]) for v in t], fill=(int(255 * (1 - s)), int(160 * s), int(255 * s)),
                        outline=(0, 0, 0))
    pen.text((10, width + 8), "map cap per triangle: red %.2f deg, blue %.2f deg and above" % (low, high),
             fill=(0, 0, 0))
    image.save(path)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out_dir")
    ap.add_argument("--png")
    args = ap.parse_args(argv)
    try:
        report = json.load(open(os.path.join(args.out_dir, "report.json")))
        points, tri, caps = output_caps([m["output"] for m in report["meshes"]])
    except (OSError, ValueError, KeyError) as e:
        sys.exit("map_caps.py: %s: %s" % (args.out_dir, e))
    angle = min(m["min_angle_deg"] for m in report["meshes"])
    print("least cap %.3f deg, median %.3f; smallest angle %.3f deg (%.3f of the least cap)"
          % (caps.min(), np.median(caps), angle, angle / caps.min()))
    if args.png:
        draw([(p, tri) for p in points[:2]], caps, args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
