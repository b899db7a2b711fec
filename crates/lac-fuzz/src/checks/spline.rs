//! `spline`: [`lac::Spline::g2`] through points. Invariants: each piece on its control
//! triangle (ends, end tangents, monotone curvature, chords between the tangents); each span
//! from its point to the next; consecutive pieces meeting with continuous position and
//! tangent, with curvature continuous (relative) at the points and zero on both sides (with
//! a sign change) at a span's inflection.

use kurbo::Point;
use lac::Closure;
use lac::{Curve, Spline, INFLECTION_LIMIT};

use super::{bounds, dist, finite, largest_end_curvature, meet, on_triangles, pt, rounding, typed};

/// The checks of a `spline` input.
pub(super) fn check(
    points: &[[f64; 2]],
    alpha: f64,
    closed: bool,
    ends: Option<[f64; 2]>,
) -> Result<bool, String> {
    let pts: Vec<Point> = points.iter().map(|&p| pt(p)).collect();
    let closure = if closed {
        Closure::Closed
    } else {
        Closure::Open
    };
    let Some(spline) = typed(Spline::from_points(&pts, alpha, closure, ends))? else {
        return Ok(false);
    };
    check_spline(&spline)?;
    Ok(true)
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
    let kmax = largest_end_curvature(pieces);
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
        let (ka, kb) = (a.signed_curvature_end(), b.signed_curvature_start());
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
