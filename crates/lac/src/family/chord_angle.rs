//! The one-dimensional search of docs/math.md §3 step 4 (seed 000 §4.1, Appendix A) and §4
//! (seed 004), for one piece or two pieces joined with G3 continuity.
//!
//! Both pieces share the reference point of their standard forms, at the joint: piece 0 is
//! θ ∈ [−θ0, 0] of LAC(α0, Λ), piece 1 is θ ∈ [0, θ1] of LAC(α1, Λ), so ρ = 1 and dρ/ds = Λ
//! on both sides of the joint (the logarithmic curvature graph is one continuous polyline).
//! A single segment is θ0 = 0 (α ≤ 1) or θ1 = 0 (α > 1).
//!
//! Instead of bisecting on Λ we search on μ with Λ(μ) = μ·E(−Dμ/Θ)/Θ, E(y) = (e^y − 1)/y,
//! where Θ = θ0 + θ1 and D = max(θ0(α0 − 1), θ1(1 − α1), 0) is such that Λ < 1/D keeps
//! both pieces clear of their singular points (ρ = 0 before the start when α0 > 1, ρ = ∞
//! after the end when α1 < 1). This maps [0, ∞) onto [0, 1/D) (onto [0, ∞) when D = 0),
//! and the end that approaches its singular point has ρ^(α−1) = e^{−Dμ/Θ} exactly, which
//! keeps the integrals accurate however close the curve comes to an inflection. For one
//! piece μ is exactly ln(ρ_max/ρ_min). The chord angle increases monotonically with μ;
//! Newton steps with the analytic derivative are taken inside a bracket that only shrinks,
//! with bisection as the fallback, so the iteration never leaves [0, μ_max].

use std::cell::OnceCell;

mod guess;

use crate::family::standard_form::integrate::{
    clothoid_arc, integrate_with, ClothoidEnd, NodeCache, CLOTHOID_MIN_LAMBDA_TURN,
    CLOTHOID_MIN_TURN,
};
use crate::family::standard_form::{StandardForm, Station};
use crate::foundation::error::{Error, NotDrawable, Result};
use crate::foundation::numeric::{expm1_ratio, ln1p_ratio, quadratic_roots, Complex};

/// Largest supported ln(ρ_max/ρ_min) along one curve (ρ ratio ≈ 1e260).
pub(crate) const MAX_LOG_RATIO: f64 = 600.0;
/// The search stops growing μ once the chord angle has reached its limit to below
/// e^(−SATURATION): for a binding piece with α < 0 the rest of the curve up to the
/// inflection is shorter than w^(|α|/(1−α)) of it, and Λ differs from its bound by the
/// factor w, which changes the whole curve by as much (w = e^{−Dμ/Θ}); for α > 1 the rest
/// up to ρ = 0 is shorter than w^(α/(α−1)) ≤ w. For 0 ≤ α < 1 the inflection is at
/// infinity and there is no limit short of MAX_LOG_RATIO.
const SATURATION: f64 = 40.0;

/// The largest chord-angle residual (radians, per radian of turning above 1) a solution
/// may have.
const RESIDUAL_TOLERANCE: f64 = 1e-9;

/// A solved standard-form piece: θ ascending from `start` to `end`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Piece {
    pub(crate) form: StandardForm,
    pub(crate) start: Station,
    pub(crate) end: Station,
    /// P(end) − P(start).
    pub(crate) chord: Complex,
}

/// Two pieces joined at the reference point; a piece with θ0 = 0 or θ1 = 0 is empty.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pieces {
    pub(crate) parts: [Piece; 2],
}

/// The search problem: slopes, turning of each piece, and the required angle from the
/// start tangent (direction −θ0) to the chord, in [0, 2π).
pub(crate) struct ChordAngle {
    alpha: [f64; 2],
    theta: [f64; 2],
    theta_e: f64,
    total: f64,
    /// D_i = θ_i |α_i − 1| for a piece heading toward its singular point, else 0.
    bound: [f64; 2],
    d: f64,
    /// Built on first use: the series path never needs them.
    nodes: [OnceCell<NodeCache>; 2],
    /// For a single clothoid piece (α = −1, θ ∈ [0, θd], θd ≥ `CLOTHOID_MIN_TURN`): e^{iθd},
    /// and e^{−iθe}, for the closed form of [`ChordAngle::eval_clothoid`].
    clothoid: Option<(Complex, Complex)>,
    /// A first μ to try instead of the circle's or the clothoid table's (a caller's last
    /// answer to a nearby problem).
    hint: Option<f64>,
    /// Whether the search may stop at a Newton step within [`LOOSE_STEP`] of μ.
    loose: bool,
}

