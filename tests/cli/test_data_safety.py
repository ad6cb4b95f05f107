"""Nothing the user has is lost: outputs never replace inputs, an endless or
oversized input is refused with a message, long directory names work, and
computed outputs are finite."""
import math
import os

import pytest

from polygons import star, write_xy


def write_obj(path, points):
    with open(path, "w") as f:
        for x, y in points:
            f.write(f"v {x!r} {y!r} 0\n")
        f.write("l " + " ".join(str(i + 1) for i in range(len(points))) + " 1\n")


def test_output_that_would_replace_an_input_is_refused(cm, tmp_path):
    write_obj(tmp_path / "a.obj", star(12, 1))
    write_obj(tmp_path / "b.obj", star(12, 2))
    before = {p: (tmp_path / p).read_bytes() for p in ("a.obj", "b.obj")}
    r = cm("triangulate", "a.obj", "b.obj", "--out-dir", ".", "--format", "obj")
    assert r.returncode == 2
    assert "would replace the input a.obj" in r.stderr
    assert sorted(os.listdir(tmp_path)) == ["a.obj", "b.obj"]
    assert {p: (tmp_path / p).read_bytes() for p in before} == before


def test_report_that_is_an_input_is_not_replaced(cm, tmp_path):
    write_xy(tmp_path / "report.json", star(12, 1))
    write_xy(tmp_path / "b.xy", star(12, 2))
    before = (tmp_path / "report.json").read_bytes()
    r = cm("triangulate", "report.json", "b.xy", "--out-dir", ".")
    assert r.returncode == 2 and "would replace the input report.json" in r.stderr
    assert (tmp_path / "report.json").read_bytes() == before


def test_sweep_output_that_is_an_input_is_refused(cm, tmp_path):
    write_xy(tmp_path / "a.msh", star(12, 1))
    write_xy(tmp_path / "b.xy", star(12, 2))
    before = (tmp_path / "a.msh").read_bytes()
    r = cm("sweep", "a.msh", "b.xy", "-o", "a.msh")
    assert r.returncode == 2 and "would replace the input a.msh" in r.stderr
    assert (tmp_path / "a.msh").read_bytes() == before


def test_endless_input_is_refused_at_the_limit(cm, tmp_path):
    write_xy(tmp_path / "b.xy", star(12, 2))
    r = cm("triangulate", "/dev/zero", "b.xy", "--out-dir", "out")
    assert r.returncode == 2
    assert r.stderr.strip() == ("compatmesh: /dev/zero: larger than 268435456 bytes "
                                "(--max-input-bytes); raise the limit to read it")
    assert not (tmp_path / "out").exists()


def test_max_input_bytes_is_inclusive(cm, tmp_path):
    write_xy(tmp_path / "a.xy", star(12, 1))
    write_xy(tmp_path / "b.xy", star(12, 2))
    size = max(os.path.getsize(tmp_path / p) for p in ("a.xy", "b.xy"))
    assert cm("triangulate", "a.xy", "b.xy", "-o", "out", "--max-input-bytes", size).returncode == 0
    r = cm("triangulate", "a.xy", "b.xy", "-o", "out2", "--max-input-bytes", size - 1)
    assert r.returncode == 2 and "--max-input-bytes" in r.stderr
    assert not (tmp_path / "out2").exists()


def test_longest_directory_name_works(cm, tmp_path):
    write_xy(tmp_path / "a.xy", star(12, 1))
    write_xy(tmp_path / "b.xy", star(12, 2))
    name = "d" * 255  # NAME_MAX: the staging directory beside it must fit too
    r = cm("triangulate", "a.xy", "b.xy", "--out-dir", name)
    assert r.returncode == 0, r.stderr
    assert sorted(os.listdir(tmp_path / name)) == ["a.off", "b.off", "preview.png", "preview.svg", "report.json"]
    assert sorted(os.listdir(tmp_path)) == ["a.xy", "b.xy", name]


@pytest.mark.parametrize("span", ["1e300", "1e308"])
def test_heights_far_apart_give_finite_nodes(cm, tmp_path, span):
    import meshio
    write_xy(tmp_path / "a.xy", star(12, 1))
    write_xy(tmp_path / "b.xy", star(12, 2))
    r = cm("sweep", "a.xy", "b.xy", "-o", "v.vtk", f"--heights=-{span},{span}")
    assert r.returncode == 0, r.stderr
    points = meshio.read(tmp_path / "v.vtk").points
    assert all(math.isfinite(v) for v in points.ravel())
    assert points[:, 2].min() == -float(span) and points[:, 2].max() == float(span)
    if span == "1e308":  # the volume, about 1e309, is reported as such
        assert "volume beyond the double range" in r.stdout
