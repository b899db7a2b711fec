//! One piece over a span of the curve turning by Θ (seed 001): b₀ and b₃ are the span's
//! ends, b₁ = b₀ + u(B − b₀) and b₂ = b₃ + v(B − b₃) with B the intersection of the end
//! tangents, w₁ = w₂ = (2 cos(Θ/2) + 1)/3 (the degree-elevated circular arc), and w₀, w₃
//! set so that the end curvatures equal the curve's. In the span's frame (b₀ at the origin,
//! start tangent +x, turning left) these are closed forms, w₀ = K₀u²/(1 − v) and
//! w₃ = K₃v²/(1 − u). The leg fractions (u, v) minimise
//!
//! ```text
//! F(u, v) = ∫₀^Θ d(φ)² dφ,   d(φ) = |x(t(φ)) − L(φ)|,
//! ```
//!
//! the squared distance between the points where the Bézier and the curve have turned by
//! the same angle φ from their start tangents (the seed's correspondence, `deviation.rs`),
//! integrated by 16-point Gauss–Legendre in φ, by Levenberg–Marquardt. F has several
//! valleys: the starts are the circular arc's u = v = 2c/(1 + 2c), c = cos(Θ/2) (the exact
//! answer for an isosceles triangle), the G2 plain cubic's leg fractions and a 2×2 grid; the
//! best start is descended, and a rough descent from the best start lying apart is finished
//! if it wins.

use kurbo::{Point, Vec2};

use super::deviation::{has_flat_end, Solve};
use super::{unfittable, Kind, QuasiPiece, TurningCurve};
use crate::family::bezier::{power_basis, Hom, RationalCubic};
use crate::family::monotone::Monotonicity;
use crate::foundation::error::Result;
use crate::foundation::gauss::GAUSS_16;

/// A piece with what the totals of the chain need.
pub(super) struct Fitted {
    pub(super) piece: QuasiPiece,
    /// ∫ d² dφ over the piece.
    /// (relative to the curve's length squared)
    pub(super) integral: f64,
}

/// A fitted span with the signed curvatures of the curve at its ends.
pub(super) struct Trial {
    pub(super) fitted: Fitted,
    pub(super) end_kappa: [f64; 2],
}

impl std::ops::Deref for Trial {
    type Target = Fitted;
    fn deref(&self) -> &Fitted {
        &self.fitted
    }
}

/// Levenberg–Marquardt stops once (u, v) are settled to ~1e-9 and F stops improving beyond
/// its rounding; further steps only chase noise.
const SETTLED: (f64, f64) = (1e-9, 1e-12);
/// … or, for a probe of a second valley, once it is clear where the descent ends.
const ROUGH: (f64, f64) = (1e-4, 1e-3);

/// The cubic of `kind` over the span of the curve from turning `phi_a` to `phi_b`, with
/// its deviation and monotonicity.
pub(super) fn fit_span(
    curve: &(impl TurningCurve + ?Sized),
    phi_a: f64,
    phi_b: f64,
    kind: Kind,
) -> Result<Trial> {
    let span = Span::new(curve, phi_a, phi_b)?;
    match kind {
        Kind::Seed => {
            let g2 = span.fit_polynomial().ok();
            span.trial(curve, &span.fit_rational(g2.as_ref())?)
        }
        Kind::Polynomial => span.trial(curve, &span.fit_polynomial()?),
        Kind::Rational => {
            // The least-squares fit weights the deviation by turning, not by length, so on
            // a short span near a sharp end the G2 cubic (also a rational cubic, with
            // equal weights) can be the closer of the two: take the better.
            let g2 = span.fit_polynomial().ok();
            let fits = [span.fit_rational(g2.as_ref()).ok(), g2];
            let mut best: Option<Trial> = None;
            for q in fits.iter().flatten() {
                let Ok(trial) = span.trial(curve, q) else {
                    continue;
                };
                let rank = |t: &Trial| {
                    let m = t.piece.monotonicity;
                    (
                        !m.verdict.is_monotone()
                            || (!m.proven && m.verdict != Monotonicity::Constant),
                        t.piece.max_deviation,
                    )
                };
                if best.as_ref().is_none_or(|b| rank(&trial) < rank(b)) {
                    best = Some(trial);
                }
            }
            best.ok_or_else(unfittable)
        }
    }
}

