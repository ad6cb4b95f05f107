#!/usr/bin/python3
"""The default pipeline's growth with the input's size, on sections of real
parts, side by side with CGAL meshing each polygon alone.

    remesh_scale.py --compatmesh BIN [--cgal BIN] [--ns 160,320,640,1280,2560]
                    [--modes index,auto] [--pairs DIR [--only REGEX]]
                    [--timeout SECONDS] [--json FILE]

The pairs: the planar sections of Gmsh's STL models the hard family holds
(bench/stl_sections.py: one part cut at two heights, and two different
parts), each outer loop resampled by arc length to n points for every n of
--ns, as a user pairs the dense sections MeshLab cuts from a fine model
(a size at which a section resamples to a polygon that is not simple, a
thin wall's two sides crossing, is left out and said so). --pairs adds the
pairs of a `cm_gen_pairs` folder whose names match --only, each polygon
resampled the same way (e.g. the hard family's glyphs at n = 160: their
outlines as 160-gons, with points added along the edges; the hard pairs
whose arc-length correspondence the remesher cannot make good, where its
time per triangle is highest).
Each pair runs through `compatmesh triangulate` in every mode (index: vertex
i on vertex i, arc length from the bottom-left points; auto: the tool
chooses), one process per run (remesh_bench.run_compatmesh), and CGAL's
mesher meshes each polygon alone at 25 degrees (remesh_bench.run_cgal).

Per run: CPU seconds (user + system) and peak resident memory, the output's
triangles and Steiner vertices, the smallest angle, the CPU per thousand
output triangles, and the CPU over CGAL's for both polygons. Per mode and
pair: the exponent of CPU time in the output's triangles and in n (least
squares on log-log over the sizes, partition_scale.slope, and between
neighbouring sizes). A
remesher whose time grows near-linearly with its output has an exponent in
triangles near 1.
"""
import argparse
import json
import os
import re
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stl_sections  # noqa: E402
from make_results import read_xy  # noqa: E402
from partition_scale import slope  # noqa: E402
from remesh_bench import Pair, run_cgal, run_compatmesh  # noqa: E402


def triangles(run):
    """Output triangles of a run without holes: 2 Steiner + boundary - 2."""
    return 2 * run["steiner"] + run["boundary"] - 2


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--compatmesh", required=True)
    ap.add_argument("--cgal", default=None)
    ap.add_argument("--ns", default="160,320,640,1280,2560")
    ap.add_argument("--modes", default="index,auto")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--pairs", default=None)
    ap.add_argument("--only", default="")
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    ns = [int(x) for x in a.ns.split(",")]
    modes = a.modes.split(",")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        skipped = lambda name, message: print("remesh_scale: left out: " + message, file=sys.stderr)
        written = stl_sections.write_pairs(os.path.join(tmp, "pairs"), ns, skipped)
        for line in open(os.path.join(a.pairs, "pairs.txt")) if a.pairs else ():
            name, *files = line.split()
            if re.search(a.only, name):
                loops = [np.asarray(read_xy(os.path.join(a.pairs, f)), dtype=float) for f in files]
                written += stl_sections.write_resampled(os.path.join(tmp, "pairs"), name.rsplit("_n", 1)[0], loops,
                                                        ns, skipped)
        for name, files in written:
            pair = Pair(name, "hard", files)
            row = {"name": name, "section": name.rsplit("_n", 1)[0], "n": pair.n,
                   "cgal": run_cgal(a.cgal, pair, a.timeout) if a.cgal else None, "runs": {}}
            for mode in modes:
                run = run_compatmesh(a.compatmesh, pair, mode, tmp, a.timeout)
                if not run["valid"]:
                    sys.exit("remesh_scale: %s (%s): %s" % (name, mode, run.get("error", "not valid")))
                run["triangles"] = triangles(run)
                row["runs"][mode] = run
                print("%s %s: %.2f s, %d triangles, %.2f degrees" %
                      (name, mode, run["cpu_s"], run["triangles"], run["min_angle_deg"]), file=sys.stderr)
            rows.append(row)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    print("| pair | n | mode | CPU s | MB | triangles | Steiner | angle | ms per 1,000 triangles "
          "| CGAL CPU s | x CGAL |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        for mode, run in r["runs"].items():
            cg = r["cgal"]["cpu_s"] if r["cgal"] and "cpu_s" in r["cgal"] else None
            print("| %s | %d | %s | %.3f | %.0f | %d | %d | %.2f | %.0f | %s | %s |" % (
                r["section"], r["n"], mode, run["cpu_s"], run["rss_mb"], run["triangles"], run["steiner"],
                run["min_angle_deg"], 1e6 * run["cpu_s"] / run["triangles"],
                "%.4f" % cg if cg else "-", "%.0f" % (run["cpu_s"] / cg) if cg else "-"))
    print()
    print("| pair | mode | exponent in triangles | exponent in n | between sizes (in triangles) |")
    print("|---|---|---:|---:|---|")
    for section in sorted({r["section"] for r in rows}):
        sized = sorted((r for r in rows if r["section"] == section), key=lambda r: r["n"])
        for mode in modes:
            runs = [(r["n"], r["runs"][mode]) for r in sized]
            by_tri = slope([(run["triangles"], run["cpu_s"]) for _, run in runs])
            by_n = slope([(n, run["cpu_s"]) for n, run in runs])
            steps = [slope([(x["triangles"], x["cpu_s"]), (y["triangles"], y["cpu_s"])])
                     for (_, x), (_, y) in zip(runs, runs[1:])]
            print("| %s | %s | %.2f | %.2f | %s |" % (section, mode, by_tri, by_n,
                                                      ", ".join("%.2f" % s if s is not None else "-" for s in steps)))


if __name__ == "__main__":
    main()
