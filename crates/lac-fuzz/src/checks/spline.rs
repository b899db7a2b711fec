//! `spline`: [`lac::Spline::from_points_with`] through points, with point types, straight
//! spans and end curvatures. Invariants: each piece on its control triangle (ends, end
//! tangents, monotone curvature, chords between the tangents); each span from its point to
//! the next; consecutive pieces meeting with continuous position and tangent (but at a
//! corner), with curvature continuous (relative) at the points and knots and zero on both
//! sides (with a sign change) at a span's inflection; every point's report: the given
//! directions, zero curvature where a curve meets a straight span, the given end curvatures;
//! the same of [`lac::Spline::from_points_near`] after its middle point is dragged.

use kurbo::Point;
use lac::{Closure, PointType, SplineEnd, SplineOptions};
use lac::{Curve, Spline, INFLECTION_LIMIT};

use super::{bounds, dist, finite, largest_end_curvature, meet, on_triangles, pt, rounding, typed};
use crate::Input;

/// The checks of a `spline` input.
pub(super) fn check(input: &Input) -> Result<bool, String> {
    let Input::Spline {
        points,
        alpha,
        closed,
        ends,
        types,
        angles,
        lines,
        curvatures,
    } = input
    else {
        unreachable!("a spline input")
    };
    let pts: Vec<Point> = points.iter().map(|&p| pt(p)).collect();
    let closure = if *closed {
        Closure::Closed
    } else {
        Closure::Open
    };
    let types: Vec<PointType> = types
        .iter()
        .zip(angles.iter().chain(std::iter::repeat(&[None, None])))
        .map(|(t, a)| match t.as_str() {
            "t" => PointType::Tangent(a[0].unwrap_or(0.0)),
            "c" => PointType::Corner {
                before: a[0],
                after: a[1],
            },
            _ => PointType::Smooth,
        })
        .collect();
    let options = SplineOptions {
        types,
        lines: lines.clone(),
        start: SplineEnd {
            angle: ends.map(|e| e[0]),
            curvature: curvatures[0],
        },
        end: SplineEnd {
            angle: ends.map(|e| e[1]),
            curvature: curvatures[1],
        },
    };
    let Some(spline) = typed(Spline::from_points_with(&pts, *alpha, closure, &options))? else {
        return Ok(false);
    };
    check_spline(&spline)?;
    check_points(&spline)?;
    // A drag: the middle point moved by 1% of the points' extent, re-solved from this answer
    // (which solves only the part of the spline the move touches), meets every check too.
    let mut moved = spline.points().to_vec();
    let extent = moved.iter().map(|p| dist(*p, moved[0])).fold(0.0, f64::max);
    let k = moved.len() / 2;
    moved[k].x += 0.006 * extent;
    moved[k].y -= 0.008 * extent;
    if let Some(near) = typed(Spline::from_points_near(
        &moved, *alpha, closure, &options, &spline,
    ))? {
        check_spline(&near).map_err(|e| format!("after a drag: {e}"))?;
        check_points(&near).map_err(|e| format!("after a drag: {e}"))?;
    }
    Ok(true)
}

/// Every point's report against its type: through the point, a given direction met, the
/// tangent continuous but at corners, the curvature continuous at smooth and tangent points
/// that meet no straight span, zero where a curve meets one, an end curvature as given.
fn check_points(spline: &Spline) -> Result<(), String> {
    let o = spline.options();
    let kmax = largest_end_curvature(spline.pieces());
    let all: Vec<Point> = spline
        .control_triangles()
        .iter()
        .flatten()
        .copied()
        .collect();
    let tol = bounds::POSITION * spline.arc_length() + rounding(&all);
    let turn = bounds::TANGENT + 1e3 * rounding(&all) / spline.arc_length();
    let reports = spline.point_reports();
    let n = reports.len();
    let wrap = |a: f64| (a - std::f64::consts::TAU * (a / std::f64::consts::TAU).round()).abs();
    for (i, r) in reports.iter().enumerate() {
        if r.gap > 64.0 * tol {
            return Err(format!("point {i} is {} from its pieces", r.gap));
        }
        let given = match r.kind {
            PointType::Tangent(a) => [Some(a), Some(a)],
            PointType::Corner { before, after } => [before, after],
            PointType::Smooth => [None, None],
        };
        for (side, g) in given.iter().enumerate() {
            if let (Some(g), Some(a), false) = (*g, r.angles[side], r.straight[side]) {
                if wrap(a - g) > turn {
                    return Err(format!("point {i} side {side}: direction {a} for {g}"));
                }
            }
        }
        let corner = matches!(r.kind, PointType::Corner { .. });
        if let ([Some(a0), Some(a1)], [Some(k0), Some(k1)], false) =
            (r.angles, r.curvatures, corner)
        {
            if wrap(a0 - a1) > turn {
                return Err(format!(
                    "point {i}: the tangent breaks by {}",
                    wrap(a0 - a1)
                ));
            }
            match r.straight {
                [false, false]
                    if (k0 - k1).abs() > bounds::JOINT_CURVATURE * k0.abs().max(k1.abs()) =>
                {
                    return Err(format!("point {i}: curvature {k0:e} to {k1:e}"));
                }
                [true, false] | [false, true] => {
                    let k = if r.straight[0] { k1 } else { k0 };
                    if k.abs() > INFLECTION_LIMIT * kmax {
                        return Err(format!(
                            "point {i} meets a straight span at curvature {k:e}"
                        ));
                    }
                }
                _ => {}
            }
        }
    }
    if !spline.is_closed() {
        for (end, k) in [
            (o.start.curvature, reports[0].curvatures[1]),
            (o.end.curvature, reports[n - 1].curvatures[0]),
        ] {
            if let (Some(want), Some(got)) = (end, k) {
                let miss = if want == 0.0 {
                    got.abs() / kmax
                } else {
                    (got - want).abs() / want.abs()
                };
                if miss > bounds::JOINT_CURVATURE {
                    return Err(format!("end curvature {got:e} for {want:e}"));
                }
            }
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
    // Pieces on either side of a corner or a straight span meet as the point's report
    // says (`check_points`).
    let broken = |k: usize| {
        let (a, b) = (spans[k], spans[(k + 1) % n]);
        let point = (a + 1) % points.len();
        a != b
            && (spline
                .options()
                .lines
                .iter()
                .any(|l| *l == a || (l + 1) % points.len() == b)
                || a + 1 != b && !(spline.is_closed() && b == 0)
                || matches!(
                    spline.options().types.get(point),
                    Some(PointType::Corner { .. })
                ))
    };
    for k in 0..pairs {
        let (a, b) = (&pieces[k], &pieces[(k + 1) % n]);
        if broken(k) {
            continue;
        }
        meet(a, b, k, tol, size)?;
        let (ka, kb) = (a.signed_curvature_end(), b.signed_curvature_start());
        // Two pieces of one span meet at its inflection, or at a knot (their triangles
        // share the point exactly), where the curvature is continuous.
        let knot = triangles[k][2] == triangles[(k + 1) % n][0];
        if spans[k] == spans[(k + 1) % n] && !knot {
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
