import numpy as np
import compatmesh

# Two polygons whose vertices correspond by index: an octagon and a star.
angles = np.linspace(0, 2 * np.pi, 8, endpoint=False)
octagon = np.c_[np.cos(angles), np.sin(angles)]
star = octagon * np.where(np.arange(8) % 2, 0.4, 1.0)[:, None]

result = compatmesh.triangulate([octagon, star], min_angle_deg=25)
print(len(result.faces), "triangles,", result.stats["steiner"], "Steiner vertices")
for vertices, quality in zip(result.vertices, result.stats["quality"]):
    print(vertices.shape, "smallest angle %.1f degrees" % quality["min_angle_deg"])
