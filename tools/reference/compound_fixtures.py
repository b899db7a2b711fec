#!/usr/bin/env python3
"""Independent 40-digit reference for compound-rhythm LAC curves (docs/math.md §4).

Writes crates/lac/tests/fixtures/compound.json.  Run from anywhere:

    .venv/bin/python tools/reference/compound_fixtures.py [-o OUT] [-j JOBS]

Mathematics (joint-reference form, docs/math.md §4)
--------------------------------------------------
Both pieces live in one standard form with the reference point (rho = 1, theta = 0,
tangent +x) at the joint and the same Lambda:

    piece 0:  theta in [-th0, 0] of LAC(a0, Lambda)
    piece 1:  theta in [0,  th1] of LAC(a1, Lambda)

so rho and drho/ds = Lambda rho^(1-alpha) are continuous at the joint (G3, seed 004
eq. 3.5 with rho_c = 1).  rho grows along the curve, so the standard-form start is the
sharp end.  Lambda ranges over [0, Lmax), Lmax = min(1/(th0 (a0-1)) if a0 > 1,
1/(th1 (1-a1)) if a1 < 1), and is found so that the chord angle at the start (angle from
the start tangent, direction -th0, to the chord P(th1) - P(-th0)) equals the required
theta_e.  At Lambda = 0 (circle) the chord angle is Theta/2; it grows with Lambda (checked
on a scan for every case).  A caller problem with theta_e < Theta/2 is solved reversed:
ends swapped, a0 <-> a1, th0 <-> th1, theta_e -> Theta - theta_e.  Right turns are solved
mirrored.  A similarity (plus reflection) maps the standard start/end to the caller's.

Inputs
  three points a0 a1 a2 + a0, a1, ratio r (seed 004): Theta = |turn(a1-a0, a2-a1)| < pi,
      th0 = r Theta on the caller's first piece, theta_e = angle at a0 between a1-a0 and
      a2-a0.
  four points P0..P3 + a0, a1 (seed 002): th0 = |turn(P1-P0, P2-P1)|,
      th1 = |turn(P2-P1, P3-P2)| (same sign), theta_e = angle from P1-P0 to P3-P0 in the
      turning direction, in [0, 2 pi).

Numbers: every input is a double; mpf(double) is exact and everything is computed at
mp.dps = 40 from those doubles.  Points of a piece come from lac_mpmath.StandardForm
(graded Gauss-Legendre in theta, checked against the arc-length form to 1e-25).

Output (caller's frame and order): lambda (the joint-reference Lambda as solved, which is
drho/ds at the joint and scale-free), arc_length, joint_s, curvature_start/joint/end
(signed, + = left), samples at arc-length fractions u (s from the first point, theta =
tangent direction from atan2 of the first leg, continuous, kappa signed), plus two
informational flags: "reversed" (the solve ran with the ends swapped) and "right_turn".
"kind" labels the slopes in the caller's order (valley: alpha0 < 0 < alpha1, mountain:
alpha0 > 0 > alpha1, same-sign, equal, circle, near-circle; ",turn>pi" for four points
turning more than pi); not-drawable cases carry "drawable": false and a "reason".

Cross-checks done inside this script, for every drawable case
  * the caller's first and last tangents are reproduced (this is the chord-angle match);
    for three points, the tangent intersection lands on a1;
  * the seed-004 construction (reference point at the start, Lambda0, rho_c,
    Lambda1 = Lambda0 rho_c^(a1-a0), theta_s, piece 1 rotated onto the joint) gives the
    same chord angle and chord length;
  * drho/ds on both sides of the joint, by one-sided finite differences of the closed
    forms rho(theta(s)), equals Lambda (G3), and rho = 1 on both sides;
  * the solved Lambda agrees with the Lambda the case was generated from;
  * a0 = a1: the curve equals segment_mpmath.solve_segment's single segment (for four
    points with Theta < pi, on the tangent intersection) to 1e-25.
"""

import argparse
import json
import os
import random
import sys
import time
from multiprocessing import Pool

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from mpmath import mp, mpf, mpc, arg, atan2, conj, expj, expm1, fabs, inf, log, pi  # noqa: E402

from lac_mpmath import StandardForm  # noqa: E402
from segment_mpmath import illinois  # noqa: E402
import segment_mpmath  # noqa: E402

DPS = 40
mp.dps = DPS
FRACTIONS = [0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0]
DEFAULT_OUT = os.path.join(HERE, "..", "..", "crates", "lac", "tests", "fixtures", "compound.json")
LAMBDA_THETA_CAP = 200  # Lambda * Theta beyond this: ill-conditioned / too costly for a fixture


class NotDrawable(Exception):
    pass


