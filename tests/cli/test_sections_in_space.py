"""Sections in planes other than z = constant (MeshLab cuts a model along
x, y or any plane): each is meshed in its plane and written back in space,
its own vertices as read; sweep lofts between the planes, every cell
positive in space; morph writes its frames between the planes (also
planes z = constant given by the inputs' z); a section
that is not planar is refused with a message and no output."""
import math

import gmsh
import numpy as np
import pytest

from polygons import leftovers, orientation, read_vertex_text, star

TET_CORNERS = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]
PRISM_CORNERS = [0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1]


def write_obj_loops(path, loops):
    """MeshLab's section format: every vertex, then one 'l a b' per edge."""
    lines, first = [], 1
    for loop in loops:
        lines += ["v %r %r %r" % tuple(map(float, p)) for p in loop]
        lines += ["l %d %d" % (first + i, first + (i + 1) % len(loop)) for i in range(len(loop))]
        first += len(loop)
    path.write_text("\n".join(lines) + "\n")


def in_plane(points, origin, turn_deg):
    """Plane points (x, y) placed in the plane through origin turned by
    turn_deg about the x axis."""
    c, s = math.cos(math.radians(turn_deg)), math.sin(math.radians(turn_deg))
    return [(origin[0] + x, origin[1] + y * c, origin[2] + y * s) for x, y in points]


def bend(degrees, radius=4.0):
    """The centre of the section turned by degrees along a bend about the
    line y = radius, z = 0."""
    t = math.radians(degrees)
    return (0.0, radius - radius * math.cos(t), radius * math.sin(t))


def test_sections_across_x_are_meshed_in_their_planes(cm, tmp_path):
    """Two sections of a duct cut at x = 1 and x = 2.5, each a square with a
    square hole, the hole listed first (the outer loop is the larger in
    space: in x and y both would have no area): the meshes lie in x = 1
    and x = 2.5 exactly, their own vertices as read."""
    def square(h, cx=0.0):
        return [(cx - h, -h), (cx + h, -h), (cx + h, h), (cx - h, h)]
    sections = {}
    for name, x, hole_at in (("a", 1.0, 0.0), ("b", 2.5, 0.2)):
        outer = [(x, y, z) for y, z in star(16, 3)]
        hole = [(x, y, z) for y, z in square(0.3, hole_at)[::-1]]
        write_obj_loops(tmp_path / f"{name}.obj", [hole, outer])
        sections[name] = (x, outer, hole)
    result = cm("triangulate", "a.obj", "b.obj", "-o", "out")
    assert result.returncode == 0, result.stderr
    for name, (x, outer, hole) in sections.items():
        text = read_vertex_text(tmp_path / "out" / f"{name}.off", "off")
        assert [tuple(p) for p in text[:20]] == [tuple(map(float, p)) for p in outer + hole]
        assert all(p[0] == x for p in text)


def test_turned_sections_sweep_as_a_loft(cm, tmp_path, gmsh_session):
    """Three sections along a bend (planes turned by 0, 30 and 60 degrees
    about x): triangulated, each mesh lies in its plane, its own vertices
    as read; swept, Gmsh reads every tetrahedron and prism positive, the
    first and last sections' nodes in their planes."""
    shapes = [star(14, 1), star(14, 2, scale=1.2), star(14, 1)]
    names = []
    for g, (turn, shape) in enumerate(zip((0, -30, -60), shapes)):
        names.append(f"s{g}.obj")
        write_obj_loops(tmp_path / names[-1], [in_plane(shape, bend(-turn), turn)])
    result = cm("triangulate", *names, "-o", "out")
    assert result.returncode == 0, result.stderr
    for g, (turn, shape) in enumerate(zip((0, -30, -60), shapes)):
        points = np.array(read_vertex_text(tmp_path / "out" / f"s{g}.off", "off"))
        assert [tuple(p) for p in points[:14]] == in_plane(shape, bend(-turn), turn)
        normal = np.array([0, -math.sin(math.radians(turn)), math.cos(math.radians(turn))])
        assert np.abs((points - bend(-turn)) @ normal).max() < 1e-12
    for kind, flag, element, corners in (("tet", ["--tets"], 4, TET_CORNERS), ("prism", [], 6, PRISM_CORNERS)):
        result = cm("sweep", *names, "-o", f"{kind}.msh", "--sections", "auto", *flag)
        assert result.returncode == 0, result.stderr
        gmsh.open(str(tmp_path / f"{kind}.msh"))
        _, determinants, _ = gmsh.model.mesh.getJacobians(element, corners)
        assert len(determinants) > 0 and min(determinants) > 0
        _, coords, _ = gmsh.model.mesh.getNodes()
        nodes = np.reshape(coords, (-1, 3))
        for turn in (0, -60):
            normal = np.array([0, -math.sin(math.radians(turn)), math.cos(math.radians(turn))])
            on_plane = np.abs((nodes - bend(-turn)) @ normal) < 1e-9
            assert on_plane.sum() >= 14, (kind, turn)


