"""Independent reference for quasi-aesthetic curves (docs/math.md §5, seed 001).

Everything here is written from the mathematics below; only the LAC segment itself is
reused (segment_mpmath.solve_lambda and lac_mpmath.StandardForm, docs/math.md §3).

Rational cubic Bezier
---------------------
Control points b0..b3 (2-D) and weights w0..w3 > 0:

    x(t) = sum B_i(t) w_i b_i / sum B_i(t) w_i,   B_i(t) = C(3, i) t^i (1 - t)^(3 - i).

Homogeneous form P(t) = (X, Y, W) = sum B_i(t) (w_i b_i, w_i); p = (X, Y), x = p / W.

Curvature and its arc-length derivative (signed, + = turning left):

    V  = p' W - p W'                  (x' = V / W^2; degree <= 4, the t^5 terms cancel)
    D  = det[P, P', P'']              (3 x 3, a Wronskian: degree <= 3; <= 2 if all w_i equal)
    det(x', x'') = D / W^3,   |x'| = |V| / W^2,   kappa = W^3 D / |V|^3,
    dkappa/ds = (dkappa/dt) / |x'| = W^4 N / |V|^6,
    N  = (3 W' D + W D') |V|^2 - 3 W D (V . V')          (degree <= 12).

Derivation: det(V, V') = W D (expand V' = p'' W - p W'' and the 3 x 3 determinant along
its W column), hence det(x', x'') = D / W^3; differentiate kappa = W^3 D |V|^-3 and
multiply by W^2 / |V|.  Where the speed |V| is not 0, W > 0 makes sign(dkappa/ds) =
sign(N).  `RationalCubic` also evaluates kappa and dkappa/ds the textbook way, from
x', x'', x''' (seed 001 eq. 5.1), and the tests check that both routes agree.

Exact monotonicity verdict
--------------------------
The float inputs are converted exactly (Fraction(float)), so N has exact rational
coefficients.  N == 0 identically: "constant" (lines, circles).  Otherwise dkappa/ds
changes sign exactly at the roots of odd multiplicity of N in the open interval (0, 1).
The product of N's odd-multiplicity square-free factors (Yun's algorithm) is square-free,
its Sturm sequence counts its distinct roots in (a, b] as V(a) - V(b), and bisection on
dyadic rationals with those counts isolates each root to an interval narrower than
1e-16; its midpoint is reported.  No such root: the sign of N at any non-root of (0, 1)
gives "increasing" (dkappa/ds >= 0) or "decreasing" (<= 0).  Curves whose speed vanishes
somewhere on [0, 1] (a common root of V's components there) are refused.

Tangent-angle correspondence (docs/math.md §5)
---------------------------------------------
An LAC segment from control points (Pa, Pb, Pc) and alpha turns by Theta = theta_d (the
turning of the control polygon, < pi).  L(phi) is its point whose tangent has turned by
phi from the start tangent (standard-form theta = theta_first +- phi, see `LacSegment`).
A chain of rational cubic pieces approximating it starts at Pa with tangent Pb - Pa;
B(phi) is the chain point whose tangent has turned by phi from the chain's start tangent
(the piece whose turning range holds phi, then t by safeguarded Newton on the piece's
turning angle arg(V(t) / V(0))).  With d(phi) = |B(phi) - L(phi)| and l the LAC arc length:

    rms = sqrt((1/Theta) int_0^Theta d(phi)^2 dphi) / l,    max = max_phi d(phi) / l.

The integral is a composite Gauss-Legendre rule: break points at the pieces' turning
ranges and at the LAC's quadrature grid (at most 1 rad, graded toward the curvature
singularity of the standard form), subdivided to at most Theta / 8, GL_NODES nodes each.
L is integrated incrementally between sorted nodes.  The maximum: d at all nodes and
break points, then golden-section refinement of every sampled local maximum within a
factor 2 of the largest.

Seed-001 one-piece fit
----------------------
b0 = Pa, b3 = Pc, b1 = Pa + u (Pb - Pa), b2 = Pc + v (Pb - Pc), w1 = w2 = (2 cos(Theta/2) + 1)/3,
and w0, w3 from the LAC's signed end curvatures (seed 001 eqs. 4.4-4.7):

    kappa0 = (2 w0 w2 / (3 w1^2)) det(b1 - b0, b2 - b1) / |b1 - b0|^3,
    kappa1 = (2 w1 w3 / (3 w2^2)) det(b2 - b1, b3 - b2) / |b3 - b2|^3.

(u, v) minimise the continuous F(u, v) = int_0^Theta d(phi)^2 dphi: a 9 x 9 grid and
Nelder-Mead from its four best points in doubles on a cheap rule (8 nodes per interval),
then Newton on the gradient at full precision with central-difference derivatives of F
on the full rule (nodes fixed, so L is computed once).  The generator checks that a finer
rule moves the optimum by less than 1e-12.

An isosceles triangle is a circular arc: u = v = 2c/(1 + 2c), c = cos(Theta/2), w0 = w3 = 1
(degree elevation of the quadratic arc with weights 1, c, 1).  There F = 0 on a whole curve
of (u, v) (a rational cubic circle need not be a degree-elevated conic: e.g. u = 0.828,
v = 0.293 at Theta = 90 degrees), so the symmetric point is a rule, not an optimum.  Near
an isosceles triangle F is nearly flat along that curve: the Hessian's condition number
grows like 1/Lambda (4e6 for legs 1 : 0.9999, Theta = 90 degrees, alpha = 0), and the
optimum tends to (u, v) = (0.655, 0.513) there, not to the symmetric point: the fit is
discontinuous at isosceles triangles.  A triangle isosceles only up to rounding has F ~ 0
all along the curve and no meaningful optimum.
"""

