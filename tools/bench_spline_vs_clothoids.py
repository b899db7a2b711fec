"""lac's G2 spline through points against a G2 clothoid spline built on the Clothoids library
(Bertolazzi & Frego, PyPI `Clothoids`), at alpha = -1, on the same random point sets.

    make py                                       # the venv with Clothoids and lac's bindings
    .venv/bin/python tools/bench_spline_vs_clothoids.py [--sets 200] [--points 6] [--seed 1]

Clothoids' own G2 spline (`ClothoidSplineG2` in C++) is not in its Python binding: in C++ it
is the system of G2 constraints for an external solver (its MATLAB class hands it to fsolve
or IPOPT). This script solves that same system: the unknowns are the tangent angles at the
interior points, every span is Clothoids' `build_G1` between its two points and tangents, and
the equations are curvature continuity at the interior points; Newton's method with a
finite-difference tridiagonal Jacobian and a backtracking line search, in Python, to a
relative curvature jump of 1e-9 at every point. lac's spline (`lac.Spline`, Rust) solves the
same equations with log-aesthetic segments, which at alpha = -1 are clothoid arcs; both start
from the tangents of the circles through each point and its neighbours and get the same end
tangents (those of the circles through the first and last three points, lac's default).

Two kinds of point sets: "one-way" (every turn of the polygon through the points has the same
sign) and "any" (turns of random sign). On "any" sets many spans must inflect: a clothoid
span passes through its inflection, and lac draws such a span as an S (one log-aesthetic
curve continued through its point of zero curvature, two segments that meet there), which at
alpha = -1 is the same clothoid arc.

Prints one JSON object: per kind, the share each solved, the median time per solve (lac: the
Rust solve through its binding; Clothoids: the Python Newton loop around the C++ `build_G1`,
so it measures that loop more than the library), and where both solved, the largest
difference of their tangent angles (the same clothoid spline, if the solution is unique).
"""

import argparse
import json
import math
import statistics
import time

import numpy as np

import Clothoids
import lac

TOL = 1e-9
STEPS = 60
H = 1e-7


def wrap(a):
    return a - 2 * math.pi * math.floor((a + math.pi) / (2 * math.pi))


def direction(a, b):
    return math.atan2(b[1] - a[1], b[0] - a[0])


def circle_tangent(a, b, c):
    """The tangent direction at b of the circle through a, b, c."""
    ab = direction(a, b)
    return ab + wrap(direction(b, c) - ab) - wrap(direction(a, c) - ab)


def start_angles(p):
    """lac's start: circle tangents inside, and its default end tangents."""
    n = len(p)
    th = [0.0] + [circle_tangent(p[i - 1], p[i], p[i + 1]) for i in range(1, n - 1)] + [0.0]
    d0 = wrap(direction(p[1], p[2]) - direction(p[0], p[1]))
    d1 = wrap(direction(p[n - 2], p[n - 1]) - direction(p[n - 3], p[n - 2]))
    th[0] = direction(p[0], p[2]) - d0
    th[-1] = direction(p[n - 3], p[n - 1]) + d1
    return th


def point_set(rng, n, one_way):
    """n points along a random walk: legs of 1-3, turns of 0.2-0.8 rad."""
    p, heading = [(0.0, 0.0)], rng.uniform(-math.pi, math.pi)
    sign = 1.0 if rng.random() < 0.5 else -1.0
    for _ in range(n - 1):
        length = rng.uniform(1.0, 3.0)
        x, y = p[-1]
        p.append((x + length * math.cos(heading), y + length * math.sin(heading)))
        turn = rng.uniform(0.2, 0.8)
        heading += sign * turn if one_way else turn * (1.0 if rng.random() < 0.5 else -1.0)
    return p


