"""The correspondence modes side by side on the bench's glyph and star
pairs whose second polygon is renumbered from a random vertex (seeded): what
an arbitrary start costs with plain arc length, and what auto recovers,
against the pair's own designed index correspondence.

usage: correspondence_bench.py BUILD_DIR OUT.md

OUT.md is rewritten up to its first '## ' section; the sections are kept.
"""
import json
import os
import random
import subprocess
import sys
import tempfile


def run(cli, files, mode, out):
    r = subprocess.run([cli, "triangulate", *files, "-o", out, "--correspondence", mode],
                       capture_output=True, text=True)
    if r.returncode:
        return None
    report = json.load(open(os.path.join(out, "report.json")))
    return (min(m["min_angle_deg"] for m in report["meshes"]), report["steiner"], report["n"],
            report["seconds"]["total"])


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    build, target = argv[1], argv[2]
    cli = os.path.join(build, "bin", "compatmesh")
    rng = random.Random(20261124)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([os.path.join(build, "bin", "cm_gen_pairs"), "--out", tmp, "--set", "bench"],
                       check=True, capture_output=True)
        for line in open(os.path.join(tmp, "pairs.txt")):
            name, *files = line.split()
            if len(files) != 2 or not name.startswith(("glyph", "star_n16", "star_n50", "star_n100")):
                continue
            a, b = (os.path.join(tmp, f) for f in files)
            lines = [l for l in open(b) if l.strip()]
            shift = rng.randrange(len(lines))
            shifted = os.path.join(tmp, name + "_shifted.xy")
            open(shifted, "w").writelines(lines[shift:] + lines[:shift])
            cells = [run(cli, [a, b], "index", os.path.join(tmp, "o1")),
                     run(cli, [a, shifted], "arclength", os.path.join(tmp, "o2")),
                     run(cli, [a, shifted], "auto", os.path.join(tmp, "o3"))]
            for d in ("o1", "o2", "o3"):
                subprocess.run(["rm", "-rf", os.path.join(tmp, d)])
            rows.append((name, shift, cells))
    def cell(c):
        return "failed" if c is None else f"{c[0]:.1f} deg, {c[1]} St, n {c[2]}"
    # sections after the table (## headings) are kept
    kept = ""
    if os.path.exists(target):
        text = open(target).read()
        kept = text[text.index("\n## "):] if "\n## " in text else ""
    with open(target, "w") as out:
        out.write("# Choosing the correspondence\n\n"
                  "`bench/correspondence_bench.py` (seeded): each pair's second polygon renumbered from a\n"
                  "random vertex; smallest angle over both meshes, Steiner vertices and boundary size.\n"
                  "`index` is the pair as designed (the start matched by hand); `arclength` pairs the\n"
                  "renumbered polygon by arc length from vertex 0; `auto` chooses the start.\n\n"
                  "| pair | shift | index (designed) | arclength (shifted) | auto (shifted) |\n"
                  "| --- | --- | --- | --- | --- |\n")
        for name, shift, cells in rows:
            out.write(f"| {name} | {shift} | " + " | ".join(cell(c) for c in cells) + " |\n")
        def median(i):
            v = sorted(c[i][0] for _, _, c in rows if c[i] is not None)
            return v[len(v) // 2] if v else float("nan")
        out.write(f"\nMedian smallest angle: index {median(0):.1f}, arclength {median(1):.1f}, "
                  f"auto {median(2):.1f} degrees over {len(rows)} pairs.\n")
        out.write(kept)
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
