"""Every pair with holes in the tests and the bench, through the default
pipeline of the entry point that tests it, in one Markdown table: the
smallest input corner c, the floor min(15, c/3), Steiner vertices, the
smallest angle per mesh, valid, whether both meshes reach the floor.

usage: /usr/bin/python3 bench/holes_table.py BUILD_DIR [--no-meshlab]

Sources (each distinct pair once; a pair several tests share is named by
all of them):
  cm_glyph_holes             the 12 glyph pairs, index (the bench's default)
                             and auto
  cm_glyph_holes --fixtures  tests/core/hole_fixtures.h (test_holes.c,
                             test_alloc_failures.c), index where the loops'
                             sizes agree and auto where they differ (the
                             rule of the command line and the Python module)
  the command line           tests/cli/test_holes.py's plate (report.json)
  the Python module          tests/python/test_holes.py's plate
  the MeshLab filter         tests/meshlab's lever sections: lever.stl cut by
                             MeshLab, paired by docs/meshlab/pair.mlx (auto)
Not counted: tests/openmesh/test_loops.cc's square/disc pair (C++ geometry
of its own, auto; the same kind as "square/disc, sizes differ").

Exit status 0 when every pair is valid, 1 otherwise.
"""
import importlib.util
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from make_results import corner_angles, quality_aims  # noqa: E402

# The C fixtures other tests triangulate too (the same loops).
ALSO = {
    "square/disc": "; tests/cli/test_holes.py, tests/python/test_holes.py (index)",
    "square/disc, sizes differ": "; tests/cli/test_holes.py, tests/python/test_holes.py (auto)",
}
HEADER = ("| source | pair | mode | holes | n | c | min(15, c/3) | aim | Steiner | min angle (deg) | valid | "
          "reaches min(15, c/3) |\n|---|---|---|---:|---:|---:|---:|---:|---:|---|---|---|")


