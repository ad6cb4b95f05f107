"""bench/remesh_bench.py: the corner-fan cap worked out by hand, and the
script run on three tiny pairs (no bound, no CGAL: both have their own
checks), with the same build as its own baseline and with a baseline that
fails."""
import json
import math
import os
import resource
import subprocess
import sys

import pytest

BENCH = os.path.join(os.path.dirname(__file__), "..", "..", "bench")
sys.path.insert(0, BENCH)
import remesh_bench as rb  # noqa: E402

CLI = os.environ["COMPATMESH"]
GEN = os.environ["CM_GEN_PAIRS"]
SCRIPT = os.path.join(BENCH, "remesh_bench.py")
TINY = ["hold_random_disc_n48_s3001", "glyph_2_Z_n40", "twisted_star_n16"]


@pytest.mark.parametrize("theta, cap", [
    ((60, 60), 60),     # one equilateral triangle in both
    ((90, 90), 45),     # one right isosceles triangle, or two 45-degree ones
    ((180, 180), 60),   # a flat corner: three equilateral triangles
    ((270, 90), 30),    # k = 3: 90 / 3 = 30 and 270 / 3 = 90 <= 180 - 60
    ((10, 170), 5),     # k = 1 fits 170 only with alpha = 5
])
def test_corner_fan_cap(theta, cap):
    assert rb.corner_fan_cap(theta) == pytest.approx(cap)


def test_fan_cap_is_the_worst_corner():
    square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    kite = [(0, 0), (1, 0), (3, 3), (0, 1)]  # corners 90, 71.6, 18.4 (at (3, 3)), ...
    assert rb.fan_cap([square, square]) == pytest.approx(45)
    worst = min(rb.corner_fan_cap(t) for t in zip(rb.corner_angles(square), rb.corner_angles(kite)))
    assert rb.fan_cap([square, kite]) == pytest.approx(worst) and worst < 45


def test_edge_cap_by_hand():
    # a 4 x 1 box: the tallest isosceles triangle on a long edge has height
    # 1 (the opposite edge), so its base angles are at most atan(2 / 4); the
    # short edges allow atan(2 * 4 / 1)
    box = [(0, 0), (4, 0), (4, 1), (0, 1)]
    assert rb.edge_cap(box) == pytest.approx(math.degrees(math.atan(0.5)))
    assert rb.edge_cap(box[::-1]) == pytest.approx(rb.edge_cap(box))
    # a spike from the bottom up to (2, 0.9), 0.1 under the top edge's middle
    spike = [(0, 0), (1.9, 0), (2, 0.9), (2.1, 0), (4, 0), (4, 1), (0, 1)]
    assert rb.edge_cap(spike) == pytest.approx(math.degrees(math.atan(2 * 0.1 / 4)))



def test_near_vertex_cap_by_hand():
    # a notch from the top down to p = (3.2, 0.3), 0.8 short of the bottom
    # edge's end b = (4, 0): the bottom edge's triangle must keep p out, so
    # its angle at b stays within phi_b = atan(0.3 / 0.8), and the triangle
    # across its side from b holds p unless it splits phi_b: at most
    # phi_b / 2 (above atan(2 * 0.3 / 4), an apex at p's height, and the
    # 5.4 degrees at a of p itself as the apex); the isosceles edge cap
    # allows phi_b whole
    notch = [(0, 0), (4, 0), (4, 2), (3.7, 2), (3.2, 0.3), (2.7, 2), (0, 2)]
    cap = math.degrees(math.atan(0.3 / 0.8)) / 2
    assert rb.near_vertex_cap(notch) == pytest.approx(cap)
    assert rb.near_vertex_cap(notch[::-1]) == pytest.approx(cap)
    assert rb.edge_cap(notch) == pytest.approx(2 * cap)
    # a 4 x 1 box: each far corner, seen at 90 degrees from a long edge's
    # end, allows 45 (the isosceles cap, 26.6, binds there)
    box = [(0, 0), (4, 0), (4, 1), (0, 1)]
    assert rb.near_vertex_cap(box) == pytest.approx(45)


