//! Small numerical building blocks: complex numbers and the functions that make the
//! log-aesthetic formulas continuous across α = 0, α = 1 and Λ = 0.

use std::ops::{Add, AddAssign, Mul, Neg, Sub};

/// `x` limited to [`lo`, `hi`] without `f64::clamp`'s panic when a bound is NaN (a NaN `x`
/// gives `lo`). Used where the bounds are computed.
#[inline]
pub(crate) fn clamp(x: f64, lo: f64, hi: f64) -> f64 {
    x.max(lo).min(hi)
}

/// The Euclidean length |v|: kurbo's `Vec2::hypot` squares its components (it overflows to ∞
/// beyond about 1e154 and underflows to 0 below about 1e-154); this takes that fast formula
/// where the square is a normal number and `f64::hypot` elsewhere, so that lengths of curves
/// at any finite scale are finite and accurate.
#[inline]
pub(crate) fn length(v: kurbo::Vec2) -> f64 {
    let squared = v.hypot2();
    if (f64::MIN_POSITIVE..f64::INFINITY).contains(&squared) {
        squared.sqrt()
    } else {
        v.x.hypot(v.y)
    }
}

/// `expm1(y) / y`, continued by 1 at y = 0.
///
/// Every removable singularity of docs/math.md §2 (α = 0, α = 1, Λ = 0) is a quotient of this form;
/// `expm1` keeps full relative accuracy for tiny `y`, so the quotient does too.
#[inline]
pub(crate) fn expm1_ratio(y: f64) -> f64 {
    if y == 0.0 {
        1.0
    } else {
        y.exp_m1() / y
    }
}

/// `ln(1 + x) / x`, continued by 1 at x = 0 (x > −1).
#[inline]
pub(crate) fn ln1p_ratio(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        x.ln_1p() / x
    }
}

/// The real roots of `a x² + b x + c = 0` (a ≠ 0) without cancellation: with
/// `q = −(b + sign(b) √(b² − 4ac)) / 2`, the roots `q/a` and `c/q` (the second tends to −c/b
/// as a → 0). A discriminant below 0 by at most `slack` × (b² + |4ac|) (rounding at a double
/// root) counts as 0; `None` below that.
pub(crate) fn quadratic_roots(a: f64, b: f64, c: f64, slack: f64) -> Option<(f64, f64)> {
    let disc = b * b - 4.0 * a * c;
    if disc < -slack * (b * b + (4.0 * a * c).abs()) {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.max(0.0).sqrt());
    Some((q / a, c / q))
}

/// ln(1 + (a + a_lo)·b·c) with the sum formed exactly (FMA error-free products and sums),
/// so that it keeps full relative accuracy when the argument is tiny: near a bound of the
/// standard form, where ρ → 0 or ∞, a plain product would lose up to all digits of the sum.
/// `a_lo` carries the rounding error of `a` when `a` is itself computed (α − 1).
pub(crate) fn ln_1p_product(a: f64, a_lo: f64, b: f64, c: f64) -> f64 {
    let p1 = a * b;
    let e1 = a.mul_add(b, -p1) + a_lo * b;
    let p2 = p1 * c;
    let e2 = p1.mul_add(c, -p2);
    // Two-sum 1 + p2 = s + t, exactly.
    let s = 1.0 + p2;
    let t = (1.0 - s) + p2;
    let w_lo = t + e2 + e1 * c;
    s.ln() + w_lo / s
}

/// `x − 1` and its rounding error, exactly (Fast2Sum; valid since |1| ≥ |x| or x ≥ 1 ulp
/// aligned as in TwoSum).
pub(crate) fn minus_one(x: f64) -> (f64, f64) {
    let d = x - 1.0;
    let z = d - x;
    let lo = (x - (d - z)) + (-1.0 - z);
    (d, lo)
}

/// Why [`find_root`] gave no root.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum RootFailure {
    /// f has the same sign at both ends of the bracket (or is NaN there).
    NotBracketed,
    /// The iteration cap was reached; the bracket at that point is kept.
    NotConverged {
        /// The narrowest bracket reached.
        lo: f64,
        /// Its other end.
        hi: f64,
    },
}

