//! Issue 18, the command line: every bad argument is one line of JSON on standard error with
//! exit code 2, a defect is one line of JSON with exit code 70 (never Rust's panic message),
//! work is limited, and successful output never holds a non-finite number.

use crate::common;

use common::{assert_failure, lac, lac_with_env};
use serde_json::Value;

#[test]
fn a_panic_is_one_json_line_with_exit_code_70() {
    let run = lac_with_env(
        &["segment", "--points", "-1,0 0.2,0.8 1,0", "--alpha", "0.5"],
        b"",
        &[("LAC_DEBUG_PANIC", "main")],
    );
    let message = assert_failure(&run, 70, "internal");
    assert!(message.contains("defect of lac"), "{message}");
    assert!(
        !run.stderr.contains("thread 'main'") && !run.stderr.contains("RUST_BACKTRACE"),
        "no Rust panic message: {}",
        run.stderr
    );
}

#[test]
fn every_bad_argument_of_every_subcommand_is_one_json_line_with_exit_code_2() {
    let seg = ["--points", "-1,0 0.2,0.8 1,0"];
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["frobnicate"], "usage"),
        (vec!["segment", "--alpha", "1"], "usage"),
        (
            [&["segment"][..], &seg, &["--alpha", "x"]].concat(),
            "usage",
        ),
        (
            [&["segment"][..], &seg, &["--alpha", "nan"]].concat(),
            "non_finite",
        ),
        (
            [&["segment"][..], &seg, &["--alpha", "1", "--samples", "-3"]].concat(),
            "usage",
        ),
        (
            [&["segment"][..], &seg, &["--alpha", "1", "--format", "pdf"]].concat(),
            "usage",
        ),
        (
            vec!["segment", "--points", "0,0 1", "--alpha", "1"],
            "invalid_input",
        ),
        (
            vec![
                "compound",
                "--points",
                "0,0 1,0 1,1",
                "--alpha0",
                "1",
                "--alpha1",
                "2",
            ],
            "usage",
        ),
        (
            vec![
                "compound",
                "--points",
                "0,0 1,0 1,1",
                "--alpha",
                "1",
                "--ratio",
                "0.5",
            ],
            "usage",
        ),
        (vec!["quasi", "--points", "0,0 1,0 1,1"], "usage"),
        (
            vec![
                "quasi",
                "--points",
                "0,0 1,0 1,1",
                "--alpha",
                "1",
                "--tolerance",
                "-1",
            ],
            "out_of_range",
        ),
        (
            vec![
                "quasi",
                "--points",
                "0,0 1,0 1,1",
                "--alpha",
                "1",
                "--cubic",
            ],
            "usage",
        ),
        (
            vec![
                "space",
                "--points",
                "0,0,0 1,0,0 1,1,0 1,1,1",
                "--alpha",
                "1",
            ],
            "usage",
        ),
        (
            vec![
                "space",
                "--points",
                "0,0,0 1,0,0 1,1,0 1,1,1",
                "--alpha",
                "1",
                "--beta",
                "0",
                "--type",
                "3",
            ],
            "out_of_range",
        ),
        (vec!["monotone", "--points", "0,0 1,0 1,1"], "invalid_input"),
        (vec!["monotone", "--weights", "1,1,1,1"], "usage"),
        (vec!["lcg", "--format", "pdf"], "usage"),
        (vec!["region"], "usage"),
        (vec!["region", "--alpha", "1", "--size", "-2"], "usage"),
        (vec!["region", "--alpha0", "1", "--alpha1", "2"], "usage"),
    ];
    for (args, kind) in &cases {
        assert_failure(&lac(args), 2, kind);
    }
}

