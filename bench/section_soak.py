"""Planar sections of real parts through the command line's default
pipeline, as a new user pairs them: every STL model Gmsh (gmsh-doc) and
OpenCASCADE (occt-misc) ship, cut at K evenly spaced heights along each
axis; each two neighbouring sections of one model and axis (the pair a
sweep between them needs) is one pair. A section is the largest region the
plane cuts (its outer loop and the loops inside it as holes), vertices as
the cut gives them (no resampling: the two sections' counts differ).

Two runs per pair, both `--correspondence auto` (the default for
different counts): the outer loops alone, and, where both sections have
the same number of holes (one or more), the sections with their holes,
each section's holes largest first (which hole pairs with which is auto's
to find: by position, through the outer loops' pairing).
Sections whose loops do not all close (a surface that is not watertight
there) or that are not simple are set aside and counted, as are pairs
above --max-vertices (summed over both polygons).

Per run: the exit status (0 valid, 2 input refused with its one-line
message, anything else a failure), the smallest angle of either mesh
against min(15, c/3) and min(20, c/2) (c the smallest input corner of the
pair, holes included), Steiner vertices, CPU seconds (user + system).

usage: /usr/bin/python3 bench/section_soak.py COMPATMESH [--heights K]
           [--max-vertices N] [--jobs J] [--timeout S] [--only REGEX]
           [--json FILE] [--markdown FILE] [--work DIR] [--in-space] [--cad]

--in-space writes each section as x y z points in its cut plane (x = h,
y = h or z = h), as MeshLab saves a section, instead of the plane's two
coordinates: the command line then fits each section's plane, places the
pair with aligned frames and writes the meshes in space.

--cad takes, instead of the STL models, the CAD models OpenCASCADE ships
(occt-misc: occ/*.brep, step/*.step, iges/*.iges), each named by its file
name: Gmsh's Python API reads one (as it is, else with its faces sewn into
solids), meshes its surfaces at 1/30 of its bounding box's diagonal (a
section has a few hundred vertices at most) into an STL file in the work
directory, which is cut and paired as above. A model Gmsh cannot read,
without a solid, or meshed the same as one before (a copy) is set aside
with its reason.

Exit status 0 when no run failed (refusals with a clear message are not
failures), 1 otherwise.
"""
import argparse
import concurrent.futures
import glob
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stl_sections  # noqa: E402
from make_results import corner_angles  # noqa: E402

MODEL_GLOBS = ["/usr/share/doc/gmsh-doc/**/*.stl.gz", "/usr/share/opencascade/data/stl/*.stl"]
CAD_GLOBS = ["/usr/share/opencascade/data/%s" % g for g in ("occ/*.brep", "step/*.step", "iges/*.iges")]
CAD_SIZE = 1 / 30  # --cad: the mesh size, of the model's bounding box diagonal


def models(globs=MODEL_GLOBS):
    found = []
    for pattern in globs:
        found += sorted(glob.glob(pattern, recursive=True))
    return found


def model_name(path):
    base = os.path.basename(path)
    return re.sub(r"\.stl(\.gz)?$", "", base).replace("_", "-")


def tessellate(path, workdir):
    """(STL file, None) of a CAD model's surfaces meshed by Gmsh at CAD_SIZE
    of its diagonal, read as it is or else with its faces sewn into solids;
    (None, why) when neither reading holds a solid."""
    import gmsh  # here: importing it resets the handling of Ctrl-C
    stl, why = os.path.join(workdir, os.path.basename(path) + ".stl"), []
    for sew in (0, 1):
        gmsh.initialize(readConfigFiles=False)
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.option.setNumber("Geometry.OCCSewFaces", sew)
            gmsh.option.setNumber("Geometry.OCCMakeSolids", sew)
            sys.stdout.flush()
            null, saved = os.open(os.devnull, os.O_WRONLY), os.dup(1)
            os.dup2(null, 1)  # OCC's IGES reader prints its counts on standard output
            try:
                gmsh.open(path)
            finally:
                os.dup2(saved, 1)
                os.close(null), os.close(saved)
            if not gmsh.model.getEntities(3):
                why.append("no solid")
                continue
            box = gmsh.model.getBoundingBox(-1, -1)
            gmsh.option.setNumber("Mesh.MeshSizeMax", CAD_SIZE * np.linalg.norm(np.subtract(box[3:], box[:3])))
            gmsh.model.mesh.generate(2)
            gmsh.write(stl)
            return stl, None
        except Exception as e:
            why.append("Gmsh: %s" % (str(e) or "an error without a message"))
        finally:
            gmsh.finalize()
    return None, "; ".join("%s: %s" % w for w in zip(("as read", "sewn"), why))


