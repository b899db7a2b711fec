//! Is the curvature of a rational cubic monotone? A decision with a proof (seed 001 §5,
//! with the verdict the right way round: docs/math.md §5).
//!
//! dκ/ds has the sign of the polynomial N(t) of `bezier.rs` (degree 12). We form N in the
//! Bernstein basis from products of the Bernstein forms of P, P′, P″, P‴; the products come
//! out in degree 18, the exact degree elevation of the degree-12 polynomial, whose
//! coefficients bound N at least as tightly as the degree-12 ones. Then, on [0, 1]:
//!
//! * all coefficients ≥ 0 (or all ≤ 0) ⇒ N ≥ 0 (≤ 0) there, by the convex hull property;
//! * the end values (the first and last coefficients) of opposite signs ⇒ N changes sign;
//! * otherwise split at the midpoint (de Casteljau) and look at both halves.
//!
//! Every coefficient is carried with a rigorous bound on its rounding error (a running
//! error bound: |exact − computed| ≤ e, grown at each operation by the worst case of round
//! to nearest, with an absolute term for underflow), and a sign counts only when the bound
//! excludes zero. So "increasing" with `proven` set is a proof about the exact curve the
//! given doubles describe, not a sample check. Where N is within its rounding bound of zero
//! on a whole piece, no amount of splitting helps; such pieces (a circular arc, whose N is
//! identically zero in exact arithmetic, or a double root where N touches zero) are
//! reported as `proven = false`.

use kurbo::{Point, Vec2};

use crate::family::bezier::{numerator, power_basis, power_jet, Hom, RationalCubic};
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::{find_root, RootFailure};

/// How the signed curvature κ of a curve varies with its parameter (docs/math.md §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Monotonicity {
    /// dκ/ds ≥ 0 everywhere (and not identically 0).
    Increasing,
    /// dκ/ds ≤ 0 everywhere (and not identically 0).
    Decreasing,
    /// dκ/ds is zero within rounding everywhere: a circular arc or a straight line.
    Constant,
    /// dκ/ds takes both signs; `t` is a parameter where it changes sign (or where the speed
    /// vanishes, at a cusp, where κ is unbounded).
    NotMonotone {
        /// A parameter in [0, 1] where dκ/ds changes sign.
        t: f64,
    },
}

impl Monotonicity {
    /// The verdict's snake_case name: `increasing`, `decreasing`, `constant`,
    /// `not_monotone`.
    pub fn name(&self) -> &'static str {
        match self {
            Monotonicity::Increasing => "increasing",
            Monotonicity::Decreasing => "decreasing",
            Monotonicity::Constant => "constant",
            Monotonicity::NotMonotone { .. } => "not_monotone",
        }
    }

    /// Is the curvature monotone (increasing, decreasing or constant)?
    pub fn is_monotone(&self) -> bool {
        !matches!(self, Monotonicity::NotMonotone { .. })
    }
}

/// The answer of [`RationalCubic::curvature_monotonicity`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MonotonicityReport {
    /// The verdict.
    pub verdict: Monotonicity,
    /// Whether the verdict is proven for the exact curve the input doubles describe. It is
    /// false only where dκ/ds is within the rounding of the computation of zero on some
    /// part of [0, 1] (always for [`Monotonicity::Constant`]); there the verdict holds up to
    /// a relative variation of the curvature of about 1e-14.
    pub proven: bool,
}

