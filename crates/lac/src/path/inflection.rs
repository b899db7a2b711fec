//! The segments that end at an inflection of a path (seed 000 §5: "an aesthetic curve segment
//! of α < 0 can be connected to a straight line segment, since the point of inflection
//! exists").
//!
//! For α < 0 the curvature of a log-aesthetic curve reaches zero (ρ → ∞) at a finite arc
//! length (docs/math.md §2, the inflection end). A segment that starts (or ends) there, with its two
//! tangents fixed by the polygon's legs, is fixed up to similarity by α and its turning
//! angle: the ratio of its two legs is then fixed. A path solves for that ratio once per
//! segment and keeps it through Newton's iterations.
//!
//! The segment is built by [`Segment::from_control_points`] like any other, on the triangle
//! whose inflection-side leg makes the curvature there [`END_RATIO`] times the curvature at
//! the other end: a segment that stops a hair before its inflection point (for α = −1, a
//! share 1e-12 of its length; the rest, which the straight piece continues, deviates from a
//! straight line by less than rounding), because `Segment` has no station at ρ = ∞.
//! Where the chord-angle solver cannot resolve the triangle that finely (the drawable
//! region's boundary, approached like d^(1/|α|): for α ≲ −1.7 the curvature cannot be
//! brought below 1e-10 of the other end's in double precision), the inflection is refused.

use kurbo::Point;

use crate::foundation::error::Result;
use crate::segment::end_curvatures_of;

/// The target |κ| at the inflection end relative to the other end's.
pub(crate) const END_RATIO: f64 = 1e-12;

/// The largest |κ| at the inflection end, relative to the other end's, that is accepted.
pub(crate) const END_RATIO_LIMIT: f64 = 1e-10;

/// The leg ratio (inflection-side leg / other leg) of the segment of slope `alpha` and
/// turning angle `turning` whose curvature at the inflection side is about
/// [`END_RATIO`] × the other end's, and that curvature ratio; `None` when no ratio below
/// [`END_RATIO_LIMIT`] is found (α ≥ 0 never reaches zero curvature).
pub(super) fn leg_ratio(alpha: f64, turning: f64) -> Option<(f64, f64)> {
    if alpha >= 0.0 {
        return None;
    }
    // The other leg first (length 1), the inflection leg after it (length e^lb).
    let ratio = |lb: f64| -> Result<f64> {
        let b = lb.exp();
        let points = [
            Point::new(-1.0, 0.0),
            Point::ORIGIN,
            Point::new(b * turning.cos(), b * turning.sin()),
        ];
        let (k0, k1) = end_curvatures_of(points, alpha)?;
        Ok((k1 / k0).abs())
    };
    // Bracket: the isosceles triangle (a circular arc, ratio 1) below, the first longer leg
    // that is not drawable or reaches the target above.
    let (mut lo, mut hi) = (0.0, None);
    let mut lb = 0.0;
    for _ in 0..400 {
        lb += 0.02;
        match ratio(lb) {
            Ok(r) if r > END_RATIO => lo = lb,
            _ => {
                hi = Some(lb);
                break;
            }
        }
    }
    let mut hi = hi?;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        match ratio(mid) {
            Ok(r) if r > END_RATIO => lo = mid,
            _ => hi = mid,
        }
    }
    // The drawable side of the bracket closest to the target.
    let candidates = [hi, lo];
    candidates.iter().find_map(|&lb| match ratio(lb) {
        Ok(r) if r <= END_RATIO_LIMIT => Some((lb.exp(), r)),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_reached_for_moderate_alpha_refused_for_steep() {
        for alpha in [-0.25, -0.5, -1.0, -1.5] {
            for turning in [0.3, 0.8, 1.5, 2.5] {
                let (q, r) = leg_ratio(alpha, turning).expect("resolved");
                assert!(
                    q > 1.0 && r <= END_RATIO_LIMIT,
                    "{alpha} {turning}: {q} {r}"
                );
            }
        }
        assert!(leg_ratio(-3.0, 0.8).is_none());
        assert!(leg_ratio(0.5, 0.8).is_none());
    }
}
