//! Quasi-aesthetic curves: rational (or plain) cubic Bézier replacements of a
//! log-aesthetic segment or compound curve (seed 001 §4, SPEC §5), one piece as in the
//! seed or as many as a tolerance needs.
//!
//! **One piece** over a span of the curve turning by Θ (seed 001): b₀ and b₃ are the span's
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
//! the same angle φ from their start tangents (the seed's correspondence), integrated by
//! 16-point Gauss–Legendre in φ, by Levenberg–Marquardt. F has several valleys: the starts
//! are the circular arc's u = v = 2c/(1 + 2c), c = cos(Θ/2) (the exact answer for an
//! isosceles triangle), the G2 plain cubic's leg fractions and a 2×2 grid; the best start is
//! descended, and a rough descent from the best start lying apart is finished if it wins.
//! t(φ) solves det(d_φ, V(t)) = 0 with V = p′w − pw′ (quartic in t) by safeguarded Newton.
//!
//! **Plain cubics** (all weights 1) have no freedom left once the ends, end tangents and end
//! curvatures are fixed: the leg lengths solve the G2 Hermite system
//! (3/2)κ₀δ₀² = det(t₀, C) − δ₁ sin Θ, (3/2)κ₁δ₁² = det(C, t₁) − δ₀ sin Θ, a quartic in δ₀;
//! of its admissible roots the one with the smallest deviation is taken.
//!
//! **Deviation**: rms = √(∫ d² dφ / Θ) and max = max d(φ), both divided by the curve's arc
//! length; the maximum is found on 64 equal steps of φ per piece and refined at the vertex
//! of the parabola through the largest sample and its neighbours.
//!
//! **Tolerance**: pieces are taken greedily from the first point, each as long as possible
//! (guided by the error model d ∝ Θ⁶ of a G2 cubic) with max ≤ tolerance and curvature
//! proven monotone in the curve's direction. Neighbouring pieces share the curve's point,
//! tangent and curvature at their join, so the chain is G2.

use kurbo::{Point, Vec2};

use crate::bezier::{power_basis, Hom, RationalCubic};
use crate::compound::CompoundCurve;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::gauss::GAUSS_16;
use crate::monotone::{Monotonicity, MonotonicityReport};
use crate::segment::Sample;
use crate::segment::Segment;
use crate::turn::Turn;

/// One piece of a [`QuasiCurve`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuasiPiece {
    /// The rational cubic (all weights equal for plain cubics).
    pub curve: RationalCubic,
    /// Its curvature monotonicity, decided with a proof.
    pub monotonicity: MonotonicityReport,
    /// The turning of the original curve, from its start, at the piece's two ends (radians,
    /// non-negative, ascending).
    pub turning: (f64, f64),
    /// Largest distance d(φ) to the original curve over the piece (caller's units).
    pub max_deviation: f64,
}

/// A chain of cubic Bézier pieces replacing a log-aesthetic curve, with its deviation.
///
/// ```
/// use kurbo::Point;
/// use lac::{Monotonicity, Segment};
///
/// let seg = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.0, 0.8)],
///     -1.0,
/// )?;
/// // The seed's single rational cubic …
/// let one = seg.to_rational_cubic()?;
/// assert_eq!(one.pieces.len(), 1);
/// assert!(one.max < 1e-2);
/// // … or as many as a tolerance of 1e-9 of the arc length needs.
/// let fine = seg.to_rational_cubics(1e-9)?;
/// assert!(fine.max <= 1e-9);
/// assert!(fine.pieces.iter().all(|p| p.monotonicity.proven
///     && p.monotonicity.verdict == Monotonicity::Increasing));
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct QuasiCurve {
    /// The pieces in order from the curve's first control point.
    pub pieces: Vec<QuasiPiece>,
    /// √(∫ d(φ)² dφ / Θ) divided by the original curve's arc length.
    pub rms: f64,
    /// max d(φ) divided by the original curve's arc length.
    pub max: f64,
}

/// Smallest accepted tolerance, relative to the arc length.
const MIN_TOLERANCE: f64 = 1e-12;
/// Most pieces a tolerance may ask for.
const MAX_PIECES: usize = 100_000;

