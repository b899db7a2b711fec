"""Log-aesthetic space curves (docs/math.md §6, seed 003) in mpmath: the 40-digit reference.

The family
----------
A log-aesthetic space curve has a straight logarithmic curvature graph (slope alpha,
parameter lam = Lambda) and a straight logarithmic torsion graph (slope beta, parameter
omega = Omega).  In the standard form (origin, tangent +x, principal normal +y, rho = 1 and
mu = nu at s = 0) the radii of curvature and torsion are

    rho(s) = exp(lam s)                                alpha = 0
           = (lam alpha s + 1)^(1/alpha)               otherwise
    mu(s)  = nu exp(sg omega s)                        beta = 0
           = (sg omega beta s + nu^beta)^(1/beta)      otherwise

with sg = +1 for type 1 (mu increases with s) and sg = -1 for type 2 (mu decreases).
kappa = 1/rho, tau = 1/mu.  They are evaluated as

    ln rho      = lam s L1(lam alpha s),                   L1(x) = ln(1 + x)/x, L1(0) = 1
    ln(mu/nu)   = sg omega s nu^-beta L1(y),              y = sg omega beta s nu^-beta

so alpha = 0, beta = 0, lam = 0 and omega = 0 are ordinary values (no case split), and
everything is continuous across them.  The radicands lam alpha s + 1 and
sg omega beta s + nu^beta must stay positive: each vanishes at most once, at

    s_rho = -1/(lam alpha)          (lower bound if lam alpha > 0, upper if < 0)
    s_mu  = -nu^beta/(sg omega beta) (type 1: -nu^b/(omega b); type 2: +nu^b/(omega b))

and the valid s range is the intersection of the rho-range and the mu-range (seed 003
Fig. 2); an absent bound is +-infinity.

Turning integrals (seed 003 eq. 10), in closed form and continuous in every parameter:

    theta(s) = int_0^s kappa = s L1(lam alpha s) E((alpha - 1) ln rho),  E(x) = expm1(x)/x
    phi(s)   = int_0^s tau   = (s/nu) L1(y) E((beta - 1) ln(mu/nu))

(theta = (rho^(alpha-1) - 1)/(lam (alpha-1)) and phi = (mu^(beta-1) - nu^(beta-1))/
(sg omega (beta-1)) where those are defined.)

The curve: Frenet-Serret
------------------------
    x' = t,   t' = kappa n,   n' = -kappa t + tau b,   b' = -tau n,   ' = d/ds,

from x = 0, t = e1, n = e2, b = e3 at s = 0, in both directions.

Sign of torsion (stated explicitly, as everywhere in this project): the frame is
right-handed, b = t x n, and tau > 0 means the curve leaves its osculating plane toward
+b: x(s) = s t + kappa s^2/2 n + kappa tau s^3/6 b + O(s^4), so for s > 0 the curve rises
toward +b (a right-handed helix for kappa, tau > 0).  Seed 003 uses exactly these equations
(its eq. 8, with b(s0) = t0 x n0 in eq. 9) and takes mu > 0 throughout, so every curve of
the family, type 1 and type 2, has tau > 0: it is right-handed in its standard form.  The
seed's phrase "kappa and -tau are the angular velocities of the tangent and the binormal"
is the same convention (b' = -tau n).  Left-handed curves come from the mirror z -> -z
(the segment method's "mirror z"), which flips the sign of tau.

Integrator (our own): a Taylor-series method on the linear system.  kappa and tau have
exact Taylor coefficients about any s0 (binomial series):

    kappa(s0 + x) = kappa0 (1 + a x)^(-1/alpha),  a = lam alpha / B0,  B0 = lam alpha s0 + 1
    coefficients  c_(j+1) = c_j (P - j a)/(j + 1),  P = -lam / B0      (alpha = 0: a = 0)

(the same for tau with b = sg omega beta / C0, Q = -sg omega / C0, C0 = sg omega beta s0 +
nu^beta), and the Frenet system turns them into the coefficients of x, t, n, b by Cauchy
products.  A step is h = min(c_R R, c_W / sqrt(kappa^2 + tau^2)), R the distance to the
nearest zero of a radicand (the radius of convergence), and each series is summed until
two successive terms are below 10^-dps (else h is halved).  The generators run it with two
different step controls and precisions and require agreement to 1e-25; the tests also check
orthonormality, the helix closed form and the reversal symmetry.  The same code runs in
mpmath's double-precision context (ctx=fp) for the long qualitative runs of the
classification (space_fixtures.py).

Classification (seed 003 Figs. 5-6): classify() derives, from the asymptotics of kappa and
tau at each end, the seed's cells (bound, theta, phi, rho, mu) and the actual behaviour of
the tangent and the binormal.  The latter uses the Darboux vector w = tau t + kappa b:
with chi = atan(tau/kappa), d = w/|w| = sin(chi) t + cos(chi) b obeys |d'| = |chi'|, so d
has a limit when tau/kappa is eventually monotone; t . d = sin(chi) and b . d = cos(chi).
Hence the tangent settles iff int kappa < inf or tau/kappa -> inf, and the binormal settles
iff int tau < inf or kappa/tau -> inf; if both integrals diverge and kappa/tau tends to a
finite nonzero limit, t and b precess about d forever.  (The seed reads "theta infinite"
as "the tangent rotates infinitely", which fails where tau/kappa -> inf.)
"""

