"""docs/figures.py, which makes the README's figures and tables, on a small
pair: the pictures are the tool's own PNGs (or drawn from its .msh), the
table's counts are those of the tool's --report, and the README has every
block the script rewrites. The demo pair and its correspondence bound are
left to the script's real run."""
import importlib.util
import json
import os
import re
import subprocess

from PIL import Image

from polygons import star, write_xy

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")


def load_figures():
    spec = importlib.util.spec_from_file_location("figures", os.path.join(ROOT, "docs", "figures.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_figures_of_a_small_pair(compatmesh_path, tmp_path):
    figures = load_figures()
    a, b = star(10, seed=1), star(10, seed=2, scale=2.0)
    write_xy(tmp_path / "u.xy", a)
    write_xy(tmp_path / "s.xy", b)
    docs = tmp_path / "docs"
    docs.mkdir()
    figures.morph_figure(compatmesh_path, str(tmp_path), str(docs))
    assert (docs / "morph_frames.png").read_bytes() == (tmp_path / "frames" / "frames.png").read_bytes()
    figures.sweep_figure(compatmesh_path, str(tmp_path), str(docs), len(a))
    with Image.open(docs / "sweep.png") as image:
        assert image.size == (figures.WIDTH, figures.HEIGHT)
        colours = {rgb for _, rgb in image.convert("RGB").getcolors(figures.WIDTH * figures.HEIGHT)}
    assert (255, 255, 255) in colours and len(colours) > 50, "a shaded surface on white"

    table = figures.size_table(compatmesh_path, str(tmp_path), a, b)
    rows = [line for line in table.splitlines() if line.startswith("| `")]
    assert len(rows) == len(figures.FORMATS)
    subprocess.run([compatmesh_path, "sweep", "ga.xy", "gb.xy", "--tets", "-o", "t.vtk", "--report",
                    "t.json"], cwd=tmp_path, check=True, capture_output=True)
    report = json.loads((tmp_path / "t.json").read_text())
    assert f"{report['nodes']} nodes and {report['cells']} tetrahedra" in " ".join(table.split())
    assert rows[2].split("|")[3].strip() == f"{round(os.path.getsize(tmp_path / 't.vtk') / 1000)} KB"


def test_readme_has_the_blocks_the_script_rewrites():
    readme = open(os.path.join(ROOT, "README.md")).read()
    names = re.findall(r"<!-- figures.py: ([a-z ]+) -->\n", readme)
    assert names == ["us", "sweep sizes"]
    assert readme.count("<!-- end figures.py -->") == 2
    figures = load_figures()
    for name in names:
        assert figures.replace_block(readme, name, "x") != readme
