"""Write the 40-digit reference fixtures for the Rust crate (crates/lac/tests/fixtures/).

    .venv/bin/python tools/reference/generate_fixtures.py      (from the repo root)

standard_form.json -- docs/math.md §2, standard form II: reference point rho = 1 at
theta = s = 0 with tangent +x; for (alpha, lambda >= 0, theta):
    rho = rho(theta), s = s(theta) (negative for theta < 0),
    x + i y = P(theta) = int_0^theta rho(psi) e^{i psi} dpsi.
Limits: lambda = 0 is the unit circle (rho = 1, s = theta); alpha = 0 and alpha = 1 use
their own closed forms.  P is integrated in the tangent-angle form and again in the
arc-length form (graded pieces, see lac_mpmath.py); they must agree to 1e-25, and so must
the incomplete-gamma closed form (alpha != 1, lambda |alpha - 1| >= 1e-3) and the
alpha = 1 closed form.

segments.json -- docs/math.md §3, a segment from control points (Pa, Pb, Pc) and alpha
(see segment_mpmath.py): lambda of the solved standard-form piece (after the swap of the
ends), theta_d in (0, pi) (unsigned), arc_length, signed end curvatures (+ = left turn),
and samples at arc-length fractions u from the caller's first point: s, x, y, theta (the
tangent direction, atan2(Pb - Pa) at u = 0 and continuous), kappa.  Not-drawable cases
have "drawable": false and a "reason".  "kind" says how the case was made: base
(Pa = (-1, 0), Pc = (1, 0), Pb random in [-1, 1] x [0.02, 1], drawn again when outside
the drawable region), similar (random scale, rotation, offset), left (mirrored), reversed
(points in reverse order), near-isosceles, boundary-inside (lambda = (1 - 1e-7)
lambda_max), boundary-outside (theta_e 1e-6 theta_d above the largest chord angle),
outside (random Pb outside the region), degenerate (collinear or coincident).  Cases
whose lambda is within 1e-12 of lambda_max, or lambda theta_d > 1000, would be unfair
to double precision and are left out (the script reports how many).

All mathematics runs in mpmath at 40 digits; inputs are doubles (written exactly as
used) and outputs are rounded to the nearest double.  Random choices use fixed seeds;
the output does not depend on the number of worker processes.
"""

import json
import math
import os
import random
import sys
import time
from multiprocessing import Pool

from mpmath import mp, mpf, mpc, arg, atan2, expj, fabs

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lac_mpmath import StandardForm  # noqa: E402
from segment_mpmath import (  # noqa: E402
    IllConditioned, NotDrawable, chord_angle, chord_angle_at_bound, cross, solve_segment)

mp.dps = 40
GENERATOR = "tools/reference/generate_fixtures.py"
OUT = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "lac", "tests", "fixtures")
FRACTIONS = [0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0]


def f64(x):
    return float(x)  # mpf -> nearest double


# ---- standard_form.json ----------------------------------------------------------------

SF_ALPHAS = [-50, -3, -1, -0.5, -1e-8, 0, 1e-8, 0.25, 0.5, 1 - 1e-8, 1, 1 + 1e-8,
             1.5, 2, 3, 10, 50]
SF_LAMBDAS = [0, 1e-9, 1e-3, 0.1, 1, 4]


def theta_values(alpha, lam):
    """About six theta values: both signs, small and large, and near the bound."""
    bound = StandardForm(alpha, lam).theta_singular()
    if bound is None:
        return [-3.0, -1.0, -1e-3, 1e-3, 1.0, 3.0]
    d = 1.0 if bound > 0 else -1.0  # the bounded side
    small = 1e-3 if fabs(bound) > 2e-3 else f64(fabs(bound) / 10)
    out = [-3.0 * d, -1e-3 * d, small * d]
    if fabs(bound) <= 25:
        out += [f64(bound * mpf(f)) for f in ("0.5", "0.9", "0.999999")]
    else:
        out += [0.3 * d, 1.0 * d, 3.0 * d]
    return sorted(out)


