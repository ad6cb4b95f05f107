"""Writes bench/RESULTS.md from a finished benchmark run.

usage: make_results.py RUN_DIR OUT.md

RUN_DIR is what bench/run_bench.sh leaves: input/pairs.txt (the pairs, in
order), status.tsv (pair, exit code, wall seconds), PAIR/report.json for
every pair that succeeded, cgal.tsv (single-polygon meshing by CGAL, when
built), bound.tsv (correspondence_bound.py per pair) and table1.md (the paper's Table 1, appended as it is).
"""
import datetime
import json
import math
import os
import platform
import subprocess
import sys


def read_pairs(run_dir):
    """[(name, [files])] in the order of pairs.txt."""
    pairs = []
    with open(os.path.join(run_dir, "input", "pairs.txt")) as f:
        for line in f:
            words = line.split()
            if words:
                pairs.append((words[0], words[1:]))
    return pairs


def tsv_rows(run_dir, name):
    """The tab-separated fields of each line of RUN_DIR/name (none if the
    file is missing: that part of the bench did not run)."""
    path = os.path.join(run_dir, name)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [line.rstrip("\n").split("\t") for line in f]


def read_status(run_dir):
    """{name: (exit code, wall seconds)}."""
    return {name: (int(code), float(wall)) for name, code, wall in tsv_rows(run_dir, "status.tsv")}