/// One safeguarded root finder for every 1-D equation of the crate.
///
/// Finds x in the bracket [`a`, `b`] (either order) with f(x) = 0, given f's values
/// `fa`, `fb` of opposite signs there (a zero counts as either sign). `f` returns f(x) and,
/// when it has one, f′(x). Each step tries, in order: Newton from the last iterate when f′
/// is given and the step stays strictly inside the bracket; the Illinois variant of regula
/// falsi (the stale end's value halved); bisection. The bracket only shrinks, so the
/// iteration never leaves it; it stops when f(x) = 0, when the bracket is narrower than
/// `x_tol` (absolute) or a few ulps, or when a Newton step is below `x_tol`. After
/// `max_iter` evaluations it reports [`RootFailure::NotConverged`] rather than a guess.
pub(crate) fn find_root<F>(
    mut f: F,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    guess: Option<f64>,
    x_tol: f64,
    max_iter: u32,
) -> Result<f64, RootFailure>
where
    F: FnMut(f64) -> (f64, Option<f64>),
{
    if fa == 0.0 {
        return Ok(a);
    }
    if fb == 0.0 {
        return Ok(b);
    }
    if !(fa.signum() != fb.signum() && a.is_finite() && b.is_finite()) {
        return Err(RootFailure::NotBracketed);
    }
    // Orient so that f(lo) < 0 < f(hi); lo may be above hi.
    let (mut lo, mut f_lo, mut hi, mut f_hi) = if fa < 0.0 {
        (a, fa, b, fb)
    } else {
        (b, fb, a, fa)
    };
    let inside = |x: f64, lo: f64, hi: f64| x > lo.min(hi) && x < lo.max(hi);
    let mut newton: Option<f64> = guess.filter(|&g| inside(g, lo, hi));
    let mut stale = 0i8;
    for _ in 0..max_iter {
        let x = match newton.take() {
            Some(x) => x,
            None => {
                let secant = lo - f_lo * (hi - lo) / (f_hi - f_lo);
                if inside(secant, lo, hi) {
                    secant
                } else {
                    0.5 * (lo + hi)
                }
            }
        };
        let (fx, dfx) = f(x);
        if fx == 0.0 {
            return Ok(x);
        }
        if fx.is_nan() {
            // Nothing to learn here but that f is undefined: retreat halfway toward the
            // end where f is known (the bracket is kept, so a later step may return).
            let back = 0.5 * (lo + x);
            if back == lo || back == x {
                return Err(RootFailure::NotConverged { lo, hi });
            }
            newton = Some(back);
            continue;
        }
        if fx < 0.0 {
            (lo, f_lo) = (x, fx);
            if stale == -1 {
                f_hi *= 0.5;
            }
            stale = -1;
        } else {
            (hi, f_hi) = (x, fx);
            if stale == 1 {
                f_lo *= 0.5;
            }
            stale = 1;
        }
        let width = (hi - lo).abs();
        if width <= x_tol || width <= 4.0 * f64::EPSILON * lo.abs().max(hi.abs()) {
            return Ok(if f_lo.abs() <= f_hi.abs() { lo } else { hi });
        }
        if let Some(d) = dfx.filter(|d| *d != 0.0 && d.is_finite()) {
            let step = fx / d;
            let next = x - step;
            if inside(next, lo, hi) {
                if step.abs() <= x_tol {
                    return Ok(next);
                }
                newton = Some(next);
                // A Newton step that shrinks the bracket slowly is no better than Illinois:
                // leave the stale-end bookkeeping to the secant steps.
                stale = 0;
            }
        }
    }
    Err(RootFailure::NotConverged { lo, hi })
}

/// A complex number `re + i im`, the seeds' notation for planar points.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Complex {
    pub(crate) re: f64,
    pub(crate) im: f64,
}

impl Complex {
    pub(crate) const ZERO: Complex = Complex { re: 0.0, im: 0.0 };

    #[inline]
    pub(crate) const fn new(re: f64, im: f64) -> Self {
        Complex { re, im }
    }

    /// `e^{iθ}`.
    #[inline]
    pub(crate) fn cis(theta: f64) -> Self {
        let (s, c) = theta.sin_cos();
        Complex { re: c, im: s }
    }

    #[inline]
    pub(crate) fn scale(self, k: f64) -> Self {
        Complex::new(self.re * k, self.im * k)
    }

    #[inline]
    pub(crate) fn conj(self) -> Self {
        Complex::new(self.re, -self.im)
    }

    #[inline]
    pub(crate) fn norm(self) -> f64 {
        self.re.hypot(self.im)
    }

    /// max(|re|, |im|): a norm that cannot overflow, within √2 of |z|.
    #[inline]
    pub(crate) fn norm_max(self) -> f64 {
        self.re.abs().max(self.im.abs())
    }

    #[inline]
    pub(crate) fn arg(self) -> f64 {
        self.im.atan2(self.re)
    }

