//! Claims about a solved segment's evaluation API, its kurbo traits and its samplings.

use kurbo::Point;
use lac::Curve;
use lac::{Error, NotDrawable, Segment};

fn segment(alpha: f64) -> Segment {
    Segment::from_control_points(
        [
            Point::new(-1.0, 0.0),
            Point::new(-0.2, 0.8),
            Point::new(1.0, 0.0),
        ],
        alpha,
    )
    .unwrap()
}

#[test]
fn evaluations_by_s_and_by_theta_agree() {
    for alpha in [-1.0, 0.0, 0.5, 1.0, 2.0] {
        let seg = segment(alpha);
        for u in [0.0, 0.2, 0.5, 0.8, 1.0] {
            let s = u * seg.arc_length();
            let theta = seg.theta_at_s(s).unwrap();
            assert!((seg.s_at_theta(theta).unwrap() - s).abs() < 1e-13);
            assert!(
                (seg.point_at_theta(theta).unwrap() - seg.point_at_s(s).unwrap()).hypot() < 1e-13
            );
            assert!(
                (seg.signed_curvature_at_theta(theta).unwrap()
                    - seg.signed_curvature_at_s(s).unwrap())
                .abs()
                    < 1e-13
            );
            let t = seg.tangent_at_s(s).unwrap();
            assert!((t.atan2() - theta).abs() < 1e-13);
        }
        assert!(seg.point_at_s(-1.0).is_err() && seg.point_at_s(seg.arc_length() * 1.01).is_err());
        assert!(seg.point_at_theta(10.0).is_err());
    }
}

#[test]
fn a_right_turn_has_negative_curvature_and_a_mirror_image_mirrors_everything() {
    let right = segment(0.5);
    let left = Segment::from_control_points(
        [
            Point::new(-1.0, 0.0),
            Point::new(-0.2, -0.8),
            Point::new(1.0, 0.0),
        ],
        0.5,
    )
    .unwrap();
    assert!(right.signed_curvature_start() < 0.0 && left.signed_curvature_start() > 0.0);
    assert!((right.signed_curvature_end() + left.signed_curvature_end()).abs() < 1e-14);
    for u in [0.1, 0.5, 0.9] {
        let (p, q) = (
            right.point_at_s(u * 2.0).unwrap(),
            left.point_at_s(u * 2.0).unwrap(),
        );
        assert!((p.x - q.x).abs() < 1e-14 && (p.y + q.y).abs() < 1e-14);
    }
}

#[test]
fn reversing_the_control_points_reverses_the_curve() {
    let fwd = segment(-1.0);
    let back = Segment::from_control_points(
        [
            Point::new(1.0, 0.0),
            Point::new(-0.2, 0.8),
            Point::new(-1.0, 0.0),
        ],
        -1.0,
    )
    .unwrap();
    let len = fwd.arc_length();
    assert!((back.arc_length() - len).abs() < 1e-14);
    assert!((fwd.signed_curvature_start() + back.signed_curvature_end()).abs() < 1e-13);
    for u in [0.0, 0.3, 0.7, 1.0] {
        let p = fwd.point_at_s(u * len).unwrap();
        let q = back.point_at_s((1.0 - u) * len).unwrap();
        assert!((p - q).hypot() < 1e-13);
    }
}

#[test]
fn an_isosceles_triangle_is_a_circular_arc_for_every_alpha() {
    for alpha in [-50.0, -1.0, 0.0, 1.0, 2.0, 50.0] {
        let seg = Segment::from_control_points(
            [
                Point::new(-1.0, 0.0),
                Point::new(0.0, 0.6),
                Point::new(1.0, 0.0),
            ],
            alpha,
        )
        .unwrap();
        assert!(seg.is_circle());
        assert!((seg.signed_curvature_start() - seg.signed_curvature_end()).abs() < 1e-15);
    }
}

#[test]
fn errors_name_the_problem() {
    let p = |x, y| Point::new(x, y);
    let seg = |pts, a| Segment::from_control_points(pts, a).unwrap_err();
    assert!(matches!(
        seg([p(0., 0.), p(0., 0.), p(1., 1.)], 0.5),
        Error::CoincidentPoints {
            first: 0,
            second: 1
        }
    ));
    assert!(matches!(
        seg([p(0., 0.), p(1., 1.), p(2., 2.)], 0.5),
        Error::CollinearPoints
    ));
    assert!(matches!(
        seg([p(0., 0.), p(1., 1.), p(0.5, 0.5)], 0.5),
        Error::CollinearPoints
    ));
    assert!(matches!(
        seg([p(0., f64::NAN), p(1., 1.), p(2., 0.)], 0.5),
        Error::NonFinite { what: "P0.y", .. }
    ));
    assert!(matches!(
        seg([p(0., 0.), p(1., 1.), p(2., 0.)], f64::NAN),
        Error::NonFinite { what: "alpha", .. }
    ));
    let far = seg([p(-1., 0.), p(0.9, 0.9), p(1., 0.)], -1.0);
    assert!(matches!(
        far,
        Error::NotDrawable(NotDrawable::ChordAngleTooLarge { .. })
    ));
    assert!(far.to_string().contains("at most"));
}

