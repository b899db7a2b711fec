"""Log-aesthetic curves in mpmath: the standard form II of docs/math.md §2.

LAC(alpha, lam): reference point at the origin with tangent +x, rho = 1 and s = theta = 0.

    rho(theta) = exp(lam theta)                         alpha = 1
               = u^(1/(alpha-1)),  u = (alpha-1) lam theta + 1     otherwise
    s(theta)   = int_0^theta rho,   theta(s) its inverse (closed forms below)
    P(theta)   = int_0^theta rho(psi) e^{i psi} dpsi = C(s) = int_0^s e^{i theta(u)} du

Every closed form is written with expm1/log1p, so alpha near 0 or 1 and lam near 0 lose
no digits; alpha = 0, alpha = 1 and lam = 0 (unit circle) use the limits.

Quadrature (Gauss-Legendre on graded pieces): the only singularity of the theta-form
integrand is where rho = 0 or inf, at theta* = 1/(lam (1 - alpha)); the arc-length
integrand is singular at s* = -1/(lam alpha) (also when theta* is at infinity, e.g. the
rho -> 0 end of alpha = 1).  Pieces are at most 1 rad and 2/lam of turning and no longer
than their distance to the singularity (bisection makes that a geometric grading toward
a nearby end), so each piece is analytic on a neighbourhood of its own size.  A piece
that runs exactly into the bound (lam = lam_max) uses the form whose integrand stays
bounded there, with tanh-sinh.  P is computed in both forms, which must agree; alpha = 1
uses its closed form, checked against both quadratures.
"""

from mpmath import mp, mpf, mpc, exp, expm1, log1p, expj, quad, inf, gammainc

MAX_PIECE = mpf(1)  # radians of turning per quadrature piece


