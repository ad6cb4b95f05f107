"""The remesher on pairs whose best map is known: a regular n-gon against its
image under diag(s, 1/s).

usage: affine_bench.py COMPATMESH [--sizes 48,200] [--stretches 2,3,4,5,7]

Why the cap is exact here. Vertex i of the n-gon corresponds to vertex i of
its image, so the boundary map is the affine map A = diag(s, 1/s) on every
edge, and an affine map of a disc is the extremal quasiconformal map for
its boundary values: every homeomorphism with them, the piecewise-linear
map of any compatible triangulation included, has a dilatation of at least
K = s^2 somewhere. A triangle whose angles are all at least alpha in both
meshes is mapped with dilatation at most K(alpha) (correspondence_bound.py),
so no compatible triangulation has a smallest angle above the cap alpha
with K(alpha) = s^2 (and the remesher's 25 degrees).

What can be reached inside. Every triangle tiles the plane, so a lattice
of one triangle and its affine image has the smaller of their smallest
angles everywhere; the best triangle for A (found here by Nelder-Mead over
its shape and turn) gives the lattice angle: the cap itself, since K(alpha)
is the dilatation between two alpha-triangles. A mesh reaching it needs that
lattice's connectivity, aligned to the stretch, joined to the polygon's
boundary.

Prints one Markdown row per pair: s, n, K, the cap, the lattice angle,
T = min(25, cap) (as bench/remesh_bench.py's T), the smallest angle
compatmesh reaches (index correspondence, default options), its ratio to
T, Steiner vertices and CPU seconds.
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile

from scipy.optimize import minimize

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from correspondence_bound import angle_bound  # noqa: E402
from make_results import smallest_corner  # noqa: E402


def lattice_angle(s):
    """The largest smallest angle of a triangle and its image under
    diag(s, 1/s), over the triangle's shape and turn."""
    def worst(x):
        turn, ax, ay = x
        if ay <= 0:
            return 1e9
        c, d = math.cos(turn), math.sin(turn)
        tri = [(0.0, 0.0), (c, d), (ax * c - ay * d, ax * d + ay * c)]
        image = [(s * x, y / s) for x, y in tri]
        return -min(smallest_corner(tri), smallest_corner(image))
    best = 0.0
    for i in range(24):
        start = (math.pi * i / 24, 0.5, 0.3 + 0.1 * (i % 8))
        r = minimize(worst, start, method="Nelder-Mead", options={"xatol": 1e-10, "fatol": 1e-10, "maxiter": 4000})
        best = max(best, -r.fun)
    return best


def write_polygon(path, points):
    with open(path, "w") as f:
        f.writelines("%.17g %.17g\n" % p for p in points)


def run(cli, s, n, work):
    disc = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]
    a, b = os.path.join(work, "disc.xy"), os.path.join(work, "ellipse.xy")
    write_polygon(a, disc)
    write_polygon(b, [(s * x, y / s) for x, y in disc])
    out = os.path.join(work, "out")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([cli, "triangulate", a, b, "-o", out, "--quiet", "--no-preview"], capture_output=True,
                       text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise SystemExit("affine_bench.py: s = %g, n = %d: %s" % (s, n, r.stderr.strip()))
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return min(m["min_angle_deg"] for m in report["meshes"]), report["steiner"], cpu


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("compatmesh")
    ap.add_argument("--sizes", default="48,200")
    ap.add_argument("--stretches", default="2,3,4,5,7")
    args = ap.parse_args(argv)
    print("| s | n | K | cap (deg) | lattice (deg) | T (deg) | compatmesh (deg) | / T | Steiner | CPU s |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for s in (float(x) for x in args.stretches.split(",")):
            cap = angle_bound(s * s)
            lattice = lattice_angle(s)
            for n in (int(x) for x in args.sizes.split(",")):
                angle, steiner, cpu = run(args.compatmesh, s, n, work)
                print("| %g | %d | %g | %.2f | %.2f | %.2f | %.2f | %.2f | %d | %.3g |" % (
                    s, n, s * s, cap, lattice, min(25.0, cap), angle, angle / min(25.0, cap), steiner, cpu),
                    flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