impl RationalCubic {
    /// Decide whether the signed curvature is monotone over t ∈ [0, 1], with a proof (see
    /// [`MonotonicityReport::proven`]).
    ///
    /// Errors: [`Error::CoincidentPoints`] when b0 = b1 or b2 = b3 (the end tangent, and
    /// so the curvature there, is undefined); [`Error::NonFinite`] for the curve of NaN that
    /// a subsegment at a NaN parameter gives.
    ///
    /// ```
    /// use kurbo::{Point, Vec2};
    /// use lac::{Monotonicity, RationalCubic};
    /// let s = RationalCubic::new(
    ///     [Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(2.0, -1.0), Point::new(3.0, 0.0)],
    ///     [1.0; 4],
    /// )?;
    /// let report = s.curvature_monotonicity()?;
    /// assert!(matches!(report.verdict, Monotonicity::NotMonotone { .. }));
    /// assert!(report.proven);
    /// # Ok::<(), lac::Error>(())
    /// ```
    pub fn curvature_monotonicity(&self) -> Result<MonotonicityReport> {
        let b = self.points();
        // Only a subsegment at a NaN parameter makes a curve of NaN.
        for p in &b {
            finite("a control point coordinate", p.x)?;
            finite("a control point coordinate", p.y)?;
        }
        for w in self.weights() {
            finite("a weight", w)?;
        }
        if b[0] == b[1] {
            return Err(Error::CoincidentPoints {
                first: 0,
                second: 1,
            });
        }
        if b[2] == b[3] {
            return Err(Error::CoincidentPoints {
                first: 2,
                second: 3,
            });
        }
        let (q, q_mag) = scaled_homogeneous(b, self.weights())?;
        let (value, magnitude) = (Numerator::new(&q), Numerator::new(&q_mag));
        let report = decide(&Poly::bernstein(&value.n, &magnitude.n), &q);
        if let Some(t) = speed_may_vanish(&Poly::bernstein(&value.speed2, &magnitude.speed2)) {
            // Where the speed may vanish the curvature may be undefined, so monotonicity
            // cannot be proven; a sign change still can: the numerator vanishes with the
            // speed, so two parameters where it has certified opposite signs are two
            // regular points where dκ/ds has those signs.
            if !(report.proven && matches!(report.verdict, Monotonicity::NotMonotone { .. })) {
                return Ok(MonotonicityReport {
                    verdict: Monotonicity::NotMonotone { t },
                    proven: false,
                });
            }
        }
        Ok(report)
    }
}

/// Arithmetic the numerator is formed in: plain doubles for the values, and [`Mag`] for
/// the same expression with every term made non-negative, which bounds the rounding.
trait Ring: Copy + Default {
    fn add(self, o: Self) -> Self;
    fn sub(self, o: Self) -> Self;
    fn mul(self, o: Self) -> Self;
    fn scale(self, k: f64) -> Self;
}

impl Ring for f64 {
    fn add(self, o: Self) -> Self {
        self + o
    }
    fn sub(self, o: Self) -> Self {
        self - o
    }
    fn mul(self, o: Self) -> Self {
        self * o
    }
    fn scale(self, k: f64) -> Self {
        self * k
    }
}

/// |x| through an expression: subtraction adds magnitudes.
#[derive(Clone, Copy, Debug, Default)]
struct Mag(f64);

impl Ring for Mag {
    fn add(self, o: Self) -> Self {
        Mag(self.0 + o.0)
    }
    fn sub(self, o: Self) -> Self {
        Mag(self.0 + o.0)
    }
    fn mul(self, o: Self) -> Self {
        Mag(self.0 * o.0)
    }
    fn scale(self, k: f64) -> Self {
        Mag(self.0 * k.abs())
    }
}

/// 2u: the unit roundoff of round to nearest is 2⁻⁵³.
const TWO_U: f64 = f64::EPSILON;
/// Grows a computed error bound past the rounding of its own computation (≤ 7 roundings).
const GROW: f64 = 1.0 + 4.0 * f64::EPSILON;
/// Absolute error a result may carry after underflow.
const ETA: f64 = 1e-290;

/// Rounding of the numerator's coefficients relative to their magnitudes. Every
/// coefficient of N (after the division by the binomial) is a sum of products that went
/// through at most K = 31 roundings (counted along `Numerator::new`), so
/// |computed − exact| ≤ γ_K · (the same sum of |products|) with γ_K = Ku/(1 − Ku), and the
/// computed magnitude falls short of the exact one by at most a factor (1 − u)^K. 64u
/// covers both with a factor of two to spare; |V|² (K = 16) uses the same bound.
const NUMERATOR_ROUNDING: f64 = 32.0 * f64::EPSILON;

/// A computed value and a bound on its error: |exact − v| ≤ e.
#[derive(Clone, Copy, Debug, Default)]
struct Bounded {
    v: f64,
    e: f64,
}

impl Bounded {
    fn lo(self) -> f64 {
        self.v - self.e
    }

    fn hi(self) -> f64 {
        self.v + self.e
    }

    /// (a + b)/2 with its rounding: halving is exact but for underflow.
    fn mid(self, o: Self) -> Self {
        let v = self.v + o.v;
        Bounded {
            v: 0.5 * v,
            e: 0.5 * ((self.e + o.e + TWO_U * v.abs()) * GROW) + ETA,
        }
    }
}

/// Highest degree formed: N = A·|V|² − 3wD·(V·V′) comes out in degree 18.
const MAX_DEGREE: usize = 18;