class IllConditioned(Exception):
    pass


def cross(u, v):
    return u.real * v.imag - u.imag * v.real


def dot(u, v):
    return u.real * v.real + u.imag * v.imag


def turn(u, v):
    """Signed turning angle from u to v, in (-pi, pi]."""
    return atan2(cross(u, v), dot(u, v))


# ---------------------------------------------------------------------------------------
# The standard (joint-reference) problem
# ---------------------------------------------------------------------------------------
class Std:
    """The left-turning, rho-increasing problem: slopes (a0, a1), turnings (t0, t1) > 0."""

    def __init__(self, a0, a1, t0, t1):
        self.a0, self.a1 = mpf(a0), mpf(a1)
        self.t0, self.t1 = mpf(t0), mpf(t1)
        self.T = self.t0 + self.t1
        lm = inf
        if self.a0 > 1:
            lm = min(lm, 1 / (self.t0 * (self.a0 - 1)))
        if self.a1 < 1:
            lm = min(lm, 1 / (self.t1 * (1 - self.a1)))
        self.lmax = lm

    def pieces(self, lam):
        return StandardForm(self.a0, lam), StandardForm(self.a1, lam)

    def chord(self, lam, check=False):
        """P(t1) - P(-t0)."""
        f0, f1 = self.pieces(lam)
        return f0.point(0, -self.t0, check=check) + f1.point(self.t1, 0, check=check)

    def unwrap(self, z_rel_start_tangent):
        """Angle of a vector given relative to the start tangent, taken continuously from
        Theta/2 (the circle's chord angle): valid for angles in (Theta/2 - pi, Theta/2 + pi]."""
        return self.T / 2 + arg(z_rel_start_tangent * expj(-self.T / 2))

    def chord_angle(self, lam, check=False):
        return self.unwrap(self.chord(lam, check) * expj(self.t0))

    def chord_angle_at_bound(self):
        """Chord angle at Lambda = Lmax: a piece ends exactly at rho = 0 or rho = inf."""
        lam = self.lmax
        f0, f1 = self.pieces(lam)
        lo = f0.theta_singular() if (self.a0 > 1 and fabs(f0.theta_singular() + self.t0)
                                     <= mpf(10) ** (-DPS + 5) * self.t0) else -self.t0
        hi = f1.theta_singular() if (self.a1 < 1 and fabs(f1.theta_singular() - self.t1)
                                     <= mpf(10) ** (-DPS + 5) * self.t1) else self.t1
        if hi != self.t1 and self.a1 >= 0:
            # 0 <= a1 < 1: the inflection (rho = inf) is at infinite distance along the end
            # tangent, so the chord angle tends to Theta itself
            return self.T
        c = f0.point(0, lo) + f1.point(hi, 0)
        return self.unwrap(c * expj(-lo))

    def candidates(self):
        cap = LAMBDA_THETA_CAP / self.T
        if self.lmax == inf:
            return [mpf(10) ** (m / mpf(2)) / self.T for m in range(-4, 5)] + [cap]
        L = self.lmax
        return ([L * f for f in (mpf(1) / 64, mpf(1) / 16, mpf(1) / 4, mpf(1) / 2, mpf(3) / 4,
                                 mpf(7) / 8)]
                + [L * (1 - mpf(10) ** -k) for k in range(2, 13)])

    def solve(self, theta_e):
        """Lambda with chord_angle(Lambda) = theta_e (theta_e >= Theta/2)."""
        theta_e = mpf(theta_e)
        f0 = self.T / 2 - theta_e
        if fabs(f0) <= mpf(10) ** (-DPS + 3) * self.T:
            return mpf(0)  # isosceles control triangle: circular arc
        assert f0 < 0
        with mp.workdps(20):
            f = lambda lam: self.chord_angle(lam) - theta_e
            lo, flo, hi, fhi = mpf(0), f0, None, None
            prev = f0
            for c in self.candidates():
                fc = f(c)
                if fc < prev - mpf("1e-15"):
                    raise AssertionError("chord angle not monotone in Lambda", self.a0, self.a1,
                                         self.t0, self.t1, c)
                prev = fc
                if fc >= 0:
                    hi, fhi = c, fc
                    break
                lo, flo = c, fc
        if hi is None:
            if self.lmax < inf:
                gap = theta_e - self.chord_angle_at_bound()
                if gap > mpf("1e-7"):
                    raise NotDrawable("theta_e exceeds the largest chord angle for these slopes "
                                      "and turnings")
            raise IllConditioned("Lambda within 1e-12 of its bound or Lambda Theta > cap")
        with mp.workdps(20):
            lam = illinois(f, lo, flo, hi, fhi, mpf("1e-17"))
        if self.lmax < inf and lam >= self.lmax * (1 - mpf("1e-11")):
            raise IllConditioned("Lambda within 1e-11 of its bound")
        # secant at full precision
        f = lambda lam: self.chord_angle(lam) - theta_e
        x0, x1 = lam, lam * (1 + mpf("1e-13"))
        y0, y1 = f(x0), f(x1)
        for _ in range(30):
            if y1 == y0:
                break
            x2 = x1 - y1 * (x1 - x0) / (y1 - y0)
            x0, y0, x1 = x1, y1, x2
            y1 = f(x1)
            if fabs(x1 - x0) <= mpf(10) ** (-DPS + 4) * fabs(x1) or y1 == 0:
                break
        assert fabs(y1) < mpf("1e-32"), ("secant", y1)
        if self.lmax < inf and x1 >= self.lmax * (1 - mpf("1e-12")):
            raise IllConditioned("Lambda within 1e-12 of its bound")
        return x1


