"""compatmesh.morph and compatmesh.sweep: valid sections, the volume, errors."""
from fractions import Fraction

import numpy as np
import pytest

import compatmesh
from conftest import ring


def turned(points, degrees):
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    return points @ np.array([[c, s], [-s, c]])


@pytest.fixture
def twisted():
    """A star and a differently shaped star turned by 160 degrees: straight
    vertex paths fold triangles over on the way."""
    return ring(12, inner=0.5), turned(ring(12, inner=0.7, jitter=False) * 1.3, 160)


def orientation(a, b, c):
    ax, ay, bx, by, cx, cy = map(Fraction, (*a, *b, *c))
    value = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (value > 0) - (value < 0)


def count_inverted(xy, faces):
    return sum(orientation(xy[a], xy[b], xy[c]) <= 0 for a, b, c in faces.tolist())


def test_convex_morph_sections_are_valid(twisted):
    a, b = twisted
    m = compatmesh.morph([a, b], frames=11)
    assert m["sections"].shape == (11, m["sections"].shape[1], 2)
    assert m["t"][0] == 0 and m["t"][-1] == 1
    assert np.array_equal(m["sections"][0][:len(a)], a)
    assert np.array_equal(m["sections"][-1][:len(b)], b)
    for xy, inverted, angle in zip(m["sections"], m["inverted"], m["min_angle_deg"]):
        assert inverted == 0 and count_inverted(xy.tolist(), m["faces"]) == 0
        assert 0 < angle < 60


def test_linear_morph_counts_inversions(twisted):
    m = compatmesh.morph(twisted, t=np.linspace(0, 1, 11), morph_method="linear")
    assert m["inverted"].sum() > 0
    for xy, inverted in zip(m["sections"], m["inverted"]):
        assert count_inverted(xy.tolist(), m["faces"]) == inverted


def test_morph_takes_triangulate_options(twisted):
    plain = compatmesh.morph(twisted, t=0.5, remesh=False)
    remeshed = compatmesh.morph(twisted, t=0.5)
    assert plain["sections"].shape[1] <= remeshed["sections"].shape[1]
    with pytest.raises(TypeError, match="morph\\(\\) got an unexpected keyword argument 'colour'"):
        compatmesh.morph(twisted, t=0.5, colour=1)


def section_area_integral(nodes, z, n):
    sections = nodes.reshape(len(z), -1, 3)
    def area(p):
        return 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    total = 0.0
    for i in range(len(z) - 1):
        low, high = sections[i, :n, :2], sections[i + 1, :n, :2]
        total += (z[i + 1] - z[i]) / 6 * (area(low) + 4 * area((low + high) / 2) + area(high))
    return total


@pytest.mark.parametrize("tets", [False, True])
def test_sweep(twisted, tets):
    a, _ = twisted
    s = compatmesh.sweep(twisted, sections=6, height=2.0, tets=tets)
    z = s["section_z"]
    assert z[0] == 0 and z[-1] == 2.0 and np.all(np.diff(z) > 0) and len(z) >= 6
    nodes, prisms = s["nodes"], s["prisms"]
    nv = len(nodes) // len(z)
    assert nodes.shape == (len(z) * nv, 3) and prisms.shape[1] == 6
    assert np.array_equal(nodes[:len(a), :2], a)
    assert s["volume"] == pytest.approx(section_area_integral(nodes, z, len(a)), rel=1e-9)
    p = nodes[prisms]
    assert np.all(p[:, 3:, 2] > p[:, :3, 2])  # the top above the bottom
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.all(normal[:, 2] > 0)  # bottom counter-clockwise seen from +z
    if tets:
        assert s["tets"].shape == (3 * len(prisms), 4)
        q = nodes[s["tets"]]
        volumes = np.einsum("ij,ij->i", np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]),
                            q[:, 3] - q[:, 0])
        assert np.all(volumes > 0)
    else:
        assert s["tets"].shape == (0, 4)


def test_sweep_heights(twisted):
    s = compatmesh.sweep(twisted, sections=3, heights=[-1.0, 0.5])
    assert s["section_z"][0] == -1.0 and s["section_z"][-1] == 0.5


