//! kurbo's curve traits for rational cubics and chains of them, checked against what they
//! claim: derivatives against central differences of `eval`, kurbo's curvature sign,
//! subsegments that keep the parametrisation, arc lengths within the requested accuracy,
//! and no invented answer for a parameter out of range or NaN.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2};

use kurbo::{
    BezPath, CubicBez, ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, PathSeg,
    Point, Vec2,
};
use lac::ToBezier;
use lac::Tolerance;
use lac::{BezierChain, RationalCubic, Segment};

fn wavy() -> RationalCubic {
    RationalCubic::new(
        [
            Point::new(0.1, -0.3),
            Point::new(1.2, 0.9),
            Point::new(2.5, -0.4),
            Point::new(3.1, 1.7),
        ],
        [1.3, 0.4, 2.2, 0.8],
    )
    .unwrap()
}

/// A quarter of the circle of radius `r` about the origin, counter-clockwise from (r, 0).
fn quarter(r: f64) -> RationalCubic {
    let c = FRAC_1_SQRT_2;
    let (k, w) = (2.0 * c / (1.0 + 2.0 * c), (2.0 * c + 1.0) / 3.0);
    RationalCubic::new(
        [
            Point::new(r, 0.0),
            Point::new(r, r * k),
            Point::new(r * k, r),
            Point::new(0.0, r),
        ],
        [1.0, w, w, 1.0],
    )
    .unwrap()
}

/// Weights far apart: the speed varies by two orders of magnitude along the curve.
fn lopsided() -> RationalCubic {
    RationalCubic::new(
        [
            Point::new(0.0, 0.0),
            Point::new(1.0, 2.0),
            Point::new(3.0, 2.5),
            Point::new(4.0, 0.0),
        ],
        [1.0, 20.0, 0.05, 1.0],
    )
    .unwrap()
}

fn plain() -> RationalCubic {
    RationalCubic::from_cubic(CubicBez::new(
        (0.0, 0.0),
        (1.0, 1.5),
        (2.5, 1.0),
        (3.0, -0.5),
    ))
    .unwrap()
}

fn curves() -> [RationalCubic; 4] {
    [wavy(), quarter(2.0), lopsided(), plain()]
}

/// Central differences of `f` at `t`: first (step h) and second (step 10h) derivative.
fn differences(f: impl Fn(f64) -> Point, t: f64, h: f64) -> (Vec2, Vec2) {
    let d1 = (f(t + h) - f(t - h)) / (2.0 * h);
    let k = 10.0 * h;
    let d2 = (f(t + k).to_vec2() - 2.0 * f(t).to_vec2() + f(t - k).to_vec2()) / (k * k);
    (d1, d2)
}

const TS: [f64; 6] = [0.03, 0.21, 0.5, 0.64, 0.88, 0.97];

#[test]
fn derivatives_agree_with_central_differences_of_eval() {
    let h = 1e-5;
    for c in curves() {
        let (d1, d2, d3) = (c.deriv(), c.deriv().deriv(), c.deriv().deriv().deriv());
        let (d4, d5) = (d3.deriv(), d3.deriv().deriv());
        assert_eq!((d1.order(), d2.order(), d3.order()), (1, 2, 3));
        for t in TS {
            let (fd1, fd2) = differences(|t| c.eval(t), t, h);
            let [v1, v2, v3, v4, v5] = [&d1, &d2, &d3, &d4, &d5].map(|d| d.eval(t).to_vec2());
            // Truncation h²/6 |x‴| and (10h)²/12 |x⁗|, doubled for their variation over the
            // stencil, and rounding.
            let tol1 = h * h / 3.0 * v3.hypot() + 1e-9 * v1.hypot().max(1.0);
            let tol2 = 100.0 * h * h / 6.0 * v4.hypot() + 1e-5 * v2.hypot().max(1.0);
            assert!((v1 - fd1).hypot() < tol1, "{c:?} x′({t})");
            assert!((v2 - fd2).hypot() < tol2, "{c:?} x″({t})");
            // The same as the inherent derivative.
            assert!((v1 - c.derivative(t)).hypot() < 1e-14 * v1.hypot());
            // Each order is the derivative of the one below.
            let (fd3, _) = differences(|t| d2.eval(t), t, h);
            let tol3 = h * h / 3.0 * v5.hypot() + 1e-9 * v3.hypot().max(1.0);
            assert!((v3 - fd3).hypot() < tol3, "{c:?} x‴({t})");
        }
    }
}