def standard_form_cases():
    rng = random.Random(1)
    alphas = SF_ALPHAS + sorted(rng.uniform(-5, 5) for _ in range(5))
    return [(a, lam, t) for a in alphas for lam in SF_LAMBDAS for t in theta_values(a, lam)]


def standard_form_row(case):
    alpha, lam, theta = case
    sf = StandardForm(alpha, lam)
    theta = mpf(theta)
    assert sf.in_range(theta)
    p = sf.point(theta, check=True)  # theta form, checked against the arc-length form
    tol = mpf("1e-25") * max(1, abs(p))
    if alpha == 1 or lam == 0:
        exact = sf.point_closed_alpha1(theta) if alpha == 1 else mpc(0, 1) * (1 - expj(theta))
        assert abs(p - exact) <= tol, case
    elif lam * abs(alpha - 1) >= 1e-3:
        assert abs(p - sf.point_gamma(theta)) <= tol, case
    return {"alpha": float(alpha), "lambda": float(lam), "theta": f64(theta), "s": f64(sf.s_of_theta(theta)),
            "rho": f64(sf.rho(theta)), "x": f64(p.real), "y": f64(p.imag)}


# ---- segments.json: configurations -----------------------------------------------------

SEG_ALPHAS = [-3, -1, -0.5, -1e-8, 0, 1e-8, 0.3, 0.5, 1 - 1e-8, 1, 1 + 1e-8, 1.5, 2, 3, 10]
PA, PC = mpc(-1, 0), mpc(1, 0)


def as_doubles(points):
    return [[f64(p.real), f64(p.imag)] for p in points]


def quick_drawable(alpha, pb):
    """Cheap 15-digit prefilter for Pa = (-1, 0), Pc = (1, 0): theta_e below the largest
    chord angle by a margin (only alpha < 0 and alpha > 1 have a finite largest one; as
    in solve_lambda it is only computed away from alpha = 0 and 1)."""
    if -0.01 < alpha < 1.01:
        return True
    with mp.workdps(15):
        v1, v2 = pb - PA, PC - pb
        theta_d = fabs(atan2(cross(v1, v2), (v1.conjugate() * v2).real))
        a, c = (PC, PA) if abs(v1) > abs(v2) else (PA, PC)
        theta_e = fabs(arg((c - a) / (pb - a)))
        return theta_e < chord_angle_at_bound(mpf(alpha), theta_d) - 1e-6


def random_pb(rng):
    while True:
        x, y = rng.uniform(-1, 1), rng.uniform(0, 1)
        if y >= 0.02:
            return mpc(x, y)


def similarity(rng):
    """Random scale (chord 1e-6 .. 1e6), rotation and offset (up to 1e7, and at most
    1e6 chords, so the rounded inputs keep about ten digits of the shape)."""
    chord = 10 ** rng.uniform(-6, 6)
    rot = expj(rng.uniform(-math.pi, math.pi)) * chord / 2
    offset = min(10 ** rng.uniform(-3, 7), 1e6 * chord) * expj(rng.uniform(-math.pi, math.pi))
    return lambda z: offset + rot * z


VARIANTS = ["base", "base", "base", "base", "similar", "similar", "similar", "left",
            "left+similar", "reversed", "reversed+similar", "left+reversed+similar"]


def variant(kind, pb, rng):
    pts = [PA, pb, PC]
    if "left" in kind:  # Pb below the chord: a left turn
        pts = [p.conjugate() for p in pts]
    if "reversed" in kind:
        pts = pts[::-1]
    if "similar" in kind:
        t = similarity(rng)
        pts = [t(p) for p in pts]
    return as_doubles(pts)


