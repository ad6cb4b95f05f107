"""The correspondence bound of every pair of a cm_gen_pairs folder, written
as bound.tsv (pair, then bench/correspondence_bound.py's output line, or
"failed"), taken from the bound cache remesh_bench.py keeps
(bench/REMESH_bounds.json: keyed by the bytes of the script and of the
pair's polygons, so a cached line is what the script would print) and
computed, then cached, where missing.

usage: cached_bounds.py COMPATMESH PAIRS_DIR OUT_TSV [TIMEOUT_SECONDS] [JOBS]
"""
import os
import sys

import remesh_bench as rb


def main(argv):
    if len(argv) not in (4, 5, 6):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    cli, folder, out = argv[1:4]
    timeout = float(argv[4]) if len(argv) > 4 else 900
    jobs = int(argv[5]) if len(argv) > 5 else 1
    pairs = []
    for line in open(os.path.join(folder, "pairs.txt")):
        if line.strip():
            name, *files = line.split()
            pairs.append(rb.Pair(name, "bench", [os.path.join(folder, f) for f in files]))
    cache = rb.BoundCache(os.path.join(rb.HERE, "REMESH_bounds.json"))
    cache.fill(cli, pairs, timeout, jobs)
    with open(out, "w") as f:
        for pair in pairs:
            b = cache.get(pair)
            line = ("%.3f %.4g %s" % (b["bound_deg"], b["K"], b["quadruple"])
                    if b.get("bound_deg") is not None else "failed")
            f.write("%s\t%s\n" % (pair.name, line))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