import operator

from mpmath import mp

SIGMA = {1: 1, 2: -1}


def _l1(ctx, x):
    """ln(1 + x)/x with the value 1 at x = 0."""
    if x == 0:
        return ctx.mpf(1)
    if x <= -1:
        raise ValueError("outside the valid range (radicand <= 0)")
    return ctx.log1p(x) / x


def _e1(ctx, x):
    """expm1(x)/x with the value 1 at x = 0."""
    if x == 0:
        return ctx.mpf(1)
    return ctx.expm1(x) / x


def _dot_for(ctx):
    if ctx is mp:
        return mp.fdot
    return lambda a, b: sum(map(operator.mul, a, b))


class Frame:
    """Point, Frenet frame, curvature and torsion at arc length s."""

    __slots__ = ("s", "x", "t", "n", "b", "kappa", "tau")

    def __init__(self, s, x, t, n, b, kappa, tau):
        self.s, self.x, self.t, self.n, self.b = s, x, t, n, b
        self.kappa, self.tau = kappa, tau


class SpaceCurve:
    """A log-aesthetic space curve in standard form.

    alpha, beta, nu > 0 and the type (1 or 2) define the family member; lam, omega >= 0 for
    the family (a negative lam is allowed internally: it is the reversed curve).  Numbers are
    converted with ctx.mpf (exact for doubles).  ctx is mpmath's mp (current mp.dps) or fp.
    """

    def __init__(self, alpha, beta, lam, omega, nu, kind, ctx=mp, c_r=None, c_w=None):
        if kind not in SIGMA:
            raise ValueError("type must be 1 or 2")
        self.ctx = ctx
        f = ctx.mpf
        self.alpha, self.beta = f(alpha), f(beta)
        self.lam, self.omega, self.nu = f(lam), f(omega), f(nu)
        if self.nu <= 0:
            raise ValueError("nu must be > 0")
        self.kind = kind
        self.sg = SIGMA[kind]
        self.nu_beta = ctx.power(self.nu, self.beta)
        self.c_rho = self.lam * self.alpha                 # radicand lam alpha s + 1
        self.c_mu = self.sg * self.omega * self.beta       # radicand c_mu s + nu^beta
        self.c_r = f(c_r) if c_r is not None else f(1) / 8
        self.c_w = f(c_w) if c_w is not None else f(2)
        self._dot = _dot_for(ctx)

    # ---- closed forms ---------------------------------------------------------------
    def rho_radicand(self, s):
        return self.c_rho * s + 1

    def mu_radicand(self, s):
        return self.c_mu * s + self.nu_beta

    def s_rho(self):
        """Where lam alpha s + 1 = 0 (None if never)."""
        return None if self.c_rho == 0 else -1 / self.c_rho

    def s_mu(self):
        """Where sg omega beta s + nu^beta = 0 (None if never)."""
        return None if self.c_mu == 0 else -self.nu_beta / self.c_mu

    def rho_range(self):
        inf = self.ctx.inf
        sr = self.s_rho()
        if sr is None:
            return (-inf, inf)
        return (sr, inf) if self.c_rho > 0 else (-inf, sr)

    def mu_range(self):
        inf = self.ctx.inf
        sm = self.s_mu()
        if sm is None:
            return (-inf, inf)
        return (sm, inf) if self.c_mu > 0 else (-inf, sm)

    def s_range(self):
        """The valid open interval of s (endpoints may be +-inf)."""
        (a, b), (c, d) = self.rho_range(), self.mu_range()
        return (max(a, c), min(b, d))

    def in_range(self, s):
        lo, hi = self.s_range()
        return lo < s < hi

    def ln_rho(self, s):
        return self.lam * s * _l1(self.ctx, self.c_rho * s)

    def ln_mu_over_nu(self, s):
        return self.sg * self.omega * s / self.nu_beta * _l1(self.ctx, self.c_mu * s / self.nu_beta)

    def rho(self, s):
        return self.ctx.exp(self.ln_rho(s))

    def mu(self, s):
        return self.nu * self.ctx.exp(self.ln_mu_over_nu(s))

    def kappa(self, s):
        return self.ctx.exp(-self.ln_rho(s))

    def tau(self, s):
        return self.ctx.exp(-self.ln_mu_over_nu(s)) / self.nu

    def theta(self, s):
        """int_0^s kappa (seed 003 eq. 10)."""
        ctx = self.ctx
        return s * _l1(ctx, self.c_rho * s) * _e1(ctx, (self.alpha - 1) * self.ln_rho(s))

    def phi(self, s):
        """int_0^s tau (seed 003 eq. 10)."""
        ctx = self.ctx
        y = self.c_mu * s / self.nu_beta
        return s / self.nu * _l1(ctx, y) * _e1(ctx, (self.beta - 1) * self.ln_mu_over_nu(s))

    # ---- Taylor-series integration of the Frenet-Serret system -----------------------
    def _radius(self, s):
        """Distance from s to the nearest singular point of kappa or tau."""
        r = self.ctx.inf
        for z in (self.s_rho(), self.s_mu()):
            if z is not None:
                r = min(r, abs(s - z))
        return r

    def _step_size(self, s, remaining):
        ctx = self.ctx
        w = ctx.sqrt(self.kappa(s) ** 2 + self.tau(s) ** 2)
        h = min(abs(remaining), self.c_r * self._radius(s), self.c_w / w if w > 0 else ctx.inf)
        return h if remaining > 0 else -h

    def _series(self, s0, state, h, tol, nmax):
        """Taylor coefficients (in sigma, s = s0 + sigma h) of the 12 state components.

        Returns None if the series has not converged to tol within nmax terms."""
        ctx, dot = self.ctx, self._dot
        b0 = self.rho_radicand(s0)
        c0 = self.mu_radicand(s0)
        if b0 <= 0 or c0 <= 0:
            raise ValueError("step starts outside the valid range")
        a, p = self.c_rho / b0, -self.lam / b0
        bb, q = self.c_mu / c0, -self.sg * self.omega / c0
        K = [h * self.kappa(s0)]
        U = [h * self.tau(s0)]
        x, t, n, b = state
        X = [[x[c]] for c in range(3)]
        T = [[t[c]] for c in range(3)]
        N = [[n[c]] for c in range(3)]
        B = [[b[c]] for c in range(3)]
        small = 0
        for k in range(nmax):
            k1 = k + 1
            K.append(K[k] * h * (p - k * a) / k1)
            U.append(U[k] * h * (q - k * bb) / k1)
            Kk, Uk = K[:k1], U[:k1]
            m = 0
            for c in range(3):
                Tc, Nc, Bc = T[c], N[c], B[c]
                tn = dot(Kk, Nc[k::-1]) / k1
                nn = (dot(Uk, Bc[k::-1]) - dot(Kk, Tc[k::-1])) / k1
                bn = -dot(Uk, Nc[k::-1]) / k1
                X[c].append(h * Tc[k] / k1)
                Tc.append(tn)
                Nc.append(nn)
                Bc.append(bn)
                m = max(m, abs(tn), abs(nn), abs(bn))
            small = small + 1 if m < tol else 0
            if small >= 2 and k1 >= 4:
                # the position needs the next coefficient of t as well
                for c in range(3):
                    X[c].append(h * T[c][k1] / (k1 + 1))
                return X, T, N, B
        return None

    @staticmethod
    def _horner(coeffs, sigma):
        acc = coeffs[-1]
        for c in reversed(coeffs[:-1]):
            acc = acc * sigma + c
        return acc

    def _eval(self, series, sigma):
        X, T, N, B = series
        hv = self._horner
        return ([hv(X[c], sigma) for c in range(3)], [hv(T[c], sigma) for c in range(3)],
                [hv(N[c], sigma) for c in range(3)], [hv(B[c], sigma) for c in range(3)])

    def _tolerance(self):
        if self.ctx is mp:
            return mp.mpf(10) ** (-mp.dps), 160
        return 1e-17, 40

    def walk(self, s_target, s0=None, state=None, on_step=None):
        """Integrate from s0 (default 0, standard frame) to s_target; return the final state.

        on_step(s_start, h, evaluate) is called for every step; evaluate(sigma) gives the
        state at s_start + sigma h for sigma in [0, 1] (dense output)."""
        ctx = self.ctx
        if s0 is None:
            s0 = ctx.mpf(0)
        if state is None:
            o, i = ctx.mpf(0), ctx.mpf(1)
            state = ([o, o, o], [i, o, o], [o, i, o], [o, o, i])
        s = s0
        s_target = ctx.mpf(s_target)
        if not (self.in_range(s_target) and self.in_range(s)):
            raise ValueError("s outside the valid range")
        tol, nmax = self._tolerance()
        while s != s_target:
            remaining = s_target - s
            h = self._step_size(s, remaining)
            while True:
                series = self._series(s, state, h, tol, nmax)
                if series is not None:
                    break
                h = h / 2
            if on_step is not None:
                on_step(s, h, lambda sigma, ser=series: self._eval(ser, sigma))
            state = self._eval(series, 1)
            s = s_target if h == remaining else s + h
        return state

    def frame_at(self, s, **kw):
        x, t, n, b = self.walk(s, **kw)
        return Frame(s, x, t, n, b, self.kappa(s), self.tau(s))

    def frames(self, s_values):
        """Frames at every s in s_values, integrating outward from 0 in each direction."""
        ctx = self.ctx
        out = {}
        for sign in (1, -1):
            todo = sorted((ctx.mpf(v) for v in s_values if sign * v > 0), key=abs)
            s, state = ctx.mpf(0), None
            for v in todo:
                state = self.walk(v, s0=s, state=state)
                s = v
                out[v] = Frame(v, *state, self.kappa(v), self.tau(v))
        for v in s_values:
            if v == 0:
                o, i = ctx.mpf(0), ctx.mpf(1)
                out[ctx.mpf(0)] = Frame(ctx.mpf(0), [o, o, o], [i, o, o], [o, i, o], [o, o, i],
                                        self.kappa(0), self.tau(0))
        return [out[ctx.mpf(v)] for v in s_values]

    def reversed_at(self, s1):
        """The same curve traversed backward from s1, as a standard-form curve.

        Returns (curve, scale, rotation, origin): the point u of `curve` is
        origin + scale * rotation . x_curve(u) = x(s1 - scale u) of self, with rotation the
        columns (-t(s1), n(s1), -b(s1)) (to be filled by the caller from a frame) and
        scale = rho(s1).  Parameters: lam' = -lam rho1^(1-alpha), omega' = omega
        rho1^(1-beta), nu' = mu(s1)/rho1, type swapped (mu runs the other way)."""
        ctx = self.ctx
        r1 = self.rho(s1)
        lam = -self.lam * ctx.power(r1, 1 - self.alpha)
        om = self.omega * ctx.power(r1, 1 - self.beta)
        nu = self.mu(s1) / r1
        other = SpaceCurve(self.alpha, self.beta, lam, om, nu, 3 - self.kind, ctx=ctx,
                           c_r=self.c_r, c_w=self.c_w)
        return other, r1


