//! Plain cubics (all weights 1) have no freedom left once the ends, end tangents and end
//! curvatures are fixed: the leg lengths solve the G2 Hermite system
//! (3/2)κ₀δ₀² = det(t₀, C) − δ₁ sin Θ, (3/2)κ₁δ₁² = det(C, t₁) − δ₀ sin Θ, a quartic in δ₀;
//! of its admissible roots the one with the smallest deviation is taken.

use kurbo::Vec2;

use super::fit::{Candidate, Span};
use super::unfittable;
use crate::family::bezier::Hom;
use crate::foundation::error::Result;
use crate::foundation::numeric::find_root;

impl Span {
    /// The plain cubic of the G2 Hermite data with the smallest deviation.
    pub(super) fn fit_polynomial(&self) -> Result<[Hom; 4]> {
        let (s, c) = self.turning.sin_cos();
        let t1 = Vec2::new(c, s);
        let big_a = self.end.y; // det(t₀, C)
        let big_b = self.end.cross(t1); // det(C, t₁)
        let (k0, k1) = (1.5 * self.kappa[0], 1.5 * self.kappa[1]);
        // δ₁(δ₀) = (A − k₀δ₀²)/s ≥ 0 and f(δ₀) = k₁δ₁² + sδ₀ − B = 0.
        let d1 = |d0: f64| (big_a - k0 * d0 * d0) / s;
        let f = |d0: f64| {
            let e = d1(d0);
            k1 * e * e + s * d0 - big_b
        };
        // f′(δ₀) = −4k₀k₁δ₀δ₁/s + s: Newton inside the bracket.
        let f_and_slope = |d0: f64| (f(d0), Some(s - 4.0 * k0 * k1 * d0 * d1(d0) / s));
        let top = (big_a / k0).sqrt();
        // Full precision: a Newton step this small leaves an error far below it.
        let x_tol = 4.0 * f64::EPSILON * top;
        const STEPS: usize = 64;
        let mut best: Option<(f64, [Hom; 4])> = None;
        let mut prev = (0.0, f(0.0));
        for i in 1..=STEPS {
            let x = top * i as f64 / STEPS as f64;
            let fx = f(x);
            let bracketed = prev.1 == 0.0 || prev.1.signum() != fx.signum();
            // A root that does not settle is not a candidate (never a guess).
            let root = bracketed
                .then(|| find_root(f_and_slope, prev, (x, fx), None, x_tol, 100).ok())
                .flatten();
            if let Some(d0) = root {
                let e1 = d1(d0);
                if d0 > 0.0 && e1 > 0.0 {
                    let q = [
                        [0.0, 0.0, 1.0],
                        [d0, 0.0, 1.0],
                        [self.end.x - e1 * c, self.end.y - e1 * s, 1.0],
                        [self.end.x, self.end.y, 1.0],
                    ];
                    if let Some((err, _)) = self.integral(&Candidate::new(q)) {
                        if best.as_ref().is_none_or(|(b, _)| err < *b) {
                            best = Some((err, q));
                        }
                    }
                }
            }
            prev = (x, fx);
        }
        best.map(|(_, q)| q).ok_or_else(unfittable)
    }
}