#[test]
fn a_plain_cubic_has_a_constant_third_derivative_and_no_fourth() {
    let c = plain();
    let b = c.points();
    let want =
        6.0 * (b[3].to_vec2() - 3.0 * b[2].to_vec2() + 3.0 * b[1].to_vec2() - b[0].to_vec2());
    let (d3, d4) = (c.deriv().deriv().deriv(), c.deriv().deriv().deriv().deriv());
    for t in TS {
        assert!((d3.eval(t).to_vec2() - want).hypot() < 1e-13 * want.hypot());
        assert_eq!(d4.eval(t), Point::ZERO);
    }
}

#[test]
fn kurbo_curvature_has_kurbos_sign_and_matches_differences() {
    for c in curves() {
        for t in TS {
            let (d1, d2) = differences(|t| c.eval(t), t, 1e-5);
            // kurbo's convention: x″ × x′ / |x′|³.
            let fd = d2.cross(d1) / d1.hypot().powi(3);
            let k = c.curvature(t);
            assert!(
                (k - fd).abs() < 1e-5 * fd.abs().max(1.0),
                "{c:?} κ({t}): {k} {fd}"
            );
            assert_eq!(k, -c.signed_curvature(t));
            // kurbo's default formula on our derivative curves gives the same.
            let (v1, v2) = (
                c.deriv().eval(t).to_vec2(),
                c.deriv().deriv().eval(t).to_vec2(),
            );
            let default = v2.cross(v1) / v1.hypot().powi(3);
            assert!(
                (k - default).abs() < 1e-12 * k.abs().max(1.0),
                "{k} {default}"
            );
        }
    }
    // A counter-clockwise arc of radius 2 turns left: kurbo says −1/2, we say +1/2.
    let arc = quarter(2.0);
    assert!((arc.curvature(0.4) + 0.5).abs() < 1e-14);
    assert!((arc.signed_curvature(0.4) - 0.5).abs() < 1e-14);
}

#[test]
fn subsegments_keep_the_parametrisation() {
    for c in curves() {
        for (a, b) in [
            (0.0, 1.0),
            (0.2, 0.7),
            (0.55, 0.6),
            (0.9, 0.1),
            (0.0, 0.3),
            (0.4, 1.0),
        ] {
            let sub = c.subsegment(a..b);
            let scale = 1e-14 * c.points()[0].to_vec2().hypot().max(4.0);
            assert!((sub.start() - c.eval(a)).hypot() < scale, "{a}..{b}");
            assert!((sub.end() - c.eval(b)).hypot() < scale, "{a}..{b}");
            for u in [0.0, 0.25, 0.5, 0.8, 1.0] {
                let t = a + u * (b - a);
                assert!((sub.eval(u) - c.eval(t)).hypot() < scale, "{a}..{b} at {u}");
                // Derivatives in the new parameter carry the factor (b − a).
                let want = (b - a) * c.derivative(t);
                let got = sub.deriv().eval(u).to_vec2();
                assert!((got - want).hypot() < 1e-12 * want.hypot().max(1.0));
                // A subsegment of the derivative is the derivative on that range.
                let piece = c.deriv().subsegment(a..b).eval(u).to_vec2();
                assert!((piece - c.derivative(t)).hypot() < 1e-13 * piece.hypot().max(1.0));
            }
            assert!(sub.weights().iter().all(|&w| w > 0.0 && w <= 1.0));
        }
    }
    // A piece of a plain cubic is a plain cubic, kurbo's own piece.
    let c = plain();
    let sub = c.subsegment(0.3..0.8).to_cubic().expect("equal weights");
    let theirs = c.to_cubic().unwrap().subsegment(0.3..0.8);
    for (p, q) in [
        (sub.p0, theirs.p0),
        (sub.p1, theirs.p1),
        (sub.p2, theirs.p2),
        (sub.p3, theirs.p3),
    ] {
        assert!((p - q).hypot() < 1e-14, "{p:?} {q:?}");
    }
}

