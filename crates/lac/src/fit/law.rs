//! The curvature law of one log-aesthetic piece in intrinsic form: curvature and tangent
//! angle along the piece from its two end curvatures, its length and α, in closed form.
//!
//! Along a log-aesthetic curve ρ^α is linear in arc length (docs/math.md §2). With t = s/L
//! the share of the piece's length and r = κ_b/κ_a (one sign, neither zero),
//!
//! ```text
//! κ(t) = κ_a (1 + t e)^(−1/α),          e = r^(−α) − 1 = expm1(−α ln r)
//! θ(t) − θ_a = κ_a L ∫₀ᵗ (1 + τ e)^(−1/α) dτ = κ_a L (y/e) · expm1(y + Y)/(y + Y)
//! ```
//!
//! where y = ln(1 + t e) and Y = ln(κ(t)/κ_a) = y ln r / (−α ln r): every quotient is an
//! `expm1`/`ln1p` ratio, so α = 0 (κ = κ_a r^t), α = 1 and r = 1 (a circle) are ordinary
//! values. For α < 0 the signed power q = sign(κ)|κ|^(−α) is linear in arc length through
//! zero curvature (the inflection at finite length), which gives the S-shaped pieces and
//! the ends at zero curvature: κ = sign(q)|q|^p with p = −1/α, and
//! θ(t) − θ_a = L (|q(t)|^(p+1) − |q_a|^(p+1)) / ((p + 1)(q_b − q_a)).

use crate::foundation::numeric::expm1_ratio;

/// The slope below which a piece may not pass through zero curvature: its halves could not
/// reach zero curvature to the precision a joint is checked to (see `build.rs`).
pub(super) const INFLECTION_ALPHA_MIN: f64 = -1.5;

/// The slope above which a piece may not pass through zero curvature: its curvature falls
/// to zero like |t − t₀|^(1/|α|), so that a hair (1e-12 of its length, see `build.rs`) from
/// its inflection the curvature is below 1e-24 of the piece's for α > −0.5, and no
/// [`Segment`](crate::Segment) places a half that ends there to the accuracy a fit is
/// checked to.
pub(super) const INFLECTION_ALPHA_MAX: f64 = -0.5;

/// Whether a piece through zero curvature may have the slope `alpha`.
pub(super) fn inflects_with(alpha: f64) -> bool {
    (INFLECTION_ALPHA_MIN..=INFLECTION_ALPHA_MAX).contains(&alpha)
}

/// ln(1 + te), e = expm1(x): by ln1p where e is small, and as ln((1 − t) + t eˣ) where
/// e nears −1 (a curvature that falls by many orders, x ≪ 0), whose 1 + te would lose eˣ
/// to cancellation (the end curvature of a fall of 1e-6 was 4% off).
#[inline]
fn ln_share(t: f64, x: f64, e: f64) -> f64 {
    if e < -0.5 {
        ((1.0 - t) + t * x.exp()).ln()
    } else {
        (t * e).ln_1p()
    }
}

/// One piece's law; see the module documentation.
#[derive(Clone, Copy, Debug)]
pub(super) struct Law {
    form: Form,
    ka: f64,
    len: f64,
    alpha: f64,
}

#[derive(Clone, Copy, Debug)]
enum Form {
    /// One sign, neither end zero: ln r, x = −α ln r and e = expm1(x).
    Ratio { ln_r: f64, x: f64, e: f64 },
    /// α < 0 through (or at) zero curvature: q_a, q_b − q_a, p = −1/α and |q_a|^(p+1)
    /// (as [`Law::at`] computes |q|^(p+1) = |q|^p |q|, so that the turning at t = 0 is 0).
    Power {
        qa: f64,
        dq: f64,
        p: f64,
        lift_a: f64,
    },
}

