//! Rational cubic Bézier curves (seed 001 §4): evaluation, signed curvature and its
//! derivative in arc length, and kurbo's curve traits.
//!
//! With homogeneous control points Qᵢ = (wᵢ bᵢ, wᵢ) the curve is the projection of the
//! polynomial P(t) = Σ Bᵢ³(t) Qᵢ = (p(t), w(t)). Writing V = p′w − p w′ (so x′ = V/w²) and
//! D = det[P, P′, P″] (so det(x′, x″) = D/w³),
//!
//! ```text
//! κ = w³ D / |V|³,        dκ/ds = w⁴ N / |V|⁶,
//! N = (3 w′ D + w D′) |V|² − 3 w D (V·V′),   D′ = det[P, P′, P‴],
//! ```
//!
//! and N is a polynomial of degree 12 in t (the t¹³ terms cancel). `monotone.rs` decides its
//! sign on [0, 1]. Everything here is evaluated relative to b₀, so a curve far from the
//! origin loses no digits to its offset.
//!
//! The derivatives of every order follow from P = (p, w) by Leibniz's rule on p = w·x:
//!
//! ```text
//! x⁽ᵏ⁾ = (p⁽ᵏ⁾ − Σⱼ₌₁³ C(k, j) w⁽ʲ⁾ x⁽ᵏ⁻ʲ⁾) / w,
//! ```
//!
//! with p⁽ᵏ⁾ = 0 for k > 3; [`RationalCubicDerivative`] evaluates them for kurbo.
//!
//! Arc length ([`ParamCurveArclen`]) is adaptive 16-point Gauss–Legendre: an interval is
//! accepted when the rule over it and over its two halves agree within its share of the
//! requested accuracy (the halves' sum, kept, is far more accurate than that difference).

use std::ops::Range;

use kurbo::{
    CubicBez, ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, Point, Vec2,
};

use crate::foundation::error::{finite, Error, Result};
use crate::foundation::gauss::GAUSS_16;
use crate::foundation::numeric::{find_root, length, RootFailure};

/// A rational cubic Bézier curve with positive weights:
///
/// `x(t) = Σ Bᵢ³(t) wᵢ bᵢ / Σ Bᵢ³(t) wᵢ`, t ∈ [0, 1], Bᵢ³ the Bernstein polynomials.
///
/// Equal weights give the ordinary (polynomial) cubic Bézier curve; scaling all weights by
/// the same factor does not change the curve.
///
/// The point at t comes from kurbo's [`ParamCurve::eval`]; the curve also has kurbo's
/// [`ParamCurveDeriv`], [`ParamCurveArclen`] and [`ParamCurveCurvature`]. Every method that
/// takes a parameter clamps it to [0, 1] (outside, w(t) may vanish and the curve has a
/// pole), and a NaN parameter gives NaN. Beware of the sign of curvature:
/// [`signed_curvature`](Self::signed_curvature) is positive for a left turn (docs/math.md §1), as
/// everywhere in this crate, while [`ParamCurveCurvature::curvature`] follows kurbo and is
/// positive for a right turn. A curve made by [`new`](Self::new) has finite coordinates and
/// positive weights, and so has every subsegment of it, but for one at a NaN parameter, which
/// is all NaN.
///
/// ```
/// use kurbo::{ParamCurve, Point};
/// use lac::RationalCubic;
///
/// // A quarter circle of radius 1: the degree-elevated conic with weights 1, √2/2, 1.
/// let c = std::f64::consts::FRAC_1_SQRT_2;
/// let w = (2.0 * c + 1.0) / 3.0;
/// let arc = RationalCubic::new(
///     [
///         Point::new(1.0, 0.0),
///         Point::new(1.0, 2.0 * c / (1.0 + 2.0 * c)),
///         Point::new(2.0 * c / (1.0 + 2.0 * c), 1.0),
///         Point::new(0.0, 1.0),
///     ],
///     [1.0, w, w, 1.0],
/// )?;
/// assert!((arc.signed_curvature(0.3) - 1.0).abs() < 1e-14);
/// assert!((arc.eval(0.7).to_vec2().hypot() - 1.0).abs() < 1e-15);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RationalCubic {
    points: [Point; 4],
    weights: [f64; 4],
}

