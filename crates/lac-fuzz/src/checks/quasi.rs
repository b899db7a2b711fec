//! `quasi`: the quasi-aesthetic fits of a segment (the seed's single rational cubic, and
//! rational and plain chains within a relative tolerance). Invariants: finite; ending on the
//! segment's ends; pieces joined G2; within the tolerance of the segment by a polyline
//! measure independent of the fit's own; each piece's curvature proven monotone in the
//! segment's direction when a tolerance was asked.

use kurbo::{ParamCurve, Point};
use lac::ToBezier;
use lac::{Curve, Monotonicity, QuasiCurve, RationalCubic, Segment, Tolerance};

use super::{bounds, dist, distance_to_segment, finite, pt, rounding, typed};

/// The checks of a `quasi` input.
pub(super) fn check(
    points: &[[f64; 2]; 3],
    alpha: f64,
    tolerance: Option<f64>,
    cubic: bool,
) -> Result<bool, String> {
    let pts = points.map(pt);
    let Some(seg) = typed(Segment::from_control_points(pts, alpha))? else {
        return Ok(false);
    };
    let fit = match (tolerance, cubic) {
        (None, _) => seg.to_rational_cubic(),
        (Some(t), false) => seg.to_rational_cubics(Tolerance::Relative(t)),
        (Some(t), true) => seg.to_cubics(Tolerance::Relative(t)),
    };
    let Some(quasi) = typed(fit)? else {
        return Ok(false);
    };
    check_quasi(&seg, &pts, &quasi, tolerance)?;
    Ok(true)
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
    let kmax = seg
        .signed_curvature_start()
        .abs()
        .max(seg.signed_curvature_end().abs());
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
    let (k0, k1) = (seg.signed_curvature_start(), seg.signed_curvature_end());
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
