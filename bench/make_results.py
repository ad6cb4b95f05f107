"""Writes bench/RESULTS.md from a finished benchmark run.

usage: make_results.py RUN_DIR OUT.md

RUN_DIR is what bench/run_bench.sh leaves: input/pairs.txt (the pairs, in
order), status.tsv (pair, exit code, wall seconds) and PAIR/report.json for
every pair that succeeded.
"""
import datetime
import json
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


def read_status(run_dir):
    """{name: (exit code, wall seconds)}."""
    status = {}
    path = os.path.join(run_dir, "status.tsv")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                name, code, wall = line.rstrip("\n").split("\t")
                status[name] = (int(code), float(wall))
    return status


def read_report(run_dir, name):
    path = os.path.join(run_dir, name, "report.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


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


def fmt_angle(degrees):
    # small angles keep two significant digits instead of printing 0.0
    return "%.1f" % degrees if degrees >= 1 else "%.2g" % degrees


def fmt_angles(report):
    return " / ".join(fmt_angle(m["min_angle_deg"]) for m in report["meshes"])


def result_row(name, report):
    return "| %s | %d | %d | %d | %d | %s | %.3g | %s |" % (
        name, report["k"], report["n"], report["steiner"],
        report["triangles"], fmt_angles(report),
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
    return "| %s | %d | %s | | | **FAILED** (%s) | %.3g | |" % (
        name, len(files), n, why, wall)


def run_date(run_dir):
    """When the run finished: the time status.tsv was last written."""
    path = os.path.join(run_dir, "status.tsv")
    stamp = os.path.getmtime(path) if os.path.exists(path) else None
    return datetime.datetime.fromtimestamp(
        stamp if stamp is not None else datetime.datetime.now().timestamp(),
        datetime.timezone.utc)


def header(run_dir, pairs, failures, version):
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
        "",
        "Minimum angles are per mesh, in the order of the inputs; time is "
        "`seconds.total` of report.json (validation, construction and the "
        "exact check).",
        "",
        "| pair | k | n | Steiner | triangles | min angle per mesh (deg) "
        "| time (s) | method |",
        "|---|---:|---:|---:|---:|---|---:|---|",
    ]
    return lines


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    run_dir, out = argv[1], argv[2]
    pairs = read_pairs(run_dir)
    status = read_status(run_dir)
    rows, failures, version = [], [], "?"
    for name, files in pairs:
        report = read_report(run_dir, name)
        ok = status.get(name, (None,))[0] == 0 and report is not None
        if ok:
            version = report.get("version", version)
            rows.append(result_row(name, report))
        else:
            failures.append(name)
            rows.append(failure_row(run_dir, name, files, status))
    lines = header(run_dir, pairs, failures, version) + rows
    if failures:
        lines += ["", "**Failed pairs:** " + ", ".join(failures)]
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
