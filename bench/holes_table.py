"""Every pair with holes in the tests and the bench, through the default
pipeline of the entry point that tests it, in one Markdown table: the
smallest input corner c, the floor min(15, c/3), Steiner vertices, the
smallest angle per mesh, valid, whether both meshes reach the floor.

usage: /usr/bin/python3 bench/holes_table.py BUILD_DIR [--no-meshlab] [--bounds]

--bounds fills the column "bound": bench/correspondence_bound.py on the
pair's loops in the correspondence the run used (index: the loops as
given; auto: the loops as the command line refines and pairs them,
`--correspondence auto --no-remesh`, read back from its meshes), the
largest smallest angle any compatible triangulation of the pair can have
(certified; about 10 s a pair, and the twist search, --twist, on the
pairs short of the floor, about 10 s a hole more), and counts the pairs
short of the floor whose bound is below it: no triangulation reaches the
floor there. The
MeshLab run has no bound (its sections are not written as loops).

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
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import meshio  # noqa: E402

from make_results import corner_angles, quality_aims  # noqa: E402

# The C fixtures other tests triangulate too (the same loops).
ALSO = {
    "square/disc": "; tests/cli/test_holes.py, tests/python/test_holes.py (index)",
    "square/disc, sizes differ": "; tests/cli/test_holes.py, tests/python/test_holes.py (auto)",
    "crowded hole": "; tests/core/test_alloc_failures.c",
}
HEADER = ("| source | pair | mode | holes | n | c | min(15, c/3) | aim | Steiner | bound | min angle (deg) | valid | "
          "reaches min(15, c/3) |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|---|")
# the column the C rows lack, before "min angle"
BOUND_COLUMN = 9


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


def write_loops(path, loops):
    with open(path, "w") as f:
        f.write("".join("> %s\n" % ("hole" if l else "outer loop") + "".join("%r %r\n" % tuple(p) for p in loop)
                        for l, loop in enumerate(loops)))
    return path


def glyph_rows(build, work):
    """(row, pair files) per pair of cm_glyph_holes' runs."""
    rows = []
    for args in ([], ["--auto"], ["--fixtures"]):
        dump = os.path.join(work, "glyphs" + "".join(args).replace("-", "_"))
        os.makedirs(dump)
        run = subprocess.run([os.path.join(build, "bin", "cm_glyph_holes"), "--markdown", "--min-good", "0", *args,
                              "--dump", dump], capture_output=True, text=True)
        lines = [l for l in run.stdout.splitlines() if l.startswith("|")]
        if run.returncode != 0 or not lines:
            raise RuntimeError("cm_glyph_holes %s: %s" % (" ".join(args), run.stderr.strip()))
        for line in lines:
            cells = line.split(" | ")
            # cm_glyph_holes --dump's file names
            clean = re.sub("[/ ,]", "_", cells[1])
            files = [os.path.join(dump, "%s_%s.xy" % (clean, g)) for g in "ab"]
            if cells[0] == "| test_holes.c":
                cells[0] = "| tests/core/" + ("test_alloc_failures.c" if "test_alloc" in cells[1] else "test_holes.c")
                cells[0] += ALSO.get(cells[1], "")
                cells[1] = cells[1].replace(" (test_alloc_failures.c)", "")
            else:
                cells[0] = "| bench glyphs"
            rows.append((" | ".join(cells), files))
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
            run.stderr.strip()), None
    report = json.load(open(os.path.join(out, "report.json")))
    assert report["valid"]
    return row("tests/cli/test_holes.py", "plate, sheared and turned", report["correspondence"], [PLATE, PLATE_MOVED],
               report["steiner"], [m["min_angle_deg"] for m in report["meshes"]], report["n"],
               report["remesh_aim_deg"]), [os.path.join(work, name) for name in ("a.xy", "b.xy")]