/// A loose search (see [`solve_near`]) stops at a Newton step no longer than this share of
/// μ: the iterate is then within about its square of the root, which is far closer than a
/// difference quotient's step needs.
const LOOSE_STEP: f64 = 1e-6;

struct Eval {
    mu: f64,
    g: f64,
    slope: f64,
    /// d ln|P|/dμ, P the chord of both pieces.
    dln_chord: f64,
    pieces: Pieces,
}

/// How a solved piece moves with the chord angle asked for: what a caller iterating on the
/// control points needs for exact derivatives, without solving again.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sensitivity {
    /// dμ/dθe.
    pub(crate) dmu_dtheta_e: f64,
    /// d ln|P|/dμ, P the piece's chord in the standard form.
    pub(crate) dln_chord_dmu: f64,
}

impl ChordAngle {
    pub(crate) fn new(alpha: [f64; 2], theta: [f64; 2], theta_e: f64) -> Self {
        let bound = [
            if alpha[0] > 1.0 {
                theta[0] * (alpha[0] - 1.0)
            } else {
                0.0
            },
            if alpha[1] < 1.0 {
                theta[1] * (1.0 - alpha[1])
            } else {
                0.0
            },
        ];
        ChordAngle {
            alpha,
            theta,
            theta_e,
            total: theta[0] + theta[1],
            bound,
            d: bound[0].max(bound[1]),
            nodes: [OnceCell::new(), OnceCell::new()],
            clothoid: (alpha == [-1.0, -1.0] && theta[0] == 0.0 && theta[1] >= CLOTHOID_MIN_TURN)
                .then(|| (Complex::cis(theta[1]), Complex::cis(theta_e).conj())),
            hint: None,
            loose: false,
        }
    }

    /// The same problem, its search started at `mu` when that is a finite positive number.
    pub(crate) fn with_hint(mut self, mu: Option<f64>) -> Self {
        self.hint = mu.filter(|m| m.is_finite() && *m > 0.0);
        self
    }

    /// The far station of piece `i` (θ = −θ0 or θ1) for Λ, with w = ρ^(α−1) there taken
    /// from the exact w_bind = e^{−Dμ/Θ} when the piece heads toward its singular point.
    fn station(&self, i: usize, lambda: f64, w_bind: f64) -> Station {
        let alpha = self.alpha[i];
        let theta = if i == 0 {
            -self.theta[0]
        } else {
            self.theta[1]
        };
        let x = (alpha - 1.0) * lambda * theta;
        // w = 1 − (D_i/D)(1 − w_bind), a sum of two non-negative terms.
        let w = if self.bound[i] > 0.0 {
            let r = self.bound[i] / self.d;
            (1.0 - r) + r * w_bind
        } else {
            1.0 + x
        };
        let (ln_rho, per_lambda) = if w < 0.5 {
            let u = w.ln() / (alpha - 1.0);
            (u, u / lambda)
        } else {
            let lr = ln1p_ratio(x);
            (lambda * theta * lr, theta * lr)
        };
        Station {
            theta,
            s: per_lambda * expm1_ratio(alpha * ln_rho),
            ln_rho,
        }
    }

