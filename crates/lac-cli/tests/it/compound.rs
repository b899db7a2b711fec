//! `lac compound`: the three-point (seed 004) and four-point (seed 002) forms, their JSON,
//! CSV and SVG, and their errors.

use crate::common;

use lac::Curve;
use std::f64::consts::{PI, TAU};

use common::{assert_failure, f, json, lac};
use kurbo::Point;
use lac::CompoundCurve;
use serde_json::Value;

const THREE: &str = "0,0 2,0 2.6,1.2";
/// Turns 191°: more than a three-point curve can.
const FOUR: &str = "0,0 2,0 2.5,2 0,1.5";

fn compound(points: &str, alpha0: &str, alpha1: &str, extra: &[&str]) -> common::Run {
    let mut args = vec![
        "compound", "--points", points, "--alpha0", alpha0, "--alpha1", alpha1,
    ];
    args.extend_from_slice(extra);
    lac(&args)
}

fn solved(points: &str, alpha0: &str, alpha1: &str, extra: &[&str]) -> Value {
    let run = compound(points, alpha0, alpha1, extra);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1);
    json(&run)
}

/// The samples as (s, x, y, theta, kappa).
fn samples(v: &Value) -> Vec<[f64; 5]> {
    v["samples"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| ["s", "x", "y", "theta", "kappa"].map(|k| f(&s[k])))
        .collect()
}

/// The index of the last sample at or before the joint.
fn before_joint(rows: &[[f64; 5]], joint_s: f64) -> usize {
    rows.iter().rposition(|r| r[0] <= joint_s).unwrap()
}

fn assert_close(a: [f64; 2], b: [f64; 2], scale: f64, what: &str) {
    let d = (a[0] - b[0]).hypot(a[1] - b[1]);
    assert!(d <= 1e-12 * scale, "{what}: {a:?} vs {b:?} ({d:e})");
}

