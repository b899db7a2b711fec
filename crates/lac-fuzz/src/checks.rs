//! The invariants: what every `Ok` answer must satisfy, checked independently of the
//! solver that produced it.

use kurbo::{ParamCurve, Point, Vec2};
use lac::{
    curvature_plot, log_curvature_graph, Alphas, CompoundCurve, ControlPolygon, Curve,
    Monotonicity, Path, QuasiCurve, RationalCubic, Sample, Segment, SpaceSegment, SpaceShape,
    Spline, Tolerance, TorsionType, Vec3, INFLECTION_LIMIT,
};

use lac_export::json::{ExportDocument, NurbsRow};
use lac_export::{ExportCurve, Exported, Format, Meta};
use lac_io::json::Solved;

use crate::Input;

/// The bounds the invariants use, as documented in the README's robustness section.
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
        } => {
            let pts = points.map(pt);
            let Some(Built::Plane(Solved::Segment(seg))) = build(input) else {
                return Ok(false);
            };
            check_curve(
                &seg,
                &[pts[0], pts[1]],
                &[pts[1], pts[2]],
                *samples,
                *accuracy,
            )?;
            let lcg = seg.lcg();
            if let Some(line) = lcg {
                finite(
                    "lcg",
                    &[line.alpha, line.intercept, line.log_rho.0, line.log_rho.1],
                )?;
            }
            Ok(true)
        }
        Input::Compound3 {
            points, samples, ..
        } => {
            let pts = points.map(pt);
            let Some(Built::Plane(Solved::Compound(c))) = build(input) else {
                return Ok(false);
            };
            check_curve(&c, &[pts[0], pts[1]], &[pts[1], pts[2]], *samples, 1e-6)?;
            check_joints(&c)?;
            Ok(true)
        }
        Input::Compound4 {
            points, samples, ..
        } => {
            let pts = points.map(pt);
            let Some(Built::Plane(Solved::Compound(c))) = build(input) else {
                return Ok(false);
            };
            check_curve(&c, &[pts[0], pts[1]], &[pts[2], pts[3]], *samples, 1e-6)?;
            check_joints(&c)?;
            // The joint's tangent is parallel to the middle leg.
            let leg = pts[2] - pts[1];
            let theta = c.theta_at_s(c.joint_s()).map_err(|e| e.to_string())?;
            let off = angle_between(Vec2::from_angle(theta), leg);
            let allowed = bounds::TANGENT + rounding(&pts) / leg.x.hypot(leg.y) * 1e3;
            if off > allowed {
                return Err(format!("joint tangent off the middle leg by {off:e} rad"));
            }
            Ok(true)
        }
        Input::Monotone { points, weights } => {
            let Ok(curve) = RationalCubic::new(points.map(pt), *weights) else {
                return Ok(false);
            };
            let Ok(report) = curve.curvature_monotonicity() else {
                return Ok(false);
            };
            check_verdict(&curve, report.verdict, report.proven)?;
            Ok(true)
        }
        Input::Analysis { pieces, per_piece } => {
            let Ok(curves) = pieces
                .iter()
                .map(|(p, w)| RationalCubic::new(p.map(pt), *w))
                .collect::<lac::Result<Vec<_>>>()
            else {
                return Ok(false);
            };
            let Ok(plot) = curvature_plot(&curves, *per_piece) else {
                return Ok(false);
            };
            for p in &plot {
                finite(
                    "curvature plot",
                    &[p.s, p.point.x, p.point.y, p.kappa, p.dkappa_ds],
                )?;
            }
            let graph = log_curvature_graph(&plot);
            for (x, y) in &graph.points {
                finite("logarithmic curvature graph", &[*x, *y])?;
            }
            if let Some(fit) = graph.fit {
                finite(
                    "LCG fit",
                    &[
                        fit.alpha,
                        fit.intercept,
                        fit.rms_residual,
                        fit.max_residual,
                        fit.log_rho.0,
                        fit.log_rho.1,
                    ],
                )?;
            }
            Ok(true)
        }
        Input::Quasi {
            points,
            alpha,
            tolerance,
            cubic,
        } => {
            let pts = points.map(pt);
            let Ok(seg) = Segment::from_control_points(pts, *alpha) else {
                return Ok(false);
            };
            let fit = match (tolerance, cubic) {
                (None, _) => seg.to_rational_cubic(),
                (Some(t), false) => seg.to_rational_cubics(Tolerance::Relative(*t)),
                (Some(t), true) => seg.to_cubics(Tolerance::Relative(*t)),
            };
            let Ok(quasi) = fit else {
                return Ok(false);
            };
            check_quasi(&seg, &pts, &quasi, *tolerance)?;
            Ok(true)
        }
        Input::Path { closed, g2, .. } => {
            let Some(Built::Path(path)) = build(input) else {
                return Ok(false);
            };
            check_path(&path, *closed, *g2)?;
            Ok(true)
        }
        Input::Spline {
            points,
            alpha,
            closed,
            ends,
        } => {
            let pts: Vec<Point> = points.iter().map(|&p| pt(p)).collect();
            let Ok(spline) = Spline::g2(&pts, *alpha, *closed, *ends) else {
                return Ok(false);
            };
            check_spline(&spline)?;
            Ok(true)
        }
        Input::Space { points, .. } => {
            let pts = points.map(Vec3::from_array);
            let Some(Built::Space(seg)) = build(input) else {
                return Ok(false);
            };
            check_space(&seg, &pts)?;
            check_space_cubics(&seg)?;
            Ok(true)
        }
        Input::Export {
            curve,
            format,
            tolerance,
            relative,
            single_spans,
        } => {
            let Some(built) = build(curve) else {
                return Ok(false);
            };
            let tolerance = if *relative {
                Tolerance::Relative(*tolerance)
            } else {
                Tolerance::Absolute(*tolerance)
            };
            let Ok(exported) = lac_export::export(
                &built.as_export(),
                *format,
                tolerance,
                *single_spans,
                &Meta {
                    name: "fuzz".to_string(),
                    timestamp: "2026-11-23T00:00:00".to_string(),
                    version: "0".to_string(),
                },
            ) else {
                return Ok(false);
            };
            check_export(&built, tolerance, &exported)?;
            Ok(true)
        }
    }
}

