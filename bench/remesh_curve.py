"""The remesher's time/quality curve: when each run reaches its final
smallest angle, as a share of its CPU time.

usage: remesh_curve.py --compatmesh TRACE_BIN [--quick] [--only REGEX]
                       [--modes index,auto] [--json FILE] [--gen-pairs BIN]
                       [--cgal BIN]

TRACE_BIN is a compatmesh CLI built with `-DCM_REMESH_TRACE=ON`: its
remesher writes one line per step to stderr (core/src/remesh/remesh.c,
trace()): the remesher (0 greedy, 1 map-aware), the step, the process's CPU
seconds (less the trace's own), the smallest angle in degrees, the Steiner
vertices and the forced moves tried so far. The steps: start (the working
mesh built; restart for a restart's run), cleanup (surplus Steiner vertices
collapsed, flips + smoothing), map (the map-aware start), refine (after each
refinement round), polish (flips + smoothing everywhere), step / step_none
(after each round of forced moves, one that gained / the last, which did
not), end (the late coarsening and the final polish), joint (the written
result's joint max-min polish), moves (the polish-scored moves). The pairs
are remesh_bench.py's (same generator, same --quick subset and modes).

Per run, angle(t) is the smallest angle of the result the pipeline would
have at t: the first run's working mesh while it runs; then the best
finished result, a later pairing's (auto) when it is higher, a restart's
when it is RESTART_GAIN higher (as the library keeps them; their working
meshes do not count), a map-aware rescue's working mesh where it is higher
(the better of the two is kept). Final: the last value. Printed per run:
the final angle, Steiner count, process CPU (os.wait4) and the shares of it
  pre      before the first start line (input, correspondence, construction)
  clean    cleanup (and the map-aware start)
  refine   the refinement rounds
  polish   the polish after them
  forced   the forced-move rounds
  late     the late coarsening and final polish
  joint    the joint max-min polish of the written result
  moves    the polish-scored moves
  rescue   the map-aware rescue run (all its steps)
  restart  the restarts' runs (all their steps)
  pairings auto's later pairings' runs (all their steps)
  post     after the last line (writing and checking the result)
and t90 / t95 / t99 / t100: the CPU share at which angle(t) first reaches
that share of the final angle. Also: the refinement's rounds, the share of
them (CPU) after its angle last rose, the angle gained by forced moves and
the forced moves tried. With --cgal, the share of the final angle angle(t)
holds at t = B times CGAL's CPU meshing each polygon alone (B in BUDGETS),
per run and as medians: the time-quality curve against CGAL. Medians per
mode at the end.
"""
import argparse
import json
import os
import shutil
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import remesh_bench  # noqa: E402

LEVELS = (0.90, 0.95, 0.99, 1.00)
STAGE_OF = {"start": "pre", "cleanup": "clean", "map": "clean", "refine": "refine", "polish": "polish",
            "step": "forced", "step_none": "forced", "end": "late", "joint": "joint", "moves": "moves"}
STAGES = ("pre", "clean", "refine", "polish", "forced", "late", "joint", "moves", "rescue", "restart", "pairings",
          "post")
# The stage of every line of a run after the first, by the run's kind
RUN_STAGE = {"rescue": "rescue", "restart": "restart", "pairing": "pairings"}


def library_constant(name, source=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "core", "src",
                                                "remesh", "remesh.c")):
    """A `#define NAME value` of the library's source, read where it is set."""
    with open(source) as f:
        for line in f:
            words = line.split()
            if words[:2] == ["#define", name]:
                return float(words[2])
    raise LookupError(f"{name} is not defined in {source}")


# A restart's result is kept when its smallest angle is this share higher
RESTART_GAIN = library_constant("CM_RESTART_GAIN")
# --cgal: the budgets, in multiples of CGAL's CPU meshing each polygon alone
BUDGETS = (5, 10, 20, 40, 80, 160)