impl Segment {
    /// One rational cubic with the segment's ends, end tangents and end curvatures, closest
    /// to it in the least-squares sense of seed 001 (see the module documentation).
    pub fn to_rational_cubic(&self) -> Result<QuasiCurve> {
        approximate(self, None, Kind::Seed)
    }

    /// As few rational cubics as needed for a maximum deviation of `tolerance` × arc length,
    /// each with proven monotone curvature, joined G2.
    pub fn to_rational_cubics(&self, tolerance: f64) -> Result<QuasiCurve> {
        approximate(self, Some(tolerance), Kind::Rational)
    }

    /// As few plain (polynomial) cubics as needed for a maximum deviation of
    /// `tolerance` × arc length, each with proven monotone curvature, joined G2; for
    /// consumers that only take cubics (SVG paths, fonts).
    pub fn to_cubics(&self, tolerance: f64) -> Result<QuasiCurve> {
        approximate(self, Some(tolerance), Kind::Polynomial)
    }
}

impl CompoundCurve {
    /// One rational cubic for the whole compound curve (see [`Segment::to_rational_cubic`]).
    pub fn to_rational_cubic(&self) -> Result<QuasiCurve> {
        approximate(self, None, Kind::Seed)
    }

    /// Rational cubics within `tolerance` × arc length (see
    /// [`Segment::to_rational_cubics`]).
    pub fn to_rational_cubics(&self, tolerance: f64) -> Result<QuasiCurve> {
        approximate(self, Some(tolerance), Kind::Rational)
    }

    /// Plain cubics within `tolerance` × arc length (see [`Segment::to_cubics`]).
    pub fn to_cubics(&self, tolerance: f64) -> Result<QuasiCurve> {
        approximate(self, Some(tolerance), Kind::Polynomial)
    }
}

/// A curve with monotone curvature of one sign, evaluated by its turning φ ∈ [0, Θ] from
/// the start tangent.
pub(crate) trait TurningCurve {
    /// Total turning Θ, radians, in (0, 2π).
    fn total_turning(&self) -> f64;
    /// Does it turn left (positive curvature)?
    fn turns_left(&self) -> bool;
    /// Arc length.
    fn length(&self) -> f64;
    /// Signed curvature at the start and at the end.
    fn end_curvatures(&self) -> (f64, f64);
    /// Samples where the tangent has turned by each of `phi` (ascending, within [0, Θ]).
    fn at_turning(&self, phi: &[f64]) -> Result<Vec<Sample>>;
}

impl<C: Curve + ?Sized> TurningCurve for C {
    fn total_turning(&self) -> f64 {
        self.pieces().iter().map(Segment::turning_angle).sum()
    }

    fn turns_left(&self) -> bool {
        self.pieces()[0].turn() == Turn::Left
    }

    fn length(&self) -> f64 {
        self.arc_length()
    }

    fn end_curvatures(&self) -> (f64, f64) {
        (self.curvature_start(), self.curvature_end())
    }