#[test]
fn samples_are_limited_to_a_million_unless_raised() {
    let cases: [&[&str]; 3] = [
        &["segment", "--points", "-1,0 0.2,0.8 1,0", "--alpha", "0.5"],
        &[
            "compound",
            "--points",
            "0,0 2,0 2.5,2 0,1.5",
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
        ],
        &[
            "space",
            "--points",
            "0,0,0 3,0,0 3,3,1.5 0,3,3",
            "--alpha",
            "0.5",
            "--beta",
            "0",
            "--frames",
        ],
    ];
    for base in cases {
        let over = [base, &["--samples", "1000001"]].concat();
        let message = assert_failure(&lac(&over), 2, "limit");
        assert!(
            message.contains("1,000,000") && message.contains("--allow-large"),
            "{message}"
        );
        // Beyond the library's own ceiling even --allow-large says no, before any work.
        let far = [base, &["--samples", "10000001", "--allow-large"]].concat();
        assert_failure(&lac(&far), 2, "limit");
        // A batch is refused before it reads a line.
        let batch = [&[base[0]][..], &["--batch", "-", "--samples", "1000001"]].concat();
        assert_failure(&lac(&batch), 2, "limit");
    }
}

/// Every number in `v`, with the keys where `null` is documented ("log_rho" and "log_lcg"
/// where κ or dκ/ds is 0, "fit" without a line, "tolerance" of the seed's single piece,
/// "standard_form" and "transform" of a planar space result).
fn non_finite_or_undocumented_null(v: &Value, key: &str, found: &mut Vec<String>) {
    match v {
        Value::Null => {
            let documented = [
                "log_rho",
                "log_lcg",
                "fit",
                "tolerance",
                "standard_form",
                "transform",
            ];
            if !documented.contains(&key) {
                found.push(format!("null at {key}"));
            }
        }
        Value::Number(n) if !n.as_f64().is_some_and(f64::is_finite) => {
            found.push(format!("{n} at {key}"))
        }
        Value::Array(items) => items
            .iter()
            .for_each(|item| non_finite_or_undocumented_null(item, key, found)),
        Value::Object(map) => map
            .iter()
            .for_each(|(k, item)| non_finite_or_undocumented_null(item, k, found)),
        _ => {}
    }
}

#[test]
fn successful_output_never_holds_a_non_finite_number_even_at_extreme_scales() {
    let cases: [&[&str]; 8] = [
        &[
            "segment",
            "--points",
            "1e-160,0 1.2e-160,1e-160 3e-160,2e-160",
            "--alpha",
            "0.5",
        ],
        &[
            "segment",
            "--points",
            "-1e160,0 0.2e160,0.8e160 1e160,0",
            "--alpha",
            "2",
        ],
        &[
            "segment",
            "--points",
            "-1,0 0.2,0.8 1,0",
            "--alpha",
            "1e-300",
        ],
        &[
            "compound",
            "--points",
            "1e150,0 3e150,0 4e150,1e150",
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
            "--ratio",
            "0.5",
        ],
        &[
            "compound",
            "--points",
            "0,0 2e-150,0 2.5e-150,2e-150 0,1.5e-150",
            "--alpha0",
            "0.5",
            "--alpha1",
            "1",
        ],
        &[
            "quasi",
            "--points",
            "1e-150,0 3e-150,0 4e-150,1e-150",
            "--alpha",
            "0.5",
            "--tolerance",
            "1e-9",
        ],
        &[
            "space",
            "--points",
            "0,0,0 3e100,0,0 3e100,3e100,1.5e100 0,3e100,3e100",
            "--alpha",
            "0.5",
            "--beta",
            "0",
            "--omega",
            "0.3",
            "--frames",
        ],
        &["segment", "--points", "0,0 1,1 2,0", "--alpha", "0.5"],
    ];
    let mut solved = 0;
    for args in cases {
        let run = lac(args);
        if run.code != 0 {
            // Refused: then as one JSON line with exit code 2 or 3.
            assert!(matches!(run.code, 2 | 3), "{args:?}: {}", run.stderr);
            let v: Value = serde_json::from_str(&run.stderr).expect("one JSON line");
            assert!(v["error"]["kind"].is_string());
            continue;
        }
        solved += 1;
        let v: Value = serde_json::from_str(&run.stdout).unwrap();
        let mut found = Vec::new();
        non_finite_or_undocumented_null(&v, "", &mut found);
        assert!(found.is_empty(), "{args:?}: {found:?}");
        assert!(!run.stdout.contains("NaN") && !run.stdout.contains("inf"));
        // The CSV as well.
        let csv = lac(&[args, &["--format", "csv"]].concat());
        assert_eq!(csv.code, 0, "{}", csv.stderr);
        let lower = csv.stdout.to_lowercase();
        assert!(!lower.contains("nan") && !lower.contains("inf"), "{args:?}");
    }
    assert!(
        solved >= 6,
        "most of these extreme inputs are drawable ({solved})"
    );
}

