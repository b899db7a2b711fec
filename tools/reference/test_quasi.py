"""Quasi-aesthetic curves (docs/math.md §5): the reference itself, then `lac quasi` and
`lac monotone` against it.

    LAC_BIN=target/release/lac .venv/bin/python -m pytest tools/reference/test_quasi.py -q

The reference is quasi_mpmath.py (exact Fraction verdicts, 40-digit mpmath evaluation, the
tangent-angle correspondence errors) and the committed fixtures monotone.json and
quasi.json written by quasi_fixtures.py.  The command-line tests are skipped, with the
reason, when `$LAC_BIN quasi --help` (or `monotone --help`) does not succeed.

`lac monotone` may qualify a verdict with "proven": false where dkappa/ds is zero within
rounding; such a verdict is not held to the exact one, but it is only accepted for the
fixture kinds built to sit there (circles, near-circles, the adversarial families).

Tolerances not stated by the brief: the reported rms is also accepted within 1e-12
absolute (like max), since both are ~1e-17 for a circular arc; for a circular arc (an
isosceles triangle) a piece may say "constant" where the exact verdict of its rounded
doubles says otherwise.
"""

import json
import os
import random
import subprocess
from fractions import Fraction

import pytest
from mpmath import mp, mpf, mpc, atan2, conj, fabs

import quasi_mpmath as qm
from lac_cli import lac_bin, require
from segment_mpmath import cross, solve_segment

mp.dps = 40
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FIXTURES = os.path.join(ROOT, "crates", "lac", "tests", "fixtures")


def load(name):
    with open(os.path.join(FIXTURES, name)) as f:
        return json.load(f)["cases"]


# ---- the reference itself ----------------------------------------------------------------