/// A homogeneous point (x·w, y·w, w).
pub(crate) type Hom = [f64; 3];

/// P, P′, P″, P‴ at one parameter, relative to b₀.
#[derive(Clone, Copy, Debug)]
pub(crate) struct HomJet {
    pub(crate) p: Hom,
    pub(crate) d1: Hom,
    pub(crate) d2: Hom,
    pub(crate) d3: Hom,
}

impl RationalCubic {
    /// The curve with control points `points = [b0, b1, b2, b3]` and `weights`.
    ///
    /// Errors: a non-finite coordinate or weight ([`Error::NonFinite`]); a weight that is not
    /// positive ([`Error::OutOfRange`]).
    pub fn new(points: [Point; 4], weights: [f64; 4]) -> Result<Self> {
        for p in &points {
            finite("a control point coordinate", p.x)?;
            finite("a control point coordinate", p.y)?;
        }
        for &w in &weights {
            finite("a weight", w)?;
            if w <= 0.0 {
                return Err(Error::OutOfRange {
                    name: "weight",
                    value: w,
                    expected: "weights must be positive",
                });
            }
        }
        Ok(RationalCubic { points, weights })
    }

    /// The polynomial cubic Bézier curve `c` (all weights 1).
    pub fn from_cubic(c: CubicBez) -> Result<Self> {
        Self::new([c.p0, c.p1, c.p2, c.p3], [1.0; 4])
    }

    /// The control points `[b0, b1, b2, b3]`.
    pub fn points(&self) -> [Point; 4] {
        self.points
    }

    /// The weights `[w0, w1, w2, w3]`.
    pub fn weights(&self) -> [f64; 4] {
        self.weights
    }

    /// The same curve as a polynomial cubic, when all weights are equal.
    pub fn to_cubic(&self) -> Option<CubicBez> {
        let w = self.weights;
        (w[1] == w[0] && w[2] == w[0] && w[3] == w[0]).then(|| {
            let [p0, p1, p2, p3] = self.points;
            CubicBez::new(p0, p1, p2, p3)
        })
    }

    /// Homogeneous control points relative to b₀.
    pub(crate) fn homogeneous(&self) -> [Hom; 4] {
        let b0 = self.points[0];
        std::array::from_fn(|i| {
            let (d, w) = (self.points[i] - b0, self.weights[i]);
            [w * d.x, w * d.y, w]
        })
    }

    /// P and its derivatives at `t` (relative to b₀).
    pub(crate) fn jet(&self, t: f64) -> HomJet {
        hom_jet(&self.homogeneous(), t)
    }

    /// The derivative dx/dt at `t`.
    pub fn derivative(&self, t: f64) -> Vec2 {
        let j = self.jet(t.clamp(0.0, 1.0));
        let w = j.p[2];
        let v = hodograph(&j);
        Vec2::new(v[0], v[1]) / (w * w)
    }

    /// Signed curvature κ at `t`, positive where the curve turns left (docs/math.md §1; kurbo's
    /// [`ParamCurveCurvature::curvature`] is its negative).
    pub fn signed_curvature(&self, t: f64) -> f64 {
        let (j, size) = self.unit_jet(t.clamp(0.0, 1.0));
        let v = hodograph(&j);
        let speed = v[0].hypot(v[1]);
        j.p[2].powi(3) * det3(&j.p, &j.d1, &j.d2) / (speed * speed * speed) / size
    }

    /// The jet of the curve scaled (exactly, by a power of two) to size about 1, and that
    /// size: the cubes and sixth powers of curvature formulas neither underflow nor overflow
    /// for curves of size 1e-100 or 1e100.
    fn unit_jet(&self, t: f64) -> (HomJet, f64) {
        let b0 = self.points[0];
        let extent = self.points.iter().fold(0.0f64, |m, p| {
            m.max((p.x - b0.x).abs()).max((p.y - b0.y).abs())
        });
        let size = if extent > 0.0 && extent.is_finite() {
            2f64.powi(extent.log2().floor() as i32)
        } else {
            1.0
        };
        let q: [Hom; 4] = std::array::from_fn(|i| {
            let (d, w) = ((self.points[i] - b0) / size, self.weights[i]);
            [w * d.x, w * d.y, w]
        });
        (hom_jet(&q, t), size)
    }

