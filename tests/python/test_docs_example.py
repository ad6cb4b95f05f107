"""The README's Python example (docs/examples/pair.py) runs as written."""
import pathlib
import subprocess
import sys

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples" / "pair.py"


def test_readme_example_runs():
    run = subprocess.run([sys.executable, str(EXAMPLE)], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 3 and "triangles" in lines[0]
    assert all("smallest angle" in line for line in lines[1:])


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