def test_homogeneous_identity_agrees_with_seed_formula():
    """kappa = w^3 D / |V|^3 and dkappa/ds = w^4 N / |V|^6 (exact polynomials) agree with
    det(x', x'') / |x'|^3 and seed 001 eq. 5.1 (x', x'', x''' by Leibniz) to 1e-30."""
    rng = random.Random(5)
    for _ in range(10):
        pts = [(rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(4)]
        ws = [10 ** rng.uniform(-1, 1) for _ in range(4)]
        exact, rc = qm.ExactCubic(pts, ws), qm.RationalCubic(pts, ws)
        assert qm.degree(exact.N) <= 12 and qm.degree(exact.D) <= 3
        for t in [0.0, 0.3, 0.71, 1.0]:
            k, dk = qm.homogeneous_kappa(exact, t)
            assert fabs(k - rc.kappa(mpf(t))) <= mpf("1e-30") * fabs(k)
            assert fabs(dk - rc.dkappa_ds(mpf(t))) <= mpf("1e-30") * fabs(dk)


def test_odd_part_keeps_only_odd_multiplicities():
    """(t - 1/3)^2 (t - 1/2)^3 (t - 3/4): dkappa/ds would change sign at 1/2 and 3/4 only."""
    lin = lambda r: [Fraction(-r), Fraction(1)]
    p = [Fraction(1)]
    for r, m in [(Fraction(1, 3), 2), (Fraction(1, 2), 3), (Fraction(3, 4), 1)]:
        for _ in range(m):
            p = qm.pmul(p, lin(r))
    assert qm.isolate_roots(qm.odd_part(p)) == [0.5, 0.75]


def test_verdicts_of_known_curves():
    """A line and an exact rational circle are constant; a parabola-like polynomial cubic
    with its vertex inside has a sign change there; reversal keeps the verdict."""
    assert qm.monotone_verdict([(0, 0), (1, 0), (2, 0), (3, 0)], [1, 2, 3, 4]) == ("constant", [])
    circle = [(0, 0), (200, 0), (360, 120), (416, 312)]  # see quasi_fixtures.exact_circles
    assert qm.monotone_verdict(circle, [15, 13, 13, 15]) == ("constant", [])
    v, t = qm.monotone_verdict([(-1, 1), (-1 / 3, -1 / 3), (1 / 3, -1 / 3), (1, 1)], [1] * 4)
    assert v == "not_monotone" and t == [0.5]
    sym = [(-1, 0), (-0.5, 1), (0.7, 1), (1, 0.2)]
    a = qm.monotone_verdict(sym, [1, 2, 0.5, 1])
    b = qm.monotone_verdict(sym[::-1], [1, 0.5, 2, 1])
    assert a[0] == b[0] and all(abs(x - (1 - y)) < 1e-15 for x, y in zip(a[1], b[1][::-1]))
    with pytest.raises(ValueError):  # a cusp: speed 0 at t = 1/2
        qm.monotone_verdict([(0, 0), (1, 1), (0, 1), (1, 0)], [1, 1, 1, 1])


def test_monotone_fixture_is_consistent():
    """Every fixture verdict is re-derived exactly for a sample of cases, and for all cases
    the sampled dkappa/ds never contradicts it; narrow cases are missed by 1000 samples."""
    cases = load("monotone.json")
    assert len(cases) >= 250
    for c in cases:
        ds = [s["dkappa_ds"] for s in c["samples"]]
        if c["verdict"] == "increasing":
            assert min(ds) >= 0
        elif c["verdict"] == "decreasing":
            assert max(ds) <= 0
        elif c["verdict"] == "constant":
            assert all(d == 0 for d in ds)
        else:
            assert c["sign_changes"]
    for c in cases[::15] + [c for c in cases if c["kind"] in ("narrow", "near-end")][::4]:
        assert qm.monotone_verdict(c["points"], c["weights"]) == (c["verdict"], c["sign_changes"])


def test_lac_segment_agrees_with_solve_segment():
    """LacSegment (points by turning) is segment_mpmath's segment: same end curvatures, arc
    length, and the point at a given turning lies on it (checked at its tangent angle)."""
    for pts, alpha in [([(0, 0), (1, 0), (1, 0.6)], 0), ([(1, 0.6), (1, 0), (0, 0)], 2),
                       ([(0, 0), (1, 0), (1, -0.8)], -1), ([(0, 0), (1, 0), (1.3, 0.5)], 1)]:
        lac = qm.LacSegment(*pts, alpha)
        ref = solve_segment(*[mpc(*p) for p in pts], mpf(alpha), [0.0, 0.25, 0.5, 1.0])
        assert fabs(lac.arc_length - ref["arc_length"]) <= mpf("1e-30") * ref["arc_length"]
        for ours, theirs in [(lac.kappa_start, ref["curvature_start"]),
                             (lac.kappa_end, ref["curvature_end"])]:
            assert fabs(ours - theirs) <= mpf("1e-30") * fabs(ours)
        for s in ref["samples"]:
            phi = fabs(s["theta"] - ref["samples"][0]["theta"])
            assert abs(lac.point(phi) - mpc(s["x"], s["y"])) <= mpf("1e-30") * lac.arc_length
            assert fabs(lac.kappa(phi) - s["kappa"]) <= mpf("1e-30") * fabs(s["kappa"])


def test_circle_fit_is_exact_and_optimum_is_stationary():
    """Isosceles: the degree-elevated arc has zero error at 40 digits.  A fixture optimum
    is a stationary point of F on a finer rule (its gradient moves (u, v) by < 1e-12)."""
    lac = qm.LacSegment((0, 0), (1, 0), (1, 1), 0.7)
    assert lac.lam == 0
    c = mp.cos(lac.theta / 2)
    pts, ws = qm.seed_construction(lac, 2 * c / (1 + 2 * c), 2 * c / (1 + 2 * c))
    assert fabs(ws[0] - 1) < mpf("1e-35") and fabs(ws[3] - 1) < mpf("1e-35")
    rms, mx = qm.correspondence_errors(lac, [qm.piece_of(pts, ws)], n=8)
    assert mx < mpf("1e-35")
    case = [c for c in load("quasi.json") if c["name"] == "turn90-r0.6-alpha0"][0]
    f = qm.FitObjective(qm.LacSegment(*case["points"], case["alpha"]), 30)
    u, v = mpf(case["u"]), mpf(case["v"])
    grad, hess = qm.gradient_hessian(f, u, v, mpf("1e-8"))
    du, dv = qm.newton_step(grad, hess)
    assert max(fabs(du), fabs(dv)) < 1e-12


# ---- the command line --------------------------------------------------------------------

def run_json(args):
    run = subprocess.run([lac_bin()] + args, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, (args, run.stderr)
    return json.loads(run.stdout)


def fmt_points(points):
    return " ".join(f"{x!r},{y!r}" for x, y in points)


def angle(a, b):
    """Unsigned angle between complex directions a and b."""
    return fabs(atan2(cross(a, b), (conj(a) * b).real))


# (fixture case name, tolerance or None); without a tolerance the fixture gives the optimum
QUASI_INPUTS = [
    ("turn90-r0.6-alpha0", None), ("turn90-r0.8-alpha-1", None), ("turn90-r0.6-alpha2", None),
    ("similar-turn90-r0.6-alpha0.5", None), ("turn90-r1.0-alpha1", None),
    ("reversed-turn90-r0.6-alpha0", 1e-3), ("turn90-r0.6-alpha1", 1e-6),
    ("right-turn90-r0.6-alpha-1", 1e-6), ("turn90-r0.4-alpha0", 1e-9),
    ("similar-turn90-r0.6-alpha0.5", 1e-9),
]


@pytest.mark.parametrize("name,tol", QUASI_INPUTS)
def test_cli_quasi(name, tol):
    """`lac quasi`: G2 chain from P0 to P2 with the LAC's end tangents and curvatures, exact
    monotonicity verdicts in the LAC's direction, the tolerance met at 40 digits, the
    reported rms/max right, and without a tolerance the seed-001 optimum as one piece."""
    require("quasi")
    case = [c for c in load("quasi.json") if c["name"] == name][0]
    points, alpha = case["points"], case["alpha"]
    args = ["quasi", "--points", fmt_points(points), "--alpha", repr(alpha)]
    if tol is not None:
        args += ["--tolerance", repr(tol)]
    out = run_json(args)
    lac = qm.LacSegment(*points, alpha)
    p0, p1, p2 = [mpc(*p) for p in points]
    chord = abs(p2 - p0)
    pieces = [qm.RationalCubic(p["points"], p["weights"]) for p in out["pieces"]]
    assert pieces, out
    first, last = pieces[0], pieces[-1]
    assert abs(first.point(mpf(0)) - p0) <= 1e-12 * chord
    assert abs(last.point(mpf(1)) - p2) <= 1e-12 * chord
    assert angle(first.tangent(mpf(0))[0], p1 - p0) <= 1e-9
    assert angle(last.tangent(mpf(1))[0], p2 - p1) <= 1e-9
    for a, b in zip(pieces, pieces[1:]):  # G2 joins
        assert abs(a.point(mpf(1)) - b.point(mpf(0))) <= 1e-12 * chord
        assert angle(a.tangent(mpf(1))[0], b.tangent(mpf(0))[0]) <= 1e-9
        ka, kb = a.kappa(mpf(1)), b.kappa(mpf(0))
        assert fabs(ka - kb) <= 1e-9 * fabs(kb), (ka, kb)
    assert fabs(first.kappa(mpf(0)) - lac.kappa_start) <= 1e-9 * fabs(lac.kappa_start)
    assert fabs(last.kappa(mpf(1)) - lac.kappa_end) <= 1e-9 * fabs(lac.kappa_end)
    circle = lac.lam == 0
    direction = "increasing" if lac.kappa_end > lac.kappa_start else "decreasing"
    for p in out["pieces"]:
        verdict, _ = qm.monotone_verdict(p["points"], p["weights"])
        if circle:
            assert p["monotone"] in ("constant", verdict), (p, verdict)
        else:
            assert p["monotone"] == verdict == direction, (p, verdict, direction)
    rms, mx = qm.correspondence_errors(lac, pieces, n=16)
    if tol is not None:
        assert mx <= tol * (1 + 1e-6), (float(mx), tol, len(pieces))
    assert abs(out["max"] - mx) <= max(1e-3 * mx, 1e-12), (out["max"], float(mx))
    assert abs(out["rms"] - rms) <= max(1e-3 * rms, 1e-12), (out["rms"], float(rms))
    if tol is None:
        assert len(pieces) == 1
        b = [mpc(*p) for p in out["pieces"][0]["points"]]
        u = abs(b[1] - b[0]) / abs(p1 - p0)
        v = abs(b[2] - b[3]) / abs(p1 - p2)
        assert fabs(u - case["u"]) <= 1e-6 and fabs(v - case["v"]) <= 1e-6, (u, v, case)


# kinds where dkappa/ds is zero within rounding somewhere: an unproven verdict is allowed
ROUNDING_KINDS = {"circle", "collinear", "near-circle", "narrow", "near-end", "near-not-monotone",
                  "near-end-monotone"}


def test_cli_monotone():
    """`lac monotone` on every fixture case (~290): a verdict it calls proven (or does not
    qualify) is the exact one, with t within 1e-6 of a sign change of dkappa/ds when not
    monotone; exactly constant curves are "constant"; unproven verdicts ("proven": false)
    occur only for the kinds where dkappa/ds is zero within rounding, and the random,
    polynomial, spiral and scaled curves are all proven."""
    require("monotone")
    cases = load("monotone.json")
    wrong, unproven = [], {}
    for c in cases:
        out = run_json(["monotone", "--points", fmt_points(c["points"]),
                        "--weights", ",".join(repr(w) for w in c["weights"])])
        if "t" in out and out["verdict"] != "not_monotone":
            wrong.append((c["name"], out, "t given for a monotone verdict"))
        if c["verdict"] == "constant" and out["verdict"] != "constant":
            wrong.append((c["name"], out, c["verdict"]))
        if not out.get("proven", True):
            unproven[c["kind"]] = unproven.get(c["kind"], 0) + 1
            if c["kind"] not in ROUNDING_KINDS:
                wrong.append((c["name"], out, c["verdict"], "unproven"))
            continue
        if out["verdict"] != c["verdict"]:
            wrong.append((c["name"], out, c["verdict"], c["sign_changes"]))
        elif c["verdict"] == "not_monotone":
            t = out.get("t")
            if not (isinstance(t, float) and min(abs(t - s) for s in c["sign_changes"]) <= 1e-6):
                wrong.append((c["name"], out, c["sign_changes"]))
    print(f"unproven verdicts by kind: {unproven}")
    assert not wrong, wrong
