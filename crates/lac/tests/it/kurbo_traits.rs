//! Claim: every log-aesthetic curve type implements kurbo's curve traits honestly — its
//! derivatives agree with finite differences of its points, its curvature is the exact one
//! with kurbo's sign, its subsegments are the same curve, and a parameter it cannot answer
//! for gives NaN rather than a made-up point.

use kurbo::{ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, Point};
use lac::SegmentChain;
use lac::{CompoundCurve, Curve, Segment};

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

/// The checks every curve must pass, with t ∝ arc length.
fn check<C, D>(curve: &C, name: &str)
where
    C: Curve
        + ParamCurve
        + ParamCurveArclen
        + ParamCurveCurvature
        + ParamCurveDeriv<DerivResult = D>,
    D: ParamCurve + ParamCurveDeriv<DerivResult = D>,
{
    let len = curve.arc_length();
    assert!(
        (curve.start() - curve.start_point()).hypot() == 0.0,
        "{name}"
    );
    assert!((curve.end() - curve.end_point()).hypot() == 0.0, "{name}");
    assert!(
        (curve.eval(0.0) - curve.start_point()).hypot() < 1e-14 * len,
        "{name}"
    );
    assert!(
        (curve.eval(1.0) - curve.end_point()).hypot() < 1e-13 * len,
        "{name}"
    );
    assert!((curve.arclen(1e-9) - len).abs() < 1e-15 * len, "{name}");
    assert!(
        (curve.inv_arclen(0.25 * len, 1e-9) - 0.25).abs() < 1e-15,
        "{name}"
    );
    let d1 = curve.deriv();
    let d2 = d1.deriv();
    let d3 = d2.deriv();
    for i in 1..20 {
        let t = i as f64 / 20.0;
        let h = 1e-5;
        let e = |t: f64| curve.eval(t).to_vec2();
        let fd1 = (e(t + h) - e(t - h)) / (2.0 * h);
        let fd2 = (e(t + h) - 2.0 * e(t) + e(t - h)) / (h * h);
        let (v, a) = (d1.eval(t).to_vec2(), d2.eval(t).to_vec2());
        assert!(
            (v - fd1).hypot() < 1e-8 * len,
            "{name} t={t}: {v:?} {fd1:?}"
        );
        assert!((a - fd2).hypot() < 1e-4 * (a.hypot() + len), "{name} t={t}");
        // |dP/dt| is the arc length: t is proportional to it.
        assert!((v.hypot() - len).abs() < 1e-12 * len, "{name} t={t}");
        let fd3 = (d2.eval(t + h).to_vec2() - d2.eval(t - h).to_vec2()) / (2.0 * h);
        assert!(
            (d3.eval(t).to_vec2() - fd3).hypot() < 1e-6 * (fd3.hypot() + len),
            "{name} t={t}"
        );
        // kurbo's sign: a″ × a′ / |a′|³, the opposite of docs/math.md's signed curvature.
        let k = curve.curvature(t);
        let ours = curve.signed_curvature_at_s(t * len).unwrap();
        assert!(
            (k + ours).abs() <= 1e-14 * ours.abs(),
            "{name} t={t}: {k} {ours}"
        );
        assert!(
            (a.cross(v) / v.hypot().powi(3) - k).abs() < 1e-11 * k.abs(),
            "{name}"
        );
    }
    // The parameter domain: clamped to [0, 1]; NaN in, NaN out.
    assert_eq!(curve.eval(-0.5), curve.eval(0.0), "{name}");
    assert_eq!(curve.eval(1.5), curve.eval(1.0), "{name}");
    assert!(curve.eval(f64::NAN).x.is_nan(), "{name}");
    assert!(curve.curvature(f64::NAN).is_nan(), "{name}");
    assert!(d1.eval(f64::NAN).x.is_nan(), "{name}");
}

