"""`compatmesh sweep --report`: the 3D quality figures of the exported
cells checked against the file as Gmsh reads it back (its coordinates, its
Jacobian determinants, and its own shape measures from the
AnalyseMeshQuality plugin), the sliver-free tetrahedra of the demo's U/S
sweep, the default height, the flat-prism warning, and a pipe's sections
swept without a twist."""
import json
import math
import os
import subprocess

import gmsh
import numpy as np
import pytest

from polygons import glyph_pair, write_xy

TET_EDGES = [(0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)]


@pytest.fixture
def us_pair(compatmesh_path, tmp_path):
    """The U and S of the paper's Figure 8, as examples/demo.sh makes them."""
    generator = os.path.join(os.path.dirname(compatmesh_path), "cm_gen_pairs")
    assert os.access(generator, os.X_OK), f"{generator} is built with compatmesh"
    subprocess.run([generator, "--out", str(tmp_path / "in"), "--set", "demo"], check=True,
                   capture_output=True)
    return tmp_path / "in" / "U_S_a.xy", tmp_path / "in" / "U_S_b.xy"


def read_back(path, element_type, corners):
    """Nodes of every element as Gmsh reads the file (elements x corners x 3)."""
    gmsh.open(str(path))
    tags, coords, _ = gmsh.model.mesh.getNodes()
    position = dict(zip(tags, np.reshape(coords, (-1, 3))))
    types, _, element_nodes = gmsh.model.mesh.getElements(3)
    assert list(types) == [element_type]
    return np.array([position[t] for t in element_nodes[0]]).reshape(-1, corners, 3)


def dihedral_angles(p):
    """The 6 dihedral angles (degrees) of each tetrahedron: at edge ij, the
    angle between corners k and l seen along it."""
    angles = []
    for i, j, k, l in TET_EDGES:
        e = p[:, j] - p[:, i]
        n1, n2 = np.cross(e, p[:, k] - p[:, i]), np.cross(e, p[:, l] - p[:, i])
        angles.append(np.degrees(np.arctan2(np.linalg.norm(np.cross(n1, n2), axis=1),
                                            np.einsum("ij,ij->i", n1, n2))))
    return np.array(angles).T


def gmsh_shape_measures():
    """Gmsh's own per-element measures (ICN: inverse condition number, IGE:
    inverse gradient error), 1 for the ideal element, 0 for a flat one."""
    for measure in ["ICNMeasure", "IGEMeasure"]:
        gmsh.plugin.setNumber("AnalyseMeshQuality", measure, 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 0)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    gmsh.plugin.run("AnalyseMeshQuality")
    values = {}
    for view in gmsh.view.getTags():
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(view)}].Name")
        _, _, data, _, _ = gmsh.view.getModelData(view, 0)
        values[name.split()[0]] = np.ravel(data)  # "ICN 3D" -> "ICN"
    return values


def test_us_tetrahedra_have_no_slivers(cm, tmp_path, gmsh_session, us_pair):
    """The demo's U/S sweep with --tets and default options: no dihedral
    angle under 5 degrees in the file Gmsh reads, the report's figures are
    those of that file, and Gmsh's own shape measures agree that no
    tetrahedron is flat (the index-order split they replace had ICN 0.001)."""
    a, b = us_pair
    result = cm("sweep", a, b, "--tets", "-o", "us.msh", "--report", "us.json")
    assert result.returncode == 0 and result.stderr == "", result.stderr
    report = json.loads((tmp_path / "us.json").read_text())
    quality = report["quality"]
    p = read_back(tmp_path / "us.msh", 4, 4)
    assert len(p) == report["cells"] and report["cell_type"] == "tetrahedron"
    assert report["morph"] == "convex"
    angles = dihedral_angles(p)
    assert angles.min() >= 5.0
    assert quality["min_dihedral_deg"] == pytest.approx(angles.min(), abs=1e-6)
    assert quality["max_dihedral_deg"] == pytest.approx(angles.max(), abs=1e-6)
    # Scaled Jacobian from Gmsh's Jacobian determinant (6 V for a linear
    # tetrahedron) over the largest product of a corner's edge lengths.
    _, determinants, _ = gmsh.model.mesh.getJacobians(4, [0.25, 0.25, 0.25])
    length = lambda i, j: np.linalg.norm(p[:, i] - p[:, j], axis=1)
    products = np.max([length(i, (i + 1) % 4) * length(i, (i + 2) % 4) * length(i, (i + 3) % 4)
                       for i in range(4)], axis=0)
    scaled = np.sqrt(2) * np.asarray(determinants) / products
    assert scaled.min() > 0
    assert quality["min_scaled_jacobian"] == pytest.approx(scaled.min(), rel=1e-6)
    # Aspect ratio: longest edge / (2 sqrt 6 inradius), inradius = 3 V / area.
    areas = sum(0.5 * np.linalg.norm(np.cross(p[:, j] - p[:, i], p[:, k] - p[:, i]), axis=1)
                for i, j, k in [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)])
    longest = np.max([length(i, j) for i, j, _, _ in TET_EDGES], axis=0)
    aspect = longest * areas / (np.sqrt(6) * np.asarray(determinants))
    assert quality["max_aspect_ratio"] == pytest.approx(aspect.max(), rel=1e-6)
    measures = gmsh_shape_measures()
    assert len(measures["ICN"]) == len(p) and measures["ICN"].min() > 0.1
    assert measures["IGE"].min() > 0.1
    # The height: the sections' largest bounding-box diagonal, said so.
    assert "largest bounding-box diagonal" in report["height"]["rule"]
    nodes = p.reshape(-1, 3)
    ends = [nodes[nodes[:, 2] == z][:, :2] for z in (nodes[:, 2].min(), nodes[:, 2].max())]
    diagonal = max(np.hypot(*np.ptp(xy, axis=0)) for xy in ends)
    assert report["height"]["value"] == pytest.approx(np.ptp(nodes[:, 2]), rel=1e-9)
    assert report["height"]["value"] == pytest.approx(diagonal, rel=1e-9)
    assert quality["flat_prisms"] == 0 and report["warnings"] == []