#[test]
fn numbers_in_messages_are_short() {
    for args in [
        &["segment", "--points", "-1,0 0.9,0.9 1,0", "--alpha", "-1"][..],
        &[
            "segment",
            "--points",
            "-1,0 0.2,0.8 1,0",
            "--alpha",
            "1e300",
        ],
        &[
            "segment",
            "--points",
            "-1,0 0.2,0.8 1,0",
            "--alpha",
            "0.5",
            "--samples",
            "123456789",
        ],
        &["region", "--alpha", "1e300", "--size", "4096"],
    ] {
        let run = lac(args);
        let v: Value = serde_json::from_str(&run.stderr).expect("one JSON line");
        let message = v["error"]["message"].as_str().unwrap();
        let longest_number = message
            .split(|c: char| !(c.is_ascii_digit() || c == '.'))
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest_number <= 20, "{args:?}: {message}");
    }
}

/// Issue 35: points within a binade of the largest double are drawn, or refused with a typed
/// error that says what to change (exit 2), never a numerical failure (exit 70).
#[test]
fn curves_near_the_largest_double_are_drawn_or_refused_with_a_typed_error() {
    let corner = ["--points", "0,0 1e308,0 1e308,1e308"];
    for alpha in ["-1", "0", "0.5", "1", "2"] {
        let run = lac(&[
            &["segment"][..],
            &corner,
            &["--alpha", alpha, "--samples", "5"],
        ]
        .concat());
        assert_eq!(run.code, 0, "segment alpha {alpha}: {}", run.stderr);
        let length = common::json(&run)["arc_length"].as_f64().unwrap();
        assert!((length / (std::f64::consts::FRAC_PI_2 * 1e308) - 1.0).abs() < 1e-12);
        // Its Bézier pieces cannot be evaluated that near the largest double: refused.
        let quasi = |p: &str| {
            lac(&[
                "quasi",
                "--points",
                &format!("0,0 {p},0 {p},{p}"),
                "--alpha",
                alpha,
                "--tolerance",
                "1e-6",
            ])
        };
        let run = quasi("1e306");
        assert_eq!(run.code, 0, "quasi alpha {alpha}: {}", run.stderr);
        assert_failure(&quasi("1e308"), 2, "unrepresentable");
    }
    // A tolerance finer than double precision can certify is refused, and says so briefly.
    let run = lac(&[
        &["export"][..],
        &corner,
        &["--alpha", "0.5", "--format", "json", "-o", "-"],
    ]
    .concat());
    let message = assert_failure(&run, 3, "tolerance_not_met");
    assert!(
        message.len() < 400 && message.contains("1.5708e308"),
        "{message}"
    );
    // Its B-spline is written up to control points of 2.8e306, beyond them refused.
    let export = |points: &str| {
        lac(&[
            "export",
            "--points",
            points,
            "--alpha",
            "0.5",
            "--relative-tolerance",
            "1e-6",
            "--format",
            "json",
            "-o",
            "-",
        ])
    };
    let run = export("0,0 1e306,0 1e306,1e306");
    assert_eq!(run.code, 0, "export: {}", run.stderr);
    assert_failure(&export("0,0 1e308,0 1e308,1e308"), 2, "unrepresentable");
    // A path of length 1.2e308 is drawn; one of 2.4e308 is beyond double range.
    let path = |p: &str| {
        lac(&[
            "path",
            "--polygon",
            &format!("0,0 {p},0 {p},{p} 0,{p}"),
            "--alpha",
            "0.5",
            "--g2",
            "--samples",
            "5",
        ])
    };
    let run = path("5e307");
    assert_eq!(run.code, 0, "path 5e307: {}", run.stderr);
    assert_failure(&path("1e308"), 2, "unrepresentable");
    let run = lac(&[
        "spline",
        "--through",
        "0,0 1e308,0 1e308,1e308 0,1e308",
        "--alpha",
        "0.5",
    ]);
    let message = assert_failure(&run, 2, "unrepresentable");
    assert!(!message.contains("must be a finite number"), "{message}");
}
