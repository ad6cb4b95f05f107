"""triangulate, morph and sweep return one kind of object (compatmesh.Output):
common attributes, to_meshio() and write() through meshio, docstrings with
shapes. Each mesh written by meshio reads back bit-identical."""
import os

import meshio
import numpy as np
import pytest

import compatmesh
from conftest import ring


@pytest.fixture(scope="module")
def pair():
    """Two stars of 12 vertices, one turned: a morph with moving vertices."""
    c, s = np.cos(2.0), np.sin(2.0)
    return ring(12, inner=0.5), ring(12, inner=0.7, jitter=False) @ np.array([[c, s], [-s, c]]) * 1.3


@pytest.fixture(scope="module")
def outputs(pair):
    return {"triangulate": compatmesh.triangulate(pair),
            "morph": compatmesh.morph(pair, frames=4),
            "sweep": compatmesh.sweep(pair, sections=3, height=2.0),
            "sweep_tets": compatmesh.sweep(pair, sections=3, height=2.0, tets=True)}


def assert_round_trip(mesh, path):
    """mesh written by meshio to path and read back: the same points, bit for
    bit, and the same cells."""
    meshio.write(path, mesh)
    back = meshio.read(path)
    assert back.points.dtype == np.float64 and np.array_equal(back.points, mesh.points)
    assert [c.type for c in back.cells] == [c.type for c in mesh.cells]
    for read, written in zip(back.cells, mesh.cells):
        assert np.array_equal(read.data, written.data)


def test_one_kind_of_object(outputs):
    for name, out in outputs.items():
        assert isinstance(out, compatmesh.Output), name
        assert isinstance(out.stats, dict) and out.stats["k"] == 2, name
        assert out.cells and all(a.dtype == np.int32 for a in out.cells.values()), name
        assert out.quality, name


def test_triangulation_to_meshio(outputs, pair, tmp_path):
    r = outputs["triangulate"]
    assert r.points is r.vertices and r.quality == r.stats["quality"]
    assert list(r.cells) == ["triangle"] and r.cells["triangle"] is r.faces
    meshes = r.to_meshio()
    assert isinstance(meshes, list) and len(meshes) == 2
    for g, mesh in enumerate(meshes):
        assert isinstance(mesh, meshio.Mesh) and mesh.points.shape == (len(r.vertices[g]), 3)
        assert np.array_equal(mesh.points[:, :2], r.vertices[g]) and np.all(mesh.points[:, 2] == 0)
        assert np.array_equal(mesh.cells_dict["triangle"], r.faces)
        assert np.array_equal(mesh.points[:12, :2], pair[g])  # the input vertices, exactly
        assert np.array_equal(r.to_meshio(g).points, mesh.points)
        assert_round_trip(mesh, tmp_path / f"geometry{g}.vtu")
        assert_round_trip(mesh, tmp_path / f"geometry{g}.msh")
    assert np.array_equal(r.to_meshio(-1).points, meshes[1].points)


def test_morph_to_meshio(outputs, tmp_path):
    m = outputs["morph"]
    assert m.points is m.sections and m.sections is m["sections"]
    assert "faces" in m and "colour" not in m and set(m.keys()) >= {"faces", "t", "sections", "n"}
    assert [q["inverted"] for q in m.quality] == list(m.inverted)
    assert [q["min_angle_deg"] for q in m.quality] == list(m.min_angle_deg)
    meshes = m.to_meshio()
    assert len(meshes) == 4
    for f, mesh in enumerate(meshes):
        assert np.array_equal(mesh.points[:, :2], m.sections[f]) and np.all(mesh.points[:, 2] == 0)
        assert np.array_equal(mesh.cells_dict["triangle"], m.faces)
        assert_round_trip(mesh, tmp_path / f"frame{f}.vtu")
    # the frames differ: the vertices move
    assert not np.array_equal(meshes[1].points, meshes[2].points)