# ---------------------------------------------------------------------------------------
# Caller problems -> standard problem
# ---------------------------------------------------------------------------------------
def parse_three(pts, alpha0, alpha1, ratio):
    a0, a1, a2 = [mpc(mpf(x), mpf(y)) for x, y in pts]
    v1, v2 = a1 - a0, a2 - a1
    if v1 == 0 or v2 == 0:
        raise NotDrawable("coincident control points")
    c = cross(v1, v2)
    if c == 0:
        raise NotDrawable("collinear control points")
    if not (0 < ratio < 1):
        raise ValueError("ratio must be in (0, 1)")
    sigma = 1 if c > 0 else -1
    T = fabs(turn(v1, v2))
    t0 = mpf(ratio) * T
    theta_e = fabs(turn(v1, a2 - a0))
    return dict(start=a0, end=a2, first_leg=v1, last_leg=v2, sigma=sigma,
                alpha=(mpf(alpha0), mpf(alpha1)), theta=(t0, T - t0), theta_e=theta_e,
                corner=a1)


def parse_four(pts, alpha0, alpha1):
    p0, p1, p2, p3 = [mpc(mpf(x), mpf(y)) for x, y in pts]
    v1, v2, v3 = p1 - p0, p2 - p1, p3 - p2
    if v1 == 0 or v2 == 0 or v3 == 0 or p3 == p0:
        raise NotDrawable("coincident control points")
    c1, c2 = cross(v1, v2), cross(v2, v3)
    if c1 == 0 or c2 == 0:
        raise NotDrawable("consecutive legs collinear (no turning, or turning of exactly pi)")
    if (c1 > 0) != (c2 > 0):
        raise NotDrawable("control polygon has an inflection")
    sigma = 1 if c1 > 0 else -1
    t0, t1 = fabs(turn(v1, v2)), fabs(turn(v2, v3))
    te = sigma * turn(v1, p3 - p0)
    if te < 0:
        te += 2 * pi
    if te == 0:
        raise NotDrawable("last point on the start tangent")
    return dict(start=p0, end=p3, first_leg=v1, last_leg=v3, sigma=sigma,
                alpha=(mpf(alpha0), mpf(alpha1)), theta=(t0, t1), theta_e=te, corner=None)


