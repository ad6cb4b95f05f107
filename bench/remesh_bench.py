"""The remesher judged against what each pair allows, side by side with CGAL
and optionally with a baseline build.

usage: remesh_bench.py --compatmesh BIN [--baseline BIN] [--quick] [--no-bound]
                       [--no-cgal] [--modes index,auto] [--only REGEX]
                       [--out bench/REMESH.md] [--json FILE] [--bound-cache FILE]
                       [--bound-jobs N] [--gen-pairs BIN] [--cgal BIN]
                       [--timeout SECONDS] [--other]

The pairs: the hard family (`cm_gen_pairs --set hard`: single-contour glyphs
of different letters from fonts other than the bench's DejaVu Sans, each
resampled by arc length from its bottom-left point to n = 48 and 160, so
vertex i of one corresponds to vertex i of the other by arc length; plus
random simple polygons against discs and stars; and planar sections of
Gmsh's STL models, bench/stl_sections.py), split into a tuning half
(`tune_*`, two fonts) and a held-out half (`hold_*`), next to the existing
bench set (`cm_gen_pairs --set bench`). `--other` adds the other fonts
(`cm_gen_pairs --set other`, `other_*`: six fonts neither half uses, made
the same way with another seed), set aside from every setting's tuning and
summarised on their own, not in "all pairs". `--quick` takes a fixed subset
of 32 pairs; `--only` keeps the pairs whose name matches a regular
expression.

Modes: `index` runs each pair as written (the hard family's correspondence
is then arc length); `auto` (`--correspondence auto`, not the bench set) lets
compatmesh choose the correspondence. c, fan, bound and T are those of the
pair as written in both modes: in `auto`, /T above 1 is what the choice of
correspondence bought. `index` never splits a boundary edge (the paper's
contract: interior Steiner vertices only), so its T is capped by edge too.

Per pair, from the input alone:
  c        the smallest interior corner over the polygons (degrees)
  fan      the corner-fan cap: at input vertex i every compatible mesh splits
           the corner into the same k triangles in every polygon, each angle
           in [alpha, 180 - 2 alpha], so alpha <= min_g theta_i / k and
           max_g theta_i / k <= 180 - 2 alpha for some k >= 1;
           fan = min_i max_k min(min theta_i / k, (180 - max theta_i / k) / 2)
  bound    bench/correspondence_bound.py: no compatible triangulation of the
           pair has a smallest angle above it (with the distortion K it comes
           from); cached by the pair's content (--bound-cache)
  edge     the boundary-edge cap (edge_cap below): with boundary edges never
           split, a triangle on edge ab whose base angles are at least alpha
           contains the isosceles triangle on ab of base angle alpha, which no
           boundary point may enter; and one step further (near_vertex_cap
           below): a boundary vertex p near ab must stay out of that
           triangle and out of the one across its side, which bounds alpha
           by half the angle p subtends at a or b, by atan(2 h / |ab|) (h
           p's height over ab), or by a triangle abp or ab and a neighbour;
           the smallest over both polygons
  T        min(25, c / 2, fan, bound), and in index mode also edge: the
           target a remesher can be held to
Per pair, build and mode (every run interleaved with the others and with
CGAL, so machine load hits all alike):
  angle    the smallest angle over all output meshes; /T its ratio to T
  map cap  the smallest, over the output's triangles, of the cap its own
           affine map allows (correspondence_bound.map_caps: no position of
           the same vertices raises a triangle above the cap of the map it
           then has); /T its ratio to T. angle / map cap near 1 says the
           triangles are as good as the mesh's map lets them be, so only a
           less distorted map (other connectivity) can gain more
  <20      the share of triangles under 20 degrees, per mesh (percent)
  Steiner  compatmesh's Steiner vertices (shared by all meshes)
  CGAL     the Steiner vertices CGAL's Delaunay mesher (bench/cgal_single.cc)
           adds to each polygon meshed alone at 25 degrees; St/CGAL is
           compatmesh's count over the larger of them
  CPU      user + system seconds of the compatmesh process (os.wait4; it
           runs under /usr/bin/time, which adds about 0.7 ms), its peak
           resident memory (MB, time's %M), and x CGAL: the CPU time over CGAL's
           for meshing each polygon alone (both processes), a ratio of two
           runs made back to back. Both sides pay a process's start-up
           (about 2 ms each for CGAL's, 4 ms for compatmesh's), which is
           most of CGAL's time: x in process is the CPU time less
           compatmesh's start-up (the median CPU of STARTUP_RUNS runs of
           `compatmesh --version` under /usr/bin/time, per build) over the
           CPU CGAL's meshing of both polygons takes inside its process
           (cm_cgal_single's mesh_cpu_s, repeated for CGAL_MIN_CPU seconds);
           compatmesh's side still holds its input, ceiling, pictures and
           output, so the ratio errs against it
  valid    exit code 0 and report.json valid (compatmesh checks every result
           exactly before it writes it)
Summary, per build, mode and group (tuning half, held-out half, bench set,
all): medians of the above over the valid runs (of <20, the worse mesh's
share; of the map cap, its ratio to T and the angle's ratio to it), the
smallest /T, how many pairs reach 0.3 T and 0.55 T, and how
many reach min(20, c / 2) and min(15, c / 3) (the aims of the choice of
correspondence; a run within AIM_TOLERANCE of an aim, relatively, reaches
it: a corner split exactly in halves reports c / 2 rounded).
With --baseline, per pair and in the summary: new / baseline ratios of the
smallest angle, the Steiner count and the CPU time.

Exit code: 0 when every run is valid, 1 when one is not, 2 on bad usage.
"""
import argparse
import concurrent.futures
import datetime
import hashlib
import json
import math
import os
import platform
import re
import shlex
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stl_sections  # noqa: E402
from map_caps import output_caps  # noqa: E402
from make_results import corner_angles, fmt_angle, read_xy  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
BOUND_SCRIPT = os.path.join(HERE, "correspondence_bound.py")
HARD_N = (48, 160)  # as in cm_gen_pairs --set hard
CGAL_ANGLE = 25.0
# CGAL's meshing inside its process is timed over repeats that take at
# least this much CPU (cm_cgal_single's third argument)
CGAL_MIN_CPU = 0.02
# compatmesh's start-up: the median of this many runs of --version
STARTUP_RUNS = 9
TARGET_CAP = 25.0
GOOD_SHARE_OF_T = 0.3
HIGH_SHARE_OF_T = 0.55
# The aims min(20, c / 2) and min(15, c / 3) of a pair with smallest corner c.
AIMS = ((20.0, 2.0), (15.0, 3.0))
# A run reaches an aim within this relative tolerance: a corner split
# exactly in two has halves of c / 2 in exact arithmetic, but the point on
# the bisector is rounded to doubles, so such a mesh reports c / 2 less a
# few units in the last place (1e-15 to 1e-11 of it on the hard glyphs).
AIM_TOLERANCE = 1e-9
# --quick: every second hard pair at n = 48 and the smallest bench pairs.
QUICK_BENCH = {"glyph_U_S_n40", "glyph_C_G_n40", "glyph_L_T_n40", "glyph_2_Z_n40",
               "star_n16", "twisted_star_n16", "random_disc_n16"}