import bisect
import math
from fractions import Fraction
from math import comb, gcd

from mpmath import mp, mpf, mpc, atan2, cos, conj, fabs, sqrt

from lac_mpmath import StandardForm
from segment_mpmath import NotDrawable, cross, piece_range, solve_lambda

mp.dps = 40
GL_NODES = 24
VERDICTS = ("increasing", "decreasing", "constant", "not_monotone")


# ---- exact polynomials: lists of Fractions, lowest degree first ---------------------------

def trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def padd(p, q):
    n = max(len(p), len(q))
    return trim([(p[i] if i < len(p) else 0) + (q[i] if i < len(q) else 0) for i in range(n)])


def pscale(p, c):
    return trim([c * a for a in p])


def psub(p, q):
    return padd(p, pscale(q, -1))


def pmul(p, q):
    if not p or not q:
        return []
    out = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            out[i + j] += a * b
    return trim(out)


def pderiv(p):
    return trim([i * a for i, a in enumerate(p)][1:])


def peval(p, t):
    acc = 0
    for a in reversed(p):
        acc = acc * t + a
    return acc


def pdivmod(a, b):
    """Quotient and remainder of a / b (b not zero)."""
    a, b = trim(a), trim(b)
    q = [Fraction(0)] * max(len(a) - len(b) + 1, 1)
    while len(a) >= len(b) and a:
        c = a[-1] / b[-1]
        k = len(a) - len(b)
        q[k] = c
        a = trim([a[i] - (c * b[i - k] if i >= k else 0) for i in range(len(a) - 1)])
    return trim(q), a


def pmonic(p):
    return pscale(p, 1 / p[-1]) if p else p


def pgcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, pdivmod(a, b)[1]
    return pmonic(a)


def degree(p):
    return len(trim(p)) - 1  # -1 for the zero polynomial


PRIME = 2 ** 61 - 1


def square_free_mod_prime(p):
    """True if gcd(p mod q, p' mod q) = 1 for the prime q = 2^61 - 1 and q does not divide
    p's leading coefficient; then p (integer coefficients) is square-free over Q, since
    the image of the rational gcd divides the gcd of the images.  False: undecided."""
    q = PRIME
    a = [c % q for c in p]
    if len(a) < 2 or a[-1] == 0:
        return False
    b = [(i * c) % q for i, c in enumerate(a)][1:]
    while b and b[-1] == 0:
        b.pop()
    while b:
        inv = pow(b[-1], q - 2, q)
        while len(a) >= len(b):
            c = a[-1] * inv % q
            k = len(a) - len(b)
            for i in range(len(b)):
                a[i + k] = (a[i + k] - c * b[i]) % q
            while a and a[-1] == 0:
                a.pop()
            if not a:
                break
        a, b = b, a
    return len(a) == 1


def odd_part(p):
    """Product of the square-free factors of odd multiplicity (Yun's algorithm); p itself
    when a modular test proves it square-free (the common case, and much faster)."""
    p = pmonic(trim(p))
    if degree(p) < 1:
        return p
    if square_free_mod_prime(integer_poly(p)):
        return p
    dp = pderiv(p)
    a = pgcd(p, dp)
    b = pdivmod(p, a)[0]
    c = pdivmod(dp, a)[0]
    d = psub(c, pderiv(b))
    out, mult = [Fraction(1)], 1
    while degree(b) >= 1:
        a = pgcd(b, d)
        if mult % 2 == 1:
            out = pmul(out, a)
        b = pdivmod(b, a)[0]
        c = pdivmod(d, a)[0]
        d = psub(c, pderiv(b))
        mult += 1
    return out