def test_sweep_to_meshio(outputs, tmp_path):
    s, t = outputs["sweep"], outputs["sweep_tets"]
    assert s.points is s.nodes and list(s.cells) == ["wedge"] and list(t.cells) == ["wedge", "tetra"]
    assert s.quality is s["quality"]
    wedges = s.to_meshio()
    assert list(wedges.cells_dict) == ["wedge"] and np.array_equal(wedges.points, s.nodes)
    # meshio's (VTK's) wedge: the bottom clockwise seen from the top
    assert np.array_equal(wedges.cells_dict["wedge"], s.prisms[:, [0, 2, 1, 3, 5, 4]])
    p = wedges.points[wedges.cells_dict["wedge"]]
    assert np.all(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2] < 0)
    tets = t.to_meshio()
    assert list(tets.cells_dict) == ["tetra"] and np.array_equal(tets.cells_dict["tetra"], t.tets)
    assert np.array_equal(t.to_meshio("wedge").cells_dict["wedge"], t.prisms[:, [0, 2, 1, 3, 5, 4]])
    for mesh, name in [(wedges, "wedges"), (tets, "tets")]:
        assert_round_trip(mesh, tmp_path / f"{name}.vtu")
        assert_round_trip(mesh, tmp_path / f"{name}.msh")


def test_write(outputs, tmp_path):
    outputs["triangulate"].write(tmp_path / "g1.vtu", 1)
    assert np.array_equal(meshio.read(tmp_path / "g1.vtu").points[:, :2], outputs["triangulate"].vertices[1])
    outputs["morph"].write(tmp_path / "f2.vtk", frame=2)
    assert np.array_equal(meshio.read(tmp_path / "f2.vtk").points[:, :2], outputs["morph"].sections[2])
    outputs["sweep_tets"].write(tmp_path / "volume.msh", cells="tetra")
    assert np.array_equal(meshio.read(tmp_path / "volume.msh").cells_dict["tetra"], outputs["sweep_tets"].tets)
    outputs["sweep"].write(tmp_path / "volume.dat", file_format="vtu")
    assert list(meshio.read(tmp_path / "volume.dat", file_format="vtu").cells_dict) == ["wedge"]


@pytest.mark.parametrize("call, error, message", [
    (lambda o: o["triangulate"].to_meshio(2), IndexError, "to_meshio: geometry 2 is out of range \\(0 to 1\\)"),
    (lambda o: o["morph"].to_meshio(-5), IndexError, "to_meshio: frame -5 is out of range"),
    (lambda o: o["triangulate"].write("x.vtu"), ValueError, "write: give the geometry to write \\(0 to 1\\)"),
    (lambda o: o["morph"].write("x.vtu"), ValueError, "write: give the frame to write \\(0 to 3\\)"),
    (lambda o: o["sweep"].to_meshio("tetra"), ValueError, "this sweep has no tetrahedra"),
    (lambda o: o["sweep"].to_meshio("hexahedron"), ValueError, "unknown cells 'hexahedron'"),
    (lambda o: o["morph"]["colour"], KeyError, "colour"),
])
def test_bad_requests(outputs, call, error, message):
    with pytest.raises(error, match=message):
        call(outputs)


def test_docstrings_give_shapes_and_types():
    for function, kind in [(compatmesh.triangulate, "Result"), (compatmesh.morph, "Morph"),
                           (compatmesh.sweep, "Sweep")]:
        assert f"-> {kind}" in function.__doc__ and "float64" in function.__doc__ and "int32" in function.__doc__
    assert "to_meshio" in compatmesh.Output.__doc__ and "float64" in compatmesh.Output.__doc__
    for cls in [compatmesh.Result, compatmesh.Morph, compatmesh.Sweep]:
        assert "meshio.Mesh" in cls.to_meshio.__doc__ and "float64" in cls.to_meshio.__doc__
        assert "meshio" in cls.write.__doc__
    assert "F x nv x 2 float64" in compatmesh.Morph.sections.__doc__
    assert "N x 3 float64" in compatmesh.Sweep.nodes.__doc__
    assert "m x 3 int32" in compatmesh.Result.faces.__doc__
    assert "n x 2 float64" in compatmesh.read_polygon.__doc__