    fn eval(&self, mu: f64) -> Eval {
        if let Some(e) = self.eval_clothoid(mu) {
            return e;
        }
        let k = self.d / self.total;
        let lambda = mu * expm1_ratio(-k * mu) / self.total;
        let w_bind = (-k * mu).exp();
        let mut parts = [Piece {
            form: StandardForm {
                alpha: self.alpha[0],
                lambda,
            },
            start: Station::REFERENCE,
            end: Station::REFERENCE,
            chord: Complex::ZERO,
        }; 2];
        let (mut p, mut dp) = (Complex::ZERO, Complex::ZERO);
        for (i, part) in parts.iter_mut().enumerate() {
            let form = StandardForm {
                alpha: self.alpha[i],
                lambda,
            };
            part.form = form;
            if self.theta[i] <= 0.0 {
                continue;
            }
            let far = self.station(i, lambda, w_bind);
            let (a, b) = if i == 0 {
                (far, Station::REFERENCE)
            } else {
                (Station::REFERENCE, far)
            };
            let nodes = self.nodes[i].get_or_init(|| NodeCache::new(a.theta, b.theta));
            let integral = integrate_with(&form, &a, &b, true, Some(nodes));
            part.start = a;
            part.end = b;
            part.chord = integral.value;
            p += integral.value;
            dp += integral.d_lambda;
        }
        let phi = (p.arg() + self.theta[0]).rem_euclid(std::f64::consts::TAU);
        // dφ/dΛ = Im(P′/P), divided without forming |P|² (P reaches 1e260).
        let dphi_dlambda = dp.div(p).im;
        let dlambda_dmu = w_bind / self.total;
        Eval {
            mu,
            g: phi - self.theta_e,
            slope: dphi_dlambda * dlambda_dmu,
            dln_chord: dp.div(p).re * dlambda_dmu,
            pieces: Pieces { parts },
        }
    }

    /// [`ChordAngle::eval`] for a single clothoid piece, where everything is in closed form:
    /// D = 2θd, so Λ = (1 − e^{−2μ})/(2θd), the curvature at the far end is e^{−μ} (ρ = 1 at
    /// the start) and the chord is a difference of Fresnel integrals. `None` where the
    /// closed form would lose precision (near the circle), for the general path.
    #[inline]
    fn eval_clothoid(&self, mu: f64) -> Option<Eval> {
        let (end_dir, unturn) = self.clothoid?;
        let theta_d = self.theta[1];
        let kappa = (-mu).exp(); // at the far end
        let w = kappa * kappa; // ρ^(α−1)
        let lambda = -(-2.0 * mu).exp_m1() / (2.0 * theta_d);
        // (Also `None` for a NaN.)
        (lambda * theta_d >= CLOTHOID_MIN_LAMBDA_TURN).then_some(())?;
        let far = ClothoidEnd {
            kappa,
            rho: 1.0 / kappa,
        };
        let start = ClothoidEnd {
            kappa: 1.0,
            rho: 1.0,
        };
        let integral = clothoid_arc(
            lambda,
            [start, far],
            [Complex::new(1.0, 0.0), end_dir],
            true,
        );
        let p = integral.value;
        let form = StandardForm {
            alpha: -1.0,
            lambda,
        };
        let end = Station {
            theta: theta_d,
            // s = (1 − κ)/Λ = 2θd/(1 + κ), as 2Λθd = 1 − κ².
            s: 2.0 * theta_d / (1.0 + kappa),
            ln_rho: mu,
        };
        let start = Piece {
            form,
            start: Station::REFERENCE,
            end: Station::REFERENCE,
            chord: Complex::ZERO,
        };
        let piece = Piece {
            form,
            start: Station::REFERENCE,
            end,
            chord: p,
        };
        // φ − θe: the chord angle φ and θe both lie in [θd/2, θd) ⊂ [0, π) (the shorter
        // leg first), so this is the argument of P e^{−iθe}, taken without atan2 near the
        // root.
        let ratio = integral.d_lambda.div(p);
        Some(Eval {
            mu,
            g: (p * unturn).arg_near_zero(),
            slope: ratio.im * w / theta_d,
            dln_chord: ratio.re * w / theta_d,
            pieces: Pieces {
                parts: [start, piece],
            },
        })
    }