def solve_caller(prob, lam_expected=None):
    """Solve a parsed caller problem; returns the fixture record (mpf values) and checks."""
    T = prob["theta"][0] + prob["theta"][1]
    te = prob["theta_e"]
    reversed_ = te < T / 2 - mpf(10) ** (-DPS + 3) * T  # ties (isosceles) are circles
    if reversed_:
        std = Std(prob["alpha"][1], prob["alpha"][0], prob["theta"][1], prob["theta"][0])
        te_std = T - te
        A, C = prob["end"], prob["start"]
    else:
        std = Std(prob["alpha"][0], prob["alpha"][1], prob["theta"][0], prob["theta"][1])
        te_std = te
        A, C = prob["start"], prob["end"]
    lam = std.solve(te_std)
    if lam_expected is not None:
        rel = fabs(lam - lam_expected) / max(lam_expected, mpf("1e-3") / std.T)
        assert rel < mpf("1e-6"), ("solved Lambda far from the generating one", lam, lam_expected)

    f0, f1 = std.pieces(lam)
    t0, t1 = std.t0, std.t1
    z_start = -f0.point(0, -t0, check=True)
    z_end = f1.point(t1, 0, check=True)
    chord = z_end - z_start
    assert fabs(std.unwrap(chord * expj(t0)) - te_std) < mpf("1e-30")
    reflect = (prob["sigma"] < 0) != reversed_
    k = (C - A) / (conj(chord) if reflect else chord)
    scale = abs(k)

    def to_caller(z):
        d = z - z_start
        return A + k * (conj(d) if reflect else d)

    def caller_dir(theta_std):
        e = expj(theta_std)
        return k * (conj(e) if reflect else e)

    # tangent checks (nontrivial: they hold only if the chord angle matches)
    tan_first = caller_dir(t1 if reversed_ else -t0) * (-1 if reversed_ else 1)
    tan_last = caller_dir(-t0 if reversed_ else t1) * (-1 if reversed_ else 1)
    assert fabs(arg(tan_first / prob["first_leg"])) < mpf("1e-28"), "start tangent"
    assert fabs(arg(tan_last / prob["last_leg"])) < mpf("1e-28"), "end tangent"
    assert abs(to_caller(z_end) - C) <= mpf("1e-30") * abs(C - A)
    if prob["corner"] is not None:
        d0, d1 = expj(-t0), expj(t1)
        corner = z_start + d0 * cross(chord, d1) / cross(d0, d1)
        assert abs(to_caller(corner) - prob["corner"]) <= mpf("1e-28") * abs(C - A), "corner"

    check_g3(std, lam)
    check_seed_route(std, lam, te_std, abs(chord))

    # arc length and samples, in the caller's order
    s_a, s_c = f0.s_of_theta(-t0), f1.s_of_theta(t1)
    length_std = s_c - s_a
    length = scale * length_std
    joint_s = scale * (s_c if reversed_ else -s_a)
    th_first = t1 if reversed_ else -t0
    sigma = prob["sigma"]
    theta_leg = atan2(prob["first_leg"].imag, prob["first_leg"].real)

    def std_theta(u):
        if u == 0:
            return th_first
        if u == 1:
            return -t0 if reversed_ else t1
        s = s_c - u * length_std if reversed_ else s_a + u * length_std
        return f0.theta_of_s(s) if s < 0 else f1.theta_of_s(s)

    def rho(th):
        return f0.rho(th) if th <= 0 else f1.rho(th)

    def point_rel_joint(th):
        return -f0.point(0, th, check=True) if th <= 0 else f1.point(th, 0, check=True)

    samples = []
    for u in FRACTIONS:
        th = std_theta(mpf(u))
        z = to_caller(point_rel_joint(th))
        samples.append({"u": u, "s": mpf(u) * length, "x": z.real, "y": z.imag,
                        "theta": theta_leg + sigma * fabs(th - th_first),
                        "kappa": sigma / (scale * rho(th))})
    first = samples[0]
    assert abs(mpc(first["x"], first["y"]) - prob["start"]) <= mpf("1e-30") * abs(C - A)
    last = samples[-1]
    assert abs(mpc(last["x"], last["y"]) - prob["end"]) <= mpf("1e-28") * abs(C - A)
    rec = {
        "lambda": lam, "arc_length": length, "joint_s": joint_s,
        "curvature_start": samples[0]["kappa"], "curvature_joint": sigma / scale,
        "curvature_end": samples[-1]["kappa"], "samples": samples,
    }
    return rec, reversed_


def check_g3(std, lam):
    """rho and drho/ds on both sides of the joint from the closed forms rho(theta(s))."""
    f0, f1 = std.pieces(lam)
    h = mpf("1e-13")
    r0 = lambda s: f0.rho(f0.theta_of_s(s))
    r1 = lambda s: f1.rho(f1.theta_of_s(s))
    assert r0(mpf(0)) == 1 and r1(mpf(0)) == 1
    # one-sided second-order differences, error O(h^2)
    d0 = (3 * r0(mpf(0)) - 4 * r0(-h) + r0(-2 * h)) / (2 * h)
    d1 = (-3 * r1(mpf(0)) + 4 * r1(h) - r1(2 * h)) / (2 * h)
    tol = mpf("1e-20") * max(1, lam) * max(1, lam) * max(1, lam)
    assert fabs(d0 - lam) < tol and fabs(d1 - lam) < tol, ("G3", lam, d0, d1)


