"""`compatmesh sweep`: the exported volume meshes read back by Gmsh (every
element's Jacobian positive across its volume) and by meshio (counts and
connectivity), the volume equal to the integral of the section areas, the
boundary's named surfaces in .msh files (faces of the cells, outward, each
on its own section or loop), bad input refused without leaving a file."""
import json
import math
import os
import re

import gmsh
import meshio
import numpy as np
import pytest

from polygons import glyph_pair, leftovers, spiral_pair, twisted_pair, write_xy

PAIRS = {"twisted": twisted_pair, "spiral": spiral_pair, "glyph": glyph_pair}
# Which reader checks which format: Gmsh reads all but Abaqus .inp (Gmsh 4.8
# has no Abaqus reader: it takes the file for a .geo script) and .vtu (no
# VTK XML reader); meshio reads .msh, .vtk, .vtu, .inp and .bdf (the tool
# adds the BEGIN BULK line Gmsh leaves out), not .unv (no meshio reader).
# Gmsh 4.8 writes VTK wedges in VTK's order but reads them back as if in its
# own, turning them inside out; test_vtk_file_uses_vtk_wedge_order and meshio
# check the .vtk prisms instead.
GMSH_CHECKS = [(fmt, kind) for fmt in ["msh", "msh22", "vtk", "bdf", "unv"]
               for kind in ["prism", "tet"] if (fmt, kind) != ("vtk", "prism")]
MESHIO_READS = ["msh", "msh22", "vtk", "vtu", "inp", "bdf"]
GMSH_TYPE = {"prism": 6, "tet": 4}
CORNERS = {"prism": [0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1],
           "tet": [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]}


