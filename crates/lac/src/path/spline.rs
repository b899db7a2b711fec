//! G2 splines through points (the interpolating mode, like Clothoids' G2 spline and Spiro):
//! every span between consecutive points is one log-aesthetic [`Segment`], whose control
//! triangle is the chord and the intersection of the tangent lines at its ends, or, for
//! α < 0, one log-aesthetic curve continued through its inflection (an S: two segments that
//! meet at zero curvature, see `s_span`). The unknowns are the tangent angles at the points;
//! the equations, curvature continuity at the interior points (every point of a closed
//! spline). The curvatures at the ends of span i depend on the angles at its two ends only,
//! so the Jacobian is tridiagonal (cyclic when closed) and Newton's method solves it like a
//! path's joints.
//!
//! A span is a single segment where one fits its end tangents (they leave the chord on
//! opposite sides and the triangle is drawable) and an S otherwise. For α ≥ 0 no curve
//! reaches zero curvature, so a span that would need an S is refused, named, with
//! [`G2Failure::SpanInflects`]; so is a point where the curvature would have to be zero.

use std::f64::consts::{PI, TAU};

use kurbo::{Point, Vec2};

use super::s_span::{SSpan, Unit, HAIR};
use super::{
    banded, joint_limits, Closure, G2_JUMP_LIMIT, G2_TOLERANCE, INFLECTION_LIMIT,
    MAX_POLYGON_POINTS,
};
use crate::curve::chain::SegmentChain;
use crate::curve::{check_total_length, Curve};
use crate::foundation::error::G2Failure;
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::length;
use crate::segment::{check_alpha, end_curvatures_of, Segment};

/// The signed end curvatures of every span.
type Ends = Vec<(f64, f64)>;

/// Most Newton steps.
const MAX_STEPS: usize = 60;
/// Most stages of the continuation in α.
const MAX_STAGES: f64 = 12.0;
/// Step of the forward differences in the tangent angles, radians.
const H: f64 = 1e-7;
/// Largest change of any tangent angle in one step, radians.
const MAX_STEP: f64 = 0.2;
/// An S whose half turns by less than this (radians) has its inflection within a hair of
/// a point.
const TINY_HALF: f64 = 1e-3;

/// A G2 spline of log-aesthetic segments through given points.
///
/// ```
/// use kurbo::Point;
/// use lac::{Closure, Curve, Spline};
///
/// let points = [
///     Point::new(0.0, 0.0), Point::new(2.0, 0.3), Point::new(3.5, 1.5), Point::new(4.0, 3.0),
/// ];
/// let spline = Spline::from_points(&points, 0.5, Closure::Open, None)?;
/// assert!(spline.max_curvature_jump() <= 1e-9);
/// assert!((spline.end_point() - points[3]).hypot() < 1e-12);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Spline {
    points: Vec<Point>,
    closed: bool,
    angles: Vec<f64>,
    /// Control triangle of every piece.
    triangles: Vec<[Point; 3]>,
    segments: Vec<Segment>,
    /// The span of every piece.
    spans_of_pieces: Vec<usize>,
    jumps: Vec<f64>,
    inflections: Vec<SplineInflection>,
}

/// Where a span of a [`Spline`] passes through an inflection, as measured on its two
/// segments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplineInflection {
    /// The span (from point `span` to the next).
    pub span: usize,
    /// The inflection point.
    pub point: Point,
    /// Signed curvature at the end of the segment before it and the start of the one after
    /// it (within [`INFLECTION_LIMIT`] of the spline's largest |κ| at a point).
    pub curvatures: [f64; 2],
    /// Distance between the two segments' ends there, caller's units.
    pub gap: f64,
}

/// The shape of one span: one segment (its control triangle) or an S.
#[derive(Clone, Copy, Debug)]
enum Shape {
    Plain([Point; 3]),
    S(SSpan),
}

/// The wrapped angle in (−π, π].
fn wrap(a: f64) -> f64 {
    a - TAU * ((a + PI) / TAU).floor()
}

fn dir(v: Vec2) -> f64 {
    v.y.atan2(v.x)
}