#[test]
fn json_has_the_documented_fields_in_order_for_both_forms() {
    let run = compound(THREE, "-1", "2", &["--ratio", "0.5"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let keys = [
        "alpha0",
        "alpha1",
        "ratio",
        "lambda",
        "arc_length",
        "joint_s",
        "curvature_start",
        "curvature_joint",
        "curvature_end",
        "turning_angle",
        "joint",
        "lcg",
        "points",
        "samples",
    ];
    let at: Vec<usize> = keys
        .iter()
        .map(|k| {
            run.stdout
                .find(&format!("\"{k}\":"))
                .unwrap_or_else(|| panic!("{k}"))
        })
        .collect();
    assert!(
        at.windows(2).all(|w| w[0] < w[1]),
        "keys in the documented order"
    );
    let v = json(&run);
    assert_eq!(v.as_object().unwrap().len(), keys.len());
    assert_eq!(
        (f(&v["alpha0"]), f(&v["alpha1"]), f(&v["ratio"])),
        (-1.0, 2.0, 0.5)
    );
    assert_eq!(v["joint"].as_array().unwrap().len(), 2);
    assert_eq!(v["points"].as_array().unwrap().len(), 3);
    let lcg = v["lcg"].as_array().unwrap();
    assert_eq!(lcg.len(), 2);
    assert_eq!((f(&lcg[0]["alpha"]), f(&lcg[1]["alpha"])), (-1.0, 2.0));
    // The two lines of the curvature graph meet at the joint's log ρ = −ln|κ_joint|.
    let joint_log_rho = -f(&v["curvature_joint"]).abs().ln();
    assert!((f(&lcg[0]["log_rho"][1]) - joint_log_rho).abs() < 1e-12);
    assert!((f(&lcg[1]["log_rho"][0]) - joint_log_rho).abs() < 1e-12);
    let rows = samples(&v);
    assert_eq!(rows.len(), 65, "default sample count");

    let v = solved(FOUR, "0.5", "1", &[]);
    assert!(v.get("ratio").is_none(), "no ratio in the four-point form");
    assert_eq!(v["points"].as_array().unwrap().len(), 4);
    assert!(f(&v["turning_angle"]) > PI, "{}", v["turning_angle"]);
}

#[test]
fn samples_run_from_the_first_to_the_last_point_equally_spaced_past_the_joint() {
    for (points, last, extra) in [
        (THREE, [2.6, 1.2], &["--ratio", "0.3"][..]),
        (FOUR, [0.0, 1.5], &[][..]),
    ] {
        for (a0, a1) in [("-1", "2"), ("2", "-1"), ("0.5", "0.5")] {
            let v = solved(points, a0, a1, &[extra, &["--samples", "101"]].concat());
            let rows = samples(&v);
            assert_eq!(rows.len(), 101);
            let (arc, joint_s) = (f(&v["arc_length"]), f(&v["joint_s"]));
            assert!(
                0.0 < joint_s && joint_s < arc,
                "{points} {a0} {a1}: {joint_s} {arc}"
            );
            assert_eq!(rows[0][0], 0.0);
            assert_close([rows[0][1], rows[0][2]], [0.0, 0.0], 3.0, "first sample");
            assert_close([rows[100][1], rows[100][2]], last, 3.0, "last sample");
            assert!((rows[100][0] - arc).abs() <= 1e-12 * arc);
            for (i, r) in rows.iter().enumerate() {
                let want = arc * i as f64 / 100.0;
                assert!((r[0] - want).abs() <= 1e-12 * arc, "sample {i}: s {}", r[0]);
            }
            assert_eq!(rows[0][4], f(&v["curvature_start"]));
            assert_eq!(rows[100][4], f(&v["curvature_end"]));
        }
    }
}

#[test]
fn curvature_and_its_slope_are_continuous_at_the_joint() {
    for (a0, a1) in [("-1", "2"), ("2", "-1")] {
        let v = solved(THREE, a0, a1, &["--ratio", "0.5", "--samples", "2001"]);
        let rows = samples(&v);
        let (joint_s, kappa_joint) = (f(&v["joint_s"]), f(&v["curvature_joint"]));
        let a = before_joint(&rows, joint_s);
        // Extrapolate κ linearly to the joint from two samples on each side: the error is
        // O(κ'' h²) ≈ 1e-7 here, while a break in κ or a misplaced joint_s shows at O(κ' h).
        let extrapolate = |i: usize, j: usize| {
            let slope = (rows[j][4] - rows[i][4]) / (rows[j][0] - rows[i][0]);
            (rows[i][4] + slope * (joint_s - rows[i][0]), slope)
        };
        let (left, left_slope) = extrapolate(a, a - 1);
        let (right, right_slope) = extrapolate(a + 1, a + 2);
        for (side, kappa) in [("before", left), ("after", right)] {
            assert!(
                (kappa - kappa_joint).abs() < 1e-5 * kappa_joint.abs(),
                "α0 {a0} α1 {a1}: κ from {side} the joint {kappa} vs curvature_joint {kappa_joint}"
            );
        }
        // G3: dκ/ds agrees too (to the finite differences' O(h) accuracy).
        assert!(
            (left_slope - right_slope).abs() < 1e-2 * left_slope.abs(),
            "{left_slope} vs {right_slope}"
        );
    }
}

#[test]
fn the_four_point_form_has_the_middle_leg_as_the_joint_tangent() {
    let v = solved(FOUR, "-1", "2", &["--samples", "4001"]);
    let rows = samples(&v);
    let joint_s = f(&v["joint_s"]);
    let a = before_joint(&rows, joint_s);
    // θ at the joint from the nearest sample before it: dθ/ds = κ, error O(κ' h²) ≈ 1e-7.
    let theta = rows[a][3] + rows[a][4] * (joint_s - rows[a][0]);
    let leg = (2.0_f64 - 0.0).atan2(2.5 - 2.0); // P2 − P1 = (0.5, 2)
    let off = (theta - leg + PI).rem_euclid(TAU) - PI;
    assert!(off.abs() < 1e-6, "θ at the joint {theta}, P2 − P1 at {leg}");
    // The first tangent is along P1 − P0 and the last along P3 − P2, 191° further on.
    assert_eq!(rows[0][3], 0.0);
    let last = rows.last().unwrap()[3];
    assert!((last - (-0.5_f64).atan2(-2.5).rem_euclid(TAU)).abs() < 1e-12);

    // The library agrees exactly at the reported joint_s.
    let p = [(0.0, 0.0), (2.0, 0.0), (2.5, 2.0), (0.0, 1.5)].map(|(x, y)| Point::new(x, y));
    let curve = CompoundCurve::from_four_points(p, -1.0, 2.0).unwrap();
    assert_eq!(curve.joint_s(), joint_s);
    let theta = curve.theta_at_s(joint_s).unwrap();
    assert!(
        ((theta - leg + PI).rem_euclid(TAU) - PI).abs() < 1e-12,
        "{theta}"
    );
}

#[test]
fn csv_has_a_header_and_the_json_samples() {
    let v = solved(THREE, "-1", "2", &["--ratio", "0.5", "--samples", "9"]);
    let run = compound(
        THREE,
        "-1",
        "2",
        &["--ratio", "0.5", "--samples", "9", "--format", "csv"],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines[0], "s,x,y,theta,kappa");
    assert_eq!(lines.len(), 10);
    for (line, row) in lines[1..].iter().zip(samples(&v)) {
        let csv: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        assert_eq!(csv, row);
    }
}

#[test]
fn the_svg_marks_the_joint_and_draws_three_or_four_control_points() {
    for (points, extra, markers) in [(THREE, &["--ratio", "0.5"][..], 3), (FOUR, &[][..], 4)] {
        let args = [extra, &["--format", "svg", "--comb", "--evolute"]].concat();
        let run = compound(points, "-1", "2", &args);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let doc = &run.stdout;
        assert!(doc.contains("xmlns=\"http://www.w3.org/2000/svg\""));
        assert_eq!(
            doc.matches("<circle class=\"joint\"").count(),
            1,
            "one joint dot"
        );
        assert_eq!(doc.matches(">P").count(), markers, "control point labels");
        assert!(doc.contains(&format!(">P{}<", markers - 1)));
        for text in [
            "α0 = -1",
            "α1 = 2",
            "Λ = ",
            "joint s = ",
            "curvature comb",
            "evolute",
        ] {
            assert!(doc.contains(text), "caption has {text:?}");
        }
        assert!(doc.contains("<title>Compound-rhythm"));
        assert!(!doc.contains("NaN") && !doc.contains("inf"));
    }
}

#[test]
fn the_number_of_points_selects_the_form_and_the_ratio_must_match_it() {
    let message = assert_failure(&compound(THREE, "-1", "2", &[]), 2, "usage");
    assert!(message.contains("--ratio"), "{message}");
    let message = assert_failure(&compound(FOUR, "-1", "2", &["--ratio", "0.5"]), 2, "usage");
    assert!(message.contains("four control points"), "{message}");
    let message = assert_failure(
        &compound("0,0 1,1", "-1", "2", &["--ratio", "0.5"]),
        2,
        "invalid_input",
    );
    assert!(message.contains("3 or 4 points"), "{message}");
    assert_failure(
        &compound("0,0 1,0 1,1 0,1 0,2", "-1", "2", &[]),
        2,
        "invalid_input",
    );
    assert_failure(
        &lac(&[
            "compound", "--points", THREE, "--alpha0", "1", "--ratio", "0.5",
        ]),
        2,
        "usage",
    );
    assert_failure(
        &compound(THREE, "-1", "2", &["--ratio", "0.5", "--comb"]),
        2,
        "usage",
    );
}

#[test]
fn invalid_input_exits_2_and_no_curve_exits_3() {
    for ratio in ["0", "1", "1.5", "-0.5"] {
        let message = assert_failure(
            &compound(THREE, "-1", "2", &["--ratio", ratio]),
            2,
            "out_of_range",
        );
        assert!(message.contains("ratio"), "{message}");
    }
    assert_failure(
        &compound(THREE, "-1", "2", &["--ratio", "nan"]),
        2,
        "non_finite",
    );
    assert_failure(
        &compound(THREE, "-1", "inf", &["--ratio", "0.5"]),
        2,
        "non_finite",
    );
    // Turns left at P1 and right at P2.
    let message = assert_failure(
        &compound("0,0 2,0 2.5,2 4,2.2", "0.5", "1", &[]),
        2,
        "inflected_polygon",
    );
    assert!(
        message.contains("left") && message.contains("right"),
        "{message}"
    );
    assert_failure(
        &compound("0,0 1,0 2,0", "-1", "2", &["--ratio", "0.5"]),
        2,
        "collinear_points",
    );
    assert_failure(
        &compound("0,0 1,0 1,0 0,1", "-1", "2", &[]),
        2,
        "coincident_points",
    );
    // A clothoid-like first piece cannot make the steep angle at the long leg.
    assert_failure(
        &compound("-1,0 0.9,0.9 1,0", "-1", "2", &["--ratio", "0.5"]),
        3,
        "not_drawable",
    );
    // Four points whose chord leaves the first point outside the tangents.
    assert_failure(
        &compound("0,0 2,0 2.5,2 -1,-1", "0.5", "1", &[]),
        3,
        "not_drawable",
    );
}

#[test]
fn help_names_the_command_and_its_flags() {
    let help = lac(&["--help"]);
    assert_eq!(help.code, 0);
    assert!(help.stdout.contains("compound"));
    let help = lac(&["compound", "--help"]);
    assert_eq!(help.code, 0);
    for arg in [
        "--points",
        "--alpha0",
        "--alpha1",
        "--ratio",
        "--batch",
        "--samples",
        "--format",
        "--comb",
        "--evolute",
    ] {
        assert!(help.stdout.contains(arg), "{arg} in compound --help");
    }
}
