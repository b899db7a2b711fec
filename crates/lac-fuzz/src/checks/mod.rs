//! The invariants: what every `Ok` answer must satisfy, checked independently of the
//! solver that produced it.
//!
//! One module per entry point ([`EntryPoint::ALL`](crate::EntryPoint::ALL); `compound`
//! holds both compound curves'), each naming the invariants it asserts. This module sends an
//! input to its checks and holds what several share: the [`bounds`], the curve an input
//! solves to, the checks of a planar curve and its samples, of pieces on their control
//! triangles and where they meet, and distances.

use kurbo::{Point, Vec2};
use lac::{
    Alphas, CompoundCurve, ControlPolygon, Curve, Path, Sample, Segment, SpaceSegment, SpaceShape,
    TorsionType, Vec3,
};
use lac::{Closure, SpaceCurve};
use lac_export::ExportCurve;
use lac_io::json::{ErrorBody, Kind, PathKind, Solved, SpaceKind};

use crate::Input;

mod analysis;
mod compound;
mod export;
mod fit;
mod monotone;
mod path;
mod quasi;
mod segment;
mod space;
mod spline;

/// The bounds the invariants use, as documented in docs/testing.md (Fuzzing).
pub mod bounds {
    /// Ends within this × (chord + the rounding of the inputs' magnitudes).
    pub const POSITION: f64 = 1e-9;
    /// End tangents within this (radians), plus what the position rounding allows.
    pub const TANGENT: f64 = 1e-9;
    /// Curvature at a joint: relative jump.
    pub const JOINT_CURVATURE: f64 = 1e-9;
    /// Curvature at a join of Bézier pieces: jump relative to the curve's largest curvature
    /// (plus what rounding of the control points' absolute coordinates allows).
    pub const QUASI_JOINT_CURVATURE: f64 = 1e-6;
    /// Curvature along a curve may step against its monotone direction by this (relative).
    pub const MONOTONE_SLACK: f64 = 1e-9;
}

/// `Ok(true)`: an answer that met every invariant; `Ok(false)`: a typed error; `Err`: a
/// broken invariant.
pub(crate) fn check(input: &Input) -> Result<bool, String> {
    match input {
        Input::Segment {
            points,
            samples,
            accuracy,
            ..
        } => segment::check(input, points, *samples, *accuracy),
        Input::Compound3 {
            points, samples, ..
        } => compound::check_three(input, points, *samples),
        Input::Compound4 {
            points, samples, ..
        } => compound::check_four(input, points, *samples),
        Input::Monotone { points, weights } => monotone::check(points, *weights),
        Input::Analysis { pieces, per_piece } => analysis::check(pieces, *per_piece),
        Input::Quasi {
            points,
            alpha,
            tolerance,
            cubic,
        } => quasi::check(points, *alpha, *tolerance, *cubic),
        Input::Path { closed, g2, .. } => path::check(input, *closed, *g2),
        Input::Spline { .. } => spline::check(input),
        Input::Space { points, .. } => space::check(input, points),
        Input::Export {
            curve,
            format,
            tolerance,
            relative,
            single_spans,
        } => export::check(curve, *format, *tolerance, *relative, *single_spans),
        Input::Fit {
            points,
            tolerance,
            max_segments,
            alpha,
            closed,
            g1,
            pin_ends,
            huber,
            weights,
        } => fit::check(&fit::Asked {
            points,
            tolerance: *tolerance,
            max_segments: *max_segments,
            alpha: *alpha,
            closed: *closed,
            g1: *g1,
            pin_ends: *pin_ends,
            huber: *huber,
            weights: weights.as_deref(),
        }),
    }
}

/// A solved curve of a solver's input.
enum Built {
    Plane(Solved),
    Path(Path),
    Space(SpaceSegment),
}

impl Built {
    fn as_export(&self) -> Result<ExportCurve<'_>, ErrorBody> {
        match self {
            Built::Plane(s) => Ok(s.export_curve()),
            Built::Path(p) => PathKind::export(p),
            Built::Space(s) => SpaceKind::export(s),
        }
    }

    /// The exact curve's ends and length.
    fn ends(&self) -> Result<([f64; 3], [f64; 3], f64), String> {
        let flat = |p: Point| [p.x, p.y, 0.0];
        match self {
            Built::Plane(s) => {
                let c = s.curve();
                let len = c.arc_length();
                let at = |s| c.point_at_s(s).map(flat).map_err(|e| e.to_string());
                Ok((at(0.0)?, at(len)?, len))
            }
            Built::Path(p) => Ok((flat(p.start_point()), flat(p.end_point()), p.arc_length())),
            Built::Space(s) => {
                let len = s.arc_length();
                let a = s.frame_at_s(0.0).map_err(|e| e.to_string())?.point;
                let b = s.frame_at_s(len).map_err(|e| e.to_string())?.point;
                Ok((a.to_array(), b.to_array(), len))
            }
        }
    }
}