def check_seed_route(std, lam, te_std, chord_len):
    """Seed 004 section 4: reference point at the start of piece 0 (rho = 1 there),
    Lambda0 = drho/ds there; piece 0 over [0, t0]; rho_c at its end; Lambda1 from eq. 3.5;
    theta_s where LAC(a1, Lambda1) has rho = rho_c; piece 1 over [theta_s, theta_s + t1]
    rotated by t0 - theta_s and attached at the joint."""
    a0, a1, t0, t1 = std.a0, std.a1, std.t0, std.t1
    f0 = StandardForm(a0, lam)
    rho_a = f0.rho(-t0)
    lam0 = lam * rho_a ** (1 - a0)
    g0 = StandardForm(a0, lam0)
    rho_c = g0.rho(t0)
    assert fabs(rho_c * rho_a - 1) < mpf("1e-30"), ("rho_c", rho_c, rho_a)
    lam1 = lam0 * rho_c ** (a1 - a0)  # eq. 3.5
    # G3 in the seed's scale: drho/ds of both pieces at the joint
    assert fabs(lam0 * rho_c ** (1 - a0) - lam1 * rho_c ** (1 - a1)) <= mpf("1e-30") * lam0 * rho_c ** (1 - a0) + mpf("1e-60")
    if lam1 == 0:
        theta_s = mpf(0)
    elif a1 == 1:
        theta_s = log(rho_c) / lam1
    else:
        theta_s = expm1((a1 - 1) * log(rho_c)) / ((a1 - 1) * lam1)
    g1 = StandardForm(a1, lam1)
    assert fabs(g1.rho(theta_s) / rho_c - 1) < mpf("1e-28"), "theta_s"
    c = g0.point(t0, 0) + expj(t0 - theta_s) * g1.point(theta_s + t1, theta_s)
    ang = std.unwrap(c)
    assert fabs(ang - te_std) < mpf("1e-25"), ("seed route chord angle", ang, te_std)
    assert fabs(abs(c) * rho_a / chord_len - 1) < mpf("1e-25"), "seed route chord length"


def compare_single_segment(prob, rec, fractions):
    """a0 = a1: the single segment of segment_mpmath on (start, tangent intersection, end)."""
    if prob["corner"] is not None:
        pb = prob["corner"]
    else:
        d0, d1 = prob["first_leg"], prob["last_leg"]
        if prob["sigma"] * cross(d0, d1) <= 0:
            return False  # total turning >= pi: no control triangle
        chord = prob["end"] - prob["start"]
        pb = prob["start"] + d0 * cross(chord, d1) / cross(d0, d1)
    try:
        seg = segment_mpmath.solve_segment(prob["start"], pb, prob["end"], prob["alpha"][0],
                                           fractions)
    except (segment_mpmath.IllConditioned, segment_mpmath.NotDrawable) as e:
        raise AssertionError("single segment failed where the compound solve succeeded", e)
    size = abs(prob["end"] - prob["start"])
    assert fabs(seg["arc_length"] - rec["arc_length"]) <= mpf("1e-25") * size
    for a, b in zip(seg["samples"], rec["samples"]):
        assert fabs(a["x"] - b["x"]) <= mpf("1e-25") * size, ("x", a["x"], b["x"])
        assert fabs(a["y"] - b["y"]) <= mpf("1e-25") * size, ("y", a["y"], b["y"])
        assert fabs(a["s"] - b["s"]) <= mpf("1e-25") * size
        assert fabs(a["theta"] - b["theta"]) <= mpf("1e-25")
        assert fabs(a["kappa"] - b["kappa"]) <= mpf("1e-25") * fabs(b["kappa"])
    return True


# ---------------------------------------------------------------------------------------
# Case generation
# ---------------------------------------------------------------------------------------
GRID = [-3.0, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0]


def kind_of(a0, a1):
    if a0 == a1:
        return "equal"
    if a0 < 0 < a1:
        return "valley"
    if a0 > 0 > a1:
        return "mountain"
    if (a0 >= 0 and a1 >= 0) or (a0 <= 0 and a1 <= 0):
        return "same-sign"
    return "mixed"


def std_lmax(a0, a1, t0, t1):
    return Std(a0, a1, t0, t1).lmax


def pick_lambda(rng, a0, a1, t0, t1):
    lm = std_lmax(a0, a1, t0, t1)
    if lm == inf:
        return mpf(10) ** mpf(rng.uniform(-1.3, 1.2)) / (t0 + t1)
    return lm * mpf(rng.uniform(0.08, 0.92))


def similarity(rng, pts, mirror):
    """Random scale, rotation, offset (and mirror) applied to complex points; rounded."""
    sc = 10 ** rng.uniform(-1.5, 2.0)
    rot = rng.uniform(-3.14159, 3.14159)
    off = mpc(rng.uniform(-50, 50), rng.uniform(-50, 50))
    k = mpf(sc) * expj(mpf(rot))
    out = []
    for z in pts:
        z = conj(z) if mirror else z
        w = off + k * z
        out.append([float(w.real), float(w.imag)])
    return out


def build_std_curve(a0, a1, t0, t1, lam):
    """Start, end and tangent-line data of the standard-form compound curve at lam."""
    with mp.workdps(25):
        f0, f1 = StandardForm(a0, lam), StandardForm(a1, lam)
        zs = -f0.point(0, -t0, check=False)
        ze = f1.point(t1, 0, check=False)
    return mpc(zs), mpc(ze)