def inside(point, loop):
    """Even-odd test of a point against a closed loop."""
    x, y = point
    xs, ys = loop[:, 0], loop[:, 1]
    xn, yn = np.roll(xs, -1), np.roll(ys, -1)
    cross = (ys > y) != (yn > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = xs + (y - ys) * (xn - xs) / (yn - ys)
    return bool(np.count_nonzero(cross & (x < at)) % 2)


def region(loops):
    """The largest region: the loop of most area, counter-clockwise, and
    the loops directly inside it, clockwise. None when a loop inside it
    holds another (an island in a hole) or a loop is not simple."""
    order = sorted(loops, key=lambda l: -abs(stl_sections.signed_area(l)))
    outer = order[0]
    holes = [l for l in order[1:] if inside(l[0], outer)]
    for i, h in enumerate(holes):
        if any(inside(h[0], o) for o in holes[:i]):
            return None
    if not all(stl_sections.is_simple(l) for l in [outer] + holes):
        return None
    outer = outer if stl_sections.signed_area(outer) > 0 else outer[::-1]
    holes = [h if stl_sections.signed_area(h) < 0 else h[::-1] for h in holes]
    return [outer] + holes


def smallest_corner(loops):
    """The smallest interior angle (degrees) of a region's loops, seen from
    the material: inside the outer loop, outside each hole."""
    outer = corner_angles(loops[0])
    return min(outer + [360.0 - a for hole in loops[1:] for a in corner_angles(hole)])


def write_region(path, loops, axis=None, height=None):
    """The .xy form: loops separated by '>' lines, outer first; with axis,
    each point in space, in the cut plane x[axis] = height (`--in-space`:
    the command line then reads a section in its own plane)."""
    with open(path, "w") as f:
        for i, l in enumerate(loops):
            if i:
                f.write(">\n")
            for p in l:
                if axis is not None:
                    p = list(p)
                    p.insert(axis, height)
                f.write(" ".join("%.17g" % c for c in p) + "\n")


def sections(path, heights, workdir):
    """(axis, j, loops or None, why, height) for every cut of one model."""
    points, triangles = stl_sections.read_stl(path, workdir)
    lo, hi = points.min(axis=0), points.max(axis=0)
    out = []
    for axis in range(3):
        span = hi[axis] - lo[axis]
        for j in range(heights):
            h = lo[axis] + (j + 0.5) / heights * span
            # off every vertex: a cut through one gives a degenerate crossing
            while np.any(np.abs(points[:, axis] - h) < 1e-9 * span):
                h += 1e-7 * span
            loops = stl_sections.section_loops(points, triangles, axis, h, closed_only=True)
            if loops is None:
                out.append((axis, j, None, "open", h))
                continue
            r = region(loops)
            out.append((axis, j, r, None if r else "not simple or nested", h))
    return out


def run(compatmesh, job, timeout):
    """One pair through `triangulate --correspondence auto`: its row, with
    the process's CPU seconds (user + system, from /usr/bin/time)."""
    name, a, b, workdir = job
    out, timing = (os.path.join(workdir, name + s) for s in ("_out", "_time"))
    shutil.rmtree(out, ignore_errors=True)
    cmd = ["/usr/bin/time", "-f", "%U %S", "-o", timing, compatmesh, "triangulate", a, b,
           "--correspondence", "auto", "-o", out, "--quiet", "--no-preview"]
    try:
        proc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=timeout)
        status, err = proc.returncode, proc.stderr
    except subprocess.TimeoutExpired as e:
        status, err = "timeout", (e.stderr or b"").decode() if isinstance(e.stderr, bytes) else (e.stderr or "")
    err = "\n".join(l for l in err.strip().splitlines() if not l.startswith("Command exited"))
    row = {"name": name, "status": status, "message": err.splitlines()[0] if err else ""}
    try:
        row["cpu"] = sum(float(x) for x in open(timing).read().split()[-2:])
    except (OSError, ValueError):
        row["cpu"] = float(timeout) if status == "timeout" else float("nan")
    report = os.path.join(out, "report.json")
    if status == 0 and os.path.exists(report):
        r = json.load(open(report))
        ceiling = (r.get("ceiling") or {}).get("ceiling_deg")
        row.update(valid=bool(r["valid"]), angle=min(m["min_angle_deg"] for m in r["meshes"]),
                   steiner=r["steiner"], choice=r["correspondence_choice"],
                   ceiling=ceiling if ceiling is not None else 60.0)
    shutil.rmtree(out, ignore_errors=True)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("compatmesh")
    ap.add_argument("--heights", type=int, default=8)
    ap.add_argument("--max-vertices", type=int, default=800)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--only", default="")
    ap.add_argument("--json")
    ap.add_argument("--markdown")
    ap.add_argument("--work")
    ap.add_argument("--in-space", action="store_true")
    ap.add_argument("--cad", action="store_true")
    args = ap.parse_args()
    workdir = args.work or tempfile.mkdtemp(prefix="section_soak_")
    os.makedirs(workdir, exist_ok=True)
    only = re.compile(args.only)

    jobs, meta, set_aside = [], {}, {"open": 0, "not simple or nested": 0, "too large": 0}
    models_aside, meshed = {}, {}
    for path in models(CAD_GLOBS if args.cad else MODEL_GLOBS):
        model = model_name(path)
        if not only.search(model):
            continue
        if args.cad:
            path, why = tessellate(path, workdir)
            if path:
                key = open(path, "rb").read()
                why, path = ("the same mesh as %s" % meshed[key], None) if key in meshed else (None, path)
                meshed.setdefault(key, model)
            if not path:
                models_aside[model] = why
                print("section_soak: %s set aside (%s)" % (model, why), file=sys.stderr)
                continue
        cuts = sections(path, args.heights, workdir)
        for why in (c[3] for c in cuts if c[3]):
            set_aside[why] += 1
        for axis in range(3):
            row = [c for c in cuts if c[0] == axis]
            for (_, j, la, _, ha), (_, _, lb, _, hb) in zip(row, row[1:]):
                if la is None or lb is None:
                    continue
                base = "%s_%s%d-%d" % (model, "xyz"[axis], j, j + 1)
                runs = [("outer", [la[0]], [lb[0]])]
                if len(la) == len(lb) > 1:
                    runs.append(("holes", la, lb))
                for kind, ra, rb in runs:
                    nv = sum(len(l) for l in ra) + sum(len(l) for l in rb)
                    if nv > args.max_vertices:
                        set_aside["too large"] += 1
                        continue
                    name = "%s_%s" % (base, kind)
                    fa, fb = (os.path.join(workdir, "%s_%s.xy" % (name, s)) for s in "ab")
                    write_region(fa, ra, axis if args.in_space else None, ha)
                    write_region(fb, rb, axis if args.in_space else None, hb)
                    c = min(smallest_corner(ra), smallest_corner(rb))
                    meta[name] = {"kind": kind, "model": model, "holes": len(ra) - 1,
                                  "n": [sum(len(l) for l in ra), sum(len(l) for l in rb)], "c": c,
                                  "floor3": min(15.0, c / 3), "floor2": min(20.0, c / 2)}
                    jobs.append((name, fa, fb, workdir))
    print("section_soak: %d runs (%s set aside)" % (len(jobs), ", ".join("%d %s" % (v, k) for k, v in set_aside.items())),
          file=sys.stderr)
    rows = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
        for i, row in enumerate(ex.map(lambda j: run(args.compatmesh, j, args.timeout), jobs)):
            row.update(meta[row["name"]])
            rows.append(row)
            print("[%d/%d] %s: %s" % (i + 1, len(jobs), row["name"],
                                      "%.2f deg (floor %.2f), %d Steiner, %.2f s" % (
                                          row["angle"], row["floor3"], row["steiner"], row["cpu"])
                                      if row["status"] == 0 else "%s %s" % (row["status"], row["message"])),
                  file=sys.stderr)
    text = summary(rows, set_aside, args, models_aside)
    print(text)
    if args.markdown:
        open(args.markdown, "w").write(text)
    if args.json:
        json.dump({"set_aside": set_aside, "models_set_aside": models_aside, "runs": rows}, open(args.json, "w"),
                  indent=1)
    if not args.work:
        shutil.rmtree(workdir, ignore_errors=True)
    return 1 if any(failed(r) for r in rows) else 0


