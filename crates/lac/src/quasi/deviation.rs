//! The deviation of a piece from the curve: d(φ) = |x(t(φ)) − L(φ)|, the distance between
//! the points where the Bézier and the curve have turned by the same angle φ from their
//! start tangents (the seed's correspondence). t(φ) solves det(d_φ, V(t)) = 0 with
//! V = p′w − pw′ (quartic in t) by Newton, safeguarded by the crate's root finder.
//!
//! rms = √(∫ d² dφ / Θ) and max = max d(φ), both divided by the curve's arc length; the
//! maximum is found on 64 equal steps of the piece's parameter t (about equal steps of arc
//! length) and refined at the vertex of the parabola through the largest sample and its
//! neighbours.
//!
//! Next to an inflection (an end where |κ| is below [`FLAT_END`] of the other end's) that
//! correspondence fails: the curve turns by almost nothing over a long stretch, so points
//! that have turned by the same angle lie far apart although the two curves nearly
//! coincide (for α = −½, κ ∝ s² next to it, and a cubic's κ ∝ t). The pieces of a curve
//! with such an end are measured by closest points instead: the largest distance from the
//! curve's points, at 65 equal steps of the piece's arc length, to the piece
//! (`max_distance`).

use kurbo::Vec2;

use super::fit::{Candidate, Node, Span};
use super::TurningCurve;
use crate::foundation::error::Result;
use crate::foundation::numeric::{find_root, times_ratio};

/// Deviation samples per piece for the maximum.
const CHECK_STEPS: usize = 64;

/// An end whose |κ| is at most this share of the other end's is flat (an inflection).
pub(super) const FLAT_END: f64 = 1e-3;

/// Does the curve have an end of (nearly) zero curvature, an inflection?
/// Only curves of slope α < 0 reach zero curvature (at a finite arc length); a small
/// |κ| ratio of α ≥ 0 comes with a tight hook at the other end, where 65 points of the
/// curve are too few for closest points (a fuzzed α = 0.36 hook was understated by 10%).
pub(super) fn has_flat_end(curve: &(impl TurningCurve + ?Sized)) -> bool {
    let (a, b) = curve.end_curvatures();
    let (a, b) = (a.abs(), b.abs());
    curve.can_inflect() && a.min(b) <= FLAT_END * a.max(b)
}

/// Gauss–Newton steps per closest point (each gains a factor ~ distance × curvature ≪ 1).
const PROJECTION_STEPS: usize = 8;

/// How to find the parameter of a node.
#[derive(Clone, Copy)]
pub(super) enum Solve {
    /// To full precision.
    Converge,
    /// One Newton step from the previous value (for finite differences).
    OneStep,
}

impl Span {
    /// Residuals √gⱼ (x(tⱼ) − Lⱼ), updating the parameters `ts` in place.
    pub(super) fn residuals(
        &self,
        cand: &Candidate,
        ts: &mut [f64],
        out: &mut Vec<f64>,
        how: Solve,
    ) -> Option<f64> {
        out.clear();
        let mut lo = 0.0;
        let mut sum = 0.0;
        for (node, t) in self.nodes.iter().zip(ts.iter_mut()) {
            let Node {
                dir,
                weight: w,
                target,
                ..
            } = node;
            let tt = match how {
                Solve::Converge => cand.solve_t(*dir, lo, *t)?,
                Solve::OneStep => cand.newton_step(*dir, *t),
            };
            *t = tt;
            lo = tt;
            let d = cand.point(tt) - *target;
            let g = w.sqrt();
            out.push(g * d.x);
            out.push(g * d.y);
            sum += w * d.hypot2();
        }
        Some(sum)
    }

    /// ∫ d² dφ over the span and the parameters of the nodes.
    pub(super) fn integral(&self, cand: &Candidate) -> Option<(f64, Vec<f64>)> {
        let mut ts = self.initial_ts();
        let mut r = Vec::new();
        let sum = self.residuals(cand, &mut ts, &mut r, Solve::Converge)?;
        Some((sum, ts))
    }

    /// max d(φ) over the span, caller's units: on 64 equal steps of the candidate's t (about
    /// equal steps of arc length, so that a stretch of small curvature, where φ hardly
    /// changes, is not passed over), each paired with the curve's point at the candidate's
    /// tangent direction there; refined at the vertex of the parabola through each large
    /// local maximum and its neighbours.
    pub(super) fn max_deviation(
        &self,
        curve: &(impl TurningCurve + ?Sized),
        cand: &Candidate,
    ) -> Result<f64> {
        let ts: Vec<f64> = (0..=CHECK_STEPS)
            .map(|i| i as f64 / CHECK_STEPS as f64)
            .collect();
        let mut phis = Vec::with_capacity(ts.len());
        let mut prev = 0.0;
        for &t in &ts {
            // Ascending for `at_turning` (it is, unless the candidate turns back).
            let phi = self.turning_at(cand, t, prev).max(prev);
            phis.push(self.phi_a + phi);
            prev = phi;
        }
        let samples = curve.at_turning(&phis)?;
        let d: Vec<f64> = ts
            .iter()
            .zip(&samples)
            .map(|(&t, s)| (cand.point(t) - self.local(s.point)).hypot())
            .collect();
        let dmax = d.iter().fold(0.0f64, |m, &x| m.max(x));
        let mut best = dmax;
        for i in 1..CHECK_STEPS {
            let (a, b, c) = (d[i - 1], d[i], d[i + 1]);
            let denom = a - 2.0 * b + c;
            if b < a || b < c || b < 0.9 * dmax || denom >= 0.0 {
                continue;
            }
            let t = (i as f64 + 0.5 * (a - c) / denom) / CHECK_STEPS as f64;
            let phi = self.turning_at(cand, t, phis[i] - self.phi_a);
            let s = curve.at_turning(&[self.phi_a + phi])?[0];
            best = best.max((cand.point(t) - self.local(s.point)).hypot());
        }
        Ok(best)
    }