/// A span of the curve in its local frame: start at the origin, start tangent +x, turning
/// left (mirrored when the curve turns right).
pub(super) struct Span {
    pub(super) origin: Point,
    /// (cos, sin) of the start tangent direction in the caller's frame.
    pub(super) rot: Vec2,
    /// Caller's lengths per local length: a power of two near the span's chord, so that the
    /// fit works at size ~1 (exactly) whatever the caller's scale — squared deviations of a
    /// curve of size 1e-157 would otherwise be subnormal: slow and inexact.
    pub(super) scale: f64,
    pub(super) mirror: bool,
    pub(super) phi_a: f64,
    pub(super) phi_b: f64,
    pub(super) turning: f64,
    pub(super) end: Vec2,
    /// |κ| at the two ends.
    pub(super) kappa: [f64; 2],
    /// The curve's arc length at the two ends.
    pub(super) s: [f64; 2],
    pub(super) signed_kappa: [f64; 2],
    /// The Gauss nodes of the objective.
    pub(super) nodes: Vec<Node>,
}

/// A node of the least-squares objective.
pub(super) struct Node {
    /// Turning from the span's start.
    pub(super) phi: f64,
    /// (cos φ, sin φ): the tangent direction there.
    pub(super) dir: Vec2,
    /// Gauss weight.
    pub(super) weight: f64,
    /// The curve's point, local frame.
    pub(super) target: Vec2,
}

/// How to find the parameter of a node.
impl Span {
    fn new(curve: &(impl TurningCurve + ?Sized), phi_a: f64, phi_b: f64) -> Result<Span> {
        let turning = phi_b - phi_a;
        let (mid, half) = (0.5 * (phi_a + phi_b), 0.5 * turning);
        let mut phi = Vec::with_capacity(2 * GAUSS_16.len() + 2);
        phi.push(phi_a);
        for &(x, _) in GAUSS_16.iter().rev() {
            phi.push(mid - half * x);
        }
        for &(x, _) in GAUSS_16.iter() {
            phi.push(mid + half * x);
        }
        phi.push(phi_b);
        let samples = curve.at_turning(&phi)?;
        let (a, b) = (samples[0], samples[samples.len() - 1]);
        let mirror = !curve.turns_left();
        let chord = b.point - a.point;
        let size = chord.x.abs().max(chord.y.abs());
        let scale = if size > 0.0 && size.is_finite() {
            2f64.powi(size.log2().floor() as i32)
        } else {
            1.0
        };
        let mut span = Span {
            origin: a.point,
            rot: Vec2::from_angle(a.theta),
            scale,
            mirror,
            phi_a,
            phi_b,
            turning,
            end: Vec2::ZERO,
            kappa: [a.kappa.abs() * scale, b.kappa.abs() * scale],
            s: [a.s, b.s],
            signed_kappa: [a.kappa, b.kappa],
            nodes: Vec::with_capacity(2 * GAUSS_16.len()),
        };
        span.end = span.local(b.point);
        let weights = GAUSS_16
            .iter()
            .rev()
            .chain(GAUSS_16.iter())
            .map(|&(_, w)| w * half);
        for ((f, s), w) in phi[1..]
            .iter()
            .zip(&samples[1..samples.len() - 1])
            .zip(weights)
        {
            let phi = f - phi_a;
            span.nodes.push(Node {
                phi,
                dir: Vec2::from_angle(phi),
                weight: w,
                target: span.local(s.point),
            });
        }
        Ok(span)
    }

    pub(super) fn local(&self, p: Point) -> Vec2 {
        let d = (p - self.origin) / self.scale;
        let (c, s) = (self.rot.x, self.rot.y);
        let v = Vec2::new(c * d.x + s * d.y, -s * d.x + c * d.y);
        if self.mirror {
            Vec2::new(v.x, -v.y)
        } else {
            v
        }
    }

