"""Claims about the space-curve reference itself (space_mpmath.py) and its fixtures.

    .venv/bin/python -m pytest tools/reference/test_space_reference.py -q   (from the repo root)

Internal consistency at 40 digits: the Frenet frame stays orthonormal and right-handed, the
helix closed form (lam = omega = 0), the sign of torsion, the LCG / LTG slopes of the rho and
mu formulas by numerical differentiation, the turning integrals by quadrature, continuity at
alpha, beta = 0, 1 and lam = 0, integration there and back, the reversal symmetry, and an
independent check with mpmath's own ODE solver.  Then the committed fixtures: their shape,
their frames, a re-integration of a few cases, and the classification table against
classify().
"""

import json
import os

import pytest
from mpmath import mp, mpf, diff, quad, odefun, log

from space_mpmath import SpaceCurve, helix_frame, classify

mp.dps = 40
FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "crates", "lac",
                        "tests", "fixtures")
CURVES = [  # alpha, beta, lam, omega, nu, type
    (-1, 0.5, 0.3, 2, 0.5, 2), (0, 0, 1, 1, 1, 1), (1, 1, 1, 1, 1, 1), (2, -1, 1, 0.5, 3, 1),
    (0.5, 2, 0.3, 0.5, 1, 2), (-0.5, -1, 1, 2, 3, 1),
]


@pytest.fixture(autouse=True)
def _forty_digits():
    with mp.workdps(40):
        yield


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def inside(curve, frac):
    """A point at `frac` of the way toward each end (or +-frac*2 toward an infinite one)."""
    lo, hi = curve.s_range()
    out = []
    for end in (lo, hi):
        out.append(end * frac if abs(end) != mp.inf else (2 * frac if end > 0 else -2 * frac))
    return out


def test_frame_is_orthonormal_and_right_handed():
    for p in CURVES:
        c = SpaceCurve(*p)
        for f in c.frames(inside(c, mpf("0.8"))):
            for u, v, want in ((f.t, f.t, 1), (f.n, f.n, 1), (f.b, f.b, 1), (f.t, f.n, 0),
                               (f.t, f.b, 0), (f.n, f.b, 0)):
                assert abs(dot(u, v) - want) < mpf("1e-25")
            assert max(abs(a - b) for a, b in zip(cross(f.t, f.n), f.b)) < mpf("1e-25")


def test_helix_closed_form():
    """lam = omega = 0 is a helix whatever alpha and beta are."""
    for alpha, beta, nu in ((0, 0, 1), (-1, 2, 0.5), (0.5, -1, 3), (1, 1, 2)):
        c = SpaceCurve(alpha, beta, 0, 0, nu, 1)
        assert c.s_range() == (-mp.inf, mp.inf)
        for s in (mpf("-2.5"), mpf("1.7"), mpf(6)):
            f, h = c.frame_at(s), helix_frame(nu, s)
            for u, v in ((f.x, h.x), (f.t, h.t), (f.n, h.n), (f.b, h.b)):
                assert max(abs(a - b) for a, b in zip(u, v)) < mpf("1e-30")


def test_torsion_sign_convention():
    """x(s) = s t + kappa s^2/2 n + kappa tau s^3/6 b + O(s^4): tau > 0 rises toward +b."""
    for p in CURVES:
        c = SpaceCurve(*p)
        k0, t0 = c.kappa(0), c.tau(0)
        assert abs(k0 - 1) < mpf("1e-35") and t0 > 0 and abs(1 / t0 - mpf(p[4])) < mpf("1e-35")
        for s in (mpf("1e-3"), mpf("-1e-3")):
            x = c.frame_at(s).x
            assert abs(x[2] - k0 * t0 * s ** 3 / 6) < 10 * abs(s) ** 4
            assert x[2] * s > 0
        # the standard-form helix with kappa = tau = 1 climbs: z(pi) > 0
        assert helix_frame(1, mp.pi).x[2] > 0


def test_rho_mu_have_straight_lcg_and_ltg():
    """log(rho ds/drho) = alpha log rho - log lam and log(mu |ds/dmu|) = beta log mu - log omega."""
    for alpha in (-1, -0.5, 0, 0.5, 1, 2):
        for beta in (-1, 0, 1, 2):
            for kind in (1, 2):
                c = SpaceCurve(alpha, beta, mpf("0.3"), mpf("0.5"), 3, kind)
                assert abs(c.rho(0) - 1) < mpf("1e-35") and abs(c.mu(0) - 3) < mpf("1e-34")
                lo, hi = c.s_range()
                for frac in ("0.2", "0.6"):
                    for s in inside(c, mpf(frac)):
                        drho = diff(c.rho, s)
                        dmu = diff(c.mu, s)
                        assert drho > 0 and (dmu > 0) == (kind == 1)
                        lcg = log(c.rho(s) / drho) - alpha * log(c.rho(s))
                        ltg = log(c.mu(s) / abs(dmu)) - beta * log(c.mu(s))
                        assert abs(lcg + log(mpf("0.3"))) < mpf("1e-25")
                        assert abs(ltg + log(mpf("0.5"))) < mpf("1e-25")