/// A solved curve of a solver's input.
enum Built {
    Plane(Solved),
    Path(Path),
    Space(SpaceSegment),
}

impl Built {
    fn as_export(&self) -> ExportCurve<'_> {
        match self {
            Built::Plane(s) => ExportCurve::from(s),
            Built::Path(p) => ExportCurve::Path(p),
            Built::Space(s) => ExportCurve::Space(s),
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
                let a = s.frame_at(0.0).map_err(|e| e.to_string())?.point;
                let b = s.frame_at(len).map_err(|e| e.to_string())?.point;
                Ok((a.to_array(), b.to_array(), len))
            }
        }
    }
}

/// The curve an input of a solver describes, or `None` when the solver refuses it.
fn build(input: &Input) -> Option<Built> {
    match input {
        Input::Segment { points, alpha, .. } | Input::Quasi { points, alpha, .. } => {
            Segment::from_control_points(points.map(pt), *alpha)
                .ok()
                .map(|s| Built::Plane(Solved::Segment(s)))
        }
        Input::Compound3 {
            points,
            alpha,
            ratio,
            ..
        } => CompoundCurve::from_three_points(points.map(pt), alpha[0], alpha[1], *ratio)
            .ok()
            .map(|c| Built::Plane(Solved::Compound(c))),
        Input::Compound4 { points, alpha, .. } => {
            CompoundCurve::from_four_points(points.map(pt), alpha[0], alpha[1])
                .ok()
                .map(|c| Built::Plane(Solved::Compound(c)))
        }
        Input::Path {
            points,
            alpha,
            closed,
            g2,
        } => {
            let pts: Vec<Point> = points.iter().map(|&p| pt(p)).collect();
            let polygon = if *closed {
                ControlPolygon::closed(&pts)
            } else {
                ControlPolygon::open(&pts)
            }
            .ok()?;
            let alphas = match alpha.as_slice() {
                [one] => Alphas::One(*one),
                many => Alphas::PerSegment(many.to_vec()),
            };
            if *g2 {
                Path::g2(&polygon, &alphas, None)
            } else {
                Path::g1(&polygon, &alphas, None)
            }
            .ok()
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
                torsion: TorsionType::from_number(*torsion).ok()?,
            };
            SpaceSegment::from_control_points(points.map(Vec3::from_array), shape)
                .ok()
                .map(Built::Space)
        }
        Input::Monotone { .. }
        | Input::Analysis { .. }
        | Input::Export { .. }
        | Input::Spline { .. } => None,
    }
}