# ---- the pairs -----------------------------------------------------------

class Pair:
    """A polygon pair: name, family (hard or bench), half (tune, hold or
    bench) and its .xy files."""

    def __init__(self, name, family, files):
        self.name, self.family, self.files = name, family, files
        self.half = name.split("_")[0] if family in ("hard", "other") else "bench"
        self.polygons = [read_xy(f) for f in files]
        self.n = len(self.polygons[0])


def generate(gen, workdir, other=False):
    """The hard family and the bench set written by cm_gen_pairs, and the
    other fonts if asked."""
    pairs = []
    for family in ("hard", "bench") + (("other",) if other else ()):
        out = os.path.join(workdir, family)
        run = subprocess.run([gen, "--out", out, "--set", family], capture_output=True, text=True)
        if run.returncode != 0:
            raise SystemExit("remesh_bench: cm_gen_pairs --set %s failed: %s" % (family, run.stderr.strip()))
        for line in open(os.path.join(out, "pairs.txt")):
            name, *files = line.split()
            pairs.append(Pair(name, family, [os.path.join(out, f) for f in files]))
    return pairs


def sections(workdir, only):
    """The held-out STL section pairs (stl_sections.py), unless --only
    leaves them all out."""
    names = stl_sections.pair_names(HARD_N)
    if only and not any(re.search(only, name) for name in names):
        return []
    if not os.path.isdir(stl_sections.MODELS):
        raise SystemExit("remesh_bench: the STL sections need Gmsh's models: install gmsh-doc "
                         "(make bench-deps), or leave them out with --quick or --only")
    return [Pair(name, "hard", files)
            for name, files in stl_sections.write_pairs(os.path.join(workdir, "sections"), HARD_N)]


def select(pairs, quick, only):
    """--quick: every second hard glyph or shape pair at n = 48 and the
    smallest bench pairs (no STL section); --only: names matching it."""
    if quick:
        hard48 = [p for p in pairs if p.family == "hard" and p.n == 48 and "_section_" not in p.name]
        keep = {p.name for p in hard48[::2]} | QUICK_BENCH
        pairs = [p for p in pairs if p.name in keep]
    if only:
        pairs = [p for p in pairs if re.search(only, p.name)]
    return pairs


# ---- what the input allows -------------------------------------------------

def corner_fan_cap(theta):
    """The largest alpha (degrees) for which some k triangles split the
    corner of angle theta[g] in every polygon g with all their angles in
    [alpha, 180 - 2 alpha]."""
    lo, hi = min(theta), max(theta)
    return max(min(lo / k, (180 - hi / k) / 2) for k in range(1, 2 + int(hi)))


def fan_cap(polygons):
    """The corner-fan cap (degrees) of polygons in index correspondence."""
    return min(corner_fan_cap(theta) for theta in zip(*(corner_angles(p) for p in polygons)))