    fn caller(&self, v: Vec2) -> Point {
        let v = if self.mirror { Vec2::new(v.x, -v.y) } else { v } * self.scale;
        let (c, s) = (self.rot.x, self.rot.y);
        self.origin + Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
    }

    /// The intersection of the end tangents: (a, 0).
    fn apex(&self) -> f64 {
        let (s, c) = self.turning.sin_cos();
        (self.end.x * s - self.end.y * c) / s
    }

    /// Homogeneous local control points of the seed's construction for (u, v).
    fn rational(&self, u: f64, v: f64) -> Option<[Hom; 4]> {
        let a = self.apex();
        let big_w = (2.0 * (0.5 * self.turning).cos() + 1.0) / 3.0;
        let cy = self.end.y;
        let e = self.end - Vec2::new(a, 0.0);
        let k0 = self.kappa[0] * 1.5 * big_w * a * a / cy;
        let k3 = self.kappa[1] * 1.5 * big_w * e.hypot().powi(3) / (a * cy);
        let (w0, w3) = (k0 * u * u / (1.0 - v), k3 * v * v / (1.0 - u));
        let b2 = self.end + v * (Vec2::new(a, 0.0) - self.end);
        let q = [
            [0.0, 0.0, w0],
            [big_w * u * a, 0.0, big_w],
            [big_w * b2.x, big_w * b2.y, big_w],
            [w3 * self.end.x, w3 * self.end.y, w3],
        ];
        let ok = a > 0.0
            && cy > 0.0
            && w0 > 0.0
            && w3 > 0.0
            && q.iter().flatten().all(|x| x.is_finite());
        ok.then_some(q)
    }

    pub(super) fn initial_ts(&self) -> Vec<f64> {
        self.nodes.iter().map(|n| n.phi / self.turning).collect()
    }

    /// The seed's rational cubic: (u, v) minimising F by Levenberg–Marquardt.
    /// `g2`: the span's G2 plain cubic, when it has one (a starting point).
    fn fit_rational(&self, g2: Option<&[Hom; 4]>) -> Result<[Hom; 4]> {
        let c = (0.5 * self.turning).cos();
        let p = [2.0 * c / (1.0 + 2.0 * c); 2];
        let eval = |p: [f64; 2], ts: &mut Vec<f64>, r: &mut Vec<f64>, how: Solve| -> Option<f64> {
            let q = self.rational(p[0], p[1])?;
            self.residuals(&Candidate::new(q), ts, r, how)
        };
        // F has long curved valleys with several local minima for asymmetric triangles (seed
        // 001 §6 reports them too). Start from the best of: the circular arc's fractions
        // (exact for an isosceles triangle), the leg fractions of the G2 plain cubic (often
        // in the global basin), and a coarse grid.
        let g2 = g2.map(|q| {
            let a = self.apex();
            let e = (self.end - Vec2::new(a, 0.0)).hypot();
            [
                q[1][0] / a,
                (Vec2::new(q[2][0], q[2][1]) - self.end).hypot() / e,
            ]
        });
        let grid = (1..=2).flat_map(|i| (1..=2).map(move |j| [i as f64 / 3.0, j as f64 / 3.0]));
        let mut starts: Vec<([f64; 2], f64)> = Vec::with_capacity(11);
        let (mut warm, mut residuals) = (self.initial_ts(), Vec::new());
        for guess in std::iter::once(p).chain(g2).chain(grid) {
            if !guess.iter().all(|&x| x > 0.0 && x < 1.0) {
                continue;
            }
            // The parameters of the previous start are a close first guess for this one's.
            let mut trial_ts = warm.clone();
            if let Some(f) = eval(guess, &mut trial_ts, &mut residuals, Solve::Converge) {
                starts.push((guess, f));
                warm = trial_ts;
            }
        }
        starts.sort_by(|a, b| a.1.total_cmp(&b.1));
        let first = *starts.first().ok_or_else(unfittable)?;
        // Descend from the best start and from the best one that lies apart from it, and
        // keep the lower end: the best start may sit in the valley of a local minimum.
        let other = starts
            .iter()
            .find(|s| (s.0[0] - first.0[0]).abs().max((s.0[1] - first.0[1]).abs()) > 0.2);
        let mut best = self.levenberg_marquardt(first.0, SETTLED);
        if let Some(other) = other {
            // A rough descent first; it is finished only if it gets below the first.
            if let Some(probe) = self.levenberg_marquardt(other.0, ROUGH) {
                if best.is_none_or(|b| probe.1 < b.1) {
                    best = self.levenberg_marquardt(probe.0, SETTLED).or(Some(probe));
                }
            }
        }
        let p = best.ok_or_else(unfittable)?.0;
        self.rational(p[0], p[1]).ok_or_else(unfittable)
    }