def test_turning_integrals_by_quadrature():
    for p in CURVES:
        c = SpaceCurve(*p)
        for s in inside(c, mpf("0.7")):
            assert abs(c.theta(s) - quad(c.kappa, [0, s])) < mpf("1e-25") * (1 + abs(c.theta(s)))
            assert abs(c.phi(s) - quad(c.tau, [0, s])) < mpf("1e-25") * (1 + abs(c.phi(s)))


def test_s_range_matches_seed_fig2():
    lam, om, nu = mpf(2), mpf("0.5"), mpf(3)
    for alpha in (-1, 0, 1):
        for beta in (-2, 0, 2):
            for kind in (1, 2):
                c = SpaceCurve(alpha, beta, lam, om, nu, kind)
                r = (-mp.inf, mp.inf) if alpha == 0 else (
                    (-mp.inf, -1 / (lam * alpha)) if alpha < 0 else (-1 / (lam * alpha), mp.inf))
                if beta == 0:
                    m = (-mp.inf, mp.inf)
                else:
                    bnd = nu ** beta / (om * beta)
                    if kind == 1:
                        m = (-mp.inf, -bnd) if beta < 0 else (-bnd, mp.inf)
                    else:
                        m = (bnd, mp.inf) if beta < 0 else (-mp.inf, bnd)
                lo, hi = c.s_range()
                assert lo == max(r[0], m[0]) and hi == min(r[1], m[1])
                for end in (lo, hi):
                    if abs(end) != mp.inf:
                        assert min(abs(c.rho_radicand(end)), abs(c.mu_radicand(end))) < mpf("1e-35")
    # the seed's example: type 1, alpha > 0, beta < 0: -1/(lam alpha) < s < -nu^beta/(omega beta)
    c = SpaceCurve(1, -2, lam, om, nu, 1)
    assert c.s_range() == (-1 / lam, -nu ** -2 / (om * -2))


def test_continuous_at_alpha_beta_0_1_and_lam_0():
    s = mpf("0.4")
    pairs = [((0, 0.5, 1, 1, 1, 1), (1e-13, 0.5, 1, 1, 1, 1)),
             ((1, 0.5, 1, 1, 1, 1), (1 - 1e-13, 0.5, 1, 1, 1, 1)),
             ((0.5, 0, 1, 1, 2, 2), (0.5, -1e-13, 1, 1, 2, 2)),
             ((0.5, 1, 1, 1, 2, 1), (0.5, 1 + 1e-13, 1, 1, 2, 1)),
             ((-1, 2, 0, 0.5, 1, 1), (-1, 2, 1e-13, 0.5, 1, 1)),
             ((-1, 2, 1, 0, 1, 2), (-1, 2, 1, 1e-13, 1, 2))]
    for p, q in pairs:
        a, b = SpaceCurve(*p), SpaceCurve(*q)
        for name in ("rho", "mu", "theta", "phi"):
            assert abs(getattr(a, name)(s) - getattr(b, name)(s)) < mpf("1e-11")
        fa, fb = a.frame_at(s), b.frame_at(s)
        assert max(abs(u - v) for u, v in zip(fa.x + fa.b, fb.x + fb.b)) < mpf("1e-11")


def test_there_and_back():
    c = SpaceCurve(-0.5, 2, 1, 0.5, 1, 2)
    s1 = inside(c, mpf("0.9"))[1]
    state = c.walk(s1)
    x, t, n, b = c.walk(0, s0=s1, state=state)
    want = ([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1])
    for u, v in zip((x, t, n, b), want):
        assert max(abs(p - q) for p, q in zip(u, v)) < mpf("1e-35")