def boundary_mesh(*loops, z=None):
    """The loops as one meshio mesh of line cells, each loop's lines in order;
    the points of all loops one after another, with z if given."""
    points = np.concatenate(loops)
    if z is not None:
        points = np.c_[points, z]
    lines, start = [], 0
    for loop in loops:
        i = np.arange(start, start + len(loop))
        lines.append(np.c_[i, np.roll(i, -1)])
        start += len(loop)
    return meshio.Mesh(points, [("line", np.concatenate(lines))])


@pytest.mark.parametrize("suffix", ["vtu", "vtk"])
def test_read_polygon_round_trip(pair, tmp_path, suffix):
    """A polygon written by meshio as lines reads back bit-identical, starting
    at the first line's first point, and triangulates like the array."""
    paths = []
    for g, polygon in enumerate(pair):
        paths.append(tmp_path / f"polygon{g}.{suffix}")
        meshio.write(paths[-1], boundary_mesh(polygon))
        back = compatmesh.read_polygon(paths[-1])
        assert back.dtype == np.float64 and np.array_equal(back, polygon)
    read = compatmesh.triangulate([compatmesh.read_polygon(p) for p in paths])
    assert np.array_equal(read.faces, compatmesh.triangulate(pair).faces)


def test_read_polygon_with_a_hole_and_in_space(tmp_path):
    outer, hole = ring(8) * 3, ring(6, jitter=False)[::-1]
    meshio.write(tmp_path / "holed.vtu", boundary_mesh(hole, outer))  # the hole first in the file
    loops = compatmesh.read_polygon(tmp_path / "holed.vtu")
    assert len(loops) == 2 and np.array_equal(loops[0], outer) and np.array_equal(loops[1], hole)
    tilted = ring(8)
    meshio.write(tmp_path / "tilted.vtu", boundary_mesh(tilted, z=0.5 * tilted[:, 0]))
    back = compatmesh.read_polygon(tmp_path / "tilted.vtu")
    assert np.array_equal(back, np.c_[tilted, 0.5 * tilted[:, 0]])


@pytest.mark.parametrize("lines, message", [
    ([[0, 1], [1, 2]], "point 0 is on 1 lines \\(a boundary point is on 2\\)"),
    ([[0, 1], [1, 2], [2, 9]], "line 2 has point 9, out of range \\(4 points\\)"),
    ([[0, 1], [1, 1]], "line 1 joins point 1 to itself"),
])
def test_read_polygon_errors(tmp_path, lines, message):
    path = tmp_path / "bad.vtu"
    meshio.write(path, meshio.Mesh(ring(4), [("line", np.array(lines))]))
    with pytest.raises(ValueError, match="read_polygon: .*bad.vtu: " + message):
        compatmesh.read_polygon(path)


def test_read_polygon_needs_lines(tmp_path):
    path = tmp_path / "triangle.vtu"
    meshio.write(path, meshio.Mesh(ring(3), [("triangle", np.array([[0, 1, 2]]))]))
    with pytest.raises(ValueError, match="no line cells"):
        compatmesh.read_polygon(path)


def gmsh_jacobians(path, element_type, corners):
    """The Jacobian determinants at the corners of every element of the type
    in the file, as Gmsh's own reader and element code give them."""
    import gmsh
    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(path))
        types = list(gmsh.model.mesh.getElements()[0])
        return types, np.asarray(gmsh.model.mesh.getJacobians(element_type, corners)[1])
    finally:
        gmsh.finalize()


PRISM_CORNERS = [0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1]
TET_CORNERS = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]


