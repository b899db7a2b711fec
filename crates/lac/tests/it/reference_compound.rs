//! Compound curves against the independent 40-digit mpmath reference written by
//! `tools/reference/compound_fixtures.py` (`tests/fixtures/compound.json`).
//!
//! Claims: positions within 1e-12 × chord, curvature (relative to the largest end curvature)
//! and arc lengths (total and to the joint) within 1e-12 relative.

use kurbo::Point;
use lac::Curve;
use lac::{CompoundCurve, Error};
use serde::Deserialize;

use crate::common::fixture_text;

const TOLERANCE: f64 = 1e-12;

#[derive(Deserialize)]
struct File {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    points: Vec<[f64; 2]>,
    alpha0: f64,
    alpha1: f64,
    ratio: Option<f64>,
    kind: String,
    drawable: bool,
    #[serde(default)]
    arc_length: f64,
    #[serde(default)]
    joint_s: f64,
    #[serde(default)]
    curvature_start: f64,
    #[serde(default)]
    curvature_joint: f64,
    #[serde(default)]
    curvature_end: f64,
    #[serde(default)]
    samples: Vec<SampleCase>,
}

#[derive(Deserialize)]
struct SampleCase {
    u: f64,
    x: f64,
    y: f64,
    theta: f64,
    kappa: f64,
}

fn solve(c: &Case) -> lac::Result<CompoundCurve> {
    let p: Vec<Point> = c.points.iter().map(|&[x, y]| Point::new(x, y)).collect();
    match (p.len(), c.ratio) {
        (3, Some(r)) => CompoundCurve::from_three_points([p[0], p[1], p[2]], c.alpha0, c.alpha1, r),
        (4, None) => CompoundCurve::from_four_points([p[0], p[1], p[2], p[3]], c.alpha0, c.alpha1),
        _ => panic!("malformed case {:?}", c.points),
    }
}

#[test]
fn compound_curves_match_the_40_digit_reference() {
    let cases = serde_json::from_str::<File>(&fixture_text("compound.json"))
        .unwrap()
        .cases;
    assert!(cases.len() >= 150, "{} cases", cases.len());
    let (mut worst_pos, mut worst_curv, mut worst_len, mut worst_angle) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut where_pos = String::new();
    let mut where_curv = String::new();
    let (mut drawable, mut refused, mut four) = (0, 0, 0);
    for c in &cases {
        let id = || {
            format!(
                "{:?} a0 {} a1 {} r {:?} ({})",
                c.points, c.alpha0, c.alpha1, c.ratio, c.kind
            )
        };
        let result = solve(c);
        if !c.drawable {
            assert!(
                matches!(
                    result,
                    Err(Error::NotDrawable(_)
                        | Error::InflectedPolygon { .. }
                        | Error::CollinearPoints
                        | Error::CoincidentPoints { .. })
                ),
                "{}: the reference says not drawable",
                id()
            );
            refused += 1;
            continue;
        }
        let curve = result.unwrap_or_else(|e| panic!("{}: {e}", id()));
        drawable += 1;
        four += usize::from(c.points.len() == 4);
        let first = Point::new(c.points[0][0], c.points[0][1]);
        let last = c.points[c.points.len() - 1];
        let chord = (Point::new(last[0], last[1]) - first).hypot();
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        worst_len = worst_len.max(rel(curve.arc_length(), c.arc_length));
        worst_len = worst_len.max((curve.joint_s() - c.joint_s).abs() / c.arc_length);
        let kmax = c.curvature_start.abs().max(c.curvature_end.abs());
        for (got, want) in [
            (curve.signed_curvature_start(), c.curvature_start),
            (curve.signed_curvature_joint(), c.curvature_joint),
            (curve.signed_curvature_end(), c.curvature_end),
        ] {
            worst_curv = worst_curv.max((got - want).abs() / kmax);
        }
        let samples = curve.sample_by_arc_length(21).unwrap();
        for r in &c.samples {
            let want = Point::new(r.x, r.y);
            let s = r.u * curve.arc_length();
            let k = (r.u * 20.0).round() as usize;
            for (got, what) in [
                (curve.point_at_s(s).unwrap(), "at s"),
                (samples[k].point, "sampled"),
            ] {
                let err = (got - want).hypot() / chord;
                if err > worst_pos {
                    worst_pos = err;
                    where_pos = format!("{} u {} {what}", id(), r.u);
                }
            }
            let kerr = (curve.signed_curvature_at_s(s).unwrap() - r.kappa).abs() / kmax;
            let terr = (curve.theta_at_s(s).unwrap() - r.theta).abs();
            if kerr > worst_curv {
                worst_curv = kerr;
                where_curv = format!("{} u {}", id(), r.u);
            }
            worst_angle = worst_angle.max(terr);
        }
    }
    eprintln!(
        "compound: {drawable} drawable ({four} from four points), {refused} refused; worst \
         position/chord {worst_pos:.2e} ({where_pos}); curvature {worst_curv:.2e} ({where_curv}); lengths \
         {worst_len:.2e}; tangent angle {worst_angle:.2e} rad"
    );
    assert!(
        worst_pos < TOLERANCE,
        "position {worst_pos:e} at {where_pos}"
    );
    assert!(worst_curv < TOLERANCE, "curvature {worst_curv:e}");
    assert!(worst_len < TOLERANCE, "length {worst_len:e}");
    assert!(worst_angle < TOLERANCE, "angle {worst_angle:e}");
}