/// The arc length by composite 16-point Gauss–Legendre on 4096 panels, independent of the
/// adaptive rule (and agreeing with the 2048-panel sum to rounding).
fn reference_length(c: &RationalCubic, t1: f64) -> f64 {
    let panels = 4096;
    let len = c.arc_length_between(0.0, t1);
    let h = t1 / panels as f64;
    let sum: f64 = (0..panels)
        .map(|k| c.arc_length_between(k as f64 * h, (k + 1) as f64 * h))
        .sum();
    assert!(
        (sum - len).abs() < 1e-6 * len.max(1e-300),
        "8-panel rule far off"
    );
    sum
}

#[test]
fn arclen_is_within_the_requested_accuracy() {
    // The quarter circle against its closed form.
    let arc = quarter(2.0);
    for accuracy in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11] {
        let err = (arc.arclen(accuracy) - 2.0 * FRAC_PI_2).abs();
        assert!(err <= accuracy, "quarter circle: {err} for {accuracy}");
    }
    for c in [wavy(), lopsided(), plain()] {
        let exact = reference_length(&c, 1.0);
        for accuracy in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11] {
            let err = (c.arclen(accuracy) - exact).abs();
            assert!(err <= accuracy, "{c:?}: {err} for {accuracy}");
        }
    }
}

#[test]
fn arclen_to_rounding_returns() {
    // Accuracy 0 asks for the length to rounding. On this curve (weights 1e-10 to 1e11)
    // the quadrature's two estimates of every interval differed by a few ulps more than
    // the floor it settled at, so it split every interval 50 times: it ran for minutes.
    let c = RationalCubic::new(
        [
            Point::new(0.414871944522654, -62.512301835765065),
            Point::new(-0.014337709407668339, -0.04651460597449992),
            Point::new(161.93849137571289, 0.019732342900604143),
            Point::new(0.001975309099794858, -0.010030468245566032),
        ],
        [
            2617051824.0125155,
            5.792402452668524e-9,
            8.808480808899191e-11,
            109336894304.8062,
        ],
    )
    .unwrap();
    let len = c.arclen(1e-9);
    assert!((c.arclen(0.0) - len).abs() <= 1e-9);
    // Seeded random curves, coordinates 1e-3 to 1e3 and weights 1e-3 to 1e3, at accuracy
    // 0 and 1e-300: each returns (before the bound on the splits, some took minutes at
    // 1e-6), finite, at least the chord, and the same for both (both ask for rounding);
    // those checked against dense polylines agree to 1e-12. At 1e-3, 1e-6 and 1e-9 of the
    // length each is within about that of the length to rounding (with 8 starting panels
    // whatever the weights, 498.37644 came back at 1e-9 for 498.37683: a narrow wiggle
    // of speed both rules sampled past).
    let mut state = 7u64;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut tried = 0;
    while tried < 200 {
        let mut coordinate = || 10f64.powf(6.0 * next() - 3.0) * (next() - 0.5);
        let p = [0; 4].map(|_| Point::new(coordinate(), coordinate()));
        let w = [0; 4].map(|_| 10f64.powf(6.0 * next() - 3.0));
        let Ok(c) = RationalCubic::new(p, w) else {
            continue;
        };
        tried += 1;
        let (l0, l1) = (c.arclen(0.0), c.arclen(1e-300));
        // The error is estimated (two rules compared), not bounded: over these 600
        // requests the worst was 1.19 times the accuracy asked.
        for share in [1e-3, 1e-6, 1e-9] {
            let l = c.arclen(share * l0);
            assert!(
                (l - l0).abs() <= 2.0 * share * l0,
                "{p:?} {w:?}: {l} at {share} of {l0}"
            );
        }
        let chord = (p[3] - p[0]).hypot();
        assert!(
            l0.is_finite() && l0 == l1 && l0 >= chord * (1.0 - 1e-12),
            "{p:?} {w:?}: {l0} {l1} chord {chord}"
        );
    }
}

