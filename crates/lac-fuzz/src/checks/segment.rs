//! `segment`: [`lac::Segment::from_control_points`], then evaluation and sampling of the
//! result. Invariants: those of every planar curve ([`check_curve`](super::check_curve):
//! finite everywhere, starting on P0 tangent to P0P1 and ending on P2 tangent to P1P2,
//! every sampled chord's direction between the tangents at its ends, curvature of one sign
//! and monotone, the polyline no longer than the arc, adaptive samples within the accuracy
//! asked), and a finite line of its logarithmic curvature graph.

use lac_io::json::Solved;

use super::{build, check_curve, finite, pt, Built};
use crate::Input;

/// The checks of a `segment` input.
pub(super) fn check(
    input: &Input,
    points: &[[f64; 2]; 3],
    samples: usize,
    accuracy: f64,
) -> Result<bool, String> {
    let pts = points.map(pt);
    let Some(Built::Plane(Solved::Segment(seg))) = build(input)? else {
        return Ok(false);
    };
    check_curve(
        &seg,
        &[pts[0], pts[1]],
        &[pts[1], pts[2]],
        samples,
        accuracy,
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