def helix_frame(nu, s, ctx=mp):
    """Closed form for lam = omega = 0 (kappa = 1, tau = 1/nu): rotation about the Darboux axis.

    k = (tau, 0, kappa)/w, w = sqrt(kappa^2 + tau^2); the frame turns about k at rate w:
    R(phi) v = v cos phi + (k x v) sin phi + k (k . v)(1 - cos phi), and
    x(s) = e1 sin(ws)/w + (k x e1)(1 - cos ws)/w + k (k . e1)(s - sin(ws)/w)."""
    f = ctx.mpf
    kap, tau = f(1), 1 / f(nu)
    s = f(s)
    w = ctx.sqrt(kap * kap + tau * tau)
    k = [tau / w, f(0), kap / w]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def rot(v, ang):
        c, sn = ctx.cos(ang), ctx.sin(ang)
        kv = cross(k, v)
        kd = sum(k[i] * v[i] for i in range(3))
        return [v[i] * c + kv[i] * sn + k[i] * kd * (1 - c) for i in range(3)]

    e1, e2, e3 = [f(1), f(0), f(0)], [f(0), f(1), f(0)], [f(0), f(0), f(1)]
    ang = w * s
    ke1 = cross(k, e1)
    x = [e1[i] * ctx.sin(ang) / w + ke1[i] * (1 - ctx.cos(ang)) / w
         + k[i] * k[0] * (s - ctx.sin(ang) / w) for i in range(3)]
    return Frame(s, x, rot(e1, ang), rot(e2, ang), rot(e3, ang), kap, tau)