    /// g and dg/dμ at μ = 0 (both pieces arcs of the unit circle) in closed form, and a
    /// first iterate from a saturating Padé model of g at μ = 0: near the circle
    /// ρ = 1 + Λψ + (2 − α)Λ²ψ²/2 + (2 − α)(3 − 2α)Λ³ψ³/6 + O(Λ⁴), so the derivatives of P
    /// in Λ are integrals of ψⁿe^{iψ}.
    fn at_circle(&self) -> (f64, f64, f64) {
        let (a, b) = (-self.theta[0], self.theta[1]);
        // e^{iψ} at the three places the antiderivatives are taken (each once).
        let (ea, eb) = (
            Complex::cis(a),
            self.clothoid
                .map_or_else(|| Complex::cis(b), |(end_dir, _)| end_dir),
        );
        let cis = |x: f64| {
            if x == 0.0 {
                Complex::new(1.0, 0.0)
            } else if x == a {
                ea
            } else {
                eb
            }
        };
        // Antiderivatives of ψⁿe^{iψ}, n = 0..3.
        let p0 = |x: f64| cis(x).mul_i().scale(-1.0);
        let p1 = |x: f64| cis(x) * Complex::new(1.0, -x);
        let p2 = |x: f64| cis(x) * Complex::new(2.0 * x, 2.0 - x * x);
        let p3 = |x: f64| cis(x) * Complex::new(3.0 * x * x - 6.0, 6.0 * x - x * x * x);
        // ∂ⁿP/∂Λⁿ at Λ = 0: ρ = 1 + Λψ + (2−α)Λ²ψ²/2 + (2−α)(3−2α)Λ³ψ³/6 + O(Λ⁴).
        let piecewise = |f: &dyn Fn(f64) -> Complex, c: &dyn Fn(f64) -> f64| {
            (f(0.0) - f(a)).scale(c(self.alpha[0])) + (f(b) - f(0.0)).scale(c(self.alpha[1]))
        };
        let p = p0(b) - p0(a);
        let r1 = (p1(b) - p1(a)).div(p);
        let r2 = piecewise(&p2, &|al| 2.0 - al).div(p);
        let r3 = piecewise(&p3, &|al| (2.0 - al) * (3.0 - 2.0 * al)).div(p);
        // Derivatives of φ = Im ln P in Λ.
        let phi1 = r1.im;
        let phi2 = (r2 - r1 * r1).im;
        let phi3 = (r3 - (r1 * r2).scale(3.0) + (r1 * r1 * r1).scale(2.0)).im;
        // Λ(μ) = μ E(−kμ)/Θ: Λ′ = 1/Θ, Λ″ = −k/Θ, Λ‴ = k²/Θ at μ = 0.
        let (k, t) = (self.d / self.total, self.total);
        let (l1, l2, l3) = (1.0 / t, -k / t, k * k / t);
        let g1 = phi1 * l1;
        let g2 = phi2 * l1 * l1 + phi1 * l2;
        let g3 = phi3 * l1 * l1 * l1 + 3.0 * phi2 * l1 * l2 + phi1 * l3;
        let g0 = 0.5 * self.total - self.theta_e;
        // The root of the Padé model g ≈ g₀ + aμ/(1 + bμ + cμ²), which saturates like the
        // chord angle does; matched to g′, g″, g‴ at 0: a = g′, b = −g″/(2a),
        // c = b² − g‴/(6a). Its root solves g₀cμ² + (g₀b + a)μ + g₀ = 0; kept only if it is
        // within a factor 3 of the Newton step.
        let linear = -g0 / g1;
        let (pa, pb) = (g1, -g2 / (2.0 * g1));
        let pc = pb * pb - g3 / (6.0 * g1);
        let (qa, qb, qc) = (g0 * pc, g0 * pb + pa, g0);
        let first = if qa.abs() <= 1e-12 * qb.abs() {
            -qc / qb
        } else {
            // The root that tends to −qc/qb as qa → 0.
            match quadratic_roots(qa, qb, qc, 0.0) {
                Some((_, root)) if root.is_finite() => root,
                _ => linear,
            }
        };
        let first = if first.is_finite() && first > linear / 3.0 && first < 3.0 * linear {
            first
        } else {
            linear
        };
        (g0, g1, first)
    }