    /// Levenberg–Marquardt on (u, v) from `p0` until a step is below `settle.0` or improves
    /// F by less than `settle.1` relative: the parameters reached and F there.
    fn levenberg_marquardt(&self, p0: [f64; 2], settle: (f64, f64)) -> Option<([f64; 2], f64)> {
        let eval = |p: [f64; 2], ts: &mut Vec<f64>, r: &mut Vec<f64>, how: Solve| -> Option<f64> {
            let q = self.rational(p[0], p[1])?;
            self.residuals(&Candidate::new(q), ts, r, how)
        };
        let (mut ts0, mut r0) = (self.initial_ts(), Vec::new());
        let f0 = eval(p0, &mut ts0, &mut r0, Solve::Converge)?;
        let (mut p, mut ts, mut r, mut f) = (p0, ts0, r0, f0);
        // An exact fit (the circular arc of an isosceles triangle) stays exact.
        let exact = (1e-15 * self.end.hypot()).powi(2) * self.turning;
        let mut lambda = 1e-3;
        let (mut r1, mut r2, mut tmp) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..100 {
            if f <= exact {
                break;
            }
            // Forward-difference Jacobian (the residuals are exact, so this only affects the
            // rate of convergence, not the optimum).
            let h = [1e-7 * p[0].max(1e-3), 1e-7 * p[1].max(1e-3)];
            let mut ts1 = ts.clone();
            let mut ts2 = ts.clone();
            // One Newton step from the current parameters is exact to O(h²) here.
            let ok1 = eval([p[0] + h[0], p[1]], &mut ts1, &mut r1, Solve::OneStep).is_some();
            let ok2 = eval([p[0], p[1] + h[1]], &mut ts2, &mut r2, Solve::OneStep).is_some();
            if !(ok1 && ok2) {
                break;
            }
            let (mut a11, mut a12, mut a22, mut g1, mut g2) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for i in 0..r.len() {
                let j1 = (r1[i] - r[i]) / h[0];
                let j2 = (r2[i] - r[i]) / h[1];
                a11 += j1 * j1;
                a12 += j1 * j2;
                a22 += j2 * j2;
                g1 += j1 * r[i];
                g2 += j2 * r[i];
            }
            let mut improved = false;
            let mut small_step = false;
            while lambda < 1e12 {
                let (b11, b22) = (a11 * (1.0 + lambda), a22 * (1.0 + lambda));
                let det = b11 * b22 - a12 * a12;
                if det.is_nan() || det <= 0.0 {
                    lambda *= 10.0;
                    continue;
                }
                let mut d = [(-g1 * b22 + g2 * a12) / det, (-g2 * b11 + g1 * a12) / det];
                // Stay inside (0, 1)².
                for k in 0..2 {
                    if p[k] + d[k] >= 1.0 {
                        d[k] = 0.5 * (1.0 - p[k]);
                    }
                    if p[k] + d[k] <= 0.0 {
                        d[k] = -0.5 * p[k];
                    }
                }
                let trial = [p[0] + d[0], p[1] + d[1]];
                let mut tts = ts.clone();
                match eval(trial, &mut tts, &mut tmp, Solve::Converge) {
                    Some(ft) if ft < f => {
                        // (u, v) are settled to ~1e-9 once F stops improving beyond its
                        // rounding; further steps only chase noise.
                        small_step =
                            d[0].abs().max(d[1].abs()) < settle.0 || f - ft <= settle.1 * f;
                        p = trial;
                        f = ft;
                        ts = tts;
                        std::mem::swap(&mut r, &mut tmp);
                        lambda = (lambda * 0.2).max(1e-12);
                        improved = true;
                        break;
                    }
                    _ => lambda *= 8.0,
                }
            }
            if !improved || small_step {
                break;
            }
        }
        Some((p, f))
    }