impl Law {
    /// The law of the piece with end curvatures `ka`, `kb`, length `len` and slope
    /// `alpha`; `None` where no log-aesthetic piece has them (α ≥ 0 with ends of opposite
    /// signs or at zero curvature, or a number that is not finite).
    pub(super) fn new(ka: f64, kb: f64, len: f64, alpha: f64) -> Option<Law> {
        if !(ka.is_finite() && kb.is_finite() && len.is_finite() && alpha.is_finite()) {
            return None;
        }
        let form = if ka != 0.0 && kb != 0.0 && ka.signum() == kb.signum() {
            let ln_r = (kb / ka).ln();
            // Near the subnormal range the quotients y/x and y/e keep only a few bits: there
            // the law is its α = 0 limit to far below rounding.
            let x = -alpha * ln_r;
            let x = if x.abs() < 1e-290 { 0.0 } else { x };
            let e = x.exp_m1();
            if !e.is_finite() {
                return None;
            }
            Form::Ratio { ln_r, x, e }
        } else if alpha < 0.0 {
            let q = |k: f64| k.signum() * k.abs().powf(-alpha);
            let qa = q(ka);
            let p = -1.0 / alpha;
            Form::Power {
                qa,
                dq: q(kb) - qa,
                p,
                lift_a: qa.abs().powf(p) * qa.abs(),
            }
        } else {
            return None;
        };
        Some(Law {
            form,
            ka,
            len,
            alpha,
        })
    }

    /// The slope α.
    pub(super) fn alpha(&self) -> f64 {
        self.alpha
    }

    /// (θ(t) − θ_a, κ(t)) at the share `t` ∈ [0, 1] of the piece.
    #[inline]
    pub(super) fn at(&self, t: f64) -> (f64, f64) {
        match self.form {
            Form::Ratio { ln_r, x, e } => {
                let y = ln_share(t, x, e);
                let big_y = if x != 0.0 { ln_r * (y / x) } else { t * ln_r };
                // y/e = t·ln(1 + te)/(te), continued by t at e = 0.
                let y_over_e = if e != 0.0 { y / e } else { t };
                let turn = self.ka * self.len * y_over_e * expm1_ratio(y + big_y);
                (turn, self.ka * big_y.exp())
            }
            Form::Power { qa, dq, p, lift_a } => {
                let q = qa + dq * t;
                let size = q.abs().powf(p);
                let kappa = q.signum() * size;
                if dq == 0.0 {
                    return (kappa * self.len * t, kappa);
                }
                // |q|^(p+1) = |q|^p |q|: one power a call, not three.
                let turn = self.len * (size * q.abs() - lift_a) / ((p + 1.0) * dq);
                (turn, kappa)
            }
        }
    }

    /// The curvature and dκ/dt at the share `t`, with one logarithm and one exponential
    /// (what the stations are placed by, at every station of every table).
    #[inline]
    pub(super) fn curvature(&self, t: f64) -> (f64, f64) {
        match self.form {
            Form::Ratio { ln_r, x, e } => {
                if x == 0.0 {
                    let kappa = self.ka * (t * ln_r).exp();
                    return (kappa, kappa * ln_r);
                }
                // κ = κa e^Y with Y = ln r · ln(1 + te)/x, so d ln κ/dt = ln r · e/(x (1 +
                // te)); the share 1 + te itself where e ≥ −0.5 (no cancellation), else
                // from its logarithm.
                let y = ln_share(t, x, e);
                let kappa = self.ka * (ln_r * (y / x)).exp();
                let share = if e < -0.5 { y.exp() } else { 1.0 + t * e };
                (kappa, kappa * ln_r * (e / x) / share)
            }
            Form::Power { qa, dq, p, .. } => {
                let q = qa + dq * t;
                let size = q.abs().powf(p);
                let slope = if q != 0.0 {
                    p * (size / q.abs()) * dq
                } else {
                    p * q.abs().powf(p - 1.0) * dq
                };
                (q.signum() * size, slope)
            }
        }
    }

    /// The share of the piece within which, on either side of its point of zero curvature,
    /// |κ| stays below `limit` (|q| = limit^(1/p), a share |q|/|q_b − q_a|); `None` for a
    /// piece whose curvature keeps one sign.
    pub(super) fn within(&self, limit: f64) -> Option<f64> {
        match self.form {
            Form::Power { dq, p, .. } if dq != 0.0 => Some(limit.powf(1.0 / p) / dq.abs()),
            _ => None,
        }
    }

    /// Whether the curvature keeps one sign and stays away from zero (the ratio form).
    pub(super) fn keeps_sign(&self) -> bool {
        matches!(self.form, Form::Ratio { .. })
    }