    /// Where the search may stop growing μ, and whether that is a limit of the family
    /// (true) or of floating point (false).
    fn mu_max(&self) -> (f64, bool) {
        if self.d <= 0.0 {
            return (MAX_LOG_RATIO, false);
        }
        // The binding piece (the one with the larger bound) sets the saturation rate.
        let i = if self.bound[0] >= self.bound[1] { 0 } else { 1 };
        let alpha = self.alpha[i];
        let rate = if alpha > 1.0 {
            1.0
        } else if alpha < 0.0 {
            (-alpha / (1.0 - alpha)).min(1.0)
        } else {
            return (MAX_LOG_RATIO, false);
        };
        let mu = SATURATION * self.total / (self.d * rate);
        if mu < MAX_LOG_RATIO {
            (mu, true)
        } else {
            (MAX_LOG_RATIO, false)
        }
    }

    /// Find μ, hence Λ, such that the chord angle is θe. Requires Θ/2 ≤ θe.
    pub(crate) fn solve(&self) -> Result<Pieces> {
        self.solve_eval().map(|e| e.pieces)
    }

    /// [`ChordAngle::solve`], with the last evaluation (its slopes are the solution's).
    fn solve_eval(&self) -> Result<Eval> {
        // An isosceles configuration is a circular arc for every α.
        if self.theta_e - 0.5 * self.total <= 4.0 * f64::EPSILON * self.total {
            return Ok(self.eval(0.0));
        }
        let (mu_max, is_limit) = self.mu_max();
        let not_drawable = |top: &Eval| {
            Error::NotDrawable(if is_limit {
                NotDrawable::ChordAngleTooLarge {
                    alpha: if self.bound[0] >= self.bound[1] {
                        self.alpha[0]
                    } else {
                        self.alpha[1]
                    },
                    theta_e: self.theta_e,
                    max: self.theta_e + top.g,
                }
            } else {
                NotDrawable::CurvatureRatioTooLarge {
                    alpha: if self.bound[0] > self.bound[1] {
                        self.alpha[0]
                    } else {
                        self.alpha[1]
                    },
                    max_log_ratio: MAX_LOG_RATIO,
                    theta_e: self.theta_e,
                    reached: self.theta_e + top.g,
                }
            })
        };
        // Newton from the circle end. g is increasing; the bracket [lo, hi] only shrinks and
        // its top is evaluated only if an iterate wants to go there.
        let (mut lo, mut hi, mut top_known) = (0.0, mu_max, false);
        // A caller's hint first; else the circle's model, good near μ = 0 only, or for a
        // clothoid its table. (With a hint the circle end is not evaluated: the first
        // Newton step after the hint is a plain one.)
        let hint = self.hint.filter(|m| *m < mu_max);
        let (g0, slope0, first) = match hint {
            Some(h) => (f64::NAN, f64::NAN, h),
            None => {
                let (g0, slope0, first) = self.at_circle();
                let first = self
                    .clothoid
                    .and_then(|_| guess::clothoid(self.theta[1], self.theta_e))
                    .unwrap_or(first);
                (g0, slope0, first)
            }
        };
        let (mut mu, mut g, mut slope) = (0.0, g0, slope0);
        let mut first = Some(first);
        let tolerance = 4.0 * f64::EPSILON * self.total;
        let mut previous_step = f64::INFINITY;
        let mut previous = (mu, slope);
        for _ in 0..200 {
            // Halley's correction with g″ from the last two slopes (no extra evaluation);
            // plain Newton when that correction is large (far from the root).
            let curvature = (slope - previous.1) / (mu - previous.0);
            let halley = 1.0 - g * curvature / (2.0 * slope * slope);
            let guessed = first.is_some();
            let newton = if let Some(guess) = first.take() {
                guess
            } else if curvature.is_finite() && (0.7..1.4).contains(&halley) {
                mu - g / (slope * halley)
            } else {
                mu - g / slope
            };
            previous = (mu, slope);
            let next = if (guessed || slope > 0.0) && newton > lo && newton < hi {
                newton
            } else if !top_known && hi == mu_max {
                hi
            } else if hi > 4.0 * (lo + 1.0) {
                // Far from the root with a wide bracket: grow geometrically, not by halves.
                4.0 * (lo + 1.0)
            } else {
                0.5 * (lo + hi)
            };
            let step = next - mu;
            let e = self.eval(next);
            if next == mu_max {
                top_known = true;
                if e.g < 0.0 {
                    return Err(not_drawable(&e));
                }
            }
            if e.g < 0.0 {
                lo = next;
            } else {
                hi = next;
            }
            (mu, g, slope) = (next, e.g, e.slope);
            // Newton converges quadratically, e_{k+1} ≈ C e_k² with e_k ≈ |step_k|: estimate
            // C from the last two steps and stop once the predicted error of `next` is below
            // 1e-16 (relative), which saves the evaluation that would only confirm it. (The
            // first guess is not a Newton step: its distance from 0 says nothing of C, and
            // taken as one it stopped the search with Λ 8e-12 off.)
            let newton_step = newton == next && next != mu_max && !guessed;
            // (Needs two Newton steps: after the first there is no estimate of C.)
            let predicted = if previous_step.is_finite() {
                step.abs() / (previous_step * previous_step) * step * step
            } else {
                f64::INFINITY
            };
            let converged = g.abs() <= tolerance
                || (newton_step && step.abs() <= 1e-9 * mu.max(1.0))
                || (self.loose && newton_step && step.abs() <= LOOSE_STEP * mu.max(1.0))
                || (newton_step
                    && step.abs() <= 1e-3 * mu.max(1.0)
                    && predicted <= 1e-16 * mu.max(1.0))
                || hi - lo <= 1e-15 * hi.max(1.0);
            previous_step = if newton_step {
                step.abs()
            } else {
                f64::INFINITY
            };
            if converged {
                return self.verified(e);
            }
        }
        self.verified(self.eval(mu))
    }

