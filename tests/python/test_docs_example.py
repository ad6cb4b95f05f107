"""The README's Python example (docs/examples/pair.py) runs as written."""
import pathlib
import re
import subprocess
import sys

import pytest

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples" / "pair.py"


def test_readme_example_runs():
    run = subprocess.run([sys.executable, str(EXAMPLE)], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 3 and "triangles" in lines[0]
    assert all("smallest angle" in line for line in lines[1:])


def test_cad_sections_example_runs(tmp_path):
    """docs/examples/cad_sections.py: two CAD sections with a bolt hole,
    their boundaries meshed by Gmsh, paired, swept and read back by Gmsh
    with every prism positive and the boundary's four named surfaces, then
    solved by CalculiX with second-order prisms pressed on the top."""
    script = EXAMPLE.parent / "cad_sections.py"
    run = subprocess.run([sys.executable, str(script), str(tmp_path)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 5, run.stdout
    assert lines[0].startswith("loops: [") and lines[0].count("[") == 2  # outer loop and hole, per section
    angle = float(lines[1].split("smallest angle ")[1].split()[0])
    assert angle >= 20  # well-shaped: both sections' corners are right angles or rounded
    prisms, determinant = int(lines[2].split()[0]), float(lines[2].rsplit(" ", 1)[1])
    assert prisms > 0 and determinant > 0 and (tmp_path / "bracket.msh").exists()
    groups = dict(part.rsplit(" ", 2)[:2] for part in lines[3].removeprefix("boundary: ").split(", "))
    assert sorted(groups) == ["bottom", "hole_1", "side", "top"] and groups["bottom"] == groups["top"]
    # The top's pressure goes to the bottom whole (nothing else holds the
    # part): the reaction is 100 MPa times the top section's area.
    held, area = (float(v) for v in re.fullmatch(
        r"CalculiX: the bottom holds (\S+) kN against 100 MPa on (\S+) mm2", lines[4]).groups())
    assert 500 < area < 900 and held * 1000 == pytest.approx(100 * area, rel=1e-5)


def readme_code_block(language):
    """The README's only code block in `language`."""
    readme = (EXAMPLE.parents[2] / "README.md").read_text()
    blocks = readme.split("```" + language + "\n")[1:]
    assert len(blocks) == 1, f"README.md must hold exactly one {language} block"
    return blocks[0].split("```")[0]


def test_readme_shows_the_examples_as_run():
    assert readme_code_block("python") == EXAMPLE.read_text()
    assert readme_code_block("cpp") == (EXAMPLE.parent / "pair.cc").read_text()
    assert readme_code_block("c") == (EXAMPLE.parent / "pair.c").read_text()