def test_msh_is_gmsh_that_gmsh_reads(outputs, tmp_path):
    """.msh is Gmsh's text format (meshio's first guess for it, ANSYS
    Fluent's, Gmsh does not read), every prism and tetrahedron positive as
    Gmsh computes it (meshio passes wedge corners through unchanged, and
    VTK's wedge is the mirror image of Gmsh's)."""
    s, t = outputs["sweep"], outputs["sweep_tets"]
    s.write(tmp_path / "prisms.msh")
    t.write(tmp_path / "tets.MSH", cells="tetra")
    outputs["triangulate"].write(tmp_path / "g0.msh", 0)
    for name in ("prisms.msh", "tets.MSH", "g0.msh"):
        assert (tmp_path / name).read_text().startswith("$MeshFormat\n4.1 0 8\n"), name
    types, det = gmsh_jacobians(tmp_path / "prisms.msh", 6, PRISM_CORNERS)
    assert 6 in types and det.size == 6 * len(s.prisms) and det.min() > 0
    types, det = gmsh_jacobians(tmp_path / "tets.MSH", 4, TET_CORNERS)
    assert 4 in types and det.size == 4 * len(t.tets) and det.min() > 0
    assert np.array_equal(meshio.read(tmp_path / "g0.msh").cells_dict["triangle"], outputs["triangulate"].faces)
    # written under a temporary name and renamed: nothing else is left, and
    # the file has the mode a new file gets
    assert sorted(os.listdir(tmp_path)) == ["g0.msh", "prisms.msh", "tets.MSH"]
    umask = os.umask(0)
    os.umask(umask)
    assert os.stat(tmp_path / "g0.msh").st_mode & 0o777 == 0o666 & ~umask


def test_solver_formats_get_gmsh_wedge_order(outputs, tmp_path):
    """Abaqus (.inp) and Nastran wedges are Gmsh's corner order (the first
    triangle counter-clockwise seen from the second), VTK's its mirror."""
    s = outputs["sweep"]
    s.write(tmp_path / "v.inp")
    s.write(tmp_path / "v.vtu")
    inp, vtu = meshio.read(tmp_path / "v.inp"), meshio.read(tmp_path / "v.vtu")
    assert np.array_equal(inp.cells_dict["wedge"], s.prisms)
    assert np.array_equal(vtu.cells_dict["wedge"], s.prisms[:, [0, 2, 1, 3, 5, 4]])
    p = inp.points[inp.cells_dict["wedge"]]
    assert np.all(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2] > 0)
    assert np.all(p[:, 3:, 2] > p[:, :3, 2])


def test_nastran_failure_is_explained(outputs, tmp_path):
    """meshio 5.0's Nastran writer asserts on full-precision coordinates:
    the error says so and where Nastran files come from instead, and the
    file that was there is left as it was, with nothing beside it."""
    (tmp_path / "v.bdf").write_text("mine")
    try:
        outputs["sweep"].write(tmp_path / "v.bdf")
    except RuntimeError as e:
        assert "Nastran writer cannot fit" in str(e) and "compatmesh sweep" in str(e)
        assert (tmp_path / "v.bdf").read_text() == "mine" and os.listdir(tmp_path) == ["v.bdf"]
    else:  # a meshio that writes them: the prisms then in Gmsh's order
        assert np.array_equal(meshio.read(tmp_path / "v.bdf").cells_dict["wedge"], outputs["sweep"].prisms)


@pytest.fixture(scope="module")
def pipe():
    """Two sections of a pipe: an annulus, and a wider one whose hole moved."""
    m = 16
    def circle(r, cx, direction):
        a = direction * 2 * np.pi * np.arange(m) / m
        return np.c_[cx + r * np.cos(a), r * np.sin(a)]
    return compatmesh.sweep([[circle(1.0, 0, 1), circle(0.4, 0, -1)], [circle(1.2, 0, 1), circle(0.3, 0.2, -1)]],
                            sections=3, height=2.0, tets=True)


