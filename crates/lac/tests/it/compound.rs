//! Claims about compound-rhythm curves (docs/math.md §4, seeds 004 and 002).

use kurbo::{Point, Vec2};
use lac::Curve;
use lac::SegmentChain;
use lac::{CompoundCurve, Error, NotDrawable, Segment};
use proptest::prelude::*;

fn three() -> [Point; 3] {
    [
        Point::new(0.0, 0.0),
        Point::new(1.0, 0.0),
        Point::new(1.6, 0.9),
    ]
}

/// Position, tangent, curvature and dκ/ds are continuous at the joint (G3).
#[test]
fn the_joint_is_g3() {
    for (a0, a1) in [
        (-1.0, 2.0),
        (2.0, -1.0),
        (0.5, -0.5),
        (-2.0, -0.5),
        (1.5, 3.0),
    ] {
        let c = CompoundCurve::from_three_points(three(), a0, a1, 0.4).unwrap();
        let [p, q] = c.pieces() else {
            panic!("a compound curve has two pieces")
        };
        let j = c.joint_s();
        assert!((p.point_at_s(j).unwrap() - q.point_at_s(0.0).unwrap()).hypot() < 1e-14);
        assert!((p.theta_at_s(j).unwrap() - q.theta_at_s(0.0).unwrap()).abs() < 1e-14);
        let (k0, k1) = (p.signed_curvature_end(), q.signed_curvature_start());
        assert!((k0 - k1).abs() < 1e-13 * k0.abs(), "{a0} {a1}: {k0} {k1}");
        // One-sided second-order differences of κ on each side of the joint.
        let h = 1e-4 * c.arc_length();
        let left = (3.0 * k0 - 4.0 * c.signed_curvature_at_s(j - h).unwrap()
            + c.signed_curvature_at_s(j - 2.0 * h).unwrap())
            / (2.0 * h);
        let right = (-3.0 * k1 + 4.0 * c.signed_curvature_at_s(j + h).unwrap()
            - c.signed_curvature_at_s(j + 2.0 * h).unwrap())
            / (2.0 * h);
        assert!(
            (left - right).abs() < 1e-5 * left.abs().max(right.abs()),
            "{a0} {a1}: dκ/ds {left} vs {right}"
        );
    }
}

/// Seed 002 writes each piece as ρ^α = c s + d with c₁ = (α₁/α₀) c₀ ρc^(α₁−α₀) and
/// d₁ = ρc^α₁ − c₁ sc: an independent formulation, checked on our solutions.
#[test]
fn the_seed_002_joint_conditions_hold() {
    for (a0, a1) in [(-1.0, 2.0), (2.0, -1.0), (0.5, 1.5), (-0.5, -2.0)] {
        for c in [
            CompoundCurve::from_three_points(three(), a0, a1, 0.6).unwrap(),
            CompoundCurve::from_four_points(
                [
                    Point::new(0.0, 0.0),
                    Point::new(1.0, 0.0),
                    Point::new(1.5, 1.0),
                    Point::new(0.8, 1.8),
                ],
                a0,
                a1,
            )
            .unwrap(),
        ] {
            let (len, sc) = (c.arc_length(), c.joint_s());
            let rho = |s: f64| 1.0 / c.signed_curvature_at_s(s).unwrap().abs();
            // Fit c, d on each piece from two points, check a third.
            let fit = |alpha: f64, s0: f64, s1: f64| {
                let (y0, y1) = (rho(s0).powf(alpha), rho(s1).powf(alpha));
                let cc = (y1 - y0) / (s1 - s0);
                (cc, y0 - cc * s0)
            };
            let (c0, d0) = fit(a0, 0.1 * sc, 0.9 * sc);
            let (c1, d1) = fit(a1, sc + 0.1 * (len - sc), sc + 0.9 * (len - sc));
            for (alpha, cc, dd, s) in [(a0, c0, d0, 0.5 * sc), (a1, c1, d1, 0.5 * (sc + len))] {
                let y = rho(s).powf(alpha);
                assert!(
                    (y - (cc * s + dd)).abs() < 1e-9 * y.abs(),
                    "linearity, {a0} {a1}"
                );
            }
            let rc = 1.0 / c.signed_curvature_joint().abs();
            let want_c1 = a1 / a0 * c0 * rc.powf(a1 - a0);
            assert!(
                (c1 - want_c1).abs() < 1e-8 * c1.abs(),
                "c1 {c1} vs {want_c1}"
            );
            let want_d1 = rc.powf(a1) - c1 * sc;
            assert!(
                (d1 - want_d1).abs() < 1e-8 * d1.abs().max(rc.powf(a1)),
                "d1 {d1} vs {want_d1}"
            );
        }
    }
}