def line_meet(p, d, q, e):
    """Intersection of p + x d and q + y e: returns (point, x, y)."""
    den = cross(d, e)
    x = cross(q - p, e) / den
    y = cross(q - p, d) / den
    return p + x * d, x, y


def gen_three(rng, a0, a1, kind_extra=None, Tr=(0.3, 2.8), rev=None, mirror=None, lam=None):
    """A drawable three-point case generated from a standard-form curve."""
    T = rng.uniform(*Tr)
    r = rng.uniform(0.2, 0.8)
    if rev is None:
        rev = rng.random() < 0.35
    if mirror is None:
        mirror = rng.random() < 0.35
    t0 = mpf(T) * mpf(r)
    t1 = mpf(T) - t0
    if lam is None:
        lam = pick_lambda(rng, a0, a1, t0, t1)
    zs, ze = build_std_curve(a0, a1, t0, t1, lam)
    d0, d1 = expj(-t0), expj(t1)
    corner, _, _ = line_meet(zs, d0, ze, d1)
    tri = [zs, corner, ze]
    if rev:
        tri = tri[::-1]
        ca0, ca1, cr = a1, a0, 1.0 - r
    else:
        ca0, ca1, cr = a0, a1, r
    pts = similarity(rng, tri, mirror)
    return {"points": pts, "alpha0": ca0, "alpha1": ca1, "ratio": cr,
            "kind": kind_extra or kind_of(ca0, ca1), "reversed": rev, "right_turn": mirror != rev,
            "_lam": lam}


def gen_four(rng, a0, a1, T, rev=None, mirror=None, kind_extra=None):
    """A drawable four-point case: turnings t0, t1 < pi each, total T."""
    while True:
        r = rng.uniform(0.2, 0.8)
        t0, t1 = T * r, T * (1 - r)
        if max(t0, t1) < 3.0:
            break
    if rev is None:
        rev = rng.random() < 0.35
    if mirror is None:
        mirror = rng.random() < 0.35
    t0, t1 = mpf(t0), mpf(t1)
    lam = pick_lambda(rng, a0, a1, t0, t1)
    zs, ze = build_std_curve(a0, a1, t0, t1, lam)
    d0, dj, d1 = expj(-t0), mpc(1), expj(t1)
    # natural P1, P2: tangent-line intersections with the joint tangent (the x axis)
    p1n, x1, _ = line_meet(zs, d0, mpc(0), dj)
    assert x1 > 0
    p1 = zs + d0 * x1 * mpf(rng.uniform(0.6, 1.4))
    p2, c, b = line_meet(p1, dj, ze, -d1)
    if not (c > 0 and b > 0):
        p1 = p1n
        p2, c, b = line_meet(p1, dj, ze, -d1)
        assert c > 0 and b > 0
    poly = [zs, p1, p2, ze]
    if rev:
        poly = poly[::-1]
        ca0, ca1 = a1, a0
    else:
        ca0, ca1 = a0, a1
    pts = similarity(rng, poly, mirror)
    k = kind_extra or kind_of(ca0, ca1)
    if T > 3.14159:
        k += ",turn>pi"
    return {"points": pts, "alpha0": ca0, "alpha1": ca1, "ratio": None, "kind": k,
            "reversed": rev, "right_turn": mirror != rev, "_lam": lam}


def bound_angle(a0, a1, t0, t1):
    with mp.workdps(25):
        std = Std(a0, a1, t0, t1)
        assert std.lmax < inf
        return std.chord_angle_at_bound()


def out_of_reach_three(rng, a0, a1, T, r, rev, mirror):
    t0, t1 = mpf(T) * mpf(r), mpf(T) - mpf(T) * mpf(r)
    tb = bound_angle(a0, a1, t0, t1)
    te = tb + (mpf(T) - tb) * mpf("0.4")
    L = mp.sin(te) / mp.sin(mpf(T) - te)
    tri = [mpc(0), mpc(1), 1 + L * expj(mpf(T))]
    ca0, ca1, cr = a0, a1, r
    if rev:
        tri, ca0, ca1, cr = tri[::-1], a1, a0, 1.0 - r
    return {"points": similarity(rng, tri, mirror), "alpha0": ca0, "alpha1": ca1,
            "ratio": cr, "kind": "out-of-reach" + (",reversed" if rev else "")}


