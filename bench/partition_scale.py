#!/usr/bin/python3
"""The partition's growth with n, two builds side by side in one run.

    partition_scale.py --pairs DIR --old OLD/compatmesh --new NEW/compatmesh [--only SUBSTR]
                       [--full] [--timeout SECONDS]

DIR from `cm_gen_pairs --out DIR --set scale`. Each pair is triangulated
with `compatmesh triangulate --no-remesh` by both builds, one after the
other, under /usr/bin/time -v: CPU seconds (user + system), peak resident
memory, Steiner vertices, overlay fallbacks, smallest angle and validity
(report.json). Prints a Markdown table, the new/old ratios and the growth
exponents of CPU time in n per family (least squares on log-log).
--full runs the default pipeline instead (the partition, the remeshing,
the exact check and every output); a run longer than --timeout seconds
is stopped and shown as "> SECONDS".
"""
import argparse
import json
import math
import os
import re
import signal
import subprocess
import sys
import tempfile


def run(binary, files, out_dir, full=False, timeout=None):
    """One run under /usr/bin/time -v; None when it outlasts timeout (its
    process group is killed)."""
    cmd = ["/usr/bin/time", "-v", binary, "triangulate", *files, *([] if full else ["--no-remesh"]),
           "--out-dir", out_dir]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        return None
    if p.returncode != 0:
        sys.exit(f"partition_scale: {' '.join(cmd)} failed:\n{err[-2000:]}")
    user = float(re.search(r"User time \(seconds\): ([\d.]+)", err).group(1))
    system = float(re.search(r"System time \(seconds\): ([\d.]+)", err).group(1))
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", err).group(1))
    with open(os.path.join(out_dir, "report.json")) as f:
        r = json.load(f)
    angle = min(float(m) for m in re.findall(r"min angle ([\d.]+) deg", out))
    return {"cpu": user + system, "rss_mb": rss / 1024.0, "steiner": r["steiner"],
            "fallbacks": r["fallback_count"], "valid": r["valid"], "angle": angle}


def cell(result, key, fmt, timeout=None):
    """A table cell: the value, or for a stopped run "> timeout" (CPU) or "-"."""
    if result is None:
        return f"> {timeout:.0f}" if timeout and key == "cpu" else "-"
    return format(result[key], fmt)


def family(name):
    return name.split("_n")[0]


def slope(points):
    """Least-squares slope of log y over log x (None without two distinct x)."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx > 0 else None


def exponents(rows, which):
    out = {}
    for fam in sorted({family(r["name"]) for r in rows}):
        e = slope([(r["n"], max(r[which]["cpu"], 1e-3)) for r in rows if family(r["name"]) == fam])
        if e is not None:
            out[fam] = e
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pairs", required=True)
    ap.add_argument("--old", required=True)
    ap.add_argument("--new", required=True)
    ap.add_argument("--only", default="")
    ap.add_argument("--full", action="store_true")
    ap.add_argument("--timeout", type=float, default=None)
    a = ap.parse_args()
    rows = []
    with open(os.path.join(a.pairs, "pairs.txt")) as f:
        for line in f:
            parts = line.split()
            if len(parts) < 3 or a.only not in parts[0]:
                continue
            name, files = parts[0], [os.path.join(a.pairs, x) for x in parts[1:]]
            n = int(re.search(r"_n(\d+)", name).group(1))
            row = {"name": name, "n": n}
            with tempfile.TemporaryDirectory() as tmp:
                for which, binary in (("old", a.old), ("new", a.new)):
                    row[which] = run(binary, files, os.path.join(tmp, which), a.full, a.timeout)
            rows.append(row)
            print(f"{name}: old {cell(row['old'], 'cpu', '.2f', a.timeout)} s; "
                  f"new {cell(row['new'], 'cpu', '.2f', a.timeout)} s", file=sys.stderr)
    print("| pair | n | old CPU s | new CPU s | new/old | old MB | new MB | old Steiner | new Steiner "
          "| old fallbacks | new fallbacks | old angle | new angle | valid |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        o, w = r["old"], r["new"]
        t = a.timeout
        ratio = f"{w['cpu'] / max(o['cpu'], 1e-3):.2f}" if o and w else f"< {w['cpu'] / t:.2f}" if w else "?"
        valid = all(x["valid"] for x in (o, w) if x)
        print(f"| {r['name']} | {r['n']} | {cell(o, 'cpu', '.2f', t)} | {cell(w, 'cpu', '.2f', t)} | {ratio} "
              f"| {cell(o, 'rss_mb', '.0f')} | {cell(w, 'rss_mb', '.0f')} | {cell(o, 'steiner', 'd')} "
              f"| {cell(w, 'steiner', 'd')} | {cell(o, 'fallbacks', 'd')} | {cell(w, 'fallbacks', 'd')} "
              f"| {cell(o, 'angle', '.2f')} | {cell(w, 'angle', '.2f')} | {'yes' if valid else 'NO'} |")
    rows = [r for r in rows if r["old"] and r["new"]]
    eo, en = exponents(rows, "old"), exponents(rows, "new")
    print()
    for fam in eo:
        steps = []
        sized = sorted((r for r in rows if family(r["name"]) == fam), key=lambda r: r["n"])
        for x, y in zip(sized, sized[1:]):
            e = [math.log(max(y[w]["cpu"], 1e-3) / max(x[w]["cpu"], 1e-3)) / math.log(y["n"] / x["n"])
                 for w in ("old", "new")]
            steps.append(f"{x['n']} to {y['n']}: n^{e[0]:.2f} / n^{e[1]:.2f}")
        print(f"- {fam}: CPU time grows as n^{eo[fam]:.2f} (old), n^{en.get(fam, float('nan')):.2f} (new) "
              f"over all sizes; old / new by step: {'; '.join(steps)}")


if __name__ == "__main__":
    main()