    /// dκ/ds, the derivative of the signed curvature in arc length, at `t`.
    pub fn curvature_derivative(&self, t: f64) -> f64 {
        let (j, size) = self.unit_jet(t.clamp(0.0, 1.0));
        let v = hodograph(&j);
        let vv = v[0] * v[0] + v[1] * v[1];
        let w = j.p[2];
        (w * w) * (w * w) * numerator(&j) / (vv * vv * vv) / (size * size)
    }

    /// Arc length from t = 0 to t = 1 (16-point Gauss–Legendre on 8 panels; relative error
    /// below 1e-14 unless the speed varies by orders of magnitude).
    pub fn arc_length(&self) -> f64 {
        self.arc_length_between(0.0, 1.0)
    }

    /// Arc length from `t0` to `t1` (each clamped to [0, 1]; negative when `t1 < t0`), by
    /// the same fixed rule; [`ParamCurveArclen::arclen`] takes an accuracy instead.
    pub fn arc_length_between(&self, t0: f64, t1: f64) -> f64 {
        let (t0, t1) = (t0.clamp(0.0, 1.0), t1.clamp(0.0, 1.0));
        let h = (t1 - t0) / PANELS as f64;
        let mut sum = 0.0;
        for k in 0..PANELS {
            let mid = t0 + (k as f64 + 0.5) * h;
            for &(x, w) in GAUSS_16.iter() {
                let dx = 0.5 * h * x;
                sum += w * (length(self.derivative(mid - dx)) + length(self.derivative(mid + dx)));
            }
        }
        0.5 * h * sum
    }

    /// x⁽ᵏ⁾(t) for `order` k ≥ 1, by Leibniz's rule on p = w·x (module documentation);
    /// `t` is clamped to [0, 1].
    pub(crate) fn nth_derivative(&self, t: f64, order: u32) -> Vec2 {
        let j = self.jet(t.clamp(0.0, 1.0));
        let p = [j.p, j.d1, j.d2, j.d3].map(|h| Vec2::new(h[0], h[1]));
        let w = [j.p[2], j.d1[2], j.d2[2], j.d3[2]];
        // x⁽ᵏ⁻³⁾, x⁽ᵏ⁻²⁾, x⁽ᵏ⁻¹⁾ in x[1..4] before step k (zero below order 0).
        let mut x = [Vec2::ZERO, Vec2::ZERO, Vec2::ZERO, p[0] / w[0]];
        for k in 1..=order {
            let pk = if k <= 3 { p[k as usize] } else { Vec2::ZERO };
            let kf = f64::from(k);
            // C(k, 1), C(k, 2), C(k, 3), zero where k is smaller.
            let binomial = [
                kf,
                kf * (kf - 1.0) / 2.0,
                kf * (kf - 1.0) * (kf - 2.0) / 6.0,
            ];
            let mut sum = pk;
            for i in 1..=3 {
                sum -= binomial[i - 1] * w[i] * x[4 - i];
            }
            x.rotate_left(1);
            x[3] = sum / w[0];
        }
        x[3]
    }

    /// The speed |x′(t)|.
    fn speed(&self, t: f64) -> f64 {
        length(self.derivative(t))
    }

    /// A bound on the speed over [0, 1]: from x′ = V/w² and
    /// V = 3 Σᵢ Σⱼ Bᵢ²(t) Bⱼ³(t) wⱼ (wᵢ₊₁(bᵢ₊₁ − bⱼ) − wᵢ(bᵢ − bⱼ)),
    /// |V| ≤ 6 w(t) w_max D with D the diameter of the control points, so
    /// |x′| ≤ 6 (w_max / w_min) D.
    fn speed_bound(&self) -> f64 {
        let b = self.points;
        let mut diameter = 0.0f64;
        for i in 0..4 {
            for j in i + 1..4 {
                diameter = diameter.max(length(b[j] - b[i]));
            }
        }
        let w = self.weights;
        let (max, min) = (
            w[0].max(w[1]).max(w[2]).max(w[3]),
            w[0].min(w[1]).min(w[2]).min(w[3]),
        );
        6.0 * (max / min) * diameter
    }