def test_morph_frames_between_the_planes(cm, tmp_path):
    """Morph of two sections in turned planes: the first and last frames are
    the triangulate meshes (the inputs' own vertices as read), the middle
    frame lies between the planes (every vertex strictly above the first
    plane and below the second along the bend), all with the same faces."""
    shapes = [star(14, 1), star(14, 2, scale=1.2)]
    for g, (turn, shape) in enumerate(zip((0, -30), shapes)):
        write_obj_loops(tmp_path / f"s{g}.obj", [in_plane(shape, bend(-turn), turn)])
    assert cm("triangulate", "s0.obj", "s1.obj", "-o", "pair").returncode == 0
    result = cm("morph", "s0.obj", "s1.obj", "-o", "frames", "--frames", "3")
    assert result.returncode == 0, result.stderr
    for f, name in ((0, "s0"), (2, "s1")):
        assert (tmp_path / "frames" / f"frame_{f:03d}.off").read_text() == \
               (tmp_path / "pair" / f"{name}.off").read_text()
    def faces_of(path):
        lines = path.read_text().splitlines()
        return lines[2 + int(lines[1].split()[0]):]
    faces = [faces_of(tmp_path / "frames" / f"frame_{f:03d}.off") for f in range(3)]
    assert faces[0] == faces[1] == faces[2]
    middle = np.array(read_vertex_text(tmp_path / "frames" / "frame_001.off", "off"))
    first = np.array([0, 0, 1.0])
    second = np.array([0, math.sin(math.radians(30)), math.cos(math.radians(30))])
    assert np.all(middle @ first > 0)
    assert np.all((middle - bend(30)) @ second < 0)


def test_morph_frames_between_z_planes(cm, tmp_path):
    """Sections given in planes z = 2, 3 and 7 (.xy with z): every morph
    frame lies in the plane its time puts between them, as the sweep's
    layers do (t = 0.25 halfway between z = 2 and 3), the inputs' frames
    are the triangulate meshes bit for bit; the same polygons without z
    give frames at z = 0."""
    shapes = [star(12, 1), star(12, 2, scale=1.3), star(12, 3, scale=0.8)]
    for g, (z, shape) in enumerate(zip((2, 3, 7), shapes)):
        (tmp_path / f"z{g}.xy").write_text("".join("%r %r %r\n" % (x, y, z) for x, y in shape))
        (tmp_path / f"f{g}.xy").write_text("".join("%r %r\n" % (x, y) for x, y in shape))
    names = ["z0.xy", "z1.xy", "z2.xy"]
    assert cm("triangulate", *names, "-o", "pair").returncode == 0
    result = cm("morph", *names, "-o", "frames", "--frames", "9")
    assert result.returncode == 0, result.stderr
    for f, name in ((0, "z0"), (4, "z1"), (8, "z2")):
        assert (tmp_path / "frames" / f"frame_{f:03d}.off").read_text() == \
               (tmp_path / "pair" / f"{name}.off").read_text()
    for f, z in ((1, 2.25), (2, 2.5), (6, 5.0)):
        path = tmp_path / "frames" / f"frame_{f:03d}.off"
        points = read_vertex_text(path, "off")
        assert all(abs(p[2] - z) < 1e-12 for p in points), (f, z)
        lines = path.read_text().splitlines()
        for face in lines[2 + len(points):]:  # x and y the morph's own: exactly counter-clockwise
            a, b, c = (points[int(i)][:2] for i in face.split()[1:4])
            assert orientation(a, b, c) > 0, (f, face)
    flat = cm("morph", "f0.xy", "f1.xy", "f2.xy", "-o", "flat", "--frames", "9")
    assert flat.returncode == 0, flat.stderr
    points = np.array(read_vertex_text(tmp_path / "flat" / "frame_002.off", "off"))
    assert np.all(points[:, 2] == 0)


def test_loft_refusals_leave_nothing(cm, tmp_path):
    """A loft whose planes cross inside the sections, a loft given heights,
    and a section that is not planar: a message each, exit 2, no output."""
    shape = star(12, 4)
    write_obj_loops(tmp_path / "a.obj", [in_plane(shape, (0, 0, 0), 0)])
    write_obj_loops(tmp_path / "b.obj", [in_plane(shape, (0, 0, 0.3), 80)])
    write_obj_loops(tmp_path / "c.obj", [in_plane(shape, (0, 0, 3), 20)])
    bent = in_plane(shape, (0, 0, 3), 20)
    bent[5] = (bent[5][0], bent[5][1], bent[5][2] + 0.05)
    write_obj_loops(tmp_path / "d.obj", [bent])
    cases = [
        (("sweep", "a.obj", "b.obj", "-o", "x.msh", "--tets"), "is not positive in space"),
        (("sweep", "a.obj", "c.obj", "-o", "x.msh", "--height", "2"), "give no --height or --heights"),
        (("triangulate", "a.obj", "d.obj", "-o", "out"), r"d.obj:6: the polygon is not planar"),
    ]
    for args, message in cases:
        result = cm(*args)
        assert result.returncode == 2, (args, result.stderr)
        assert message in result.stderr, (args, result.stderr)
        assert not (tmp_path / "x.msh").exists() and not (tmp_path / "out").exists()
    assert leftovers(tmp_path) == []