    /// The piece for local homogeneous control points `q`, with its deviation and verdict.
    fn trial(&self, curve: &(impl TurningCurve + ?Sized), q: &[Hom; 4]) -> Result<Trial> {
        let cand = Candidate::new(*q);
        // Both in the caller's units: the local frame is scaled by `scale`.
        let (integral, _) = self.integral(&cand).ok_or_else(unfittable)?;
        // Relative to the curve's length squared: in the caller's units it would overflow
        // for curves of size 1e155.
        let integral = integral * (self.scale / curve.length()).powi(2);
        let max_deviation = if has_flat_end(curve) {
            self.max_distance(curve, &cand)?
        } else {
            self.max_deviation(curve, &cand)?
        } * self.scale;
        let curve_q = self.to_caller(q)?;
        let monotonicity = curve_q.curvature_monotonicity()?;
        Ok(Trial {
            fitted: Fitted {
                piece: QuasiPiece {
                    curve: curve_q,
                    monotonicity,
                    // The ends exactly as asked: the next piece starts where this one ends.
                    turning: (self.phi_a, self.phi_b),
                    max_deviation,
                },
                integral,
            },
            end_kappa: self.signed_kappa,
        })
    }

    /// The caller's rational cubic for local homogeneous control points.
    fn to_caller(&self, q: &[Hom; 4]) -> Result<RationalCubic> {
        let points = q.map(|h| self.caller(Vec2::new(h[0] / h[2], h[1] / h[2])));
        // Normalise so that w₁ = w₂ keep the seed's value and w₀, w₃ scale with them.
        RationalCubic::new(points, q.map(|h| h[2]))
    }
}

/// A candidate curve in the local frame, ready for repeated evaluation.
pub(super) struct Candidate {
    /// Power-basis coefficients of the homogeneous P(t).
    c: [Hom; 4],
    /// Power-basis coefficients of V = p′w − pw′ (degree 4; the t⁵ terms cancel).
    v: [[f64; 5]; 2],
}

impl Candidate {
    pub(super) fn new(q: [Hom; 4]) -> Self {
        let c = power_basis(&q);
        let mut v = [[0.0; 5]; 2];
        for (i, vi) in v.iter_mut().enumerate() {
            // p′w − pw′ = Σ (a − b) cₐ[i] c_b[w] tᵃ⁺ᵇ⁻¹; the a = b terms vanish, t⁵ with them.
            for a in 0..4 {
                for b in 0..4 {
                    if a != b {
                        vi[a + b - 1] += (a as f64 - b as f64) * c[a][i] * c[b][2];
                    }
                }
            }
        }
        Candidate { c, v }
    }

    pub(super) fn point(&self, t: f64) -> Vec2 {
        let e =
            |i: usize| self.c[0][i] + t * (self.c[1][i] + t * (self.c[2][i] + t * self.c[3][i]));
        let w = e(2);
        Vec2::new(e(0) / w, e(1) / w)
    }

    /// The weight w(t).
    pub(super) fn weight(&self, t: f64) -> f64 {
        self.c[0][2] + t * (self.c[1][2] + t * (self.c[2][2] + t * self.c[3][2]))
    }

    /// V(t) and V′(t).
    pub(super) fn hodograph(&self, t: f64) -> (Vec2, Vec2) {
        let ev = |p: &[f64; 5]| {
            let mut v = p[4];
            let mut d = 0.0;
            for k in (0..4).rev() {
                d = d * t + v;
                v = v * t + p[k];
            }
            (v, d)
        };
        let (x, dx) = ev(&self.v[0]);
        let (y, dy) = ev(&self.v[1]);
        (Vec2::new(x, y), Vec2::new(dx, dy))
    }
}