def test_reversal_symmetry():
    """Backward from s1 the curve is LASC(alpha, beta, -lam rho1^(1-alpha),
    omega rho1^(1-beta), mu1/rho1, other type) scaled by rho1 with frame (-t1, n1, -b1)."""
    for p in [(0.5, 2, 0.3, 0.5, 1, 2), (-1, -1, 1, 2, 3, 1), (0, 1, 1, 0.5, 0.5, 1)]:
        c = SpaceCurve(*p)
        s1 = inside(c, mpf("0.6"))[1]
        f1 = c.frame_at(s1)
        rev, r1 = c.reversed_at(s1)
        cols = ([-v for v in f1.t], f1.n, [-v for v in f1.b])

        def to_caller(v, translate):
            out = [sum(cols[j][i] * v[j] for j in range(3)) for i in range(3)]
            return [translate[i] + r1 * out[i] for i in range(3)] if translate else out

        for frac in (mpf("0.5"), mpf(1)):
            u = s1 / r1 * frac
            g = rev.frame_at(u)
            orig = c.frame_at(s1 - r1 * u) if frac != 1 else None
            x = to_caller(g.x, f1.x)
            t = to_caller(g.t, None)
            if orig is None:
                assert max(abs(v) for v in x) < mpf("1e-30")
                assert max(abs(a - b) for a, b in zip(t, [-1, 0, 0])) < mpf("1e-30")
            else:
                assert max(abs(a - b) for a, b in zip(x, orig.x)) < mpf("1e-30")
                assert max(abs(a + b) for a, b in zip(t, orig.t)) < mpf("1e-30")
            assert abs(g.tau / r1 - c.tau(s1 - r1 * u)) < mpf("1e-30")


def test_agrees_with_mpmath_odefun():
    """An independent solver (mpmath's Taylor ODE method, generic derivatives) at 18 digits."""
    c = SpaceCurve(-1, 0.5, 0.3, 2, 0.5, 2)
    with mp.workdps(18):
        def rhs(s, y):
            k, tt = c.kappa(s), c.tau(s)
            t, n, b = y[3:6], y[6:9], y[9:12]
            return (list(t) + [k * n[i] for i in range(3)]
                    + [-k * t[i] + tt * b[i] for i in range(3)] + [-tt * n[i] for i in range(3)])
        y0 = [mpf(v) for v in (0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)]
        y = odefun(rhs, 0, y0)(mpf("0.3"))
    f = c.frame_at(mpf("0.3"))
    ref = f.x + f.t + f.n + f.b
    assert max(abs(a - b) for a, b in zip(y, ref)) < mpf("1e-15")


def test_seed_fig3_turning_integrals_at_the_range_ends():
    """Seed 003 Fig. 3: theta at the ends of the rho range, phi at the ends of the mu range
    (type 2 mirrors type 1: phi_2(s) = -phi_1(-s)).  Checked with the closed forms at
    10^-30 and 10^-60 from a finite end or |s| = 10^30 and 10^60."""
    def at(end, d, k):
        return end - d * abs(end) * mpf(10) ** -k if abs(end) != mp.inf else d * mpf(10) ** k

    def behaviour(f, end, d):
        with mp.workdps(90):
            step = f(at(end, d, 60)) - f(at(end, d, 30))  # log divergence: ~ 69 / lam
        if abs(step) < mpf("1e-3"):
            return "Finite"
        assert abs(step) > 10 and step * d > 0
        return "inf" if d > 0 else "-inf"

    fig3a = {-1: ("-inf", "Finite"), 0.5: ("-inf", "Finite"), 1: ("-inf", "inf"),
             2: ("Finite", "inf")}
    for alpha, want in fig3a.items():
        c = SpaceCurve(alpha, 0, 1, 0, 1, 1)
        lo, hi = c.rho_range()
        assert (behaviour(c.theta, lo, -1), behaviour(c.theta, hi, 1)) == want
    fig3b = {-1: ("-inf", "Finite"), 0.5: ("-inf", "Finite"), 1: ("-inf", "inf"),
             2: ("Finite", "inf")}
    fig3c = {-1: ("Finite", "inf"), 0.5: ("Finite", "inf"), 1: ("-inf", "inf"),
             2: ("-inf", "Finite")}
    for kind, table in ((1, fig3b), (2, fig3c)):
        for beta, want in table.items():
            c = SpaceCurve(0, beta, 0, 1, 1, kind)
            lo, hi = c.mu_range()
            assert (behaviour(c.phi, lo, -1), behaviour(c.phi, hi, 1)) == want


def test_classify_basics():
    cls = classify(-1, -1, 1, 1, 1, 1)          # seed row a2: both bounds at s = 1
    assert cls["upper"]["bound"] == "A" and cls["upper"]["binds"] == "both"
    assert cls["upper"]["rho"] == "inf" and cls["upper"]["mu"] == "inf"
    assert cls["lower"]["kappa_over_tau"] == "finite"
    assert not cls["lower"]["tangent_settles"] and not cls["lower"]["binormal_settles"]
    with pytest.raises(ValueError):
        classify(0, 0, 0, 1, 1, 1)


# ---- the committed fixtures -------------------------------------------------------------
def _load(name):
    path = os.path.join(FIXTURES, name)
    if not os.path.exists(path):
        pytest.fail("fixture %s missing: `make fixtures` writes it" % name)
    with open(path) as f:
        return json.load(f)


