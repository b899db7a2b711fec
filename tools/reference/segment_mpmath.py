"""docs/math.md §3 in mpmath: an LAC segment from control points Pa, Pb, Pc and alpha.

1. theta_d = |turning angle| from Pb - Pa to Pc - Pb; sigma = +1 for a left turn, -1 right.
2. If |Pa Pb| > |Pb Pc| the ends are swapped: A = Pc, C = Pa (else A = Pa, C = Pc).
   A is the sharp end (smallest rho), where the standard-form piece starts.
3. theta_e = angle at A between Pb - A and C - A.
4. Piece of StandardForm(alpha, lam): theta in [0, theta_d] (alpha <= 1) or
   [-theta_d, 0] (alpha > 1); its chord angle at the start (angle from the start tangent
   to the chord) must equal theta_e.  Chord angle = theta_d / 2 at lam = 0 and grows
   with lam up to lam_max = 1 / (theta_d |1 - alpha|) (no bound for alpha = 1).
   Root: scan for a bracket and Illinois at 20 digits, then secant steps at full precision.
5. A similarity (a reflection too when A, Pb, C turn right) maps piece start -> A and
   end -> C; then the piece's tangent intersection lands on Pb (asserted).
Output is in the caller's frame and order: s from the caller's first point, theta the
tangent direction (atan2 of Pb - Pa at s = 0, continuous), kappa signed (+ = left).
"""

from mpmath import mp, mpf, mpc, atan2, arg, expj, fabs, conj

from lac_mpmath import StandardForm


class NotDrawable(Exception):
    """No LAC segment with this alpha fits the control points."""


class IllConditioned(Exception):
    """Drawable in exact arithmetic, but lam is within 1e-12 (relative) of its bound or
    lam theta_d > 1000, or the verdict is within 1e-9 rad of the drawable boundary:
    unfit for a fixture."""


def cross(u, v):
    return u.real * v.imag - u.imag * v.real


def piece_range(alpha, theta_d):
    return (mpf(0), theta_d) if alpha <= 1 else (-theta_d, mpf(0))


def chord_angle(alpha, lam, theta_d, check=False):
    sf = StandardForm(alpha, lam)
    t0, t1 = piece_range(alpha, theta_d)
    return arg(sf.point(t1, t0, check=check) * expj(-t0))


def chord_angle_at_bound(alpha, theta_d):
    """Chord angle of the piece that runs into rho = inf (alpha < 1) or rho = 0 (alpha > 1)."""
    sf = StandardForm(alpha, 1 / (theta_d * fabs(1 - alpha)))
    ts = sf.theta_singular()  # = +-theta_d up to rounding; use it exactly
    t0, t1 = (mpf(0), ts) if alpha < 1 else (ts, mpf(0))
    return arg(sf.point(t1, t0) * expj(-t0))


def bracket_candidates(alpha, theta_d):
    """Increasing trial values of lam: powers of ten, then toward lam_max.  Capped at
    lam theta_d = 1000 (rho changes by e^1000 along the piece for alpha = 1)."""
    cap = 1000 / theta_d
    lam_max = cap if alpha == 1 else 1 / (theta_d * fabs(1 - alpha))
    grow = [mpf(10) ** m for m in range(-2, 20) if mpf(10) ** m <= min(lam_max / 100, cap)]
    near = [lam_max * (1 - mpf(10) ** -k) for k in range(1, 13)] if lam_max <= cap else []
    return grow + near + ([cap] if alpha == 1 else [])


def illinois(f, a, fa, b, fb, tol):
    """Root of increasing f in [a, b], fa < 0 < fb, to |f| < tol or width tol * b."""
    side = 0
    c = a
    for _ in range(400):
        c = (a * fb - b * fa) / (fb - fa)
        fc = f(c)
        if fabs(fc) < tol:
            return c
        if fc > 0:
            b, fb = c, fc
            if side == -1:
                fa /= 2
            side = -1
        else:
            a, fa = c, fc
            if side == 1:
                fb /= 2
            side = 1
        if b - a <= tol * b:
            return c
    raise RuntimeError("Illinois did not converge")