class StandardForm:
    """LAC(alpha, lam) in standard form II; all arguments are mpf (or exact doubles)."""

    def __init__(self, alpha, lam):
        self.alpha = mpf(alpha)
        self.lam = mpf(lam)
        if self.lam < 0:
            raise ValueError("lambda must be >= 0")

    # ---- closed forms -------------------------------------------------------------
    def theta_singular(self):
        """theta where rho hits 0 or inf (None if there is none)."""
        a, lam = self.alpha, self.lam
        if lam == 0 or a == 1:
            return None
        return 1 / (lam * (1 - a))

    def in_range(self, theta):
        ts = self.theta_singular()
        if ts is None:
            return True
        return theta < ts if self.alpha < 1 else theta > ts

    def rho(self, theta):
        a, lam = self.alpha, self.lam
        if lam == 0:
            return mpf(1)
        if a == 1:
            return exp(lam * theta)
        return exp(log1p((a - 1) * lam * theta) / (a - 1))

    def s_of_theta(self, theta):
        a, lam = self.alpha, self.lam
        if lam == 0:
            return mpf(theta)
        if a == 0:
            return -log1p(-lam * theta) / lam
        if a == 1:
            return expm1(lam * theta) / lam
        if theta == self.theta_singular():
            # exactly s*: 1 + (a-1) lam theta rounds to ~1e-40, not 0, and
            # s* - s ~ (theta* - theta)^(a/(a-1)) magnifies that hugely for a near 0
            return self.s_singular()
        return expm1(a / (a - 1) * log1p((a - 1) * lam * theta)) / (lam * a)

    def theta_of_s(self, s):
        a, lam = self.alpha, self.lam
        if lam == 0:
            return mpf(s)
        if a == 0:
            return -expm1(-lam * s) / lam
        if a == 1:
            return log1p(lam * s) / lam
        return expm1((a - 1) / a * log1p(lam * a * s)) / (lam * (a - 1))

    def s_singular(self):
        """s where rho hits 0 or inf (None if there is none or it is at infinity)."""
        if self.lam == 0 or self.alpha == 0:
            return None
        return -1 / (self.lam * self.alpha)

    # ---- points ---------------------------------------------------------------------
    def theta_grid(self, t0, t1):
        """Break points from t0 to t1 (in that order), graded toward theta_singular.
        Pieces are also at most 2/lam long: rho ~ exp(lam theta) near alpha = 1 varies
        by at most e^2 on a piece (the grading alone would allow far more)."""
        max_len = MAX_PIECE if self.lam == 0 else min(MAX_PIECE, 2 / self.lam)
        return graded([t0, t1], self.theta_singular(), max_len)

    def s_grid(self, t0, t1):
        """The theta grid mapped to s, then graded toward s_singular as well: the
        arc-length integrand is singular at s* even when theta* is at infinity."""
        return graded([self.s_of_theta(t) for t in self.theta_grid(t0, t1)],
                      self.s_singular(), inf)

    def point_by_theta(self, t1, t0=0, method="gauss-legendre"):
        """P(t1) - P(t0) by the tangent-angle integral."""
        if t1 == t0:
            return mpc(0)
        f = lambda psi: self.rho(psi) * expj(psi)
        return quad(f, self.theta_grid(t0, t1), method=method)

    def point_by_s(self, t1, t0=0, method="gauss-legendre"):
        """P(t1) - P(t0) by the arc-length integral on the same (mapped) pieces."""
        if t1 == t0:
            return mpc(0)
        return quad(lambda u: expj(self.theta_of_s(u)), self.s_grid(t0, t1), method=method)

    def point(self, t1, t0=0, check=True):
        """P(t1) - P(t0); with check, both forms must agree to 1e-25 (relative).

        An end point may be exactly theta_singular() (the piece runs into the bound):
        then the form with a bounded integrand is used (arc length where rho -> inf,
        tangent angle where rho -> 0) with tanh-sinh, and there is no second form.
        """
        sing = self.theta_singular()
        if sing is not None and sing in (t0, t1):
            if self.alpha < 1:
                return self.point_by_s(t1, t0, method="tanh-sinh")
            return self.point_by_theta(t1, t0, method="tanh-sinh")
        if self.alpha == 1:  # closed form; the quadratures are only checks
            p = self.point_closed_alpha1(t1) - self.point_closed_alpha1(t0)
            if check:
                q = self.point_by_theta(t1, t0)
                assert abs(p - q) <= mpf("1e-25") * max(1, abs(p)), (self.lam, t0, t1, p, q)
        else:
            p = self.point_by_theta(t1, t0)
        if check:
            q = self.point_by_s(t1, t0)
            assert abs(p - q) <= mpf("1e-25") * max(1, abs(p)), (self.alpha, self.lam, t0, t1, p, q)
        return p

    def point_gamma(self, theta):
        """P(theta) by upper incomplete gamma functions (docs/math.md §2), for checks only.

        Needs alpha != 1 and lam > 0; computed with 40 extra digits because it cancels
        badly as alpha -> 1 or lam -> 0.  theta = theta_singular() means u = 0 exactly.
        """
        at_bound = theta == self.theta_singular()
        with mp.extradps(40):
            a, lam = self.alpha, self.lam
            k = 1 / (lam * (a - 1))
            g = a / (a - 1)
            u = 0 if at_bound else (a - 1) * lam * mpf(theta) + 1
            mik = mpc(0, -k)
            p = k * expj(-k) * mik ** (-g) * (gammainc(g, mik) - gammainc(g, mik * u))
        return +p

    def point_closed_alpha1(self, theta):
        """alpha = 1 closed form (exp((lam + i) theta) - 1) / (lam + i)."""
        z = mpc(self.lam, 1)
        return expm1(z * theta) / z


def graded(points, sing, max_len):
    """Refine the monotone break points so that no piece is longer than max_len or than
    its distance to sing (a singularity outside the open pieces, or None).  Pieces that
    touch sing are left to tanh-sinh."""
    out = [mpf(points[0])]
    for p, q in zip(points, points[1:]):
        todo = [(mpf(p), mpf(q))]
        while todo:
            p, q = todo.pop()
            length = abs(q - p)
            dist = inf
            if sing is not None and sing != p and sing != q:
                dist = min(abs(sing - p), abs(sing - q))
            if length > max_len or length > dist:
                m = (p + q) / 2
                todo += [(m, q), (p, m)]
            else:
                out.append(q)
                if len(out) > 100000:
                    raise ValueError("more than 1e5 quadrature pieces")
    return out