def sweep(cm, tmp_path, pair, fmt, *extra):
    """Runs the sweep of pair into out.<ext>; returns (path, stdout)."""
    a, b = pair
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    extension = "msh" if fmt == "msh22" else fmt
    args = ["--msh-version", "2.2"] if fmt == "msh22" else []
    result = cm("sweep", "a.xy", "b.xy", "--sections", 6, "--height", 2.5, "-o",
                f"out.{extension}", *args, *extra, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    # Only the flat-prism warning may be printed (the glyph's inserted
    # sections make a few thin layers at this height).
    assert all(re.fullmatch(r"compatmesh: sweep: warning: \d+ of \d+ prisms are flatter than 1:10 .*", line)
               for line in result.stderr.splitlines()), result.stderr
    assert leftovers(tmp_path) == []
    return tmp_path / f"out.{extension}", result.stdout


def reported(stdout):
    m = re.search(r"\((\d+) sections, (\d+) nodes, (\d+) (prisms|tetrahedra), "
                  r"volume ([-+0-9.e]+)\)", stdout)
    assert m, stdout
    return int(m[1]), int(m[2]), int(m[3]), float(m[5])


@pytest.mark.parametrize("fmt, kind", GMSH_CHECKS)
@pytest.mark.parametrize("name", sorted(PAIRS))
def test_gmsh_reads_back_positive_elements(cm, tmp_path, gmsh_session, name, fmt, kind):
    extra = ["--tets"] if kind == "tet" else []
    path, stdout = sweep(cm, tmp_path, PAIRS[name](), fmt, *extra)
    sections, nodes, cells, volume = reported(stdout)
    gmsh.open(str(path))
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    assert len(node_tags) == nodes
    types, tags, element_nodes = gmsh.model.mesh.getElements(3)
    assert list(types) == [GMSH_TYPE[kind]] and len(tags[0]) == cells
    # Every element's Jacobian determinant positive at its Gauss points and
    # its corners: positive volume everywhere, not only on average.
    gauss, _ = gmsh.model.mesh.getIntegrationPoints(GMSH_TYPE[kind], "Gauss4")
    for points in (gauss, CORNERS[kind]):
        _, determinants, _ = gmsh.model.mesh.getJacobians(GMSH_TYPE[kind], points)
        assert len(determinants) == cells * (len(points) // 3)
        assert min(determinants) > 0
    weights = gmsh.model.mesh.getIntegrationPoints(GMSH_TYPE[kind], "Gauss4")[1]
    _, determinants, _ = gmsh.model.mesh.getJacobians(GMSH_TYPE[kind], gauss)
    integrated = float(np.sum(np.reshape(determinants, (cells, -1)) @ np.asarray(weights)))
    if kind == "prism":
        # The volume Gmsh integrates is the one the tool reported.
        assert integrated == pytest.approx(volume, rel=1e-6)  # .bdf keeps 9 digits
    else:
        # Tetrahedra have flat faces where the prisms' sides are ruled, so
        # their total is their own; it must be what their corners give.
        position = dict(zip(node_tags, np.reshape(coords, (-1, 3))))
        p = np.array([position[t] for t in element_nodes[0]]).reshape(-1, 4, 3)
        six = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                        p[:, 3] - p[:, 0])
        assert integrated == pytest.approx(six.sum() / 6, rel=1e-9)


def ring(r_outer, r_hole, cx, m=24):
    """An annulus as '>'-separated loops: the outer circle counter-clockwise,
    the hole clockwise, its centre at (cx, 0)."""
    outer = [(r_outer * math.cos(2 * math.pi * i / m), r_outer * math.sin(2 * math.pi * i / m)) for i in range(m)]
    hole = [(cx + r_hole * math.cos(-2 * math.pi * i / m), r_hole * math.sin(-2 * math.pi * i / m))
            for i in range(m)]
    return outer, hole


def write_boundary_pair(tmp_path, name):
    """Writes a.xy and b.xy: the glyph pair, or two sections of a pipe (an
    annulus against one with its hole moved); returns the loop of each
    boundary vertex."""
    if name == "glyph":
        a, b = glyph_pair()
        write_xy(tmp_path / "a.xy", a)
        write_xy(tmp_path / "b.xy", b)
        return [0] * len(a)
    for path, (outer, hole) in zip(("a.xy", "b.xy"), [ring(1.0, 0.4, 0.0), ring(1.2, 0.3, 0.2)]):
        (tmp_path / path).write_text("".join(f"{x!r} {y!r}\n" for x, y in outer) + ">\n" +
                                     "".join(f"{x!r} {y!r}\n" for x, y in hole))
    return [0] * 24 + [1] * 24


def square(cx, cy, h, sx=1.0, clockwise=False, m=16):
    """A square loop of m vertices (m / 4 a side) from its lower left corner."""
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    if clockwise:
        corners = corners[:1] + corners[:0:-1]
    side = m // 4
    return [(cx + sx * h * ((1 - i % side / side) * corners[i // side][0] + i % side / side * corners[(i // side + 1) % 4][0]),
             cy + h * ((1 - i % side / side) * corners[i // side][1] + i % side / side * corners[(i // side + 1) % 4][1]))
            for i in range(m)]


@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_wall_corners_give_a_group_per_face(cm, tmp_path, gmsh_session, kind):
    """--wall-corners 45 on a square plate with a square hole swept to a
    wider one: side_1 .. side_4 and hole_1_1 .. hole_1_4, each one face of
    the profile (5 nodes on one side of the square at each end; the convex
    morph bows the sections between, --ruled keeps every wall flat), in the
    .msh file, the .inp file's node sets and the report; an angle out of
    range is a usage error."""
    for path, (outer, hole) in zip(("a.xy", "b.xy"), [(square(0, 0, 1), square(0, 0, 0.4, clockwise=True)),
                                                       (square(0, 0, 1, 1.5), square(0.3, 0.1, 0.3, clockwise=True))]):
        (tmp_path / path).write_text("".join(f"{x!r} {y!r}\n" for x, y in outer) + ">\n" +
                                     "".join(f"{x!r} {y!r}\n" for x, y in hole))
    extra = ["--tets"] if kind == "tet" else []
    walls = [f"side_{i}" for i in range(1, 5)] + [f"hole_1_{i}" for i in range(1, 5)]
    for out in ("out.msh", "out.inp"):
        result = cm("sweep", "a.xy", "b.xy", "--sections", 3, "--height", 2, "--wall-corners", 45, "-o", out,
                    "--report", "r.json", *extra, cwd=tmp_path)
        assert result.returncode == 0, result.stderr
        assert list(json.loads((tmp_path / "r.json").read_text())["boundary_faces"]) == ["bottom", "top"] + walls
    gmsh.open(str(tmp_path / "out.msh"))
    names = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
    assert sorted(names) == sorted(["sweep", "bottom", "top"] + walls)
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    position = dict(zip(node_tags, np.reshape(coords, (-1, 3))))
    planes = {}
    for wall in walls:
        (entity,) = gmsh.model.getEntitiesForPhysicalGroup(*names[wall])
        nodes = np.unique(np.concatenate(gmsh.model.mesh.getElements(2, entity)[2]))
        p = np.array([position[t] for t in nodes])
        for z in (0, 2):
            end = p[p[:, 2] == z]
            assert len(end) == 5 and (np.ptp(end[:, 0]) == 0 or np.ptp(end[:, 1]) == 0), (wall, z)
        planes[wall] = set(nodes)
    mesh = meshio.read(tmp_path / "out.inp")
    for wall in walls:
        assert set(mesh.point_sets[wall] + 1) == planes[wall], wall
    # Ruled, as a CAD loft: every wall flat (each side of the square moves
    # parallel to itself), the report's morph "linear".
    result = cm("sweep", "a.xy", "b.xy", "--sections", 3, "--height", 2, "--wall-corners", 45, "--ruled",
                "-o", "ruled.msh", "--report", "r.json", *extra, cwd=tmp_path)
    assert result.returncode == 0 and json.loads((tmp_path / "r.json").read_text())["morph"] == "linear"
    gmsh.open(str(tmp_path / "ruled.msh"))
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    position = dict(zip(node_tags, np.reshape(coords, (-1, 3))))
    for wall in walls:
        (entity,) = gmsh.model.getEntitiesForPhysicalGroup(*names[wall])
        p = np.array([position[t] for t in np.unique(np.concatenate(gmsh.model.mesh.getElements(2, entity)[2]))])
        assert np.linalg.eigvalsh(np.cov((p - p.mean(axis=0)).T))[0] < 1e-14, wall  # in one plane (rounding aside)
    result = cm("sweep", "a.xy", "b.xy", "--wall-corners", 180, "-o", "bad.msh", cwd=tmp_path)
    assert result.returncode == 2 and "--wall-corners '180' is not an angle between 0 and 180" in result.stderr
    assert not (tmp_path / "bad.msh").exists()


def test_ruled_falls_back_where_straight_lines_invert(cm, tmp_path):
    """--ruled on the twisted pair: straight vertex paths would invert
    triangles, so the convex morph's sections are swept, and said."""
    a, b = twisted_pair()
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("sweep", "a.xy", "b.xy", "--ruled", "-o", "v.msh", "--report", "r.json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert json.loads((tmp_path / "r.json").read_text())["morph"] == "convex"


@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_inp_node_sets(cm, tmp_path, kind):
    """Abaqus decks get the boundary as node sets (*NSET), not as shell
    elements: the bottom and top sections' nodes, and the nodes over each
    loop."""
    loop_of = write_boundary_pair(tmp_path, "pipe")
    extra = ["--tets"] if kind == "tet" else []
    result = cm("sweep", "a.xy", "b.xy", "--sections", 4, "--height", 2.5, "-o", "out.inp", *extra, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    sections, nodes, cells, _ = reported(result.stdout)
    nv = nodes // sections
    mesh = meshio.read(tmp_path / "out.inp")
    assert [(c.type, len(c.data)) for c in mesh.cells] == [("wedge" if kind == "prism" else "tetra", cells)]
    index = np.arange(nodes)
    z = mesh.points[:, 2]
    expected = {"bottom": index[z == 0], "top": index[z == 2.5],
                "side": index[[i % nv < len(loop_of) and loop_of[i % nv] == 0 for i in index]],
                "hole_1": index[[i % nv < len(loop_of) and loop_of[i % nv] == 1 for i in index]]}
    assert len(expected["bottom"]) == nv and len(expected["side"]) == 24 * sections
    assert sorted(mesh.point_sets) == sorted(expected)
    for name, members in expected.items():
        assert np.array_equal(np.sort(mesh.point_sets[name]), members), name


SECOND_ORDER = {"prism": (18, 15, "15-node prisms"), "tet": (11, 10, "10-node tetrahedra")}


@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_second_order_cells(cm, tmp_path, gmsh_session, kind):
    """--order 2: the same cells with a node at the middle of every edge
    (Gmsh's 15-node prisms, 10-node tetrahedra), every Jacobian positive;
    the boundary's surfaces second-order too, and an Abaqus deck's node
    sets hold every node of their faces (the bottom: every node at z = 0)."""
    write_boundary_pair(tmp_path, "pipe")
    extra = ["--tets"] if kind == "tet" else []
    gmsh_type, per_cell, words = SECOND_ORDER[kind]
    for out in ("out.msh", "out.inp"):
        result = cm("sweep", "a.xy", "b.xy", "--sections", 4, "--height", 2.5, "--order", 2, "-o", out, *extra,
                    cwd=tmp_path)
        assert result.returncode == 0, result.stderr
        m = re.search(rf"\(\d+ sections, (\d+) corner nodes, (\d+) {words}, volume", result.stdout)
        assert m, result.stdout
    corners, cells = int(m[1]), int(m[2])
    gmsh.open(str(tmp_path / "out.msh"))
    types, tags, element_nodes = gmsh.model.mesh.getElements(3)
    assert list(types) == [gmsh_type] and len(tags[0]) == cells and len(element_nodes[0]) == per_cell * cells
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    assert len(node_tags) > corners
    points, _ = gmsh.model.mesh.getIntegrationPoints(gmsh_type, "Gauss4")
    _, determinants, _ = gmsh.model.mesh.getJacobians(gmsh_type, points)
    assert len(determinants) == cells * (len(points) // 3) and min(determinants) > 0
    groups = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
    assert sorted(groups) == ["bottom", "hole_1", "side", "sweep", "top"]
    (entity,) = gmsh.model.getEntitiesForPhysicalGroup(*groups["bottom"])
    assert list(gmsh.model.mesh.getElements(2, entity)[0]) == [9]  # 6-node triangles
    deck = (tmp_path / "out.inp").read_text()
    assert f"type=C3D{per_cell}," in deck
    z = {}
    for line in deck.split("*NODE\n")[1].split("*")[0].splitlines():
        number, _, _, height = line.split(",")
        z[int(number)] = float(height)
    bottom = deck.split("*NSET, NSET=bottom\n")[1].split("*")[0].replace("\n", ",").split(",")
    assert sorted(int(v) for v in bottom if v.strip()) == sorted(n for n, h in z.items() if h == 0)
    assert len(z) == len(node_tags)


def test_sections_auto_follow_the_edges(cm, tmp_path):
    """--sections auto: layers about as tall as the triangulation's median
    edge, so a sweep four times as tall has about four times the layers."""
    write_boundary_pair(tmp_path, "pipe")
    layers = []
    for height in (1.0, 4.0):
        result = cm("sweep", "a.xy", "b.xy", "--sections", "auto", "--height", height, "-o", "out.msh",
                    "--report", "r.json", cwd=tmp_path)
        assert result.returncode == 0, result.stderr
        layers.append(json.loads((tmp_path / "r.json").read_text())["sections"] - 1)
    assert layers[0] >= 2 and 3 * layers[0] <= layers[1] <= 5 * layers[0], layers


def test_inp_is_titled_with_its_own_name(cm, tmp_path):
    """The deck's *Heading names the file written (not the temporary file
    it was written to), so the same sweep gives the same deck twice."""
    write_boundary_pair(tmp_path, "pipe")
    for out in ("one.inp", "two.inp"):
        result = cm("sweep", "a.xy", "b.xy", "--sections", 3, "-o", out, cwd=tmp_path)
        assert result.returncode == 0, result.stderr
    one, two = ((tmp_path / out).read_text().split("\n", 2) for out in ("one.inp", "two.inp"))
    assert one[:2] == ["*Heading", " one.inp"] and two[:2] == ["*Heading", " two.inp"]
    assert one[2] == two[2]
    assert not list(tmp_path.glob(".*compatmesh-*"))


@pytest.mark.parametrize("version", ["4.1", "2.2"])
@pytest.mark.parametrize("kind", ["prism", "tet"])
@pytest.mark.parametrize("name", ["glyph", "pipe"])
def test_msh_boundary_groups(cm, tmp_path, gmsh_session, name, kind, version):
    """The boundary as surfaces, one physical group each (bottom, top, side,
    hole_1): every face is a face of a cell, outward from it, and lies on
    the first section, the last, or over its own loop; the tetrahedra's
    unshared faces are exactly the boundary's triangles."""
    loop_of = write_boundary_pair(tmp_path, name)
    extra = ["--tets"] if kind == "tet" else []
    result = cm("sweep", "a.xy", "b.xy", "--sections", 4, "--height", 2.5, "--msh-version", version,
                "-o", "out.msh", "--report", "report.json", *extra, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    sections, nodes, cells, _ = reported(result.stdout)
    nv = nodes // sections
    gmsh.open(str(tmp_path / "out.msh"))
    names = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
    expected = ["bottom", "top", "side"] + (["hole_1"] if name == "pipe" else []) + ["sweep"]
    assert sorted(names) == sorted(expected)
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    position = dict(zip(node_tags, np.reshape(coords, (-1, 3))))
    types, _, element_nodes = gmsh.model.mesh.getElements(3)
    corners = GMSH_TYPE[kind] == 4 and 4 or 6
    cell_nodes = np.reshape(element_nodes[0], (-1, corners))
    # Each cell's faces as they point out of it (Gmsh's positive tetrahedron
    # and wedge, which test_gmsh_reads_back_positive_elements checks), keyed
    # by their sorted nodes.
    outward = ([(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)] if kind == "tet" else
               [(0, 2, 1), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)])
    owner = {}
    for cell in cell_nodes:
        for f in outward:
            owner.setdefault(tuple(sorted(cell[list(f)])), []).append(tuple(cell[list(f)]))

    def rotations(face):
        return {tuple(face[i:]) + tuple(face[:i]) for i in range(len(face))}

    seen, counts = set(), {}
    for group in expected[:-1]:
        dim, tag = names[group]
        assert dim == 2
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            for element_type, _, flat in zip(*gmsh.model.mesh.getElements(2, entity)):
                size = {2: 3, 3: 4}[element_type]
                counts[group] = counts.get(group, 0) + len(flat) // size
                assert size == (4 if kind == "prism" and group not in ("bottom", "top") else 3), group
                for face in np.reshape(flat, (-1, size)):
                    key = tuple(sorted(face))
                    holders = owner.get(key, [])
                    assert len(holders) == 1 and key not in seen, (group, face)
                    assert tuple(face) in rotations(holders[0]), (group, face, "not outward")
                    seen.add(key)
                    p = np.array([position[t] for t in face])
                    index = (np.asarray(face, dtype=np.int64) - 1)
                    if group == "bottom":
                        assert np.all(p[:, 2] == 0)
                    elif group == "top":
                        assert np.all(p[:, 2] == 2.5)
                    else:
                        vertex = index % nv
                        assert np.all(vertex < len(loop_of))
                        assert {loop_of[v] for v in vertex} == {expected.index(group) - 2}
                        assert len(set(index // nv)) == 2
    # Every face of a cell that no other cell shares is on the boundary.
    unshared = {key for key, holders in owner.items() if len(holders) == 1}
    assert unshared == seen
    # The report names the same groups with the same counts.
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["boundary_faces"] == counts and list(report["boundary_faces"]) == expected[:-1]


def section_area_integral(points, n, nv):
    """Integral over z of the area of the section polygons: the prisms blend
    their triangles linearly between two sections, so the area is quadratic
    in z in each slab and Simpson's rule is exact there."""
    sections = points.reshape(-1, nv, 3)
    def area(xy):
        x, y = xy[:, 0], xy[:, 1]
        return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    total = 0.0
    for low, high in zip(sections[:-1], sections[1:]):
        z0, z1 = low[0, 2], high[0, 2]
        assert np.all(low[:, 2] == z0) and np.all(high[:, 2] == z1) and z1 > z0
        b, t = low[:n, :2], high[:n, :2]
        total += (z1 - z0) / 6 * (area(b) + 4 * area((b + t) / 2) + area(t))
    return total


@pytest.mark.parametrize("name", sorted(PAIRS))
def test_volume_is_the_integral_of_section_areas(cm, tmp_path, name):
    pair = PAIRS[name]()
    path, stdout = sweep(cm, tmp_path, pair, "msh")
    sections, nodes, cells, volume = reported(stdout)
    mesh = meshio.read(path)
    assert len(mesh.points) == nodes and nodes % sections == 0
    expected = section_area_integral(mesh.points, len(pair[0]), nodes // sections)
    assert volume == pytest.approx(expected, rel=1e-9)
    # The two ends are the inputs, at z = 0 and z = 2.5.
    assert mesh.points[:, 2].min() == 0 and mesh.points[:, 2].max() == 2.5
    # Gmsh prints 16 significant digits: close, not bit-identical.
    assert np.allclose(mesh.points[:len(pair[0]), :2], pair[0], rtol=0, atol=1e-14)


@pytest.mark.parametrize("kind", ["prism", "tet"])
def test_meshio_reads_every_format_alike(cm, tmp_path, kind):
    extra = ["--tets"] if kind == "tet" else []
    meshes = {}
    for fmt in MESHIO_READS:
        directory = tmp_path / fmt
        directory.mkdir()
        path, stdout = sweep(cm, directory, glyph_pair(), fmt, *extra)
        meshes[fmt] = meshio.read(path)
        _, nodes, cells, _ = reported(stdout)
        cell_type = "wedge" if kind == "prism" else "tetra"
        # .msh files also hold the boundary's faces (test_msh_boundary_groups)
        volume_cells = [(c.type, len(c.data)) for c in meshes[fmt].cells if c.type in ("wedge", "tetra")]
        assert volume_cells == [(cell_type, cells)]
        meshes[fmt].cells = [c for c in meshes[fmt].cells if c.type == cell_type]
        assert len(meshes[fmt].points) == nodes
    reference = meshes["msh"]
    for fmt, mesh in meshes.items():
        # Positive Jacobians as read: at every corner of every cell (meshio
        # gives wedges in Gmsh's order: bottom counter-clockwise from above).
        p = mesh.points[mesh.cells[0].data]
        corners = ([(0, 1, 2, 3), (1, 2, 0, 3), (2, 0, 1, 3), (3, 1, 0, 2)] if kind == "tet" else
                   [(0, 1, 2, 3), (1, 2, 0, 4), (2, 0, 1, 5), (3, 5, 4, 0), (4, 3, 5, 1), (5, 4, 3, 2)])
        for c, i, j, k in corners:
            det = np.einsum("ij,ij->i", np.cross(p[:, i] - p[:, c], p[:, j] - p[:, c]), p[:, k] - p[:, c])
            assert det.min() > 0, (fmt, c)
        # meshio gives wedges in Gmsh's order whatever the file's convention,
        # so equal connectivity means each writer kept the orientation.
        assert np.array_equal(mesh.cells[0].data, reference.cells[0].data), fmt
        digits = 1e-7 if fmt == "bdf" else 1e-12  # Nastran's 16-character fields keep 9 digits
        assert np.allclose(mesh.points, reference.points, rtol=0, atol=digits), fmt


def test_vtk_file_uses_vtk_wedge_order(cm, tmp_path):
    """VTK wants the first triangle's normal pointing away from the second
    (Gmsh: towards it); read the legacy file's own numbers."""
    path, _ = sweep(cm, tmp_path, twisted_pair(), "vtk")
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("POINTS"))
    count = int(lines[start].split()[1])
    numbers = " ".join(lines[start + 1:]).split()
    points = np.array(numbers[:3 * count], dtype=float).reshape(-1, 3)
    cells_at = next(i for i, line in enumerate(lines) if line.startswith("CELLS"))
    wedges = np.array([line.split() for line in
                       lines[cells_at + 1:cells_at + 1 + int(lines[cells_at].split()[1])]],
                      dtype=int)
    assert np.all(wedges[:, 0] == 6)
    p = points[wedges[:, 1:]]
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    towards_top = np.einsum("ij,ij->i", normal, p[:, 3:].mean(axis=1) - p[:, :3].mean(axis=1))
    assert np.all(towards_top < 0)


def test_vtu_file_is_vtk_xml_in_vtk_wedge_order(cm, tmp_path):
    """The .vtu is VTK XML (parsed here with the standard library, not
    meshio) with VTK's wedge order, like the .vtk Gmsh writes."""
    import xml.etree.ElementTree as ElementTree
    path, stdout = sweep(cm, tmp_path, twisted_pair(), "vtu")
    _, nodes, cells, _ = reported(stdout)
    piece = ElementTree.parse(path).getroot().find("UnstructuredGrid/Piece")
    assert int(piece.get("NumberOfPoints")) == nodes and int(piece.get("NumberOfCells")) == cells
    arrays = {a.get("Name"): np.array(a.text.split(), dtype=float) for a in piece.iter("DataArray")}
    points = arrays[None].reshape(-1, 3)
    assert np.all(arrays["types"] == 13) and np.all(np.diff(arrays["offsets"]) == 6)
    p = points[arrays["connectivity"].astype(int).reshape(-1, 6)]
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    towards_top = np.einsum("ij,ij->i", normal, p[:, 3:].mean(axis=1) - p[:, :3].mean(axis=1))
    assert np.all(towards_top < 0)


def write_obj(path, points, z):
    lines = [f"v {x!r} {y!r} {z!r}" for x, y in points]
    lines.append("l " + " ".join(str(i + 1) for i in range(len(points))) + " 1")
    path.write_text("\n".join(lines) + "\n")


def test_heights_default_to_the_inputs_z(cm, tmp_path):
    a, b = twisted_pair()
    write_obj(tmp_path / "a.obj", a, -1.5)
    write_obj(tmp_path / "b.obj", b, 4.0)
    result = cm("sweep", "a.obj", "b.obj", "-o", "out.msh")
    assert result.returncode == 0, result.stderr
    z = meshio.read(tmp_path / "out.msh").points[:, 2]
    assert z.min() == -1.5 and z.max() == 4.0
    assert len(np.unique(z)) == reported(result.stdout)[0] >= 11


def test_heights_of_three_inputs(cm, tmp_path):
    a, b = twisted_pair()
    c, _ = glyph_pair(8)
    for name, points in (("a", a), ("b", b), ("c", c)):
        write_xy(tmp_path / f"{name}.xy", points)
    result = cm("sweep", "a.xy", "b.xy", "c.xy", "--sections", 3, "--heights", "0,1,3",
                "-o", "out.vtk")
    assert result.returncode == 0, result.stderr
    mesh = meshio.read(tmp_path / "out.vtk")
    levels = np.unique(mesh.points[:, 2])
    assert {0.0, 1.0, 3.0} <= set(levels.tolist())
    middle = mesh.points[mesh.points[:, 2] == 1.0][:len(b), :2]
    assert np.allclose(middle, b, rtol=0, atol=1e-14)


@pytest.mark.parametrize("args, code, message", [
    (("-o", "out.stl"), 2, "compatmesh: sweep: out.stl: unknown extension; the format follows "
                           "it, one of msh, vtk, vtu, inp (Abaqus), bdf (Nastran), unv\n"),
    (("-o", "out"), 2, "compatmesh: sweep: out: unknown extension; the format follows it, "
                       "one of msh, vtk, vtu, inp (Abaqus), bdf (Nastran), unv\n"),
    (("-o", "blocker/out.msh"), 1, "compatmesh: cannot write blocker/out.msh: blocker is not "
                                   "a directory\n"),
    (("-o", "missing/out.msh"), 1, "compatmesh: cannot write missing/out.msh: missing: No such file or "
                                   "directory\n"),
    (("-o", "out.msh", "--heights", "0,1,2"), 2,
     "compatmesh: sweep: --heights gives 3 heights for 2 inputs\n"),
    (("-o", "out.msh", "--heights", "1,1"), 2,
     "compatmesh: sweep: --heights '1,1': the heights must increase strictly (item 2 is "
     "not above item 1)\n"),
    (("-o", "out.msh", "--height", "2", "--heights", "0,1"), 2,
     "compatmesh: sweep: give --height or --heights, not both\n"),
    (("-o", "out.msh", "--height", "-1"), 2,
     "compatmesh: sweep: --height '-1' is not a positive number\n"),
    (("-o", "out.msh", "--msh-version", "3"), 2,
     "compatmesh: sweep: unknown --msh-version '3' (known: 4.1, 2.2)\n"),
    (("-o", "out.msh", "--sections", "1"), 2,
     "compatmesh: sweep: --sections '1' is not 'auto' or a whole number from 2 to 10000\n"),
    (("-o", "out.msh", "--order", "3"), 2, "compatmesh: sweep: unknown --order '3' (known: 1, 2)\n"),
    (("-o", "out.vtu", "--order", "2"), 2,
     "compatmesh: sweep: out.vtu: second-order cells go to the formats Gmsh writes (msh, vtk, inp, bdf, unv), "
     "not .vtu\n"),
])
def test_bad_arguments(cm, tmp_path, args, code, message):
    a, b = twisted_pair()
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    (tmp_path / "blocker").write_text("a file")
    before = sorted(os.listdir(tmp_path))
    result = cm("sweep", "a.xy", "b.xy", *args)
    assert (result.returncode, result.stderr) == (code, message)
    assert sorted(os.listdir(tmp_path)) == before


def test_mismatched_counts(cm, tmp_path):
    a, _ = twisted_pair(16)
    _, b = twisted_pair(12)
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("sweep", "a.xy", "b.xy", "-o", "out.msh", "--correspondence", "index")
    assert result.returncode == 2
    assert result.stderr == ("compatmesh: b.xy has 12 vertices but a.xy has 16; with --correspondence "
                             "index the vertices correspond by index, so the counts must be equal\n")
    assert sorted(os.listdir(tmp_path)) == ["a.xy", "b.xy"]


def test_inputs_with_and_without_z(cm, tmp_path):
    a, b = twisted_pair()
    c, _ = glyph_pair(8)
    write_obj(tmp_path / "a.obj", a, 0.0)
    write_xy(tmp_path / "b.xy", b)
    write_obj(tmp_path / "c.obj", c, 2.0)
    result = cm("sweep", "a.obj", "b.xy", "c.obj", "-o", "out.msh")
    assert result.returncode == 2
    assert result.stderr == ("compatmesh: sweep: some inputs give z and some do not; give all "
                             "of them z or use --height / --heights\n")
    assert not (tmp_path / "out.msh").exists()
    # A flat drawing (z = 0) beside a .xy file is fine.
    assert cm("sweep", "a.obj", "b.xy", "-o", "out.msh").returncode == 0


def test_heights_from_xy_z(cm, tmp_path):
    """.xy files may give z as a third column: the sweep stacks them there,
    as it does OBJ files with z."""
    a, b = twisted_pair()
    (tmp_path / "a.xy").write_text("".join(f"{x!r} {y!r} 1.5\n" for x, y in a))
    (tmp_path / "b.xy").write_text("".join(f"{x!r}, {y!r}, 4\n" for x, y in b))
    result = cm("sweep", "a.xy", "b.xy", "-o", "out.msh")
    assert result.returncode == 0, result.stderr
    z = meshio.read(tmp_path / "out.msh").points[:, 2]
    assert z.min() == 1.5 and z.max() == 4


def test_inputs_z_must_increase(cm, tmp_path):
    a, b = twisted_pair()
    write_obj(tmp_path / "a.obj", a, 2.0)
    write_obj(tmp_path / "b.obj", b, 1.0)
    result = cm("sweep", "a.obj", "b.obj", "-o", "out.msh")
    assert result.returncode == 2
    assert result.stderr == ("compatmesh: sweep: b.obj lies at z = 1, not above a.obj at z = 2; "
                             "the inputs' z must increase (or use --height / --heights)\n")
    assert not (tmp_path / "out.msh").exists()
    assert cm("sweep", "a.obj", "b.obj", "--heights", "0,1", "-o", "out.msh").returncode == 0


def test_default_height_follows_the_section_size(cm, tmp_path):
    """Without heights or z, the sweep is as tall as the largest bounding-box
    diagonal: sections hundreds of units wide give no flat prisms."""
    a, b = twisted_pair()
    a, b = ([(300 * x, 300 * y) for x, y in p] for p in (a, b))
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("sweep", "a.xy", "b.xy", "-o", "out.msh")
    assert result.returncode == 0, result.stderr
    z = meshio.read(tmp_path / "out.msh").points[:, 2]
    diagonal = max(np.hypot(np.ptp([p[0] for p in q]), np.ptp([p[1] for p in q])) for q in (a, b))
    assert z.min() == 0 and z.max() == pytest.approx(diagonal, rel=1e-15)


def test_quiet_sweep_prints_no_summary(cm, tmp_path):
    a, b = twisted_pair()
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    result = cm("sweep", "a.xy", "b.xy", "--sections", 4, "-o", "out.msh",
                "--report", "report.json", "--quiet")
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    assert all(line.startswith("compatmesh: sweep: warning: ")
               for line in result.stderr.splitlines()), result.stderr
    assert meshio.read(tmp_path / "out.msh").points.shape[0] > 0
    assert (tmp_path / "report.json").stat().st_size > 0