@pytest.mark.parametrize("cells", ["wedge", "tetra"])
def test_boundary_faces_close_the_volume(pipe, cells):
    """boundary(): bottom, top, side and hole_1, each face an unshared face
    of one cell, ordered as that cell's own face seen from outside (Gmsh's
    positive wedge and tetrahedron); every unshared cell face is on it."""
    groups = pipe.boundary(cells)
    assert list(groups) == ["bottom", "top", "side", "hole_1"]
    nodes, nv = pipe.nodes, len(pipe.nodes) // len(pipe.section_z)
    if cells == "tetra":
        cell_nodes, outward = pipe.tets, [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    else:
        cell_nodes, outward = pipe.prisms, [(0, 2, 1), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)]
    owner = {}
    for cell in cell_nodes:
        for f in outward:
            owner.setdefault(tuple(sorted(cell[list(f)])), []).append(tuple(cell[list(f)]))
    seen = set()
    for name, faces in groups.items():
        assert faces.dtype == np.int32
        assert faces.shape[1] == (4 if cells == "wedge" and name in ("side", "hole_1") else 3), name
        for face in faces:
            key = tuple(sorted(face))
            (mine,) = owner[key]
            assert any(tuple(face) == mine[i:] + mine[:i] for i in range(len(mine))), (name, face)
            seen.add(key)
        z = nodes[faces, 2]
        if name == "bottom":
            assert np.all(z == pipe.section_z[0])
        elif name == "top":
            assert np.all(z == pipe.section_z[-1])
        else:  # vertices 0..15 are the outer loop, 16..31 the hole
            loop = (faces % nv) // 16
            assert np.all(faces % nv < 32) and np.all(loop == ("side", "hole_1").index(name))
    assert seen == {key for key, holders in owner.items() if len(holders) == 1}


def test_msh_holds_the_boundary_groups(pipe, tmp_path):
    """.msh written by Gmsh: the cells in "sweep" and one surface per
    boundary group, as boundary() gives them; a Gmsh session the user has
    open is left as it was (the write runs in a process of its own)."""
    import gmsh
    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("mine")
        gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
        gmsh.model.occ.synchronize()
        pipe.write(tmp_path / "tets.msh")
        pipe.write(tmp_path / "prisms.msh", cells="wedge", file_format="gmsh22")
        assert gmsh.model.getCurrent() == "mine" and gmsh.model.getEntities(3) == [(3, 1)]
        for name, cells, version in (("tets.msh", "tetra", "4.1"), ("prisms.msh", "wedge", "2.2")):
            assert (tmp_path / name).read_text().startswith(f"$MeshFormat\n{version} 0 8\n")
            gmsh.open(str(tmp_path / name))
            groups = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
            assert sorted(groups) == ["bottom", "hole_1", "side", "sweep", "top"]
            expected = pipe.boundary(cells)
            for group, faces in expected.items():
                dim, tag = groups[group]
                (entity,) = gmsh.model.getEntitiesForPhysicalGroup(dim, tag)
                _, _, face_nodes = gmsh.model.mesh.getElements(2, entity)
                read = np.asarray(face_nodes[0], dtype=np.int64).reshape(-1, faces.shape[1]) - 1
                assert np.array_equal(read, faces), group
    finally:
        gmsh.finalize()
    assert sorted(os.listdir(tmp_path)) == ["prisms.msh", "tets.msh"]


def test_inp_holds_node_sets(pipe, tmp_path):
    """Abaqus decks get the cells in the element set "sweep" and the
    boundary groups as node sets, not elements; every number fits the 21
    characters CalculiX reads."""
    pipe.write(tmp_path / "v.inp")
    text = (tmp_path / "v.inp").read_text()
    nodes = text.split("*NODE\n")[1].split("*")[0].splitlines()
    assert len(nodes) == len(pipe.nodes) and max(len(f.strip()) for line in nodes for f in line.split(",")) <= 21
    back = meshio.read(tmp_path / "v.inp")
    assert np.allclose(back.points, pipe.nodes, rtol=1e-13, atol=1e-13)
    assert list(back.cell_sets) == ["sweep"] and np.array_equal(back.cell_sets["sweep"][0], np.arange(len(pipe.tets)))
    assert [c.type for c in back.cells] == ["tetra"]
    assert sorted(back.point_sets) == ["bottom", "hole_1", "side", "top"]
    for name, faces in pipe.boundary().items():
        assert np.array_equal(np.sort(back.point_sets[name]), np.unique(faces)), name