def edge_cap(points):
    """The largest alpha (degrees) a triangle on some boundary edge of this
    polygon can have as its smallest angle when boundary edges are never
    split (index mode): a triangle on edge ab whose base angles are both at
    least alpha contains the isosceles triangle on ab of base angle alpha,
    and no boundary point may lie inside it. So alpha is at most atan(2 h /
    |ab|), h the lowest height of that isosceles triangle that a boundary
    point enters, over every edge. (core/src/remesh/criteria.c computes the
    same cap for the remesher's aim.)"""
    xy = np.asarray(points, dtype=float)
    if sum(xy[i - 1, 0] * xy[i, 1] - xy[i, 0] * xy[i - 1, 1] for i in range(len(xy))) < 0:
        xy = xy[::-1]  # counter-clockwise: the inside is left of each edge
    n, best = len(xy), 90.0
    p, q = xy, np.roll(xy, -1, axis=0)  # segment e runs from p[e] to q[e]
    for i in range(n):
        a, b = xy[i], xy[(i + 1) % n]
        half = 0.5 * math.hypot(*(b - a))
        u = (b - a) / (2 * half)
        m = 0.5 * (a + b)

        def coords(pts):  # along the edge from its midpoint, and inward
            r = pts - m
            return r @ u, r @ np.array([-u[1], u[0]])

        s0, d0 = coords(p)
        s1, d1 = coords(q)
        sd, dd = s1 - s0, d1 - d0
        # the segment's parameter range inside the strip d > 0, |s| < half;
        # ends shared with the edge are approached, not taken
        t0 = np.where(np.isin(np.arange(n), (i, (i + 1) % n)), 1e-7, 0.0)
        t1 = np.where(np.isin((np.arange(n) + 1) % n, (i, (i + 1) % n)), 1 - 1e-7, 1.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            for alpha, beta in ((d0, dd), (half - s0, -sd), (half + s0, sd)):
                lim = -alpha / beta
                t0 = np.where(beta > 0, np.maximum(t0, lim), t0)
                t1 = np.where(beta < 0, np.minimum(t1, lim), t1)
                t1 = np.where((beta == 0) & ~(alpha > 0), -1.0, t1)
            kink = np.where(sd != 0, -s0 / sd, -1.0)
        h = np.full(n, np.inf)
        for t in (t0, t1, np.where((kink > t0) & (kink < t1), kink, t0)):
            s, d = s0 + t * sd, d0 + t * dd
            room = 1 - np.abs(s) / half
            h = np.minimum(h, np.where((d > 0) & (room > 0), d / np.where(room > 0, room, 1), np.inf))
        h[i] = np.inf
        h = np.where(t0 <= t1, h, np.inf)
        best = min(best, math.degrees(math.atan2(2 * h.min(), 2 * half)))
    return best


def _ccw(points):
    xy = np.asarray(points, dtype=float)
    if sum(xy[i - 1, 0] * xy[i, 1] - xy[i, 0] * xy[i - 1, 1] for i in range(len(xy))) < 0:
        xy = xy[::-1]  # counter-clockwise: the inside is left of each edge
    return xy


def _smallest_angle(p, q, r):
    def at(u, v, w):
        x, y = v - u, w - u
        return math.atan2(abs(x[0] * y[1] - x[1] * y[0]), x @ y)
    return min(at(p, q, r), at(q, r, p), at(r, p, q))


def near_vertex_cap(points):
    """The boundary-edge cap one step further (index mode, degrees): for
    boundary edge ab (counter-clockwise, |ab| = L) and a boundary vertex p
    left of it at height h, seen at angle phi_a from a (between ab and ap)
    and phi_b from b, the triangle abc on ab with all angles >= alpha has
        alpha <= max(min(phi_b, max(phi_b / 2, atan(2 h / L))),   (1)
                     min(phi_a, max(phi_a / 2, atan(2 h / L))),   (2)
                     smallest angle of abp,                       (3)
                     smallest angle of the triangle of ab and a boundary
                     neighbour of a or b, where it is one)        (4)
    Proof: p is not inside the open triangle abc, whose angles at b and a
    are beta and gamma, so beta <= phi_b or gamma <= phi_a. Say beta <=
    phi_b, psi = phi_b - beta (the other case is (2)). If c = p it is (3);
    if bc is a boundary edge, c is b's other neighbour, (4). Otherwise the
    triangle bcx across bc has angles >= alpha at b and c, so it holds the
    open isosceles triangle on bc of base angle alpha, and p is not in that
    (x = p needs psi >= alpha too): psi >= alpha, so alpha <= phi_b / 2, or
    |bc| <= |bp| sin(alpha + psi) / sin(alpha) (p seen from c at alpha or
    more). |bc| = L sin(gamma) / sin(beta + gamma) grows with gamma, so
    gamma = alpha is its least: L sin^2(alpha) <= |bp| sin(alpha + beta)
    sin(alpha + phi_b - beta) = |bp| (cos(phi_b - 2 beta) - cos(2 alpha +
    phi_b)) / 2, whose right side over alpha <= beta <= phi_b is largest at
    beta = alpha once alpha >= phi_b / 2: L sin^2(alpha) <= h sin(2 alpha),
    tan(alpha) <= 2 h / L. And alpha <= beta <= phi_b. The cap is the
    least over edges and vertices of that maximum; (4) counts only where the
    neighbour is left of ab and no vertex lies inside the triangle."""
    xy = _ccw(points)
    n, best = len(xy), math.pi / 2
    idx = np.arange(n)

    def left(a, b, q):  # twice the signed area of abq, q one point or many
        q = np.asarray(q)
        return (b[0] - a[0]) * (q[..., 1] - a[1]) - (b[1] - a[1]) * (q[..., 0] - a[0])

    def neighbour_triangle(t, own):
        """(4) for triangle t (counter-clockwise when it is one), own its
        vertices' indices: 0 where it cannot be a triangle of the mesh."""
        if not left(t[0], t[1], t[2]) > 0:
            return 0.0
        others = xy[~np.isin(idx, own)]
        inside = np.ones(len(others), bool)
        for m in range(3):
            inside &= left(t[m], t[(m + 1) % 3], others) > 0
        return 0.0 if inside.any() else _smallest_angle(*t)

    for i in range(n):
        j = (i + 1) % n
        a, b = xy[i], xy[j]
        L = math.hypot(*(b - a))
        u = (b - a) / L
        escape = max(neighbour_triangle((xy[i - 1], a, b), ((i - 1) % n, i, j)),
                     neighbour_triangle((a, b, xy[(j + 1) % n]), (i, j, (j + 1) % n)))
        r = xy - a
        h = u[0] * r[:, 1] - u[1] * r[:, 0]
        along = r @ u
        keep = (h > 0) & (idx != i) & (idx != j)
        h, along = h[keep], along[keep]
        phi_a, phi_b = np.arctan2(h, along), np.arctan2(h, L - along)
        w = np.arctan(2 * h / L)
        cap = np.maximum.reduce([np.minimum(phi_b, np.maximum(phi_b / 2, w)),
                                 np.minimum(phi_a, np.maximum(phi_a / 2, w)),
                                 np.minimum(np.minimum(phi_a, phi_b), math.pi - phi_a - phi_b),
                                 np.full(len(h), escape)])
        if len(cap):
            best = min(best, cap.min())
    return math.degrees(best)


def smallest_corner(polygons):
    return min(min(corner_angles(p)) for p in polygons)


def content_key(files):
    """The bound cache key: the bound script and the polygons' bytes."""
    h = hashlib.sha256(open(BOUND_SCRIPT, "rb").read())
    for f in files:
        h.update(b"\0" + open(f, "rb").read())
    return h.hexdigest()


class BoundCache:
    """Correspondence bounds by content key, in a JSON file written after
    every new bound (an interrupted run keeps what it computed)."""

    def __init__(self, path):
        self.path = path
        self.data = json.load(open(path)) if path and os.path.exists(path) else {}

    def fill(self, cli, pairs, timeout, jobs):
        """Computes the bounds not cached yet, `jobs` at a time (they are
        not timed, so they need not run alone)."""
        missing = {content_key(p.files): p for p in pairs}
        missing = [(k, p) for k, p in missing.items() if k not in self.data]
        with concurrent.futures.ThreadPoolExecutor(max(1, jobs)) as pool:
            futures = {pool.submit(compute_bound, cli, p.files, timeout): (k, p) for k, p in missing}
            for done, future in enumerate(concurrent.futures.as_completed(futures)):
                key, pair = futures[future]
                self.data[key] = dict(future.result(), pair=pair.name)
                self.save()
                print("[bound %d/%d] %s: %s" % (done + 1, len(missing), pair.name,
                                                self.data[key]["bound_deg"]), flush=True)

    def save(self):
        if self.path:
            tmp = self.path + ".tmp"
            with open(tmp, "w") as f:
                json.dump(self.data, f, indent=0, sort_keys=True)
            os.replace(tmp, self.path)

    def get(self, pair):
        return self.data[content_key(pair.files)]


def compute_bound(cli, files, timeout):
    try:
        run = subprocess.run([sys.executable, BOUND_SCRIPT, cli, *files], capture_output=True,
                             text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"bound_deg": None, "K": None, "error": "timed out after %g s" % timeout}
    if run.returncode != 0:
        return {"bound_deg": None, "K": None, "error": run.stderr.strip().splitlines()[-1:]}
    words = run.stdout.split()
    return {"bound_deg": float(words[0]), "K": float(words[1]), "quadruple": words[2]}


# ---- measured runs -----------------------------------------------------------

def run_measured(cmd, timeout, cwd=None, peak_rss=False):
    """Runs cmd; returns (exit code or None on timeout, CPU seconds, peak RSS
    in MB or NaN, stdout, stderr). CPU comes from os.wait4, user + system.
    With peak_rss the command runs under /usr/bin/time, whose %M is the
    peak (wait4's own would not do: a child holds this Python process's
    pages until it execs, and the kernel keeps that high-water mark), and
    the CPU then includes time's own, about 0.7 ms."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err, \
            tempfile.NamedTemporaryFile(mode="r") as peak:
        wrap = ["/usr/bin/time", "-f", "%M", "-o", peak.name] if peak_rss else []
        proc = subprocess.Popen(wrap + list(cmd), stdout=out, stderr=err, stdin=subprocess.DEVNULL, cwd=cwd,
                                start_new_session=True)
        deadline = time.monotonic() + timeout
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline:
                os.killpg(proc.pid, signal.SIGKILL)
                pid, status, usage = os.wait4(proc.pid, 0)
                status = None
                break
            time.sleep(0.002)
        proc.returncode = 0  # reaped here: keep Popen from waiting again
        out.seek(0)
        err.seek(0)
        code = None if status is None else os.waitstatus_to_exitcode(status)
        words = peak.read().split()  # "Command exited with non-zero status N" first, if it did
        rss = int(words[-1]) / 1024.0 if peak_rss and code is not None and words else float("nan")
        return (code, usage.ru_utime + usage.ru_stime, rss,
                out.read().decode(errors="replace"), err.read().decode(errors="replace"))


def run_compatmesh(cli, pair, mode, workdir, timeout, extra=()):
    """One compatmesh run: its numbers, or valid False and why."""
    out = os.path.join(workdir, "run")
    shutil.rmtree(out, ignore_errors=True)
    cmd = [cli, "triangulate", *pair.files, "--out-dir", out, *extra]
    if mode != "index":  # index is the default for equal counts, also in older builds
        cmd += ["--correspondence", mode]
    code, cpu, rss, _, err = run_measured(cmd, timeout, peak_rss=True)
    result = {"exit": code, "cpu_s": cpu, "rss_mb": rss, "valid": False}
    report_path = os.path.join(out, "report.json")
    if code != 0 or not os.path.exists(report_path):
        result["error"] = "timed out" if code is None else (err.strip().splitlines() or ["?"])[-1]
        return result
    report = json.load(open(report_path))
    caps = float(output_caps([m["output"] for m in report["meshes"]])[2].min())
    shutil.rmtree(out, ignore_errors=True)
    result.update(map_cap_deg=caps,valid=bool(report.get("valid", False)), steiner=report["steiner"],
                  boundary=report["n"],
                  min_angle_deg=min(m["min_angle_deg"] for m in report["meshes"]),
                  under20_pct=[m["pct_triangles_below_20deg"] for m in report["meshes"]])
    return result


def run_cgal(cgal, pair, timeout, in_process=False):
    """Each polygon meshed alone by CGAL at 25 degrees: Steiner counts and
    the CPU time of both processes together; with in_process, also that of
    both meshings inside their processes (mesh_s, timed over repeats)."""
    counts, cpu, mesh = [], 0.0, 0.0
    for f in pair.files:
        for repeat in (False, True) if in_process else (False,):
            cmd = [cgal, f, "%g" % CGAL_ANGLE] + (["%g" % CGAL_MIN_CPU] if repeat else [])
            code, seconds, _, out, err = run_measured(cmd, timeout)
            if code != 0:
                return {"error": "cm_cgal_single %s: %s" % (os.path.basename(f), err.strip() or code)}
            words = out.split()
            if repeat:
                mesh += float(words[words.index("mesh_cpu_s") + 1])
            else:
                counts.append(int(words[words.index("steiner") + 1]))
                cpu += seconds
    return {"steiner": counts, "cpu_s": cpu, **({"mesh_s": mesh} if in_process else {})}


def startup_cpu(cli):
    """compatmesh's start-up: the median CPU of `cli --version` runs, timed
    as its triangulate runs are (under /usr/bin/time)."""
    return statistics.median(run_measured([cli, "--version"], 60, peak_rss=True)[1] for _ in range(STARTUP_RUNS))


def measure_pair(pair, builds, modes, cgal, workdir, timeout, flip):
    """CGAL, then every build in every mode, builds alternating their order
    from pair to pair so neither always runs first."""
    record = {"cgal": run_cgal(cgal, pair, timeout, in_process=True) if cgal else None, "runs": {}}
    order = list(builds.items())
    if flip:
        order.reverse()
    for mode in modes:
        if mode != "index" and pair.family == "bench":
            continue
        record["runs"][mode] = {label: run_compatmesh(cli, pair, mode, workdir, timeout, extra)
                                for label, (cli, extra) in order}
    return record


# ---- derived numbers ---------------------------------------------------------

def ratio(a, b):
    return a / b if a is not None and b not in (None, 0) else None


def derive(run, target, cgal, startup):
    """Adds the ratios of one run to T and to CGAL (startup: its build's
    start-up CPU)."""
    if not run["valid"]:
        return run
    run["to_T"] = ratio(run["min_angle_deg"], target)
    run["map_cap_to_T"] = ratio(run.get("map_cap_deg"), target)
    run["angle_to_map_cap"] = ratio(run["min_angle_deg"], run.get("map_cap_deg"))
    if cgal and "error" not in cgal:
        run["steiner_to_cgal"] = ratio(run["steiner"], max(cgal["steiner"]))
        run["cpu_to_cgal"] = ratio(run["cpu_s"], cgal["cpu_s"])
        run["in_process_to_cgal"] = ratio(run["cpu_s"] - startup, cgal.get("mesh_s"))
    return run


def versus(new, base):
    """new / baseline ratios of the smallest angle, Steiner count and CPU."""
    if not (new["valid"] and base["valid"]):
        return None
    return {"angle": ratio(new["min_angle_deg"], base["min_angle_deg"]),
            "steiner": ratio(new["steiner"], base["steiner"]) if base["steiner"] else None,
            "cpu": ratio(new["cpu_s"], base["cpu_s"])}


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def reaches(angle, aim):
    """Does a smallest angle reach an aim (within AIM_TOLERANCE)?"""
    return angle >= aim * (1 - AIM_TOLERANCE)


def summarize(rows, label, mode, group):
    """One summary line's numbers for the rows of a group."""
    runs = [(r["c"], r["runs"][mode][label]) for r in rows if mode in r["runs"]]
    ok = [x for _, x in runs if x["valid"]]
    to_t = [x["to_T"] for x in ok if x.get("to_T") is not None]
    at_aims = {"at_min(%g,c/%g)" % (cap, div): sum(reaches(x["min_angle_deg"], min(cap, c / div))
                                                   for c, x in runs if x["valid"])
               for cap, div in AIMS}
    return {"build": label, "mode": mode, "group": group, "pairs": len(runs),
            "invalid": len(runs) - len(ok),
            "median_angle": median(x["min_angle_deg"] for x in ok),
            "median_to_T": median(to_t), "min_to_T": min(to_t) if to_t else None,
            "median_map_cap_to_T": median(x.get("map_cap_to_T") for x in ok),
            "median_angle_to_map_cap": median(x.get("angle_to_map_cap") for x in ok),
            "at_least_0.3T": sum(reaches(t, GOOD_SHARE_OF_T) for t in to_t),
            "at_least_0.55T": sum(reaches(t, HIGH_SHARE_OF_T) for t in to_t), **at_aims,
            "median_steiner": median(x["steiner"] for x in ok),
            "median_steiner_to_cgal": median(x.get("steiner_to_cgal") for x in ok),
            "median_cpu_s": median(x["cpu_s"] for x in ok),
            "median_cpu_to_cgal": median(x.get("cpu_to_cgal") for x in ok),
            "median_in_process_to_cgal": median(x.get("in_process_to_cgal") for x in ok),
            "median_under20_pct": median(max(x["under20_pct"]) for x in ok)}


def summarize_versus(rows, mode, group):
    pairs = [r["versus"][mode] for r in rows if r.get("versus", {}).get(mode)]
    return {"mode": mode, "group": group, "pairs": len(pairs),
            **{"median_" + k: median(p[k] for p in pairs) for k in ("angle", "steiner", "cpu")}}


GROUPS = (("tune", "hard family, tuning half"), ("hold", "hard family, held-out half"),
          ("bench", "bench set"), ("all", "all pairs"), ("other", "other fonts, set aside"))


def in_group(row, group):
    return row["half"] != "other" if group == "all" else row["half"] == group


# ---- the report --------------------------------------------------------------

def num(value, fmt="%.2f"):
    return "-" if value is None else fmt % value


def angle(value):
    return "-" if value is None else fmt_angle(value)


def pair_table(rows, mode, labels):
    """The Markdown table of one mode."""
    head = ["pair", "half", "n", "c", "fan", "bound (K)", "edge", "T"]
    for label in labels:
        p = "" if len(labels) == 1 else label + " "
        head += [p + "angle", p + "/T", p + "map cap", p + "<20 %", p + "Steiner", p + "St/CGAL", p + "CPU s",
                 p + "x CGAL", p + "x in process", p + "MB", p + "valid"]
    head.insert(len(head) - 11 * len(labels), "CGAL alone")
    if len(labels) == 2:
        head += ["angle new/base", "Steiner new/base", "CPU new/base"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        if mode not in r["runs"]:
            continue
        bound = "-" if r["bound_deg"] is None else "%s (%.3g)" % (angle(r["bound_deg"]), r["K"])
        cgal = r["cgal"]
        cells = [r["name"], r["half"], str(r["n"]), angle(r["c"]), angle(r["fan"]), bound,
                 angle(r["edge"]), angle(target_of(r, mode)),
                 "-" if not cgal else cgal.get("error") or " / ".join(map(str, cgal["steiner"]))]
        for label in labels:
            x = r["runs"][mode][label]
            if not x["valid"]:
                cells += ["-"] * 10 + ["**no**: %s" % x.get("error", "report not valid")]
                continue
            cells += [angle(x["min_angle_deg"]), num(x.get("to_T")), angle(x.get("map_cap_deg")),
                      " / ".join("%.0f" % s for s in x["under20_pct"]), str(x["steiner"]),
                      num(x.get("steiner_to_cgal"), "%.1f"), num(x["cpu_s"], "%.3g"),
                      num(x.get("cpu_to_cgal"), "%.0f"), num(x.get("in_process_to_cgal"), "%.0f"),
                      num(x["rss_mb"], "%.0f"), "yes"]
        if len(labels) == 2:
            v = r["versus"].get(mode) or {}
            cells += [num(v.get("angle")), num(v.get("steiner")), num(v.get("cpu"))]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def summary_lines(summaries):
    aims = ["min(%g,c/%g)" % a for a in AIMS]
    lines = ["| build | mode | pairs | invalid | median angle | median /T | min /T | median map cap /T | "
             "median angle / map cap | >= 0.3 T | >= 0.55 T | " +
             " | ".join(">= " + a.replace(",", ", ") for a in aims) + " | "
             "median Steiner | median St/CGAL | median CPU s | median x CGAL | median x CGAL in process | "
             "median <20 % |",
             "|" + "---|" * (17 + len(aims))]
    for s in summaries:
        valid = s["pairs"] - s["invalid"]
        lines.append("| %s | %s: %s | %d | %d | %s | %s | %s | %s | %s | %d of %d | %d of %d | %s | %s | %s | %s | %s | %s | %s |" % (
            s["build"], s["mode"], dict(GROUPS)[s["group"]], s["pairs"], s["invalid"],
            angle(s["median_angle"]), num(s["median_to_T"]), num(s["min_to_T"]),
            num(s["median_map_cap_to_T"]), num(s["median_angle_to_map_cap"], "%.3f"),
            s["at_least_0.3T"], valid, s["at_least_0.55T"], valid,
            " | ".join("%d of %d" % (s["at_" + a], valid) for a in aims), num(s["median_steiner"], "%.0f"),
            num(s["median_steiner_to_cgal"], "%.1f"), num(s["median_cpu_s"], "%.3g"),
            num(s["median_cpu_to_cgal"], "%.0f"), num(s["median_in_process_to_cgal"], "%.0f"),
            num(s["median_under20_pct"], "%.0f")))
    return lines


def versus_lines(summaries):
    lines = ["| mode | pairs | median angle new/base | median Steiner new/base | median CPU new/base |",
             "|---|---|---|---|---|"]
    for s in summaries:
        lines.append("| %s: %s | %d | %s | %s | %s |" % (
            s["mode"], dict(GROUPS)[s["group"]], s["pairs"], num(s["median_angle"]),
            num(s["median_steiner"]), num(s["median_cpu"])))
    return lines


# The written report: the introduction, the dated sections that earlier
# runs and their readings left (kept as they are), then this run's.
FULL_RUN = "\n## Full run ("


def kept_sections(path):
    """The dated sections of the report at path: from its first section
    to its last run's, which this run replaces ("" for a new report)."""
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        text = f.read()
    start, end = text.find("\n## "), text.rfind(FULL_RUN)
    if end < 0:
        end = text.find("\n## Summary")
    if start < 0 or end <= start:
        return ""
    return text[start + 1:end + 1]


def write_markdown(path, result):
    meta, rows = result["meta"], result["pairs"]
    labels = [b["label"] for b in meta["builds"]]
    lines = ["# Remesher benchmark", "",
             "`bench/remesh_bench.py` (its docstring defines every number). Hard family: "
             "`cm_gen_pairs --set hard` (glyphs of different letters from FreeSerif Italic and P052 "
             "for tuning; Nimbus Sans, Z003, URW Bookman, C059, Liberation Serif, Noto Sans, random "
             "simple polygons against discs and stars, and planar sections of Gmsh's STL models "
             "(`bench/stl_sections.py`) held out; n = 48 and 160, arc-length "
             "correspondence from the bottom-left point), next to the bench set "
             "(`cm_gen_pairs --set bench`). T = min(25, c/2, fan, bound), and edge too in "
             "index mode (boundary edges never split)%s." % (
                 "" if meta["bound"] else " (bound skipped: --no-bound)"), ""]
    kept = kept_sections(path)
    lines += ([kept] if kept else []) + ["## Full run (%s)" % meta["date"], ""]
    lines += ["- Date: %s; machine: %s, %d cores; load average %.1f at the start, %.1f at the end "
              "(CPU seconds are measured, not wall time)" % (meta["date"], meta["machine"], meta["cores"],
                                                             meta["load"][0], meta["load"][1]),
              "- Command: `%s` (bench at commit %s)" % (meta["command"], meta["commit"])]
    for b in meta["builds"]:
        lines.append("- %s: `%s` (%s; start-up %s ms of CPU)" % (b["label"], b["path"], b["version"],
                                                                   num(1e3 * b["startup_s"], "%.1f")))
    lines.append("- CGAL alone: %s" % (meta["cgal"] or "not run (--no-cgal)"))
    lines += ["", "## Summary", ""] + summary_lines(result["summary"])
    if result.get("versus"):
        lines += ["", "New over baseline, same pairs, same run:", ""] + versus_lines(result["versus"])
    for mode in meta["modes"]:
        lines += ["", "## Pairs, mode `%s`" % mode, ""] + pair_table(rows, mode, labels)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


# ---- main --------------------------------------------------------------------

def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--compatmesh", required=True, help="the compatmesh CLI to judge")
    ap.add_argument("--baseline", help="a second compatmesh CLI, run side by side")
    ap.add_argument("--compatmesh-args", default="",
                    help="options added to every triangulate run of --compatmesh, e.g. '--remesher map'")
    ap.add_argument("--baseline-args", default="", help="the same for --baseline")
    ap.add_argument("--gen-pairs", help="cm_gen_pairs (default: next to --compatmesh)")
    ap.add_argument("--cgal", help="cm_cgal_single (default: next to --compatmesh)")
    ap.add_argument("--no-cgal", action="store_true", help="skip meshing each polygon alone with CGAL")
    ap.add_argument("--no-bound", action="store_true", help="skip the correspondence bound")
    ap.add_argument("--bound-cache", default=os.path.join(HERE, "REMESH_bounds.json"),
                    help="the bounds computed so far, by pair content")
    ap.add_argument("--bound-jobs", type=int, default=1,
                    help="bounds computed at once, before the timed runs")
    ap.add_argument("--quick", action="store_true", help="a fixed subset of 32 pairs")
    ap.add_argument("--other", action="store_true", help="add the other fonts (cm_gen_pairs --set other)")
    ap.add_argument("--only", help="keep the pairs whose name matches this regular expression")
    ap.add_argument("--modes", default="index", help="comma-separated: index, auto")
    ap.add_argument("--out", default=os.path.join(HERE, "REMESH.md"))
    ap.add_argument("--json", help="also write the raw numbers here")
    ap.add_argument("--timeout", type=float, default=900, help="seconds per run")
    args = ap.parse_args(argv)
    args.modes = args.modes.split(",")
    if any(m not in ("index", "auto") for m in args.modes):
        ap.error("--modes: index and auto only")
    bindir = os.path.dirname(os.path.abspath(args.compatmesh))
    args.gen_pairs = args.gen_pairs or os.path.join(bindir, "cm_gen_pairs")
    args.cgal = None if args.no_cgal else args.cgal or os.path.join(bindir, "cm_cgal_single")
    for tool, what in ((args.compatmesh, "--compatmesh"), (args.baseline, "--baseline"),
                       (args.gen_pairs, "--gen-pairs"), (args.cgal, "--cgal")):
        if tool and not os.access(tool, os.X_OK):
            hint = " (CGAL: make bench-deps, rebuild; or --no-cgal)" if what == "--cgal" else ""
            ap.error("%s: %s is not an executable%s" % (what, tool, hint))
    return args


def machine():
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return platform.machine()


def source_commit():
    run = subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    return run.stdout.strip() or "unknown"


def version(cli):
    run = subprocess.run([cli, "--version"], capture_output=True, text=True)
    return run.stdout.strip() or "version unknown"


def static_row(pair, args, cache):
    """What the input allows: c, fan, bound and T."""
    c, fan = smallest_corner(pair.polygons), fan_cap(pair.polygons)
    bound = cache.get(pair) if not args.no_bound else {}
    b = bound.get("bound_deg")
    target = min(TARGET_CAP, c / 2, fan, b if b is not None else 60)
    edge = min(min(edge_cap(p), near_vertex_cap(p)) for p in pair.polygons)
    return {"name": pair.name, "family": pair.family, "half": pair.half, "n": pair.n,
            "key": content_key(pair.files), "c": c, "fan": fan, "bound_deg": b, "K": bound.get("K"),
            "edge": edge, "T": target, "T_index": min(target, edge)}


def target_of(row, mode):
    """T of a pair in a mode: index runs keep every boundary edge whole."""
    return row["T_index"] if mode == "index" else row["T"]


def main(argv):
    args = parse_args(argv)
    builds = {"new": (args.compatmesh, shlex.split(args.compatmesh_args))}
    if args.baseline:
        builds["baseline"] = (args.baseline, shlex.split(args.baseline_args))
    cache = BoundCache(args.bound_cache)
    load = os.getloadavg()[0]
    startups = {label: startup_cpu(cli) for label, (cli, _) in builds.items()}
    work = tempfile.mkdtemp(prefix="remesh_bench_")
    try:
        pairs = generate(args.gen_pairs, work, args.other)
        if not args.quick:
            hard = sum(p.family == "hard" for p in pairs)
            pairs[hard:hard] = sections(work, args.only)
        pairs = select(pairs, args.quick, args.only)
        if not pairs:
            print("remesh_bench: no pair selected", file=sys.stderr)
            return 2
        if not args.no_bound:
            cache.fill(args.compatmesh, pairs, args.timeout, args.bound_jobs)
        rows = []
        for i, pair in enumerate(pairs):
            row = static_row(pair, args, cache)
            row.update(measure_pair(pair, builds, args.modes, args.cgal, work, args.timeout, i % 2 == 1))
            for mode, runs in row["runs"].items():
                for label, run in runs.items():
                    derive(run, target_of(row, mode), row["cgal"], startups[label])
                if args.baseline:
                    row.setdefault("versus", {})[mode] = versus(runs["new"], runs["baseline"])
            if not row["runs"]:  # a bench-set pair when only auto is asked for
                continue
            rows.append(row)
            new = next(iter(row["runs"].values()))["new"]
            print("[%d/%d] %s T %.1f: %s" % (i + 1, len(pairs), pair.name, row["T_index"],
                  "%.2f deg, %d Steiner, %.3g s" % (new["min_angle_deg"], new["steiner"], new["cpu_s"])
                  if new["valid"] else "INVALID: " + new.get("error", "")), flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    summaries = [summarize([r for r in rows if in_group(r, g)], label, mode, g)
                 for mode in args.modes for label in builds for g, _ in GROUPS
                 if any(in_group(r, g) and mode in r["runs"] for r in rows)]
    vs = [summarize_versus([r for r in rows if in_group(r, g)], mode, g)
          for mode in args.modes for g, _ in GROUPS
          if args.baseline and any(in_group(r, g) and mode in r["runs"] for r in rows)]
    result = {"meta": {"date": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
                       "machine": machine(), "cores": os.cpu_count(),
                       "command": " ".join(["remesh_bench.py"] + argv), "commit": source_commit(),
                       "load": [load, os.getloadavg()[0]],
                       "builds": [{"label": k, "path": " ".join([v[0], *v[1]]), "version": version(v[0]),
                                   "startup_s": startups[k]} for k, v in builds.items()],
                       "cgal": args.cgal, "bound": not args.no_bound, "modes": args.modes},
              "pairs": rows, "summary": summaries, "versus": vs}
    write_markdown(args.out, result)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
    for line in summary_lines(summaries):
        print(line)
    invalid = [(r["name"], m, k) for r in rows for m, runs in r["runs"].items()
               for k, x in runs.items() if not x["valid"]]
    for name, mode, label in invalid:
        print("remesh_bench: %s (%s, %s) is not valid" % (name, mode, label), file=sys.stderr)
    print("remesh_bench: wrote %s%s" % (args.out, " and " + args.json if args.json else ""))
    return 1 if invalid else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