    fn at_turning(&self, phi: &[f64]) -> Result<Vec<Sample>> {
        let pieces = self.pieces();
        let mut out = Vec::with_capacity(phi.len());
        let (mut next, mut turned, mut start) = (0, 0.0, 0.0);
        for (i, piece) in pieces.iter().enumerate() {
            let turning = piece.turning_angle();
            let last = i + 1 == pieces.len();
            let mut stations = Vec::new();
            while next < phi.len() && (last || phi[next] <= turned + turning) {
                stations.push(piece.station_at_turning(phi[next] - turned)?);
                next += 1;
            }
            if !stations.is_empty() {
                out.extend(piece.samples_at(&stations).into_iter().map(|s| Sample {
                    s: s.s + start,
                    ..s
                }));
            }
            turned += turning;
            start += piece.length();
        }
        Ok(out)
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    /// The seed's least-squares rational cubic.
    Seed,
    /// The better of the seed's fit and the G2 cubic.
    Rational,
    /// The G2 plain cubic.
    Polynomial,
}

fn approximate(
    curve: &impl TurningCurve,
    tolerance: Option<f64>,
    kind: Kind,
) -> Result<QuasiCurve> {
    let length = curve.length();
    let total = curve.total_turning();
    let (k0, k1) = curve.end_curvatures();
    let expected = expected_direction(k0, k1);
    let pieces = match tolerance {
        None => vec![fit_span(curve, 0.0, total, kind)?.fitted],
        Some(tol) => {
            if !(tol.is_finite() && (MIN_TOLERANCE..=1.0).contains(&tol)) {
                return Err(Error::OutOfRange {
                    name: "tolerance",
                    value: tol,
                    expected: "a tolerance (relative to the arc length) between 1e-12 and 1",
                });
            }
            greedy(curve, tol * length, kind, expected)?
        }
    };
    let (mut integral, mut max) = (0.0, 0.0f64);
    for p in &pieces {
        integral += p.integral;
        max = max.max(p.piece.max_deviation);
    }
    Ok(QuasiCurve {
        pieces: pieces.into_iter().map(|p| p.piece).collect(),
        rms: (integral / total).sqrt() / length,
        max: max / length,
    })
}

/// The verdict a faithful piece must have: that of the curve (constant for an arc).
fn expected_direction(k0: f64, k1: f64) -> Monotonicity {
    if (k1 - k0).abs() <= 1e-12 * k0.abs().max(k1.abs()) {
        Monotonicity::Constant
    } else if k1 > k0 {
        Monotonicity::Increasing
    } else {
        Monotonicity::Decreasing
    }
}

/// Is this piece's monotonicity the curve's, proven (or constant within rounding where the
/// curve's curvature hardly changes over the piece)?
fn faithful(piece: &QuasiPiece, expected: Monotonicity, k0: f64, k1: f64) -> bool {
    let m = piece.monotonicity;
    match m.verdict {
        Monotonicity::Constant => {
            expected == Monotonicity::Constant || (k1 - k0).abs() <= 1e-9 * k0.abs().max(k1.abs())
        }
        v => m.proven && v == expected,
    }
}

struct Fitted {
    piece: QuasiPiece,
    /// ∫ d² dφ over the piece.
    integral: f64,
}

fn greedy(
    curve: &impl TurningCurve,
    tol: f64,
    kind: Kind,
    expected: Monotonicity,
) -> Result<Vec<Fitted>> {
    let total = curve.total_turning();
    // Accept a little below the tolerance: the maximum found is a value attained, within
    // about 1e-6 (relative) of the true maximum.
    let accept = tol * (1.0 - 1e-4);
    let mut out: Vec<Fitted> = Vec::new();
    let mut start = 0.0;
    let mut width = total;
    while start < total {
        if out.len() >= MAX_PIECES {
            return Err(Error::ToleranceNotMet {
                tolerance: tol / curve.length(),
                reached: f64::INFINITY,
            });
        }
        let remaining = total - start;
        width = width.min(remaining);
        let mut best: Option<(f64, Fitted)> = None;
        let mut worst_seen = f64::INFINITY;
        for _ in 0..16 {
            // Never leave a sliver: a remainder shorter than half a piece is shared out.
            if width < remaining && remaining - width < 0.5 * width {
                width = 0.5 * remaining;
            }
            let end = if width >= remaining {
                total
            } else {
                start + width
            };
            let (error, accepted) = match fit_span(curve, start, end, kind) {
                Ok(trial) => {
                    let error = trial.piece.max_deviation;
                    let [ka, kb] = trial.end_kappa;
                    // A plain cubic cannot have constant curvature: for a circular arc
                    // only the deviation is asked of it.
                    let ok = error <= accept
                        && ((kind == Kind::Polynomial && expected == Monotonicity::Constant)
                            || faithful(&trial.piece, expected, ka, kb));
                    (error, ok.then_some(trial.fitted))
                }
                Err(_) => (f64::INFINITY, None),
            };
            if let Some(fitted) = accepted {
                let done = width >= remaining;
                best = Some((width, fitted));
                // Grow when the error model promises a clearly longer piece.
                let grow = (accept / error.max(f64::MIN_POSITIVE)).powf(1.0 / 6.0) * 0.97;
                if done || grow < 1.05 {
                    break;
                }
                width = (width * grow.min(2.0)).min(remaining);
            } else {
                worst_seen = worst_seen.min(error);
                let shrink = if error.is_finite() {
                    ((accept / error).powf(1.0 / 6.0) * 0.9).clamp(0.2, 0.9)
                } else {
                    0.5
                };
                let smaller = width * shrink;
                if let Some((w, _)) = &best {
                    if smaller <= *w {
                        break;
                    }
                }
                width = smaller;
                if width < 1e-9 * total {
                    break;
                }
            }
        }
        let Some((w, fitted)) = best else {
            return Err(Error::ToleranceNotMet {
                tolerance: tol / curve.length(),
                reached: worst_seen / curve.length(),
            });
        };
        start = fitted.piece.turning.1;
        out.push(fitted);
        width = w;
    }
    Ok(out)
}

/// A fitted span with the signed curvatures of the curve at its ends.
struct Trial {
    fitted: Fitted,
    end_kappa: [f64; 2],
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

/// Deviation samples per piece for the maximum.
const CHECK_STEPS: usize = 64;

fn fit_span(curve: &impl TurningCurve, phi_a: f64, phi_b: f64, kind: Kind) -> Result<Trial> {
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
struct Span {
    origin: Point,
    /// (cos, sin) of the start tangent direction in the caller's frame.
    rot: Vec2,
    mirror: bool,
    phi_a: f64,
    phi_b: f64,
    turning: f64,
    end: Vec2,
    /// |κ| at the two ends.
    kappa: [f64; 2],
    signed_kappa: [f64; 2],
    /// The Gauss nodes of the objective.
    nodes: Vec<Node>,
}

/// A node of the least-squares objective.
struct Node {
    /// Turning from the span's start.
    phi: f64,
    /// (cos φ, sin φ): the tangent direction there.
    dir: Vec2,
    /// Gauss weight.
    weight: f64,
    /// The curve's point, local frame.
    target: Vec2,
}

/// How to find the parameter of a node.
#[derive(Clone, Copy)]
enum Solve {
    /// To full precision.
    Converge,
    /// One Newton step from the previous value (for finite differences).
    OneStep,
}

impl Span {
    fn new(curve: &impl TurningCurve, phi_a: f64, phi_b: f64) -> Result<Span> {
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
        let mut span = Span {
            origin: a.point,
            rot: Vec2::from_angle(a.theta),
            mirror,
            phi_a,
            phi_b,
            turning,
            end: Vec2::ZERO,
            kappa: [a.kappa.abs(), b.kappa.abs()],
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

    fn local(&self, p: Point) -> Vec2 {
        let d = p - self.origin;
        let (c, s) = (self.rot.x, self.rot.y);
        let v = Vec2::new(c * d.x + s * d.y, -s * d.x + c * d.y);
        if self.mirror {
            Vec2::new(v.x, -v.y)
        } else {
            v
        }
    }

    fn caller(&self, v: Vec2) -> Point {
        let v = if self.mirror { Vec2::new(v.x, -v.y) } else { v };
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

    /// Residuals √gⱼ (x(tⱼ) − Lⱼ), updating the parameters `ts` in place.
    fn residuals(
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
    fn integral(&self, cand: &Candidate) -> Option<(f64, Vec<f64>)> {
        let mut ts = self.initial_ts();
        let mut r = Vec::new();
        let sum = self.residuals(cand, &mut ts, &mut r, Solve::Converge)?;
        Some((sum, ts))
    }

    fn initial_ts(&self) -> Vec<f64> {
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

    /// The plain cubic of the G2 Hermite data with the smallest deviation.
    fn fit_polynomial(&self) -> Result<[Hom; 4]> {
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
        let top = (big_a / k0).sqrt();
        const STEPS: usize = 64;
        let mut best: Option<(f64, [Hom; 4])> = None;
        let mut prev = (0.0, f(0.0));
        for i in 1..=STEPS {
            let x = top * i as f64 / STEPS as f64;
            let fx = f(x);
            if prev.1 == 0.0 || prev.1.signum() != fx.signum() {
                let root = bisect(&f, prev.0, x);
                let (d0, e1) = (root, d1(root));
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

    /// max d(φ) over the span, caller's units: on 64 equal steps of the candidate's t (about
    /// equal steps of arc length, so that a stretch of small curvature, where φ hardly
    /// changes, is not passed over), each paired with the curve's point at the candidate's
    /// tangent direction there; refined at the vertex of the parabola through each large
    /// local maximum and its neighbours.
    fn max_deviation(&self, curve: &impl TurningCurve, cand: &Candidate) -> Result<f64> {
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

    /// The candidate's turning at `t`, within [0, Θ], unwrapped next to `near`.
    fn turning_at(&self, cand: &Candidate, t: f64, near: f64) -> f64 {
        let (v, _) = cand.hodograph(t);
        let raw = v.y.atan2(v.x);
        let tau = std::f64::consts::TAU;
        let phi = raw + tau * ((near - raw) / tau).round();
        phi.clamp(0.0, self.turning)
    }

    /// The piece for local homogeneous control points `q`, with its deviation and verdict.
    fn trial(&self, curve: &impl TurningCurve, q: &[Hom; 4]) -> Result<Trial> {
        let cand = Candidate::new(*q);
        let (integral, _) = self.integral(&cand).ok_or_else(unfittable)?;
        let max_deviation = self.max_deviation(curve, &cand)?;
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

fn bisect(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

fn unfittable() -> Error {
    Error::FitFailed
}

/// A candidate curve in the local frame, ready for repeated evaluation.
struct Candidate {
    /// Power-basis coefficients of the homogeneous P(t).
    c: [Hom; 4],
    /// Power-basis coefficients of V = p′w − pw′ (degree 4; the t⁵ terms cancel).
    v: [[f64; 5]; 2],
}

impl Candidate {
    fn new(q: [Hom; 4]) -> Self {
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

    fn point(&self, t: f64) -> Vec2 {
        let e =
            |i: usize| self.c[0][i] + t * (self.c[1][i] + t * (self.c[2][i] + t * self.c[3][i]));
        let w = e(2);
        Vec2::new(e(0) / w, e(1) / w)
    }

    /// V(t) and V′(t).
    fn hodograph(&self, t: f64) -> (Vec2, Vec2) {
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

    /// One Newton step on det(dir, V(t)) = 0 from `t`.
    fn newton_step(&self, dir: Vec2, t: f64) -> f64 {
        let (v, dv) = self.hodograph(t);
        t - dir.cross(v) / dir.cross(dv)
    }

    /// The parameter in [lo, 1] where the tangent has direction `dir`: Newton on
    /// det(dir, V(t)) from `guess`, and where that fails to settle quickly on a root with
    /// the right direction, Newton safeguarded by bisection.
    fn solve_t(&self, dir: Vec2, lo: f64, guess: f64) -> Option<f64> {
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
            (dir.cross(v), dir.cross(dv))
        };
        let (mut a, mut b) = (lo, 1.0);
        let (ha, hb) = (h(a).0, h(b).0);
        if ha > 0.0 || hb < 0.0 {
            // The tangent direction is not between those at lo and 1: the candidate turns
            // the wrong way somewhere.
            if ha.abs() <= 1e-15 * self.hodograph(a).0.hypot() {
                return Some(a);
            }
            if hb.abs() <= 1e-15 * self.hodograph(b).0.hypot() {
                return Some(b);
            }
            return None;
        }
        let mut t = guess.clamp(a, b);
        for _ in 0..100 {
            let (f, df) = h(t);
            if f == 0.0 {
                return Some(t);
            }
            if f < 0.0 {
                a = t;
            } else {
                b = t;
            }
            let mut next = t - f / df;
            if !(next > a && next < b) {
                next = 0.5 * (a + b);
            }
            if (next - t).abs() <= 4.0 * f64::EPSILON * t.abs().max(1e-3) || b - a <= f64::EPSILON {
                return Some(next);
            }
            t = next;
        }
        Some(t)
    }
}