# Abaqus' face numbering of a C3D4 (S1 ... S4) and a C3D6 (S1 ... S5).
TET_FACES = [(0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)]
PRISM_FACES = [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)]


@pytest.mark.parametrize("cells", ["tetra", "wedge"])
def test_boundary_cells_name_the_faces(pipe, cells):
    """boundary_cells(cells): each face of boundary(cells), in its order,
    is the face of the cell it names (Abaqus' numbering from 0)."""
    corners, table = (pipe.tets, TET_FACES) if cells == "tetra" else (pipe.prisms, PRISM_FACES)
    named = pipe.boundary_cells(cells)
    faces = pipe.boundary(cells)
    assert list(named) == list(faces)
    for name, pairs in named.items():
        assert pairs.dtype == np.int64 and pairs.shape == (len(faces[name]), 2)
        for (cell, face), nodes in zip(pairs, faces[name]):
            assert sorted(corners[cell][list(table[face])]) == sorted(nodes[nodes >= 0]), name


@pytest.mark.parametrize("cells", ["tetra", "wedge"])
def test_inp_holds_element_face_surfaces(pipe, tmp_path, cells):
    """Each boundary group is also an element-face surface (*SURFACE,
    TYPE=ELEMENT: element and face S1 ...), for pressures: the faces it
    names are the group's faces, each once."""
    pipe.write(tmp_path / "v.inp", cells=cells)
    text = (tmp_path / "v.inp").read_text()
    corners, table = (pipe.tets, TET_FACES) if cells == "tetra" else (pipe.prisms, PRISM_FACES)
    blocks = text.split("*SURFACE, NAME=")[1:]
    surfaces = {}
    for block in blocks:
        head, *lines = block.split("*")[0].strip().splitlines()
        assert head.endswith(", TYPE=ELEMENT")
        pairs = [line.split(",") for line in lines]
        surfaces[head.split(",")[0]] = sorted(tuple(sorted(corners[int(e) - 1][list(table[int(f.strip()[1:]) - 1])]))
                                              for e, f in pairs)
    assert sorted(surfaces) == ["bottom", "hole_1", "side", "top"]
    for name, faces in pipe.boundary(cells).items():
        assert surfaces[name] == sorted(tuple(sorted(f[f >= 0])) for f in faces), name


@pytest.mark.parametrize("cells", ["tetra", "wedge"])
def test_second_order_write(pipe, tmp_path, cells):
    """order=2 writes the cells with a node at the middle of every edge
    through Gmsh, as the command line's --order 2 (C3D10, C3D15), the node
    sets holding every node of their faces; formats Gmsh does not write,
    and orders other than 1 and 2, are refused with no file left."""
    pipe.write(tmp_path / "v.inp", cells=cells, order=2)
    text = (tmp_path / "v.inp").read_text()
    count = len(pipe.tets if cells == "tetra" else pipe.prisms)
    kind = "C3D10" if cells == "tetra" else "C3D15"
    body = text.split(f"*ELEMENT, type={kind}, ELSET=Volume1\n")[1].split("*")[0].splitlines()
    assert len(body) == count and all(len(line.split(",")) == (11 if cells == "tetra" else 16) for line in body)
    z = {int(line.split(",")[0]): float(line.split(",")[3])
         for line in text.split("*NODE\n")[1].split("*")[0].splitlines()}
    assert len(z) > len(pipe.nodes)
    for name, height in (("bottom", 0.0), ("top", 2.0)):
        members = text.split(f"*NSET, NSET={name}\n")[1].split("*")[0].replace("\n", ",").split(",")
        assert sorted(int(v) for v in members if v.strip()) == sorted(n for n, h in z.items() if h == height)
    assert text.splitlines()[1] == " v.inp" and "*SURFACE, NAME=hole_1, TYPE=ELEMENT" in text
    with pytest.raises(ValueError, match="order=2"):
        pipe.write(tmp_path / "v.vtu", order=2)
    with pytest.raises(ValueError, match="order must be 1 or 2"):
        pipe.write(tmp_path / "w.inp", order=3)
    assert sorted(os.listdir(tmp_path)) == ["v.inp"]


