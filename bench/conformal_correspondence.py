"""The conformal correspondence measured against `--correspondence auto`.

usage: conformal_correspondence.py --compatmesh BIN [--gen-pairs BIN]
           [--variants NAME,...] [--only REGEX] [--max-n N] [--jobs N]
           [--json FILE] [--baseline BIN] [--script-bound]

With --variants '' only compatmesh's own auto runs (beside --baseline's).

Every polygon is mapped conformally onto the unit disk: on a fine mesh of
it (compatmesh's triangulation of the polygon paired with itself, split
into four until it has 4000 triangles, as bench/correspondence_bound.py
builds it), the discrete Green's function G of a point z0 far from the
boundary (P1 elements, K G = e_z0, G = 0 on the boundary) gives the
harmonic measure of the boundary seen from z0 as the flux -(K G) at the
boundary nodes; its running sum, times 2 pi, is the boundary angle of the
conformal map taking z0 to the centre. Two polygons' maps agree up to an
automorphism of the disk, w -> e^(i rho) (w - a) / (1 - conj(a) w),
chosen here (Nelder-Mead from 16 rotations) to minimise the objective of
the variant:
  stretch     (also geo) the mean square log of the arc-length stretch d s_B / d s_A
              (normalised arc lengths): crowding balanced
  procrustes  the least-squares similarity residual of 128 points evenly
              spaced on polygon 0 and their images (today's auto criterion
              on the conformal correspondence)
The correspondence sigma: s_A -> s_B is then blended with arc length,
sigma_t = t sigma_conformal + (1 - t) sigma_linear, where sigma_linear is
linear in arc length between anchors: no anchors (one shift, the mean
offset of sigma_conformal) or the corners of polygon 0 turning by more
than 45 degrees, matched conformally. Variants geo-tT (automorphism by
stretch) and geoP-tT (by procrustes) instead blend in the stretch: d sigma / d s_A = (conformal stretch)^T, normalised.
Both polygons keep all their vertices (bit-identical, counter-clockwise,
vertex 0 of polygon 0 first) and get the other's vertices at their images
on their edges; a vertex whose image lies within half the parameter gap to
its neighbours of one of the other polygon's vertices is paired with it
(compatmesh's own merge rule, CM_SNAP in arclength.c). The merged pair is
run with `--correspondence index`; today's auto runs on the input pair.
Per run: smallest angle, Steiner vertices, boundary size and compatmesh's
correspondence bound (report.json ceiling) of the correspondence used.
"""
import argparse
import concurrent.futures
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np
import scipy.optimize
import scipy.sparse
import scipy.sparse.linalg

from correspondence_bound import Polygon
from make_results import read_xy

HERE = os.path.dirname(os.path.abspath(__file__))
SNAP = 0.5  # as CM_SNAP in core/src/correspond/arclength.c
ROTATIONS = 16
PROCRUSTES_SAMPLES = 128
CORNER_TURN_DEG = 45.0


def signed_area(p):
    p = np.asarray(p)
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


