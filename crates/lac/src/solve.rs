//! The one-dimensional search of SPEC §3 step 4 (seed 000 §4.1, Appendix A).
//!
//! Instead of bisecting on Λ, we search on μ = ln(ρ_max/ρ_min), the logarithm of the
//! curvature ratio along the piece. Λ(μ) = μ·(1 − e^{−|α−1|μ})/(|α−1|μ)/θd maps
//! [0, ∞) onto the seed's bracket [0, 1/(θd|1−α|)) for every α (α = 1 included), and the
//! end of the piece that approaches the singular point has ρ^(α−1) = e^{−|α−1|μ} exactly,
//! which keeps the integrals accurate however close the segment comes to an inflection.
//! The chord angle increases monotonically with μ; Newton steps with the analytic
//! derivative are taken inside a bracket that only shrinks, and bisection is the fallback,
//! so the iteration never leaves [0, μ_max].

use std::cell::OnceCell;

use crate::error::{Error, NotDrawable, Result};
use crate::integrate::{integrate_with, NodeCache};
use crate::numeric::{expm1_ratio, Complex};
use crate::standard_form::{StandardForm, Station};

/// Largest supported ln(ρ_max/ρ_min) along one segment (ρ ratio ≈ 1e260).
pub(crate) const MAX_LOG_RATIO: f64 = 600.0;
/// Beyond μ = SATURATION/|α| (α < 0) or SATURATION/(α − 1) (α > 1) the chord angle has
/// reached its limit to below 1e-17: for α < 0 the rest of the curve up to the inflection is
/// shorter than e^(−|α|μ) of the piece; and Λ differs from its bound 1/(θd|1−α|) by the
/// factor e^(−|α−1|μ), which changes the whole piece by as much (the slower of the two
/// rates is the binding one: |α| for α < 0, α − 1 for α > 1).
const SATURATION: f64 = 40.0;

/// A solved standard-form piece: θ ∈ [−θd, 0] or [0, θd], ascending.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Piece {
    pub(crate) form: StandardForm,
    pub(crate) start: Station,
    pub(crate) end: Station,
    /// P(end) − P(start).
    pub(crate) chord: Complex,
}

struct ChordAngle {
    alpha: f64,
    beta: f64,
    theta_d: f64,
    theta_e: f64,
    range: (f64, f64),
    /// Built on first use: the series path never needs it.
    nodes: OnceCell<NodeCache>,
}

struct Eval {
    g: f64,
    slope: f64,
    piece: Piece,
}

impl ChordAngle {
    fn piece_stations(&self, mu: f64) -> (Station, Station) {
        let (a, b, td) = (self.alpha, self.beta, self.theta_d);
        let denom = expm1_ratio(-b * mu);
        if a <= 1.0 {
            let end = Station {
                theta: td,
                s: td * expm1_ratio(a * mu) / denom,
                ln_rho: mu,
            };
            (Station::REFERENCE, end)
        } else {
            let start = Station {
                theta: -td,
                s: -td * expm1_ratio(-a * mu) / denom,
                ln_rho: -mu,
            };
            (start, Station::REFERENCE)
        }
    }

    fn eval(&self, mu: f64) -> Eval {
        let lambda = mu * expm1_ratio(-self.beta * mu) / self.theta_d;
        let form = StandardForm {
            alpha: self.alpha,
            lambda,
        };
        let (start, end) = self.piece_stations(mu);
        let nodes = self
            .nodes
            .get_or_init(|| NodeCache::new(self.range.0, self.range.1));
        let integral = integrate_with(&form, &start, &end, true, Some(nodes));
        let p = integral.value;
        let offset = if self.alpha > 1.0 { self.theta_d } else { 0.0 };
        let phi = p.arg() + offset;
        let dphi_dlambda = (p.conj() * integral.d_lambda).im / p.norm_sqr();
        let dlambda_dmu = (-self.beta * mu).exp() / self.theta_d;
        Eval {
            g: phi - self.theta_e,
            slope: dphi_dlambda * dlambda_dmu,
            piece: Piece {
                form,
                start,
                end,
                chord: p,
            },
        }
    }

    /// g and dg/dμ at μ = 0 (the circle) in closed form.
    fn at_circle(&self) -> (f64, f64) {
        let td = self.theta_d;
        let (a, b) = if self.alpha > 1.0 {
            (-td, 0.0)
        } else {
            (0.0, td)
        };
        // ∫ e^{iψ} = −i[e^{iψ}], ∫ ψ e^{iψ} = [e^{iψ}(1 − iψ)].
        let p = (Complex::cis(b) - Complex::cis(a)).mul_i().scale(-1.0);
        let prim = |x: f64| Complex::cis(x) * Complex::new(1.0, -x);
        let dp = prim(b) - prim(a);
        let slope = (p.conj() * dp).im / p.norm_sqr() / td;
        (td / 2.0 - self.theta_e, slope)
    }
}

/// Find the piece whose chord angle at its start is `theta_e`, for turning `theta_d`.
///
/// Requires 0 < θd < π and θd/2 ≤ θe < θd (the caller has put the shorter leg first).
pub(crate) fn solve(alpha: f64, theta_d: f64, theta_e: f64) -> Result<Piece> {
    let range = if alpha > 1.0 {
        (-theta_d, 0.0)
    } else {
        (0.0, theta_d)
    };
    let problem = ChordAngle {
        alpha,
        beta: (alpha - 1.0).abs(),
        theta_d,
        theta_e,
        range,
        nodes: OnceCell::new(),
    };
    // An isosceles triangle is a circular arc for every α.
    if theta_e - 0.5 * theta_d <= 4.0 * f64::EPSILON * theta_d {
        return Ok(problem.eval(0.0).piece);
    }
    let mu_max = if alpha < 0.0 {
        MAX_LOG_RATIO.min(SATURATION / -alpha)
    } else if alpha > 1.0 {
        MAX_LOG_RATIO.min(SATURATION / (alpha - 1.0))
    } else {
        MAX_LOG_RATIO
    };
    let not_drawable = |top: &Eval| {
        Error::NotDrawable(if mu_max < MAX_LOG_RATIO {
            NotDrawable::ChordAngleTooLarge {
                alpha,
                theta_e,
                max: theta_e + top.g,
            }
        } else {
            NotDrawable::CurvatureRatioTooLarge {
                alpha,
                max_log_ratio: MAX_LOG_RATIO,
            }
        })
    };
    // Newton from the circle end. g is increasing; the bracket [lo, hi] only shrinks and
    // its top is evaluated only if an iterate wants to go there.
    let (mut lo, mut hi, mut top_known) = (0.0, mu_max, false);
    let (g0, slope0) = problem.at_circle();
    let (mut mu, mut g, mut slope) = (0.0, g0, slope0);
    let tolerance = 4.0 * f64::EPSILON * theta_d;
    for _ in 0..200 {
        let newton = mu - g / slope;
        let next = if slope > 0.0 && newton > lo && newton < hi {
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
        let e = problem.eval(next);
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
        // Newton converges quadratically: after a step of 1e-9 the error is ~1e-18.
        let converged = g.abs() <= tolerance
            || (next != mu_max && step.abs() <= 1e-9 * mu.max(1.0) && newton == next)
            || hi - lo <= 1e-15 * hi.max(1.0);
        if converged {
            return Ok(e.piece);
        }
    }
    Ok(problem.eval(mu).piece)
}