/// α0 = α1 is a single segment, wherever the joint is (docs/math.md §4).
#[test]
fn equal_slopes_give_the_single_segment() {
    for alpha in [-1.0, 0.0, 0.5, 1.0, 2.0] {
        let seg = Segment::from_control_points(three(), alpha).unwrap();
        for ratio in [0.1, 0.5, 0.9] {
            let c = CompoundCurve::from_three_points(three(), alpha, alpha, ratio).unwrap();
            assert!((c.arc_length() - seg.arc_length()).abs() < 1e-13);
            assert!(
                (c.signed_curvature_start() - seg.signed_curvature_start()).abs()
                    < 1e-12 * seg.signed_curvature_start().abs()
            );
            assert!(
                (c.signed_curvature_end() - seg.signed_curvature_end()).abs()
                    < 1e-12 * seg.signed_curvature_end().abs()
            );
            for u in [0.2, 0.7] {
                let s = u * c.arc_length();
                assert!((c.point_at_s(s).unwrap() - seg.point_at_s(s).unwrap()).hypot() < 1e-13);
            }
        }
    }
}

/// α0 and r_θ refer to the piece at the caller's first point, whichever way the solver runs:
/// reversing the input (and swapping α0 ↔ α1, r → 1 − r) reverses the same curve.
#[test]
fn reversing_the_input_reverses_the_curve() {
    let p = three();
    for (a0, a1, r) in [(-1.0, 2.0, 0.3), (2.0, -1.0, 0.7), (0.2, 0.9, 0.5)] {
        let fwd = CompoundCurve::from_three_points(p, a0, a1, r).unwrap();
        let back = CompoundCurve::from_three_points([p[2], p[1], p[0]], a1, a0, 1.0 - r).unwrap();
        let len = fwd.arc_length();
        assert!((back.arc_length() - len).abs() < 1e-13);
        assert!((back.joint_s() - (len - fwd.joint_s())).abs() < 1e-12);
        for u in [0.0, 0.25, 0.6, 1.0] {
            let d = fwd.point_at_s(u * len).unwrap() - back.point_at_s((1.0 - u) * len).unwrap();
            assert!(d.hypot() < 1e-12, "{a0} {a1} {r} u {u}");
        }
        // The α0 piece is the one at the caller's first point.
        assert_eq!(fwd.alpha(), [a0, a1]);
        let turn0 = (fwd.theta_at_s(fwd.joint_s()).unwrap() - fwd.theta_at_s(0.0).unwrap()).abs();
        let total = (fwd.theta_at_s(len).unwrap() - fwd.theta_at_s(0.0).unwrap()).abs();
        assert!((turn0 / total - r).abs() < 1e-13);
    }
}