    /// Arc length from `t0` to `t1` (in [0, 1]) within `accuracy`, by adaptive
    /// Gauss–Legendre (module documentation).
    pub(crate) fn arclen_between(&self, t0: f64, t1: f64, accuracy: f64) -> f64 {
        let c = power_basis(&self.homogeneous());
        let speed = |t: f64| {
            let j = power_jet(&c, t);
            let v = hodograph(&j);
            v[0].hypot(v[1]) / (j.p[2] * j.p[2])
        };
        let rule = |a: f64, b: f64| {
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            half * GAUSS_16
                .iter()
                .map(|&(x, w)| w * (speed(mid - half * x) + speed(mid + half * x)))
                .sum::<f64>()
        };
        // The speed's features narrow as the weights grow unlike (where the small ones
        // dominate, the point moves through a short span of t): more starting panels.
        let w = self.weights;
        let ratio = w.iter().fold(0.0f64, |m, &x| m.max(x))
            / w.iter().fold(f64::INFINITY, |m, &x| m.min(x));
        // (A NaN ratio, from a curve of NaN, takes the fewest.)
        let panels = (PANELS as f64 * ratio.sqrt()).min(MAX_PANELS as f64) as usize;
        let panels = panels.max(PANELS);
        adaptive(&rule, t0, t1, accuracy.max(0.0), panels)
    }
}

/// Splits of intervals over one arc-length quadrature, at most: a bound on its time (about
/// 1.6 million speed evaluations, some tens of milliseconds) whatever the accuracy asked.
/// Smooth pieces take a few splits and pieces with a sharp peak of speed or a cusp a few
/// hundred.
const MAX_SPLITS: usize = 1 << 14;

/// The intervals [`adaptive`] starts on for equal weights (times the square root of the
/// ratio of the largest weight to the smallest for others), and at most.
const PANELS: usize = 8;
const MAX_PANELS: usize = 1024;

/// The length "to rounding", relative: the least error estimate the quadrature works
/// toward, relative to the whole length (the speeds come from the power basis, a few ulps
/// of its coefficients, which may be far larger than the speed).
const ROUNDING_FLOOR: f64 = 64.0 * f64::EPSILON;

/// One interval of [`adaptive`]: its two halves' estimates and how far their sum is from
/// the estimate over the whole interval (which bounds the error of that whole estimate,
/// and far more than bounds the halves').
struct Interval {
    a: f64,
    b: f64,
    halves: [f64; 2],
    error: f64,
}

impl Interval {
    fn new(rule: &impl Fn(f64, f64) -> f64, a: f64, b: f64, whole: f64) -> Interval {
        let mid = 0.5 * (a + b);
        let halves = [rule(a, mid), rule(mid, b)];
        let error = (halves[0] + halves[1] - whole).abs();
        Interval {
            a,
            b,
            halves,
            error,
        }
    }

    fn value(&self) -> f64 {
        self.halves[0] + self.halves[1]
    }
}

// Ordered by error, for the heap of [`adaptive`] (NaN errors end the search before they
// are compared).
impl PartialEq for Interval {
    fn eq(&self, other: &Self) -> bool {
        self.error.total_cmp(&other.error).is_eq()
    }
}
impl Eq for Interval {}
impl PartialOrd for Interval {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Interval {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.error.total_cmp(&other.error)
    }
}

