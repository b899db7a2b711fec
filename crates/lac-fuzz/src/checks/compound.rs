//! `compound3` and `compound4`: [`lac::CompoundCurve::from_three_points`] and
//! [`lac::CompoundCurve::from_four_points`]. Invariants: those of every planar curve
//! ([`check_curve`](super::check_curve)), its two pieces meeting at the joint with continuous
//! position, tangent and curvature, and, from four points, the joint's tangent parallel to
//! the middle leg.

use kurbo::Vec2;
use lac::SegmentChain;
use lac::{CompoundCurve, Curve};
use lac_io::json::Solved;

use super::{angle_between, bounds, build, check_curve, dist, pt, rounding, Built};
use crate::Input;

/// The checks of a `compound3` input.
pub(super) fn check_three(
    input: &Input,
    points: &[[f64; 2]; 3],
    samples: usize,
) -> Result<bool, String> {
    let pts = points.map(pt);
    let Some(Built::Plane(Solved::Compound(c))) = build(input)? else {
        return Ok(false);
    };
    check_curve(&c, &[pts[0], pts[1]], &[pts[1], pts[2]], samples, 1e-6)?;
    check_joints(&c)?;
    Ok(true)
}

/// The checks of a `compound4` input.
pub(super) fn check_four(
    input: &Input,
    points: &[[f64; 2]; 4],
    samples: usize,
) -> Result<bool, String> {
    let pts = points.map(pt);
    let Some(Built::Plane(Solved::Compound(c))) = build(input)? else {
        return Ok(false);
    };
    check_curve(&c, &[pts[0], pts[1]], &[pts[2], pts[3]], samples, 1e-6)?;
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
    let ka = a.signed_curvature_end();
    let kb = b.signed_curvature_start();
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