def test_sweep_heights_from_the_sections_own_z(twisted):
    """Slices of a model (n x 3, each in a plane z = constant, z rounded to
    float as a file may keep it) lie at their own z, as the command line
    takes its inputs' z; given heights win."""
    z1 = float(np.float32(2.1))  # 2.1 through single precision
    sections = [np.c_[twisted[0], np.full(12, -0.5)], np.c_[twisted[1], np.full(12, 2.1)]]
    sections[1][3, 2] = z1
    s = compatmesh.sweep(sections, sections=3)
    assert list(s.section_z) == [-0.5, 0.8, 2.1] and not s.height_is_default
    assert np.array_equal(s.nodes[:12, :2], twisted[0]) and np.all(s.nodes[:12, 2] == -0.5)
    given = compatmesh.sweep(sections, heights=[0, 1], sections=2).section_z
    assert (given[0], given[-1]) == (0, 1)
    flat = [np.c_[p, np.full(12, 3.0)] for p in twisted]  # one plane for both: a drawing, no heights
    assert compatmesh.sweep(flat, sections=2).height_is_default


def test_morph_between_the_sections_own_z(twisted):
    """Sections n x 3 in planes z = constant morph as their (x, y): the
    sections are the n x 2 morph's with z blended between the planes (a
    polygon's own z at its time, as sweep()'s layers), the end sections
    the polygons themselves."""
    sections = [np.c_[twisted[0], np.full(12, -0.5)], np.c_[twisted[1], np.full(12, 2.1)]]
    m = compatmesh.morph(sections, frames=5)
    plain = compatmesh.morph(twisted, frames=5)
    assert m.sections.shape == plain.sections.shape[:2] + (3,)
    assert np.array_equal(m.sections[:, :, :2], plain.sections)
    assert np.allclose(m.sections[:, :, 2], np.linspace(-0.5, 2.1, 5)[:, None], rtol=0, atol=1e-15)
    assert np.array_equal(m.sections[0][:12], sections[0]) and np.array_equal(m.sections[-1][:12], sections[1])
    with pytest.raises(ValueError, match="morph: some polygons lie in a plane z = constant and some do not"):
        compatmesh.morph([sections[0], twisted[1]], frames=3)


def test_sections_auto(twisted):
    """sections="auto" (`--sections auto`): layers about as tall as the
    triangulation's median edge; ten times as tall, about ten times as
    many."""
    low, high = (compatmesh.sweep(twisted, sections="auto", height=h) for h in (10.0, 100.0))
    assert 8 * (len(low.section_z) - 1) <= len(high.section_z) - 1 <= 12 * (len(low.section_z) - 1)


def in_plane(points, origin, turn_deg):
    """Plane points (n x 2) placed in the plane through origin turned by
    turn_deg about the x axis."""
    c, s = np.cos(np.radians(turn_deg)), np.sin(np.radians(turn_deg))
    return np.asarray(origin, float) + points[:, :1] * [1.0, 0, 0] + points[:, 1:] * [0, c, s]


def normal_of(turn_deg):
    return np.array([0, -np.sin(np.radians(turn_deg)), np.cos(np.radians(turn_deg))])


def test_loft_between_turned_planes(tmp_path):
    """Sections of a bent part (n x 3 in planes that are not z = constant)
    are lofted between their planes: the first section's nodes are its
    input, the last lie in its plane, the height is the path between the
    planes' origins, every tetrahedron is positive (its determinant here,
    and Gmsh's Jacobians of the written .msh)."""
    from test_meshio import TET_CORNERS, gmsh_jacobians
    a, b = ring(12, inner=0.5), 1.3 * ring(12, inner=0.7, jitter=False)
    # along a bend of radius 4 about the line y = 4, z = 0, whose planes
    # meet there, outside the sections
    bend = [(0, 4 - 4 * np.cos(np.radians(t)), 4 * np.sin(np.radians(t))) for t in (0, 30, 60)]
    sections = [in_plane(a, bend[0], 0), in_plane(b, bend[1], -30), in_plane(a, bend[2], -60)]
    s = compatmesh.sweep(sections, sections="auto", tets=True)
    nv = len(s.nodes) // len(s.section_z)
    assert np.array_equal(s.nodes[:12], sections[0])
    last = s.nodes[-nv:]
    assert np.abs((last - sections[2][0]) @ normal_of(-60)).max() < 1e-12
    assert np.abs(last[:12] - sections[2]).max() < 1e-12
    centres = [np.mean(p, axis=0) for p in sections]
    path = sum(np.linalg.norm(centres[g + 1] - centres[g]) for g in range(2))
    assert s.height == pytest.approx(path, rel=1e-12) and s.section_z[0] == 0
    corners = s.nodes[s.tets]
    det = np.linalg.det(corners[:, 1:] - corners[:, :1])
    assert len(s.tets) > 0 and det.min() > 0
    s.write(tmp_path / "loft.msh", cells="tetra")
    types, jac = gmsh_jacobians(tmp_path / "loft.msh", 4, TET_CORNERS)
    assert 4 in types and jac.size == 4 * len(s.tets) and jac.min() > 0
    assert 0 < s.volume and s.quality["min_dihedral_deg"] > 0