    /// The pieces, if the chord angle they make is the one asked for: a collapsed bracket
    /// or the iteration cap is not a solution unless the residual says so (the residuals
    /// seen on the reference set are below 2e-14 rad).
    fn verified(&self, e: Eval) -> Result<Eval> {
        if e.g.abs() <= RESIDUAL_TOLERANCE * self.total.max(1.0) {
            Ok(e)
        } else {
            Err(Error::NumericalFailure {
                what: "the chord-angle equation (the search did not converge)",
            })
        }
    }
}

/// A single piece at some μ, and how it moves: the solution of [`solve`], or one evaluation
/// of [`eval_at`] on the way to it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Solution {
    pub(crate) piece: Piece,
    pub(crate) mu: f64,
    /// The piece's chord angle less the one asked for (rounding, for a solution).
    pub(crate) g: f64,
    /// `None` where the slopes are not usable numbers.
    pub(crate) sensitivity: Option<Sensitivity>,
}

/// The standard-form arrangement of a single piece: ρ = 1 at the end that stays regular as
/// Λ grows (docs/math.md §3 step 4); the turning on either side of the reference point, and which
/// of the two pieces is the one.
fn single(alpha: f64, theta_d: f64) -> ([f64; 2], usize) {
    if alpha > 1.0 {
        ([theta_d, 0.0], 0)
    } else {
        ([0.0, theta_d], 1)
    }
}

impl Solution {
    fn of(e: Eval, i: usize) -> Solution {
        let dmu_dtheta_e = 1.0 / e.slope;
        let sensitivity =
            (dmu_dtheta_e.is_finite() && e.dln_chord.is_finite()).then_some(Sensitivity {
                dmu_dtheta_e,
                dln_chord_dmu: e.dln_chord,
            });
        Solution {
            piece: e.pieces.parts[i],
            mu: e.mu,
            g: e.g,
            sensitivity,
        }
    }
}

/// Find the single piece whose chord angle at its start is `theta_e`, for turning
/// `theta_d`. Requires 0 < θd < π and θd/2 ≤ θe < θd (the shorter leg first).
/// The search starts at `hint` (e.g. the μ of a nearby problem's solution) when given: the
/// same solution (g increases with μ, so there is one), in fewer evaluations when the hint
/// is close. With `loose` it stops at a Newton step shorter than 1e-6 of μ, without the
/// evaluation that would confirm it (μ then within about 1e-12 of itself: for a difference
/// quotient taken over a far larger step).
pub(crate) fn solve_near(
    alpha: f64,
    theta_d: f64,
    theta_e: f64,
    (hint, loose): (Option<f64>, bool),
) -> Result<Solution> {
    let (theta, i) = single(alpha, theta_d);
    let mut problem = ChordAngle::new([alpha, alpha], theta, theta_e).with_hint(hint);
    problem.loose = loose;
    let e = problem.solve_eval()?;
    Ok(Solution::of(e, i))
}

