//! `lac monotone`: the proven curvature-monotonicity verdict of a (rational) cubic, checked
//! against the curve's own dκ/ds.

use crate::common;

use common::{assert_failure, json, lac, lac_with_input};
use kurbo::Point;
use lac::RationalCubic;
use serde_json::Value;

const S_CURVE: &str = "0,0 1,1 2,-1 3,0";
/// A spiral-like cubic: the legs shorten and turn towards the end, so the curvature grows.
const SPIRAL: &str = "0,0 1.2,0 2,0.4 2.4,1";
const SPIRAL_POINTS: [(f64, f64); 4] = [(0.0, 0.0), (1.2, 0.0), (2.0, 0.4), (2.4, 1.0)];

/// The line `lac monotone args…` prints, and its JSON.
fn monotone_line(args: &[&str]) -> (String, Value) {
    let mut all = vec!["monotone"];
    all.extend_from_slice(args);
    let run = lac(&all);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1);
    let v = json(&run);
    (run.stdout, v)
}

fn monotone(args: &[&str]) -> Value {
    monotone_line(args).1
}

fn cubic(points: [(f64, f64); 4], weights: [f64; 4]) -> RationalCubic {
    RationalCubic::new(points.map(|(x, y)| Point::new(x, y)), weights).unwrap()
}

#[test]
fn an_s_curve_is_not_monotone_and_dkappa_ds_changes_sign_at_t() {
    let (line, v) = monotone_line(&["--points", S_CURVE]);
    common::assert_keys(&line, &v, &["verdict", "proven", "t"]);
    assert_eq!(v["verdict"], "not_monotone");
    assert_eq!(v["proven"], true);
    let t = v["t"].as_f64().unwrap();
    assert!(t > 0.0 && t < 1.0, "{t}");
    let c = cubic([(0.0, 0.0), (1.0, 1.0), (2.0, -1.0), (3.0, 0.0)], [1.0; 4]);
    let h = 1e-6;
    let (a, b) = (c.curvature_derivative(t - h), c.curvature_derivative(t + h));
    assert!(a * b < 0.0, "dκ/ds on either side of t = {t}: {a} {b}");
}

#[test]
fn a_spiral_like_cubic_is_proven_increasing_and_sampling_agrees() {
    let (line, v) = monotone_line(&["--points", SPIRAL]);
    common::assert_keys(&line, &v, &["verdict", "proven"]);
    assert_eq!(v["verdict"], "increasing");
    assert_eq!(v["proven"], true);
    let c = cubic(SPIRAL_POINTS, [1.0; 4]);
    for i in 0..=1000 {
        let d = c.curvature_derivative(i as f64 / 1000.0);
        assert!(d >= 0.0, "dκ/ds = {d} at t = {}", i as f64 / 1000.0);
    }
    // The mirror image turns right: its signed curvature falls.
    let v = monotone(&["--points", "0,0 1.2,0 2,-0.4 2.4,-1"]);
    assert_eq!(v["verdict"], "decreasing");
    assert_eq!(v["proven"], true);
}

#[test]
fn weights_change_the_verdict_and_default_to_one() {
    let plain = monotone(&["--points", SPIRAL]);
    let ones = monotone(&["--points", SPIRAL, "--weights", "1,1,1,1"]);
    assert_eq!(plain, ones);
    // A quarter circle as a degree-elevated conic has constant curvature; as a plain cubic
    // with the same control points it does not.
    let k = 2.0 * std::f64::consts::FRAC_1_SQRT_2 / (1.0 + std::f64::consts::SQRT_2);
    let w = (std::f64::consts::SQRT_2 + 1.0) / 3.0;
    let points = format!("1,0 1,{k} {k},1 0,1");
    let arc = monotone(&["--points", &points, "--weights", &format!("1,{w},{w},1")]);
    assert_eq!(arc["verdict"], "constant");
    assert_eq!(arc["proven"], false, "zero within rounding is not a proof");
    let cubic = monotone(&["--points", &points]);
    assert_eq!(cubic["verdict"], "not_monotone");
}