def test_morph_of_sections_in_space():
    """Sections in turned planes morph in space: the first and last sections
    are the polygons' meshes as triangulate() gives them (the inputs' own
    vertices), the middle one lies between the planes."""
    a, b = ring(12, inner=0.5), 1.3 * ring(12, inner=0.7, jitter=False)
    bend = [(0, 4 - 4 * np.cos(np.radians(t)), 4 * np.sin(np.radians(t))) for t in (0, 30)]
    sections = [in_plane(a, bend[0], 0), in_plane(b, bend[1], -30)]
    m = compatmesh.morph(sections, frames=3)
    assert m.sections.shape[0] == 3 and m.sections.shape[2] == 3
    assert np.array_equal(m.sections[0][:12], sections[0]) and np.array_equal(m.sections[2][:12], sections[1])
    middle = m.sections[1]
    assert np.all(middle[:, 2] > 0) and np.all((middle - bend[1]) @ normal_of(-30) < 0)


def test_loft_that_folds_is_refused(twisted):
    """Planes crossing inside the polygons fold the straight blend: a
    ValueError saying so. A section listed the other way round runs
    clockwise in its plane (its normal on the side of the one before): the
    index correspondence refuses it as a mirror image, auto reverses it and
    the loft is valid."""
    a = ring(12, inner=0.5)
    crossing = [in_plane(a, (0, 0, 0), 0), in_plane(a, (0, 0, 0.3), 80)]
    with pytest.raises(ValueError, match="is not positive in space"):
        compatmesh.sweep(crossing, tets=True)
    reversed_one = [in_plane(a, (0, 0, 0), 10), in_plane(a[::-1], (0, 0, 2), 20)]
    with pytest.raises(compatmesh.InputError, match="would mirror the shape"):
        compatmesh.sweep(reversed_one)
    s = compatmesh.sweep(reversed_one, correspondence="auto", tets=True)
    corners = s.nodes[s.tets]
    assert np.linalg.det(corners[:, 1:] - corners[:, :1]).min() > 0


@pytest.mark.parametrize("call, error, message", [
    (lambda p: compatmesh.morph(p, t=1.5), ValueError, "morph: t = 1.5 is outside \\[0, 1\\]"),
    (lambda p: compatmesh.morph(p, frames=1), ValueError, "frames must be 2 to 1000"),
    (lambda p: compatmesh.morph(p, t=0.5, frames=3), TypeError, "exactly one of t and frames"),
    (lambda p: compatmesh.morph(p, t=0.5, morph_method="bezier"), ValueError,
     "unknown morph_method 'bezier'"),
    (lambda p: compatmesh.sweep(p, heights=[1.0, 0.0]), ValueError,
     "sweep: heights must increase strictly"),
    (lambda p: compatmesh.sweep(p, heights=[0.0, 1.0, 2.0]), ValueError,
     "heights has 3 values for 2 polygons"),
    (lambda p: compatmesh.sweep(p, sections=1), ValueError, "sweep: sections must be .auto. or 2 to 10000, got 1"),
    (lambda p: compatmesh.sweep(p, height=-1.0), ValueError, "height must be positive"),
    (lambda p: compatmesh.sweep([p[0], p[1][:-1]], correspondence="index"), compatmesh.InputError,
     "polygon 1 has 11 vertices but polygon 0 has 12"),
    (lambda p: compatmesh.sweep([p[0], np.c_[p[1], 1 + 0.1 * p[1][:, 0]]]),
     ValueError, "polygon 1: expected an n x 2 array, or n x 3 arrays for every polygon"),
    (lambda p: compatmesh.sweep([np.c_[p[0], 0.1 * p[0][:, 0]], np.c_[p[1], 1 + 0.1 * p[1][:, 0]]], height=2.0),
     ValueError, "the polygons lie in planes of space, which place them: give no height or heights"),
    (lambda p: compatmesh.sweep([np.c_[p[0], np.zeros(12)], p[1]]), ValueError,
     "some polygons lie in a plane z = constant and some do not"),
    (lambda p: compatmesh.sweep([np.c_[p[0], np.ones(12)], np.c_[p[1], np.zeros(12)]]), ValueError,
     "polygon 1 lies at z = 0.0, not above polygon 0 at z = 1.0"),
])
def test_bad_arguments(twisted, call, error, message):
    with pytest.raises(error, match=message):
        call(twisted)