def python_row(build, work):
    sys.path.insert(0, os.path.join(build, "python"))
    import compatmesh
    t = test_module("python", "test_holes")
    PLATE, PLATE_MOVED = t.PLATE, t.PLATE_MOVED
    plate = [loop.tolist() for loop in PLATE]
    moved = [loop.tolist() for loop in PLATE_MOVED]
    result = compatmesh.triangulate([plate, moved])
    files = [write_loops(os.path.join(work, "python_%s.xy" % g), loops) for g, loops in zip("ab", (plate, moved))]
    return row("tests/python/test_holes.py", "plate, sheared and moved", "index", [plate, moved],
               result.stats["steiner"], [q["min_angle_deg"] for q in result.stats["quality"]], result.stats["n"],
               result.stats["remesh_aim_deg"]), files


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
        return "| tests/meshlab (lever_sections, lever_volume) | lever sections | auto | | | | | | | | **no** | no |", None
    # x and y: the cuts are across the plate, one tilted by 0.02 (corners change by less than 0.01 degree)
    polygons = [[[p[:2] for p in loop] for loop in s] for s in sections]
    return row("tests/meshlab (lever_sections, lever_volume)", "lever.stl sections", "auto", polygons,
               int(m.group(2)), [float(a) for a in angles.groups()], int(m.group(1)), None), None


def auto_pair(cli, files, work):
    """The loops of an auto run, as the command line refines and pairs
    them, written so that vertex i of loop j corresponds to vertex i of loop
    j: read back from its meshes (same vertex numbers; the loops' vertices
    first, outer loop first), each loop followed along its boundary edges
    from its lowest vertex."""
    out = os.path.join(work, "auto")
    run = subprocess.run([cli, "triangulate", *files, "--correspondence", "auto", "--no-remesh", "--out-dir", out],
                         capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError("%s: %s" % (" ".join(files), run.stderr.strip()))
    meshes = [meshio.read(os.path.join(out, "%s.off" % os.path.splitext(os.path.basename(f))[0])) for f in files]
    shutil.rmtree(out)
    tri = meshes[0].cells_dict["triangle"]
    count = {}
    for t in tri:
        for k in range(3):
            e = frozenset((int(t[k]), int(t[(k + 1) % 3])))
            count[e] = count.get(e, 0) + 1
    around = {}
    for e, c in count.items():
        if c == 1:
            u, v = tuple(e)
            around.setdefault(u, []).append(v)
            around.setdefault(v, []).append(u)
    cycles, seen = [], set()
    for start in sorted(around):
        if start in seen:
            continue
        cycle = [start, min(around[start])]
        while cycle[-1] != start:
            cycle.append(next(w for w in around[cycle[-1]] if w != cycle[-2]))
        cycles.append(cycle[:-1])
        seen.update(cycle)
    return [write_loops(os.path.join(work, "auto_%s.xy" % g), [[m.points[v][:2] for v in c] for c in cycles])
            for g, m in zip("ab", meshes)]


def bound_cell(cli, files, mode, twist, work):
    """bench/correspondence_bound.py's angle and family for a pair (with
    its twist search if twist)."""
    if files is None:
        return ""
    if mode == "auto":
        files = auto_pair(cli, files, work)
    run = subprocess.run([sys.executable, os.path.join(HERE, "correspondence_bound.py"), cli, *files,
                          *(["--twist"] if twist else [])], capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError("correspondence_bound.py %s: %s" % (" ".join(files), run.stderr.strip()))
    angle, _, family = run.stdout.split()
    return "%.2f (%s)" % (float(angle), family)


def main(argv):
    if len(argv) < 2 or argv[1].startswith("-") or not os.path.isdir(argv[1]):
        print(__doc__, file=sys.stderr)
        return 2
    build = os.path.abspath(argv[1])
    cli = os.path.join(build, "bin", "compatmesh")
    with tempfile.TemporaryDirectory() as work:
        pairs = glyph_rows(build, work)
        pairs.append(cli_row(build, work))
        pairs.append(python_row(build, work))
        if "--no-meshlab" not in argv:
            pairs.append(meshlab_row(build, work))
        rows, below = [], 0
        for line, files in pairs:
            cells = line.split(" | ")
            short = cells[-1] != "yes |"
            bound = bound_cell(cli, files, cells[2], short, work) if "--bounds" in argv else ""
            cells.insert(BOUND_COLUMN, bound)
            rows.append(" | ".join(cells))
            if bound and short and float(bound.split()[0]) < float(cells[6]):
                below += 1
    print(HEADER)
    print("\n".join(rows))
    valid = sum(r.split(" | ")[-2] == "yes" for r in rows)
    good = sum(r.endswith("| yes |") for r in rows)
    print("\n%d pairs with holes: %d valid, %d (%.0f %%) reach min(15, c/3) in both meshes" % (
        len(rows), valid, good, 100.0 * good / len(rows)))
    if "--bounds" in argv:
        print("%d short of it, %d of them with the correspondence bound below min(15, c/3): no compatible "
              "triangulation reaches it" % (len(rows) - good, below))
    return 0 if valid == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
