//! `lac path`: G1 and G2 paths from a control polygon, their JSON, CSV and SVG, and their
//! errors (the joint named, the nearest G1 path offered).

use crate::common;

use common::{assert_failure, f, json, lac};
use serde_json::Value;

const POLYGON: &str = "0,0 2,0 3.5,1 4,3 3,4.5 1,5";

#[test]
fn g2_path_json_reports_every_joint_continuous() {
    let run = lac(&["path", "--polygon", POLYGON, "--alpha", "0.5", "--g2"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["continuity"], "g2");
    assert_eq!(v["segments"].as_array().unwrap().len(), 4);
    let joints = v["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 3);
    for j in joints {
        let [a, b] = [f(&j["curvature"][0]), f(&j["curvature"][1])];
        assert!((a - b).abs() <= 1e-9 * a.abs().max(b.abs()), "{j}");
        // The joint is where the samples say the curve is, at its arc length.
        assert!(f(&j["gap"]) < 1e-12 && f(&j["tangent_jump"]) < 1e-12);
    }
    // Consecutive segments share their joint (the end of one is the start of the next).
    let segs = v["segments"].as_array().unwrap();
    for w in segs.windows(2) {
        assert_eq!(w[0]["control_points"][2], w[1]["control_points"][0]);
    }
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 65);
    assert!((f(&samples[64]["x"]) - 1.0).abs() < 1e-12);
    assert!((f(&samples[64]["y"]) - 5.0).abs() < 1e-12);
}

#[test]
fn g1_path_takes_fractions_and_alphas_per_segment() {
    let run = lac(&[
        "path",
        "--polygon",
        POLYGON,
        "--alphas",
        "0,0.5,1,1",
        "--fractions",
        "0.3,0.5,0.7",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["continuity"], "g1");
    let fractions: Vec<f64> = v["joints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|j| f(&j["fraction"]))
        .collect();
    assert_eq!(fractions, vec![0.3, 0.5, 0.7]);
    let alphas: Vec<f64> = v["segments"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| f(&s["alpha"]))
        .collect();
    assert_eq!(alphas, vec![0.0, 0.5, 1.0, 1.0]);
}

#[test]
fn closed_path_csv_and_svg() {
    let poly = "0,0 3,-0.5 4.5,2 2,4 -0.5,2.5";
    let run = lac(&[
        "path",
        "--polygon",
        poly,
        "--closed",
        "--alpha",
        "0",
        "--g2",
        "--format",
        "csv",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines[0], "s,x,y,theta,kappa");
    assert_eq!(lines.len(), 66);
    // Closed: the last sample is the first.
    let first: Vec<f64> = lines[1].split(',').map(|t| t.parse().unwrap()).collect();
    let last: Vec<f64> = lines[65].split(',').map(|t| t.parse().unwrap()).collect();
    assert!((first[1] - last[1]).abs() < 1e-12 && (first[2] - last[2]).abs() < 1e-12);
    let run = lac(&[
        "path",
        "--polygon",
        poly,
        "--closed",
        "--alpha",
        "0",
        "--g2",
        "--format",
        "svg",
        "--comb",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.starts_with("<svg") || run.stdout.starts_with("<?xml"));
    assert!(run.stdout.contains("</svg>"));
}

#[test]
fn a_failed_g2_names_the_joint_and_offers_the_nearest_g1_path() {
    let run = lac(&[
        "path",
        "--polygon",
        "0,0 2,0 3,1 4,1",
        "--alpha",
        "0.5",
        "--g2",
    ]);
    assert_failure(&run, 3, "no_g2_path");
    assert!(
        run.stderr.contains("leg P1-P2") && run.stderr.contains("nearest G1 path"),
        "{}",
        run.stderr
    );
    let run = lac(&["path", "--polygon", "0,0 1,0 2,0 3,1", "--alpha", "0.5"]);
    assert_failure(&run, 2, "collinear_points");
    assert!(run.stderr.contains("vertex P1"), "{}", run.stderr);
    let run = lac(&["path", "--polygon", "0,0 1,0", "--alpha", "0.5"]);
    assert_failure(&run, 2, "invalid_input");
    let run = lac(&["path", "--polygon", POLYGON, "--alphas", "0.5,0.5"]);
    assert_failure(&run, 2, "out_of_range");
}

#[test]
fn s_shaped_g2_path_reports_its_straight_piece_and_samples_through_it() {
    let polygon = "0,0 1,0 2,0.5 5,2.5 6,3 7,3";
    let run = lac(&["path", "--polygon", polygon, "--alpha", "-1", "--g2"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["continuity"], "g2");
    let lines = v["straight_pieces"].as_array().unwrap();
    assert_eq!(lines.len(), 1);
    let line = &lines[0];
    assert_eq!(line["leg"], 2);
    let scale = v["segments"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|s| [f(&s["curvature"][0]).abs(), f(&s["curvature"][1]).abs()])
        .fold(0.0, f64::max);
    for k in [f(&line["curvature"][0]), f(&line["curvature"][1])] {
        assert!(k.abs() <= 1e-9 * scale, "{line}");
    }
    // The segments on either side end exactly where the straight piece does.
    let segs = v["segments"].as_array().unwrap();
    assert_eq!(segs[1]["control_points"][2], line["points"][0]);
    assert_eq!(segs[2]["control_points"][0], line["points"][1]);
    // The arc length counts it, and the samples on it have zero curvature.
    let total: f64 = segs.iter().map(|s| f(&s["arc_length"])).sum::<f64>() + f(&line["length"]);
    assert!((f(&v["arc_length"]) - total).abs() < 1e-12);
    let (s0, s1) = (f(&line["s"]), f(&line["s"]) + f(&line["length"]));
    let on_line: Vec<&Value> = v["samples"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| f(&p["s"]) > s0 && f(&p["s"]) < s1)
        .collect();
    assert!(on_line.len() > 10);
    assert!(on_line.iter().all(|p| f(&p["kappa"]) == 0.0));
    // The SVG draws it and names it in the caption.
    let run = lac(&[
        "path",
        "--polygon",
        polygon,
        "--alpha",
        "-1",
        "--g2",
        "--format",
        "svg",
        "--comb",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.contains("straight s = "), "{}", run.stdout);
}
