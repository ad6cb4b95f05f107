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