#[test]
fn bad_input_is_a_one_line_json_error_with_exit_code_2() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["monotone", "--points", SPIRAL, "--weights", "1,0,1,1"],
            "out_of_range",
        ),
        (
            &["monotone", "--points", SPIRAL, "--weights", "1,-2,1,1"],
            "out_of_range",
        ),
        (
            &["monotone", "--points", SPIRAL, "--weights", "1,nan,1,1"],
            "non_finite",
        ),
        (
            &["monotone", "--points", SPIRAL, "--weights", "1,1,1"],
            "invalid_input",
        ),
        (&["monotone", "--points", "0,0 1,1 2,0"], "invalid_input"),
        (&["monotone", "--points", "nan,0 1,1 2,0 3,1"], "non_finite"),
        (
            &["monotone", "--points", "0,0 0,0 1,1 2,0"],
            "coincident_points",
        ),
        (&["monotone"], "usage"),
    ];
    for (args, kind) in cases {
        assert_failure(&lac(args), 2, kind);
    }
}

#[test]
fn lac_monotone_reads_what_lac_quasi_prints_and_judges_every_piece() {
    let quasi = lac(&[
        "quasi",
        "--points",
        "0,0 3,0 4.2,1.9",
        "--alpha",
        "0.5",
        "--tolerance",
        "1e-7",
    ]);
    assert_eq!(quasi.code, 0, "{}", quasi.stderr);
    let q: Value = serde_json::from_str(&quasi.stdout).unwrap();
    let pieces = q["pieces"].as_array().unwrap();
    assert!(pieces.len() >= 2);
    let run = lac_with_input(&["monotone"], quasi.stdout.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1);
    let v = json(&run);
    common::assert_keys(&run.stdout, &v, &["pieces"]);
    let verdicts = v["pieces"].as_array().unwrap();
    assert_eq!(verdicts.len(), pieces.len());
    for (verdict, piece) in verdicts.iter().zip(pieces) {
        // The same verdict as lac quasi's, and as --points/--weights give for the piece.
        assert_eq!(verdict["verdict"], piece["monotone"]);
        assert_eq!(verdict["proven"], piece["proven"]);
        let points: Vec<String> = piece["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| format!("{},{}", p[0], p[1]))
            .collect();
        let weights: Vec<String> = piece["weights"]
            .as_array()
            .unwrap()
            .iter()
            .map(Value::to_string)
            .collect();
        let single = monotone(&[
            "--points",
            &points.join(" "),
            "--weights",
            &weights.join(","),
        ]);
        assert_eq!(&single, verdict);
    }
    // From a file, "-" for standard input, and one piece as a document.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("quasi.json");
    std::fs::write(&path, &quasi.stdout).unwrap();
    assert_eq!(
        lac(&["monotone", path.to_str().unwrap()]).stdout,
        run.stdout
    );
    assert_eq!(
        lac_with_input(&["monotone", "-"], quasi.stdout.as_bytes()).stdout,
        run.stdout
    );
    let piece = r#"{"points":[[0,0],[1,1],[2,-1],[3,0]]}"#;
    let one = lac_with_input(&["monotone"], piece.as_bytes());
    assert_eq!(one.stdout, lac(&["monotone", "--points", S_CURVE]).stdout);
}

#[test]
fn a_monotone_document_that_cannot_be_read_is_a_json_error() {
    assert_failure(&lac_with_input(&["monotone"], b"{"), 2, "invalid_input");
    assert_failure(
        &lac_with_input(&["monotone"], br#"{"pieces":[]}"#),
        2,
        "invalid_input",
    );
    assert_failure(&lac(&["monotone", "/nonexistent/quasi.json"]), 1, "io");
    let message = assert_failure(&lac_with_input(&["monotone"], b"  \n"), 2, "usage");
    assert!(message.contains("lac quasi"), "{message}");
    // A FILE and --points are two inputs.
    assert_failure(
        &lac(&["monotone", "x.json", "--points", SPIRAL]),
        2,
        "usage",
    );
}