/// A polynomial Σ cₖ tᵏ (1 − t)ⁿ⁻ᵏ: the Bernstein form with the binomials folded into the
/// coefficients, so that products are plain convolutions.
#[derive(Clone, Copy, Debug)]
struct Poly<T> {
    c: [T; MAX_DEGREE + 1],
    n: usize,
}

impl<T: Ring> Poly<T> {
    fn new(coefficients: &[T]) -> Self {
        let mut c = [T::default(); MAX_DEGREE + 1];
        c[..coefficients.len()].copy_from_slice(coefficients);
        Poly {
            c,
            n: coefficients.len() - 1,
        }
    }

    fn mul(&self, o: &Self) -> Self {
        let n = self.n + o.n;
        debug_assert!(n <= MAX_DEGREE);
        let mut c = [T::default(); MAX_DEGREE + 1];
        for (i, a) in self.c[..=self.n].iter().enumerate() {
            for (j, b) in o.c[..=o.n].iter().enumerate() {
                let p = a.mul(*b);
                // The first term of cᵢ₊ⱼ is the one with i = 0 or j = o.n.
                c[i + j] = if i == 0 || j == o.n {
                    p
                } else {
                    c[i + j].add(p)
                };
            }
        }
        Poly { c, n }
    }

    fn add(&self, o: &Self) -> Self {
        debug_assert_eq!(self.n, o.n);
        let mut out = *self;
        for k in 0..=self.n {
            out.c[k] = self.c[k].add(o.c[k]);
        }
        out
    }

    fn sub(&self, o: &Self) -> Self {
        debug_assert_eq!(self.n, o.n);
        let mut out = *self;
        for k in 0..=self.n {
            out.c[k] = self.c[k].sub(o.c[k]);
        }
        out
    }

    fn scale(&self, k: f64) -> Self {
        let mut out = *self;
        for c in &mut out.c[..=self.n] {
            *c = c.scale(k);
        }
        out
    }
}

impl Poly<Bounded> {
    /// Ordinary Bernstein coefficients cₖ / C(n, k) of `value`, with error bounds from
    /// `magnitude` (the same polynomial formed in [`Mag`]).
    fn bernstein(value: &Poly<f64>, magnitude: &Poly<Mag>) -> Self {
        let n = value.n;
        let mut c = [Bounded::default(); MAX_DEGREE + 1];
        let mut binomial = 1.0;
        for (k, ck) in c[..=n].iter_mut().enumerate() {
            *ck = Bounded {
                v: value.c[k] / binomial,
                e: NUMERATOR_ROUNDING * magnitude.c[k].0 / binomial + ETA,
            };
            binomial = binomial * (n - k) as f64 / (k + 1) as f64;
        }
        Poly { c, n }
    }

    /// The two halves, by de Casteljau at t = 1/2.
    fn split(&self) -> (Self, Self) {
        let n = self.n;
        let mut work = self.c;
        let (mut left, mut right) = (*self, *self);
        for r in 1..=n {
            for k in 0..=n - r {
                work[k] = work[k].mid(work[k + 1]);
            }
            left.c[r] = work[0];
            right.c[n - r] = work[n - r];
        }
        (left, right)
    }

    fn coefficients(&self) -> &[Bounded] {
        &self.c[..=self.n]
    }
}

/// The homogeneous control points relative to b₀, scaled by powers of two (exact) so that
/// coordinates and weights are at most 1 in magnitude, as values and as magnitudes; the
/// rounding of b − b₀ is the first of the K roundings.
/// Four homogeneous control points.
type Homogeneous<T> = [[T; 3]; 4];

fn scaled_homogeneous(b: [Point; 4], w: [f64; 4]) -> Result<(Homogeneous<f64>, Homogeneous<Mag>)> {
    let d: [Vec2; 4] = std::array::from_fn(|i| b[i] - b[0]);
    let size = d
        .iter()
        .fold(0.0f64, |m, v| m.max(v.x.abs()).max(v.y.abs()));
    if !size.is_finite() {
        return Err(Error::OutOfRange {
            name: "control point coordinate",
            value: size,
            expected: "control points closer together than about 1e308",
        });
    }
    let ks = power_of_two_below(size);
    let kw = power_of_two_below(w[0].max(w[1]).max(w[2]).max(w[3]));
    let q: Homogeneous<f64> = std::array::from_fn(|i| {
        let wi = w[i] * kw;
        [d[i].x * ks * wi, d[i].y * ks * wi, wi]
    });
    Ok((q, q.map(|r| r.map(|x| Mag(x.abs())))))
}