# ---- classification ------------------------------------------------------------------
# Seed notation for the theta / phi cells: "-inf" / "inf" (the integral diverges at the end),
# "Finite" (converges at the function's own end), "Finite(-inf)" / "Finite(inf)" /
# "Finite(F)" (the end is set by the other function first, so the integral stops at a
# finite value; in parentheses what it would do at its own end).  rho / mu cells: "0",
# "inf" (the limit, with "*" when the length is infinite or the integral diverges -- the
# seed's own convention, see README of the fixture) or "-" (a finite positive value).


class _Behaviour:
    """How kappa (or tau) behaves toward one end: kind in {"cut", "upow", "spow", "exp"}.

    cut: the end is finite and set by the other function: a finite positive value.
    upow: ~ u^p, u = distance to a finite end (its own radicand vanishes there).
    spow: ~ |s|^p as s -> +-inf.      exp: ~ e^(g |s|) as s -> +-inf (g = 0: constant)."""

    def __init__(self, kind, p=0, g=0):
        self.kind, self.p, self.g = kind, p, g

    def blows_up(self):
        if self.kind == "upow":
            return self.p < 0
        if self.kind == "spow":
            return self.p > 0
        if self.kind == "exp":
            return self.g > 0
        return False

    def vanishes(self):
        if self.kind == "upow":
            return self.p > 0
        if self.kind == "spow":
            return self.p < 0
        if self.kind == "exp":
            return self.g < 0
        return False

    def integral_diverges(self):
        if self.kind == "upow":
            return self.p <= -1
        if self.kind == "spow":
            return self.p >= -1
        if self.kind == "exp":
            return self.g >= 0
        return False

    def growth_key(self):
        """Order of growth at an infinite end: exponentials beat powers."""
        return (self.g, 0) if self.kind == "exp" else (0, self.p)