/// The curve an input of a solver describes, or `None` when the solver refuses it.
fn build(input: &Input) -> Result<Option<Built>, String> {
    Ok(match input {
        Input::Segment { points, alpha, .. } | Input::Quasi { points, alpha, .. } => {
            typed(Segment::from_control_points(points.map(pt), *alpha))?
                .map(|s| Built::Plane(Solved::Segment(s)))
        }
        Input::Compound3 {
            points,
            alpha,
            ratio,
            ..
        } => typed(CompoundCurve::from_three_points(
            points.map(pt),
            alpha[0],
            alpha[1],
            *ratio,
        ))?
        .map(|c| Built::Plane(Solved::Compound(c))),
        Input::Compound4 { points, alpha, .. } => typed(CompoundCurve::from_four_points(
            points.map(pt),
            alpha[0],
            alpha[1],
        ))?
        .map(|c| Built::Plane(Solved::Compound(c))),
        Input::Path {
            points,
            alpha,
            closed,
            g2,
        } => {
            let pts: Vec<Point> = points.iter().map(|&p| pt(p)).collect();
            let closure = if *closed {
                Closure::Closed
            } else {
                Closure::Open
            };
            let Some(polygon) = typed(ControlPolygon::from_points(&pts, closure))? else {
                return Ok(None);
            };
            let alphas = match alpha.as_slice() {
                [one] => Alphas::One(*one),
                many => Alphas::PerSegment(many.to_vec()),
            };
            typed(if *g2 {
                Path::from_polygon_g2(&polygon, &alphas)
            } else {
                Path::from_polygon_g1(&polygon, &alphas, None)
            })?
            .map(Built::Path)
        }
        Input::Space {
            points,
            alpha,
            beta,
            omega,
            torsion,
        } => {
            let shape = SpaceShape {
                alpha: *alpha,
                beta: *beta,
                omega: *omega,
                torsion: match TorsionType::from_number(*torsion) {
                    Ok(torsion) => torsion,
                    Err(_) => return Ok(None),
                },
            };
            typed(SpaceSegment::from_control_points(
                points.map(Vec3::from_array),
                shape,
            ))?
            .map(Built::Space)
        }
        Input::Monotone { .. }
        | Input::Analysis { .. }
        | Input::Export { .. }
        | Input::Fit { .. }
        | Input::Spline { .. } => None,
    })
}

/// |a − b| without squaring (points near 1e308).
fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0, |d, (x, y)| d.hypot(x - y))
}

fn pt(p: [f64; 2]) -> Point {
    Point::new(p[0], p[1])
}

fn finite(what: &str, values: &[f64]) -> Result<(), String> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(v) => Err(format!("{what}: a number is not finite ({v})")),
        None => Ok(()),
    }
}

/// What rounding the inputs' absolute coordinates allows in positions.
fn rounding(points: &[Point]) -> f64 {
    let magnitude = points
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()))
        .fold(0.0, f64::max);
    64.0 * f64::EPSILON * magnitude
}

/// The unsigned angle between two directions, radians.
fn angle_between(a: Vec2, b: Vec2) -> f64 {
    a.cross(b).atan2(a.dot(b)).abs()
}