#[test]
fn inv_arclen_lands_within_the_requested_accuracy() {
    for c in [wavy(), lopsided(), quarter(2.0)] {
        let total = reference_length(&c, 1.0);
        for accuracy in [1e-3, 1e-6, 1e-9] {
            for share in [0.01, 0.3, 0.5, 0.77, 0.999] {
                let s = share * total;
                let t = c.inv_arclen(s, accuracy);
                assert!((0.0..=1.0).contains(&t));
                let err = (reference_length(&c, t) - s).abs();
                assert!(err <= accuracy, "{c:?}: s = {s}, t = {t}, off by {err}");
            }
        }
        assert_eq!(c.inv_arclen(0.0, 1e-9), 0.0);
        assert_eq!(c.inv_arclen(-1.0, 1e-9), 0.0);
        assert_eq!(c.inv_arclen(2.0 * total, 1e-9), 1.0);
    }
}

#[test]
fn out_of_range_parameters_clamp_and_nan_gives_nan() {
    let c = wavy();
    // Beyond [0, 1] the curve would run into a pole (w(t) = 0); it stops at its ends.
    assert_eq!(c.eval(-0.5), c.eval(0.0));
    assert_eq!(c.eval(1.5), c.eval(1.0));
    assert_eq!(c.eval(f64::NEG_INFINITY), c.eval(0.0));
    assert_eq!(c.deriv().eval(7.0), c.deriv().eval(1.0));
    assert_eq!(c.curvature(-3.0), c.curvature(0.0));
    assert_eq!(
        c.subsegment(-1.0..2.0).eval(0.5),
        c.subsegment(0.0..1.0).eval(0.5)
    );
    // NaN is never read as a start point.
    let nan = f64::NAN;
    let is_nan = |p: Point| p.x.is_nan() && p.y.is_nan();
    assert!(is_nan(c.eval(nan)));
    assert!(is_nan(c.deriv().eval(nan)));
    assert!(is_nan(c.deriv().deriv().eval(nan)));
    assert!(c.curvature(nan).is_nan() && c.signed_curvature(nan).is_nan());
    assert!(c.curvature_derivative(nan).is_nan());
    assert!(c.inv_arclen(nan, 1e-9).is_nan());
    let broken = c.subsegment(nan..0.5);
    assert!(broken.points().into_iter().all(is_nan));
    assert!(broken.arclen(1e-9).is_nan());
    assert!(broken.curvature_monotonicity().is_err());
}

fn chain() -> BezierChain {
    let seg = Segment::from_control_points(
        [
            Point::new(0.0, 0.0),
            Point::new(3.0, 0.0),
            Point::new(4.0, 1.5),
        ],
        -1.0,
    )
    .unwrap();
    let quasi = seg.to_rational_cubics(Tolerance::Relative(1e-7)).unwrap();
    assert!(quasi.pieces.len() >= 3);
    quasi.chain().unwrap()
}

#[test]
fn piece_i_of_n_covers_i_over_n_to_the_next() {
    let c = chain();
    let n = c.pieces().len();
    for (i, piece) in c.pieces().iter().enumerate() {
        let k = i as f64 / n as f64;
        assert_eq!(c.knots()[i], k);
        assert_eq!(c.eval(k), piece.eval(0.0));
        let mid = (i as f64 + 0.5) / n as f64;
        assert!((c.eval(mid) - piece.eval(0.5)).hypot() < 1e-14);
    }
    assert_eq!(c.eval(1.0), c.pieces()[n - 1].eval(1.0));
    assert_eq!(
        (c.start(), c.end()),
        (c.pieces()[0].start(), c.pieces()[n - 1].end())
    );
}

#[test]
fn chain_derivatives_and_curvature_agree_with_central_differences() {
    let c = chain();
    let n = c.pieces().len() as f64;
    let (d1, d2) = (c.deriv(), c.deriv().deriv());
    for i in 0..c.pieces().len() {
        // Inside the pieces, away from the knots the differences would straddle.
        for u in [0.2, 0.5, 0.8] {
            let t = (i as f64 + u) / n;
            let (fd1, fd2) = differences(|t| c.eval(t), t, 1e-6);
            let (v1, v2) = (d1.eval(t).to_vec2(), d2.eval(t).to_vec2());
            assert!((v1 - fd1).hypot() < 1e-7 * v1.hypot(), "x′({t})");
            assert!((v2 - fd2).hypot() < 1e-4 * v2.hypot().max(1.0), "x″({t})");
            let fd = fd2.cross(fd1) / fd1.hypot().powi(3);
            assert!((c.curvature(t) - fd).abs() < 1e-4 * fd.abs(), "κ({t})");
            // The clothoid turns left: kurbo's curvature is negative.
            assert!(c.curvature(t) < 0.0);
        }
    }
}