class Disk:
    """A polygon (counter-clockwise, vertex 0 first) and its boundary under
    the conformal map onto the disk: per fine boundary node its normalised
    arc length s and its angle theta (both increasing from vertex 0)."""

    def __init__(self, cli, points, workdir):
        self.points = points
        self.n = len(points)
        path = os.path.join(workdir, "poly.xy")
        with open(path, "w") as f:
            f.writelines("%r %r\n" % tuple(p) for p in points)
        mesh = Polygon(cli, path, workdir)
        xy = mesh.xy
        cycle = np.concatenate([e[:-1] for e in mesh.edge_nodes])
        boundary = np.zeros(len(xy), dtype=bool)
        boundary[cycle] = True
        # z0: the interior node farthest from the boundary nodes
        bxy = xy[cycle]
        inner = np.flatnonzero(~boundary)
        dist = np.full(len(inner), np.inf)
        for chunk in np.array_split(np.arange(len(bxy)), max(1, len(bxy) // 256)):
            d = np.linalg.norm(xy[inner][:, None, :] - bxy[chunk][None, :, :], axis=2).min(axis=1)
            dist = np.minimum(dist, d)
        z0 = inner[np.argmax(dist)]
        K = mesh.stiffness.tocsr()
        rhs = np.zeros(len(inner))
        rhs[np.searchsorted(inner, z0)] = 1.0
        G = np.zeros(len(xy))
        G[inner] = scipy.sparse.linalg.spsolve(K[inner][:, inner].tocsc(), rhs)
        flux = -(K @ G)[cycle]
        flux = np.maximum(flux, 0.0)
        flux /= flux.sum()
        # lumped: node k sits at the middle of its share of the measure
        theta = 2 * math.pi * (np.cumsum(flux) - 0.5 * flux)
        theta -= theta[0]
        seg = np.linalg.norm(np.roll(bxy, -1, axis=0) - bxy, axis=1)
        s = np.concatenate([[0.0], np.cumsum(seg)[:-1]]) / seg.sum()
        self.perimeter = seg.sum()
        self.s, self.theta = s, np.maximum.accumulate(theta)
        # the vertices' arc lengths (exact, from the input points)
        p = np.asarray(points)
        e = np.linalg.norm(np.roll(p, -1, axis=0) - p, axis=1)
        self.vertex_s = np.concatenate([[0.0], np.cumsum(e)[:-1]]) / e.sum()
        turn = []
        for i in range(self.n):
            a, b, c = p[i - 1], p[i], p[(i + 1) % self.n]
            u, v = b - a, c - b
            turn.append(math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0], u @ v)))
        self.turn = np.array(turn)

    def s_to_theta(self, s):
        s = np.asarray(s) % 1.0
        return np.interp(s, np.append(self.s, 1.0), np.append(self.theta, 2 * math.pi))

    def theta_to_s(self, theta):
        """Lifted: theta in any turn gives s + that turn."""
        turns = np.floor(np.asarray(theta) / (2 * math.pi))
        t = np.asarray(theta) - 2 * math.pi * turns
        return np.interp(t, np.append(self.theta, 2 * math.pi), np.append(self.s, 1.0)) + turns

    def point(self, s):
        """The boundary point at normalised arc length s (on an edge)."""
        s = float(s) % 1.0
        i = int(np.searchsorted(self.vertex_s, s, side="right") - 1)
        j = (i + 1) % self.n
        end = self.vertex_s[j] if j else 1.0
        t = (s - self.vertex_s[i]) / (end - self.vertex_s[i])
        a, b = self.points[i], self.points[j]
        return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))


def mobius_angle(theta, a, rho):
    w = np.exp(1j * theta)
    return np.angle(np.exp(1j * rho) * (w - a) / (1 - np.conj(a) * w))


class Correspondence:
    """sigma: s_A -> s_B (lifted, increasing) on a grid of s_A."""

    def __init__(self, A, B, objective):
        self.A, self.B = A, B
        self.grid = np.linspace(0.0, 1.0, 2048, endpoint=False)
        self.theta_a = A.s_to_theta(self.grid)
        if objective == "procrustes":
            self.pa = np.array([complex(*A.point(s)) for s in np.linspace(0, 1, PROCRUSTES_SAMPLES, endpoint=False)])
            self.pa -= self.pa.mean()
            self.sample_theta = A.s_to_theta(np.linspace(0, 1, PROCRUSTES_SAMPLES, endpoint=False))
        best = None
        for r in range(ROTATIONS):
            x0 = np.array([0.0, 0.0, 2 * math.pi * r / ROTATIONS])
            res = scipy.optimize.minimize(lambda x: self.cost(x, objective), x0, method="Nelder-Mead",
                                          options={"xatol": 1e-4, "fatol": 1e-7, "maxiter": 400})
            if best is None or res.fun < best.fun:
                best = res
        self.params = best.x
        self.sigma = self.map(self.theta_a, best.x)

    @staticmethod
    def unpack(x):
        z = complex(x[0], x[1])
        return z / (1 + abs(z)), x[2]

    def map(self, theta_a, x):
        """B's arc length of A's angles under the automorphism (lifted)."""
        a, rho = self.unpack(x)
        # the automorphism of B's disk that puts its angles on A's: invert
        # w -> e^(i rho) (w - a) / (1 - conj(a) w)
        w = np.exp(1j * theta_a) * np.exp(-1j * rho)
        wb = (w + a) / (1 + np.conj(a) * w)
        tb = np.unwrap(np.angle(wb))
        tb -= 2 * math.pi * math.floor(tb[0] / (2 * math.pi))
        return self.B.theta_to_s(tb)

    def cost(self, x, objective):
        if objective == "stretch":
            sb = self.map(self.theta_a, x)
            d = np.diff(np.append(sb, sb[0] + 1.0))
            d = np.maximum(d, 1e-12) * len(d)
            return float(np.mean(np.log(d) ** 2))
        sb = self.map(self.sample_theta, x)
        pb = np.array([complex(*self.B.point(s)) for s in sb])
        pb -= pb.mean()
        zw = np.vdot(self.pa, pb)
        zz, ww = np.vdot(self.pa, self.pa).real, np.vdot(pb, pb).real
        return float((ww - abs(zw) ** 2 / zz) / ww)