def test_aims_count_rounding_ties_only():
    # a corner of 25.6 degrees split in halves: 12.8 each in exact arithmetic,
    # a few units in the last place below it in doubles
    c = 25.6
    assert rb.reaches(c / 2 - 2e-15, c / 2) and rb.reaches(c / 2 * (1 - 1e-11), c / 2)
    assert not rb.reaches(c / 2 - 1e-5, c / 2) and not rb.reaches(0.999 * 20, 20)
    runs = [(c, 12.8 - 2e-15), (60.0, 20.0), (60.0, 19.99), (30.0, 10.0)]
    rows = [{"c": c, "half": "tune", "runs": {"auto": {"new": {"valid": True, "min_angle_deg": a, "to_T": 1.0,
                                                                "steiner": 1, "cpu_s": 1.0, "under20_pct": [0, 0]}}}}
            for c, a in runs]
    s = rb.summarize(rows, "new", "auto", "all")
    assert s["at_min(20,c/2)"] == 2  # 12.8 tie and 20.0; not 19.99, not 10 against 15
    assert s["at_min(15,c/3)"] == 4  # 10.0 reaches min(15, 30 / 3) = 10, 19.99 reaches 15, 12.8 reaches 8.5
    assert s["at_least_0.55T"] == 4


def bench(tmp_path, *extra):
    out, raw = tmp_path / "out.md", tmp_path / "out.json"
    run = subprocess.run([sys.executable, SCRIPT, "--compatmesh", CLI, "--gen-pairs", GEN,
                          "--no-bound", "--no-cgal", "--only", "^(%s)$" % "|".join(TINY),
                          "--out", str(out), "--json", str(raw), *extra],
                         capture_output=True, text=True, timeout=300)
    return run, out, raw


def test_peak_memory_is_the_command_s_own():
    """The peak RSS is the measured program's, not this Python process's,
    whose pages a child holds until it execs: a program that touches 64 MB
    peaks above that, /bin/true far below this process's own peak."""
    _, cpu, small, _, _ = rb.run_measured(["/bin/true"], 10, peak_rss=True)
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    assert own > 20 and small < 8 and cpu >= 0
    code, _, big, _, _ = rb.run_measured(["/usr/bin/python3", "-c", "b = bytearray(64 << 20)"], 30, peak_rss=True)
    assert code == 0 and 64 < big < 200
    assert math.isnan(rb.run_measured(["/bin/true"], 10)[2])


def test_tiny_pairs_against_themselves(tmp_path):
    run, out, raw = bench(tmp_path, "--baseline", CLI)
    assert run.returncode == 0, run.stderr
    result = json.loads(raw.read_text())
    assert sorted(r["name"] for r in result["pairs"]) == sorted(TINY)
    for r in result["pairs"]:
        assert 0 < r["T"] <= 25 and r["T"] <= r["c"] / 2 and r["bound_deg"] is None
        assert r["T_index"] == min(r["T"], r["edge"])
        for label in ("new", "baseline"):
            x = r["runs"]["index"][label]
            assert x["valid"] and x["exit"] == 0, (r["name"], x)
            # index mode keeps every boundary edge: no triangle beats the edge cap
            assert x["min_angle_deg"] <= r["edge"] * (1 + 1e-9)
            assert 0 < x["min_angle_deg"] <= 60 and x["to_T"] == pytest.approx(x["min_angle_deg"] / r["T_index"])
            assert len(x["under20_pct"]) == 2 and x["cpu_s"] > 0 and x["rss_mb"] > 0
            # no triangle is better than its own map allows
            assert x["min_angle_deg"] <= x["map_cap_deg"] * (1 + 1e-9) and x["map_cap_deg"] <= 60
            assert x["angle_to_map_cap"] == pytest.approx(x["min_angle_deg"] / x["map_cap_deg"])
        # the same deterministic build on both sides
        assert r["versus"]["index"]["angle"] == 1 and r["versus"]["index"]["steiner"] in (1, None)
    text = out.read_text()
    for name in TINY:
        assert "| %s |" % name in text
    everything = [s for s in result["summary"] if s["group"] == "all"]
    assert [s["build"] for s in everything] == ["new", "baseline"]
    assert all(s["pairs"] == 3 and s["invalid"] == 0 for s in everything)
    assert "all pairs" in text and "New over baseline" in text


def test_a_failing_baseline_is_reported_and_fails(tmp_path):
    broken = tmp_path / "broken"
    broken.write_text("#!/bin/sh\necho 'compatmesh: broken on purpose' >&2\nexit 3\n")
    broken.chmod(0o755)
    run, out, raw = bench(tmp_path, "--baseline", str(broken))
    assert run.returncode == 1
    assert run.stderr.count("(index, baseline) is not valid") == len(TINY)
    result = json.loads(raw.read_text())
    for r in result["pairs"]:
        assert r["runs"]["index"]["new"]["valid"]
        assert r["runs"]["index"]["baseline"] == dict(r["runs"]["index"]["baseline"], valid=False, exit=3)
    assert out.read_text().count("**no**: compatmesh: broken on purpose") == len(TINY)


