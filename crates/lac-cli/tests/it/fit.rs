//! `lac fit`: paths fitted to points read in every documented form, their JSON, CSV and SVG,
//! a fit's result exported, `--batch`, and one-line errors for bad input.

use crate::common;

use common::{assert_failure, assert_keys, f, json, lac, lac_with_input};
use serde_json::Value;

/// The samples (x, y) of a `lac` run that prints them.
fn sampled(args: &[&str]) -> Vec<[f64; 2]> {
    let run = lac(args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    json(&run)["samples"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| [f(&s["x"]), f(&s["y"])])
        .collect()
}

/// 200 points on a segment of α = 0.5.
fn segment_points() -> Vec<[f64; 2]> {
    sampled(&[
        "segment",
        "--points",
        "0,0 3,0 4.2,1.9",
        "--alpha",
        "0.5",
        "--samples",
        "200",
    ])
}

/// 300 points on a G2 path of four segments of α = 0.5.
fn path_points() -> Vec<[f64; 2]> {
    sampled(&[
        "path",
        "--polygon",
        "0,0 2,0 3.5,1 4,3 3,4.5 1,5",
        "--alpha",
        "0.5",
        "--g2",
        "--samples",
        "300",
    ])
}

/// Points one a line, "x y", exactly as printed.
fn lines(points: &[[f64; 2]]) -> String {
    points
        .iter()
        .map(|[x, y]| format!("{x:?} {y:?}\n"))
        .collect()
}

fn fit(input: &str, args: &[&str]) -> common::Run {
    let mut all = vec!["fit"];
    all.extend_from_slice(args);
    lac_with_input(&all, input.as_bytes())
}

#[test]
fn every_point_form_gives_the_same_fit_and_a_segment_is_found_again() {
    let points = segment_points();
    let plain = lines(&points);
    let comma: String = points
        .iter()
        .map(|[x, y]| format!("{x:?},{y:?}\n"))
        .collect();
    let tab: String = points
        .iter()
        .map(|[x, y]| format!("{x:?}\t{y:?}\t7 # a comment\n"))
        .collect();
    let json_array = serde_json::to_string(&points).unwrap();
    let first = fit(&format!("x,y\n{plain}"), &[]);
    assert_eq!(first.code, 0, "{}", first.stderr);
    for text in [plain.clone(), comma, tab, json_array] {
        let run = fit(&text, &[]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        assert_eq!(run.stdout, first.stdout);
    }
    // From a file too.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("points.txt");
    std::fs::write(&file, &plain).unwrap();
    let run = lac(&["fit", file.to_str().unwrap()]);
    assert_eq!(run.stdout, first.stdout);

    let v = json(&first);
    assert_keys(
        &first.stdout,
        &v,
        &[
            "continuity",
            "closed",
            "arc_length",
            "max_curvature_jump",
            "point_count",
            "tolerance",
            "fitted_segments",
            "rms",
            "max_distance",
            "worst_point",
            "farthest",
            "pieces",
            "segments",
            "joints",
            "samples",
        ],
    );
    assert_eq!(v["point_count"], 200);
    assert_eq!(v["fitted_segments"], 1);
    assert!(v["tolerance"].is_null());
    assert!(
        (f(&v["pieces"][0]["alpha"]) - 0.5).abs() < 1e-5,
        "{}",
        v["pieces"]
    );
    assert!(f(&v["max_distance"]) < 1e-8, "{}", v["max_distance"]);
    assert_eq!(v["farthest"][0]["index"], v["worst_point"]);
    assert_eq!(v["samples"].as_array().unwrap().len(), 65);
}

#[test]
fn a_tolerance_gives_a_path_within_it_with_continuous_joints() {
    let points = path_points();
    let run = fit(&lines(&points), &["--tolerance", "1e-4", "--samples", "9"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert!(f(&v["max_distance"]) <= 1e-4);
    assert_eq!(f(&v["tolerance"]), 1e-4);
    let pieces = v["pieces"].as_array().unwrap();
    assert!(pieces.len() >= 2, "{}", v["pieces"]);
    assert_eq!(
        v["fitted_segments"].as_u64().unwrap() as usize,
        pieces.len()
    );
    let joints = v["joints"].as_array().unwrap();
    assert_eq!(joints.len(), pieces.len() - 1);
    for j in joints {
        assert!(f(&j["curvature_jump"]) <= 1e-9, "{j}");
        assert!(f(&j["gap"]) <= 1e-9 && f(&j["tangent_jump"]) <= 1e-9, "{j}");
    }
    // Every segment row belongs to a piece, and the pieces name their rows in order.
    let segments = v["segments"].as_array().unwrap();
    for (i, p) in pieces.iter().enumerate() {
        let [a, b] = [
            p["segments"][0].as_u64().unwrap(),
            p["segments"][1].as_u64().unwrap(),
        ];
        for k in a..=b {
            assert_eq!(segments[k as usize]["piece"], i);
        }
    }
    // Fewer segments than asked is refused as a tolerance not met, naming the stretch.
    let run = fit(
        &lines(&points),
        &["--tolerance", "1e-9", "--max-segments", "1"],
    );
    let message = assert_failure(&run, 3, "fit_tolerance_not_met");
    assert!(
        message.contains("1e-9") || message.contains("1.0e-9"),
        "{message}"
    );
}

#[test]
fn fixed_alpha_g1_closed_pinned_and_robust_fits_answer_as_asked() {
    let points = segment_points();
    let text = lines(&points);
    let run = fit(&text, &["--alpha", "1"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(f(&json(&run)["pieces"][0]["alpha"]), 1.0);
    let run = fit(&text, &["--pin-ends", "--alpha-range", "-1,2"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    let first = &v["samples"][0];
    assert!((f(&first["x"]) - points[0][0]).abs() < 1e-9);
    assert!((f(&first["y"]) - points[0][1]).abs() < 1e-9);
    let run = fit(&text, &["--g1", "--max-segments", "2"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(json(&run)["continuity"], "g1");

    // A closed set: points round a closed G2 path.
    let closed = sampled(&[
        "path",
        "--polygon",
        "0,0 3,0 4,2 2,4 -1,2",
        "--alpha",
        "0.5",
        "--g2",
        "--closed",
        "--samples",
        "241",
    ]);
    let round = &closed[..closed.len() - 1];
    let run = fit(&lines(round), &["--closed", "--tolerance", "1e-3"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["closed"], true);
    assert_eq!(
        v["joints"].as_array().unwrap().len(),
        v["pieces"].as_array().unwrap().len()
    );

    // An outlier: Huber's loss keeps the fit on the other points, and names it farthest.
    let mut moved = points.clone();
    moved[120][1] += 0.3;
    let run = fit(&lines(&moved), &["--huber", "1e-3"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["worst_point"], 120);
    assert!(f(&v["farthest"][1]["distance"]) < 1e-3, "{}", v["farthest"]);

    // A weight column: the outlier weighted zero does not pull the fit.
    let weighted: String = moved
        .iter()
        .enumerate()
        .map(|(k, [x, y])| format!("{x:?} {y:?} {}\n", if k == 120 { 0 } else { 1 }))
        .collect();
    let run = fit(&weighted, &["--weighted"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["worst_point"], 120);
    assert!(f(&v["farthest"][1]["distance"]) < 1e-6, "{}", v["farthest"]);
}

#[test]
fn csv_is_the_samples_and_svg_draws_points_path_comb_joints_and_curvature() {
    let text = lines(&path_points());
    let run = fit(&text, &["--format", "csv", "--samples", "7"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let rows: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(rows[0], "s,x,y,theta,kappa");
    assert_eq!(rows.len(), 8);
    let run = fit(&text, &["--format", "svg", "--tolerance", "1e-4"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = &run.stdout;
    assert!(svg.starts_with("<?xml") && svg.trim_end().ends_with("</svg>"));
    assert!(
        svg.contains("<title>Log-aesthetic path (G2) fitted to 300 points: "),
        "{}",
        &svg[..400]
    );
    let v = json(&fit(&text, &["--tolerance", "1e-4"]));
    let joints = v["joints"].as_array().unwrap().len();
    // One dot per joint on the path, one dashed line per joint on the plot.
    assert_eq!(svg.matches(r#"<circle class="joint""#).count(), joints);
    assert_eq!(svg.matches(r#"<path class="joint""#).count(), joints);
    assert_eq!(svg.matches(r#"class="worst""#).count(), 1);
    for class in [
        "class=\"fit\"",
        "class=\"comb\"",
        "class=\"points\"",
        "class=\"measured\"",
        "class=\"fit-curvature\"",
    ] {
        assert!(svg.contains(class), "{class}");
    }
    // The points are all drawn: 300 in the points' group.
    let group = svg.split(r#"<g class="points""#).nth(1).unwrap();
    let group = &group[..group.find("</g>").unwrap()];
    assert_eq!(group.matches("<circle").count(), 300);
}

#[test]
fn a_fits_result_exports_like_a_paths_with_its_joints_as_knots() {
    let run = fit(&lines(&path_points()), &["--tolerance", "1e-4"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let report: Value = json(&run);
    let exported = lac_with_input(
        &["export", "--format", "json", "--tolerance", "1e-7"],
        run.stdout.as_bytes(),
    );
    assert_eq!(exported.code, 0, "{}", exported.stderr);
    let doc: Value = serde_json::from_str(&exported.stdout).unwrap();
    assert_eq!(doc["kind"], "fit");
    assert_eq!(doc["continuity"], "G2");
    assert!(f(&doc["max_deviation"]) <= 1e-7);
    let knots: Vec<f64> = doc["curves"][0]["knots"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    for joint in report["joints"].as_array().unwrap() {
        let s = f(&joint["s"]);
        let near = knots
            .iter()
            .fold(f64::INFINITY, |m, k| m.min((k - s).abs()));
        assert!(near < 1e-6, "joint at s = {s}: nearest knot {near} away");
    }
}

#[test]
fn batch_lines_answer_as_the_single_command_and_bad_lines_in_place() {
    let points = segment_points();
    let single = fit(&lines(&points), &["--samples", "5", "--tolerance", "1e-6"]);
    assert_eq!(single.code, 0, "{}", single.stderr);
    let good = serde_json::json!({"points": points, "tolerance": 1e-6}).to_string();
    let input = format!("{good}\n{{\"points\":[[0,0],[1,1]]}}\n{good}\n");
    let run = lac_with_input(&["fit", "--batch", "-", "--samples", "5"], input.as_bytes());
    assert_eq!(run.code, 2, "{}", run.stderr);
    let out: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(out.len(), 3);
    assert_eq!(format!("{}\n", out[0]), single.stdout);
    assert_eq!(out[2], out[0]);
    let bad: Value = serde_json::from_str(out[1]).unwrap();
    assert_eq!(bad["error"]["kind"], "too_few_points");
    assert!(bad["error"]["message"]
        .as_str()
        .unwrap()
        .starts_with("line 2: "));
}

#[test]
fn bad_input_is_one_line_of_json_with_the_exit_code_of_its_class() {
    let message = assert_failure(&fit("0 0\n1 1\n2 x\n", &[]), 2, "invalid_input");
    assert!(message.starts_with("line 3: y \"x\""), "{message}");
    let message = assert_failure(&fit("0 0\n1 1\nnan 2\n", &[]), 2, "invalid_input");
    assert!(message.starts_with("line 3: x \"nan\""), "{message}");
    assert_failure(&fit("[[0,0],[1,1],[2]]", &[]), 2, "invalid_input");
    assert_failure(&fit("0 0\n1 1\n", &[]), 2, "too_few_points");
    assert_failure(&fit("0 0\n1 1\n1 1\n1 1\n", &[]), 2, "too_few_points");
    assert_failure(&fit("", &[]), 2, "too_few_points");
    assert_failure(&fit("0 0\n1 1\n2 2\n3 3\n", &[]), 2, "collinear_points");
    let text = lines(&segment_points());
    assert_failure(&fit(&text, &["--max-segments", "65"]), 2, "out_of_range");
    assert_failure(&fit(&text, &["--tolerance", "-1"]), 2, "out_of_range");
    assert_failure(&fit(&text, &["--alpha-range", "1"]), 2, "invalid_input");
    assert_failure(
        &fit(&text, &["--alpha", "1", "--alpha-range", "0,2"]),
        2,
        "usage",
    );
    assert_failure(&fit(&text, &["--closed", "--pin-ends"]), 2, "usage");
    assert_failure(&fit(&text, &["--weighted"]), 2, "invalid_input");
    assert_failure(
        &fit(&text, &["--batch", "-", "--format", "svg"]),
        2,
        "usage",
    );
}
