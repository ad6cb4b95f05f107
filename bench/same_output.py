"""Two builds of the command-line tool on the same pairs: are their outputs
the same byte for byte, and what does the new one cost against the old?

usage: same_output.py --old BIN --new BIN [--quick] [--only REGEX]
                      [--modes index,auto] [--repeats N] [--gen-pairs BIN]
                      [--args 'OPTIONS'] [--ignore-key KEY ...]

The pairs are remesh_bench.py's (`--quick`: its 32-pair subset; `--only`:
names matching a regular expression, added to the quick set when both are
given). `--args` adds options to every run of both builds (e.g.
'--no-remesh --no-preview' to compare the construction alone). Each pair
runs in each mode with each build, old and new
interleaved, REPEATS times (the order swapped every other repeat, so load
from other work hits both alike). Compared by SHA-256: every output mesh,
report.json with its "seconds" object taken out (wall times) and any
top-level key named by `--ignore-key` (one the new build adds), and the
pictures preview.svg and preview.png. Measured: CPU seconds (user + system,
wait4 of /usr/bin/time, which adds its own few hundred microseconds to
both builds alike) and peak resident memory (time's "%M": the tool's own;
a process forked from Python would keep Python's).

Prints one line per pair and mode (median CPU old and new, new/old), then
the geometric mean and median of new/old over the runs per mode, the
largest peak memory of each build, and how many runs differ. Exit code 0
when every output is the same, 1 when one differs or a run fails.
"""
import argparse
import hashlib
import json
import math
import os
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from remesh_bench import generate, select  # noqa: E402


def digest(out, ignore=()):
    """SHA-256 of each output file, report.json without its wall times and
    the keys in `ignore`."""
    sums = {}
    for name in sorted(os.listdir(out)):
        data = open(os.path.join(out, name), "rb").read()
        if name == "report.json":
            report = json.loads(data)
            for key in ("seconds", *ignore):
                report.pop(key, None)
            data = json.dumps(report, sort_keys=True).encode()
        sums[name] = hashlib.sha256(data).hexdigest()
    return sums


def run(cli, pair, mode, out, extra=(), ignore=()):
    """CPU seconds, peak RSS (MB) and the outputs' digests of one run."""
    shutil.rmtree(out, ignore_errors=True)
    cmd = [cli, "triangulate", *pair.files, "--out-dir", out, *extra]
    if mode != "index":
        cmd += ["--correspondence", mode]
    peak = out + ".rss"
    proc = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", peak, *cmd],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        return None, "exit %d: %s" % (proc.returncode, err.strip())
    with open(peak) as f:
        rss = int(f.read().split()[-1]) / 1024.0
    os.remove(peak)
    return (usage.ru_utime + usage.ru_stime, rss, digest(out, ignore)), None


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--old", required=True)
    ap.add_argument("--new", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only")
    ap.add_argument("--modes", default="index,auto")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--gen-pairs")
    ap.add_argument("--args", default="", help="options added to every run of both builds")
    ap.add_argument("--ignore-key", action="append", default=[],
                    help="a top-level report.json key left out of the comparison (repeatable)")
    args = ap.parse_args(argv)
    gen = args.gen_pairs or os.path.join(os.path.dirname(os.path.abspath(args.new)), "cm_gen_pairs")
    work = tempfile.mkdtemp(prefix="same_output_")
    differ = failed = 0
    ratios = {m: [] for m in args.modes.split(",")}
    peak = {"old": 0.0, "new": 0.0}
    try:
        every = generate(gen, work)
        pairs = select(every, args.quick, None) if args.quick else []
        if args.only:
            names = {p.name for p in pairs}
            pairs += [p for p in select(every, False, args.only) if p.name not in names]
        for pair in pairs:
            for mode in ratios:
                if mode != "index" and pair.family != "hard":
                    continue  # as remesh_bench.py: auto on the hard family only
                cpu = {"old": [], "new": []}
                sums = {}
                for r in range(args.repeats):
                    order = ("old", "new") if r % 2 == 0 else ("new", "old")
                    for build in order:
                        got, error = run(getattr(args, build), pair, mode, os.path.join(work, "out"),
                                         shlex.split(args.args), args.ignore_key)
                        if error:
                            print("%s %s %s: %s" % (pair.name, mode, build, error))
                            failed += 1
                            continue
                        cpu[build].append(got[0])
                        peak[build] = max(peak[build], got[1])
                        sums.setdefault(build, got[2])
                same = sums.get("old") == sums.get("new")
                if not same and "old" in sums and "new" in sums:
                    differ += 1
                    bad = sorted(k for k in set(sums["old"]) | set(sums["new"])
                                 if sums["old"].get(k) != sums["new"].get(k))
                    print("%s %s: DIFFERENT %s" % (pair.name, mode, " ".join(bad)))
                if cpu["old"] and cpu["new"]:
                    old, new = statistics.median(cpu["old"]), statistics.median(cpu["new"])
                    ratios[mode].append(new / old)
                    print("%-40s %-5s old %.4f new %.4f new/old %.3f %s" %
                          (pair.name, mode, old, new, new / old, "same" if same else "DIFFERENT"), flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for mode, r in ratios.items():
        if r:
            gmean = math.exp(sum(math.log(x) for x in r) / len(r))
            print("%s: %d runs, CPU new/old geometric mean %.3f, median %.3f" %
                  (mode, len(r), gmean, statistics.median(r)))
    print("peak RSS MB: old %.1f, new %.1f; runs that differ: %d; failed: %d" %
          (peak["old"], peak["new"], differ, failed))
    return 1 if differ or failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