def integer_poly(p):
    """A positive multiple of p with coprime integer coefficients."""
    den = 1
    for a in p:
        den = den * a.denominator // gcd(den, a.denominator)
    ints = [int(a * den) for a in p]
    g = 0
    for a in ints:
        g = gcd(g, a)
    return [a // g for a in ints] if g else ints


def sign_at(p, a, k):
    """Sign of the integer polynomial p at the dyadic rational a / 2^k: the sign of
    sum c_i a^i 2^(k (d - i)), by Horner in a with powers of 2^k (all integers)."""
    d = len(p) - 1
    acc = p[d]
    for i in range(d - 1, -1, -1):
        acc = acc * a + (p[i] << (k * (d - i)))
    return (acc > 0) - (acc < 0)


def sturm_chain(p):
    """Sturm sequence of a square-free p as integer polynomials (each member a positive
    multiple of the textbook one, which leaves the sign variations unchanged)."""
    chain = [pmonic(p), pmonic(pderiv(p))]
    while degree(chain[-1]) > 0:
        r = pdivmod(chain[-2], chain[-1])[1]
        if not r:
            break
        chain.append(pscale(r, -1 / abs(r[-1])))
    return [integer_poly(q) for q in chain]


def variations(chain, a, k):
    """Sign variations of the chain at a / 2^k."""
    signs = [s for s in (sign_at(q, a, k) for q in chain) if s]
    return sum(1 for x, y in zip(signs, signs[1:]) if x != y)


def isolate_roots(p, bits=54):
    """Each distinct root of the square-free p in the open interval (0, 1), bracketed to
    (a, b] with b - a = 2^-bits (< 1e-16), as floats (a + b) / 2, increasing.

    Intervals are dyadic (a / 2^k, (a + 1) / 2^k]; Sturm counts split them until each
    holds one root, then bisection on the sign of p (the root is simple)."""
    if degree(p) < 1:
        return []
    chain = sturm_chain(p)
    ip = chain[0]
    at_one = sign_at(ip, 1, 0) == 0
    out = []
    todo = [(0, 0)]  # (a, k): the interval (a / 2^k, (a + 1) / 2^k]
    while todo:
        a, k = todo.pop()
        n = variations(chain, a, k) - variations(chain, a + 1, k)
        if at_one and a + 1 == 1 << k:
            n -= 1  # the root at t = 1 is not in the open interval
        if n == 0:
            continue
        if n > 1:
            todo += [(2 * a + 1, k + 1), (2 * a, k + 1)]
            continue
        s_hi = sign_at(ip, a + 1, k)
        while k < bits:
            if s_hi == 0:  # the right end is the root itself
                break
            m = 2 * a + 1
            s_m = sign_at(ip, m, k + 1)
            if s_m == 0:
                a, k, s_hi = m - 1, k + 1, 0
                break
            a, k = (2 * a, k + 1) if s_m == s_hi else (m, k + 1)
        if s_hi == 0:
            out.append(float(Fraction(a + 1, 1 << k)))
        else:
            out.append(float(Fraction(2 * a + 1, 1 << (k + 1))))
    return sorted(out)


# ---- the rational cubic, exactly ---------------------------------------------------------

def exact(x):
    return x if isinstance(x, Fraction) else Fraction(x)  # Fraction(float) is exact


def bernstein_to_power(c):
    """Power-basis coefficients of sum_i C(3, i) t^i (1 - t)^(3 - i) c_i."""
    out = [Fraction(0)] * 4
    for i, ci in enumerate(c):
        for j in range(3 - i + 1):  # (1 - t)^(3 - i) = sum_j C(3 - i, j) (-t)^j
            out[i + j] += comb(3, i) * comb(3 - i, j) * (-1) ** j * ci
    return out


class ExactCubic:
    """X, Y, W, V, D and N of a rational cubic, with exact Fraction coefficients."""

    def __init__(self, points, weights):
        pts = [(exact(x), exact(y)) for x, y in points]
        ws = [exact(w) for w in weights]
        if any(w <= 0 for w in ws):
            raise ValueError("weights must be positive")
        self.X = bernstein_to_power([w * p[0] for w, p in zip(ws, pts)])
        self.Y = bernstein_to_power([w * p[1] for w, p in zip(ws, pts)])
        self.W = bernstein_to_power(ws)
        X, Y, W = self.X, self.Y, self.W
        X1, Y1, W1 = pderiv(X), pderiv(Y), pderiv(W)
        X2, Y2, W2 = pderiv(X1), pderiv(Y1), pderiv(W1)
        self.Vx = psub(pmul(X1, W), pmul(X, W1))
        self.Vy = psub(pmul(Y1, W), pmul(Y, W1))
        det2 = lambda a, b, c, d: psub(pmul(a, d), pmul(b, c))
        self.D = padd(padd(pmul(W, det2(X1, Y1, X2, Y2)), pscale(pmul(W1, det2(X, Y, X2, Y2)), -1)),
                      pmul(W2, det2(X, Y, X1, Y1)))
        speed2 = padd(pmul(self.Vx, self.Vx), pmul(self.Vy, self.Vy))
        vdv = padd(pmul(self.Vx, pderiv(self.Vx)), pmul(self.Vy, pderiv(self.Vy)))
        D, D1 = self.D, pderiv(self.D)
        self.N = psub(pmul(padd(pscale(pmul(W1, D), 3), pmul(W, D1)), speed2),
                      pscale(pmul(pmul(W, D), vdv), 3))
        assert degree(self.Vx) <= 4 and degree(self.Vy) <= 4
        assert degree(self.D) <= 3 and degree(self.N) <= 12, (degree(self.D), degree(self.N))

    def speed_vanishes(self):
        """True when x'(t) = 0 for some t in [0, 1] (a common root of Vx and Vy)."""
        g = pgcd(self.Vx, self.Vy)
        if not g:  # V identically 0
            return True
        if degree(g) < 1:
            return False
        if peval(g, 0) == 0 or peval(g, 1) == 0:
            return True
        g = pdivmod(g, pgcd(g, pderiv(g)))[0]  # square-free
        return bool(isolate_roots(g, bits=1))

    def sign_changes(self):
        """Parameters in (0, 1) where dkappa/ds changes sign (odd roots of N), as floats."""
        return isolate_roots(odd_part(self.N)) if self.N else []

    def count_sign_changes(self):
        """How many times dkappa/ds changes sign in (0, 1) (Sturm count, no isolation)."""
        p = odd_part(self.N) if self.N else []
        if degree(p) < 1:
            return 0
        chain = sturm_chain(p)
        at_one = sign_at(chain[0], 1, 0) == 0
        return variations(chain, 0, 0) - variations(chain, 1, 0) - at_one

    def end_signs(self):
        """Signs of dkappa/ds at t = 0 and t = 1."""
        sgn = lambda x: (x > 0) - (x < 0)
        return sgn(peval(self.N, 0)), sgn(peval(self.N, 1))

    def verdict(self):
        if not self.N:
            return "constant", []
        changes = self.sign_changes()
        if changes:
            return "not_monotone", changes
        k = 2
        while True:  # N has at most 12 roots: some 1/k is not one of them
            v = peval(self.N, Fraction(1, k))
            if v:
                return ("increasing" if v > 0 else "decreasing"), []
            k += 1


def monotone_verdict(points, weights):
    """(verdict, sign-change parameters) for float (or Fraction) inputs; ValueError if the
    speed vanishes on [0, 1]."""
    c = ExactCubic(points, weights)
    if c.speed_vanishes():
        raise ValueError("the speed |x'| vanishes on [0, 1]")
    return c.verdict()


# ---- the rational cubic in mpmath --------------------------------------------------------

def to_mpf(x):
    if isinstance(x, Fraction):
        return mpf(x.numerator) / x.denominator
    return mpf(x)


def mp_bernstein_to_power(c):
    return [sum(comb(3, i) * comb(3 - i, k - i) * (-1) ** (k - i) * c[i] for i in range(k + 1))
            for k in range(4)]


def poly_derivs(c, t):
    """Value and first three derivatives at t of the cubic with power coefficients c."""
    c0, c1, c2, c3 = c
    return (((c3 * t + c2) * t + c1) * t + c0, (3 * c3 * t + 2 * c2) * t + c1,
            6 * c3 * t + 2 * c2, 6 * c3)


class RationalCubic:
    """A rational cubic Bezier in mpmath at the working precision (inputs taken exactly)."""

    def __init__(self, points, weights):
        self.points = [mpc(to_mpf(x), to_mpf(y)) for x, y in points]
        self.weights = [to_mpf(w) for w in weights]
        hom = [w * b for w, b in zip(self.weights, self.points)]
        self.cz = mp_bernstein_to_power(hom)  # complex X + iY
        self.cw = mp_bernstein_to_power(self.weights)
        self.v0 = self.tangent(mpf(0))[0]

    def homogeneous(self, t):
        """(p, p', p'', p''') as complex numbers and (w, w', w'', w''') at t."""
        return poly_derivs(self.cz, t), poly_derivs(self.cw, t)

    def point(self, t):
        (p, *_), (w, *_) = self.homogeneous(t)
        return p / w

    def derivatives(self, t):
        """x, x', x'', x''' (complex) by Leibniz's rule on p = w x."""
        (p, p1, p2, p3), (w, w1, w2, w3) = self.homogeneous(t)
        x = p / w
        x1 = (p1 - w1 * x) / w
        x2 = (p2 - 2 * w1 * x1 - w2 * x) / w
        x3 = (p3 - 3 * w1 * x2 - 3 * w2 * x1 - w3 * x) / w
        return x, x1, x2, x3

    def kappa(self, t):
        _, x1, x2, _ = self.derivatives(t)
        return cross(x1, x2) / abs(x1) ** 3

    def dkappa_ds(self, t):
        """Seed 001 eq. 5.1: [det(x', x''') |x'|^2 - 3 det(x', x'') (x' . x'')] / |x'|^6."""
        _, x1, x2, x3 = self.derivatives(t)
        sp2 = x1.real ** 2 + x1.imag ** 2
        dot12 = x1.real * x2.real + x1.imag * x2.imag
        return (cross(x1, x3) * sp2 - 3 * cross(x1, x2) * dot12) / sp2 ** 3

    def tangent(self, t):
        """V = p' w - p w' (parallel to x') and V' = p'' w - p w''."""
        (p, p1, p2, _), (w, w1, w2, _) = self.homogeneous(t)
        return p1 * w - p * w1, p2 * w - p * w2

    def turning(self, t, sigma):
        """Tangent turning from t = 0 to t, in the direction sigma (+1 left, -1 right),
        in (-pi, pi]; and its derivative in t."""
        v, dv = self.tangent(t)
        v0 = self.v0
        ang = sigma * atan2(cross(v0, v), (conj(v0) * v).real)
        return ang, sigma * cross(v, dv) / (v.real ** 2 + v.imag ** 2)

    def solve_turning(self, target, sigma, guess=None):
        """t in [0, 1] whose tangent has turned by target; safeguarded Newton assuming the
        turning increases with t (no inflection)."""
        lo, hi = mpf(0), mpf(1)
        t = mpf(guess) if guess is not None else mpf(0.5)
        tol = mpf(10) ** (-mp.dps + 4)
        for _ in range(300):
            f, df = self.turning(t, sigma)
            f -= target
            if f == 0:
                return t
            if f > 0:
                hi = t
            else:
                lo = t
            t_new = t - f / df if df > 0 else (lo + hi) / 2
            if not lo < t_new < hi:
                t_new = (lo + hi) / 2
            if fabs(t_new - t) <= tol or hi - lo <= tol:
                return t_new
            t = t_new
        raise RuntimeError("solve_turning did not converge")


def homogeneous_kappa(cubic, t):
    """kappa = W^3 D / |V|^3 and dkappa/ds = W^4 N / |V|^6 from the exact polynomials."""
    t = exact(t)
    vx, vy = peval(cubic.Vx, t), peval(cubic.Vy, t)
    w, d, n = peval(cubic.W, t), peval(cubic.D, t), peval(cubic.N, t)
    sp2 = to_mpf(vx * vx + vy * vy)
    return to_mpf(w ** 3 * d) / sp2 ** mpf(1.5), to_mpf(w ** 4 * n) / sp2 ** 3


# ---- the LAC segment, parametrised by tangent turning -------------------------------------

def as_complex(p):
    return p if isinstance(p, mpc) else mpc(to_mpf(p[0]), to_mpf(p[1]))


class LacSegment:
    """The LAC segment of docs/math.md §3 for caller points (Pa, Pb, Pc) and alpha, as in
    segment_mpmath.solve_segment (same Lambda and similarity), with points by turning.

    Standard-form piece theta in [t_start, t_end]; the caller's first point is its start
    unless the ends were swapped (|Pa Pb| > |Pb Pc|).  Turning phi from the caller's start
    is standard theta = theta_first + direction * phi."""

    def __init__(self, pa, pb, pc, alpha):
        pa, pb, pc = as_complex(pa), as_complex(pb), as_complex(pc)
        self.alpha = mpf(alpha)
        v1, v2 = pb - pa, pc - pb
        if v1 == 0 or v2 == 0:
            raise NotDrawable("coincident control points")
        turn = cross(v1, v2)
        if turn == 0:
            raise NotDrawable("collinear control points")
        self.sigma = 1 if turn > 0 else -1
        self.theta = fabs(atan2(turn, (conj(v1) * v2).real))  # Theta, total turning
        swapped = abs(v1) > abs(v2)
        a, c = (pc, pa) if swapped else (pa, pc)
        theta_e = fabs(mp.arg((c - a) / (pb - a)))
        self.lam = solve_lambda(self.alpha, self.theta, theta_e)
        self.sf = StandardForm(self.alpha, self.lam)
        self.t_start, self.t_end = piece_range(self.alpha, self.theta)
        chord = self.sf.point(self.t_end, self.t_start, check=True)
        reflect = cross(pb - a, c - pb) < 0
        self.start, self.reflect = a, reflect
        self.k = (c - a) / (conj(chord) if reflect else chord)
        scale = abs(self.k)
        s_of = self.sf.s_of_theta
        self.arc_length = scale * (s_of(self.t_end) - s_of(self.t_start))
        self.theta_first = self.t_end if swapped else self.t_start
        self.direction = -1 if swapped else 1
        self.scale = scale
        self.kappa_start = self.kappa(0)
        self.kappa_end = self.kappa(self.theta)
        self.pa, self.pb, self.pc = pa, pb, pc
        self._cache = [(self.t_start, mpc(0)), (self.t_end, chord)]  # sorted by theta

    def std_theta(self, phi):
        return self.theta_first + self.direction * phi

    def kappa(self, phi):
        """Signed curvature where the tangent has turned by phi."""
        return self.sigma / (self.scale * self.sf.rho(self.std_theta(phi)))

    def _to_caller(self, z):
        return self.start + self.k * (conj(z) if self.reflect else z)

    def point(self, phi):
        """L(phi): P(theta) - P(t_start), integrated from the nearest theta already known."""
        th = self.std_theta(mpf(phi))
        th = min(max(th, self.t_start), self.t_end)
        keys = [c[0] for c in self._cache]
        i = bisect.bisect_left(keys, th)
        if i < len(keys) and keys[i] == th:
            return self._to_caller(self._cache[i][1])
        cands = [j for j in (i - 1, i) if 0 <= j < len(keys)]
        j = min(cands, key=lambda j: fabs(keys[j] - th))
        z = self._cache[j][1] + self.sf.point(th, keys[j], check=False)
        self._cache.insert(i, (th, z))
        return self._to_caller(z)

    def breaks(self):
        """Turning values of the LAC's quadrature grid (graded toward the singularity)."""
        grid = self.sf.theta_grid(self.t_start, self.t_end)
        return sorted(fabs(t - self.theta_first) for t in grid)


# ---- tangent-angle correspondence ---------------------------------------------------------

class Chain:
    """Consecutive rational cubic pieces; piece k covers turning [start_k, start_k + turn_k]
    from the chain's start tangent (sigma: the turning direction)."""

    def __init__(self, pieces, sigma):
        self.pieces = pieces
        self.sigma = sigma
        self.starts, self.turns = [], []
        acc, prev_end = mpf(0), None
        for piece in pieces:
            v0 = piece.tangent(mpf(0))[0]
            v1 = piece.tangent(mpf(1))[0]
            if prev_end is not None:  # a G1 join: at most a rounding-sized kink
                acc += sigma * atan2(cross(prev_end, v0), (conj(prev_end) * v0).real)
            turn = sigma * atan2(cross(v0, v1), (conj(v0) * v1).real)
            self.starts.append(acc)
            self.turns.append(turn)
            acc += turn
            prev_end = v1
        self.total = acc

    def locate(self, phi):
        k = max(0, bisect.bisect_right(self.starts, phi) - 1)
        return k

    def point(self, phi, guess=None):
        k = self.locate(phi)
        local = min(max(phi - self.starts[k], mpf(0)), self.turns[k])
        t = self.pieces[k].solve_turning(local, self.sigma, guess)
        return self.pieces[k].point(t), k, t


_GL = {}


def rule_nodes(a, b, n):
    """n-point Gauss-Legendre nodes and weights on [a, b]."""
    key = (n, mp.prec)
    if key not in _GL:
        xs, ws = mp.gauss_quadrature(n, "legendre")
        _GL[key] = ([xs[i] for i in range(n)], [ws[i] for i in range(n)])
    xs, ws = _GL[key]
    h = (b - a) / 2
    return [a + h * (x + 1) for x in xs], [h * w for w in ws]


def phi_breaks(lac, chain_starts, max_len_fraction=8):
    """Break points of the composite rule on [0, Theta]."""
    theta = lac.theta
    pts = set(lac.breaks()) | {mpf(0), theta}
    pts |= {s for s in chain_starts if 0 < s < theta}
    pts = sorted(pts)
    out = [pts[0]]
    for p, q in zip(pts, pts[1:]):
        m = int(mp.ceil((q - p) * max_len_fraction / theta))
        out += [p + (q - p) * j / m for j in range(1, m)] + [q]
    return out


def correspondence_nodes(lac, chain_starts, n=GL_NODES):
    """(phi, weight) of the composite rule, phi increasing."""
    br = phi_breaks(lac, chain_starts)
    nodes = []
    for p, q in zip(br, br[1:]):
        xs, ws = rule_nodes(p, q, n)
        nodes += list(zip(xs, ws))
    return nodes


def golden_max(f, a, b, tol):
    """Maximum of a unimodal f on [a, b] by golden-section search: (value, argument)."""
    g = (sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    while b - a > tol:
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    return max((fc, c), (fd, d), (f(a), a), (f(b), b))


def correspondence_errors(lac, pieces, n=GL_NODES):
    """rms and max of d(phi) = |B(phi) - L(phi)| over [0, Theta], divided by the LAC arc
    length (docs/math.md §5 with the continuous tangent-angle correspondence).

    pieces: RationalCubic objects in order from the LAC's first point."""
    chain = Chain(pieces, lac.sigma)
    theta = lac.theta
    nodes = correspondence_nodes(lac, chain.starts, n)
    br = phi_breaks(lac, chain.starts)

    def dist(phi):
        b, _, _ = chain.point(phi)
        return abs(b - lac.point(phi))

    integral = mpf(0)
    samples = [(mpf(0), dist(mpf(0)))]
    for phi, w in nodes:
        d = dist(phi)
        integral += w * d * d
        samples.append((phi, d))
    samples += [(p, dist(p)) for p in br[1:]]
    samples.sort(key=lambda s: s[0])
    best = max(d for _, d in samples)
    peaks = [i for i in range(len(samples))
             if samples[i][1] >= best / 2
             and (i == 0 or samples[i][1] >= samples[i - 1][1])
             and (i == len(samples) - 1 or samples[i][1] >= samples[i + 1][1])]
    dmax = best
    for i in peaks:
        a = samples[max(i - 1, 0)][0]
        b = samples[min(i + 1, len(samples) - 1)][0]
        if b > a:
            dmax = max(dmax, golden_max(dist, a, b, theta * mpf("1e-10"))[0])
    rms = sqrt(integral / theta)
    return rms / lac.arc_length, dmax / lac.arc_length


# ---- the seed-001 one-piece fit ----------------------------------------------------------

def seed_construction(lac, u, v):
    """Control points (complex) and weights of the seed-001 piece for (u, v)."""
    pa, pb, pc = lac.pa, lac.pb, lac.pc
    b0, b3 = pa, pc
    b1 = pa + u * (pb - pa)
    b2 = pc + v * (pb - pc)
    w12 = (2 * cos(lac.theta / 2) + 1) / 3
    w0 = lac.kappa_start * (3 * w12 / 2) * abs(b1 - b0) ** 3 / cross(b1 - b0, b2 - b1)
    w3 = lac.kappa_end * (3 * w12 / 2) * abs(b3 - b2) ** 3 / cross(b2 - b1, b3 - b2)
    return [b0, b1, b2, b3], [w0, w12, w12, w3]


def piece_of(points, weights):
    return RationalCubic([(p.real, p.imag) for p in points], weights)


class FitObjective:
    """F(u, v) = int_0^Theta d(phi)^2 dphi on a fixed composite rule (L precomputed)."""

    def __init__(self, lac, n):
        self.lac = lac
        self.nodes = correspondence_nodes(lac, [], n)
        self.targets = [lac.point(phi) for phi, _ in self.nodes]

    def __call__(self, u, v):
        pts, ws = seed_construction(self.lac, u, v)
        if not (ws[0] > 0 and ws[3] > 0):
            return mp.inf
        piece = piece_of(pts, ws)
        total, t = mpf(0), None
        for (phi, w), target in zip(self.nodes, self.targets):
            t = piece.solve_turning(phi, self.lac.sigma, t)
            total += w * abs(piece.point(t) - target) ** 2
        return total


def nelder_mead(f, x0, step, tol, max_iter=400):
    """Minimise f(x, y) from x0 with the downhill simplex; returns (fmin, point)."""
    simplex = [x0, (x0[0] + step, x0[1]), (x0[0], x0[1] + step)]
    vals = [f(*p) for p in simplex]
    for _ in range(max_iter):
        order = sorted(range(3), key=lambda i: vals[i])
        simplex, vals = [simplex[i] for i in order], [vals[i] for i in order]
        if max(abs(simplex[i][j] - simplex[0][j]) for i in (1, 2) for j in (0, 1)) < tol:
            break
        cx = (simplex[0][0] + simplex[1][0]) / 2
        cy = (simplex[0][1] + simplex[1][1]) / 2
        worst = simplex[2]
        refl = (2 * cx - worst[0], 2 * cy - worst[1])
        fr = f(*refl)
        if fr < vals[0]:
            exp_ = (3 * cx - 2 * worst[0], 3 * cy - 2 * worst[1])
            fe = f(*exp_)
            simplex[2], vals[2] = (exp_, fe) if fe < fr else (refl, fr)
        elif fr < vals[1]:
            simplex[2], vals[2] = refl, fr
        else:
            con = ((cx + worst[0]) / 2, (cy + worst[1]) / 2)
            fc = f(*con)
            if fc < vals[2]:
                simplex[2], vals[2] = con, fc
            else:  # shrink toward the best vertex
                for i in (1, 2):
                    simplex[i] = ((simplex[i][0] + simplex[0][0]) / 2,
                                  (simplex[i][1] + simplex[0][1]) / 2)
                    vals[i] = f(*simplex[i])
    i = min(range(3), key=lambda i: vals[i])
    return vals[i], simplex[i]


class FloatObjective:
    """F(u, v) in double precision on a cheap rule: only to find the basin."""

    def __init__(self, objective):
        self.lac = objective.lac
        self.nodes = [(float(phi), float(w)) for phi, w in objective.nodes]
        self.targets = [complex(z) for z in objective.targets]
        self.sigma = objective.lac.sigma

    def __call__(self, u, v):
        if not (0 < u < 1 and 0 < v < 1):
            return math.inf
        pts, ws = seed_construction(self.lac, mpf(u), mpf(v))
        if not (ws[0] > 0 and ws[3] > 0):
            return math.inf
        ws = [float(w) for w in ws]
        hom = [w * complex(b) for w, b in zip(ws, pts)]
        cz = mp_bernstein_to_power(hom)
        cw = mp_bernstein_to_power(ws)
        sigma = self.sigma

        def tangent(t):
            p, p1, p2, _ = poly_derivs(cz, t)
            w, w1, w2, _ = poly_derivs(cw, t)
            return p1 * w - p * w1, p2 * w - p * w2

        v0 = tangent(0.0)[0]
        if v0 == 0 or not all(math.isfinite(w) for w in ws):
            return math.inf
        total, t = 0.0, 0.5
        for (phi, w), target in zip(self.nodes, self.targets):
            lo, hi = 0.0, 1.0
            for _ in range(100):
                tv, dv = tangent(t)
                rel = tv / v0
                f = sigma * math.atan2(rel.imag, rel.real) - phi
                df = sigma * (tv.real * dv.imag - tv.imag * dv.real) / abs(tv) ** 2
                if f > 0:
                    hi = t
                else:
                    lo = t
                t_new = t - f / df if df > 0 else (lo + hi) / 2
                if not lo <= t_new <= hi:
                    t_new = (lo + hi) / 2
                done = abs(t_new - t) < 1e-15
                t = t_new
                if done:
                    break
            p = poly_derivs(cz, t)[0] / poly_derivs(cw, t)[0]
            total += w * abs(p - target) ** 2
        return total


def gradient_hessian(f, u, v, h):
    """Central differences of f at (u, v): (gu, gv), (huu, huv, hvv)."""
    f0 = f(u, v)
    fu1, fu0 = f(u + h, v), f(u - h, v)
    fv1, fv0 = f(u, v + h), f(u, v - h)
    fpp, fpm = f(u + h, v + h), f(u + h, v - h)
    fmp, fmm = f(u - h, v + h), f(u - h, v - h)
    grad = ((fu1 - fu0) / (2 * h), (fv1 - fv0) / (2 * h))
    hess = ((fu1 - 2 * f0 + fu0) / h ** 2, (fpp - fpm - fmp + fmm) / (4 * h ** 2),
            (fv1 - 2 * f0 + fv0) / h ** 2)
    return grad, hess


def newton_step(grad, hess):
    (gu, gv), (huu, huv, hvv) = grad, hess
    det = huu * hvv - huv ** 2
    return -(hvv * gu - huv * gv) / det, -(huu * gv - huv * gu) / det


def newton_minimise(f, u, v, h=mpf("1e-10"), iters=8, tol=mpf("1e-20")):
    """Newton on grad F with central differences (nodes fixed, so f is smooth).
    Returns u, v, the last step and the last Hessian."""
    for _ in range(iters):
        grad, hess = gradient_hessian(f, u, v, h)
        du, dv = newton_step(grad, hess)
        u, v = u + du, v + dv
        if max(fabs(du), fabs(dv)) < tol:
            break
    return u, v, (du, dv), hess


def seed_fit(pa, pb, pc, alpha, n=GL_NODES, log=None):
    """The reference optimum of the seed-001 one-piece fit.

    Returns (lac, u, v, points, weights, info) with mpf u, v, weights and complex points;
    info holds the objective on the full rule ("objective"), the last Newton step and
    Hessian.  An isosceles triangle (Lambda = 0, a circular arc) returns the degree-elevated
    arc u = v = 2c / (1 + 2c): there F = 0 on a whole curve of (u, v) (rational cubic
    circles need not be degree-elevated conics), and the symmetric one is the rule."""
    lac = LacSegment(pa, pb, pc, alpha)
    c = cos(lac.theta / 2)
    circle = 2 * c / (1 + 2 * c)
    fine = FitObjective(lac, n)
    if lac.lam == 0:
        pts, ws = seed_construction(lac, circle, circle)
        return lac, circle, circle, pts, ws, {"objective": fine, "step": (0, 0), "hessian": None}
    f = FloatObjective(FitObjective(lac, 8))  # coarse: grid, then Nelder-Mead, in doubles
    grid = [(f(u, v), (u, v)) for u in [i / 10 for i in range(1, 10)]
            for v in [i / 10 for i in range(1, 10)]]
    grid.append((f(float(circle), float(circle)), (float(circle), float(circle))))
    grid.sort(key=lambda g: g[0])
    best = min(nelder_mead(f, g[1], 0.05, 1e-9) for g in grid[:4])
    u, v, step, hess = newton_minimise(fine, mpf(best[1][0]), mpf(best[1][1]))
    if log:
        log(f"  coarse {best[1]}, last Newton step {mp.nstr(max(fabs(step[0]), fabs(step[1])), 3)}")
    pts, ws = seed_construction(lac, u, v)
    return lac, u, v, pts, ws, {"objective": fine, "step": step, "hessian": hess}