def target(row):
    """T = min(25, c/2, the certified ceiling of the correspondence made)."""
    return min(25.0, row["c"] / 2, row["ceiling"])


def failed(row):
    return row["status"] not in (0, 2) or (row["status"] == 0 and not row.get("valid"))


def summary(rows, set_aside, args, models_aside):
    lines = ["| runs | pairs | valid | refused | failed | at min(15, c/3) | at min(20, c/2) | "
             "median angle (deg) | least angle (deg) | median / least angle over T | median Steiner | "
             "median CPU (s) | largest CPU (s) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for kind in ("outer", "holes"):
        rs = [r for r in rows if r["kind"] == kind]
        if not rs:
            continue
        ok = [r for r in rs if r["status"] == 0 and r.get("valid")]
        at3 = sum(r["angle"] >= r["floor3"] * (1 - 1e-9) for r in ok)
        at2 = sum(r["angle"] >= r["floor2"] * (1 - 1e-9) for r in ok)
        med = lambda v: statistics.median(v) if v else float("nan")  # noqa: E731
        share = [r["angle"] / target(r) for r in ok]
        lines.append("| %s | %d | %d | %d | %d | %d | %d | %.2f | %.2f | %.2f / %.2f | %d | %.2f | %.2f |" % (
            "outer loops" if kind == "outer" else "with holes", len(rs), len(ok),
            sum(r["status"] == 2 for r in rs), sum(failed(r) for r in rs), at3, at2,
            med([r["angle"] for r in ok]), min([r["angle"] for r in ok], default=float("nan")),
            med(share), min(share, default=float("nan")),
            med([r["steiner"] for r in ok]), med([r["cpu"] for r in rs]), max(r["cpu"] for r in rs)))
    lines.append("")
    lines.append("Set aside: %s. %d heights per axis, at most %d vertices a pair." % (
        ", ".join("%d sections %s" % (v, k) if k != "too large" else "%d runs too large" % v
                  for k, v in set_aside.items()), args.heights, args.max_vertices))
    if models_aside:
        lines[-1] += " Models set aside: %s." % "; ".join("%s (%s)" % m for m in models_aside.items())
    short = sorted((r for r in rows if r["status"] == 0 and r.get("valid") and r["angle"] < r["floor3"] * (1 - 1e-9)),
                   key=lambda r: r["angle"] / max(r["floor3"], 1e-12))
    bad = [r for r in rows if r["status"] != 0 or not r.get("valid")]
    if short or bad:
        lines += ["", "| run | n | holes | c (deg) | min(15, c/3) | ceiling (deg) | smallest angle or status | "
                  "Steiner | CPU (s) |", "|---|---|---:|---:|---:|---:|---|---:|---:|"]
        for r in bad + short:
            ok = r["status"] == 0 and r.get("valid")
            what = "%.2f" % r["angle"] if ok else "%s: %s" % (r["status"], r["message"])
            lines.append("| %s | %d / %d | %d | %.2f | %.2f | %s | %s | %s | %.2f |" % (
                r["name"], r["n"][0], r["n"][1], r["holes"], r["c"], r["floor3"],
                "%.2f" % r["ceiling"] if ok else "-", what, r.get("steiner", "-"), r["cpu"]))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