def geometric(corr, t):
    """The stretch d sigma / d s_A raised to the power t (from 1e-12 up:
    where the conformal stretch is below it, doubles hold no more of it),
    integrated: crowding e^-x becomes e^-tx."""
    sig, grid = corr.sigma, corr.grid
    d = np.diff(np.append(sig, sig[0] + 1.0)) * len(grid)
    rho = np.maximum(d, 1e-12) ** t
    rho /= rho.sum()
    out = np.concatenate([[0.0], np.cumsum(rho)[:-1]])
    return out + float(np.mean(sig - out))


def blended(corr, t, anchors):
    """sigma_t on corr.grid: t sigma + (1 - t) the piecewise-linear one."""
    A, sig, grid = corr.A, corr.sigma, corr.grid
    if anchors:
        corners = [A.vertex_s[i] for i in range(A.n) if abs(A.turn[i]) > CORNER_TURN_DEG]
    else:
        corners = []
    if len(corners) < 2:
        shift = float(np.mean(sig - grid))
        lin = grid + shift
    else:
        cs = np.array(corners)
        cb = np.interp(cs, grid, sig, period=None)
        xs = np.concatenate([cs, [cs[0] + 1.0]])
        ys = np.concatenate([cb, [cb[0] + 1.0]])
        g = np.where(grid < cs[0], grid + 1.0, grid)
        lin = np.interp(g, xs, ys)
        lin = np.where(grid < cs[0], lin - 1.0, lin)
    return t * sig + (1 - t) * lin


def merge(A, B, grid, sigma):
    """Two polygons of one count: A's vertices and B's at their images."""
    turns = range(-3, 4)  # sigma may start turns away from 0
    lifted_grid = np.concatenate([grid + k for k in turns])
    lifted_sigma = np.concatenate([sigma + k for k in turns])
    sa_of_b = np.interp(B.vertex_s, lifted_sigma, lifted_grid) % 1.0
    sb_of_a = np.interp(A.vertex_s, np.append(grid, 1.0), np.append(sigma, sigma[0] + 1.0))
    entries = [(A.vertex_s[i], 0, i) for i in range(A.n)] + [(sa_of_b[j], 1, j) for j in range(B.n)]
    param = {0: A.vertex_s, 1: sa_of_b}

    def room(g, i):
        p = param[g]
        order = np.sort(p)
        k = np.searchsorted(order, p[i])
        before = p[i] - order[k - 1] if k > 0 else p[i] - order[-1] + 1
        after = order[k + 1] - p[i] if k + 1 < len(order) else order[0] + 1 - p[i]
        return min(before, after)

    entries.sort(key=lambda e: (e[0], e[1]))
    merged = []  # [u, room, own A, own B]
    for u, g, i in entries:
        r = room(g, i)
        if merged and merged[-1][2 + g] is None and u - merged[-1][0] < SNAP * min(r, merged[-1][1]):
            merged[-1][2 + g] = i
        else:
            own = [None, None]
            own[g] = i
            merged.append([u, r, *own])
    pa, pb = [], []
    for u, _, ia, ib in merged:
        pa.append(A.points[ia] if ia is not None else A.point(u))
        pb.append(B.points[ib] if ib is not None else B.point(sb_of_a[ia]))
    return pa, pb


def ccw(points):
    return points if signed_area(points) > 0 else [points[0]] + points[:0:-1]


def run(cli, files, workdir, extra, script_bound=False):
    """One compatmesh run; script_bound: also bench/correspondence_bound.py
    on the boundaries in correspondence it wrote."""
    out = os.path.join(workdir, "out")
    shutil.rmtree(out, ignore_errors=True)
    proc = subprocess.run([cli, "triangulate", *files, "--out-dir", out, *extra],
                          capture_output=True, text=True, timeout=300)
    path = os.path.join(out, "report.json")
    if proc.returncode != 0 or not os.path.exists(path):
        return {"valid": False, "error": (proc.stderr.strip().splitlines() or ["?"])[-1]}
    r = json.load(open(path))
    ceiling = r.get("ceiling", {})
    result = {"valid": bool(r["valid"]), "angle": min(m["min_angle_deg"] for m in r["meshes"]),
              "steiner": r["steiner"], "n": r["n"], "bound": ceiling.get("correspondence_bound_deg"),
              "fan": ceiling.get("corner_fan_cap_deg")}
    if script_bound:
        boundaries = []
        for g, f in enumerate(files):
            stem = os.path.splitext(os.path.basename(f))[0]
            lines = open(os.path.join(out, stem + ".off")).read().split("\n")
            boundaries.append(os.path.join(workdir, "boundary%d.xy" % g))
            with open(boundaries[-1], "w") as b:
                b.writelines(" ".join(line.split()[:2]) + "\n" for line in lines[2:2 + r["n"]])
        bound = subprocess.run([sys.executable, os.path.join(HERE, "correspondence_bound.py"), cli, *boundaries],
                               capture_output=True, text=True)
        result["script_bound"] = float(bound.stdout.split()[0]) if bound.returncode == 0 else None
    return result