def parse_trace(stderr):
    """[(remesher, step, cpu, angle, steiner, forced)] from the trace lines."""
    out = []
    for line in stderr.splitlines():
        w = line.split()
        if len(w) == 7 and w[0] == "cm_trace":
            out.append((int(w[1]), w[2], float(w[3]), float(w[4]), int(w[5]), int(w[6])))
    return out


def runs_of(trace):
    """The kind of the run each trace line belongs to: first, rescue (the
    map-aware one), restart or pairing (auto's later ones)."""
    kinds, kind = [], "first"
    first_remesher = trace[0][0]
    for i, (remesher, step, *_) in enumerate(trace):
        if i and step == "restart":
            kind = "restart"
        elif i and step == "start":
            kind = "pairing" if remesher == first_remesher else "rescue"
        kinds.append(kind)
    return kinds


def curve_of(trace, kinds):
    """angle(t) as the module's docstring says: [(t, angle, steiner)]."""
    curve, done_best = [], 0.0

    def finish(i):  # run ending at line i: its result may take over
        nonlocal done_best
        angle = trace[i][3]
        if kinds[i] == "restart":
            done_best = angle if angle >= (1 + RESTART_GAIN) * done_best else done_best
        else:
            done_best = max(done_best, angle)
        curve[i] = (curve[i][0], done_best, curve[i][2])

    for i, (_, step, t, angle, steiner, _) in enumerate(trace):
        if i and kinds[i] != "rescue" and step in ("start", "restart"):
            finish(i - 1)
        elif i and kinds[i] == "rescue" and kinds[i - 1] != "rescue":
            done_best = max(done_best, trace[i - 1][3])  # the greedy result, held
        value = {"first": angle, "rescue": max(angle, done_best)}.get(kinds[i], done_best)
        curve.append((t, value, steiner))
    finish(len(trace) - 1)
    return curve