impl Spline {
    /// The G2 spline through `points` (at least 3; the first repeated last of a closed one
    /// is dropped) with slope `alpha`, open or closed (`closure`); an open spline's end tangent
    /// directions are `ends` (radians) or those of the circles through its first and last
    /// three points.
    ///
    /// Errors: [`Error::NoG2Spline`] naming the span (from point `span` to the next) that
    /// must inflect ([`G2Failure::SpanInflects`]) or where the curvature could not be made
    /// continuous, or [`Error::SplineSpan`] naming the span whose segment cannot be drawn;
    /// bad input.
    pub fn from_points(
        points: &[Point],
        alpha: f64,
        closure: Closure,
        ends: Option<[f64; 2]>,
    ) -> Result<Spline> {
        check_alpha("alpha", alpha)?;
        let closed = closure == Closure::Closed;
        let mut points = points.to_vec();
        if closed && points.len() > 3 && points.first() == points.last() {
            points.pop();
        }
        let n = points.len();
        if !(3..=MAX_POLYGON_POINTS).contains(&n) {
            return Err(Error::OutOfRange {
                name: "number of points",
                value: n as f64,
                expected: "at least 3 points and at most 100000",
            });
        }
        for p in &points {
            finite("point x", p.x)?;
            finite("point y", p.y)?;
        }
        let spans = if closed { n } else { n - 1 };
        for i in 0..spans {
            let j = (i + 1) % n;
            if points[i] == points[j] {
                return Err(Error::CoincidentPoints {
                    first: i,
                    second: j,
                });
            }
            let d = points[j] - points[i];
            if !d.x.hypot(d.y).is_finite() {
                return Err(Error::OutOfRange {
                    name: "points",
                    value: f64::INFINITY,
                    expected: "coordinates whose differences do not overflow",
                });
            }
        }
        if let Some(e) = ends {
            finite("start angle", e[0])?;
            finite("end angle", e[1])?;
        }
        let mut s = Spline {
            points,
            closed,
            angles: Vec::new(),
            triangles: Vec::new(),
            segments: Vec::new(),
            spans_of_pieces: Vec::new(),
            jumps: Vec::new(),
            inflections: Vec::new(),
        };
        s.solve(alpha, ends)?;
        check_total_length(&s)?;
        Ok(s)
    }