def segment_configs():
    rng = random.Random(1)
    specs, rejected = [], []

    def draw(alpha, kinds):
        for kind in kinds:
            for _ in range(1000):
                pb = random_pb(rng)
                if quick_drawable(alpha, pb):
                    break
                rejected.append((alpha, pb))
            specs.append((variant(kind, pb, rng), alpha, kind))

    for alpha in SEG_ALPHAS:
        draw(alpha, VARIANTS)
    for _ in range(16):
        draw(rng.uniform(-6, 6), [rng.choice(VARIANTS) for _ in range(5)])
    # near-isosceles (lambda tiny) and exactly isosceles (lambda = 0)
    for i, alpha in enumerate([-1, 0, 0.5, 1, 2, 10, -3, 1.5]):
        dx = [0, 1e-3, 1e-6, 1e-9, 1e-12, -1e-6, -1e-9, 0][i]
        specs.append((as_doubles([PA, mpc(dx, rng.uniform(0.05, 1)), PC]), alpha, "near-isosceles"))
    # near the drawable boundary: inside at lambda = (1 - 1e-7) lambda_max, outside with
    # theta_e 1e-6 theta_d above the largest chord angle
    for alpha in [-3, -1, -0.5, -6, 1.5, 2, 3, 10]:
        theta_d = mpf(rng.uniform(0.3, 2.0))
        lam = (1 - mpf("1e-7")) / (theta_d * abs(1 - mpf(alpha)))
        inside = chord_angle(mpf(alpha), lam, theta_d)
        outside = chord_angle_at_bound(mpf(alpha), theta_d) + mpf("1e-6") * theta_d
        for theta_e, kind in [(inside, "boundary-inside"), (outside, "boundary-outside")]:
            pb = PA + 2 * mp.sin(theta_d - theta_e) / mp.sin(theta_d) * expj(theta_e)
            specs.append((as_doubles([PA, pb, PC]), alpha, kind))
    # random configurations outside the drawable region, spread over the rejected draws
    for alpha, pb in rejected[::max(1, len(rejected) // 8)][:8]:
        specs.append((as_doubles([PA, pb, PC]), alpha, "outside"))
    degenerate = [[PA, mpc(0.25, 0), PC], [PA, mpc(3, 0), PC], [PA, PA, PC], [PA, PC, PC],
                  [PA, mpc(-2, 0), PC]]
    for pts, alpha in zip(degenerate, [0.5, -1, 2, 1, 0]):
        specs.append((as_doubles(pts), alpha, "degenerate"))
    return specs


def segment_row(spec):
    points, alpha, kind = spec
    head = {"points": points, "alpha": float(alpha), "kind": kind}
    try:
        r = solve_segment(*[mpc(x, y) for x, y in points], mpf(alpha), FRACTIONS)
    except NotDrawable as e:
        return dict(head, drawable=False, reason=str(e))
    except IllConditioned as e:
        return dict(head, skip=str(e))
    out = dict(head, drawable=True)
    for key in ["lambda", "theta_d", "arc_length", "curvature_start", "curvature_end"]:
        out[key] = f64(r[key])
    out["samples"] = [{"u": s["u"], **{k: f64(s[k]) for k in ["s", "x", "y", "theta", "kappa"]}}
                      for s in r["samples"]]
    return out


# ---- output ----------------------------------------------------------------------------

def write(name, cases):
    path = os.path.normpath(os.path.join(OUT, name))
    lines = [json.dumps(c, separators=(",", ":")) for c in cases]
    with open(path, "w") as f:
        f.write('{"generator": "%s", "dps": %d, "cases": [\n' % (GENERATOR, mp.dps))
        f.write(",\n".join(lines))
        f.write("\n]}\n")
    print(f"{path}: {len(cases)} cases, {os.path.getsize(path)} bytes")


def main():
    start = time.time()
    with Pool(os.cpu_count()) as pool:
        sf = pool.map(standard_form_row, standard_form_cases(), chunksize=4)
        write("standard_form.json", sf)
        seg = pool.map(segment_row, segment_configs(), chunksize=2)
    skipped = [c for c in seg if "skip" in c]
    seg = [c for c in seg if "skip" not in c]
    write("segments.json", seg)
    drawable = sum(c["drawable"] for c in seg)
    print(f"segments: {drawable} drawable, {len(seg) - drawable} not drawable, "
          f"{len(skipped)} skipped as ill-conditioned")
    for c in skipped:
        print("  skipped:", c["alpha"], c["points"], c["kind"], c["skip"])
    print(f"total {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