/// An export: a report of finite figures whose measured deviation is within the tolerance
/// asked; a document without a non-finite number; for JSON, well-formed clamped B-splines
/// (knots ascending, weights positive) that start and end at the exact curve's ends, the
/// pieces of `--pieces` meeting end to start, evaluated here by de Boor's algorithm.
fn check_export(built: &Built, tolerance: Tolerance, exported: &Exported) -> Result<(), String> {
    let report = &exported.report;
    let (start, end, len) = built.ends()?;
    finite(
        "export report",
        &[
            report.tolerance,
            report.max_deviation,
            report.fit_deviation,
            report.arc_length,
        ],
    )?;
    let asked = match tolerance {
        Tolerance::Absolute(t) => t,
        Tolerance::Relative(t) => t * len,
    };
    if (report.tolerance - asked).abs() > 1e-12 * asked {
        return Err(format!(
            "export tolerance {:e} reported for {asked:e} asked",
            report.tolerance
        ));
    }
    // Both finite (checked above).
    if report.max_deviation > report.tolerance || report.pieces == 0 {
        return Err(format!(
            "export deviation {:e} over its tolerance {:e} ({} pieces)",
            report.max_deviation, report.tolerance, report.pieces
        ));
    }
    let doc = &exported.document;
    if doc.is_empty() || doc.contains("NaN") || doc.contains("inf") {
        return Err(format!("{:?} document empty or not finite", report.format));
    }
    if report.format != Format::Json {
        return Ok(());
    }
    let parsed: ExportDocument =
        serde_json::from_str(doc).map_err(|e| format!("export JSON does not parse: {e}"))?;
    let magnitude = start.iter().chain(&end).fold(0.0f64, |m, x| m.max(x.abs()));
    let near = report.tolerance + 64.0 * f64::EPSILON * magnitude;
    let mut previous_end: Option<Vec<f64>> = None;
    for row in &parsed.curves {
        let n = row.control_points.len();
        let well_formed = row.degree == 3
            && n >= 4
            && row.weights.len() == n
            && row.knots.len() == n + 4
            && row.knots.windows(2).all(|w| w[0] <= w[1])
            && row.knots[3] < row.knots[n]
            && row.weights.iter().all(|w| w.is_finite() && *w > 0.0)
            && row
                .control_points
                .iter()
                .all(|p| p.len() == row.dimension && p.iter().all(|x| x.is_finite()));
        if !well_formed {
            return Err("exported B-spline malformed".to_string());
        }
        let a = nurbs_point(row, row.knots[3]);
        if let Some(b) = &previous_end {
            if distance(&a, b) > near {
                return Err(format!("exported pieces apart by {:e}", distance(&a, b)));
            }
        }
        previous_end = Some(nurbs_point(row, row.knots[n]));
    }
    let first = parsed.curves.first().map(|r| nurbs_point(r, r.knots[3]));
    let last = previous_end;
    for (what, got, want) in [("start", first, start), ("end", last, end)] {
        let got = got.ok_or("an export without curves")?;
        if distance(&got, &want) > near {
            return Err(format!(
                "exported curve's {what} {:e} from the exact one's (tolerance {:e})",
                distance(&got, &want),
                report.tolerance
            ));
        }
    }
    Ok(())
}

fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// The point at `u` of a clamped rational cubic B-spline, by de Boor's algorithm in
/// homogeneous coordinates.
fn nurbs_point(row: &NurbsRow, u: f64) -> Vec<f64> {
    const P: usize = 3;
    let (k, n, dim) = (&row.knots, row.control_points.len(), row.dimension);
    let mut i = P;
    while i + 1 < n && k[i + 1] <= u {
        i += 1;
    }
    let mut d: Vec<Vec<f64>> = (0..=P)
        .map(|j| {
            let w = row.weights[i - P + j];
            let mut h: Vec<f64> = row.control_points[i - P + j]
                .iter()
                .map(|x| x * w)
                .collect();
            h.push(w);
            h
        })
        .collect();
    for r in 1..=P {
        for j in (r..=P).rev() {
            let a = (u - k[i - P + j]) / (k[i + 1 + j - r] - k[i - P + j]);
            let prev = d[j - 1].clone();
            for (x, y) in d[j].iter_mut().zip(prev) {
                *x = (1.0 - a) * y + a * *x;
            }
        }
    }
    let w = d[P][dim];
    let mut p: Vec<f64> = d[P][..dim].iter().map(|x| x / w).collect();
    p.resize(3, 0.0);
    p
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
        &[len, curve.curvature_start(), curve.curvature_end()],
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
    if let Ok(adaptive) = curve.sample_adaptive(accuracy) {
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

/// A path: each segment on its control triangle (ends, end tangents, monotone curvature,
/// chords between tangents); consecutive segments (and the last and first of a closed path)
/// meet with continuous position and tangent, and curvature too in G2; the whole is finite.
fn check_path(path: &Path, closed: bool, g2: bool) -> Result<(), String> {
    let pieces = path.segments();
    let triangles = path.control_triangles();
    if pieces.len() != triangles.len() || pieces.is_empty() {
        return Err(format!(
            "{} segments for {} control triangles",
            pieces.len(),
            triangles.len()
        ));
    }
    finite("arc length", &[path.arc_length()])?;
    on_triangles(pieces, &triangles)?;
    let all: Vec<Point> = triangles.iter().flatten().copied().collect();
    let size = path.arc_length();
    let tol = bounds::POSITION * size + rounding(&all);
    // The whole path sampled: finite everywhere.
    for q in path
        .sample_by_arc_length(65)
        .map_err(|e| format!("sampling a solved path failed: {e}"))?
    {
        finite(
            "path sample",
            &[q.s, q.point.x, q.point.y, q.theta, q.kappa],
        )?;
    }
    // Segments meet one another directly only where no straight piece (an inflection leg)
    // lies between them; those joints are the path's own check (its joints list).
    if !path.straight_pieces().is_empty() {
        return Ok(());
    }
    let pairs = pieces.len() - usize::from(!closed);
    let kmax = pieces
        .iter()
        .map(|p| p.curvature_start().abs().max(p.curvature_end().abs()))
        .fold(0.0, f64::max);
    for i in 0..pairs {
        let (a, b) = (&pieces[i], &pieces[(i + 1) % pieces.len()]);
        meet(a, b, i, tol, size)?;
        let (ka, kb) = (a.curvature_end(), b.curvature_start());
        if g2 && (ka - kb).abs() > bounds::JOINT_CURVATURE * kmax {
            return Err(format!(
                "curvature jumps after segment {i}: {ka:e} to {kb:e}"
            ));
        }
    }
    Ok(())
}

/// A spline: each piece on its control triangle (ends, end tangents, monotone curvature,
/// chords between tangents); each span from its point to the next; consecutive pieces meet
/// with continuous position and tangent, with curvature continuous (relative) at the points
/// and zero on both sides (with a sign change) at a span's inflection.
fn check_spline(spline: &Spline) -> Result<(), String> {
    let pieces = spline.pieces();
    let triangles = spline.control_triangles();
    let spans = spline.spans_of_pieces();
    let points = spline.points();
    if pieces.len() != triangles.len() || pieces.len() != spans.len() || pieces.is_empty() {
        return Err("pieces, triangles and spans disagree in number".to_string());
    }
    finite("arc length", &[spline.arc_length()])?;
    on_triangles(pieces, triangles)?;
    let all: Vec<Point> = triangles.iter().flatten().copied().collect();
    let size = spline.arc_length();
    let tol = bounds::POSITION * size + rounding(&all);
    let n = pieces.len();
    let kmax = pieces
        .iter()
        .map(|p| p.curvature_start().abs().max(p.curvature_end().abs()))
        .fold(0.0, f64::max);
    for k in 0..n {
        let i = spans[k];
        let first = k == 0 || spans[k - 1] != i;
        let last = k + 1 == n || spans[k + 1] != i;
        let (a, b) = (points[i], points[(i + 1) % points.len()]);
        if first && dist(pieces[k].start_point(), a) > 64.0 * tol {
            return Err(format!("span {i} does not start at its point"));
        }
        if last && dist(pieces[k].end_point(), b) > 64.0 * tol {
            return Err(format!("span {i} does not end at its point"));
        }
    }
    let pairs = n - usize::from(!spline.is_closed());
    for k in 0..pairs {
        let (a, b) = (&pieces[k], &pieces[(k + 1) % n]);
        meet(a, b, k, tol, size)?;
        let (ka, kb) = (a.curvature_end(), b.curvature_start());
        if spans[k] == spans[(k + 1) % n] {
            if !(ka.abs().max(kb.abs()) <= INFLECTION_LIMIT * kmax && ka * kb <= 0.0) {
                return Err(format!(
                    "no inflection in span {}: {ka:e}, {kb:e}",
                    spans[k]
                ));
            }
        } else if (ka - kb).abs() > bounds::JOINT_CURVATURE * ka.abs().max(kb.abs()) {
            return Err(format!("curvature jumps after piece {k}: {ka:e} to {kb:e}"));
        }
    }
    for q in spline
        .sample_by_arc_length(65)
        .map_err(|e| format!("sampling a solved spline failed: {e}"))?
    {
        finite(
            "spline sample",
            &[q.s, q.point.x, q.point.y, q.theta, q.kappa],
        )?;
    }
    Ok(())
}

/// Pieces meet with continuous position, tangent and curvature.
fn check_joints(curve: &CompoundCurve) -> Result<(), String> {
    let [a, b] = curve.pieces() else {
        return Err("a compound curve without two pieces".to_string());
    };
    let (pa, pb) = (a.end_point(), b.start_point());
    let scale = curve.arc_length();
    if dist(pa, pb) > 1e-12 * scale + rounding(&[pa]) {
        return Err(format!("pieces {:e} apart at the joint", dist(pa, pb)));
    }
    let ka = a.curvature_end();
    let kb = b.curvature_start();
    if (ka - kb).abs() > bounds::JOINT_CURVATURE * ka.abs().max(kb.abs()) {
        return Err(format!("curvature jumps at the joint: {ka:e} to {kb:e}"));
    }
    let ta = a.theta_at_s(a.arc_length()).map_err(|e| e.to_string())?;
    let tb = b.theta_at_s(0.0).map_err(|e| e.to_string())?;
    if (ta - tb).abs() > 1e-12 * (1.0 + ta.abs()) {
        return Err(format!("tangent jumps at the joint: {ta} to {tb}"));
    }
    Ok(())
}

/// A verdict is never contradicted by sampling the curvature (within its rounding).
fn check_verdict(curve: &RationalCubic, verdict: Monotonicity, proven: bool) -> Result<(), String> {
    if let Monotonicity::NotMonotone { t } = verdict {
        if !(0.0..=1.0).contains(&t) {
            return Err(format!("sign change reported at t = {t}"));
        }
        return Ok(());
    }
    if !proven {
        return Ok(());
    }
    let ks: Vec<f64> = (0..=256)
        .map(|i| curve.signed_curvature(i as f64 / 256.0))
        .collect();
    if ks.iter().any(|k| !k.is_finite()) {
        return Ok(());
    }
    let big = ks.iter().fold(0.0f64, |m, k| m.max(k.abs()));
    let slack = 1e-9 * big;
    for w in ks.windows(2) {
        let bad = match verdict {
            Monotonicity::Increasing => w[1] < w[0] - slack,
            Monotonicity::Decreasing => w[1] > w[0] + slack,
            Monotonicity::Constant => (w[1] - w[0]).abs() > slack,
            Monotonicity::NotMonotone { .. } => false,
        };
        if bad {
            return Err(format!(
                "proven {verdict:?}, but sampled curvature goes {:e} → {:e}",
                w[0], w[1]
            ));
        }
    }
    Ok(())
}

/// A quasi-aesthetic chain: finite; ends on the segment's ends; pieces joined G2; within the
/// tolerance of the segment by a polyline measure independent of the fit's own; each piece's
/// curvature proven monotone in the segment's direction when a tolerance was asked.
fn check_quasi(
    seg: &Segment,
    pts: &[Point; 3],
    quasi: &QuasiCurve,
    tolerance: Option<f64>,
) -> Result<(), String> {
    finite("rms and max", &[quasi.rms, quasi.max])?;
    if quasi.pieces.is_empty() {
        return Err("no pieces".to_string());
    }
    let len = seg.arc_length();
    let tol = bounds::POSITION * len + rounding(pts);
    for p in &quasi.pieces {
        let b = p.curve.points();
        finite(
            "piece",
            &[
                b[0].x, b[0].y, b[1].x, b[1].y, b[2].x, b[2].y, b[3].x, b[3].y,
            ],
        )?;
        finite("weights", &p.curve.weights())?;
        finite(
            "turning and deviation",
            &[p.turning.0, p.turning.1, p.max_deviation],
        )?;
    }
    let first = quasi.pieces[0].curve.points()[0];
    let last = quasi.pieces[quasi.pieces.len() - 1].curve.points()[3];
    if dist(first, pts[0]) > tol || dist(last, pts[2]) > 64.0 * tol {
        return Err(format!(
            "chain ends off the segment's: {:e}, {:e}",
            dist(first, pts[0]),
            dist(last, pts[2])
        ));
    }
    // Curvature at a join is computed from control points rounded in absolute coordinates:
    // its error grows with the coordinates' magnitude over the piece's size.
    let kmax = seg.curvature_start().abs().max(seg.curvature_end().abs());
    let magnitude = rounding(pts) / 64.0;
    for w in quasi.pieces.windows(2) {
        let (a, b) = (w[0].curve, w[1].curve);
        let (pa, pb) = (a.points()[3], b.points()[0]);
        if dist(pa, pb) > 64.0 * tol {
            return Err(format!("pieces {:e} apart", dist(pa, pb)));
        }
        let size = dist(a.points()[0], a.points()[3]).min(dist(b.points()[0], b.points()[3]));
        let (ka, kb) = (a.signed_curvature(1.0), b.signed_curvature(0.0));
        // Control points rounded by δ move a piece's end curvature by about δ/size² (not
        // relative to κ: a nearly straight piece far from the origin feels it most).
        let allowed = (bounds::QUASI_JOINT_CURVATURE + 1e3 * magnitude / size) * kmax
            + 1e3 * magnitude / (size * size)
            + 4.0 * (conditioning(&a, false) + conditioning(&b, true));
        if (ka - kb).abs() > allowed {
            return Err(format!("curvature jumps between pieces: {ka:e} to {kb:e}"));
        }
    }
    let Some(relative) = tolerance else {
        return Ok(());
    };
    if quasi.max > relative {
        return Err(format!(
            "reported max {:e} over the tolerance {relative:e}",
            quasi.max
        ));
    }
    let (k0, k1) = (seg.curvature_start(), seg.curvature_end());
    let constant = (k1 - k0).abs() <= 1e-9 * k0.abs().max(k1.abs());
    for p in &quasi.pieces {
        let m = p.monotonicity;
        // A plain cubic cannot have constant curvature: of a circular arc's pieces only the
        // deviation is asked (as the library documents).
        if constant && p.curve.to_cubic().is_some() {
            continue;
        }
        let faithful = match m.verdict {
            Monotonicity::Constant => true,
            Monotonicity::Increasing => m.proven && (constant || k1 >= k0),
            Monotonicity::Decreasing => m.proven && (constant || k1 <= k0),
            Monotonicity::NotMonotone { .. } => constant,
        };
        if !faithful {
            return Err(format!("a piece's curvature verdict is {:?}", m.verdict));
        }
    }
    // Independent distance: every point of every piece lies within the tolerance of a
    // polyline that is itself within a tenth of it of the segment.
    let allowed = relative * len;
    let Ok(poly) = seg.sample_adaptive(0.1 * allowed) else {
        return Ok(());
    };
    if poly.len() > 20_000 {
        return Ok(());
    }
    // Each piece is compared with the part of the polyline over its turning range (and a
    // margin), found by bisection on the samples' turning, which ascends.
    let theta0 = poly[0].theta;
    let turned: Vec<f64> = poly.iter().map(|s| (s.theta - theta0).abs()).collect();
    for p in &quasi.pieces {
        let margin = 0.5 * (p.turning.1 - p.turning.0) + 1e-9;
        let lo = turned
            .partition_point(|&t| t < p.turning.0 - margin)
            .saturating_sub(1);
        let hi = (turned.partition_point(|&t| t <= p.turning.1 + margin) + 1).min(poly.len());
        let part = &poly[lo..hi.max(lo + 2).min(poly.len())];
        for i in 0..=32 {
            let x = p.curve.eval(i as f64 / 32.0);
            let d = part
                .windows(2)
                .map(|w| distance_to_segment(x, w[0].point, w[1].point))
                .fold(f64::INFINITY, f64::min);
            if d > 1.1 * allowed + 64.0 * tol {
                return Err(format!(
                    "a piece lies {:e} (relative) from the segment, tolerance {relative:e}",
                    d / len
                ));
            }
        }
    }
    Ok(())
}

/// |a − b| without kurbo's overflow of the squares from 1e154 on.
fn dist(a: Point, b: Point) -> f64 {
    (a.x - b.x).hypot(a.y - b.y)
}

/// What rounding the control points of `c` (a few ulps of its largest coordinate) can do
/// to its curvature at an end: the curvature there is ∝ h/L² (L the end leg, h the third
/// point's distance from the end tangent), so a nearly collinear end triangle (small h)
/// makes it sensitive.
fn conditioning(c: &RationalCubic, at_start: bool) -> f64 {
    let p = c.points();
    let [b0, b1, b2] = if at_start {
        [p[0], p[1], p[2]]
    } else {
        [p[3], p[2], p[1]]
    };
    let ulps = rounding(&p) / 16.0; // 4 ulps of the largest coordinate
    let l = dist(b1, b0);
    let h = ((b1 - b0).cross(b2 - b0) / l).abs();
    let k = c.signed_curvature(if at_start { 0.0 } else { 1.0 }).abs();
    let bound = k * ulps * (2.0 / l + (1.0 + dist(b2, b0) / l) / h);
    if bound.is_nan() {
        f64::INFINITY
    } else {
        bound
    }
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

/// A space segment: finite frames, orthonormal and right-handed; starts at P0 along the
/// first leg, ends at P3 along the last.
fn check_space(seg: &SpaceSegment, pts: &[Vec3; 4]) -> Result<(), String> {
    let len = seg.arc_length();
    let frames = seg.sample(33).map_err(|e| e.to_string())?;
    let chord = (pts[3] - pts[0]).length();
    let magnitude = pts
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()).max(p.z.abs()))
        .fold(0.0, f64::max);
    let tol = bounds::POSITION * chord + 64.0 * f64::EPSILON * magnitude;
    finite("arc length", &[len])?;
    for f in &frames {
        let v = [f.point, f.tangent, f.normal, f.binormal];
        finite(
            "frame",
            &v.iter()
                .flat_map(|p| [p.x, p.y, p.z])
                .chain([f.s, f.curvature, f.torsion])
                .collect::<Vec<_>>(),
        )?;
        let orth = [
            (f.tangent.length() - 1.0).abs(),
            (f.normal.length() - 1.0).abs(),
            f.tangent.dot(f.normal).abs(),
            (f.tangent.cross(f.normal) - f.binormal).length(),
        ];
        if orth.iter().any(|e| *e > 1e-9) {
            return Err(format!("frame not orthonormal at s = {}", f.s));
        }
        if f.curvature < 0.0 {
            return Err("negative curvature".to_string());
        }
    }
    let (a, b) = (frames[0], frames[frames.len() - 1]);
    if (a.point - pts[0]).length() > tol || (b.point - pts[3]).length() > 64.0 * tol {
        return Err(format!(
            "space segment ends off: {:e}, {:e} (chord {chord:e})",
            (a.point - pts[0]).length(),
            (b.point - pts[3]).length()
        ));
    }
    let t0 = (pts[1] - pts[0]).normalize();
    let t1 = (pts[3] - pts[2]).normalize();
    let allowed = bounds::TANGENT + 1e3 * tol / chord;
    let off0 = a.tangent.angle_to(t0);
    let off1 = b.tangent.angle_to(t1);
    if off0 > allowed || off1 > allowed {
        return Err(format!("space end tangents off by {off0:e}, {off1:e} rad"));
    }
    Ok(())
}

/// The cubic pieces of a solved space segment (`SpaceSegment::to_cubics`, what `lac export`
/// writes) at a relative tolerance of 1e-4: a typed error, or pieces with finite points, the
/// segment's ends, shared joins and a deviation within the tolerance, re-measured here at
/// the middle of every piece against the segment's own point there.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN must fail the checks
fn check_space_cubics(seg: &SpaceSegment) -> Result<(), String> {
    let Ok(chain) = seg.to_cubics(Tolerance::Relative(1e-4)) else {
        return Ok(());
    };
    let len = seg.arc_length();
    let tol = 1e-4 * len;
    let pieces = &chain.pieces;
    if pieces.is_empty() || pieces.len() > lac::MAX_PIECES {
        return Err(format!("space cubics: {} pieces", pieces.len()));
    }
    let coords: Vec<f64> = pieces
        .iter()
        .flat_map(|p| p.points.iter().flat_map(|q| q.to_array()))
        .collect();
    finite("space cubics", &coords)?;
    if !(chain.max_deviation <= tol) {
        return Err(format!(
            "space cubics: deviation {:e} over the tolerance {tol:e}",
            chain.max_deviation
        ));
    }
    for w in pieces.windows(2) {
        if w[0].points[3] != w[1].points[0] || w[0].s.1 != w[1].s.0 {
            return Err("space cubics: pieces that do not share their join".into());
        }
    }
    // u = 0.3 is between the fit's 48 steps: the pair there is not one it measured, and the
    // fit's margin (accepted below 0.98 of the tolerance) must cover it.
    let at: Vec<f64> = pieces
        .iter()
        .map(|p| p.s.0 + 0.3 * (p.s.1 - p.s.0))
        .collect();
    let frames = seg.frames(&at).map_err(|e| e.to_string())?;
    for (p, f) in pieces.iter().zip(&frames) {
        let d = p.eval(0.3).distance(f.point);
        if !(d <= tol) {
            return Err(format!(
                "space cubics: {d:e} from the curve at a piece's middle"
            ));
        }
    }
    Ok(())
}