def test_build_args_reach_their_side_only(tmp_path):
    run, out, raw = bench(tmp_path, "--compatmesh-args=--remesher map", "--baseline", CLI,
                          "--baseline-args=--remesher none")
    assert run.returncode == 1
    assert run.stderr.count("(index, baseline) is not valid") == len(TINY)
    result = json.loads(raw.read_text())
    assert [b["path"] for b in result["meta"]["builds"]] == [CLI + " --remesher map", CLI + " --remesher none"]
    for r in result["pairs"]:
        assert r["runs"]["index"]["new"]["valid"] and not r["runs"]["index"]["baseline"]["valid"]
    assert "unknown --remesher 'none'" in out.read_text()


def test_missing_cgal_is_a_usage_error(tmp_path):
    run = subprocess.run([sys.executable, SCRIPT, "--compatmesh", CLI, "--gen-pairs", GEN,
                          "--cgal", str(tmp_path / "none"), "--out", str(tmp_path / "x.md")],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and "--cgal" in run.stderr and "--no-cgal" in run.stderr
    assert not (tmp_path / "x.md").exists()


def test_a_new_run_keeps_the_dated_sections(tmp_path):
    """The report's dated sections (readings of earlier runs, which the
    README cites) survive a new run; the last run's own section and
    tables are replaced, not added to."""
    meta = {"date": "2026-01-02 03:04 UTC", "machine": "m", "cores": 2, "load": [0.0, 0.0],
            "command": "remesh_bench.py", "commit": "c", "builds": [{"label": "new", "path": "p", "version": "v", "startup_s": 0.004}],
            "cgal": None, "bound": False, "modes": ["index"]}
    result = {"meta": meta, "pairs": [], "summary": [], "versus": []}
    out = tmp_path / "REMESH.md"
    rb.write_markdown(str(out), result)
    first = out.read_text()
    assert first.count("## Full run (2026-01-02 03:04 UTC)") == 1 and "## Affine pairs" not in first
    dated = "## Affine pairs (2025-12-31)\n\n- read by hand\n\n"
    at = first.index("## Full run")
    out.write_text(first[:at] + dated + first[at:])
    meta["date"] = "2026-02-03 04:05 UTC"
    rb.write_markdown(str(out), result)
    second = out.read_text()
    assert second.count(dated) == 1 and second.index(dated) < second.index("## Full run")
    assert "2026-01-02" not in second and second.count("## Full run (2026-02-03 04:05 UTC)") == 1
    assert second.count("## Summary") == 1 and second.startswith("# Remesher benchmark")


def test_cgal_inside_its_process_and_compatmesh_less_its_start_up(tmp_path):
    """The in-process ratio: CGAL's meshing timed inside its process (the
    repeated run's mesh_cpu_s, both polygons), compatmesh's CPU less its
    start-up; a fake cm_cgal_single says which run is which."""
    fake = tmp_path / "cgal"
    fake.write_text("#!/bin/sh\n[ $# -eq 3 ] && t=0.0005 || t=0.002\n"
                    "echo steiner 3 boundary_steiner 1 triangles 9 min_angle_deg 25.1 mesh_cpu_s $t repeats 1\n")
    fake.chmod(0o755)
    files = [tmp_path / "a.xy", tmp_path / "b.xy"]
    for f in files:
        f.write_text("0 0\n1 0\n0 1\n")
    pair = rb.Pair("hold_p", "hard", [str(f) for f in files])
    assert "mesh_s" not in rb.run_cgal(str(fake), pair, 10)
    cgal = rb.run_cgal(str(fake), pair, 10, in_process=True)
    assert cgal["steiner"] == [3, 3] and cgal["mesh_s"] == pytest.approx(0.001) and cgal["cpu_s"] >= 0
    run = rb.derive({"valid": True, "min_angle_deg": 10.0, "steiner": 6, "cpu_s": 0.104}, 20.0, cgal, 0.004)
    assert run["in_process_to_cgal"] == pytest.approx(100) and run["to_T"] == 0.5
    startup = rb.startup_cpu(CLI)
    assert 0 < startup < 0.5