def variant_spec(name):
    """name: OBJECTIVE[-tT][-corners]"""
    parts = name.split("-")
    objective, t, anchors = parts[0], 1.0, False
    for p in parts[1:]:
        if p.startswith("t"):
            t = float(p[1:])
        elif p == "corners":
            anchors = True
    return objective, t, anchors


def measure(cli, name, files, variants, baseline=None, script_bound=False):
    row = {"pair": name}
    with tempfile.TemporaryDirectory() as workdir:
        row["auto"] = run(cli, files, workdir, ["--correspondence", "auto"], script_bound)
        if baseline:
            row["baseline auto"] = run(baseline, files, workdir, ["--correspondence", "auto"], script_bound)
        if not variants:
            return row
        points = [ccw(read_xy(f)) for f in files]
        try:
            disks = [Disk(cli, p, workdir) for p in points]
        except Exception as e:  # noqa: BLE001 - reported per pair
            row["error"] = str(e)
            return row
        corrs = {}
        for v in variants:
            objective, t, anchors = variant_spec(v)
            objective = {"geo": "stretch", "geoP": "procrustes"}.get(objective, objective)
            if objective not in corrs:
                corrs[objective] = Correspondence(disks[0], disks[1], objective)
            c = corrs[objective]
            sigma = geometric(c, t) if v.startswith("geo") else blended(c, t, anchors)
            pa, pb = merge(disks[0], disks[1], c.grid, sigma)
            paths = [os.path.join(workdir, "m%d.xy" % g) for g in range(2)]
            for path, pts in zip(paths, (pa, pb)):
                with open(path, "w") as f:
                    f.writelines("%r %r\n" % (float(x), float(y)) for x, y in pts)
            row[v] = run(cli, paths, workdir, ["--correspondence", "index"])
            row[v]["automorphism"] = [float(x) for x in c.params]
    return row


def pairs(gen, workdir):
    out = []
    for set_name in ("hard", "bench"):
        d = os.path.join(workdir, set_name)
        subprocess.run([gen, "--out", d, "--set", set_name], check=True, capture_output=True)
        for line in open(os.path.join(d, "pairs.txt")):
            name, *files = line.split()
            out.append((name, [os.path.join(d, f) for f in files]))
    return out


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("--compatmesh", required=True)
    ap.add_argument("--gen-pairs")
    ap.add_argument("--variants", default="stretch")
    ap.add_argument("--only")
    ap.add_argument("--max-n", type=int, default=10 ** 9)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--json")
    ap.add_argument("--baseline", help="another compatmesh whose auto runs beside")
    ap.add_argument("--script-bound", action="store_true",
                    help="the auto runs' bound also by bench/correspondence_bound.py")
    args = ap.parse_args(argv[1:])
    cli = os.path.abspath(args.compatmesh)
    gen = args.gen_pairs or os.path.join(os.path.dirname(cli), "cm_gen_pairs")
    variants = [v for v in args.variants.split(",") if v]
    baseline = os.path.abspath(args.baseline) if args.baseline else None
    rows = []
    with tempfile.TemporaryDirectory() as workdir:
        todo = [(n, f) for n, f in pairs(gen, workdir)
                if (not args.only or re.search(args.only, n)) and len(read_xy(f[0])) <= args.max_n
                and len(f) == 2]
        with concurrent.futures.ProcessPoolExecutor(args.jobs) as ex:
            futures = [ex.submit(measure, cli, n, f, variants, baseline, args.script_bound) for n, f in todo]
            for fut in futures:
                row = fut.result()
                rows.append(row)
                line = [row["pair"]]
                for v in ["auto"] + (["baseline auto"] if baseline else []) + variants:
                    r = row.get(v)
                    if r is None:
                        line.append("%s: %s" % (v, row.get("error", "?")))
                    elif not r["valid"]:
                        line.append("%s: invalid (%s)" % (v, r.get("error")))
                    else:
                        line.append("%s: %.1f deg %d St n %d bound %.1f%s" % (
                            v, r["angle"], r["steiner"], r["n"], r["bound"] or 60,
                            " script %.1f" % r["script_bound"] if r.get("script_bound") else ""))
                print(" | ".join(line), flush=True)
    if args.json:
        json.dump(rows, open(args.json, "w"), indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