    /// The argument, as [`Complex::arg`], without a call of atan2 when the point lies
    /// within 1e-3 rad of the positive real axis (as a Newton iteration's last residuals
    /// do): atan(t), t = im/re, by its series to t⁷, whose remainder is below 1e-25 of it.
    #[inline]
    pub(crate) fn arg_near_zero(self) -> f64 {
        if self.re > 0.0 && self.im.abs() < 1e-3 * self.re {
            let t = self.im / self.re;
            let t2 = t * t;
            t * (1.0 - t2 * (1.0 / 3.0 - t2 * (0.2 - t2 / 7.0)))
        } else {
            self.arg()
        }
    }

    /// Multiplication by `i`.
    #[inline]
    pub(crate) fn mul_i(self) -> Self {
        Complex::new(-self.im, self.re)
    }

    /// Division by Smith's method, which never forms |d|² and so neither overflows nor
    /// underflows for divisors up to the largest finite magnitudes (standard-form chords
    /// reach 1e260 when the curvature ratio does). A dividend near the largest magnitudes
    /// (caller coordinates of 1e308) can overflow the sums of the method while the quotient
    /// is finite: then both parts are halved first and the quotient doubled back.
    #[inline]
    pub(crate) fn div(self, d: Complex) -> Self {
        let q = self.smith_div(d);
        if q.re.is_finite() && q.im.is_finite() || !(self.re.is_finite() && self.im.is_finite()) {
            return q;
        }
        let half = Complex::new(0.5 * self.re, 0.5 * self.im).smith_div(d);
        Complex::new(2.0 * half.re, 2.0 * half.im)
    }

    fn smith_div(self, d: Complex) -> Self {
        if d.re.abs() >= d.im.abs() {
            let r = d.im / d.re;
            let den = d.re + d.im * r;
            Complex::new((self.re + self.im * r) / den, (self.im - self.re * r) / den)
        } else {
            let r = d.re / d.im;
            let den = d.re * r + d.im;
            Complex::new((self.re * r + self.im) / den, (self.im * r - self.re) / den)
        }
    }
}

impl Add for Complex {
    type Output = Complex;
    #[inline]
    fn add(self, o: Complex) -> Complex {
        Complex::new(self.re + o.re, self.im + o.im)
    }
}

impl AddAssign for Complex {
    #[inline]
    fn add_assign(&mut self, o: Complex) {
        self.re += o.re;
        self.im += o.im;
    }
}

impl Sub for Complex {
    type Output = Complex;
    #[inline]
    fn sub(self, o: Complex) -> Complex {
        Complex::new(self.re - o.re, self.im - o.im)
    }
}

impl Neg for Complex {
    type Output = Complex;
    #[inline]
    fn neg(self) -> Complex {
        Complex::new(-self.re, -self.im)
    }
}