/// The single piece of [`solve`] at the search's first guess of μ, not solved (see
/// [`eval_at`]).
pub(crate) fn eval_at_guess(alpha: f64, theta_d: f64, theta_e: f64) -> Option<Solution> {
    let (theta, _) = single(alpha, theta_d);
    let problem = ChordAngle::new([alpha, alpha], theta, theta_e);
    let guess = problem
        .clothoid
        .and_then(|_| guess::clothoid(theta_d, theta_e))
        .unwrap_or_else(|| problem.at_circle().2);
    eval_at(alpha, theta_d, theta_e, guess)
}

/// The single piece of [`solve`] at `mu`, not solved: one evaluation, for a caller that
/// iterates on μ together with its own unknowns (`None` outside 0 < μ ≤ the search's
/// range, or where the numbers are not finite).
pub(crate) fn eval_at(alpha: f64, theta_d: f64, theta_e: f64, mu: f64) -> Option<Solution> {
    let (theta, i) = single(alpha, theta_d);
    let problem = ChordAngle::new([alpha, alpha], theta, theta_e);
    if !(mu > 0.0 && mu <= problem.mu_max().0) {
        return None;
    }
    let out = Solution::of(problem.eval(mu), i);
    (out.g.is_finite() && out.piece.chord.norm().is_finite() && out.sensitivity.is_some())
        .then_some(out)
}

#[cfg(test)]
mod tests {
    use super::guess::{ratio_at, turn_at};
    use super::*;

    /// μ of the clothoid piece turning by `theta_d` with chord angle `theta_e`.
    fn clothoid_mu(theta_d: f64, theta_e: f64) -> f64 {
        let pieces = ChordAngle::new([-1.0; 2], [0.0, theta_d], theta_e)
            .solve()
            .unwrap();
        pieces.parts[1].end.ln_rho
    }

    /// The chord angle's limit for turning `theta_d` (at μ = 40 it is within e^{−40}).
    fn phi_max(theta_d: f64) -> f64 {
        ChordAngle::new([-1.0; 2], [0.0, theta_d], 0.0).eval(40.0).g
    }

    /// A hint, near or far (even past the search's range), gives the solution found
    /// without one: g increases with μ, so there is one root.
    #[test]
    fn a_hint_gives_the_same_solution() {
        for alpha in [-1.0, -0.5, 0.0, 0.7, 2.0] {
            for (theta_d, r) in [(0.8, 0.52), (2.0, 0.7), (0.01, 0.6)] {
                let theta_e = r * theta_d;
                let Ok(cold) = solve_near(alpha, theta_d, theta_e, (None, false)) else {
                    // Not drawable: not with a hint either.
                    assert!(solve_near(alpha, theta_d, theta_e, (Some(0.5), false)).is_err());
                    continue;
                };
                for hint in [
                    cold.mu * (1.0 + 1e-6),
                    cold.mu * 2.0 + 0.1,
                    1e-9,
                    1e6,
                    f64::NAN,
                ] {
                    let warm = solve_near(alpha, theta_d, theta_e, (Some(hint), false)).unwrap();
                    assert!(
                        (warm.mu - cold.mu).abs() <= 1e-12 * cold.mu.max(1.0),
                        "{alpha} {theta_d} {r} {hint}: {} {}",
                        warm.mu,
                        cold.mu
                    );
                }
                // A loose search from a difference quotient's step away (1e-7 in θe) stops
                // an evaluation early, within 1e-11 of μ.
                let nudged = theta_e + 1e-7;
                let Ok(tight) = solve_near(alpha, theta_d, nudged, (Some(cold.mu), false)) else {
                    continue;
                };
                let loose = solve_near(alpha, theta_d, nudged, (Some(cold.mu), true)).unwrap();
                assert!(
                    (loose.mu - tight.mu).abs() <= 1e-11 * tight.mu.max(1.0),
                    "{alpha} {theta_d} {r}: {} {}",
                    loose.mu,
                    tight.mu
                );
            }
        }
    }