/// ∫ over [a, b] by `rule`, globally adaptive: the interval with the largest error
/// estimate is split next, until the estimates sum to at most half `tol` or to rounding
/// ([`ROUNDING_FLOOR`] of the whole), or [`MAX_SPLITS`] are spent. Splitting where the
/// error is largest puts the work where the speed has a sharp peak; intervals where the
/// speed's own rounding keeps the two estimates apart are left while larger errors remain
/// (splitting by depth first spent every split there, and a bound on the splits then left
/// a peak elsewhere unresolved: found by comparing lengths at accuracy 1e-3 and 0).
fn adaptive(rule: &impl Fn(f64, f64) -> f64, a: f64, b: f64, tol: f64, panels: usize) -> f64 {
    // Started on `panels` intervals: on too wide a one, the two estimates of a speed with a
    // narrow wiggle can agree, both sampling past it.
    let h = (b - a) / panels as f64;
    let mut heap = std::collections::BinaryHeap::new();
    let (mut value, mut error) = (0.0, 0.0);
    for k in 0..panels {
        let (lo, hi) = (
            a + k as f64 * h,
            if k + 1 == panels {
                b
            } else {
                a + (k + 1) as f64 * h
            },
        );
        let first = Interval::new(rule, lo, hi, rule(lo, hi));
        value += first.value();
        error += first.error;
        heap.push(first);
    }
    for _ in 0..MAX_SPLITS {
        // (A NaN, from a curve of NaN, stops at once.)
        if !(error > 0.5 * tol && error > ROUNDING_FLOOR * value.abs()) {
            break;
        }
        let Some(worst) = heap.pop() else {
            break;
        };
        let mid = 0.5 * (worst.a + worst.b);
        if !(mid > worst.a && mid < worst.b) {
            // Too narrow to split in double precision.
            heap.push(worst);
            break;
        }
        let left = Interval::new(rule, worst.a, mid, worst.halves[0]);
        let right = Interval::new(rule, mid, worst.b, worst.halves[1]);
        value += left.value() + right.value() - worst.value();
        error += left.error + right.error - worst.error;
        heap.push(left);
        heap.push(right);
    }
    // The sum afresh, without the running sum's drift.
    heap.iter().map(Interval::value).sum()
}

/// `x + t (y − x)`, exact at t = 0 and t = 1, and equal to x wherever y = x.
fn lerp(x: f64, y: f64, t: f64) -> f64 {
    if t <= 0.5 {
        x + t * (y - x)
    } else {
        y - (1.0 - t) * (y - x)
    }
}

/// The blossom Q(u₁, u₂, u₃) of the homogeneous cubic with control points `q`: de Casteljau
/// with the parameter uₖ at level k.
fn blossom(q: &[Hom; 4], u: [f64; 3]) -> Hom {
    let mut r = *q;
    for (level, &t) in u.iter().enumerate() {
        for i in 0..3 - level {
            r[i] = std::array::from_fn(|k| lerp(r[i][k], r[i + 1][k], t));
        }
    }
    r[0]
}

impl ParamCurve for RationalCubic {
    /// The point at `t`, clamped to [0, 1]; NaN gives a NaN point.
    fn eval(&self, t: f64) -> Point {
        let j = self.jet(t.clamp(0.0, 1.0));
        self.points[0] + Vec2::new(j.p[0] / j.p[2], j.p[1] / j.p[2])
    }

    /// The piece between `range.start` and `range.end` (each clamped to [0, 1]; reversed
    /// when start > end), itself a rational cubic: the blossoms Q(a,a,a), Q(a,a,b), Q(a,b,b),
    /// Q(b,b,b) of the homogeneous curve, weights rescaled so that the largest is 1. The
    /// parametrisation carries over, `c.subsegment(a..b).eval(u) = c.eval(a + u (b − a))`;
    /// equal weights stay equal, so a piece of a plain cubic is a plain cubic. A NaN end
    /// gives a curve of NaN.
    fn subsegment(&self, range: Range<f64>) -> RationalCubic {
        let (a, b) = (range.start.clamp(0.0, 1.0), range.end.clamp(0.0, 1.0));
        if a.is_nan() || b.is_nan() {
            return RationalCubic {
                points: [Point::new(f64::NAN, f64::NAN); 4],
                weights: [f64::NAN; 4],
            };
        }
        let q = self.homogeneous();
        let r = [[a, a, a], [a, a, b], [a, b, b], [b, b, b]].map(|u| blossom(&q, u));
        let top = r.iter().fold(0.0f64, |m, h| m.max(h[2]));
        let b0 = self.points[0];
        RationalCubic {
            points: r.map(|h| b0 + Vec2::new(h[0] / h[2], h[1] / h[2])),
            weights: r.map(|h| h[2] / top),
        }
    }