def out_of_reach_four(rng, a0, a1, T, r, rev, mirror):
    t0, t1 = mpf(T) * mpf(r), mpf(T) - mpf(T) * mpf(r)
    tb = bound_angle(a0, a1, t0, t1)
    te = tb + (mpf(T) - tb) * mpf("0.4")
    e = expj(te)
    q = 1 + expj(t0)
    n = -cross(e, q) / cross(e, expj(mpf(T)))
    assert n > 0
    poly = [mpc(0), mpc(1), q, q + n * expj(mpf(T))]
    ca0, ca1 = a0, a1
    if rev:
        poly, ca0, ca1 = poly[::-1], a1, a0
    return {"points": similarity(rng, poly, mirror), "alpha0": ca0, "alpha1": ca1,
            "ratio": None, "kind": "out-of-reach" + (",reversed" if rev else "")
            + (",turn>pi" if T > 3.14159 else "")}


def generate_inputs(seed=20240607):
    rng = random.Random(seed)
    three, four, bad = [], [], []

    def rnd_alpha():
        return round(rng.uniform(-4, 4), 6)

    # valley pairs from the grid
    valley = [(a, b) for a in GRID if a < 0 for b in GRID if b > 0]
    mountain = [(a, b) for a in GRID if a > 0 for b in GRID if b < 0]
    same = [(a, b) for a in GRID for b in GRID if a != b and (a * b > 0 or (a == 0) != (b == 0))]
    rng.shuffle(valley)
    rng.shuffle(mountain)
    rng.shuffle(same)
    pairs = valley + mountain + valley[::-1] + mountain[::-1] + same[:24]
    pairs += [(rnd_alpha(), rnd_alpha()) for _ in range(24)]
    pairs += [(a, a) for a in (-1.0, 0.0, 0.5, 1.0, 2.0, 3.0)] + [(rnd_alpha(),) * 2]
    for a0, a1 in pairs:
        three.append(gen_three(rng, a0, a1))
    # a few forced reversed / mirrored and near-circle cases
    for a0, a1 in [(-1.0, 1.5), (2.0, -0.5), (1.0, -3.0), (-3.0, 3.0)]:
        three.append(gen_three(rng, a0, a1, rev=True, mirror=True))
    for a0, a1, lam in [(-1.0, 2.0, "1e-3"), (0.5, -1.0, "5e-4"), (2.0, -3.0, "1e-4")]:
        c = gen_three(rng, a0, a1, rev=False, mirror=False, lam=mpf(lam))
        c["kind"] = "near-circle"
        three.append(c)
    # exact isosceles triangles: circular arcs (Lambda = 0) for any slopes
    for (a0, a1, r), (h, sc) in zip([(-1.0, 2.0, 0.3), (1.5, -0.5, 0.7)], [(0.4, 1.0), (1.5, 3.0)]):
        three.append({"points": [[-sc, 0.0], [0.0, h * sc], [sc, 0.0]], "alpha0": a0,
                      "alpha1": a1, "ratio": r, "kind": "circle", "reversed": False,
                      "right_turn": True, "_lam": mpf(0)})

    # four points
    four_pairs = valley[:8] + mountain[:8] + same[24:32]
    four_pairs += [(rnd_alpha(), rnd_alpha()) for _ in range(24)]
    four_pairs += [(-1.0, -1.0), (0.5, 0.5), (2.0, 2.0), (1.0, 1.0)]
    for i, (a0, a1) in enumerate(four_pairs):
        T = rng.uniform(0.4, 2.9) if i % 2 == 0 else rng.uniform(3.3, 5.6)
        four.append(gen_four(rng, a0, a1, T))
    for a0, a1 in [(-1.0, 2.0), (2.0, -1.0), (0.0, 1.5), (-0.5, 0.5), (3.0, -3.0), (-2.0, -2.0)]:
        four.append(gen_four(rng, a0, a1, rng.uniform(3.5, 5.5), rev=True, mirror=True))
    for a0, a1 in [(-1.0, 2.0), (0.5, 0.5), (1.5, -0.5)]:
        four.append(gen_four(rng, a0, a1, rng.uniform(0.5, 2.5), rev=True, mirror=False))

    # not drawable
    bad += [
        {"points": [[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]], "alpha0": -1.0, "alpha1": 2.0,
         "ratio": 0.5, "kind": "collinear"},
        {"points": [[0.0, 0.0], [2.0, 1.0], [-2.0, -1.0]], "alpha0": 0.5, "alpha1": -1.0,
         "ratio": 0.4, "kind": "u-turn"},
        {"points": [[1.0, 2.0], [1.0, 2.0], [4.0, 0.0]], "alpha0": 0.0, "alpha1": 1.0,
         "ratio": 0.5, "kind": "coincident"},
        {"points": [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [2.0, 3.0]], "alpha0": -1.0,
         "alpha1": 1.5, "ratio": None, "kind": "coincident-skip"},  # placeholder, replaced
        {"points": [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, 1.0]], "alpha0": -1.0,
         "alpha1": 1.5, "ratio": None, "kind": "inflection"},
        {"points": [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 1.0]], "alpha0": -1.0,
         "alpha1": 1.5, "ratio": None, "kind": "no-turn-on-first-piece"},
        {"points": [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, -1.0]], "alpha0": -1.0,
         "alpha1": 1.5, "ratio": None, "kind": "leg-reversal"},
        {"points": [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [1.0, 1.0]], "alpha0": 0.0,
         "alpha1": 2.0, "ratio": None, "kind": "coincident"},
    ]
    bad = [b for b in bad if b["kind"] != "coincident-skip"]
    # beyond the largest chord angle: theta_e between the chord angle at Lambda = Lmax
    # (computed here) and Theta
    for a0, a1, T, r, rev, mirror in [(-3.0, -3.0, 1.2, 0.5, False, False),
                                      (3.0, -2.0, 2.0, 0.6, False, True),
                                      (2.0, 3.0, 1.5, 0.3, True, False)]:
        bad.append(out_of_reach_three(rng, a0, a1, T, r, rev, mirror))
    for a0, a1, T, r, rev, mirror in [(0.5, -1.0, 2.0, 0.5, False, False),
                                      (2.0, 1.5, 4.0, 0.45, True, True)]:
        bad.append(out_of_reach_four(rng, a0, a1, T, r, rev, mirror))
    return three, four, bad