def test_prism_report_matches_gmsh_jacobians(cm, tmp_path, gmsh_session):
    """For prisms the scaled Jacobian is taken at the 6 corners: Gmsh's
    corner determinants (the reference wedge is 2 high) give the same."""
    a, b = glyph_pair()
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("sweep", "a.xy", "b.xy", "-o", "g.msh", "--report", "g.json")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "g.json").read_text())
    p = read_back(tmp_path / "g.msh", 6, 6)
    corners = [0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1]
    _, determinants, _ = gmsh.model.mesh.getJacobians(6, corners)
    determinants = np.reshape(determinants, (len(p), 6))
    # The corner's edges: along the triangle both ways, then to the other end.
    others = [(1, 2, 3), (2, 0, 4), (0, 1, 5), (5, 4, 0), (3, 5, 1), (4, 3, 2)]
    scaled = []
    for c, (i, j, k) in enumerate(others):
        product = np.prod([np.linalg.norm(p[:, x] - p[:, c], axis=1) for x in (i, j, k)], axis=0)
        scaled.append(2 / np.sqrt(3) * 2 * determinants[:, c] / product)
    assert np.min(scaled) > 0
    assert report["quality"]["min_scaled_jacobian"] == pytest.approx(np.min(scaled), rel=1e-6)
    assert report["cell_type"] == "prism" and report["cells"] == len(p)


def test_flat_prisms_are_warned_about(cm, tmp_path):
    """A height far below the sections' size: the sweep succeeds, and says on
    stderr and in the report how many prisms are flatter than 1:10."""
    a, b = glyph_pair()
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("sweep", "a.xy", "b.xy", "--height", "0.05", "--tets", "-o", "f.vtk", "--report", "f.json")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "f.json").read_text())
    quality = report["quality"]
    assert quality["flat_prisms"] > 0 and quality["max_prism_flatness"] > quality["flat_ratio"] == 10
    assert report["height"] == {"value": 0.05, "rule": "given by --height"}
    line = result.stderr.strip()
    assert line.startswith("compatmesh: sweep: warning: %d of " % quality["flat_prisms"]) and "1:10" in line
    assert report["warnings"] == [line.removeprefix("compatmesh: sweep: warning: ")]


def test_pipe_sections_sweep_without_twist(cm, tmp_path, gmsh_session):
    """Two sections of a pipe as a user has them: circles of 48 and 40
    points, the second's listed from 0.3 radians on, around holes of 24 and
    20 points. Every turn of a circle fits a circle alike; the pairing that
    turns least keeps the prisms' sides along the pipe. Expected: the file
    Gmsh reads holds the sections in order, and the top section's nodes
    are the bottom's turned by under 2 degrees (before, 159)."""
    def circle(m, radius, start, direction):
        return [(radius * math.cos(start + direction * 2 * math.pi * i / m),
                 radius * math.sin(start + direction * 2 * math.pi * i / m)) for i in range(m)]

    for name, (outer, hole) in {"a.xy": ((48, 0.0), (24, 0.0)), "b.xy": ((40, 0.3), (20, 0.1))}.items():
        lines = ["%r %r" % p for p in circle(outer[0], 2.0, outer[1], 1)] + [">"]
        lines += ["%r %r" % p for p in circle(hole[0], 1.0, hole[1], -1)]
        (tmp_path / name).write_text("\n".join(lines) + "\n")
    result = cm("sweep", "a.xy", "b.xy", "-n", "5", "--height", "4", "-o", "pipe.msh")
    assert result.returncode == 0, result.stderr
    gmsh.open(str(tmp_path / "pipe.msh"))
    tags, coords, _ = gmsh.model.mesh.getNodes()
    p = np.reshape(coords, (-1, 3))[np.argsort(tags)]
    per_section = len(p) // 5
    bottom, top = p[:per_section], p[-per_section:]
    assert len(p) == 5 * per_section and np.all(bottom[:, 2] == 0) and np.allclose(top[:, 2], 4)
    zb = (bottom[:, 0] - bottom[:, 0].mean()) + 1j * (bottom[:, 1] - bottom[:, 1].mean())
    zt = (top[:, 0] - top[:, 0].mean()) + 1j * (top[:, 1] - top[:, 1].mean())
    twist = math.degrees(np.angle(np.sum(np.conj(zb) * zt)))
    assert abs(twist) < 2, twist
