#!/usr/bin/python3
"""The partition against CGAL's mesher, two builds side by side in one run.

    partition_vs_cgal.py --old OLD/cm_partition_bench --new NEW/cm_partition_bench
                         --cgal cm_cgal_single --pairs BENCH --hard HARD
                         [--max-n N] [--min-cpu S] [--commit REV] [--out FILE]

BENCH from `cm_gen_pairs --set bench`, HARD from `cm_gen_pairs --set hard`.
Both benches are this source's bench/partition_bench.c (OLD built against
the older library: copy the file into the older tree and build its
cm_partition_bench target). Each runs every pair with --cgal: the
partition's in-process CPU time (validate + build + check) beside CGAL's
meshing CPU time of each polygon alone, summed, measured in the same run.
Writes a Markdown table per pair (ratios partition / CGAL, old and new, and
new / old), the median ratios at n <= 160 overall and per family, and the
growth exponents of time in n per family (least squares on log-log).
"""
import argparse
import datetime
import math
import os
import statistics
import subprocess
import sys
import tempfile

TARGET_N = 160


def run_bench(binary, args, tsv):
    cmd = [binary, "--pairs", args.pairs, "--hard", args.hard, "--cgal", args.cgal,
           "--min-cpu", str(args.min_cpu), "--max-n", str(args.max_n),
           "--out", os.devnull, "--tsv", tsv]
    p = subprocess.run(cmd, capture_output=True, text=True)
    # Exit status 1 flags a missed Steiner-free pair or an invalid result:
    # still a measurement, reported below; anything else is a failure.
    if p.returncode not in (0, 1) or not os.path.exists(tsv):
        sys.exit(f"partition_vs_cgal: {' '.join(cmd)} failed:\n{p.stderr[-2000:]}")
    rows = {}
    for line in open(tsv):
        name, family, n, steiner, part, cgal = line.rstrip("\n").split("\t")
        rows[name] = dict(family=family, n=int(n), steiner=int(steiner), part=float(part), cgal=float(cgal))
    return rows


def slope(points):
    """Least-squares exponent of t in n; None with a single size."""
    if len({n for n, _ in points}) < 2:
        return None
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def fmt(v, digits=2):
    return "-" if v is None else f"{v:.{digits}f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--old", required=True)
    ap.add_argument("--new", required=True)
    ap.add_argument("--cgal", required=True)
    ap.add_argument("--pairs", required=True)
    ap.add_argument("--hard", required=True)
    ap.add_argument("--max-n", type=int, default=2000)
    ap.add_argument("--min-cpu", type=float, default=0.05)
    ap.add_argument("--commit", default="")
    ap.add_argument("--out", default="-")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        old = run_bench(args.old, args, os.path.join(tmp, "old.tsv"))
        new = run_bench(args.new, args, os.path.join(tmp, "new.tsv"))
    names = [k for k in new if k in old and old[k]["cgal"] > 0 and new[k]["cgal"] > 0]
    lines = []
    out = lines.append
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
    out(f"Run on {date}{', commit ' + args.commit if args.commit else ''}: `bench/partition_vs_cgal.py "
        f"--max-n {args.max_n} --min-cpu {args.min_cpu:g}`, the old bench first, then the new one.")
    out("CPU milliseconds in process; CGAL: its Delaunay mesher at 25 degrees on each polygon alone,")
    out("summed over the pair, timed in each run beside the partition (old / new: each run's own).")
    out("")
    ratio = lambda r: r["part"] / r["cgal"]
    small = [k for k in names if new[k]["n"] <= TARGET_N]
    if small:
        out(f"- median partition / CGAL at n <= {TARGET_N}: old {statistics.median(ratio(old[k]) for k in small):.2f}, "
            f"new {statistics.median(ratio(new[k]) for k in small):.2f} ({len(small)} pairs); "
            f"median new / old partition time {statistics.median(new[k]['part'] / old[k]['part'] for k in small):.2f}")
    families = sorted({new[k]["family"] for k in names})
    for fam in families:
        ks = [k for k in names if new[k]["family"] == fam]
        ks_small = [k for k in ks if new[k]["n"] <= TARGET_N]
        e_old = slope([(old[k]["n"], old[k]["part"]) for k in ks])
        e_new = slope([(new[k]["n"], new[k]["part"]) for k in ks])
        e_cgal = slope([(new[k]["n"], new[k]["cgal"]) for k in ks])
        med = lambda rows: fmt(statistics.median(ratio(rows[k]) for k in ks_small)) if ks_small else "-"
        out(f"  - {fam}: median partition / CGAL at n <= {TARGET_N} old {med(old)}, new {med(new)} "
            f"({len(ks_small)} pairs); time ~ n^e, e = {fmt(e_old)} old, {fmt(e_new)} new, {fmt(e_cgal)} CGAL "
            f"(n {min(new[k]['n'] for k in ks)}..{max(new[k]['n'] for k in ks)})")
    steiner_changed = [k for k in names if old[k]["steiner"] != new[k]["steiner"]]
    out(f"- pairs whose Steiner count differs between the builds: {len(steiner_changed)}"
        + (" (" + ", ".join(steiner_changed) + ")" if steiner_changed else ""))
    out("")
    out("| pair | family | n | Steiner | CGAL ms (old run) | CGAL ms (new run) | old ms | new ms | new / old |"
        " old / CGAL | new / CGAL |")
    out("|---|---|---|---|---|---|---|---|---|---|---|")
    for k in names:
        o, n = old[k], new[k]
        out(f"| {k} | {n['family']} | {n['n']} | {n['steiner']} | {1e3 * o['cgal']:.3f} | {1e3 * n['cgal']:.3f} | "
            f"{1e3 * o['part']:.3f} | {1e3 * n['part']:.3f} | {n['part'] / o['part']:.2f} | {ratio(o):.1f} | {ratio(n):.1f} |")
    text = "\n".join(lines) + "\n"
    if args.out == "-":
        sys.stdout.write(text)
    else:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