#[test]
fn chain_subsegments_keep_the_parametrisation_across_knots() {
    let c = chain();
    for (a, b) in [
        (0.1, 0.9),
        (0.0, 1.0),
        (0.45, 0.52),
        (0.8, 0.15),
        (0.3, 0.3),
    ] {
        let sub = c.subsegment(a..b);
        assert_eq!((sub.knots()[0], *sub.knots().last().unwrap()), (0.0, 1.0));
        assert!(sub.knots().windows(2).all(|w| w[0] < w[1]) || a == b);
        assert!((sub.start() - c.eval(a)).hypot() < 1e-13, "{a}..{b}");
        assert!((sub.end() - c.eval(b)).hypot() < 1e-13, "{a}..{b}");
        for u in [0.1, 0.333, 0.5, 0.9] {
            let t = a + u * (b - a);
            assert!((sub.eval(u) - c.eval(t)).hypot() < 1e-13, "{a}..{b} at {u}");
            let want = (b - a) * c.deriv().eval(t).to_vec2();
            let got = sub.deriv().eval(u).to_vec2();
            assert!(
                (got - want).hypot() < 1e-10 * want.hypot().max(1e-3),
                "{a}..{b} at {u}"
            );
        }
    }
}

#[test]
fn chain_arc_length_is_the_sum_within_the_accuracy() {
    let c = chain();
    let exact: f64 = c.pieces().iter().map(|p| reference_length(p, 1.0)).sum();
    for accuracy in [1e-1, 1e-4, 1e-7, 1e-10] {
        assert!((c.arclen(accuracy) - exact).abs() <= accuracy);
        for share in [0.05, 0.5, 0.95] {
            let t = c.inv_arclen(share * exact, accuracy);
            let s = c.subsegment(0.0..t).arclen(1e-13);
            assert!((s - share * exact).abs() <= accuracy, "{share}: {s}");
        }
    }
    assert!(c.inv_arclen(f64::NAN, 1e-9).is_nan());
    let nan = c.eval(f64::NAN);
    assert!(nan.x.is_nan() && nan.y.is_nan());
    assert!(c.curvature(f64::NAN).is_nan());
}

#[test]
fn plain_cubic_chains_are_kurbo_paths_and_rational_ones_are_not() {
    let seg = Segment::from_control_points(
        [
            Point::new(0.0, 0.0),
            Point::new(2.0, 0.0),
            Point::new(2.6, 1.2),
        ],
        0.5,
    )
    .unwrap();
    let quasi = seg.to_cubics(Tolerance::Relative(1e-6)).unwrap();
    let path = quasi.to_bez_path().expect("plain cubics");
    // The SVG path data reads back as the pieces.
    let back = BezPath::from_svg(&path.to_svg()).unwrap();
    let segs: Vec<PathSeg> = back.segments().collect();
    assert_eq!(segs.len(), quasi.pieces.len());
    for (seg, piece) in segs.iter().zip(&quasi.pieces) {
        let PathSeg::Cubic(c) = seg else {
            panic!("{seg:?}")
        };
        let b = piece.curve.points();
        for (p, q) in [(c.p1, b[1]), (c.p2, b[2]), (c.p3, b[3])] {
            assert_eq!(p, q);
        }
        // Each starts where the previous one ends, within rounding of the fit.
        assert!((c.p0 - b[0]).hypot() < 1e-13);
    }
    assert!(seg
        .to_rational_cubics(Tolerance::Relative(1e-6))
        .unwrap()
        .to_bez_path()
        .is_none());
    assert!(BezierChain::new(Vec::new()).is_err());
}
