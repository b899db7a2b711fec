//! Claim: every planar curve type answers `Curve`'s questions consistently. A point, tangent
//! direction and signed curvature asked at one arc length agree with the samples at the
//! same arc length; dκ/ds agrees with central differences of κ; the tangent direction is
//! continuous from the first point across joints (paths with straight pieces, chains of
//! Bézier pieces); the provided adaptive sampling stays within its accuracy; and the
//! logarithmic curvature graph gives a segment's own α back.

use kurbo::{ParamCurve, Point};
use lac::{
    Alphas, BezierChain, Closure, CompoundCurve, ControlPolygon, Curve, Path, RationalCubic,
    Segment, Spline, ToBezier, Tolerance,
};

fn segment() -> Segment {
    Segment::from_control_points(
        [
            Point::new(0.0, 0.0),
            Point::new(3.0, 0.0),
            Point::new(4.2, 1.9),
        ],
        0.5,
    )
    .unwrap()
}

/// A G2 path through an inflection: two segments and a straight piece between them.
fn s_path() -> Path {
    let points: Vec<Point> = [
        (0.0, 0.0),
        (1.0, 0.0),
        (2.0, 0.5),
        (5.0, 2.5),
        (6.0, 3.0),
        (7.0, 3.0),
    ]
    .iter()
    .map(|&(x, y)| Point::new(x, y))
    .collect();
    let polygon = ControlPolygon::from_points(&points, Closure::Open).unwrap();
    let path = Path::from_polygon_g2(&polygon, &Alphas::One(-1.0)).unwrap();
    assert!(
        !path.straight_pieces().is_empty(),
        "the test path has a straight piece"
    );
    path
}

fn bezier_chain() -> BezierChain {
    segment()
        .to_rational_cubics(Tolerance::Relative(1e-10))
        .unwrap()
        .chain()
        .unwrap()
}

fn spline() -> Spline {
    let points = [
        Point::new(0.0, 0.0),
        Point::new(2.0, 0.3),
        Point::new(3.5, 1.5),
        Point::new(4.0, 3.0),
    ];
    Spline::from_points(&points, 0.5, Closure::Open, None).unwrap()
}

fn compound() -> CompoundCurve {
    CompoundCurve::from_three_points(
        [
            Point::new(0.0, 0.0),
            Point::new(1.0, 0.0),
            Point::new(1.6, 0.9),
        ],
        -1.0,
        2.0,
        0.5,
    )
    .unwrap()
}

fn curves() -> Vec<(&'static str, Box<dyn Curve>)> {
    vec![
        ("segment", Box::new(segment())),
        ("compound", Box::new(compound())),
        ("path", Box::new(s_path())),
        ("spline", Box::new(spline())),
        ("bezier chain", Box::new(bezier_chain())),
    ]
}

#[test]
fn every_curve_answers_at_an_arc_length_what_its_samples_say_there() {
    for (name, curve) in curves() {
        let len = curve.arc_length();
        let samples = curve.sample_by_arc_length(41).unwrap();
        assert!(
            (samples[0].point - curve.start_point()).hypot() <= 1e-12 * len,
            "{name}"
        );
        assert!(
            (samples[40].point - curve.end_point()).hypot() <= 1e-12 * len,
            "{name}"
        );
        let kmax = samples.iter().fold(0.0f64, |m, s| m.max(s.kappa.abs()));
        for s in &samples {
            let point = curve.point_at_s(s.s).unwrap();
            assert!(
                (point - s.point).hypot() <= 1e-10 * len,
                "{name} at {}",
                s.s
            );
            let theta = curve.theta_at_s(s.s).unwrap();
            assert!(
                (theta - s.theta).abs() <= 1e-9,
                "{name} θ at {}: {theta} {}",
                s.s,
                s.theta
            );
            let kappa = curve.signed_curvature_at_s(s.s).unwrap();
            assert!(
                (kappa - s.kappa).abs() <= 1e-9 * kmax,
                "{name} κ at {}",
                s.s
            );
        }
        let ends = (curve.signed_curvature_start(), curve.signed_curvature_end());
        assert!((ends.0 - samples[0].kappa).abs() <= 1e-9 * kmax, "{name}");
        assert!((ends.1 - samples[40].kappa).abs() <= 1e-9 * kmax, "{name}");
        let turning = samples[40].theta - samples[0].theta;
        assert!((curve.turning() - turning).abs() <= 1e-9, "{name} turning");
    }
}