/// A subsegment is the same curve over the sub-range, forward or reversed.
fn check_subsegments<C, D>(curve: &C, name: &str)
where
    C: Curve + ParamCurve + ParamCurveCurvature + ParamCurveDeriv<DerivResult = D>,
    D: ParamCurve + ParamCurveDeriv<DerivResult = D>,
{
    let len = curve.arc_length();
    for (a, b) in [
        (0.2, 0.7),
        (0.05, 0.3),
        (0.6, 0.95),
        (0.0, 1.0),
        (0.7, 0.2),
        (0.9, 0.1),
    ] {
        let sub = curve.subsegment(a..b);
        assert!(
            (sub.arc_length() - (b - a).abs() * len).abs() < 1e-13 * len,
            "{name} {a}..{b}"
        );
        assert!(
            (sub.start_point() - curve.eval(a)).hypot() < 1e-13 * len,
            "{name}"
        );
        for u in [0.0, 0.3, 0.5, 1.0] {
            let q = curve.eval(a + (b - a) * u);
            assert!(
                (sub.eval(u) - q).hypot() < 1e-13 * len,
                "{name} {a}..{b} u={u}"
            );
            // Reversed, the curve turns the other way.
            let sign = if b >= a { 1.0 } else { -1.0 };
            let k = curve.curvature(a + (b - a) * u);
            assert!(
                (sub.curvature(u) - sign * k).abs() < 1e-12 * k.abs(),
                "{name} {a}..{b} u={u}"
            );
        }
    }
}

#[test]
fn segments_implement_kurbo_traits_honestly() {
    let mut checked = 0;
    for alpha in [-1.0, 0.0, 0.5, 1.0, 2.0] {
        for pts in [
            [p(-1.0, 0.0), p(-0.2, 0.8), p(1.0, 0.0)],
            [p(0.0, 0.0), p(3.0, 0.0), p(4.2, 1.9)],
        ] {
            let Ok(seg) = Segment::from_control_points(pts, alpha) else {
                continue;
            };
            let name = format!("segment {alpha} {pts:?}");
            check(&seg, &name);
            check_subsegments(&seg, &name);
            checked += 1;
        }
    }
    assert!(checked >= 9, "{checked}");
}

#[test]
fn compound_curves_implement_kurbo_traits_honestly() {
    let three = [p(0.0, 0.0), p(2.0, 0.0), p(2.6, 1.2)];
    let four = [p(0.0, 0.0), p(2.0, 0.0), p(2.5, 2.0), p(0.0, 1.5)];
    let mut checked = 0;
    for (a0, a1) in [(-1.0, 2.0), (0.5, -0.5), (1.5, 3.0), (0.0, 1.0)] {
        for ratio in [0.3, 0.5, 0.8] {
            let Ok(c) = CompoundCurve::from_three_points(three, a0, a1, ratio) else {
                continue;
            };
            let name = format!("compound {a0} {a1} {ratio}");
            check(&c, &name);
            check_subsegments(&c, &name);
            checked += 1;
        }
        if let Ok(c) = CompoundCurve::from_four_points(four, a0, a1) {
            let name = format!("four points {a0} {a1}");
            check(&c, &name);
            check_subsegments(&c, &name);
            checked += 1;
        }
    }
    assert!(checked >= 12, "{checked}");
}

#[test]
fn a_compound_subsegment_within_one_piece_stays_connected() {
    let c =
        CompoundCurve::from_three_points([p(0.0, 0.0), p(2.0, 0.0), p(2.6, 1.2)], -1.0, 2.0, 0.5)
            .unwrap();
    let t_joint = c.joint_s() / c.arc_length();
    for range in [
        0.1..0.5 * t_joint,
        0.5 * (1.0 + t_joint)..0.95,
        0.95..(0.5 * (1.0 + t_joint)),
    ] {
        let sub = c.subsegment(range.clone());
        let [a, b] = sub.pieces() else { unreachable!() };
        // One piece is empty, and the chain is connected.
        assert!(a.arc_length() == 0.0 || b.arc_length() == 0.0, "{range:?}");
        assert!(
            (a.end_point() - b.start_point()).hypot() < 1e-14,
            "{range:?}"
        );
        assert!(
            (sub.start_point() - c.eval(range.start)).hypot() < 1e-13,
            "{range:?}"
        );
        assert!(
            (sub.end_point() - c.eval(range.end)).hypot() < 1e-13,
            "{range:?}"
        );
    }
}