    /// The share of the piece where its curvature is zero, strictly inside it, if any.
    pub(super) fn inflection(&self) -> Option<f64> {
        match self.form {
            Form::Power { qa, dq, .. } if dq != 0.0 => {
                let t = -qa / dq;
                (t > 0.0 && t < 1.0).then_some(t)
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// κ(t) from the law against ρ^α linear in s, and θ against a Simpson sum of κ.
    #[test]
    fn curvature_and_turning_agree_with_the_definition() {
        let cases = [
            (1.0, 3.0, 0.7, -1.0),
            (3.0, 1.0, 0.7, 2.0),
            (-2.0, -0.5, 1.3, 0.0),
            (-2.0, -0.5, 1.3, 1.0),
            (0.4, 0.4, 2.0, 0.5),
            (1.0, -2.0, 1.0, -1.0),
            (0.0, 2.0, 1.0, -0.5),
            (1.5, 0.0, 1.0, -2.0),
        ];
        for (ka, kb, len, alpha) in cases {
            let law = Law::new(ka, kb, len, alpha).unwrap();
            let n = 4000;
            let mut turned = 0.0;
            for i in 0..n {
                let (t0, t1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                let k = |t: f64| law.at(t).1;
                turned += len / n as f64 / 6.0 * (k(t0) + 4.0 * k(0.5 * (t0 + t1)) + k(t1));
            }
            let (turn, kappa) = law.at(1.0);
            assert!(
                (kappa - kb).abs() < 1e-12,
                "{ka} {kb} {alpha}: κ(1) = {kappa}"
            );
            // Simpson's sum converges slowly where κ ~ √(distance) at a zero-curvature end.
            let slack = if ka * kb == 0.0 { 1e-6 } else { 1e-9 };
            assert!(
                (turn - turned).abs() < slack,
                "{ka} {kb} {alpha}: {turn} {turned}"
            );
            // ρ^α (ln ρ for α = 0, the signed power for α < 0) is linear in t.
            let g = |k: f64| {
                if alpha == 0.0 {
                    k.abs().ln()
                } else {
                    k.signum() * k.abs().powf(-alpha)
                }
            };
            if ka != 0.0 && kb != 0.0 && (ka > 0.0) == (kb > 0.0) || alpha < 0.0 {
                let mid = g(law.at(0.3).1);
                let lin = g(ka) + 0.3 * (g(kb) - g(ka));
                assert!(
                    (mid - lin).abs() < 1e-12 * (1.0 + lin.abs()),
                    "{ka} {kb} {alpha}"
                );
            }
        }
    }

    /// α → 0 and α = 0 agree: the law is continuous there, down to the smallest normal
    /// slope with a curvature ratio near 1, whose −α ln r is subnormal (the turning was
    /// 1e-6 off there before such slopes were taken as 0).
    #[test]
    fn continuous_across_alpha_zero() {
        let a = Law::new(1.0, 2.0, 1.0, 0.0).unwrap().at(0.6);
        let b = Law::new(1.0, 2.0, 1.0, 1e-12).unwrap().at(0.6);
        assert!((a.0 - b.0).abs() < 1e-11 && (a.1 - b.1).abs() < 1e-11);
        let near = |alpha: f64, t: f64| {
            Law::new(-0.7027782104771556, -0.7027782071578693, 17.88, alpha)
                .unwrap()
                .at(t)
        };
        for j in 0..=100 {
            let t = j as f64 / 100.0;
            let (a, b) = (near(0.0, t), near(f64::MIN_POSITIVE, t));
            assert!(
                (a.0 - b.0).abs() <= 1e-14 * a.0.abs() && (a.1 - b.1).abs() < 1e-15,
                "t = {t}: {a:?} {b:?}"
            );
        }
    }

    /// A curvature that rises a thousandfold at α = 3 (e = r^(−α) − 1 within 1e-9 of −1)
    /// ends at its end curvature: 1 + te lost e^x to cancellation before (1e-8 off here,
    /// 4% for a fall of 1e6).
    #[test]
    fn a_steep_rise_ends_at_its_end_curvature() {
        for (ka, kb, alpha) in [(1e-3, 1.0, 3.0), (1e-6, 1.0, 2.0), (2.0, 2e-5, -2.5)] {
            let law = Law::new(ka, kb, 1.0, alpha).unwrap();
            let kappa = law.at(1.0).1;
            assert!(
                (kappa - kb).abs() <= 1e-13 * kb.abs(),
                "{ka} → {kb}, α {alpha}: {kappa}"
            );
        }
    }

    #[test]
    fn opposite_signs_need_a_negative_alpha() {
        assert!(Law::new(1.0, -1.0, 1.0, 0.5).is_none());
        assert!(Law::new(0.0, 1.0, 1.0, 0.0).is_none());
        let s = Law::new(1.0, -1.0, 1.0, -1.0).unwrap();
        assert!((s.inflection().unwrap() - 0.5).abs() < 1e-15);
    }
}