/// A planar curve: finite everywhere; starts on the first leg's start tangent to it, ends
/// on the last leg's end tangent to it; every sampled chord's direction lies between the
/// tangents at its ends; curvature of one sign and monotone; the polyline is no longer than
/// the arc; adaptive samples within the accuracy asked.
fn check_curve(
    curve: &dyn Curve,
    first_leg: &[Point; 2],
    last_leg: &[Point; 2],
    n: usize,
    accuracy: f64,
) -> Result<(), String> {
    let all = [first_leg[0], first_leg[1], last_leg[0], last_leg[1]];
    let len = curve.arc_length();
    finite(
        "arc length and end curvatures",
        &[
            len,
            curve.signed_curvature_start(),
            curve.signed_curvature_end(),
        ],
    )?;
    let (start, end) = (first_leg[0], last_leg[1]);
    let chord = dist(end, start);
    let tol = bounds::POSITION * chord + rounding(&all);
    if !(len > 0.0 && len >= chord * (1.0 - 1e-12) - tol) {
        return Err(format!(
            "arc length {len:e} shorter than the chord {chord:e}"
        ));
    }
    let n_check = n.clamp(2, 2000).max(65);
    let samples = curve
        .sample_by_arc_length(n_check)
        .map_err(|e| format!("sampling a solved curve failed: {e}"))?;
    for s in &samples {
        finite("sample", &[s.s, s.point.x, s.point.y, s.theta, s.kappa])?;
    }
    let (a, b) = (samples[0], samples[samples.len() - 1]);
    if dist(a.point, start) > tol {
        return Err(format!(
            "starts {:e} from the first point",
            dist(a.point, start)
        ));
    }
    if dist(b.point, end) > 64.0 * tol {
        return Err(format!("ends {:e} from the last point", dist(b.point, end)));
    }
    let angle_tol = bounds::TANGENT + 1e3 * tol / chord;
    let leg0 = first_leg[1] - first_leg[0];
    let leg1 = last_leg[1] - last_leg[0];
    if angle_between(a.tangent(), leg0) > angle_tol {
        return Err(format!(
            "start tangent off the first leg by {:e} rad",
            angle_between(a.tangent(), leg0)
        ));
    }
    if angle_between(b.tangent(), leg1) > angle_tol {
        return Err(format!(
            "end tangent off the last leg by {:e} rad",
            angle_between(b.tangent(), leg1)
        ));
    }
    check_samples(&samples, tol, len)?;
    // The requested sampling itself: Ok only for a valid count, and then finite.
    if let Ok(s) = curve.sample_by_arc_length(n) {
        if s.len() != n {
            return Err(format!("asked for {n} samples, got {}", s.len()));
        }
    } else if (2..=10_000_000).contains(&n) {
        return Err(format!("{n} samples refused"));
    }
    if let Some(adaptive) = typed(curve.sample_adaptive(accuracy))? {
        for s in &adaptive {
            finite(
                "adaptive sample",
                &[s.s, s.point.x, s.point.y, s.theta, s.kappa],
            )?;
        }
        // Every equally spaced sample lies within the accuracy of the polyline.
        let mut j = 0;
        for s in &samples {
            while j + 2 < adaptive.len() && adaptive[j + 1].s < s.s {
                j += 1;
            }
            let (p, q) = (adaptive[j].point, adaptive[j + 1].point);
            let d = distance_to_segment(s.point, p, q);
            if d > accuracy * 1.001 + 16.0 * tol {
                return Err(format!(
                    "adaptive polyline {d:e} from the curve (asked {accuracy:e})"
                ));
            }
        }
    }
    // These may refuse with a typed error (dκ/ds beyond double range for tiny curves), but
    // what they return must be finite.
    for p in curve.evolute(9).unwrap_or_default() {
        finite("evolute", &[p.x, p.y])?;
    }
    for p in curve.curvature_plot(9).unwrap_or_default() {
        finite("curvature plot", &[p.s, p.kappa, p.dkappa_ds])?;
    }
    Ok(())
}

/// Samples of a log-aesthetic curve: chord directions between the tangents, curvature of
/// one sign and monotone, the polyline no longer than the arc.
fn check_samples(samples: &[Sample], tol: f64, len: f64) -> Result<(), String> {
    let sign = samples[0].kappa.signum();
    let increasing = samples[samples.len() - 1].kappa.abs() >= samples[0].kappa.abs();
    let mut polyline = 0.0;
    for w in samples.windows(2) {
        let (p, q) = (w[0], w[1]);
        if p.kappa.signum() != sign || q.kappa.signum() != sign {
            return Err("curvature changes sign".to_string());
        }
        let (kp, kq) = (p.kappa.abs(), q.kappa.abs());
        let slack = bounds::MONOTONE_SLACK * kp.max(kq);
        if (increasing && kq < kp - slack) || (!increasing && kq > kp + slack) {
            return Err(format!("curvature not monotone at s = {:e}", q.s));
        }
        if q.s < p.s {
            return Err("samples not ascending in arc length".to_string());
        }
        let d = q.point - p.point;
        let step = dist(q.point, p.point);
        polyline += step;
        // Skip chords that rounding dominates.
        if step > 1e6 * tol {
            let dir = d.atan2();
            let (lo, hi) = (p.theta.min(q.theta), p.theta.max(q.theta));
            let mid = 0.5 * (lo + hi);
            // The chord's direction, unwrapped next to the tangents'.
            let tau = std::f64::consts::TAU;
            let dir = dir + tau * ((mid - dir) / tau).round();
            let allowed = 1e-9 + 4.0 * tol / step;
            if dir < lo - allowed || dir > hi + allowed {
                return Err(format!(
                    "the chord from s = {:e} to {:e} points {:e} rad outside the tangents there",
                    p.s,
                    q.s,
                    (dir - mid).abs() - 0.5 * (hi - lo)
                ));
            }
        }
    }
    if polyline > len * (1.0 + 1e-9) + 64.0 * tol {
        return Err(format!("polyline {polyline:e} longer than the arc {len:e}"));
    }
    Ok(())
}