    fn spans(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 1
        }
    }

    /// The shape of span `i` for tangent angles `phi` at slope `alpha` (`unit` is the
    /// unit curve through the inflection, for α < 0) and its signed end curvatures, or why
    /// it has none.
    fn shape(
        &self,
        alpha: f64,
        unit: Option<&Unit>,
        phi: &[f64],
        i: usize,
    ) -> Result<(Shape, (f64, f64))> {
        let n = self.points.len();
        let (a, b) = (self.points[i], self.points[(i + 1) % n]);
        let (ta, tb) = self.tangents(phi, i);
        let c = length(b - a);
        let s_span = || self.s_span_at(unit, phi, i);
        // One segment turns one way: its tangents leave and reach the chord from opposite
        // sides, and turn by less than π.
        if ta * tb < 0.0 && ta.abs() + tb.abs() < PI {
            let u = c * tb.abs().sin() / (ta.abs() + tb.abs()).sin();
            let t = [a, a + Vec2::from_angle(phi[i]) * u, b];
            return match end_curvatures_of(t, alpha) {
                Ok(k) => Ok((Shape::Plain(t), k)),
                Err(e) => match s_span() {
                    Some(s) => Ok((Shape::S(s), s.end_curvatures())),
                    None => Err(Error::SplineSpan {
                        span: i,
                        // Points near 1e308 can put the tangents' meeting point beyond double
                        // range: say so, not that an input was infinite.
                        source: Box::new(if t[1].x.is_finite() && t[1].y.is_finite() {
                            e
                        } else {
                            Error::Unrepresentable {
                                what: "control triangle of a span (where its end \
                                       tangents meet)",
                            }
                        }),
                    }),
                },
            };
        }
        match s_span() {
            Some(s) => Ok((Shape::S(s), s.end_curvatures())),
            None => Err(Error::NoG2Spline {
                span: i,
                reason: G2Failure::SpanInflects,
            }),
        }
    }

    /// The angles of span `i`'s end tangents from its chord, in (−π, π].
    fn tangents(&self, phi: &[f64], i: usize) -> (f64, f64) {
        let n = self.points.len();
        let psi = dir(self.points[(i + 1) % n] - self.points[i]);
        (wrap(phi[i] - psi), wrap(phi[(i + 1) % n] - psi))
    }

    /// Span `i` as an S, if one fits its end tangents (only for α < 0).
    fn s_span_at(&self, unit: Option<&Unit>, phi: &[f64], i: usize) -> Option<SSpan> {
        let n = self.points.len();
        let (ta, tb) = self.tangents(phi, i);
        let c = length(self.points[(i + 1) % n] - self.points[i]);
        unit.and_then(|u| u.s_span(ta, tb, c))
    }

    /// End curvatures of every span.
    fn curvatures(&self, alpha: f64, unit: Option<&Unit>, phi: &[f64]) -> Result<Ends> {
        (0..self.spans())
            .map(|i| Ok(self.shape(alpha, unit, phi, i)?.1))
            .collect()
    }

    /// The points whose curvature is continuous in a solved spline (the interior points;
    /// every point when closed).
    fn unknowns(&self) -> Vec<usize> {
        let n = self.points.len();
        if self.closed {
            (0..n).collect()
        } else {
            (1..n - 1).collect()
        }
    }

    /// A length at each unknown point: the mean of its two chords.
    fn lengths(&self) -> Vec<f64> {
        let n = self.points.len();
        let p = &self.points;
        self.unknowns()
            .iter()
            .map(|&j| 0.5 * (length(p[j] - p[(j + n - 1) % n]) + length(p[(j + 1) % n] - p[j])))
            .collect()
    }

    /// The residual at each unknown point, (κ⁻ − κ⁺) times its length: unlike ln|κ⁻/κ⁺|,
    /// it is smooth where the curvature changes sign, so that Newton's method can move a
    /// span between a segment and an S (where one end's curvature passes through zero).
    fn residual(&self, k: &[(f64, f64)], lengths: &[f64]) -> Vec<f64> {
        let n = self.points.len();
        self.unknowns()
            .iter()
            .zip(lengths)
            .map(|(&j, l)| (k[(j + n - 1) % n].1 - k[j % k.len()].0) * l)
            .collect()
    }

    /// The relative curvature jump |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|) at each unknown point.
    fn jumps(&self, k: &[(f64, f64)]) -> Vec<f64> {
        let n = self.points.len();
        self.unknowns()
            .iter()
            .map(|&j| {
                let (before, after) = (k[(j + n - 1) % n].1, k[j % k.len()].0);
                (before - after).abs() / before.abs().max(after.abs())
            })
            .collect()
    }

    fn solve(&mut self, alpha: f64, ends: Option<[f64; 2]>) -> Result<()> {
        let n = self.points.len();
        let p = &self.points;
        let at = |i: usize| p[i % n];
        // Start: the tangents of the circles through each point and its neighbours.
        // (The tangent at B of the circle through A, B, C is dir AB + dir BC − dir AC.)
        let circle = |a: Point, b: Point, c: Point| {
            dir(b - a) + wrap(dir(c - b) - dir(b - a)) - wrap(dir(c - a) - dir(b - a))
        };
        let mut phi: Vec<f64> = (0..n)
            .map(|i| {
                if self.closed || (i > 0 && i + 1 < n) {
                    circle(at(i + n - 1), at(i), at(i + 1))
                } else {
                    0.0
                }
            })
            .collect();
        if !self.closed {
            let delta0 = wrap(dir(p[2] - p[1]) - dir(p[1] - p[0]));
            let delta1 = wrap(dir(p[n - 1] - p[n - 2]) - dir(p[n - 2] - p[n - 3]));
            let [s, e] =
                ends.unwrap_or([dir(p[2] - p[0]) - delta0, dir(p[n - 1] - p[n - 3]) + delta1]);
            phi[0] = s;
            phi[n - 1] = e;
        }
        // For α < 0 every pair of end tangents has a segment or an S (up to half-turns of
        // π), so Newton's method starts at α itself from the circles' tangents.
        if alpha < 0.0 {
            if let Ok((p2, r)) = self.newton(alpha, phi.clone()) {
                if r.iter().all(|x| *x <= 0.5 * G2_JUMP_LIMIT) && self.finish(alpha, p2, r).is_ok()
                {
                    return Ok(());
                }
            }
        }
        // Otherwise, continuation in α from the nearest of [0, 1] (where the circles'
        // tangents are drawable for any sensible points), each stage warm-started from the
        // last.
        let start = alpha.clamp(0.0, 1.0);
        // (Steps of 0.25 in α, at most MAX_STAGES of them: each stage is a Newton solve.)
        let stages = ((alpha - start).abs() / 0.25).ceil().clamp(0.0, MAX_STAGES) as usize;
        let mut last = Err(Error::NumericalFailure {
            what: "the spline's continuation in alpha",
        });
        for stage in 0..=stages {
            let a = if stage == stages {
                alpha
            } else {
                start + (alpha - start) * stage as f64 / stages.max(1) as f64
            };
            last = self.newton(a, phi.clone());
            match &last {
                Ok((p2, _)) => phi = p2.clone(),
                Err(_) if stage == 0 && stages > 0 => {
                    // The circles' tangents do not solve at α in [0, 1]: try α directly.
                    last = self.newton(alpha, phi.clone());
                    break;
                }
                Err(_) => break,
            }
        }
        let (phi, r) = last?;
        self.finish(alpha, phi, r)
    }

    /// Newton's method on the unknown angles of `phi` at slope `alpha`: the angles and
    /// relative curvature jumps reached, or the span that fails at the start.
    fn newton(&self, alpha: f64, mut phi: Vec<f64>) -> Result<(Vec<f64>, Vec<f64>)> {
        let n = self.points.len();
        let unit = Unit::new(alpha);
        let unknowns = self.unknowns();
        let lengths = self.lengths();
        let eval = |phi: &[f64]| -> Result<(Ends, Vec<f64>)> {
            let k = self.curvatures(alpha, unit.as_ref(), phi)?;
            let r = self.residual(&k, &lengths);
            Ok((k, r))
        };
        let norm = |r: &[f64]| r.iter().map(|x| x * x).sum::<f64>().sqrt();
        let (mut k, mut r) = eval(&phi)?;
        for _ in 0..MAX_STEPS {
            if self.jumps(&k).iter().all(|x| *x <= G2_TOLERANCE) {
                break;
            }
            // ∂κ_start, ∂κ_end of each span in the angles at its two ends.
            let spans = self.spans();
            let mut d = vec![[[0.0; 2]; 2]; spans];
            for (i, di) in d.iter_mut().enumerate() {
                for (e, end) in [i, (i + 1) % n].into_iter().enumerate() {
                    let mut moved = phi.clone();
                    moved[end] += H;
                    let Ok((_, (a, b))) = self.shape(alpha, unit.as_ref(), &moved, i) else {
                        continue;
                    };
                    di[e] = [(a - k[i].0) / H, (b - k[i].1) / H];
                }
            }
            let m = unknowns.len();
            let (mut sub, mut diag, mut sup) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
            for (u, &j) in unknowns.iter().enumerate() {
                let (before, after) = ((j + n - 1) % n, j % spans);
                // R_j = (κ_end(before) − κ_start(after)) · l_j
                diag[u] = (d[before][1][1] - d[after][0][0]) * lengths[u];
                sub[u] = d[before][0][1] * lengths[u];
                sup[u] = -d[after][1][0] * lengths[u];
            }
            let rhs: Vec<f64> = r.iter().map(|x| -x).collect();
            let Some(dx) = banded::solve(&sub, &diag, &sup, &rhs, self.closed) else {
                break;
            };
            let big = dx.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let mut lambda = if big > MAX_STEP { MAX_STEP / big } else { 1.0 };
            let now = norm(&r);
            let mut next = None;
            for _ in 0..30 {
                let mut trial = phi.clone();
                for (u, &j) in unknowns.iter().enumerate() {
                    trial[j] += lambda * dx[u];
                }
                if let Ok((k2, r2)) = eval(&trial) {
                    if norm(&r2) < now * (1.0 - 1e-4 * lambda) {
                        next = Some((trial, k2, r2));
                        break;
                    }
                }
                lambda *= 0.5;
            }
            let Some((p2, k2, r2)) = next else { break };
            (phi, k, r) = (p2, k2, r2);
        }
        let jumps = self.jumps(&k);
        Ok((phi, jumps))
    }

    /// Check the answer of the last stage and build the segments.
    fn finish(&mut self, alpha: f64, phi: Vec<f64>, r: Vec<f64>) -> Result<()> {
        let n = self.points.len();
        let unknowns = self.unknowns();
        let (worst, jump) = r.iter().enumerate().fold((0, 0.0f64), |(i, m), (j, x)| {
            if x.abs() > m || x.is_nan() {
                (j, x.abs())
            } else {
                (i, m)
            }
        });
        if jump > 0.5 * G2_JUMP_LIMIT {
            return Err(Error::NoG2Spline {
                span: unknowns[worst],
                reason: G2Failure::NoConvergence { jump },
            });
        }
        // The checked segments (two for an S span), and the joints measured on them.
        let unit = Unit::new(alpha);
        let (mut triangles, mut segments, mut spans_of_pieces) = (vec![], vec![], vec![]);
        let mut inflection_points = Vec::new();
        for i in 0..self.spans() {
            let piece = |t: [Point; 3]| {
                Segment::from_control_points(t, alpha).map_err(|e| Error::SplineSpan {
                    span: i,
                    source: Box::new(e),
                })
            };
            let (a, b) = (self.points[i], self.points[(i + 1) % n]);
            let mut s_span = |s: SSpan| -> Result<Vec<Segment>> {
                inflection_points.push((i, s.inflection(a, b)));
                let halves = s.halves(a, b, HAIR);
                triangles.extend(halves);
                // A half that cannot be drawn lies too near the edge of the drawable
                // region for the segment solver: its inflection end is unresolved, or the
                // inflection falls within a hair of a point (the half turns by almost
                // nothing, its triangle flat to the rounding of its angles).
                let reason = if s.theta[0].min(s.theta[1]) < TINY_HALF {
                    G2Failure::InflectionAtPoint
                } else {
                    G2Failure::InflectionUnresolved { alpha }
                };
                halves
                    .into_iter()
                    .map(|t| {
                        Segment::from_control_points(t, alpha).map_err(|_| Error::NoG2Spline {
                            span: i,
                            reason: reason.clone(),
                        })
                    })
                    .collect()
            };
            let built = match self.shape(alpha, unit.as_ref(), &phi, i)?.0 {
                Shape::Plain(t) => match piece(t) {
                    Ok(segment) => {
                        triangles.push(t);
                        vec![segment]
                    }
                    // At the edge of the drawable region, where a segment's curvature
                    // reaches zero at one end, the S family continues it.
                    Err(e) => match self.s_span_at(unit.as_ref(), &phi, i) {
                        Some(s) => s_span(s)?,
                        None => return Err(e),
                    },
                },
                Shape::S(s) => s_span(s)?,
            };
            for segment in built {
                segments.push(segment);
                spans_of_pieces.push(i);
            }
        }
        let size = self
            .points
            .iter()
            .map(|q| length(*q - self.points[0]))
            .fold(0.0, f64::max);
        // The curvature scale: the largest |κ| at a point.
        let scale = segments
            .iter()
            .zip(&spans_of_pieces)
            .enumerate()
            .flat_map(|(k, (seg, &span))| {
                let (k0, k1) = seg.end_curvatures();
                let first = k == 0 || spans_of_pieces[k - 1] != span;
                let last = k + 1 == segments.len() || spans_of_pieces[k + 1] != span;
                [if first { k0 } else { 0.0 }, if last { k1 } else { 0.0 }]
            })
            .fold(0.0f64, |m, k| m.max(k.abs()));
        let pairs = if self.closed {
            segments.len()
        } else {
            segments.len() - 1
        };
        let failure = || Error::NumericalFailure {
            what: "the spline's joint check (a point's position, tangent or curvature does \
                   not match)",
        };
        let (gap_limit, tangent_limit) = joint_limits(&self.points, size);
        let (mut jumps, mut inflections) = (Vec::new(), Vec::new());
        for k in 0..pairs {
            let next = (k + 1) % segments.len();
            let (a, b) = (&segments[k], &segments[next]);
            let gap = length(a.end_point() - b.start_point());
            let dt = wrap(
                a.theta_of(&a.station_at_turning(a.turning_angle())?)
                    - b.theta_of(&b.station_at_turning(0.0)?),
            );
            let (k0, k1) = (a.end_curvatures().1, b.end_curvatures().0);
            if gap.is_nan() || gap > gap_limit {
                return Err(failure());
            }
            if dt.is_nan() || dt.abs() > tangent_limit {
                return Err(Error::NoG2Spline {
                    span: spans_of_pieces[next],
                    reason: G2Failure::TangentUnresolved { jump: dt.abs() },
                });
            }
            if spans_of_pieces[k] == spans_of_pieces[next] {
                // The two halves of an S, at the inflection.
                let flat = k0.abs().max(k1.abs());
                if !(flat <= INFLECTION_LIMIT * scale && k0 * k1 <= 0.0) {
                    return Err(Error::NoG2Spline {
                        span: spans_of_pieces[k],
                        reason: G2Failure::InflectionUnresolved { alpha },
                    });
                }
                let span = spans_of_pieces[k];
                let point = inflection_points
                    .iter()
                    .find(|(i, _)| *i == span)
                    .map_or(a.end_point(), |(_, p)| *p);
                inflections.push(SplineInflection {
                    span,
                    point,
                    curvatures: [k0, k1],
                    gap,
                });
            } else {
                let jump = (k0 - k1).abs() / k0.abs().max(k1.abs());
                if !(jump <= G2_JUMP_LIMIT && jump.is_finite()) {
                    // Newton's answer met the tolerance on the curvatures it computed; the
                    // segments as built differ from them (a curvature near zero at a
                    // point, where both ends' digits are few).
                    return Err(Error::NoG2Spline {
                        span: spans_of_pieces[next],
                        reason: G2Failure::NoConvergence { jump },
                    });
                }
                jumps.push(jump);
            }
        }
        self.angles = phi;
        self.triangles = triangles;
        self.segments = segments;
        self.spans_of_pieces = spans_of_pieces;
        self.jumps = jumps;
        self.inflections = inflections;
        Ok(())
    }

    /// The points it passes through.
    pub fn points(&self) -> &[Point] {
        &self.points
    }

    /// Whether it is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The tangent direction at each point, radians.
    pub fn angles(&self) -> &[f64] {
        &self.angles
    }

    /// The control triangle of each piece as solved: (its first point, the intersection of
    /// its end tangents, its last point), the points exactly as given. A span through an
    /// inflection has two pieces, each ending a hair (1e-12 of its length) short of the
    /// inflection point.
    pub fn control_triangles(&self) -> &[[Point; 3]] {
        &self.triangles
    }

    /// The span of each piece (span i runs from point i to the next): one piece per span,
    /// two for a span through an inflection.
    pub fn spans_of_pieces(&self) -> &[usize] {
        &self.spans_of_pieces
    }

    /// The inflections, one per span that passes through one (only for α < 0), in order.
    pub fn inflections(&self) -> &[SplineInflection] {
        &self.inflections
    }

    /// The relative curvature jump measured at each joint (the interior points; every
    /// point when closed, the last at the first point).
    pub fn curvature_jumps(&self) -> &[f64] {
        &self.jumps
    }

    /// The largest relative curvature jump over the joints.
    pub fn max_curvature_jump(&self) -> f64 {
        self.jumps.iter().fold(0.0, |m, j| m.max(*j))
    }
}

impl SegmentChain for Spline {
    fn pieces(&self) -> &[Segment] {
        &self.segments
    }
}