#[test]
fn tangent_angle_samples_are_equally_spaced_in_theta() {
    let seg = segment(2.0);
    let samples = seg.sample_by_tangent_angle(17).unwrap();
    let step = samples[1].theta - samples[0].theta;
    for w in samples.windows(2) {
        assert!((w[1].theta - w[0].theta - step).abs() < 1e-13);
    }
    for s in &samples {
        assert!((seg.point_at_s(s.s).unwrap() - s.point).hypot() < 1e-13);
    }
    assert!(seg.sample_by_tangent_angle(1).is_err());
}

#[test]
fn adaptive_samples_stay_within_tolerance() {
    for alpha in [-1.0, 0.5, 2.0] {
        let seg = segment(alpha);
        for tol in [1e-2, 1e-4, 1e-7] {
            let poly = seg.sample_adaptive(tol).unwrap();
            // Every dense sample lies within tol of the polyline segment covering it.
            let dense = seg.sample_by_arc_length(4001).unwrap();
            let mut j = 0;
            for d in &dense {
                while j + 2 < poly.len() && poly[j + 1].s < d.s {
                    j += 1;
                }
                let (a, b) = (poly[j].point, poly[j + 1].point);
                let ab = b - a;
                let dist = (d.point - a).cross(ab).abs() / ab.hypot();
                assert!(
                    dist <= tol * (1.0 + 1e-6),
                    "alpha {alpha} tol {tol}: {dist}"
                );
            }
            // and not wastefully many: a circle-like arc of length L needs about sqrt(L κ / 8 tol).
            assert!(
                poly.len() < 4 + (3.0 / tol).sqrt() as usize,
                "{} samples",
                poly.len()
            );
        }
        assert!(seg.sample_adaptive(0.0).is_err() && seg.sample_adaptive(f64::NAN).is_err());
    }
}

#[test]
fn the_evolute_is_at_distance_rho_along_the_normal() {
    let seg = segment(-1.0);
    let samples = seg.sample_by_arc_length(9).unwrap();
    let evolute = seg.evolute(9).unwrap();
    for (s, e) in samples.iter().zip(&evolute) {
        let d = *e - s.point;
        assert!((d.hypot() - 1.0 / s.kappa.abs()).abs() < 1e-12 / s.kappa.abs());
        assert!(d.dot(s.tangent()).abs() < 1e-12 * d.hypot());
        // The centre of curvature is on the side the curve turns to.
        assert!(s.tangent().cross(d) * s.kappa > 0.0);
    }
}

/// A near-reversal polygon with α = 1 has a standard-form chord of ~1e215; dividing by it
/// once squared its norm and overflowed, collapsing the curve to a point. The curve is a
/// hook (it turns 168° within a trillionth of its length at its first point), so it is
/// refused now — with its true curvature ratio, which only a computation that kept the
/// scale can report.
#[test]
fn huge_curvature_ratios_keep_their_scale() {
    let pts = [
        Point::new(-1.0, 0.0),
        Point::new(-1.336_953_595_120_045_3, -0.014_620_700_738_368_487),
        Point::new(1.0, 0.0),
    ];
    match Segment::from_control_points(pts, 1.0) {
        Err(Error::NotDrawable(NotDrawable::HiddenTurn {
            at_first: true,
            turning,
            curvature_ratio,
        })) => {
            assert!(turning > 2.9 && turning < std::f64::consts::PI, "{turning}");
            assert!(curvature_ratio > 1e200 && curvature_ratio.is_finite());
        }
        other => panic!("expected a hidden turn, got {other:?}"),
    }
    // The same kind of triangle, less extreme, is drawn and ends where it should.
    let milder = [pts[0], Point::new(-1.3, -0.3), pts[2]];
    let seg = Segment::from_control_points(milder, 1.0).unwrap();
    let samples = seg.sample_by_arc_length(5).unwrap();
    assert!((samples[4].point - pts[2]).hypot() < 1e-12);
}