class ClothoidSpline:
    """The G2 clothoid spline through `p` with end tangents th[0], th[-1]."""

    def __init__(self, p):
        self.p = p
        self.curve = Clothoids.ClothoidCurve()

    def ends(self, i, a, b):
        """Curvature at the start and end of span i with end tangents a, b."""
        (x0, y0), (x1, y1) = self.p[i], self.p[i + 1]
        c = self.curve
        if not c.build_G1(x0, y0, a, x1, y1, b):
            raise ArithmeticError("build_G1 failed")
        return c.kappa(0.0), c.kappa(c.length())

    def residual(self, th):
        k = [self.ends(i, th[i], th[i + 1]) for i in range(len(self.p) - 1)]
        r = np.array([k[j - 1][1] - k[j][0] for j in range(1, len(self.p) - 1)])
        scale = np.array([max(abs(k[j - 1][1]), abs(k[j][0]), 1e-300)
                          for j in range(1, len(self.p) - 1)])
        return k, r, scale

    def solve(self, th):
        th = list(th)
        n = len(self.p)
        k, r, scale = self.residual(th)
        for _ in range(STEPS):
            if np.all(np.abs(r) <= TOL * scale):
                return th, float(np.max(np.abs(r) / scale))
            # d k0, d k1 of each span in the angles at its two ends.
            d = []
            for i in range(n - 1):
                a = [(ka - k[i][0]) / H for ka in (self.ends(i, th[i] + H, th[i + 1])[0],
                                                   self.ends(i, th[i], th[i + 1] + H)[0])]
                b = [(kb - k[i][1]) / H for kb in (self.ends(i, th[i] + H, th[i + 1])[1],
                                                   self.ends(i, th[i], th[i + 1] + H)[1])]
                d.append((a, b))
            m = n - 2
            jac = np.zeros((m, m))
            for u in range(m):
                j = u + 1  # r_j = k1(span j-1) - k0(span j)
                jac[u, u] = d[j - 1][1][1] - d[j][0][0]
                if u > 0:
                    jac[u, u - 1] = d[j - 1][1][0]
                if u + 1 < m:
                    jac[u, u + 1] = -d[j][0][1]
            try:
                dx = np.linalg.solve(jac, -r)
            except np.linalg.LinAlgError:
                break
            big = float(np.max(np.abs(dx)))
            lam = min(1.0, 0.2 / big) if big > 0 else 1.0
            now = float(np.linalg.norm(r / scale))
            for _ in range(30):
                trial = th[:1] + [th[j] + lam * dx[j - 1] for j in range(1, n - 1)] + th[-1:]
                try:
                    k2, r2, s2 = self.residual(trial)
                except ArithmeticError:
                    lam *= 0.5
                    continue
                if float(np.linalg.norm(r2 / s2)) < now * (1 - 1e-4 * lam):
                    th, k, r, scale = trial, k2, r2, s2
                    break
                lam *= 0.5
            else:
                break
        if np.all(np.abs(r) <= TOL * scale):
            return th, float(np.max(np.abs(r) / scale))
        return None, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sets", type=int, default=200, help="point sets per kind")
    ap.add_argument("--points", type=int, default=6, help="points per set")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    import random
    rng = random.Random(args.seed)
    out = {"alpha": -1.0, "points": args.points, "sets": args.sets, "tolerance": TOL}
    for kind, one_way in (("one_way", True), ("any", False)):
        lac_ok = clo_ok = both = 0
        lac_t, clo_t, agree, lac_jump, clo_jump = [], [], [], [], []
        for _ in range(args.sets):
            p = point_set(rng, args.points, one_way)
            th0 = start_angles(p)
            t = time.perf_counter()
            try:
                spline = lac.Spline(np.array(p), -1.0, False, ends=[th0[0], th0[-1]])
            except lac.LacError:
                spline = None
            lac_t.append(time.perf_counter() - t)
            t = time.perf_counter()
            try:
                th, jump = ClothoidSpline(p).solve(th0)
            except ArithmeticError:
                th, jump = None, None
            clo_t.append(time.perf_counter() - t)
            if spline is not None:
                lac_ok += 1
                lac_jump.append(spline.max_curvature_jump)
            if th is not None:
                clo_ok += 1
                clo_jump.append(jump)
            if spline is not None and th is not None:
                both += 1
                agree.append(max(abs(wrap(a - b)) for a, b in zip(spline.angles, th)))
        out[kind] = {
            "lac_solved": lac_ok / args.sets,
            "clothoids_solved": clo_ok / args.sets,
            "both_solved": both / args.sets,
            "lac_median_us": 1e6 * statistics.median(lac_t),
            "clothoids_median_us": 1e6 * statistics.median(clo_t),
            "lac_max_jump": max(lac_jump, default=None),
            "clothoids_max_jump": max(clo_jump, default=None),
            "max_angle_difference": max(agree, default=None),
        }
    print(json.dumps(out))


if __name__ == "__main__":
    main()
