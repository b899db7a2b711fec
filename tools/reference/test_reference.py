"""Claims about the 40-digit reference itself (lac_mpmath.py, segment_mpmath.py).

    .venv/bin/python -m pytest tools/reference -q      (from the repo root)
"""

from mpmath import mp, mpf, mpc, arg, expj, gammainc

from lac_mpmath import StandardForm
from segment_mpmath import chord_angle, chord_angle_at_bound, solve_segment

mp.dps = 40
FRACTIONS = [0.0, 0.125, 0.25, 0.5, 0.75, 0.875, 1.0]  # u and 1 - u both exact


def gamma_point_at_bound(alpha, lam, digits):
    """P(theta*) by incomplete gammas with u = 0 exactly, at `digits` working digits."""
    with mp.workdps(digits):
        a, lam = mpf(alpha), mpf(lam)
        k = 1 / (lam * (a - 1))
        g = a / (a - 1)
        mik = mpc(0, -k)
        return k * expj(-k) * mik ** (-g) * (gammainc(g, mik) - gammainc(g, 0))


def test_point_agrees_with_incomplete_gamma_form():
    for alpha, lam, frac in [(-50, 4, "0.999999"), (-3, 0.1, "-0.3"), (-1, 1, "0.999999"),
                             (0, 1, "0.9"), (0.5, 4, "0.999999"), (2, 1, "0.999999"),
                             (3, 0.1, "-0.5"), (50, 4, "0.5")]:
        sf = StandardForm(alpha, lam)
        theta = sf.theta_singular() * mpf(frac)
        p = sf.point(theta)
        assert abs(p - sf.point_gamma(theta)) <= mpf("1e-30") * max(1, abs(p))


def test_largest_chord_angle_agrees_with_incomplete_gamma_form():
    """The piece that runs into the bound, where the integrand is singular at an end."""
    for alpha in [-6, -1, -0.1, -0.01, 1.05, 2, 10]:
        for theta_d in [mpf("0.05"), mpf(1), mpf(3)]:
            lam = 1 / (theta_d * abs(1 - mpf(alpha)))
            p = gamma_point_at_bound(alpha, lam, 300)
            ref = arg(p) if alpha < 1 else arg(-p * expj(theta_d))
            assert abs(chord_angle_at_bound(mpf(alpha), theta_d) - ref) < mpf("1e-30")


def test_limits_alpha_0_alpha_1_lambda_0_are_continuous():
    theta = mpf("0.7")
    for a0, a1, lam0, lam1 in [(0, 1e-12, 1, 1), (0, -1e-12, 1, 1), (1, 1 + 1e-12, 1, 1),
                               (1, 1 - 1e-12, 1, 1), (-1, -1, 0, 1e-15), (2, 2, 0, 1e-15)]:
        p, q = StandardForm(a0, lam0), StandardForm(a1, lam1)
        assert abs(p.point(theta) - q.point(theta)) < 1e-11
        assert abs(p.s_of_theta(theta) - q.s_of_theta(theta)) < 1e-11
        assert abs(p.rho(theta) - q.rho(theta)) < 1e-11


def test_chord_angle_increases_with_lambda_from_half_the_turn():
    theta_d = mpf("1.2")
    for alpha in [-3, -1, 0, 0.5, 1, 2, 10]:
        lam_top = 1 / (theta_d * abs(1 - mpf(alpha))) if alpha != 1 else mpf(50)
        with mp.workdps(20):
            values = [chord_angle(mpf(alpha), lam_top * k / 16, theta_d) for k in range(16)]
        assert abs(values[0] - theta_d / 2) < 1e-18
        assert all(b > a for a, b in zip(values, values[1:])), alpha


def test_reversed_and_mirrored_control_points_give_the_same_curve():
    pa, pb, pc = mpc(-1, 0), mpc("0.3", "0.5"), mpc(1, 0)
    for alpha in [-1, 0.5, 2]:
        r = solve_segment(pa, pb, pc, alpha, FRACTIONS)
        rev = solve_segment(pc, pb, pa, alpha, FRACTIONS)
        mir = solve_segment(pa.conjugate(), pb.conjugate(), pc.conjugate(), alpha, FRACTIONS)
        assert abs(rev["arc_length"] - r["arc_length"]) < 1e-35
        assert abs(rev["curvature_start"] + r["curvature_end"]) < 1e-35
        assert abs(mir["curvature_start"] + r["curvature_start"]) < 1e-35
        for s, t, m in zip(r["samples"], rev["samples"][::-1], mir["samples"]):
            assert abs(mpc(s["x"], s["y"]) - mpc(t["x"], t["y"])) < 1e-35
            assert abs(s["kappa"] + t["kappa"]) < 1e-35
            assert abs(mpc(s["x"], -s["y"]) - mpc(m["x"], m["y"])) < 1e-35
            assert abs(s["theta"] + m["theta"]) < 1e-35
