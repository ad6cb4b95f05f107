"""The paper's Figure 8: U and S from DejaVu Sans, compatibly triangulated
and remeshed. Surazhsky and Gotsman report 17.1 and 17.6 degrees with 7
Steiner vertices (Fig. 8(e)-(f)); compatmesh must do at least as well on
the angles, with a stated Steiner bound. The glyph pairs come from
cm_gen_pairs (FreeType), in feature-matched correspondence."""
import json
import os
import subprocess

import pytest

GEN = os.environ["CM_GEN_PAIRS"]
CLI = os.environ["COMPATMESH"]

# (pair, smallest angle promised per mesh, Steiner bound)
FIXTURES = [
    ("glyph_U_S_n40", (17.1, 17.6), 30),
    ("glyph_U_S_n80", (17.1, 17.6), 120),
    ("glyph_2_Z_n80", (24.0, 24.0), 40),
    # C and G: the C's lower terminal needs the forced moves (12.5 degrees
    # without them; 15.8 and 17.3 with)
    ("glyph_C_G_n40", (15.5, 15.5), 40),
]


@pytest.fixture(scope="module")
def pairs(tmp_path_factory):
    out = tmp_path_factory.mktemp("pairs")
    subprocess.run([GEN, "--out", str(out), "--set", "bench"], check=True,
                   capture_output=True, timeout=300)
    return out


@pytest.mark.parametrize("name,angles,max_steiner", FIXTURES)
def test_glyph_pair_quality(pairs, tmp_path, name, angles, max_steiner):
    inputs = [str(pairs / f"{name}_{g}.xy") for g in "ab"]
    run = subprocess.run([CLI, "triangulate", *inputs, "-o", str(tmp_path / "out")],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    got = [mesh["min_angle_deg"] for mesh in report["meshes"]]
    assert all(g >= a for g, a in zip(got, angles)), (name, got, angles)
    assert report["steiner"] <= max_steiner, (name, report["steiner"])