    fn start(&self) -> Point {
        self.points[0]
    }

    fn end(&self) -> Point {
        self.points[3]
    }
}

impl ParamCurveDeriv for RationalCubic {
    type DerivResult = RationalCubicDerivative;

    fn deriv(&self) -> RationalCubicDerivative {
        RationalCubicDerivative {
            curve: *self,
            order: 1,
            t0: 0.0,
            t1: 1.0,
            scale: 1.0,
        }
    }
}

impl ParamCurveArclen for RationalCubic {
    /// The arc length within `accuracy` (absolute, in the curve's units), by adaptive
    /// Gauss–Legendre; an accuracy below the rounding of the sum (or not positive) gives the
    /// length to rounding.
    fn arclen(&self, accuracy: f64) -> f64 {
        self.arclen_between(0.0, 1.0, accuracy)
    }

    /// The parameter at arc length `arclen` from the start, such that the arc length to it
    /// is within `accuracy` of `arclen`: Newton on s(t) − `arclen` (s′ = |x′|) inside the
    /// bracket [0, 1], by the crate's root finder. 0 for `arclen` ≤ 0, 1 from the length
    /// on, NaN for NaN.
    fn inv_arclen(&self, arclen: f64, accuracy: f64) -> f64 {
        if arclen.is_nan() {
            return f64::NAN;
        }
        if arclen <= 0.0 {
            return 0.0;
        }
        // Half the accuracy for the lengths, half for the parameter.
        let half = 0.5 * accuracy;
        let total = self.arclen(half);
        if total.is_nan() {
            return f64::NAN;
        }
        if arclen >= total {
            return 1.0;
        }
        let f = |t: f64| {
            (
                self.arclen_between(0.0, t, half) - arclen,
                Some(self.speed(t)),
            )
        };
        let x_tol = half / self.speed_bound();
        let (mut a, mut b) = ((0.0, -arclen), (1.0, total - arclen));
        let mut guess = Some(arclen / total);
        // s(t) is increasing, so the bracket always holds the root; should the iteration cap
        // come first, a restart from the signs alone bisects first, so each restart at least
        // halves the bracket.
        loop {
            match find_root(f, a, b, guess, x_tol, 100) {
                Ok(t) => return t,
                Err(RootFailure::NotConverged { lo, hi }) => {
                    (a, b) = ((lo, -1.0), (hi, 1.0));
                    guess = None;
                }
                Err(RootFailure::NotBracketed) => {
                    unreachable!("s(0) < arclen < s(1) brackets the root")
                }
            }
        }
    }
}

impl ParamCurveCurvature for RationalCubic {
    /// kurbo's signed curvature x″ × x′ / |x′|³, **positive for a right turn**: the negative
    /// of [`RationalCubic::signed_curvature`] (exact, not from the derivative curves).
    fn curvature(&self, t: f64) -> f64 {
        -self.signed_curvature(t)
    }
}

