//! `lac segment`: output shapes, negative numbers, exit codes and error lines.

use crate::common;

use common::{assert_failure, json, lac};
use serde_json::Value;

const POINTS: &str = "-1,0 0.2,0.8 1,0";

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-12 * scale
}

fn xy(sample: &Value) -> (f64, f64) {
    (sample["x"].as_f64().unwrap(), sample["y"].as_f64().unwrap())
}

#[test]
fn json_has_the_documented_fields_and_samples_run_from_the_first_to_the_third_point() {
    let run = lac(&[
        "segment",
        "--points",
        "-3,1 -1.5,2.8 2,1.5",
        "--alpha",
        "0.5",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1);
    let v = json(&run);
    for key in [
        "alpha",
        "lambda",
        "arc_length",
        "curvature_start",
        "curvature_end",
    ] {
        assert!(v[key].is_f64(), "{key} in {v}");
    }
    assert_eq!(v["alpha"], 0.5);
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 65, "default sample count");
    for s in samples {
        let mut keys: Vec<&String> = s.as_object().unwrap().keys().collect();
        keys.sort();
        assert_eq!(keys, ["kappa", "s", "theta", "x", "y"]);
    }
    // In the documented order in the text.
    assert!(
        run.stdout.starts_with(r#"{"alpha":0.5,"lambda":"#),
        "{}",
        run.stdout
    );
    assert!(run
        .stdout
        .contains(r#""samples":[{"s":0.0,"x":-3.0,"y":1.0,"theta":"#));
    let scale = 5.0;
    let (first, last) = (xy(&samples[0]), xy(&samples[64]));
    assert!(
        close(first.0, -3.0, scale) && close(first.1, 1.0, scale),
        "{first:?}"
    );
    assert!(
        close(last.0, 2.0, scale) && close(last.1, 1.5, scale),
        "{last:?}"
    );
    let arc = v["arc_length"].as_f64().unwrap();
    assert_eq!(samples[0]["s"], 0.0);
    assert!(close(samples[64]["s"].as_f64().unwrap(), arc, arc));
    // Equally spaced in arc length.
    let step = arc / 64.0;
    for (i, s) in samples.iter().enumerate() {
        assert!(
            close(s["s"].as_f64().unwrap(), i as f64 * step, arc),
            "sample {i}"
        );
    }
    // The curve turns right (clockwise): curvature negative, theta decreasing.
    assert!(v["curvature_start"].as_f64().unwrap() < 0.0);
    assert_eq!(samples[0]["kappa"], v["curvature_start"]);
    let theta0 = samples[0]["theta"].as_f64().unwrap();
    assert!(
        close(theta0, 1.8_f64.atan2(1.5), 1.0),
        "start tangent along P1 - P0"
    );
}

#[test]
fn a_left_turn_has_positive_curvature() {
    let v = json(&lac(&[
        "segment",
        "--points",
        "1,0 0.2,0.8 -1,0",
        "--alpha",
        "0.5",
    ]));
    assert!(v["curvature_start"].as_f64().unwrap() > 0.0);
    assert!(v["curvature_end"].as_f64().unwrap() > 0.0);
}

#[test]
fn samples_sets_the_count_and_must_be_at_least_two() {
    let v = json(&lac(&[
        "segment",
        "--points",
        POINTS,
        "--alpha",
        "2",
        "--samples",
        "2",
    ]));
    assert_eq!(v["samples"].as_array().unwrap().len(), 2);
    assert_failure(
        &lac(&[
            "segment",
            "--points",
            POINTS,
            "--alpha",
            "2",
            "--samples",
            "1",
        ]),
        2,
        "usage",
    );
}

#[test]
fn negative_numbers_are_values_as_typed() {
    for alpha in ["-1", "-0.5", "-.5", "-1e-3", "-2E0"] {
        let run = lac(&[
            "segment",
            "--alpha",
            alpha,
            "--points",
            POINTS,
            "--samples",
            "3",
        ]);
        assert_eq!(run.code, 0, "--alpha {alpha}: {}", run.stderr);
        let expected: f64 = alpha.parse().unwrap();
        assert_eq!(json(&run)["alpha"].as_f64().unwrap(), expected);
    }
    let run = lac(&[
        "segment",
        "--points",
        "-1,-0.5 -0.2,0.3 1,-0.5",
        "--alpha",
        "-1",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(json(&run)["samples"][0]["y"], -0.5);
}

#[test]
fn points_may_be_separated_by_semicolons_and_spaces() {
    let a = lac(&["segment", "--points", "-1,0;0.2,0.8;1,0", "--alpha", "0.5"]);
    let b = lac(&[
        "segment",
        "--points",
        " -1, 0 ;  0.2 ,0.8  1,0 ",
        "--alpha",
        "0.5",
    ]);
    let c = lac(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    assert_eq!(a.code, 0, "{}", a.stderr);
    assert_eq!(a.stdout, c.stdout);
    assert_eq!(b.stdout, c.stdout);
}

#[test]
fn invalid_input_exits_2_with_one_json_line_naming_the_problem() {
    let cases = [
        ("0,0 1,0 2,0", "0.5", "collinear_points"),
        ("0,0 0,0 1,1", "0.5", "coincident_points"),
        ("0,0 1,1 1,1", "0.5", "coincident_points"),
        ("nan,0 1,1 2,0", "0.5", "non_finite"),
        ("0,inf 1,1 2,0", "0.5", "non_finite"),
        ("0,0 1,1 2,0", "nan", "non_finite"),
        ("0,0 1,1", "0.5", "invalid_input"),
        ("0,0 1,1 2,0 3,3", "0.5", "invalid_input"),
        ("0,0 1;1 2,0", "0.5", "invalid_input"),
        ("0,0 1,one 2,0", "0.5", "invalid_input"),
        ("(0,0) (1,1) (2,0)", "0.5", "invalid_input"),
    ];
    for (points, alpha, kind) in cases {
        let run = lac(&["segment", "--points", points, "--alpha", alpha]);
        let message = assert_failure(&run, 2, kind);
        if kind == "non_finite" {
            assert!(message.contains("finite"), "{message}");
        }
    }
}

#[test]
fn not_drawable_exits_3_with_the_librarys_advice() {
    let run = lac(&["segment", "--alpha", "-1", "--points", "-1,0 0.9,0.9 1,0"]);
    let message = assert_failure(&run, 3, "not_drawable");
    assert!(
        message.contains("alpha = -1") && message.contains("isosceles"),
        "{message}"
    );
}

#[test]
fn usage_errors_are_one_json_line_with_exit_code_2() {
    let cases: [&[&str]; 6] = [
        &[],
        &["segment", "--alpha", "1"],
        &["segment", "--points", POINTS],
        &["segment", "--points", POINTS, "--alpha", "one"],
        &[
            "segment",
            "--points",
            POINTS,
            "--alpha",
            "1",
            "--frobnicate",
        ],
        &["segment", "--points", POINTS, "--alpha", "1", "--comb"],
    ];
    for args in cases {
        assert_failure(&lac(args), 2, "usage");
    }
}

#[test]
fn help_and_version_print_normally_and_exit_0() {
    let help = lac(&["--help"]);
    assert_eq!(help.code, 0);
    assert!(help.stdout.contains("segment") && help.stdout.contains("region"));
    let help = lac(&["segment", "--help"]);
    assert_eq!(help.code, 0);
    for arg in [
        "--points",
        "--alpha",
        "--batch",
        "--samples",
        "--format",
        "--comb",
        "--evolute",
    ] {
        assert!(help.stdout.contains(arg), "{arg} in segment --help");
    }
    let version = lac(&["--version"]);
    assert_eq!(version.code, 0);
    assert!(version.stdout.starts_with("lac "));
}

#[test]
fn csv_has_a_header_and_one_row_per_sample() {
    let run = lac(&[
        "segment",
        "--points",
        POINTS,
        "--alpha",
        "2",
        "--format",
        "csv",
        "--samples",
        "7",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines[0], "s,x,y,theta,kappa");
    assert_eq!(lines.len(), 8);
    let first: Vec<f64> = lines[1].split(',').map(|x| x.parse().unwrap()).collect();
    assert_eq!(first[..3], [0.0, -1.0, 0.0]);
}

#[test]
fn output_goes_to_the_file_and_a_failed_run_leaves_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.json");
    let path_str = path.to_str().unwrap();
    let run = lac(&[
        "segment", "--points", POINTS, "--alpha", "0", "-o", path_str,
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.is_empty());
    let written = std::fs::read_to_string(&path).unwrap();
    assert_eq!(
        written,
        lac(&["segment", "--points", POINTS, "--alpha", "0"]).stdout
    );

    let missing = dir.path().join("missing.json");
    let run = lac(&[
        "segment",
        "--points",
        "0,0 1,0 2,0",
        "--alpha",
        "0",
        "-o",
        missing.to_str().unwrap(),
    ]);
    assert_failure(&run, 2, "collinear_points");
    assert!(!missing.exists());

    let unwritable = dir.path().join("no/such/dir/out.json");
    let run = lac(&[
        "segment",
        "--points",
        POINTS,
        "--alpha",
        "0",
        "-o",
        unwritable.to_str().unwrap(),
    ]);
    assert_failure(&run, 1, "io");
}
