"""What a compatible mesh's own map allows: per triangle, the largest
smallest angle any two triangles related by that triangle's affine map can
both have. No moving of the mesh's vertices raises a triangle above the
cap of the map it then has, so a mesh whose smallest angle is near its
least cap is as good as its map lets it be; only a less distorted map
(another connectivity) can gain more."""
import math

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