def test_family_fixture_is_consistent():
    doc = _load("space_family.json")
    cases = doc["cases"]
    assert len(cases) >= 140
    assert doc["max_difference_between_integrations"] < 1e-25
    for case in cases:
        with mp.workdps(20):
            c = SpaceCurve(case["alpha"], case["beta"], case["lambda"], case["omega"],
                           case["nu"], case["type"])
            lo, hi = case["s_range"]
            signs = set()
            for p in case["points"]:
                assert (lo is None or p["s"] > lo) and (hi is None or p["s"] < hi)
                signs.add(p["s"] > 0)
                t, n, b = p["t"], p["n"], p["b"]
                assert abs(dot(t, t) - 1) < 1e-14 and abs(dot(t, n)) < 1e-14
                assert max(abs(u - v) for u, v in zip(cross(t, n), b)) < 1e-14
                assert abs(p["kappa"] - c.kappa(p["s"])) <= 1e-14 * p["kappa"]
                assert abs(p["tau"] - c.tau(p["s"])) <= 1e-14 * p["tau"]
            assert signs == {True, False}


def test_family_fixture_reintegrated():
    doc = _load("space_family.json")
    for case in doc["cases"][5::37]:
        with mp.workdps(25):
            c = SpaceCurve(case["alpha"], case["beta"], case["lambda"], case["omega"],
                           case["nu"], case["type"], c_r=mpf(1) / 6)
            pts = case["points"]
            frames = c.frames([p["s"] for p in pts])
            for p, f in zip(pts, frames):
                scale = max(1, abs(p["s"]))
                for key in ("x", "t", "n", "b"):
                    got = getattr(f, key)
                    assert max(abs(u - v) for u, v in zip(got, p[key])) < 1e-15 * scale


def test_classification_fixture_matches_classify():
    doc = _load("space_classification.json")
    rows = doc["rows"]
    assert [r["row"] for r in rows] == ["a%d" % i for i in range(1, 46)] + \
        ["b%d" % i for i in range(1, 38)]
    for r in rows:
        for chk in r["checks"]:
            p = (chk["alpha"], chk["beta"], chk["lambda"], chk["omega"], chk["nu"])
            with mp.workdps(30):
                cls = classify(*p, r["type"])
            for end in ("lower", "upper"):
                cells = {k: cls[end][k] for k in ("bound", "theta", "phi", "rho", "mu")}
                assert cells == r["expected"][end] == chk[end]["cells"]
                assert cls[end]["tangent_settles"] == chk[end]["tangent_settles"]
                assert cls[end]["binormal_settles"] == chk[end]["binormal_settles"]
                ev = chk[end]["integration_evidence"]["verdict"]
                assert ev["tangent"] == ("settles" if chk[end]["tangent_settles"] else "turns")
                assert ev["binormal"] == ("settles" if chk[end]["binormal_settles"] else "turns")
        # every cell where the seed differs is listed, and nothing else
        listed = {(d["end"], d["cell"]) for d in r["disagreements"] if d["kind"] != "reading"}
        differ = set()
        for end in ("lower", "upper"):
            for key in ("s", "theta", "phi", "rho", "mu"):
                want = r["expected"][end]["bound" if key == "s" else key]
                if r["seed"][end][key] != want:
                    differ.add((end, key))
        assert listed == differ, r["row"]


def test_classification_transcribes_the_seed_text():
    """The 'seed' cells are the cells of seed 003 Figs. 5-6 (data/seed003_figs5_6.txt)."""
    import re
    names = {"$-\\infty$": "-inf", "∞": "inf", "∞ *": "inf*", "$\\infty*$": "inf*",
             "Finite($-\\infty$)": "Finite(-inf)", "Finite(- ∞)": "Finite(-inf)",
             "Finite(∞)": "Finite(inf)", "$-1/(\\Lambda\\alpha)$": "A",
             "$-v^\\beta/(\\Omega\\beta)$": "B", "$v^\\beta/(\\Omega\\beta)$": "B"}
    text = {}
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "data",
                           "seed003_figs5_6.txt"), encoding="utf-8") as f:
        for line in f:
            m = re.match(r"^([ab]\d+)\t", line)
            if m:
                cells = [names.get(c.strip(), c.strip()) for c in line.rstrip("\n").split("\t")[1:]]
                text[m.group(1)] = [c for c in cells if c and not c.startswith(("if", "$\\alpha",
                                                                            "$\\beta", "$0 <"))]
    doc = _load("space_classification.json")
    assert len(text) == 82
    for r in doc["rows"]:
        ours = [r["seed"][end][k] for end in ("lower", "upper")
                for k in ("s", "theta", "phi", "rho", "mu")]
        assert [c for c in ours if c is not None] == text[r["row"]], r["row"]
