"""Polylines as MeshLab writes sections: OBJ with one `l a b` line per edge
(in any order and direction) and PLY edge meshes (ASCII, binary little and
big endian). The polygon follows the first edge; its vertices reach the
output bit for bit; a file that is not one closed polyline is a one-line
error naming the file and the line (or, in binary files, the edge)."""
import random
import struct

import pytest

from polygons import read_vertex_text, star, write_xy


def shuffled_edges(n, seed):
    """The loop's edges, the first kept first, the rest shuffled and some
    reversed, as Compute Planar Section leaves them."""
    rng = random.Random(seed)
    edges = [(i, (i + 1) % n) for i in range(n)]
    rest = edges[1:]
    rng.shuffle(rest)
    return [edges[0]] + [(b, a) if rng.random() < 0.5 else (a, b) for a, b in rest]


def write_obj(path, points, edges, z=0.0):
    with open(path, "w") as f:
        f.write("# section\n")
        for x, y in points:
            f.write(f"v {x!r} {y!r} {z!r}\n")
        for a, b in edges:
            f.write(f"l {a + 1} {b + 1}\n")


def write_ply(path, points, edges, fmt="ascii", z=0.0, faces=0, coordinate="double"):
    """fmt: ascii, binary_little_endian or binary_big_endian."""
    header = (f"ply\nformat {fmt} 1.0\ncomment made by the tests\nelement vertex {len(points)}\n"
              f"property {coordinate} x\nproperty {coordinate} y\nproperty {coordinate} z\n"
              f"property uchar red\nelement edge {len(edges)}\nproperty int vertex1\nproperty int vertex2\n"
              f"element face {faces}\nproperty list uchar int vertex_indices\nend_header\n")
    if fmt == "ascii":
        body = "".join(f"{x!r} {y!r} {z!r} 7\n" for x, y in points) + "".join(f"{a} {b}\n" for a, b in edges)
        path.write_text(header + body)
        return
    end = "<" if fmt == "binary_little_endian" else ">"
    c = "d" if coordinate == "double" else "f"
    body = b"".join(struct.pack(end + 3 * c + "B", x, y, z, 7) for x, y in points)
    body += b"".join(struct.pack(end + "ii", a, b) for a, b in edges)
    path.write_bytes(header.encode() + body)


def boundary_of(tmp_path, name, n):
    return [list(p[:2]) for p in read_vertex_text(tmp_path / "out" / f"{name}.off", "off")[:n]]


@pytest.mark.parametrize("fmt", ["obj", "ascii", "binary_little_endian", "binary_big_endian"])
def test_sections_read_in_loop_order(cm, tmp_path, fmt):
    points = star(23, 5)
    edges = shuffled_edges(23, 1)
    # The first edge runs from vertex 4 backwards: the polygon starts at 4
    # and walks 4, 3, 2, ... (clockwise, which the core reverses).
    rotated = points[4:] + points[:4]
    edges = [(4, 3)] + [e for e in edges if set(e) != {3, 4}]
    path = tmp_path / ("a.obj" if fmt == "obj" else "a.ply")
    (write_obj(path, points, edges) if fmt == "obj" else write_ply(path, points, edges, fmt))
    expected = [points[(4 - i) % 23] for i in range(23)]
    write_xy(tmp_path / "b.xy", [(2 * x + 1, y) for x, y in expected])
    r = cm("triangulate", path.name, "b.xy", "-o", "out")
    assert r.returncode == 0, r.stderr
    got = boundary_of(tmp_path, path.stem, 23)
    assert got == [list(p) for p in expected], "the polygon is not the loop, bit for bit"
    assert rotated  # the loop covers every vertex once


def test_float_ply_keeps_the_floats(cm, tmp_path):
    """MeshLab stores floats: a binary float PLY's coordinates come back as
    those floats exactly."""
    points = [(float(struct.unpack("f", struct.pack("f", x))[0]), float(struct.unpack("f", struct.pack("f", y))[0]))
              for x, y in star(12, 3)]
    write_ply(tmp_path / "a.ply", points, [(i, (i + 1) % 12) for i in range(12)], "binary_little_endian",
              coordinate="float")
    write_xy(tmp_path / "b.xy", star(12, 4))
    r = cm("triangulate", "a.ply", "b.xy", "-o", "out")
    assert r.returncode == 0, r.stderr
    assert boundary_of(tmp_path, "a", 12) == [list(p) for p in points]


def loop_edges(n, start=0):
    return [(start + i, start + (i + 1) % n) for i in range(n)]


SQUARE8 = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0), (0.0, 2.0), (0.0, 1.0)]
TWO_LOOPS = SQUARE8 + [(x + 5, y) for x, y in SQUARE8]
# name: (points, edges, OBJ message, ASCII PLY message, binary PLY message)
BAD = {
    # Two loops are a polygon with a hole; the other input has none.
    "two_loops": (TWO_LOOPS, loop_edges(8) + loop_edges(8, 8),
                  r"b\.xy: polygon 1 has 0 holes but polygon 0 has 1",
                  r"b\.xy: polygon 1 has 0 holes but polygon 0 has 1",
                  r"b\.xy: polygon 1 has 0 holes but polygon 0 has 1"),
    "open": (SQUARE8, loop_edges(8)[:-1],
             r"a\.obj:10: the polyline is not closed: vertex 1 has only this edge",
             r"a\.ply:23: the polyline is not closed: vertex 0 has only this edge",
             r"a\.ply: edge 0: the polyline is not closed: vertex 0 has only this edge"),
    "branching": (SQUARE8, loop_edges(8) + [(1, 5)],
                  r"a\.obj:18: vertex 2 has a third edge \(the others at lines 10 and 11\): the polyline branches",
                  r"a\.ply:31: vertex 1 has a third edge \(the others at lines 23 and 24\): the polyline branches",
                  r"a\.ply: edge 8: vertex 1 has a third edge \(the others at edges 0 and 1\)"),
    "out_of_range": (SQUARE8, loop_edges(8)[:-1] + [(7, 8)],
                     r"a\.obj:17: vertex index 9 is out of range \(the file has 8 vertices\)",
                     r"a\.ply:30: vertex index 8 is out of range",
                     r"a\.ply: edge 7: vertex index 8 is out of range"),
    "loop_to_itself": (SQUARE8, loop_edges(8) + [(3, 3)],
                       r"a\.obj:18: an edge from vertex 4 to itself",
                       r"a\.ply:31: an edge from vertex 3 to itself",
                       r"a\.ply: edge 8: an edge from vertex 3 to itself"),
}