INTERRUPTED_WRITE = """
import os, signal, sys, threading
import numpy as np
import compatmesh
angles = np.linspace(0, 2 * np.pi, 300, endpoint=False)
disc = np.c_[np.cos(angles), np.sin(angles)]
volume = compatmesh.sweep([disc, 1.5 * disc], sections=40, tets=True)
main = threading.get_ident()
threading.Timer(0.02, lambda: signal.pthread_kill(main, signal.SIGINT)).start()
try:
    volume.write(os.path.join(sys.argv[1], "v.msh"))
except KeyboardInterrupt:
    print("interrupted")
"""


def test_interrupted_msh_write_leaves_nothing(tmp_path):
    """Ctrl-C while Gmsh writes a .msh (in its child process, which loads
    Gmsh for longer than the 0.02 s the interrupt waits): KeyboardInterrupt,
    the child stopped, no file and no temporary left."""
    import subprocess
    import sys
    run = subprocess.run([sys.executable, "-c", INTERRUPTED_WRITE, str(tmp_path)], capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0 and run.stdout.strip() == "interrupted", run.stdout + run.stderr
    assert os.listdir(tmp_path) == []


def test_wall_corner_deg_splits_the_walls():
    """wall_corner_deg: a square against a wider rectangle gives four
    walls, one per side (5 vertices each, on one line at the bottom),
    numbered from the first corner; 0 keeps one wall; 180 is refused."""
    side = np.linspace(-1, 1, 5)[:-1]
    square = np.r_[np.c_[side, -np.ones(4)], np.c_[np.ones(4), side], np.c_[-side, np.ones(4)], np.c_[-np.ones(4), -side]]
    split = compatmesh.sweep([square, square * [1.5, 1]], sections=3, wall_corner_deg=45)
    walls = split.boundary()
    assert list(walls) == ["bottom", "top", "side_1", "side_2", "side_3", "side_4"]
    nv = len(split.nodes) // len(split.section_z)
    bottom = split.nodes[:nv]
    for k, name in enumerate(["side_1", "side_2", "side_3", "side_4"]):
        vertices = np.unique(walls[name] % nv)
        assert np.array_equal(vertices, np.sort(np.arange(4 * k, 4 * k + 5) % 16)), (name, vertices)
        assert np.ptp(bottom[vertices, 0]) == 0 or np.ptp(bottom[vertices, 1]) == 0, name
    assert list(compatmesh.sweep([square, square * [1.5, 1]], sections=3).boundary())[2:] == ["side"]
    with pytest.raises(ValueError, match="wall_corner_deg must be in"):
        compatmesh.sweep([square, square * [1.5, 1]], wall_corner_deg=180)


def test_ruled_sweep_moves_every_vertex_straight():
    """ruled=True: a square against a wider rectangle is swept as a loft,
    every node on the straight line between its two polygons (morph
    "linear"); by default the convex morph's sections."""
    side = np.linspace(-1, 1, 5)[:-1]
    square = np.r_[np.c_[side, -np.ones(4)], np.c_[np.ones(4), side], np.c_[-side, np.ones(4)], np.c_[-np.ones(4), -side]]
    ruled = compatmesh.sweep([square, square * [1.5, 1]], sections=5, height=1.0, ruled=True)
    assert ruled.morph == "linear"
    nv = len(ruled.nodes) // len(ruled.section_z)
    start, end = ruled.nodes[:nv, :2], ruled.nodes[-nv:, :2]
    t = ruled.nodes[:, 2:3]
    assert np.allclose(ruled.nodes[:, :2], (1 - t) * np.tile(start, (len(ruled.section_z), 1)) +
                       t * np.tile(end, (len(ruled.section_z), 1)), rtol=0, atol=1e-12)
    assert compatmesh.sweep([square, square * [1.5, 1]], sections=5, height=1.0).morph == "convex"