/// The `order`-th derivative of a [`RationalCubic`] x(t), as a curve: what kurbo's
/// [`ParamCurveDeriv::deriv`] returns, a curve whose "points" are the vectors x⁽ᵏ⁾(t).
///
/// The derivative of a rational cubic is not one (x′ = V/w² is a quartic over a sextic),
/// so it has a type of its own. It is exact for every order up to rounding: with
/// P = (p, w) = Σ Bᵢ³(t) (wᵢ bᵢ, wᵢ), Leibniz's rule on p = w·x gives
///
/// ```text
/// x⁽ᵏ⁾ = (p⁽ᵏ⁾ − Σⱼ₌₁³ C(k, j) w⁽ʲ⁾ x⁽ᵏ⁻ʲ⁾) / w,   p⁽ᵏ⁾ = 0 for k > 3;
/// ```
///
/// the rounding grows with the order, slowly for the first and second derivatives that
/// kurbo uses. Its domain is the curve's: the parameter is clamped to [0, 1], and NaN gives
/// NaN. A subsegment keeps the parametrisation,
/// `d.subsegment(a..b).eval(u) = d.eval(a + u (b − a))`, and the derivative of a derivative
/// is taken in its own parameter.
///
/// ```
/// use kurbo::{ParamCurve, ParamCurveDeriv, Point};
/// use lac::RationalCubic;
///
/// let c = RationalCubic::new(
///     [Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(2.0, 1.0), Point::new(3.0, 0.0)],
///     [1.0, 2.0, 0.5, 1.0],
/// )?;
/// let (d1, d2) = (c.deriv(), c.deriv().deriv());
/// assert_eq!(d2.order(), 2);
/// let h = 1e-5;
/// let fd = (c.eval(0.4 + h) - c.eval(0.4 - h)) / (2.0 * h);
/// assert!((d1.eval(0.4).to_vec2() - fd).hypot() < 1e-8);
/// let fd2 = (d1.eval(0.4 + h) - d1.eval(0.4 - h)) / (2.0 * h);
/// assert!((d2.eval(0.4).to_vec2() - fd2).hypot() < 1e-7);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RationalCubicDerivative {
    curve: RationalCubic,
    order: u32,
    /// eval(u) = scale · x⁽ᵏ⁾(t₀ + u (t₁ − t₀)).
    t0: f64,
    t1: f64,
    scale: f64,
}

impl RationalCubicDerivative {
    /// The order k ≥ 1 of the derivative.
    pub fn order(&self) -> u32 {
        self.order
    }
}

impl ParamCurve for RationalCubicDerivative {
    /// x⁽ᵏ⁾ at `u`, clamped to [0, 1] (NaN gives NaN), as a point.
    fn eval(&self, u: f64) -> Point {
        let t = self.t0 + u.clamp(0.0, 1.0) * (self.t1 - self.t0);
        (self.scale * self.curve.nth_derivative(t, self.order)).to_point()
    }

    fn subsegment(&self, range: Range<f64>) -> RationalCubicDerivative {
        let at = |u: f64| self.t0 + u.clamp(0.0, 1.0) * (self.t1 - self.t0);
        RationalCubicDerivative {
            t0: at(range.start),
            t1: at(range.end),
            ..*self
        }
    }
}

impl ParamCurveDeriv for RationalCubicDerivative {
    type DerivResult = RationalCubicDerivative;

    fn deriv(&self) -> RationalCubicDerivative {
        RationalCubicDerivative {
            order: self.order.saturating_add(1),
            scale: self.scale * (self.t1 - self.t0),
            ..*self
        }
    }
}

/// Power-basis coefficients of P(t) = c0 + c1 t + c2 t² + c3 t³ from Bernstein ones.
pub(crate) fn power_basis(q: &[Hom; 4]) -> [Hom; 4] {
    std::array::from_fn(|k| {
        std::array::from_fn(|i| {
            let (a, b, c, d) = (q[0][i], q[1][i], q[2][i], q[3][i]);
            match k {
                0 => a,
                1 => 3.0 * (b - a),
                2 => 3.0 * (c - 2.0 * b + a),
                _ => d - 3.0 * c + 3.0 * b - a,
            }
        })
    })
}

pub(crate) fn hom_jet(q: &[Hom; 4], t: f64) -> HomJet {
    power_jet(&power_basis(q), t)
}

/// P and its derivatives at `t` from the power-basis coefficients `c`.
pub(crate) fn power_jet(c: &[Hom; 4], t: f64) -> HomJet {
    let p = std::array::from_fn(|i| c[0][i] + t * (c[1][i] + t * (c[2][i] + t * c[3][i])));
    let d1 = std::array::from_fn(|i| c[1][i] + t * (2.0 * c[2][i] + 3.0 * t * c[3][i]));
    let d2 = std::array::from_fn(|i| 2.0 * c[2][i] + 6.0 * t * c[3][i]);
    let d3 = std::array::from_fn(|i| 6.0 * c[3][i]);
    HomJet { p, d1, d2, d3 }
}

