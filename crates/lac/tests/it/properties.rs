//! Property tests: for random control points, α, scales and orientations the library either
//! returns an error or a curve whose ends, end tangents and tangent intersection reproduce
//! the control points, whose curvature is monotone, and which contains no NaN.

use kurbo::{Point, Vec2};
use lac::Curve;
use lac::Segment;
use proptest::prelude::*;

/// Tolerance on positions relative to the chord: 1e-12, plus what rounding of the caller's
/// absolute coordinates allows (an offset of 1e7 with a chord of 1e-6 leaves 1e-3).
fn position_tolerance(points: &[Point; 3], chord: f64) -> f64 {
    let magnitude = points
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()))
        .fold(0.0, f64::max);
    1e-12 * chord + 64.0 * f64::EPSILON * magnitude
}

fn check(points: [Point; 3], alpha: f64) -> Result<(), TestCaseError> {
    let Ok(seg) = Segment::from_control_points(points, alpha) else {
        return Ok(());
    };
    let chord = (points[2] - points[0]).hypot();
    let tol = position_tolerance(&points, chord);
    let samples = seg.sample_by_arc_length(33).unwrap();
    for s in &samples {
        prop_assert!(
            s.point.x.is_finite()
                && s.point.y.is_finite()
                && s.kappa.is_finite()
                && s.theta.is_finite()
        );
    }
    prop_assert!((samples[0].point - points[0]).hypot() <= tol);
    prop_assert!(
        (samples[32].point - points[2]).hypot() <= 64.0 * tol,
        "end {:?}",
        samples[32].point
    );
    // End tangents point along the legs.
    let leg0 = (points[1] - points[0]).normalize();
    let leg1 = (points[2] - points[1]).normalize();
    let angle_tol = 1e-9 + tol / chord * 1e3;
    prop_assert!(
        samples[0].tangent().cross(leg0).abs() <= angle_tol && samples[0].tangent().dot(leg0) > 0.0
    );
    prop_assert!(
        samples[32].tangent().cross(leg1).abs() <= angle_tol
            && samples[32].tangent().dot(leg1) > 0.0
    );
    // The tangent lines meet at the middle control point.
    let p1 = seg.control_points()[1];
    let leg = (points[1] - points[0])
        .hypot()
        .min((points[2] - points[1]).hypot());
    prop_assert!(
        (p1 - points[1]).hypot() <= 1e-7 * leg.max(chord) + 1e3 * tol,
        "P1 {p1:?}"
    );
    // Monotone curvature of one sign.
    let k: Vec<f64> = samples.iter().map(|s| s.kappa).collect();
    let up = k.windows(2).all(|w| w[1] >= w[0] - 1e-12 * w[0].abs());
    let down = k.windows(2).all(|w| w[1] <= w[0] + 1e-12 * w[0].abs());
    prop_assert!(up || down, "curvature not monotone: {k:?}");
    prop_assert!(k.iter().all(|&x| x > 0.0) || k.iter().all(|&x| x < 0.0));
    Ok(())
}

fn rotate(p: Point, angle: f64, scale: f64, offset: Vec2) -> Point {
    Vec2::from_angle(angle).rotate_dummy(p, scale) + offset
}

trait RotateDummy {
    fn rotate_dummy(self, p: Point, scale: f64) -> Point;
}

impl RotateDummy for Vec2 {
    fn rotate_dummy(self, p: Point, scale: f64) -> Point {
        Point::new(
            scale * (self.x * p.x - self.y * p.y),
            scale * (self.y * p.x + self.x * p.y),
        )
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn solved_segments_reproduce_their_control_points(
        bx in -1.5f64..1.5, by in -1.5f64..1.5,
        alpha in prop_oneof![-50.0f64..50.0, -2.0f64..3.0, Just(0.0), Just(1.0), Just(2.0), Just(-1.0)],
        log_scale in -6.0f64..6.0,
        angle in -3.2f64..3.2,
        ox in -1e7f64..1e7, oy in -1e7f64..1e7,
        use_offset in any::<bool>(),
    ) {
        let scale = 10f64.powf(log_scale);
        let offset = if use_offset { Vec2::new(ox, oy) } else { Vec2::ZERO };
        let pts = [Point::new(-1.0, 0.0), Point::new(bx, by), Point::new(1.0, 0.0)]
            .map(|p| rotate(p, angle, scale, offset));
        check(pts, alpha)?;
    }

    #[test]
    fn arbitrary_numbers_never_panic(
        xs in proptest::array::uniform6(prop_oneof![
            any::<f64>(), -10.0f64..10.0, Just(f64::NAN), Just(f64::INFINITY), Just(0.0), Just(1e-300), Just(1e300)
        ]),
        alpha in prop_oneof![any::<f64>(), -100.0f64..100.0, Just(f64::NAN)],
    ) {
        let pts = [Point::new(xs[0], xs[1]), Point::new(xs[2], xs[3]), Point::new(xs[4], xs[5])];
        if let Ok(seg) = Segment::from_control_points(pts, alpha) {
            let l = seg.arc_length();
            prop_assert!(l.is_finite() && l > 0.0);
            prop_assert!(seg.signed_curvature_start().is_finite() && seg.signed_curvature_end().is_finite());
            for s in seg.sample_by_arc_length(9).unwrap() {
                prop_assert!(s.point.x.is_finite() && s.point.y.is_finite() && s.kappa.is_finite());
            }
        }
    }
}