def test_module(directory, name):
    """A test module by its path (tests/cli and tests/python both have a
    test_holes.py)."""
    spec = importlib.util.spec_from_file_location("%s_%s" % (directory, name),
                                                  os.path.join(ROOT, "tests", directory, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def smallest_corner(polygons):
    """The smallest corner of the material over every loop (outer loop
    first): a hole's corner is 360 minus its loop's interior angle."""
    return min(a if l == 0 else 360 - a
               for loops in polygons for l, loop in enumerate(loops) for a in corner_angles(loop))


def row(source, name, mode, polygons, steiner, angles, n, aim):
    c = smallest_corner(polygons)
    floor = quality_aims(c)[1]
    good = all(a >= floor for a in angles)
    return "| %s | %s | %s | %d | %d | %.1f | %.2f | %s | %d | %s | yes | %s |" % (
        source, name, mode, len(polygons[0]) - 1, n, c, floor, "" if aim is None else "%.1f" % aim, steiner,
        " / ".join("%.1f" % a for a in angles), "yes" if good else "**no**")


def glyph_rows(build):
    rows = []
    for args in ([], ["--auto"], ["--fixtures"]):
        run = subprocess.run([os.path.join(build, "bin", "cm_glyph_holes"), "--markdown", "--min-good", "0", *args],
                             capture_output=True, text=True)
        lines = [l for l in run.stdout.splitlines() if l.startswith("|")]
        if run.returncode != 0 or not lines:
            raise RuntimeError("cm_glyph_holes %s: %s" % (" ".join(args), run.stderr.strip()))
        for line in lines:
            cells = line.split(" | ")
            if cells[0] == "| test_holes.c":
                cells[0] = "| tests/core/" + ("test_alloc_failures.c" if "test_alloc" in cells[1] else "test_holes.c")
                cells[0] += ALSO.get(cells[1], "")
                cells[1] = cells[1].replace(" (test_alloc_failures.c)", "")
            else:
                cells[0] = "| bench glyphs"
            rows.append(" | ".join(cells))
    return rows


def cli_row(build, work):
    sys.path.insert(0, os.path.join(ROOT, "tests", "cli"))
    t = test_module("cli", "test_holes")
    PLATE, PLATE_MOVED, xy_text = t.PLATE, t.PLATE_MOVED, t.xy_text
    for name, loops in (("a.xy", PLATE), ("b.xy", PLATE_MOVED)):
        with open(os.path.join(work, name), "w") as f:
            f.write(xy_text(loops))
    out = os.path.join(work, "cli")
    run = subprocess.run([os.path.join(build, "bin", "compatmesh"), "triangulate", "a.xy", "b.xy", "--out-dir", out],
                         cwd=work, capture_output=True, text=True)
    if run.returncode != 0:
        return "| tests/cli/test_holes.py | plate, sheared and turned | index | | | | | | | | **no**: %s | no |" % (
            run.stderr.strip())
    report = json.load(open(os.path.join(out, "report.json")))
    assert report["valid"]
    return row("tests/cli/test_holes.py", "plate, sheared and turned", report["correspondence"], [PLATE, PLATE_MOVED],
               report["steiner"], [m["min_angle_deg"] for m in report["meshes"]], report["n"], report["remesh_aim_deg"])


def python_row(build):
    sys.path.insert(0, os.path.join(build, "python"))
    import compatmesh
    t = test_module("python", "test_holes")
    PLATE, PLATE_MOVED = t.PLATE, t.PLATE_MOVED
    plate = [loop.tolist() for loop in PLATE]
    moved = [loop.tolist() for loop in PLATE_MOVED]
    result = compatmesh.triangulate([plate, moved])
    return row("tests/python/test_holes.py", "plate, sheared and moved", "index", [plate, moved],
               result.stats["steiner"], [q["min_angle_deg"] for q in result.stats["quality"]], result.stats["n"],
               result.stats["remesh_aim_deg"])


def meshlab_row(build, work):
    sys.argv = [sys.argv[0], os.path.join(build, "bin", "meshlabserver-compatmesh"),
                os.path.join(ROOT, "docs", "meshlab"), "none"]
    sys.path.insert(0, os.path.join(ROOT, "tests", "meshlab"))
    import meshlab_cases as mc
    w = os.path.join(work, "meshlab")
    os.makedirs(w)
    sections = mc.cut_lever(w)
    code, log = mc.run(w, ["a.obj", "b.obj"], os.path.join(mc.DOCS, "pair.mlx"), {2: "pa.ply", 3: "pb.ply"})
    m = re.search(r"compatible triangulation: (\d+) boundary vertices, (\d+) Steiner vertices", log)
    angles = re.search(r"smallest angle: ([\d.]+) deg in '[^']*', ([\d.]+) deg", log)
    if code != 0 or not m or not angles:
        return "| tests/meshlab (lever_sections, lever_volume) | lever sections | auto | | | | | | | | **no** | no |"
    # x and y: the cuts are across the plate, one tilted by 0.02 (corners change by less than 0.01 degree)
    polygons = [[[p[:2] for p in loop] for loop in s] for s in sections]
    return row("tests/meshlab (lever_sections, lever_volume)", "lever.stl sections", "auto", polygons,
               int(m.group(2)), [float(a) for a in angles.groups()], int(m.group(1)), None)


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    build = os.path.abspath(argv[1])
    rows = glyph_rows(build)
    with tempfile.TemporaryDirectory() as work:
        rows.append(cli_row(build, work))
        rows.append(python_row(build))
        if "--no-meshlab" not in argv:
            rows.append(meshlab_row(build, work))
    print(HEADER)
    print("\n".join(rows))
    valid = sum(r.split(" | ")[-2] == "yes" for r in rows)
    good = sum(r.endswith("| yes |") for r in rows)
    print("\n%d pairs with holes: %d valid, %d (%.0f %%) reach min(15, c/3) in both meshes" % (
        len(rows), valid, good, 100.0 * good / len(rows)))
    return 0 if valid == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
