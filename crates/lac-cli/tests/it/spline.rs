//! `lac spline`: G2 splines through points, their JSON, CSV and SVG, and their errors (the
//! span named).

use crate::common;

use common::{assert_failure, f, json, lac};

#[test]
fn open_spline_passes_through_its_points_with_continuous_curvature() {
    let through = "0,0 2,0.3 3.5,1.5 4,3 3.5,4.5";
    let run = lac(&["spline", "--through", through, "--alpha", "-0.5"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    let spans = v["pieces"].as_array().unwrap();
    assert_eq!(spans.len(), 4);
    assert!(v["inflections"].as_array().unwrap().is_empty());
    let points = v["points"].as_array().unwrap();
    for (i, s) in spans.iter().enumerate() {
        assert_eq!(s["control_points"][0], points[i]);
        assert_eq!(s["control_points"][2], points[i + 1]);
    }
    for w in spans.windows(2) {
        let (a, b) = (f(&w[0]["curvature"][1]), f(&w[1]["curvature"][0]));
        assert!((a - b).abs() <= 1e-9 * a.abs().max(b.abs()), "{a} {b}");
    }
    assert_eq!(v["curvature_jumps"].as_array().unwrap().len(), 3);
    assert!(f(&v["max_curvature_jump"]) <= 1e-9);
    // Given end tangents; CSV and SVG.
    let run = lac(&[
        "spline",
        "--through",
        through,
        "--alpha",
        "0.5",
        "--start-angle",
        "0.1",
        "--end-angle",
        "2.0",
        "--format",
        "csv",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.starts_with("s,x,y,theta,kappa"));
    let run = lac(&[
        "spline",
        "--through",
        "0,0 3,-0.5 4.5,2 2,4 -0.5,2.5",
        "--closed",
        "--alpha",
        "1",
        "--format",
        "svg",
        "--comb",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.contains("<svg") && run.stdout.contains("joint s = "));
}

#[test]
fn a_span_through_an_inflection_is_two_pieces_meeting_at_zero_curvature() {
    let wave = "0,0.2955 1,0.9320 2,0.8632 3,0.1411 4,-0.6878 5,-0.9962 6,-0.5507 7,0.3115";
    let run = lac(&["spline", "--through", wave, "--alpha", "-1"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    let pieces = v["pieces"].as_array().unwrap();
    let spans: Vec<u64> = pieces.iter().map(|p| p["span"].as_u64().unwrap()).collect();
    assert_eq!(spans, [0, 1, 2, 3, 3, 4, 5, 6]);
    let inflections = v["inflections"].as_array().unwrap();
    assert_eq!(inflections.len(), 1);
    assert_eq!(inflections[0]["span"], 3);
    let (before, after) = (&pieces[3], &pieces[4]);
    let (k0, k1) = (f(&before["curvature"][1]), f(&after["curvature"][0]));
    assert!(
        k0.abs().max(k1.abs()) <= 1e-9 && k0 * k1 <= 0.0,
        "{k0} {k1}"
    );
    assert!(f(&before["curvature"][0]) * f(&after["curvature"][1]) < 0.0);
    // The halves meet at the inflection point.
    let m = &inflections[0]["point"];
    for end in [&before["control_points"][2], &after["control_points"][0]] {
        let d = (f(&end[0]) - f(&m[0])).hypot(f(&end[1]) - f(&m[1]));
        assert!(d <= 1e-11, "{d}");
    }
    assert!(f(&v["max_curvature_jump"]) <= 1e-9);
}

#[test]
fn a_span_that_must_inflect_is_named() {
    let run = lac(&[
        "spline",
        "--through",
        "0,0 2,0.5 4,0 6,-0.5 8,0",
        "--alpha",
        "0.5",
    ]);
    assert_failure(&run, 3, "no_g2_path");
    assert!(
        run.stderr.contains("would have to inflect"),
        "{}",
        run.stderr
    );
    let run = lac(&["spline", "--through", "0,0 1,1", "--alpha", "0.5"]);
    assert_failure(&run, 2, "invalid_input");
}

/// Issue 35: the joints of a spline lie on the points it passes through, where a dot would
/// hide under the point's circle: they are rings around it, and the legend shows rings.
#[test]
fn the_svg_marks_joints_on_the_points_as_rings_that_the_points_do_not_hide() {
    let run = lac(&[
        "spline",
        "--through",
        "0,0 2,0.3 3.5,1.5 4,3",
        "--alpha",
        "0.5",
        "--format",
        "svg",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = &run.stdout;
    let circles: Vec<&str> = svg.lines().filter(|l| l.starts_with("<circle")).collect();
    let joints: Vec<&&str> = circles
        .iter()
        .filter(|l| l.contains(r#"class="joint""#))
        .collect();
    assert_eq!(joints.len(), 2, "{joints:?}");
    for joint in joints {
        // Larger than the point's circle (r 3.5) and open, so the point shows inside it.
        assert!(
            joint.contains(r#"r="6""#) && joint.contains(r#"fill="none""#),
            "{joint}"
        );
    }
    let keys: Vec<&&str> = circles
        .iter()
        .filter(|l| l.contains(r#"class="key""#))
        .collect();
    assert!(
        !keys.is_empty() && keys.iter().all(|k| k.contains(r#"fill="none""#)),
        "{keys:?}"
    );
}

/// A U with point types: straight sides (`--lines`) met with zero curvature, the bottom
/// horizontal (`--types`, `--angles`); the report gives each point's type, directions and
/// curvatures on both sides, and the knots; the same read back by `lac export`.
#[test]
fn point_types_straight_spans_and_end_curvatures_are_reported_per_point() {
    let u = [
        "spline",
        "--through",
        "0,4 0,1.5 1,0 2,1.5 2,4",
        "--alpha",
        "-1",
        "--types",
        "s s t s s",
        "--angles",
        "2:0",
        "--lines",
        "0-1,3-4",
        "--samples",
        "5",
    ];
    let run = lac(&u);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    let at = v["at_points"].as_array().unwrap();
    assert_eq!(at.len(), 5);
    assert_eq!(at[2]["type"], "tangent");
    assert!(f(&at[2]["angles"][0]).abs() < 1e-12 && f(&at[2]["angles"][1]).abs() < 1e-12);
    let (k0, k1) = (f(&at[2]["curvatures"][0]), f(&at[2]["curvatures"][1]));
    assert!((k0 - k1).abs() <= 1e-9 * k0.abs());
    for i in [1, 3] {
        assert_eq!(at[i]["straight"][usize::from(i == 3)], true);
        let k = f(&at[i]["curvatures"][usize::from(i == 1)]);
        assert!(k.abs() <= 1e-12 * k0.abs(), "{k}");
    }
    assert!(at[0]["angles"][0].is_null() && at[4]["curvatures"][1].is_null());
    assert_eq!(v["knots"].as_array().unwrap().len(), 2);
    assert_eq!(v["lines"], serde_json::json!([0, 3]));
    // The report read back: the same spline exported.
    let export = common::lac_with_input(&["export", "--format", "json"], run.stdout.as_bytes());
    assert_eq!(export.code, 0, "{}", export.stderr);
    // A G2 Hermite start and a curvature-only end.
    let run = lac(&[
        "spline",
        "--through",
        "0,0 1,0.6 2,0.8 3,0.6 4,0",
        "--alpha",
        "0.5",
        "--start-angle",
        "0.7",
        "--start-curvature",
        "-0.3",
        "--end-curvature",
        "-0.2",
        "--samples",
        "2",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert!((f(&v["at_points"][0]["curvatures"][1]) + 0.3).abs() <= 1e-12 * 0.3);
    assert!((f(&v["at_points"][4]["curvatures"][0]) + 0.2).abs() <= 1e-12 * 0.2);
    assert_eq!(v["start"]["curvature"], -0.3);
}

/// Refusals: a straight span for alpha >= 0 names its point and says what to change; bad
/// types, angles and lines are usage errors.
#[test]
fn point_type_refusals_name_the_point() {
    let through = "0,4 0,1.5 1,0 2,1.5 2,4";
    let run = lac(&[
        "spline",
        "--through",
        through,
        "--alpha",
        "0.5",
        "--lines",
        "0-1",
    ]);
    let message = assert_failure(&run, 3, "no_g2_path");
    assert!(
        message.contains("point P1") && message.contains("make this point a corner"),
        "{message}"
    );
    for args in [
        ["--types", "s s t s"],
        ["--types", "s s t s s"],
        ["--lines", "1-3"],
        ["--types", "s s x s s"],
    ] {
        let mut all = vec!["spline", "--through", through, "--alpha", "-1"];
        all.extend(args);
        assert_failure(&lac(&all), 2, "usage");
    }
    let run = lac(&[
        "spline",
        "--through",
        through,
        "--alpha",
        "-1",
        "--types",
        "s s s s s",
        "--angles",
        "2:0",
    ]);
    let message = assert_failure(&run, 2, "usage");
    assert!(message.contains("type it t"), "{message}");
}