def solve_lambda(alpha, theta_d, theta_e):
    """lam of the standard-form piece whose chord angle is theta_e."""
    f0 = theta_d / 2 - theta_e
    if f0 >= -mpf(10) ** (-mp.dps + 2):
        return mpf(0)  # isosceles: circular arc
    with mp.workdps(20):
        f = lambda lam: chord_angle(alpha, lam, theta_d) - theta_e
        lo, flo, hi = mpf(0), f0, None
        for cand in bracket_candidates(alpha, theta_d):
            fc = f(cand)
            if fc >= 0:
                hi, fhi = cand, fc
                break
            lo, flo = cand, fc
    if hi is None:
        if alpha <= -0.01 or alpha >= 1.01:
            gap = theta_e - chord_angle_at_bound(alpha, theta_d)
            if gap > 1e-9:
                raise NotDrawable("theta_e exceeds the largest chord angle for this alpha")
        raise IllConditioned("lambda within 1e-12 of its bound or lambda theta_d > 1000")
    with mp.workdps(20):
        lam = illinois(f, lo, flo, hi, fhi, mpf("1e-18"))
    # secant steps at full precision from the 20-digit root
    f = lambda lam: chord_angle(alpha, lam, theta_d) - theta_e
    x0, x1 = lam, lam * (1 + mpf("1e-12")) + mpf("1e-30")
    f0, f1 = f(x0), f(x1)
    for _ in range(20):
        if f1 == f0:
            break
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        x0, f0, x1 = x1, f1, x2
        f1 = f(x1)
        if fabs(x1 - x0) <= mpf(10) ** (-mp.dps + 6) * fabs(x1) or f1 == 0:
            break
    assert fabs(f1) < mpf("1e-30"), (alpha, theta_d, theta_e, x1, f1)
    return x1


def solve_segment(pa, pb, pc, alpha, fractions):
    """The segment for control points (complex mpc) and alpha, sampled at arc-length
    fractions of the caller's curve.  Raises NotDrawable / IllConditioned."""
    alpha = mpf(alpha)
    v1, v2 = pb - pa, pc - pb
    if v1 == 0 or v2 == 0:
        raise NotDrawable("coincident control points")
    turn = cross(v1, v2)
    if turn == 0:
        raise NotDrawable("collinear control points")
    sigma = 1 if turn > 0 else -1
    theta_d = fabs(atan2(turn, (conj(v1) * v2).real))
    swapped = abs(v1) > abs(v2)
    a, c = (pc, pa) if swapped else (pa, pc)
    theta_e = fabs(arg((c - a) / (pb - a)))
    lam = solve_lambda(alpha, theta_d, theta_e)

    sf = StandardForm(alpha, lam)
    t_start, t_end = piece_range(alpha, theta_d)
    chord = sf.point(t_end, t_start, check=True)
    reflect = cross(pb - a, c - pb) < 0
    k = (c - a) / (conj(chord) if reflect else chord)
    to_caller = lambda z: a + k * (conj(z) if reflect else z)  # z relative to the start

    # self-check: the piece's tangent intersection lands on Pb
    d0, d1 = expj(t_start), expj(t_end)
    corner = d0 * cross(chord, d1) / cross(d0, d1)
    assert abs(to_caller(corner) - pb) <= mpf("1e-25") * abs(c - a)

    scale = abs(k)
    s_start, s_end = sf.s_of_theta(t_start), sf.s_of_theta(t_end)
    length = scale * (s_end - s_start)
    t_first = t_end if swapped else t_start  # standard theta at the caller's first point
    theta0 = atan2(v1.imag, v1.real)

    def std_theta(u):
        if u == 0 or u == 1:
            return t_start if (u == 0) != swapped else t_end
        s = s_end - u * (s_end - s_start) if swapped else s_start + u * (s_end - s_start)
        return sf.theta_of_s(s)

    thetas = [std_theta(mpf(u)) for u in fractions]
    points, prev, acc = {}, t_start, mpc(0)
    for t in sorted(set(thetas)):
        acc += sf.point(t, prev, check=False)
        points[t], prev = acc, t
    samples = []
    for u, t in zip(fractions, thetas):
        # the ends are the control points exactly (to_caller is checked against them below)
        z = pa if u == 0 else pc if u == 1 else to_caller(points[t])
        samples.append({
            "u": u, "s": mpf(u) * length, "x": z.real, "y": z.imag,
            "theta": theta0 + sigma * fabs(t - t_first),
            "kappa": sigma / (scale * sf.rho(t)),
        })
    assert abs(to_caller(points[t_end]) - c) <= mpf("1e-25") * abs(c - a)
    return {
        "lambda": lam, "theta_d": theta_d, "arc_length": length,
        "curvature_start": sigma / (scale * sf.rho(t_first)),
        "curvature_end": sigma / (scale * sf.rho(t_start if swapped else t_end)),
        "samples": samples,
    }