impl Mul for Complex {
    type Output = Complex;
    #[inline]
    fn mul(self, o: Complex) -> Complex {
        Complex::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
}

/// `x · num / den` as written (bit for bit) where the product stays finite, and dividing
/// first where it overflows: a station `i / n` of the way along a length near 1e308.
pub fn times_ratio(x: f64, num: f64, den: f64) -> f64 {
    match x * num / den {
        y if y.is_finite() => y,
        _ => x * (num / den),
    }
}

/// A number with six significant digits at most, for messages: `0.333333`, `1.5e-7`.
pub fn short_number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        let text = format!("{x:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (5.0 - magnitude) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// As written where the product is finite (bit for bit), dividing first where it is not.
    #[test]
    fn times_ratio_divides_first_only_where_the_product_overflows() {
        for (x, num, den) in [(0.1, 3.0, 7.0), (1e300, 17.0, 64.0), (-2.5, 1.0, 3.0)] {
            assert_eq!(
                times_ratio(x, num, den).to_bits(),
                (x * num / den).to_bits()
            );
        }
        let near_max = 1.5e308_f64;
        assert!((near_max * 63.0 / 64.0).is_infinite());
        assert_eq!(times_ratio(near_max, 63.0, 64.0), near_max * (63.0 / 64.0));
    }

    /// Both roots to rounding, the small one too when a is tiny (where the textbook formula
    /// cancels), a double root through `slack`, none for complex roots.
    #[test]
    fn quadratic_roots_keep_their_digits() {
        assert_eq!(quadratic_roots(1.0, -3.0, 2.0, 0.0), Some((2.0, 1.0)));
        let (big, small) = quadratic_roots(1e-20, 1.0, -1.0, 0.0).expect("real roots");
        assert!(
            (small - 1.0).abs() < 1e-15 && (big + 1e20).abs() < 1e5,
            "{big} {small}"
        );
        let third = 1.0 / 3.0;
        let (a, b, c) = (1.0, -2.0 * third, third * third);
        assert!(quadratic_roots(a, b, c, 1e-12)
            .is_some_and(|(r, s)| (r - third).abs() < 1e-7 && (s - third).abs() < 1e-7));
        assert_eq!(quadratic_roots(1.0, 0.0, 1.0, 1e-12), None);
    }

    #[test]
    fn ln_1p_product_is_accurate_next_to_minus_one() {
        // 1 + (−0.5)(0.1)(19.999979999999997) in exact rational arithmetic of these doubles
        // is 1.0000000000842668e-6; its logarithm to 20 digits (mpmath):
        let exact = -13.815_510_557_880_007;
        let (a, b, c): (f64, f64, f64) = (-0.5, 0.1, 19.999_979_999_999_997);
        let got = ln_1p_product(a, 0.0, b, c);
        assert!((got - exact).abs() < 4e-16 * exact.abs(), "{got}");
        // A plain evaluation is wrong from the 11th digit on.
        assert!(((a * b * c).ln_1p() - exact).abs() > 1e-11);
    }

    #[test]
    fn division_survives_huge_divisors() {
        let big = Complex::new(3e200, 4e200);
        let q = Complex::new(6.0, 8.0).div(big);
        assert!((q.re - 2e-200).abs() < 1e-215 && q.im.abs() < 1e-215);
        let q = Complex::new(1.0, 2.0).div(Complex::new(0.0, 2.0));
        assert_eq!((q.re, q.im), (1.0, -0.5));
    }

    #[test]
    fn minus_one_is_exact() {
        let (d, lo) = minus_one(-1e-8);
        // −1.00000001 is not a double; d + lo is, to 1e-32.
        assert_eq!(d, -1.000_000_01);
        assert!(lo != 0.0 && lo.abs() < 1e-16);
        assert_eq!(minus_one(0.5), (-0.5, 0.0));
    }

    #[test]
    fn ratios_are_continuous_at_zero() {
        for &y in &[1e-300, 1e-20, 1e-9, -1e-9, -1e-20] {
            assert!((expm1_ratio(y) - 1.0).abs() < 1e-8, "{y}");
            assert!((ln1p_ratio(y) - 1.0).abs() < 1e-8, "{y}");
        }
        assert_eq!(expm1_ratio(0.0), 1.0);
        assert_eq!(ln1p_ratio(0.0), 1.0);
        // Away from zero they are the plain quotients.
        assert!((expm1_ratio(1.0) - (1f64.exp() - 1.0)).abs() < 1e-15);
        assert!((ln1p_ratio(1.0) - 2f64.ln()).abs() < 1e-15);
    }

    #[test]
    fn find_root_converges_with_and_without_derivatives() {
        let cubic = |x: f64| (x * x * x - 2.0, Some(3.0 * x * x));
        let r = find_root(cubic, (0.0, -2.0), (2.0, 6.0), None, 1e-15, 100).unwrap();
        assert!((r - 2f64.cbrt()).abs() < 4e-16);
        let plain = |x: f64| (x.cos() - x, None);
        let r = find_root(
            plain,
            (1.0, 1f64.cos() - 1.0),
            (0.0, 1.0),
            Some(0.5),
            0.0,
            100,
        )
        .unwrap();
        assert!((r.cos() - r).abs() < 1e-15, "{r}");
    }

    #[test]
    fn find_root_reports_what_went_wrong() {
        let f = |x: f64| (x * x + 1.0, None);
        assert_eq!(
            find_root(f, (0.0, 1.0), (1.0, 2.0), None, 1e-12, 50),
            Err(RootFailure::NotBracketed)
        );
        // A cap too small to converge is a failure, not an answer.
        let g = |x: f64| (x.powi(3) - 0.3, None);
        assert!(matches!(
            find_root(g, (0.0, -0.3), (1.0, 0.7), None, 0.0, 3),
            Err(RootFailure::NotConverged { .. })
        ));
        // NaN inside the bracket is stepped around.
        let h = |x: f64| {
            (
                if (0.49..0.51).contains(&x) {
                    f64::NAN
                } else {
                    x - 0.7
                },
                None,
            )
        };
        let r = find_root(h, (0.0, -0.7), (1.0, 0.3), Some(0.5), 1e-14, 200).unwrap();
        assert!((r - 0.7).abs() < 1e-13);
    }
}