/// Each piece of a path or spline on its control triangle (ends, end tangents, monotone
/// curvature, chords between tangents).
fn on_triangles(pieces: &[Segment], triangles: &[[Point; 3]]) -> Result<(), String> {
    for (seg, t) in pieces.iter().zip(triangles) {
        check_curve(
            seg,
            &[t[0], t[1]],
            &[t[1], t[2]],
            9,
            1e-3 * seg.arc_length(),
        )?;
    }
    Ok(())
}

/// Piece `k` (`a`) and the next (`b`) of a path or spline of length `size` meet: positions
/// within 64 `tol`, tangents within the tangent bound.
fn meet(a: &Segment, b: &Segment, k: usize, tol: f64, size: f64) -> Result<(), String> {
    let (pa, pb) = (a.end_point(), b.start_point());
    if dist(pa, pb) > 64.0 * tol {
        return Err(format!("pieces {k} and {} {:e} apart", k + 1, dist(pa, pb)));
    }
    let ta = a.theta_at_s(a.arc_length()).map_err(|e| e.to_string())?;
    let tb = b.theta_at_s(0.0).map_err(|e| e.to_string())?;
    let tau = std::f64::consts::TAU;
    let jump = (ta - tb) - tau * ((ta - tb) / tau).round();
    if jump.abs() > bounds::TANGENT + 1e3 * tol / size {
        return Err(format!("tangent jumps {jump:e} rad after piece {k}"));
    }
    Ok(())
}

/// |a − b| without kurbo's overflow of the squares from 1e154 on.
fn dist(a: Point, b: Point) -> f64 {
    (a.x - b.x).hypot(a.y - b.y)
}

/// Distance from `x` to the segment pq, without squaring coordinates (curves of size 1e160).
fn distance_to_segment(x: Point, p: Point, q: Point) -> f64 {
    let len = dist(q, p);
    if len == 0.0 {
        return dist(x, p);
    }
    let u = (q - p) / len;
    let along = ((x - p).dot(u)).clamp(0.0, len);
    dist(x, p + along * u)
}

/// The largest |κ| at an end of any of `pieces`.
fn largest_end_curvature(pieces: &[Segment]) -> f64 {
    pieces
        .iter()
        .map(|p| {
            p.signed_curvature_start()
                .abs()
                .max(p.signed_curvature_end().abs())
        })
        .fold(0.0, f64::max)
}

/// An error that is lac's own defect (a numerical failure), not a refusal of the input.
pub(super) trait Defect: std::fmt::Display {
    /// Is it a defect?
    fn is_defect(&self) -> bool;
}

impl Defect for lac::Error {
    fn is_defect(&self) -> bool {
        self.kind() == lac::ErrorKind::NumericalFailure
    }
}

impl Defect for lac_export::Error {
    fn is_defect(&self) -> bool {
        matches!(self, lac_export::Error::Lac(e) if e.is_defect())
    }
}

impl Defect for ErrorBody {
    fn is_defect(&self) -> bool {
        matches!(self.kind.as_str(), "numerical_failure" | "internal")
    }
}

/// The answer of a call, `None` for a typed refusal, and a violation for a numerical
/// failure: every input either solves or is refused with an error that names it.
pub(super) fn typed<T, E: Defect>(result: Result<T, E>) -> Result<Option<T>, String> {
    match result {
        Ok(answer) => Ok(Some(answer)),
        Err(e) if e.is_defect() => Err(format!("a numerical failure, not a typed error: {e}")),
        Err(_) => Ok(None),
    }
}