@pytest.mark.parametrize("function, stage", [(compatmesh.morph, "morph system"),
                                             (compatmesh.sweep, "sweep")])
def test_progress_reaches_and_cancels_the_morph_and_sweep(twisted, function, stage):
    stages = []
    def progress(fraction, name):
        stages.append(name)
        return name == stage  # stop there
    kwargs = {"t": 0.5} if function is compatmesh.morph else {}
    with pytest.raises(compatmesh.Cancelled):
        function(twisted, progress=progress, **kwargs)
    assert stages[-1] == stage
    assert "enclosure" in stages  # the morph reported before


def test_progress_errors_propagate(twisted):
    def progress(fraction, name):
        if name == "morph system":
            raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        compatmesh.morph(twisted, t=0.5, progress=progress)


def test_sweep_default_height_follows_the_size(twisted):
    """Without height or heights the sweep is as tall as the largest
    bounding-box diagonal, as on the command line."""
    big = [300.0 * np.asarray(p) for p in twisted]
    s = compatmesh.sweep(big, sections=3)
    diagonal = max(np.hypot(*np.ptp(p, axis=0)) for p in big)
    assert s["nodes"][:, 2].min() == 0 and s["nodes"][:, 2].max() == pytest.approx(diagonal, rel=1e-15)
    assert s["height"] == s["nodes"][:, 2].max() and s["height_is_default"]
    assert s["morph"] == "convex"  # its prisms need no more than max_refine sections
    given = compatmesh.sweep(big, sections=3, height=50.0)
    assert given["height"] == 50.0 and not given["height_is_default"]


def test_sweep_quality_matches_the_tetrahedra(twisted):
    """The quality figures are those of the returned tetrahedra, recomputed
    here: the smallest and largest dihedral angle and the scaled Jacobian
    (6 V over the largest product of a corner's three edge lengths, times
    sqrt 2)."""
    s = compatmesh.sweep(twisted, tets=True)
    p = s["nodes"][s["tets"]]
    angles = []
    for i, j, k, l in [(0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)]:
        e = p[:, j] - p[:, i]
        n1, n2 = np.cross(e, p[:, k] - p[:, i]), np.cross(e, p[:, l] - p[:, i])
        angles.append(np.degrees(np.arctan2(np.linalg.norm(np.cross(n1, n2), axis=1),
                                            np.einsum("ij,ij->i", n1, n2))))
    angles = np.array(angles)
    q = s["quality"]
    assert q["min_dihedral_deg"] == pytest.approx(angles.min(), abs=1e-9)
    assert q["max_dihedral_deg"] == pytest.approx(angles.max(), abs=1e-9)
    six_volume = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    length = lambda a, b: np.linalg.norm(p[:, a] - p[:, b], axis=1)
    products = np.array([length(0, 1) * length(0, 2) * length(0, 3), length(1, 0) * length(1, 2) * length(1, 3),
                         length(2, 0) * length(2, 1) * length(2, 3), length(3, 0) * length(3, 1) * length(3, 2)])
    assert q["min_scaled_jacobian"] == pytest.approx((np.sqrt(2) * six_volume / products.max(axis=0)).min(), rel=1e-9)
    assert q["min_dihedral_deg"] > 5 and q["flat_prisms"] == 0