/// 2^−k with 2^(k−1) ≤ x < 2^k (1 for x = 0), limited to stay finite.
fn power_of_two_below(x: f64) -> f64 {
    if x == 0.0 {
        return 1.0;
    }
    let k = (x.log2().floor() as i32 + 1).clamp(-1000, 1000);
    2f64.powi(-k)
}

/// The polynomials of the test, in scaled Bernstein form.
struct Numerator<T> {
    /// |V|², degree 10: the squared speed times w⁴.
    speed2: Poly<T>,
    /// N, degree 18.
    n: Poly<T>,
}

impl<T: Ring> Numerator<T> {
    fn new(q: &[[T; 3]; 4]) -> Self {
        // P = Σ C(3,i) Qᵢ tⁱ(1−t)³⁻ⁱ; P′ = 3 Σ C(2,i) ΔQᵢ …; P″ = 6 Σ Δ²Qᵢ …; P‴ = 6 Δ³Q₀.
        let d1 = |i: usize, k: usize| q[k + 1][i].sub(q[k][i]);
        let d2 = |i: usize, k: usize| d1(i, k + 1).sub(d1(i, k));
        let p: [Poly<T>; 3] = std::array::from_fn(|i| {
            Poly::new(&[q[0][i], q[1][i].scale(3.0), q[2][i].scale(3.0), q[3][i]])
        });
        let p1: [Poly<T>; 3] = std::array::from_fn(|i| {
            Poly::new(&[
                d1(i, 0).scale(3.0),
                d1(i, 1).scale(6.0),
                d1(i, 2).scale(3.0),
            ])
        });
        let p2: [Poly<T>; 3] =
            std::array::from_fn(|i| Poly::new(&[d2(i, 0).scale(6.0), d2(i, 1).scale(6.0)]));
        let p3: [Poly<T>; 3] =
            std::array::from_fn(|i| Poly::new(&[d2(i, 1).sub(d2(i, 0)).scale(6.0)]));
        const W: usize = 2;
        let v = [0, 1].map(|i| p1[i].mul(&p[W]).sub(&p[i].mul(&p1[W])));
        let dv = [0, 1].map(|i| p2[i].mul(&p[W]).sub(&p[i].mul(&p2[W])));
        let d = det3(&p, &p1, &p2);
        let dd = det3(&p, &p1, &p3);
        let a = p1[W].mul(&d).scale(3.0).add(&p[W].mul(&dd));
        let speed2 = v[0].mul(&v[0]).add(&v[1].mul(&v[1]));
        let v_dv = v[0].mul(&dv[0]).add(&v[1].mul(&dv[1]));
        let n = a.mul(&speed2).sub(&p[W].mul(&d).scale(3.0).mul(&v_dv));
        Numerator { speed2, n }
    }
}

fn det3<T: Ring>(a: &[Poly<T>; 3], b: &[Poly<T>; 3], c: &[Poly<T>; 3]) -> Poly<T> {
    let minor = |i: usize, j: usize| b[i].mul(&c[j]).sub(&b[j].mul(&c[i]));
    a[0].mul(&minor(1, 2))
        .sub(&a[1].mul(&minor(0, 2)))
        .add(&a[2].mul(&minor(0, 1)))
}

/// Splitting stops at intervals this narrow …
const MIN_WIDTH: f64 = 1.0 / (1u64 << 30) as f64;
/// … or after this many intervals.
const MAX_INTERVALS: usize = 2048;

/// Can |V|² vanish on [0, 1]? The parameter of an interval where positivity could not be
/// shown, if any.
fn speed_may_vanish(speed2: &Poly<Bounded>) -> Option<f64> {
    let mut stack = vec![(0.0, 1.0, *speed2)];
    let mut count = 0;
    while let Some((a, b, p)) = stack.pop() {
        count += 1;
        if p.coefficients().iter().all(|c| c.lo() > 0.0) {
            continue;
        }
        let stuck = p.coefficients()[0].lo() <= 0.0 || p.coefficients()[p.n].lo() <= 0.0;
        if stuck || b - a < MIN_WIDTH || count > MAX_INTERVALS {
            return Some(0.5 * (a + b));
        }
        let (l, r) = p.split();
        let m = 0.5 * (a + b);
        stack.push((m, b, r));
        stack.push((a, m, l));
    }
    None
}