def _behaviour(coef, exponent, rate, direction, end, own):
    """Behaviour of f = radicand^exponent (or e^(rate s) when coef = 0) toward `end`.

    coef: the radicand's slope (0: exponential with `rate`); own: its own zero or None."""
    if end in (mp.inf, -mp.inf):
        if coef == 0:
            return _Behaviour("exp", g=rate * direction)
        return _Behaviour("spow", p=exponent)
    if own is not None and end == own:
        return _Behaviour("upow", p=exponent)
    return _Behaviour("cut")


def _own_end(coef, own, direction):
    """The end f would have by itself in `direction` (its radicand's zero, or +-inf)."""
    if coef != 0 and ((coef > 0 and direction < 0) or (coef < 0 and direction > 0)):
        return own
    return direction * mp.inf


def _ratio_limit(bk, bt, finite_end):
    """Limit of kappa/tau: "0", "inf" or "finite"."""
    if finite_end:
        pk = bk.p if bk.kind == "upow" else 0
        pt = bt.p if bt.kind == "upow" else 0
        if pk == pt:
            return "finite"
        return "inf" if pk < pt else "0"
    kk, kt = bk.growth_key(), bt.growth_key()
    if kk == kt:
        return "finite"
    return "inf" if kk > kt else "0"


def classify(alpha, beta, lam, omega, nu, kind):
    """Behaviour of LASC(alpha, beta, lam, omega, nu, type) at both ends of its s range.

    Works in mpmath at the current precision with exact comparisons (so '=' cases must be
    exactly equal in binary).  Needs lam, omega > 0 (seed 003: with lam or omega = 0 the
    classification does not hold).  Returns {"lower": {...}, "upper": {...}}."""
    a, b = mp.mpf(alpha), mp.mpf(beta)
    lam, omega, nu = mp.mpf(lam), mp.mpf(omega), mp.mpf(nu)
    if lam <= 0 or omega <= 0:
        raise ValueError("classification needs lam > 0 and omega > 0")
    curve = SpaceCurve(a, b, lam, omega, nu, kind)
    lo, hi = curve.s_range()
    s_r, s_m = curve.s_rho(), curve.s_mu()
    sg = SIGMA[kind]
    k_exp = -1 / a if a != 0 else 0       # kappa = radicand^(-1/alpha)
    t_exp = -1 / b if b != 0 else 0
    out = {}
    for name, end, d in (("lower", lo, -1), ("upper", hi, 1)):
        finite = end not in (mp.inf, -mp.inf)
        bk = _behaviour(curve.c_rho, k_exp, -lam, d, end, s_r)
        bt = _behaviour(curve.c_mu, t_exp, -sg * omega, d, end, s_m)
        own_k = _behaviour(curve.c_rho, k_exp, -lam, d, _own_end(curve.c_rho, s_r, d), s_r)
        own_t = _behaviour(curve.c_mu, t_exp, -sg * omega, d, _own_end(curve.c_mu, s_m, d), s_m)
        inf_word = "-inf" if d < 0 else "inf"

        def cell(bh, own):
            if bh.kind != "cut":
                return inf_word if bh.integral_diverges() else "Finite"
            return "Finite(%s)" % (inf_word if own.integral_diverges() else "F")

        theta_div, phi_div = bk.integral_diverges(), bt.integral_diverges()
        ratio = _ratio_limit(bk, bt, finite)
        t_settles = (not theta_div) or ratio == "0"
        b_settles = (not phi_div) or ratio == "inf"

        def radius_cell(bh, star):
            # the radius is 1/f: f blows up -> radius 0, f vanishes -> radius inf
            if bh.kind == "cut":
                return "-"
            v = "0" if bh.blows_up() else ("inf" if bh.vanishes() else "const")
            return v + ("*" if star else "")

        if not finite:
            bound = inf_word
        elif s_r is not None and end == s_r:
            bound = "A"          # -1/(lam alpha); also when both bounds coincide
        else:
            bound = "B"          # the mu bound: type 1 -nu^b/(omega b), type 2 nu^b/(omega b)
        binds = ("none" if not finite else
                 "both" if (s_r is not None and s_m is not None and s_r == s_m) else
                 "rho" if end == s_r else "mu")
        out[name] = {
            "bound": bound,
            "binds": binds,
            "s": end,
            "length_finite": finite,
            "theta": cell(bk, own_k),
            "phi": cell(bt, own_t),
            "rho": radius_cell(bk, (not finite) or theta_div),
            "mu": radius_cell(bt, (not finite) or phi_div),
            "kappa_over_tau": ratio,
            "tangent_settles": t_settles,
            "binormal_settles": b_settles,
            # stars by the actual behaviour: length infinite or the vector keeps turning
            "rho_settle_star": radius_cell(bk, (not finite) or not t_settles),
            "mu_settle_star": radius_cell(bt, (not finite) or not b_settles),
        }
    return out