/// V = p′w − p w′ (x′ = V/w²).
pub(crate) fn hodograph(j: &HomJet) -> [f64; 2] {
    [
        j.d1[0] * j.p[2] - j.p[0] * j.d1[2],
        j.d1[1] * j.p[2] - j.p[1] * j.d1[2],
    ]
}

pub(crate) fn det3(a: &Hom, b: &Hom, c: &Hom) -> f64 {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

/// N = (3w′D + wD′)|V|² − 3wD(V·V′), whose sign is that of dκ/ds.
pub(crate) fn numerator(j: &HomJet) -> f64 {
    let v = hodograph(j);
    let dv = [
        j.d2[0] * j.p[2] - j.p[0] * j.d2[2],
        j.d2[1] * j.p[2] - j.p[1] * j.d2[2],
    ];
    let d = det3(&j.p, &j.d1, &j.d2);
    let dd = det3(&j.p, &j.d1, &j.d3);
    let (w, w1) = (j.p[2], j.d1[2]);
    let vv = v[0] * v[0] + v[1] * v[1];
    (3.0 * w1 * d + w * dd) * vv - 3.0 * w * d * (v[0] * dv[0] + v[1] * dv[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wavy() -> RationalCubic {
        RationalCubic::new(
            [
                Point::new(0.1, -0.3),
                Point::new(1.2, 0.9),
                Point::new(2.5, -0.4),
                Point::new(3.1, 1.7),
            ],
            [1.3, 0.4, 2.2, 0.8],
        )
        .unwrap()
    }

    #[test]
    fn derivatives_agree_with_central_differences() {
        let c = wavy();
        for &t in &[0.05, 0.3, 0.61, 0.97] {
            let h = 1e-5;
            let fd = (c.eval(t + h) - c.eval(t - h)) / (2.0 * h);
            assert!((fd - c.derivative(t)).hypot() < 1e-8 * fd.hypot());
            // dκ/ds = (dκ/dt) / |x′|.
            let dk = (c.signed_curvature(t + h) - c.signed_curvature(t - h)) / (2.0 * h);
            let want = dk / c.derivative(t).hypot();
            let got = c.curvature_derivative(t);
            assert!(
                (got - want).abs() < 1e-6 * want.abs().max(1.0),
                "{got} {want}"
            );
        }
    }

    #[test]
    fn curvature_matches_the_plane_curve_formula() {
        let c = wavy();
        let t = 0.42;
        let h = 1e-4;
        let d1 = c.derivative(t);
        let d2 = (c.derivative(t + h) - c.derivative(t - h)) / (2.0 * h);
        let want = d1.cross(d2) / d1.hypot().powi(3);
        assert!((c.signed_curvature(t) - want).abs() < 1e-7 * want.abs());
    }

    #[test]
    fn arc_length_of_a_quarter_circle() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let w = (2.0 * c + 1.0) / 3.0;
        let k = 2.0 * c / (1.0 + 2.0 * c);
        let arc = RationalCubic::new(
            [
                Point::new(2.0, 0.0),
                Point::new(2.0, 2.0 * k),
                Point::new(2.0 * k, 2.0),
                Point::new(0.0, 2.0),
            ],
            [1.0, w, w, 1.0],
        )
        .unwrap();
        assert!((arc.arc_length() - std::f64::consts::PI).abs() < 1e-14);
    }

    #[test]
    fn weights_must_be_positive_and_finite() {
        let p = [
            Point::ZERO,
            Point::new(1.0, 0.0),
            Point::new(1.0, 1.0),
            Point::new(0.0, 1.0),
        ];
        assert!(matches!(
            RationalCubic::new(p, [1.0, 0.0, 1.0, 1.0]),
            Err(Error::OutOfRange { .. })
        ));
        assert!(matches!(
            RationalCubic::new(p, [1.0, f64::NAN, 1.0, 1.0]),
            Err(Error::NonFinite { .. })
        ));
    }
}