/// The sign of N, certified, at parameter `t`.
#[derive(Clone, Copy, PartialEq)]
enum Sign {
    Positive,
    Negative,
}

fn certified_sign(c: Bounded) -> Option<Sign> {
    if c.lo() > 0.0 {
        Some(Sign::Positive)
    } else if c.hi() < 0.0 {
        Some(Sign::Negative)
    } else {
        None
    }
}

/// Subdivide until every interval has a certified sign (or is zero within rounding) or two
/// parameters of certified opposite signs are found.
fn decide(n: &Poly<Bounded>, q: &[Hom; 4]) -> MonotonicityReport {
    let mut stack = vec![(0.0, 1.0, *n)];
    let mut seen: Option<(f64, Sign)> = None;
    let mut unresolved = false;
    let mut count = 0;
    let mut bracket = None;
    'search: while let Some((a, b, p)) = stack.pop() {
        count += 1;
        let c = p.coefficients();
        let nonneg = c.iter().all(|c| c.lo() >= 0.0);
        let nonpos = c.iter().all(|c| c.hi() <= 0.0);
        // Parameters of certified sign, left to right: the ends, and the middle of an
        // interval where all coefficients have one sign and one is certainly nonzero.
        let mut points = [
            (a, certified_sign(c[0])),
            (0.5 * (a + b), None),
            (b, certified_sign(c[p.n])),
        ];
        if nonneg && c.iter().any(|c| c.lo() > 0.0) {
            points[1].1 = Some(Sign::Positive);
        } else if nonpos && c.iter().any(|c| c.hi() < 0.0) {
            points[1].1 = Some(Sign::Negative);
        }
        for (t, sign) in points {
            let Some(sign) = sign else { continue };
            match seen {
                Some((t0, s0)) if s0 != sign => {
                    bracket = Some((t0, t, s0));
                    break 'search;
                }
                _ => seen = Some((t, sign)),
            }
        }
        if nonneg || nonpos {
            continue;
        }
        let hopeless = c.iter().all(|c| c.v.abs() <= c.e);
        if hopeless || b - a < MIN_WIDTH || count > MAX_INTERVALS {
            unresolved = true;
            continue;
        }
        let (l, r) = p.split();
        let m = 0.5 * (a + b);
        stack.push((m, b, r));
        stack.push((a, m, l));
    }
    let (verdict, proven) = match (bracket, seen) {
        (Some((t0, t1, s0)), _) => (
            Monotonicity::NotMonotone {
                t: sign_change(q, t0, t1, s0),
            },
            true,
        ),
        (None, Some((_, Sign::Positive))) => (Monotonicity::Increasing, !unresolved),
        (None, Some((_, Sign::Negative))) => (Monotonicity::Decreasing, !unresolved),
        (None, None) => (Monotonicity::Constant, false),
    };
    MonotonicityReport { verdict, proven }
}