#[test]
fn the_curvature_derivative_is_that_of_the_curvature() {
    for (name, curve) in curves() {
        let len = curve.arc_length();
        let joints = curve.joint_arc_lengths();
        let h = 1e-6 * len;
        for i in 1..20 {
            let s = len * i as f64 / 20.0;
            // Central differences only away from joints, where κ may jump or bend.
            if joints.iter().any(|j| (j - s).abs() < 2.0 * h) {
                continue;
            }
            let ahead = curve.signed_curvature_at_s(s + h).unwrap();
            let behind = curve.signed_curvature_at_s(s - h).unwrap();
            let difference = (ahead - behind) / (2.0 * h);
            let exact = curve.curvature_derivative_at_s(s).unwrap();
            assert!(
                (difference - exact).abs() <= 1e-5 * exact.abs().max(1.0),
                "{name} at {s}: {difference} against {exact}"
            );
        }
    }
}

#[test]
fn a_bezier_chain_is_measured_by_arc_length_piece_by_piece() {
    let chain = bezier_chain();
    let pieces = chain.pieces();
    assert!(pieces.len() > 1);
    let lengths: Vec<f64> = pieces.iter().map(RationalCubic::arc_length).collect();
    let total: f64 = lengths.iter().sum();
    assert_eq!(chain.arc_length(), total);
    let joints = chain.joint_arc_lengths();
    assert_eq!(joints.len(), pieces.len() - 1);
    // The joints are where the pieces meet, and the tangent is continuous there.
    let mut start = 0.0;
    for (i, &joint) in joints.iter().enumerate() {
        start += lengths[i];
        assert_eq!(joint, start);
        let at = chain.point_at_s(joint).unwrap();
        assert!((at - pieces[i + 1].start()).hypot() <= 1e-12 * total);
        let before = chain.theta_at_s(joint - 1e-9 * total).unwrap();
        let after = chain.theta_at_s(joint).unwrap();
        assert!((after - before).abs() <= 1e-6, "θ jumps at joint {i}");
    }
    // Inside a piece, the point at s is where that piece's own arc length reaches s.
    let s = 0.5 * lengths[0];
    let point = chain.point_at_s(s).unwrap();
    let t = (0..=4000)
        .map(|k| k as f64 / 4000.0)
        .min_by(|a, b| {
            let da = (pieces[0].eval(*a) - point).hypot();
            let db = (pieces[0].eval(*b) - point).hypot();
            da.total_cmp(&db)
        })
        .unwrap();
    assert!((pieces[0].arc_length_between(0.0, t) - s).abs() <= 1e-3 * lengths[0]);
    assert!(chain.point_at_s(-1.0).is_err() && chain.point_at_s(f64::NAN).is_err());
}

#[test]
fn adaptive_samples_stay_within_their_accuracy() {
    for (name, curve) in curves() {
        let accuracy = 1e-4 * curve.arc_length();
        let polyline = curve.sample_adaptive(accuracy).unwrap();
        for w in polyline.windows(2) {
            let middle = curve.point_at_s(0.5 * (w[0].s + w[1].s)).unwrap();
            let (p, q) = (w[0].point, w[1].point);
            let chord = q - p;
            let d = if chord.hypot() == 0.0 {
                (middle - p).hypot()
            } else {
                (middle - p).cross(chord).abs() / chord.hypot()
            };
            assert!(d <= 1.01 * accuracy, "{name}: {d:e} over {accuracy:e}");
        }
    }
}

#[test]
fn a_segment_s_logarithmic_curvature_graph_gives_its_alpha_back() {
    let graph = segment().log_curvature_graph(65).unwrap();
    let fit = graph.fit.unwrap();
    assert!((fit.alpha - 0.5).abs() <= 1e-9, "{}", fit.alpha);
}
