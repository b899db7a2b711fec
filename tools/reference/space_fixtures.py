#!/usr/bin/env python3
"""Write the log-aesthetic space-curve fixtures (docs/math.md §6, seed 003; maths: space_mpmath.py).

    .venv/bin/python tools/reference/space_fixtures.py [--only family|classification] [-j JOBS]

crates/lac/tests/fixtures/space_family.json -- the standard-form curve
(origin, tangent +x, normal +y, rho = 1 and mu = nu at s = 0; right-handed frame b = t x n,
tau = 1/mu > 0 so the curve leaves its osculating plane toward +b) for a grid of
(alpha, beta) in {-1, -0.5, 0, 0.5, 1, 2} x {-1, 0, 1, 2}, types 1 and 2, three
(lambda, omega, nu) each from {0, 0.3, 1} x {0, 0.5, 2} x {0.5, 1, 3} (Latin-square
choice), plus a few cases next to alpha, beta = 0 and 1.  Per case: s_range [lower, upper]
(null = infinite) and at several s inside it (both signs where valid: 0.3, 0.7 and 0.95 of a
bound closer than 8, else +-0.5, 1.5, 4; halved until |theta| + |phi| <= 50)
the point x, the unit tangent t, normal n, binormal b, kappa and tau.  Each curve is
integrated twice (Taylor method, 50 digits with c_R = 1/8, c_W = 2, and 60 digits with
c_R = 1/5, c_W = 3); the two must agree to 1e-25 (the script reports the largest difference)
and the frame must be orthonormal to 1e-25.  Values are rounded to the nearest double.

crates/lac/tests/fixtures/space_classification.json -- seed 003 Figs. 5 (type 1, rows
a1-a45) and 6 (type 2, rows b1-b37) transcribed from the seed's text extraction, and for
each row the conditions, the seed's cells, the cells the mathematics gives ("expected", in
the seed's notation and star convention), the actual behaviour of the tangent and the
binormal ("settles" = has a limit direction), the disagreements, and one or more concrete
parameter sets checked numerically:
  * closed forms in mpmath at depths 10^-1, -2, -4, -8, -16, -32 (relative) from a finite end,
    or |s| = 10^1 ... 10^32 toward an infinite end: ln rho, ln mu, theta, phi, kappa/tau and
    the verdicts read from them (limit 0 / inf / finite; integral converges or diverges by the
    ratio of successive increments; the cut function's integral at its own end for the
    Finite(...) qualifier);
  * the Frenet-Serret system integrated in double precision (same Taylor code) from s = 0
    toward the end until 3000 rad of frame rotation or depth 10^-12 / |s| = 10^10: the spread
    (largest angle to the last value) of t and of b over the last 4 pi of rotation within the
    last three decades: < 0.2 rad "settles", > 0.6 rad "turns".
Every numerical verdict must match the classification in space_mpmath.classify(); the script
stops otherwise.  Seed notation: bound "A" = -1/(lam alpha), "B" = the mu bound
(type 1: -nu^beta/(omega beta); type 2: nu^beta/(omega beta)), "-inf"/"inf"; theta and phi
cells "-inf" / "inf" / "Finite" / "Finite(-inf)" / "Finite(inf)" / "Finite(F)"; rho and mu
cells "0" / "inf" (with "*" when the length or the integral theta (for rho) / phi (for mu) is
infinite -- the convention the seed's table follows in all but one cell) or "-" (finite).
"""

import argparse
import json
import math
import os
import sys
import time
from multiprocessing import Pool

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpmath import mp, fp, mpf  # noqa: E402

from space_mpmath import SpaceCurve, classify  # noqa: E402

OUT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                    "crates", "lac", "tests", "fixtures"))
AGREE = mpf("1e-25")

# ======================================================================================
# space_family.json
# ======================================================================================
ALPHAS = [-1, -0.5, 0, 0.5, 1, 2]
BETAS = [-1, 0, 1, 2]
LAMS = [0, 0.3, 1]
OMEGAS = [0, 0.5, 2]
NUS = [0.5, 1, 3]
EXTRA = [  # next to the removable singularities, and a plain helix
    (1e-9, 0, 1, 0.5, 1, 1), (-1e-9, 1, 0.3, 2, 3, 2), (1 + 1e-9, -1e-9, 1, 0.5, 0.5, 1),
    (1 - 1e-9, 1 + 1e-9, 0.3, 0.5, 1, 2), (0.5, 1e-9, 1, 2, 1, 2), (2, 1 - 1e-9, 1, 2, 3, 1),
    (-1, 2, 0, 0, 1, 1), (0, 0, 1e-9, 1e-9, 1, 1),
]
ROTATION_CAP = 50  # |theta(s)| + |phi(s)| at the sample points