/// A parameter in [`t0`, `t1`] where dκ/ds changes sign, given its certified sign `s0` at
/// `t0` (and the opposite one at `t1`): a root of N, evaluated pointwise from the scaled
/// homogeneous control points `q` (a power-of-two scaling, so N neither overflows nor
/// underflows and only changes by an exact factor), by the crate's root finder (Illinois:
/// N has no cheap derivative).
fn sign_change(q: &[Hom; 4], t0: f64, t1: f64, s0: Sign) -> f64 {
    let c = power_basis(q);
    let sign = if s0 == Sign::Positive { 1.0 } else { -1.0 };
    // f > 0 at t0 and < 0 at t1 (certified by the Bernstein bounds).
    let f = |t: f64| (sign * numerator(&power_jet(&c, t)), None);
    let (f0, f1) = (f(t0).0, f(t1).0);
    let (mut a, mut b) = if f0 > 0.0 && f1 < 0.0 {
        ((t0, f0), (t1, f1))
    } else {
        // Pointwise rounding disagrees with the certified signs: start from the signs
        // alone (the first step then bisects).
        ((t0, 1.0), (t1, -1.0))
    };
    // The bracket narrows to adjacent doubles (or to f = 0) unless the iteration cap comes
    // first; then the sign change lies in the bracket reached, and a restart there from the
    // signs alone bisects first, so that every restart at least halves it.
    loop {
        match find_root(f, a, b, None, f64::MIN_POSITIVE, 100) {
            Ok(t) => return t,
            Err(RootFailure::NotConverged { lo, hi }) => (a, b) = ((hi, 1.0), (lo, -1.0)),
            Err(RootFailure::NotBracketed) => {
                unreachable!("the bracket's ends have opposite signs by construction")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(p: [(f64, f64); 4], w: [f64; 4]) -> RationalCubic {
        RationalCubic::new(p.map(|(x, y)| Point::new(x, y)), w).unwrap()
    }

    #[test]
    fn numerator_polynomial_matches_pointwise_evaluation() {
        let c = curve(
            [(0.1, -0.3), (1.2, 0.9), (2.5, -0.4), (3.1, 1.7)],
            [1.3, 0.4, 2.2, 0.8],
        );
        let (q, m) = scaled_homogeneous(c.points(), c.weights()).unwrap();
        let b = Poly::bernstein(&Numerator::new(&q).n, &Numerator::new(&m).n);
        let qf = q;
        for &t in &[0.0, 0.2, 0.5, 0.77, 1.0] {
            // de Casteljau on the values.
            let mut w: Vec<f64> = b.coefficients().iter().map(|c| c.v).collect();
            for r in 1..w.len() {
                for k in 0..w.len() - r {
                    w[k] = (1.0 - t) * w[k] + t * w[k + 1];
                }
            }
            let want = numerator(&crate::family::bezier::hom_jet(&qf, t));
            assert!(
                (w[0] - want).abs() < 1e-12 * want.abs().max(1e-3),
                "{t}: {} {want}",
                w[0]
            );
        }
    }

    #[test]
    fn degree_elevated_circle_is_constant() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let w = (2.0 * c + 1.0) / 3.0;
        let k = 2.0 * c / (1.0 + 2.0 * c);
        let arc = curve(
            [(1.0, 0.0), (1.0, k), (k, 1.0), (0.0, 1.0)],
            [1.0, w, w, 1.0],
        );
        let r = arc.curvature_monotonicity().unwrap();
        assert_eq!(r.verdict, Monotonicity::Constant);
        assert!(!r.proven);
    }

    #[test]
    fn s_curve_changes_sign_near_its_middle() {
        let s = curve([(0.0, 0.0), (1.0, 1.0), (2.0, -1.0), (3.0, 0.0)], [1.0; 4]);
        let r = s.curvature_monotonicity().unwrap();
        let Monotonicity::NotMonotone { t } = r.verdict else {
            panic!("{r:?}")
        };
        // dκ/ds changes sign where |κ| peaks, on either side of the inflection at t = 1/2.
        let h = 1e-7;
        let (a, b) = (s.curvature_derivative(t - h), s.curvature_derivative(t + h));
        assert!(a * b < 0.0, "{t} {a} {b}");
    }

    #[test]
    fn the_sign_change_of_a_huge_curve_is_where_the_unit_curves_is() {
        // At 2³³⁰ ≈ 1e99 the pointwise numerator (degree 4 in the coordinates) would
        // overflow; evaluated from the power-of-two-scaled points it is the unit curve's.
        let p = [(0.0, 0.0), (1.0, 1.0), (2.0, -1.0), (3.0, 0.0)];
        let w = [1.3, 0.4, 2.2, 0.8];
        let at = |k: f64| {
            let r = curve(p.map(|(x, y)| (k * x, k * y)), w)
                .curvature_monotonicity()
                .unwrap();
            assert!(r.proven);
            match r.verdict {
                Monotonicity::NotMonotone { t } => t,
                v => panic!("{v:?}"),
            }
        };
        let unit = at(1.0);
        assert_eq!(at(2f64.powi(330)), unit);
        assert_eq!(at(2f64.powi(-330)), unit);
    }

    #[test]
    fn a_spiral_arc_is_proven_increasing() {
        // A polynomial cubic whose legs shorten toward the sharp end.
        let c = curve([(0.0, 0.0), (1.2, 0.0), (2.0, 0.4), (2.4, 1.0)], [1.0; 4]);
        let r = c.curvature_monotonicity().unwrap();
        assert_eq!(r.verdict, Monotonicity::Increasing);
        assert!(r.proven);
        assert!((0..=1000).all(|i| c.curvature_derivative(i as f64 / 1000.0) > 0.0));
    }

    #[test]
    fn coincident_end_legs_are_refused() {
        let c = curve([(0.0, 0.0), (0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], [1.0; 4]);
        assert!(matches!(
            c.curvature_monotonicity(),
            Err(Error::CoincidentPoints {
                first: 0,
                second: 1
            })
        ));
    }
}