#[test]
fn four_points_fix_ends_tangents_and_the_joint_direction() {
    // Turns 230°: more than the three-point form can express.
    let pts = [
        Point::new(0.0, 0.0),
        Point::new(2.0, 0.0),
        Point::new(2.5, 2.0),
        Point::new(0.0, 2.5),
    ];
    for (a0, a1) in [(-1.0, 2.0), (0.5, 0.5), (2.0, -1.0), (1.0, 0.0)] {
        let c = match CompoundCurve::from_four_points(pts, a0, a1) {
            Ok(c) => c,
            Err(Error::NotDrawable(_)) => continue,
            Err(e) => panic!("{a0} {a1}: {e}"),
        };
        let len = c.arc_length();
        assert!((c.point_at_s(0.0).unwrap() - pts[0]).hypot() < 1e-13);
        assert!((c.point_at_s(len).unwrap() - pts[3]).hypot() < 1e-12);
        let dir = |v: Vec2| v.atan2();
        let wrap = |a: f64| {
            (a + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
        };
        assert!(wrap(c.theta_at_s(0.0).unwrap() - dir(pts[1] - pts[0])).abs() < 1e-13);
        assert!(wrap(c.theta_at_s(c.joint_s()).unwrap() - dir(pts[2] - pts[1])).abs() < 1e-12);
        assert!(wrap(c.theta_at_s(len).unwrap() - dir(pts[3] - pts[2])).abs() < 1e-12);
    }
    assert!(CompoundCurve::from_four_points(pts, 0.5, 0.5).is_ok());
}

#[test]
fn errors_name_the_problem() {
    let zig = [
        Point::new(0.0, 0.0),
        Point::new(1.0, 0.0),
        Point::new(2.0, 1.0),
        Point::new(3.0, 0.0),
    ];
    assert!(matches!(
        CompoundCurve::from_four_points(zig, 0.5, 0.5),
        Err(Error::InflectedPolygon {
            first: lac::Turn::Left,
            second: lac::Turn::Right
        })
    ));
    // Arc lengths outside the curve are refused, not clamped to an end.
    let c = CompoundCurve::from_three_points(three(), 0.5, -1.0, 0.5).unwrap();
    for s in [-0.1, 1.5 * c.arc_length(), f64::INFINITY, f64::NAN] {
        assert!(
            c.point_at_s(s).is_err() && c.signed_curvature_at_s(s).is_err(),
            "s = {s}"
        );
    }
    assert!(c.point_at_s(c.arc_length()).is_ok() && c.sample_by_arc_length(1).is_err());
    for ratio in [0.0, 1.0, 1.5, f64::NAN] {
        assert!(CompoundCurve::from_three_points(three(), 0.5, 0.5, ratio).is_err());
    }
    // Turning 260° one way, but the chord P3 − P0 (at 284°) leaves the tangents' sweep.
    let outside = [
        Point::new(0.0, 0.0),
        Point::new(1.0, 0.0),
        Point::new(1.0, 1.0),
        Point::new(0.5, -2.0),
    ];
    assert!(matches!(
        CompoundCurve::from_four_points(outside, 0.5, 0.5),
        Err(Error::NotDrawable(NotDrawable::ChordOutsideTangents { .. }))
    ));
    let far = [
        Point::new(-1.0, 0.0),
        Point::new(0.9, 0.9),
        Point::new(1.0, 0.0),
    ];
    assert!(matches!(
        CompoundCurve::from_three_points(far, -1.0, -1.0, 0.5),
        Err(Error::NotDrawable(_))
    ));
}

#[test]
fn the_lcg_is_one_continuous_polyline() {
    let c = CompoundCurve::from_three_points(three(), -1.0, 2.0, 0.5).unwrap();
    let [l0, l1] = c.lcg().map(Option::unwrap);
    assert_eq!((l0.alpha, l1.alpha), (-1.0, 2.0));
    assert!((l0.log_rho.1 - l1.log_rho.0).abs() < 1e-14);
    assert!((l0.at(l0.log_rho.1) - l1.at(l1.log_rho.0)).abs() < 1e-13);
    // And it is the graph of the curve: ρ ds/dρ from finite differences.
    let s = 0.3 * c.joint_s();
    let h = 1e-5;
    let rho = |s: f64| 1.0 / c.signed_curvature_at_s(s).unwrap().abs();
    let drho = (rho(s + h) - rho(s - h)) / (2.0 * h);
    let y = (rho(s) / drho.abs()).ln();
    assert!((y - l0.at(rho(s).ln())).abs() < 1e-6);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn compound_curves_reproduce_their_control_points(
        bx in -1.5f64..1.5, by in -1.5f64..1.5,
        a0 in prop_oneof![-50.0f64..50.0, -2.0f64..3.0, Just(0.0), Just(1.0)],
        a1 in prop_oneof![-50.0f64..50.0, -2.0f64..3.0, Just(0.0), Just(1.0)],
        ratio in 0.01f64..0.99,
        angle in -3.2f64..3.2,
        log_scale in -6.0f64..6.0,
    ) {
        let rot = Vec2::from_angle(angle) * 10f64.powf(log_scale);
        let map = |x: f64, y: f64| Point::new(rot.x * x - rot.y * y, rot.y * x + rot.x * y);
        let pts = [map(-1.0, 0.0), map(bx, by), map(1.0, 0.0)];
        if let Ok(c) = CompoundCurve::from_three_points(pts, a0, a1, ratio) {
            let chord = (pts[2] - pts[0]).hypot();
            let samples = c.sample_by_arc_length(33).unwrap();
            prop_assert!((samples[0].point - pts[0]).hypot() <= 1e-12 * chord);
            prop_assert!((samples[32].point - pts[2]).hypot() <= 1e-11 * chord, "{:?}", samples[32].point);
            let k: Vec<f64> = samples.iter().map(|s| s.kappa).collect();
            prop_assert!(k.iter().all(|x| x.is_finite()));
            let up = k.windows(2).all(|w| w[1] >= w[0] - 1e-12 * w[0].abs());
            let down = k.windows(2).all(|w| w[1] <= w[0] + 1e-12 * w[0].abs());
            prop_assert!(up || down, "curvature not monotone: {k:?}");
            // A piece may be shorter than an ulp of the whole (curvature ratios up to e^600).
            let j = c.joint_s();
            prop_assert!(j >= 0.0 && j <= c.arc_length());
        }
    }
}

/// Near a circle the first Newton step is small; the solver once stopped after it because
/// its convergence estimate needs two steps (found by the 40-digit compound fixtures).
#[test]
fn near_circles_converge_fully() {
    let p = [
        Point::new(18.355_573_376_593_092, -4.103_424_522_260_902_5),
        Point::new(18.318_987_487_307_86, -4.168_665_707_204_79),
        Point::new(18.366_831_693_312_832, -4.226_179_966_007_010_5),
    ];
    let c = CompoundCurve::from_three_points(p, 0.5, -1.0, 0.422_304_407_413_060_2).unwrap();
    // mpmath at 40 digits: Λ = 5.00000000035264662e-4, κ0 = 9.19692838237197741. Λ is set
    // by θe − Θ/2 ≈ 6e-5, known to ~1e-16 absolute, so to ~1e-11 relative (the bug: 1.3e-8).
    assert!(
        (c.lambda() - 5.000_000_000_352_647e-4).abs() < 1e-10 * 5e-4,
        "{}",
        c.lambda()
    );
    assert!((c.signed_curvature_start() - 9.196_928_382_371_977).abs() < 1e-13 * 9.2);
}