def read_report(run_dir, name):
    path = os.path.join(run_dir, name, "report.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def read_cgal(run_dir):
    """{pair: [(steiner, boundary steiner, min angle) per polygon]} from
    cgal.tsv, when the bench could run CGAL."""
    cgal = {}
    for name, _, result in tsv_rows(run_dir, "cgal.tsv"):
        words = result.split()  # "key value" pairs, or "failed"
        fields = dict(zip(words[::2], words[1::2])) if len(words) % 2 == 0 else {}
        value = None
        if {"steiner", "boundary_steiner", "min_angle_deg"} <= fields.keys():
            value = (int(fields["steiner"]), int(fields["boundary_steiner"]), float(fields["min_angle_deg"]))
        cgal.setdefault(name, []).append(value)
    return cgal


def read_alone(run_dir):
    """{pair: [smallest angle of each polygon remeshed alone, or None]}."""
    alone = {}
    for name, _, angle in tsv_rows(run_dir, "alone.tsv"):
        alone.setdefault(name, []).append(None if angle == "failed" else float(angle))
    return alone


def read_bound(run_dir):
    """{pair: (bound degrees, K)} from bound.tsv (correspondence_bound.py)."""
    bound = {}
    for name, result in tsv_rows(run_dir, "bound.tsv"):
        words = result.split()
        bound[name] = (float(words[0]), float(words[1])) if len(words) == 3 else None
    return bound


def fmt_bound(entry):
    return "%.1f (K %.3g)" % entry if entry else "not run"


def fmt_cgal(entries):
    """"S (B on the boundary) / ..." per polygon, "-" when CGAL failed."""
    if not entries:
        return ""
    return " / ".join("%d (%d)" % (e[0], e[1]) if e else "failed" for e in entries)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def source_revision():
    """Short commit of the source tree, marked when it has local changes."""
    src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    try:
        rev = subprocess.run(["git", "-C", src, "rev-parse", "--short", "HEAD"],
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", src, "status", "--porcelain",
                                "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    return rev + (" with local changes" if dirty else "")


def read_loops(path):
    """The loops of an .xy polygon, outer loop first: a line beginning with
    '>' ends a loop (the command line's format)."""
    loops = [[]]
    with open(path) as f:
        for line in f:
            if line.startswith(">"):
                if loops[-1]:
                    loops.append([])
                continue
            line = line.split("#")[0].replace(",", " ").split()
            if line:
                loops[-1].append((float(line[0]), float(line[1])))
    return [loop for loop in loops if loop]


def read_xy(path):
    """The points of an .xy polygon without holes."""
    return read_loops(path)[0]


def corner_angles(points):
    """The interior angle at each vertex of a simple polygon, in degrees."""
    n = len(points)
    area2 = sum(points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1]
                for i in range(n))
    sign = 1 if area2 > 0 else -1
    angles = []
    for i in range(n):
        (x0, y0), (x1, y1), (x2, y2) = points[i - 1], points[i], points[(i + 1) % n]
        ux, uy, vx, vy = x2 - x1, y2 - y1, x0 - x1, y0 - y1
        angles.append(math.degrees(math.atan2(sign * (ux * vy - uy * vx), ux * vx + uy * vy)) % 360)
    return angles


def smallest_corner(points):
    """The smallest interior angle of a simple polygon, in degrees."""
    return min(corner_angles(points))


def quality_aims(c):
    """What the remesher should reach on a pair whose smallest input corner
    is c degrees: with interior Steiner vertices only, a corner whose ear is
    poor must be split, so c/2 is what can be promised there. The aim, met
    on 95 % of the pairs, and the floor, met on all."""
    return min(25.0, c / 2) - 1, min(15.0, c / 3)


def fmt_angle(degrees):
    # small angles keep two significant digits instead of printing 0.0
    return "%.1f" % degrees if degrees >= 1 else "%.2g" % degrees


def fmt_angles(report):
    return " / ".join(fmt_angle(m["min_angle_deg"]) for m in report["meshes"])


def verdict(angle, c):
    aim, floor = quality_aims(c)
    return "aim" if angle >= aim else ("floor" if angle >= floor else "**below**")


def result_row(name, report, c, cgal, alone, bound):
    worst = min(m["min_angle_deg"] for m in report["meshes"])
    alone_text = " / ".join(fmt_angle(a) if a is not None else "failed" for a in alone)
    return "| %s | %d | %d | %s | %s | %d | %d | %d | %s | %s | %s | %s | %.3g | %s |" % (
        name, report["k"], report["n"], fmt_angle(c), fmt_bound(bound),
        report.get("steiner_before_remesh", 0), report["steiner"], report["triangles"],
        fmt_angles(report), verdict(worst, c), alone_text, fmt_cgal(cgal.get(name)),
        report["seconds"]["total"], report["method"])


def count_vertices(path):
    try:
        with open(path) as f:
            return str(sum(1 for line in f if line.strip()))
    except OSError:
        return ""


def failure_row(run_dir, name, files, status):
    code, wall = status.get(name, (None, 0.0))
    why = "not run" if code is None else (
        "timed out" if code == 124 else "exit %d" % code)
    n = count_vertices(os.path.join(run_dir, "input", files[0])) if files else ""
    return "| %s | %d | %s | | | | | | **FAILED** (%s) | | | | %.3g | |" % (
        name, len(files), n, why, wall)


def run_date(run_dir):
    """When the run finished: the time status.tsv was last written."""
    path = os.path.join(run_dir, "status.tsv")
    stamp = os.path.getmtime(path) if os.path.exists(path) else None
    return datetime.datetime.fromtimestamp(
        stamp if stamp is not None else datetime.datetime.now().timestamp(),
        datetime.timezone.utc)


def header(run_dir, pairs, failures, version, verdicts, alone_aim, beyond):
    now = run_date(run_dir)
    revision = source_revision()
    if revision:
        version += ", commit " + revision
    lines = [
        "# Benchmark results",
        "",
        "Compatible triangulations computed by `compatmesh triangulate` "
        "(compatmesh %s) for the benchmark pairs made by `cm_gen_pairs --set "
        "bench`: glyph outlines from DejaVu Sans, random stars, spirals and "
        "combs against discs, twisted correspondences and random simple "
        "polygons." % version,
        "",
        "- Machine: %s, %d cores (`nproc`)" % (cpu_model(), os.cpu_count() or 0),
        "- Date: %s" % now.strftime("%Y-%m-%d %H:%M UTC"),
        "- Regenerate with `make bench`",
        "- Pairs: %d, failed: %d" % (len(pairs), len(failures)),
        "- Quality (default options: partition, then remeshing to 25 degrees): "
        "smallest angle at least the aim min(25, c/2) - 1 on %d of %d pairs, "
        "at least the floor min(15, c/3) on %d of %d, c being the pair's "
        "smallest input corner" % (verdicts.count("aim"), len(verdicts),
                                   len(verdicts) - verdicts.count("**below**"),
                                   len(verdicts)),
        "- On the %d pairs whose polygons each reach the aim when remeshed alone, "
        "the pair reaches it on %d. The gap is the correspondence: where it maps "
        "a long thin part onto a short stretch of the other polygon (a spiral arm "
        "or a comb tooth onto an arc of a disc, the third arm of a T onto the end "
        "of an L), every compatible mesh is stretched there, however fine; on "
        "pairs of similar shape (U and S, 2 and Z) the pair comes within a few "
        "degrees of the polygons alone." % alone_aim,
        "- No compatible triangulation of the pair, with any number of Steiner "
        "vertices, can have a smallest angle above its bound "
        "(`bench/correspondence_bound.py`: the correspondence forces a modulus "
        "distortion K somewhere, and triangles with angles of at least alpha in "
        "both polygons allow at most K(alpha), the largest dilatation between two such triangles). The bound is below the aim on "
        "%d of %d pairs: %s. On those the aim cannot be reached; on the other "
        "%d pairs compatmesh reaches it on %d." % (
            len(beyond[0]), len(verdicts), ", ".join(beyond[0]) or "none",
            len(verdicts) - len(beyond[0]), beyond[1]),
        "",
        "c: smallest input corner angle over the pair's polygons (degrees); "
        "bound: the correspondence bound (degrees) and the modulus distortion K "
        "it comes from; "
        "Steiner before: the first compatible triangulation's; minimum angles "
        "are per mesh, in the order of the inputs; reaches: the best of aim, "
        "floor, below that the smallest angle reaches; alone: the smallest "
        "angle of each polygon remeshed on its own (paired with itself); "
        "CGAL alone: the "
        "Steiner vertices CGAL's Delaunay mesher adds to each polygon meshed "
        "on its own at 25 degrees (in brackets those on the boundary, which "
        "compatmesh never splits), the price of compatibility; time is "
        "`seconds.total` of report.json (validation, construction, "
        "remeshing and the exact check).",
        "",
        "| pair | k | n | c | bound | Steiner before | Steiner | triangles "
        "| min angle per mesh (deg) | reaches | alone (deg) | CGAL alone | time (s) | method |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---|---|---|---|---:|---|",
    ]
    return lines


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    run_dir, out = argv[1], argv[2]
    pairs = read_pairs(run_dir)
    status = read_status(run_dir)
    cgal, alone, bound = read_cgal(run_dir), read_alone(run_dir), read_bound(run_dir)
    rows, failures, version, verdicts = [], [], "?", []
    beyond = [[], 0]  # pairs whose bound is below the aim; aims reached elsewhere
    alone_aim = [0, 0]
    for name, files in pairs:
        report = read_report(run_dir, name)
        ok = status.get(name, (None,))[0] == 0 and report is not None
        if ok:
            version = report.get("version", version)
            c = min(smallest_corner(read_xy(os.path.join(run_dir, "input", f)))
                    for f in files)
            rows.append(result_row(name, report, c, cgal, alone.get(name, []), bound.get(name)))
            worst = min(m["min_angle_deg"] for m in report["meshes"])
            verdicts.append(verdict(worst, c))
            if bound.get(name) and bound[name][0] < quality_aims(c)[0]:
                beyond[0].append(name)
            else:
                beyond[1] += verdicts[-1] == "aim"
            angles = alone.get(name, [])
            if angles and all(a is not None and verdict(a, c) == "aim" for a in angles):
                alone_aim[0] += 1
                alone_aim[1] += verdicts[-1] == "aim"
        else:
            failures.append(name)
            rows.append(failure_row(run_dir, name, files, status))
    lines = header(run_dir, pairs, failures, version, verdicts, tuple(alone_aim), beyond) + rows
    if failures:
        lines += ["", "**Failed pairs:** " + ", ".join(failures)]
    table1 = os.path.join(run_dir, "table1.md")
    if os.path.exists(table1):
        with open(table1) as f:
            lines += ["", f.read().rstrip("\n")]
    # Sections recorded by other runs (`make soak`) are kept.
    kept = ""
    if os.path.exists(out):
        with open(out) as f:
            previous = f.read()
        start = previous.find("\n## Soak")
        if start >= 0:
            kept = previous[start:]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n" + kept)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