def analyse(trace, cpu, cgal_cpu=None):
    """The numbers of one run from its trace and its process CPU (and
    CGAL's, for the budgets)."""
    stages = dict.fromkeys(STAGES, 0.0)
    kinds = runs_of(trace)
    prev_t = 0.0
    for (_, step, t, *_), kind in zip(trace, kinds):
        stages[STAGE_OF[step] if kind == "first" else RUN_STAGE[kind]] += t - prev_t
        prev_t = t
    stages["post"] += max(0.0, cpu - prev_t)
    curve = curve_of(trace, kinds)
    final = curve[-1][1]
    reach = {}
    for level in LEVELS:
        hit = next((t for t, a, _ in curve if a >= level * final), curve[-1][0])
        reach[level] = hit / cpu
    budget = {}
    for b in BUDGETS if cgal_cpu else ():
        held = [a for t, a, _ in curve if t <= b * cgal_cpu]
        budget[b] = (held[-1] if held else 0.0) / final
    first = [r for r, kind in zip(trace, kinds) if kind == "first"]
    rounds = [r for r in first if r[1] == "refine"]
    polish = next((r for r in first if r[1] == "polish"), None)
    end = next((r for r in first if r[1] == "end"), None)
    refine_tail = 0.0
    if rounds:
        last_rise, best = None, -1.0
        for r in rounds:
            if r[3] > best + 1e-12:
                best, last_rise = r[3], r[2]
        refine_tail = (rounds[-1][2] - last_rise) / cpu
    forced_gain = (end[3] - polish[3]) if polish and end else 0.0
    steps = [r for r in first if r[1] in ("step", "step_none")]
    return {"stages": {k: v / cpu for k, v in stages.items()}, "reach": reach, "budget": budget, "final": final,
            "peak": max(a for _, a, _ in curve), "steiner": curve[-1][2], "rounds": len(rounds),
            "refine_tail": refine_tail, "polish_angle": polish[3] if polish else None,
            "forced_gain": forced_gain, "forced_rounds": len(steps),
            "forced_tries": steps[-1][5] if steps else 0, "rescued": "rescue" in kinds,
            "curve": curve, "trace": trace}


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--compatmesh", required=True, help="a compatmesh CLI built with -DCM_REMESH_TRACE=ON")
    ap.add_argument("--gen-pairs", help="cm_gen_pairs (default: next to --compatmesh, else build/bin)")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only")
    ap.add_argument("--modes", default="index,auto")
    ap.add_argument("--json", help="also write every run's numbers and curve here")
    ap.add_argument("--cgal", help="cm_cgal_single: the curve at budgets in multiples of its CPU")
    ap.add_argument("--timeout", type=float, default=900)
    args = ap.parse_args(argv)
    gen = args.gen_pairs or os.path.join(os.path.dirname(os.path.abspath(args.compatmesh)), "cm_gen_pairs")
    if not os.access(gen, os.X_OK):
        ap.error("--gen-pairs: %s is not an executable" % gen)
    if args.cgal and not os.access(args.cgal, os.X_OK):
        ap.error("--cgal: %s is not an executable" % args.cgal)
    work = tempfile.mkdtemp(prefix="remesh_curve_")
    runs = []
    try:
        pairs = remesh_bench.select(remesh_bench.generate(gen, work), args.quick, args.only)
        for pair in pairs:
            cgal = remesh_bench.run_cgal(args.cgal, pair, args.timeout) if args.cgal else {}
            if "error" in cgal:
                print("remesh_curve: %s: %s" % (pair.name, cgal["error"]), file=sys.stderr)
                return 1
            for mode in args.modes.split(","):
                if mode != "index" and pair.family != "hard":
                    continue
                out = os.path.join(work, "run")
                shutil.rmtree(out, ignore_errors=True)
                cmd = [args.compatmesh, "triangulate", *pair.files, "--out-dir", out]
                if mode != "index":
                    cmd += ["--correspondence", mode]
                code, cpu, _, _, err = remesh_bench.run_measured(cmd, args.timeout)
                trace = parse_trace(err)
                if code != 0 or not trace:
                    print("remesh_curve: %s (%s) failed: %s" % (pair.name, mode, err.strip()[-200:]),
                          file=sys.stderr)
                    return 1
                a = analyse(trace, cpu, cgal.get("cpu_s"))
                with open(os.path.join(out, "report.json")) as f:
                    reported = min(m["min_angle_deg"] for m in json.load(f)["meshes"])
                if abs(a["final"] - reported) > 1e-6 * reported:
                    print("remesh_curve: %s (%s): the trace ends at %.9g degrees, the result has %.9g"
                          % (pair.name, mode, a["final"], reported), file=sys.stderr)
                    return 1
                a.update(name=pair.name, half=pair.half, mode=mode, cpu=cpu)
                runs.append(a)
                print("%-32s %-5s %6.2f deg %4d St %.3f s  t90 %.2f t95 %.2f t99 %.2f t100 %.2f "
                      % (pair.name, mode, a["final"], a["steiner"], cpu, *[a["reach"][lv] for lv in LEVELS])
                      + "".join(" %s %.2f" % (k, a["stages"][k]) for k in STAGES)
                      + "  rounds %d tail %.2f forced +%.2f deg (%d rounds, %d tries)"
                      % (a["rounds"], a["refine_tail"], a["forced_gain"], a["forced_rounds"], a["forced_tries"])
                      + "".join("  %gx %.2f" % (b, share) for b, share in a["budget"].items()), flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for mode in args.modes.split(","):
        rs = [r for r in runs if r["mode"] == mode]
        if not rs:
            continue
        med = lambda f: statistics.median(f(r) for r in rs)  # noqa: E731
        print("%s, %d runs: median t90 %.2f t95 %.2f t99 %.2f t100 %.2f; stages %s; refine tail %.2f%s"
              % (mode, len(rs), *[med(lambda r, lv=lv: r["reach"][lv]) for lv in LEVELS],
                 " ".join("%s %.2f" % (k, med(lambda r, k=k: r["stages"][k])) for k in STAGES),
                 med(lambda r: r["refine_tail"]),
                 "; share of the final angle at " + ", ".join(
                     "%gx CGAL %.2f" % (b, med(lambda r, b=b: r["budget"][b])) for b in BUDGETS)
                 if args.cgal else ""))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(runs, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
