"""Two builds of the command-line tool side by side: CPU seconds (user +
system) and peak RSS of the same runs, old and new interleaved, ROUNDS
times each. Each run goes through /usr/bin/time -v, whose "Maximum resident
set size" is the peak RSS (the tool's own: a process forked from Python
would keep Python's); the CPU time is the kernel's rusage of that time
process (wait4), in microseconds rather than time's hundredths, and so
includes time's own few hundred microseconds, the same for both builds.
Prints a markdown table: the median CPU, the largest peak RSS, and the
shared libraries each build loads at start (ldd).

    python3 bench/cli_cost.py OLD_COMPATMESH NEW_COMPATMESH PAIRS_DIR [ROUNDS]

PAIRS_DIR: made by `cm_gen_pairs --set bench`.

    python3 bench/cli_cost.py --preview OLD NEW A B ROUNDS [OPTION ...]

What the preview pictures cost: `triangulate A B [OPTION ...]` with the
pictures and with --no-preview (the control), the four runs interleaved
ROUNDS times; the median CPU of each and the pictures' share, the
difference of the medians.
"""
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

CASES = [
    ("--version", ["--version"]),
    ("triangulate n=40 --no-remesh",
     ["triangulate", "{p}/glyph_L_T_n40_a.xy", "{p}/glyph_L_T_n40_b.xy", "-o", "{o}", "--no-remesh"]),
    ("triangulate n=160", ["triangulate", "{p}/glyph_U_S_n160_a.xy", "{p}/glyph_U_S_n160_b.xy", "-o", "{o}"]),
    ("morph n=1000, 100 frames",
     ["morph", "{p}/star_n1000_a.xy", "{p}/star_n1000_b.xy", "-o", "{o}", "-n", "100"]),
    ("sweep n=80 to .msh", ["sweep", "{p}/glyph_U_S_n80_a.xy", "{p}/glyph_U_S_n80_b.xy", "-o", "{o}.msh"]),
]


def run(binary, arguments, work):
    """CPU seconds and peak RSS (KiB) of one run."""
    out = os.path.join(work, "out")
    shutil.rmtree(out, ignore_errors=True)
    if os.path.exists(out + ".msh"):
        os.remove(out + ".msh")
    report = os.path.join(work, "time.txt")
    with open(os.path.join(work, "stderr.txt"), "w+") as stderr:
        process = subprocess.Popen(["/usr/bin/time", "-v", "-o", report, binary, *arguments],
                                   stdout=subprocess.DEVNULL, stderr=stderr)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        if process.returncode != 0:
            stderr.seek(0)
            sys.exit(f"cli_cost.py: {binary} {' '.join(arguments)} failed:\n{stderr.read()}")
    with open(report) as f:
        peak = next(int(line.split(":")[1]) for line in f if "Maximum resident set size" in line)
    return usage.ru_utime + usage.ru_stime, peak


def libraries(binary):
    return len(subprocess.run(["ldd", binary], capture_output=True, text=True, check=True).stdout.splitlines())


def preview(old, new, a, b, rounds, options):
    with tempfile.TemporaryDirectory() as work:
        arguments = ["triangulate", a, b, "-o", os.path.join(work, "out"), *options]
        runs = {"pictures": arguments, "--no-preview": arguments + ["--no-preview"]}
        cpu = {(b, r): [] for b in (old, new) for r in runs}
        for _ in range(rounds):
            for name, args in runs.items():
                for binary in (old, new):
                    cpu[binary, name].append(run(binary, args, work)[0])
    median = {key: statistics.median(values) for key, values in cpu.items()}
    print("| run | old CPU (ms) | new CPU (ms) | new / old |")
    print("|---|---:|---:|---:|")
    for name in runs:
        print(f"| {name} | {1e3 * median[old, name]:.1f} | {1e3 * median[new, name]:.1f} "
              f"| {median[new, name] / median[old, name]:.2f} |")
    share = {b: median[b, "pictures"] - median[b, "--no-preview"] for b in (old, new)}
    print(f"| the pictures (difference) | {1e3 * share[old]:.1f} | {1e3 * share[new]:.1f} "
          f"| {share[new] / share[old]:.2f} |")
    print(f"\n{rounds} interleaved runs each, median CPU (user + system).")


def main():
    if len(sys.argv) >= 7 and sys.argv[1] == "--preview":
        old, new, a, b = sys.argv[2:6]
        preview(old, new, a, b, int(sys.argv[6]), sys.argv[7:])
        return
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    old, new, pairs = sys.argv[1:4]
    rounds = int(sys.argv[4]) if len(sys.argv) == 5 else 5
    with tempfile.TemporaryDirectory() as work:
        print("| run | old CPU (s) | new CPU (s) | new / old | old peak RSS (MB) | new peak RSS (MB) |")
        print("|---|---:|---:|---:|---:|---:|")
        for name, template in CASES:
            arguments = [a.format(p=pairs, o=os.path.join(work, "out")) for a in template]
            results = {old: [], new: []}
            for _ in range(rounds):
                for binary in (old, new):
                    results[binary].append(run(binary, arguments, work))
            cpu = {b: statistics.median(c for c, _ in r) for b, r in results.items()}
            rss = {b: max(m for _, m in r) / 1024 for b, r in results.items()}
            print(f"| {name} | {cpu[old]:.4f} | {cpu[new]:.4f} | {cpu[new] / cpu[old]:.2f} "
                  f"| {rss[old]:.1f} | {rss[new]:.1f} |")
    print(f"\nShared libraries at start (ldd): old {libraries(old)}, new {libraries(new)}; "
          f"{rounds} interleaved runs each, median CPU, largest peak RSS.")


if __name__ == "__main__":
    main()