@pytest.mark.parametrize("case", sorted(BAD))
@pytest.mark.parametrize("fmt", ["obj", "ascii", "binary_big_endian"])
def test_bad_polylines(cm, tmp_path, case, fmt):
    points, edges, obj_message, ascii_message, binary_message = BAD[case]
    name = "a.obj" if fmt == "obj" else "a.ply"
    if fmt == "obj":
        write_obj(tmp_path / name, points, edges)
    else:
        write_ply(tmp_path / name, points, edges, fmt)
    write_xy(tmp_path / "b.xy", star(8, 2))
    r = cm("triangulate", name, "b.xy", "-o", "out")
    message = {"obj": obj_message, "ascii": ascii_message}.get(fmt, binary_message)
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1
    assert __import__("re").match("compatmesh: " + message, r.stderr), r.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("fmt", ["obj", "ply"])
@pytest.mark.parametrize("off_plane, accepted", [(2e-6, True), (1e-3, False)])
def test_section_z_up_to_float_rounding(cm, tmp_path, fmt, off_plane, accepted):
    """MeshLab computes a section's points in single precision: its OBJ of
    the plane z = -9.485472 (sh2.stl) has vertices at z = -9.485474, a
    float's last digits away. Such a section is in the plane; a vertex 1e-3
    off it (of a polygon 10 across) is not."""
    points = [(5 * x, 5 * y) for x, y in star(11, 3)]
    z = [-9.4854719999999997] + [-9.4854719999999997 + (off_plane if i % 3 == 1 else 0) for i in range(1, 11)]
    edges = [(i, (i + 1) % 11) for i in range(11)]
    if fmt == "obj":
        text = "".join(f"v {x!r} {y!r} {zi!r}\n" for (x, y), zi in zip(points, z))
        text += "".join(f"l {a + 1} {b + 1}\n" for a, b in edges)
    else:
        text = ("ply\nformat ascii 1.0\nelement vertex 11\nproperty double x\nproperty double y\n"
                "property double z\nelement edge 11\nproperty int vertex1\nproperty int vertex2\nend_header\n")
        text += "".join(f"{x!r} {y!r} {zi!r}\n" for (x, y), zi in zip(points, z))
        text += "".join(f"{a} {b}\n" for a, b in edges)
    (tmp_path / f"a.{fmt}").write_text(text)
    write_xy(tmp_path / "b.xy", star(11, 4))
    r = cm("triangulate", f"a.{fmt}", "b.xy", "-o", "out", "--no-remesh")
    if accepted:
        assert r.returncode == 0, r.stderr
        assert boundary_of(tmp_path, "a", 11) == [list(p) for p in points]
    else:
        assert r.returncode == 2 and "the polygon is not planar" in r.stderr, r.stderr


@pytest.mark.parametrize("content, message", [
    (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nelement face 1\n"
     b"property list uchar int vertex_indices\nend_header\n0 0\n1 0\n0 1\n3 0 1 2\n",
     r"a\.ply: 1 faces; expected an edge mesh"),
    (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nend_header\n0 0\n1 0\n0 1\n",
     r"a\.ply: no element edge"),
    (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
     b"element edge 3\nproperty int vertex1\nproperty int vertex2\nend_header\n" + b"\0" * 30,
     r"a\.ply: the file ends in edge 0 of 3"),
    (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
     b"element edge 3\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0\n1 zero\n",
     r"a\.ply:11: 'zero' is not a finite number"),
    (b"ply\nformat ascii 2.0\nend_header\n", r"a\.ply:2: expected 'format ascii\|binary_little_endian"),
    (b"PLY\n", r"a\.ply:1: not a PLY file"),
    (b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
     b"element edge 4\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0 1\n1 0 1\n1 1 2\n0 1 1\n"
     b"0 1\n1 2\n2 3\n3 0\n",
     r"a\.ply:1[1-4]: the polygon is not planar: vertex \d is 0\.\d+ away from the best-fitting plane"),
])
def test_bad_ply_files(cm, tmp_path, content, message):
    (tmp_path / "a.ply").write_bytes(content)
    write_xy(tmp_path / "b.xy", star(3, 2))
    r = cm("triangulate", "a.ply", "b.xy", "-o", "out")
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert __import__("re").match("compatmesh: " + message, r.stderr), r.stderr


def test_binary_file_errors_name_the_vertex(cm, tmp_path):
    """The core's errors point into a binary file by vertex index."""
    points = [(0.0, 0.0), (2.0, 0.0), (0.0, 2.0), (2.0, 2.0)]  # a bow tie
    write_ply(tmp_path / "a.ply", points, loop_edges(4), "binary_little_endian")
    write_xy(tmp_path / "b.xy", [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)])
    r = cm("triangulate", "a.ply", "b.xy", "-o", "out")
    assert r.returncode == 2
    assert __import__("re").match(r"compatmesh: a\.ply: vertex \d: .*cross", r.stderr), r.stderr