def family_cases():
    cases = []
    c = 0
    for a in ALPHAS:
        for b in BETAS:
            for kind in (1, 2):
                for j in range(3):
                    cases.append((a, b, LAMS[j], OMEGAS[(j + c) % 3], NUS[(j + c // 3) % 3], kind))
                c += 1
    return cases + EXTRA


def sample_points(curve):
    """Several s inside the valid range, both signs where valid, rotation capped."""
    lo, hi = curve.s_range()
    pts = []
    for end in (hi, lo):
        d = 1 if end > 0 else -1
        if abs(end) > 8:               # infinite, or far away (alpha, beta near 0)
            cands = [d * mpf(v) for v in ("0.5", "1.5", "4")]
        else:
            cands = [end * mpf(v) for v in ("0.3", "0.7", "0.95")]
        for s in cands:
            while abs(curve.theta(s)) + abs(curve.phi(s)) > ROTATION_CAP:
                s = s / 2
            s = mpf(float(s))          # a double, used exactly
            if s not in pts and curve.in_range(s):
                pts.append(s)
    return pts


def _flt(x):
    return float(x)


def family_case(params):
    a, b, lam, om, nu, kind = params
    out = {"alpha": a, "beta": b, "lambda": lam, "omega": om, "nu": nu, "type": kind}
    with mp.workdps(50):
        cur = SpaceCurve(a, b, lam, om, nu, kind)
        lo, hi = cur.s_range()
        out["s_range"] = [None if lo == -mp.inf else _flt(lo), None if hi == mp.inf else _flt(hi)]
        s_list = sample_points(cur)
        fa = cur.frames(s_list)
    with mp.workdps(60):
        cur2 = SpaceCurve(a, b, lam, om, nu, kind, c_r=mpf(1) / 5, c_w=3)
        fb = cur2.frames(s_list)
    with mp.workdps(60):
        worst, ortho, pts = _compare_frames(fa, fb)
    out["points"] = pts
    return out, worst, ortho


def _compare_frames(fa, fb):
    """Largest difference between two integrations, orthonormality error, rounded points."""
    worst, ortho = mpf(0), mpf(0)
    pts = []
    for p, q in zip(fa, fb):
        for u, v in ((p.x, q.x), (p.t, q.t), (p.n, q.n), (p.b, q.b)):
            for i in range(3):
                worst = max(worst, abs(u[i] - v[i]) / max(1, abs(v[i])))
        vs = (p.t, p.n, p.b)
        for i in range(3):
            for j in range(3):
                dot = sum(vs[i][k] * vs[j][k] for k in range(3))
                ortho = max(ortho, abs(dot - (1 if i == j else 0)))
        pts.append({"s": _flt(p.s), "x": [_flt(v) for v in p.x], "t": [_flt(v) for v in p.t],
                    "n": [_flt(v) for v in p.n], "b": [_flt(v) for v in p.b],
                    "kappa": _flt(p.kappa), "tau": _flt(p.tau)})
    return worst, ortho, pts


def write_family(jobs):
    cases = family_cases()
    t0 = time.time()
    if jobs > 1:
        with Pool(jobs) as pool:
            results = pool.map(family_case, cases)
    else:
        results = [family_case(c) for c in cases]
    worst = max(r[1] for r in results)
    ortho = max(r[2] for r in results)
    if worst > AGREE or ortho > AGREE:
        sys.exit("family: integrations disagree (%s) or frame not orthonormal (%s)"
                 % (mp.nstr(worst, 3), mp.nstr(ortho, 3)))
    doc = {
        "generator": "tools/reference/space_fixtures.py",
        "conventions": (
            "standard form: x(0) = 0, t(0) = +x, n(0) = +y, b = t x n = +z, rho(0) = 1, "
            "mu(0) = nu; kappa = 1/rho, tau = 1/mu > 0 (right-handed: the curve leaves the "
            "osculating plane toward +b); rho = (lambda alpha s + 1)^(1/alpha) (alpha = 0: "
            "exp(lambda s)); mu = (sg omega beta s + nu^beta)^(1/beta) (beta = 0: "
            "nu exp(sg omega s)), sg = +1 type 1, -1 type 2; s_range null = unbounded"),
        "max_difference_between_integrations": float(worst),
        "max_orthonormality_error": float(ortho),
        "cases": [r[0] for r in results],
    }
    path = os.path.join(OUT, "space_family.json")
    with open(path, "w") as f:
        f.write('{"generator": %s, "dps": 50, "conventions": %s,\n'
                % (json.dumps(doc["generator"]), json.dumps(doc["conventions"])))
        f.write('"max_difference_between_integrations": %r, "max_orthonormality_error": %r,\n'
                % (doc["max_difference_between_integrations"], doc["max_orthonormality_error"]))
        f.write('"cases": [\n')
        f.write(",\n".join(json.dumps(c, separators=(",", ":")) for c in doc["cases"]))
        f.write("\n]}\n")
    print("space_family.json: %d cases, %d points, max difference %s, orthonormality %s, %.0f s"
          % (len(cases), sum(len(r[0]["points"]) for r in results), mp.nstr(worst, 3),
             mp.nstr(ortho, 3), time.time() - t0))


# ======================================================================================
# space_classification.json
# ======================================================================================
# The seed's tables as its text extraction gives them.  Per row: name, alpha class, beta
# class, bound comparison (None, "<", "=", ">": -1/(lam alpha) versus the mu bound), then the
# cells at the lower and at the upper bound: s, theta, phi, rho, mu.  None = the extraction
# has no cell there (noted in GARBLED).  Classes: "<0", "=0", "(0,1)", "=1", ">1".
TYPE1 = """
a1  <0    <0    >  | -inf -inf -inf 0* 0*                 | B Finite(F) Finite - inf
a2  <0    <0    =  | -inf -inf -inf 0* 0*                 | A Finite Finite inf inf
a3  <0    <0    <  | -inf -inf -inf 0* 0*                 | A Finite Finite(F) inf -
a4  <0    =0    .  | -inf -inf -inf 0* 0*                 | A Finite Finite(F) inf -
a5  <0    (0,1) .  | B Finite(-inf) -inf - 0*             | A Finite Finite inf -
a6  <0    =1    .  | B Finite(-inf) -inf - 0*             | A Finite Finite(inf) inf -
a7  <0    >1    .  | B Finite(-inf) Finite - 0            | A Finite Finite(inf) inf -
a8  =0    <0    .  | -inf -inf -inf 0* 0*                 | B Finite(F) Finite - inf
a9  =0    =0    .  | -inf -inf -inf 0* 0*                 | inf Finite Finite inf* inf*
a10 =0    (0,1) .  | B Finite(-inf) -inf - 0*             | inf Finite Finite inf* inf*
a11 =0    =1    .  | B Finite(-inf) -inf - 0*             | inf Finite inf inf* inf*
a12 =0    >1    .  | B Finite(-inf) Finite - 0            | inf Finite inf inf* inf*
a13 (0,1) <0    .  | A -inf Finite(-inf) 0* -             | B Finite(F) Finite - inf
a14 (0,1) =0    .  | A -inf Finite(-inf) 0* -             | inf Finite Finite inf* inf*
a15 (0,1) (0,1) >  | A -inf Finite(-inf) 0* -             | inf Finite Finite inf* inf*
a16 (0,1) (0,1) =  | A -inf -inf 0* 0*                    | inf Finite Finite inf* inf*
a17 (0,1) (0,1) <  | B Finite(-inf) -inf - 0*             | inf Finite Finite inf* inf*
a18 (0,1) =1    >  | A -inf Finite(-inf) 0* -             | inf Finite inf inf* inf*
a19 (0,1) =1    =  | A -inf -inf 0* 0*                    | inf Finite inf inf* inf*
a20 (0,1) =1    <  | B Finite(-inf) -inf - 0*             | inf Finite inf inf* inf*
a21 (0,1) >1    >  | A -inf Finite(F) 0* -                | inf Finite inf inf* inf*
a22 (0,1) >1    =  | A -inf Finite 0* 0                   | inf Finite inf inf* inf*
a23 (0,1) >1    <  | B Finite(-inf) Finite - 0            | inf Finite inf inf* inf*
a24 =1    <0    .  | A -inf Finite(-inf) 0* -             | B Finite(F) Finite - inf
a25 =1    =0    .  | A -inf Finite(-inf) 0* -             | inf inf Finite inf* inf*
a26 =1    (0,1) >  | A -inf Finite(-inf) 0* -             | inf inf ? inf* inf*
a27 =1    (0,1) =  | A -inf -inf 0* 0*                    | inf inf Finite inf* inf*
a28 =1    (0,1) <  | B Finite(-inf) -inf - 0*             | inf inf Finite inf* inf*
a29 =1    =1    >  | A -inf Finite(-inf) 0* -             | inf inf ? inf* inf*
a30 =1    =1    =  | A -inf -inf 0* 0*                    | inf inf ? inf* inf*
a31 =1    =1    <  | B Finite(-inf) -inf - 0*             | inf inf ? inf* inf*
a32 =1    >1    >  | A -inf Finite(F) 0* -                | inf inf ? inf* inf*
a33 =1    >1    =  | A -inf Finite 0* 0                   | inf inf ? inf* inf*
a34 =1    >1    <  | B Finite(-inf) Finite - 0            | inf inf ? inf* inf*
a35 >1    <0    .  | A Finite Finite(-inf) 0 -            | B Finite(F) Finite - inf
a36 >1    =0    .  | A Finite Finite(-inf) 0 -            | inf inf Finite inf* inf*
a37 >1    (0,1) >  | A Finite Finite(-inf) 0 -            | inf inf Finite inf* inf*
a38 >1    (0,1) =  | A Finite -inf 0 0*                   | inf inf Finite inf* inf*
a39 >1    (0,1) <  | B Finite(F) -inf - 0*                | inf inf Finite inf* inf*
a40 >1    =1    >  | A Finite Finite(-inf) 0 -            | inf inf ? inf* inf*
a41 >1    =1    =  | A Finite -inf 0 0*                   | inf inf ? inf* inf*
a42 >1    =1    <  | B Finite(F) -inf - 0*                | inf inf ? inf* inf*
a43 >1    >1    >  | A Finite Finite(F) 0 -               | inf inf ? inf* inf*
a44 >1    >1    =  | A Finite Finite 0 0                  | inf inf ? inf* inf*
a45 >1    >1    <  | B Finite(F) Finite - 0               | inf inf ? inf* inf*
"""

TYPE2 = """
b1  <0    <0    .  | B Finite(-inf) Finite - inf          | A Finite Finite(inf) inf -
b2  <0    =0    .  | -inf -inf Finite 0* inf*             | A Finite Finite(inf) inf -
b3  <0    (0,1) <  | -inf -inf Finite 0* inf*             | A Finite Finite(inf) inf -
b4  <0    (0,1) =  | -inf -inf Finite 0* inf*             | A Finite inf inf 0*
b5  <0    (0,1) >  | -inf -inf Finite 0* inf*             | B Finite(F) inf - 0*
b6  <0    =1    <  | -inf -inf -inf 0* inf*               | A Finite Finite(inf) inf -
b7  <0    =1    =  | -inf -inf -inf 0* inf*               | A Finite inf inf 0*
b8  <0    =1    >  | -inf -inf -inf 0* inf*               | B Finite(F) inf - 0*
b9  <0    >1    <  | -inf -inf -inf 0* inf*               | A Finite Finite(F) inf -
b10 <0    >1    =  | -inf -inf -inf 0* inf*               | A Finite Finite inf 0
b11 <0    >1    >  | -inf -inf -inf 0* inf*               | B Finite(F) Finite - 0
b12 =0    <0    .  | B Finite(-inf) Finite - inf          | inf Finite inf - 0*
b13 =0    =0    .  | -inf -inf Finite 0* inf*             | inf Finite inf inf* 0*
b14 =0    (0,1) .  | -inf -inf Finite 0* inf*             | B Finite(F) inf - 0*
b15 =0    =1    .  | -inf -inf -inf 0* inf*               | B Finite(F) inf - 0*
b16 =0    >1    .  | -inf -inf -inf 0* inf*               | B Finite(F) Finite - 0
b17 (0,1) <0    <  | B Finite(-inf) Finite - inf          | inf inf ? inf* 0*
b18 (0,1) <0    =  | A -inf Finite 0* inf*                | inf Finite inf inf* 0*
b19 (0,1) <0    >  | A -inf Finite(F) 0* -                | inf Finite inf inf* 0*
b20 (0,1) =0    .  | A -inf Finite(F) 0* -                | inf Finite inf inf* 0*
b21 (0,1) (0,1) .  | A -inf Finite(F) 0* -                | B Finite(F) inf - 0*
b22 (0,1) =1    .  | A -inf Finite(-inf) 0* -             | B Finite(F) inf - 0*
b23 (0,1) >1    .  | A -inf Finite(-inf) 0* -             | B Finite(F) Finite - 0
b24 =1    <0    <  | B Finite(-inf) Finite - inf          | inf inf ? inf* 0*
b25 =1    <0    =  | A -inf Finite 0* inf                 | inf inf inf inf* 0*
b26 =1    <0    >  | A -inf Finite(F) 0* -                | inf inf inf inf* 0*
b27 =1    =0    .  | A -inf Finite(F) 0* -                | inf inf inf inf* 0*
b28 =1    (0,1) .  | A -inf Finite(F) 0* -                | B Finite(inf) inf - 0*
b29 =1    =1    .  | A -inf Finite(-inf) 0* -             | B Finite(inf) inf - 0*
b30 =1    >1    .  | A -inf Finite(-inf) 0* -             | B Finite(inf) Finite - 0
b31 >1    <0    <  | B Finite(F) Finite - inf             | inf inf ? inf* 0*
b32 >1    <0    =  | A Finite Finite 0 inf                | inf inf inf inf* 0*
b33 >1    <0    >  | A Finite Finite(F) 0 -               | inf inf inf inf* 0*
b34 >1    =0    .  | A Finite Finite(F) 0 -               | inf inf inf inf* 0*
b35 >1    (0,1) .  | A Finite Finite(F) 0 -               | B Finite(inf) inf - 0*
b36 >1    =1    .  | A Finite Finite(-inf) 0 -            | B Finite(inf) inf - 0*
b37 >1    >1    .  | A Finite Finite(-inf) 0 -            | B Finite(inf) Finite - 0
"""

# What the text extraction does to some rows (not disagreements with the mathematics).
GARBLED = {
    "a13": "the alpha cell of a13-a14 is empty; '0 < alpha < 1' stands in row a15 (a merged "
           "cell): a13, a14 belong to 0 < alpha < 1 by position",
    "a14": "the beta cell 'beta = 0' stands in the alpha column",
    "a26": "the upper bound has four cells for five columns (s, theta, phi, rho, mu): "
           "'inf inf inf* inf*'; read left to right, phi is missing",
    "a35": "'alpha > 1' stands in the beta column and 'beta < 0' in the comparison column; "
           "a36-a45 have their beta class in the alpha column",
    "b17": "the upper bound has four cells for five columns: 'inf inf inf* 0*' (the same "
           "text as b24); read left to right theta = inf and phi is missing",
    "b18": "the comparison stands in the alpha column (b18, b19)",
    "b24": "the upper bound has four cells for five columns: 'inf inf inf* 0*'",
    "b31": "the upper bound has four cells for five columns: 'inf inf inf* 0*'",
}
for _r in ("a29", "a30", "a31", "a32", "a33", "a34", "a40", "a41", "a42", "a43", "a44", "a45"):
    GARBLED[_r] = ("the upper bound has four cells for five columns: 'inf inf inf* inf*' "
                   "(three equal cells s = theta = phi = inf appear as two)")


def parse_table(text, kind):
    rows = []
    for line in text.strip().splitlines():
        head, lower, upper = [p.split() for p in line.split("|")]
        name, ac, bc, cmp = head
        cells = []
        for part in (lower, upper):
            assert len(part) == 5, line
            cells.append(dict(zip(("s", "theta", "phi", "rho", "mu"),
                                  [None if c == "?" else c for c in part])))
        rows.append({"row": name, "type": kind, "alpha": ac, "beta": bc,
                     "compare": None if cmp == "." else cmp,
                     "seed": {"lower": cells[0], "upper": cells[1]}})
    return rows


CLASS_DEFAULT = {"<0": -1, "=0": 0, "(0,1)": 0.5, "=1": 1, ">1": 2}
CLASS_TEST = {"<0": lambda v: v < 0, "=0": lambda v: v == 0, "(0,1)": lambda v: 0 < v < 1,
              "=1": lambda v: v == 1, ">1": lambda v: v > 1}

# Rows whose tangent / binormal behaviour depends on more than the row's conditions get
# one parameter set per sub-case: (alpha, beta, lam (None = default), omega (None = from the
# comparison), why).
SUBCASES = {}
for _r in ("a1", "a2", "a3"):
    SUBCASES[_r] = [(-2, -0.5, None, None, "alpha < beta: tau/kappa -> inf at s -> -inf"),
                    (-0.5, -2, None, None, "alpha > beta: kappa/tau -> inf at s -> -inf"),
                    (-1, -1, None, None, "alpha = beta: kappa/tau -> (lam/omega)^(1/|alpha|)")]
SUBCASES["a9"] = [(0, 0, 0.25, 1, "lam < omega: tau/kappa = e^((omega-lam)|s|)/nu -> inf"),
                  (0, 0, 1, 0.25, "lam > omega: kappa/tau -> inf"),
                  (0, 0, 1, 1, "lam = omega: kappa/tau = nu")]
SUBCASES["a16"] = [(0.75, 0.25, None, None, "alpha > beta: tau/kappa ~ u^(1/alpha-1/beta) -> inf"),
                   (0.25, 0.75, None, None, "alpha < beta: kappa/tau -> inf"),
                   (0.5, 0.5, None, None, "alpha = beta: kappa/tau -> constant")]
for _r in ("a43", "a44", "a45"):
    SUBCASES[_r] = [(1.25, 8, None, None, "alpha < beta: tau/kappa ~ s^(1/alpha-1/beta) -> inf"),
                    (8, 1.25, None, None, "alpha > beta: kappa/tau -> inf"),
                    (2, 2, None, None, "alpha = beta: kappa/tau -> constant")]
# Slow (logarithmic) divergences need lam, omega <= 1 to show a turning vector within reach.
LAM_OVERRIDE = {"a32": 0.5, "a33": 0.5, "a34": 0.25, "b28": 1, "b29": 1, "b30": 1}


def mu_bound_expr(kind):
    return "-nu^beta/(omega beta)" if kind == 1 else "nu^beta/(omega beta)"


def choose_params(row, alpha, beta, lam, omega):
    """Concrete (alpha, beta, lam, omega, nu) satisfying the row's conditions.

    nu = 1.  With a comparison: '=' takes lam = |beta|, omega = |alpha| (then the two bound
    expressions are the same double), '<' / '>' take the mu bound at twice or half of
    -1/(lam alpha)."""
    kind, cmp = row["type"], row["compare"]
    nu = 1.0
    if lam is None:
        lam = LAM_OVERRIDE.get(row["row"], 1.0)
    if cmp is None:
        omega = 1.0 if omega is None else omega
    elif omega is None:
        if cmp == "=":
            lam, omega = abs(beta), abs(alpha)
        else:
            A = -1 / (lam * alpha)
            # '>' means A > B: B = A/2 when A > 0, B = 2A when A < 0; '<' the other way
            r = (0.5 if A > 0 else 2.0) if cmp == ">" else (2.0 if A > 0 else 0.5)
            B = A * r
            omega = (-1 if kind == 1 else 1) * nu ** beta / (beta * B)
    return float(alpha), float(beta), float(lam), float(omega), nu


def check_conditions(row, p):
    a, b, lam, om, nu = p
    assert CLASS_TEST[row["alpha"]](a) and CLASS_TEST[row["beta"]](b), (row["row"], p)
    assert lam > 0 and om > 0
    if row["compare"]:
        A = -1 / (lam * a)
        B = (-1 if row["type"] == 1 else 1) * nu ** b / (om * b)
        ok = {"<": A < B, "=": A == B, ">": A > B}[row["compare"]]
        assert ok, (row["row"], p, A, B)


# ---- numerical evidence ----------------------------------------------------------------
DEPTHS = [1, 2, 4, 8, 16, 32]      # decades toward the end


def depth_points(curve, end, d):
    """s at 10^-k (relative) from a finite end, or |s| = 10^k toward an infinite one."""
    if end in (mp.inf, -mp.inf):
        return [d * mpf(10) ** k for k in DEPTHS]
    D = abs(end)
    return [end - d * D * mpf(10) ** (-k) for k in DEPTHS]


def _trend(values):
    """Increments between the last three depths."""
    return values[-2] - values[-3], values[-1] - values[-2]


def closed_form_evidence(curve, end, d):
    with mp.workdps(60):
        ss = depth_points(curve, end, d)
        lr = [curve.ln_rho(s) for s in ss]
        lm = [curve.ln_mu_over_nu(s) + mp.log(curve.nu) for s in ss]
        th = [curve.theta(s) for s in ss]
        ph = [curve.phi(s) for s in ss]
        lratio = [b - a for a, b in zip(lr, lm)]        # ln(kappa/tau) = ln mu - ln rho

        def limit(vals):
            d1, d2 = _trend(vals)
            if abs(d2) < mpf("1e-6"):
                return "finite"
            return "0" if d2 < 0 else "inf"

        def integral(vals):
            d1, d2 = _trend(vals)
            if abs(d2) < abs(d1) / 4 or abs(d2) < mpf("1e-20"):
                return "converges"
            return "-inf" if d2 < 0 else "inf"

        d1, d2 = _trend(lratio)
        ratio = "finite" if abs(d2) < mpf("0.05") else ("inf" if d2 > 0 else "0")

        def own_integral(f_int, own_end):
            # the integral toward the function's own end, beyond the other function's bound
            pts = depth_points(curve, own_end, d)
            return integral([f_int(s) for s in pts])

        rr_lo, rr_hi = curve.rho_range()
        mr_lo, mr_hi = curve.mu_range()
        own_k = rr_lo if d < 0 else rr_hi
        own_t = mr_lo if d < 0 else mr_hi
        ev = {
            "depth": ("|s| = 10^k" if end in (mp.inf, -mp.inf)
                      else "distance to the end = |end| 10^-k") + ", k = %s" % DEPTHS,
            "ln_rho": [mp.nstr(v, 8) for v in lr],
            "ln_mu": [mp.nstr(v, 8) for v in lm],
            "theta": [mp.nstr(v, 8) for v in th],
            "phi": [mp.nstr(v, 8) for v in ph],
            "ln_kappa_over_tau": [mp.nstr(v, 8) for v in lratio],
            "verdict": {
                "rho": limit(lr), "mu": limit(lm),
                "theta": integral(th), "phi": integral(ph),
                "kappa_over_tau": ratio,
                "theta_at_own_end": own_integral(curve.theta, own_k),
                "phi_at_own_end": own_integral(curve.phi, own_t),
            },
        }
        if end not in (mp.inf, -mp.inf):
            ev["rho_radicand_at_bound"] = mp.nstr(curve.rho_radicand(end), 5)
            ev["mu_radicand_at_bound"] = mp.nstr(curve.mu_radicand(end), 5)
    return ev


class _Budget(Exception):
    pass


def _angle(u, v):
    dot = sum(a * b for a, b in zip(u, v))
    cr = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return math.atan2(math.sqrt(sum(c * c for c in cr)), dot)


BUDGET = 3000.0          # rad of frame rotation (|theta| + |phi|) for one run
INT_DEPTH = 24           # half-decades: 10^-12 relative, or |s| = 10^12 ... capped below
SPREAD_SETTLES, SPREAD_TURNS = 0.2, 0.6


def integration_evidence(p, kind, end, d):
    """Integrate in doubles from s = 0 toward the end; spread of t and b near the end."""
    a, b, lam, om, nu = p
    cur = SpaceCurve(a, b, lam, om, nu, kind, ctx=fp)
    finite = end not in (mp.inf, -mp.inf)
    if finite:
        e = float(end)
        D = abs(e)
        checkpoints = [e - d * D * 10 ** (-j / 2) for j in range(1, INT_DEPTH + 1)]
    else:
        checkpoints = [d * 10 ** (j / 2) for j in range(0, 21)]
    samples = []            # (s, W, t, b)

    def rot(s):
        return abs(cur.theta(s)) + abs(cur.phi(s))

    def on_step(s0, h, ev):
        for sig in (0.25, 0.5, 0.75, 1.0):
            s = s0 + sig * h
            x, t, n, bb = ev(sig)
            samples.append((s, rot(s), t, bb))
        if samples[-1][1] > BUDGET:
            raise _Budget()

    s, state = 0.0, None
    reached = []
    stop = "depth"
    try:
        for c in checkpoints:
            state = cur.walk(c, s0=s, state=state, on_step=on_step)
            s = c
            reached.append(c)
            if not finite and abs(c) >= 1e10:
                break
    except (_Budget, OverflowError):
        stop = "rotation budget"
    s_end, w_end, t_end, b_end = samples[-1]
    # window: the last 4 pi of rotation, within the last three decades of depth
    if finite:
        u_end = abs(e - s_end)
        deep = [q for q in samples if abs(e - q[0]) <= 1000 * u_end]
    else:
        deep = [q for q in samples if abs(q[0]) >= abs(s_end) / 1000]
    win = [q for q in deep if q[1] >= w_end - 4 * math.pi]
    st = max(_angle(q[2], t_end) for q in win)
    sb = max(_angle(q[3], b_end) for q in win)

    def verdict(x):
        return "settles" if x < SPREAD_SETTLES else ("turns" if x > SPREAD_TURNS else "unclear")

    return {
        "stopped_by": stop,
        "s_reached": repr(s_end),
        "distance_to_end": repr(abs(e - s_end)) if finite else None,
        "rotation_reached": round(w_end, 3),
        "window_rotation": round(w_end - min(q[1] for q in win), 3),
        "tangent_spread": round(st, 6),
        "binormal_spread": round(sb, 6),
        "log10_kappa_over_tau_at_end": round((cur.ln_mu_over_nu(s_end) + math.log(nu)
                                               - cur.ln_rho(s_end)) / math.log(10), 4),
        "verdict": {"tangent": verdict(st), "binormal": verdict(sb)},
    }


# ---- comparison ----------------------------------------------------------------------------
def _strip(c):
    return c.rstrip("*") if c else c


def expected_cells(cls):
    return {k: cls[k] for k in ("bound", "theta", "phi", "rho", "mu")}


def numeric_agrees(cls, ev_cf, ev_int):
    """Do the numerical verdicts reproduce the classification?  Returns a list of problems."""
    bad = []
    v = ev_cf["verdict"]
    lim = {"0": "0", "inf": "inf", "-": "finite"}
    if lim[_strip(cls["rho"])] != v["rho"]:
        bad.append("rho")
    if lim[_strip(cls["mu"])] != v["mu"]:
        bad.append("mu")
    for key, vk, own in (("theta", "theta", "theta_at_own_end"), ("phi", "phi", "phi_at_own_end")):
        c = cls[key]
        if c.startswith("Finite"):
            if v[vk] != "converges":
                bad.append(key)
            q = c[7:-1] if c.startswith("Finite(") else None
            if q is not None and {"F": "converges"}.get(q, q) != v[own]:
                bad.append(key + " qualifier")
        elif v[vk] != c:
            bad.append(key)
    if cls["kappa_over_tau"] != v["kappa_over_tau"]:
        bad.append("kappa/tau")
    want_t = "settles" if cls["tangent_settles"] else "turns"
    want_b = "settles" if cls["binormal_settles"] else "turns"
    if ev_int["verdict"]["tangent"] != want_t:
        bad.append("tangent")
    if ev_int["verdict"]["binormal"] != want_b:
        bad.append("binormal")
    return bad


def compare_row(row, cls):
    """Cells where the seed's table differs from the mathematics (seed's own notation)."""
    out = []
    for end in ("lower", "upper"):
        seed, exp = row["seed"][end], cls[end]
        for key in ("s", "theta", "phi", "rho", "mu"):
            want = exp["bound"] if key == "s" else exp[key]
            if seed[key] != want:
                out.append({"end": end, "cell": key, "seed": seed[key], "expected": want})
    return out


def reading_problems(row, checks):
    """Where the seed's reading of an infinite theta / phi ("the tangent / binormal rotates
    infinitely toward the bound", and '*' = "direction not determined") fails: the integral
    diverges but the vector has a limit."""
    out = {}
    for c in checks:
        for end in ("lower", "upper"):
            for key, vec in (("theta", "tangent"), ("phi", "binormal")):
                if c[end]["cells"][key] in ("-inf", "inf") and c[end][vec + "_settles"]:
                    item = out.setdefault((end, key), {
                        "end": end, "cell": key, "seed": row["seed"][end][key],
                        "expected": c[end]["cells"][key], "kind": "reading",
                        "note": "the %s settles although %s diverges (%s)" % (
                            vec, key, "kappa/tau -> inf" if vec == "binormal"
                            else "tau/kappa -> inf"),
                        "when": []})
                    item["when"].append(c.get("subcase") or "always")
                    if c[end]["length_finite"]:
                        radius = "rho" if key == "theta" else "mu"
                        item["radius_cell_by_behaviour"] = {
                            "seed": row["seed"][end][radius],
                            "by_behaviour": c[end]["radius_cells_by_behaviour"][radius]}
    return list(out.values())


def seed_reading(row):
    """What the seed's cells say under the seed's own reading: a finite s bound = finite
    length; an infinite theta / phi = the tangent / binormal rotates infinitely."""
    out = {}
    for end in ("lower", "upper"):
        c = row["seed"][end]

        def vec(cell):
            if cell is None:
                return None
            return "turns" if cell in ("-inf", "inf") else "settles"

        out[end] = {"length_finite": c["s"] not in ("-inf", "inf"),
                    "tangent": vec(c["theta"]), "binormal": vec(c["phi"]),
                    "rho": c["rho"], "mu": c["mu"]}
    return out


KIND_NOTES = {
    ("a5", "upper", "phi"): "labelling: the upper bound is set by rho; phi stops before its "
                            "own (finite) limit, which the seed writes Finite(F) in a3, a4",
    ("a24", "upper", "theta"): "error: for alpha = 1 theta -> inf at its own end (s -> inf), so "
                               "cut at the mu bound it is Finite(inf), not Finite(F) (compare "
                               "b28-b30, which have it right)",
    ("a35", "upper", "theta"): "error: for alpha > 1 theta -> inf as s -> inf, so cut at the mu "
                               "bound it is Finite(inf), not Finite(F) (compare b35-b37)",
    ("b12", "upper", "rho"): "error: s -> inf with alpha = 0, rho = exp(lam s) -> inf (infinite "
                             "length: inf*), not a finite value (compare b13)",
    ("b17", "upper", "theta"): "error or garble: for 0 < alpha < 1 theta converges as s -> inf "
                               "(Finite, as in b18-b20); the text has 'inf' here and lacks a cell",
    ("b18", "lower", "mu"): "star: phi is finite and the length finite, so by the table's own "
                            "convention (b25, b32, a22) mu is 'inf' without '*'",
}


def _word(settles):
    return "settles" if settles else "turns"


def classification_row(row):
    kind = row["type"]
    subs = SUBCASES.get(row["row"])
    if subs is None:
        subs = [(CLASS_DEFAULT[row["alpha"]], CLASS_DEFAULT[row["beta"]], None, None, None)]
    checks, cls0 = [], None
    for a, b, lam, om, why in subs:
        p = choose_params(row, a, b, lam, om)
        check_conditions(row, p)
        with mp.workdps(50):
            cls = classify(*p, kind)
            curve = SpaceCurve(*p, kind)
            lo, hi = curve.s_range()
        ends = {}
        for name, end, d in (("lower", lo, -1), ("upper", hi, 1)):
            c = cls[name]
            ev_cf = closed_form_evidence(curve, end, d)
            ev_int = integration_evidence(p, kind, end, d)
            bad = numeric_agrees(c, ev_cf, ev_int)
            if bad:
                raise SystemExit("%s %s %s: numerics disagree with classify(): %s\n%s\n%s"
                                 % (row["row"], p, name, bad, ev_cf["verdict"], ev_int))
            ends[name] = {
                "bound_value": None if end in (mp.inf, -mp.inf) else float(end),
                "binds": c["binds"],
                "length_finite": c["length_finite"],
                "cells": expected_cells(c),
                "kappa_over_tau": c["kappa_over_tau"],
                "radius_cells_by_behaviour": {"rho": c["rho_settle_star"],
                                              "mu": c["mu_settle_star"]},
                "tangent_settles": c["tangent_settles"],
                "binormal_settles": c["binormal_settles"],
                "closed_form_evidence": ev_cf,
                "integration_evidence": ev_int,
            }
        chk = {"alpha": p[0], "beta": p[1], "lambda": p[2], "omega": p[3], "nu": p[4],
               "type": kind, "lower": ends["lower"], "upper": ends["upper"]}
        if why:
            chk["subcase"] = why
        checks.append(chk)
        if cls0 is None:
            cls0 = cls
    # the seed-notation cells do not depend on the subcase; the settling may
    for chk in checks[1:]:
        for end in ("lower", "upper"):
            assert chk[end]["cells"] == checks[0][end]["cells"]
    expected = {end: expected_cells(cls0[end]) for end in ("lower", "upper")}
    behaviour = {}
    for end in ("lower", "upper"):
        vals = {(c[end]["tangent_settles"], c[end]["binormal_settles"]) for c in checks}
        if len(vals) == 1:
            ts, bs = vals.pop()
            behaviour[end] = {"length_finite": cls0[end]["length_finite"],
                              "tangent": _word(ts), "binormal": _word(bs)}
        else:
            behaviour[end] = {"length_finite": cls0[end]["length_finite"], "tangent": "depends",
                              "binormal": "depends",
                              "cases": [{"when": c.get("subcase"),
                                         "tangent": _word(c[end]["tangent_settles"]),
                                         "binormal": _word(c[end]["binormal_settles"])}
                                        for c in checks]}
    dis = []
    for item in compare_row(row, cls0):
        if item["seed"] is None:
            item["kind"] = "garbled"
            item["note"] = "cell missing in the text extraction"
        else:
            item["kind"] = "table"
            note = KIND_NOTES.get((row["row"], item["end"], item["cell"]))
            if note is None:
                raise SystemExit("unexplained disagreement %s %s" % (row["row"], item))
            item["note"] = note
        dis.append(item)
    dis += reading_problems(row, checks)
    mb = mu_bound_expr(kind)
    cond = {"alpha": row["alpha"], "beta": row["beta"], "compare": row["compare"]}
    if row["compare"]:
        cond["text"] = "-1/(lambda alpha) %s %s" % (row["compare"], mb)
    return {
        "row": row["row"], "type": kind, "conditions": cond,
        "bound_expressions": {"A": "-1/(lambda alpha)", "B": mb},
        "seed": row["seed"],
        "seed_reading": seed_reading(row),
        "seed_text_note": GARBLED.get(row["row"]),
        "expected": expected,
        "behaviour": behaviour,
        "disagreements": dis,
        "checks": checks,
    }


def write_classification(jobs):
    rows = parse_table(TYPE1, 1) + parse_table(TYPE2, 2)
    assert len(rows) == 82
    t0 = time.time()
    if jobs > 1:
        with Pool(jobs) as pool:
            out = pool.map(classification_row, rows)
    else:
        out = [classification_row(r) for r in rows]
    doc = {
        "generator": "tools/reference/space_fixtures.py",
        "source": "seed 003 (Yoshida, Fukuda & Saito 2010), Fig. 5 (type 1) and Fig. 6 (type 2), "
                  "from the plain-text extraction",
        "notation": {
            "bound": "A = -1/(lambda alpha); B = the mu bound (type 1 -nu^beta/(omega beta), "
                     "type 2 nu^beta/(omega beta)); -inf / inf",
            "theta_phi": "theta = int_0^s kappa, phi = int_0^s tau toward the end: -inf / inf "
                         "diverges; Finite converges at the function's own end; "
                         "Finite(-inf) / Finite(inf) / Finite(F): the end is set by the other "
                         "function first (the integral stops at a finite value; in "
                         "parentheses what it does at its own end)",
            "rho_mu": "0 / inf: the limit; '*' when the length is infinite or the integral "
                      "(theta for rho, phi for mu) diverges; '-' a finite positive value",
            "seed_null": "null in 'seed': the text extraction has no cell there",
            "seed_reading": "the seed's cells read as the seed reads them: finite s bound = "
                            "finite length, infinite theta / phi = the tangent / binormal "
                            "turns forever",
            "radius_cells_by_behaviour": "the rho / mu cells with '*' set by the actual "
                                         "behaviour (infinite length or the vector keeps "
                                         "turning), i.e. the seed's definition of '*' "
                                         "('direction not determined') applied correctly",
            "behaviour": "settles = the unit vector has a limit at the end; turns = it keeps "
                         "rotating. The tangent settles iff int kappa < inf or tau/kappa -> "
                         "inf; the binormal iff int tau < inf or kappa/tau -> inf (Darboux "
                         "axis argument, space_mpmath.py)",
            "disagreement_kinds": "table: the seed's cell contradicts the mathematics under "
                                  "the seed's own definitions; garbled: the extraction lost "
                                  "the cell; reading: the cell is right as an integral but the "
                                  "seed's reading 'infinite theta/phi = the tangent/binormal "
                                  "rotates infinitely' is wrong there (the vector settles)",
        },
        "assumptions": "lambda > 0 and omega > 0 (seed 003: with either 0 the table does not "
                       "hold); '=' rows use nu = 1, lambda = |beta|, omega = |alpha|, so "
                       "the two bound expressions are the same double",
        "rows": out,
    }
    path = os.path.join(OUT, "space_classification.json")
    with open(path, "w") as f:      # one row per line
        head = {k: v for k, v in doc.items() if k != "rows"}
        f.write(json.dumps(head, indent=1)[:-2] + ',\n "rows": [\n')
        f.write(",\n".join(json.dumps(r, separators=(",", ":")) for r in out))
        f.write("\n]}\n")
    n_dis = {}
    for r in out:
        for d_ in r["disagreements"]:
            n_dis[d_["kind"]] = n_dis.get(d_["kind"], 0) + 1
    print("space_classification.json: %d rows, %d checks, disagreements %s, %.0f s"
          % (len(out), sum(len(r["checks"]) for r in out), n_dis, time.time() - t0))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", choices=["family", "classification"])
    ap.add_argument("-j", "--jobs", type=int, default=1)
    args = ap.parse_args()
    if args.only in (None, "family"):
        write_family(args.jobs)
    if args.only in (None, "classification"):
        write_classification(args.jobs)


if __name__ == "__main__":
    main()