    /// The guess table is what the solver makes of its grid (so it can be regenerated, and a
    /// changed solver shows here), and it guesses μ to 1e-3 between the nodes (r from 0
    /// to 1 − 1e-4).
    #[test]
    fn guess_table() {
        use guess::table::{M, NR, NT, PHI_MAX};
        let mut phi = [0.0; NT];
        let mut m = [[0.0; NR]; NT];
        for (i, (top, column)) in phi.iter_mut().zip(&mut m).enumerate() {
            let theta_d = turn_at(i);
            *top = phi_max(theta_d);
            let half = 0.5 * theta_d;
            for (j, cell) in column.iter_mut().enumerate().skip(1) {
                // The last row is the limit r → 1, within 1e-6 (closer, μ is ill-determined:
                // the chord angle hardly moves with it).
                let r = ratio_at(j).min(1.0 - 1e-6);
                let mu = clothoid_mu(theta_d, half + r * (*top - half));
                *cell = mu + (-r).ln_1p();
            }
        }
        if std::env::var_os("LAC_WRITE_GUESS_TABLE").is_some() {
            let path = concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/src/family/chord_angle/guess/table.rs"
            );
            let rows: Vec<String> = m
                .iter()
                .map(|row| {
                    let cells: Vec<String> = row.iter().map(|x| format!("{x:?}")).collect();
                    format!("    [{}],\n", cells.join(", "))
                })
                .collect();
            let phis: Vec<String> = phi.iter().map(|x| format!("{x:?}")).collect();
            let text = format!(
                "//! Generated by `LAC_WRITE_GUESS_TABLE=1 cargo test -p lac --release \
                 guess_table`; do not\n//! edit.\n\n/// Grid columns (turning angles).\n\
                 pub(crate) const NT: usize = {NT};\n/// Grid rows (ratios r).\n\
                 pub(crate) const NR: usize = {NR};\n/// φmax at each column.\n\
                 #[rustfmt::skip]\npub(crate) const PHI_MAX: [f64; NT] = [{}];\n\
                 /// m = μ + ln(1 − r) at each column and row.\n#[rustfmt::skip]\n\
                 pub(crate) const M: [[f64; NR]; NT] = [\n{}];\n",
                phis.join(", "),
                rows.concat()
            );
            std::fs::write(path, text).unwrap();
            return;
        }
        for i in 0..NT {
            assert!((PHI_MAX[i] - phi[i]).abs() <= 1e-12, "φmax at column {i}");
            for j in 0..NR {
                // (The last row, next to the limit, is determined to about 1e-8 only.)
                let allowed = if j + 1 == NR { 1e-6 } else { 1e-9 };
                assert!(
                    (M[i][j] - m[i][j]).abs() <= allowed,
                    "m at ({i}, {j}): {} vs {}",
                    M[i][j],
                    m[i][j]
                );
            }
        }
        // Between the nodes: a sweep of turning angles and ratios.
        let mut worst: f64 = 0.0;
        for a in 0..97 {
            let theta_d = 0.05 + (std::f64::consts::PI - 0.06) * (a as f64 + 0.5) / 97.0;
            let (half, top) = (0.5 * theta_d, phi_max(theta_d));
            for b in 1..100 {
                // Up to 1 − 1e-4 (μ ≈ 10); closer still, φmax's own interpolation error
                // (1e-8) is a visible part of 1 − r, and the guess is good to 2e-2 only.
                let r = 1.0 - (b as f64 / 100.0).powi(2);
                let theta_e = half + r * (top - half);
                let mu = clothoid_mu(theta_d, theta_e);
                let guess = guess::clothoid(theta_d, theta_e).unwrap();
                worst = worst.max((guess - mu).abs() / mu);
            }
        }
        eprintln!("worst relative error of the guess: {worst:e}");
        assert!(worst < 1e-3, "{worst}");
    }
}