# ---------------------------------------------------------------------------------------
def to_float(v):
    if isinstance(v, dict):
        return {k: to_float(x) for k, x in v.items()}
    if isinstance(v, list):
        return [to_float(x) for x in v]
    if isinstance(v, (bool, str)) or v is None:
        return v
    return float(v)


def process(case):
    mp.dps = DPS
    inp = {k: v for k, v in case.items() if not k.startswith("_")}
    pts = case["points"]
    out = {"points": pts, "alpha0": case["alpha0"], "alpha1": case["alpha1"],
           "ratio": case["ratio"], "kind": case["kind"]}
    info = {"equal_checked": False}
    try:
        if len(pts) == 3:
            prob = parse_three(pts, case["alpha0"], case["alpha1"], case["ratio"])
        else:
            prob = parse_four(pts, case["alpha0"], case["alpha1"])
        rec, rev = solve_caller(prob, case.get("_lam"))
    except NotDrawable as e:
        out.update({"drawable": False, "reason": str(e)})
        return out, info
    except IllConditioned as e:
        info["ill"] = str(e)
        return None, info
    if "reversed" in inp:
        assert rev == inp["reversed"], ("reversal", rev, inp["reversed"])
        assert (prob["sigma"] < 0) == inp["right_turn"], "mirror"
    if case["alpha0"] == case["alpha1"]:
        info["equal_checked"] = compare_single_segment(prob, rec, FRACTIONS)
    out["drawable"] = True
    out.update(to_float(rec))
    out["reversed"] = rev
    out["right_turn"] = prob["sigma"] < 0
    return out, info


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", "--out", default=DEFAULT_OUT)
    ap.add_argument("-j", "--jobs", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--limit", type=int, default=None, help="debug: first N cases of each group")
    args = ap.parse_args()
    t_start = time.time()
    three, four, bad = generate_inputs()
    if args.limit:
        three, four, bad = three[:args.limit], four[:args.limit], bad[:args.limit]
    cases = three + four + bad
    if args.jobs > 1:
        with Pool(args.jobs) as pool:
            results = pool.map(process, cases, chunksize=1)
    else:
        results = [process(c) for c in cases]
    out, n3, n4, nbad, neq, nill = [], 0, 0, 0, 0, 0
    for case, (rec, info) in zip(cases, results):
        if rec is None:
            nill += 1
            print("skipped (ill-conditioned):", case["points"], case["alpha0"], case["alpha1"],
                  info.get("ill"), file=sys.stderr)
            continue
        if case in bad:
            assert not rec["drawable"], ("expected not drawable", case)
        if not rec["drawable"]:
            if case not in bad:
                raise AssertionError(("generated case not drawable", case, rec))
            nbad += 1
        elif len(case["points"]) == 3:
            n3 += 1
        else:
            n4 += 1
        neq += info["equal_checked"]
        out.append(rec)
    with open(args.out, "w") as fh:
        fh.write('{"generator": "tools/reference/compound_fixtures.py", "dps": %d, "cases": [\n'
                 % DPS)
        fh.write(",\n".join(json.dumps(c, separators=(",", ":")) for c in out))
        fh.write("\n]}\n")
    print(f"wrote {args.out}: {n3} three-point, {n4} four-point drawable, {nbad} not drawable, "
          f"{nill} skipped; {neq} equal-slope cases matched segment_mpmath; "
          f"{time.time() - t_start:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