    /// The largest distance from the curve's points at 65 equal steps of the span's arc
    /// length to the candidate (local units): each point's closest point on the candidate
    /// by Gauss–Newton on (x(t) − q)·x′(t) = 0 from the last one's parameter. Every
    /// iterate's distance is the distance to a point of the candidate, so the smallest seen
    /// bounds the true one from above even where the iteration does not settle.
    pub(super) fn max_distance(
        &self,
        curve: &(impl TurningCurve + ?Sized),
        cand: &Candidate,
    ) -> Result<f64> {
        let [sa, sb] = self.s;
        let at: Vec<f64> = (0..=CHECK_STEPS)
            .map(|i| {
                if i == CHECK_STEPS {
                    sb
                } else {
                    sa + times_ratio(sb - sa, i as f64, CHECK_STEPS as f64)
                }
            })
            .collect();
        let samples = curve.at_arc_lengths(&at)?;
        let mut worst = 0.0f64;
        let mut t = 0.0f64;
        for sample in &samples {
            let q = self.local(sample.point);
            let mut best = f64::INFINITY;
            for _ in 0..PROJECTION_STEPS {
                let (x, dx) = cand.point_and_derivative(t);
                let d = x - q;
                best = best.min(d.hypot());
                let step = d.dot(dx) / dx.hypot2();
                if !step.is_finite() {
                    break;
                }
                t = (t - step).clamp(0.0, 1.0);
            }
            best = best.min((cand.point(t) - q).hypot());
            worst = worst.max(best);
        }
        Ok(worst)
    }

    /// The candidate's turning at `t`, within [0, Θ], unwrapped next to `near`.
    fn turning_at(&self, cand: &Candidate, t: f64, near: f64) -> f64 {
        let (v, _) = cand.hodograph(t);
        let raw = v.y.atan2(v.x);
        let tau = std::f64::consts::TAU;
        let phi = raw + tau * ((near - raw) / tau).round();
        phi.clamp(0.0, self.turning)
    }
}

impl Candidate {
    /// x(t) and x′(t) = V(t)/w(t)².
    fn point_and_derivative(&self, t: f64) -> (Vec2, Vec2) {
        let w = self.weight(t);
        (self.point(t), self.hodograph(t).0 / (w * w))
    }

    /// One Newton step on det(dir, V(t)) = 0 from `t`.
    pub(super) fn newton_step(&self, dir: Vec2, t: f64) -> f64 {
        let (v, dv) = self.hodograph(t);
        t - dir.cross(v) / dir.cross(dv)
    }

    /// The parameter in [lo, 1] where the tangent has direction `dir`: Newton on
    /// det(dir, V(t)) from `guess`, and where that fails to settle quickly on a root with
    /// the right direction, the crate's safeguarded root finder on [lo, 1]
    /// ([`find_root`]). None where neither finds it.
    pub(super) fn solve_t(&self, dir: Vec2, lo: f64, guess: f64) -> Option<f64> {
        // Unguarded Newton first: from the neighbouring node's parameter it settles in two or
        // three evaluations, where the bracketed finder spends two on the bracket's ends
        // alone; going straight to it doubles the time of the seed's fit (`cargo bench -p lac
        // --bench quasi`, quasi_median/fit: 48 µs → 93 µs).
        let mut t = guess;
        for _ in 0..6 {
            let (v, dv) = self.hodograph(t);
            let step = dir.cross(v) / dir.cross(dv);
            t -= step;
            if !(t >= lo - 1e-9 && t <= 1.0 + 1e-9) {
                break;
            }
            // Newton converges quadratically: after a step below 1e-8 the error is ~1e-16.
            if step.abs() <= 1e-8 {
                if dir.dot(self.hodograph(t).0) > 0.0 {
                    return Some(t.clamp(0.0, 1.0));
                }
                break;
            }
        }
        self.solve_t_bracketed(dir, lo, guess)
    }

    fn solve_t_bracketed(&self, dir: Vec2, lo: f64, guess: f64) -> Option<f64> {
        let h = |t: f64| {
            let (v, dv) = self.hodograph(t);
            (dir.cross(v), Some(dir.cross(dv)))
        };
        let (ha, hb) = (h(lo).0, h(1.0).0);
        if !(ha <= 0.0 && hb >= 0.0) {
            // The tangent direction is not between those at lo and 1: the candidate turns
            // the wrong way somewhere.
            if ha.abs() <= 1e-15 * self.hodograph(lo).0.hypot() {
                return Some(lo);
            }
            if hb.abs() <= 1e-15 * self.hodograph(1.0).0.hypot() {
                return Some(1.0);
            }
            return None;
        }
        // Newton converges quadratically: after a step of a few ulps of 1 the error is far
        // below them. A parameter that does not settle fails the candidate.
        find_root(h, (lo, ha), (1.0, hb), Some(guess), 4.0 * f64::EPSILON, 100).ok()
    }
}
