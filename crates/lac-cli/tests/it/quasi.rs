//! `lac quasi`: rational and plain cubic Bézier replacements of segments and compound
//! curves, as JSON and SVG, and their errors.

use crate::common;

use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};

use common::{assert_failure, f, json, lac};
use serde_json::Value;

/// An isosceles control triangle: the segment is a quarter circle of radius √2.
const ISOSCELES: &str = "0,0 1,1 2,0";
/// A clothoid-friendly right-angled triangle turning by π/2.
const CORNER: &str = "0,0 1,0 1,0.8";

/// The line `lac quasi args…` prints.
fn quasi_line(args: &[&str]) -> String {
    let mut all = vec!["quasi"];
    all.extend_from_slice(args);
    let run = lac(&all);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1, "one line");
    assert!(run.stderr.is_empty(), "{}", run.stderr);
    run.stdout
}

fn quasi(args: &[&str]) -> Value {
    serde_json::from_str(&quasi_line(args)).expect("JSON")
}

fn pair(v: &Value) -> [f64; 2] {
    [f(&v[0]), f(&v[1])]
}

fn pieces(v: &Value) -> &Vec<Value> {
    v["pieces"].as_array().expect("pieces")
}

#[test]
fn an_isosceles_triangle_gives_one_exact_circular_piece() {
    let line = quasi_line(&["--points", ISOSCELES, "--alpha", "0.5"]);
    let v: Value = serde_json::from_str(&line).unwrap();
    common::assert_keys(
        &line,
        &v,
        &["pieces", "rms", "max", "arc_length", "tolerance", "kind"],
    );
    assert_eq!(v["tolerance"], Value::Null);
    assert_eq!(v["kind"], "rational");
    assert!((f(&v["arc_length"]) - SQRT_2 * FRAC_PI_2).abs() < 1e-14);
    assert!(f(&v["rms"]) < 1e-14 && f(&v["max"]) < 1e-14, "{v}");
    let [piece] = &pieces(&v)[..] else {
        panic!("one piece: {v}")
    };
    common::assert_keys(
        &line,
        piece,
        &[
            "points",
            "weights",
            "monotone",
            "proven",
            "turning",
            "max_deviation",
        ],
    );
    assert_eq!(piece["monotone"], "constant");
    // A circle's dκ/ds is zero: within rounding, so not provable.
    assert_eq!(piece["proven"], false);
    let points = piece["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    assert_eq!(pair(&points[0]), [0.0, 0.0]);
    let end = pair(&points[3]);
    assert!(
        (end[0] - 2.0).abs() < 1e-15 && end[1].abs() < 1e-15,
        "{end:?}"
    );
    // The degree-elevated conic: inner weights (2 cos(θ/2) + 1)/3 relative to the ends.
    let w: Vec<f64> = piece["weights"].as_array().unwrap().iter().map(f).collect();
    let inner = (2.0 * (PI / 4.0).cos() + 1.0) / 3.0;
    assert!((w[1] / w[0] - inner).abs() < 1e-14, "{w:?}");
    assert!((w[3] / w[0] - 1.0).abs() < 1e-14, "{w:?}");
    let turning = pair(&piece["turning"]);
    assert_eq!(turning[0], 0.0);
    assert!((turning[1] - FRAC_PI_2).abs() < 1e-15);
}

#[test]
fn a_tolerance_of_1e_9_is_met_by_pieces_proven_monotone_that_join_end_to_end() {
    let v = quasi(&["--points", CORNER, "--alpha", "-1", "--tolerance", "1e-9"]);
    assert_eq!(f(&v["tolerance"]), 1e-9);
    assert!(f(&v["max"]) <= 1e-9, "{}", v["max"]);
    assert!(f(&v["rms"]) <= f(&v["max"]));
    let length = f(&v["arc_length"]);
    let list = pieces(&v);
    assert!(list.len() > 1, "a clothoid needs several pieces at 1e-9");
    for p in list {
        // The clothoid's curvature grows from the first point: every piece's too, proven.
        assert_eq!(p["monotone"], "increasing", "{p}");
        assert_eq!(p["proven"], true, "{p}");
        assert!(f(&p["max_deviation"]) <= 1e-9 * length, "{p}");
        assert!(p["weights"].as_array().unwrap().iter().all(|w| f(w) > 0.0));
    }
    for pair_of in list.windows(2) {
        let (a, b) = (&pair_of[0], &pair_of[1]);
        let (end, start) = (pair(&a["points"][3]), pair(&b["points"][0]));
        assert!(
            (end[0] - start[0]).hypot(end[1] - start[1]) < 1e-14,
            "joint"
        );
        assert_eq!(a["turning"][1], b["turning"][0], "turning continues");
    }
    assert_eq!(pair(&list[0]["points"][0]), [0.0, 0.0]);
    let last = pair(&list[list.len() - 1]["points"][3]);
    assert!((last[0] - 1.0).hypot(last[1] - 0.8) < 1e-14, "{last:?}");
    let total = f(&list[list.len() - 1]["turning"][1]);
    assert!((total - FRAC_PI_2).abs() < 1e-14, "{total}");
}

#[test]
fn compound_curves_from_three_or_four_points_are_fitted() {
    let three = quasi(&[
        "--points",
        "0,0 2,0 2.6,1.2",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
        "--ratio",
        "0.5",
        "--tolerance",
        "1e-6",
    ]);
    assert!(f(&three["max"]) <= 1e-6);
    let curve = json(&lac(&[
        "compound",
        "--points",
        "0,0 2,0 2.6,1.2",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
        "--ratio",
        "0.5",
    ]));
    assert_eq!(three["arc_length"], curve["arc_length"]);
    assert!(pieces(&three)
        .iter()
        .all(|p| p["monotone"] == "increasing" && p["proven"] == true));

    let four = quasi(&[
        "--points",
        "0,0 2,0 2.5,2 0,1.5",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
        "--tolerance",
        "1e-3",
    ]);
    assert!(f(&four["max"]) <= 1e-3);
    let list = pieces(&four);
    let total = f(&list[list.len() - 1]["turning"][1]);
    assert!(total > PI, "four points turn by more than π: {total}");
}

#[test]
fn the_single_piece_of_a_curve_that_turns_too_far_is_not_found_exit_3() {
    let run = lac(&[
        "quasi",
        "--points",
        "0,0 2,0 2.5,2 0,1.5",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
    ]);
    let message = assert_failure(&run, 3, "fit_failed");
    assert!(message.contains("tolerance"), "{message}");
}

#[test]
fn cubic_gives_plain_cubics_with_unit_weights() {
    let v = quasi(&[
        "--points",
        CORNER,
        "--alpha",
        "0.5",
        "--tolerance",
        "1e-4",
        "--cubic",
    ]);
    assert_eq!(v["kind"], "cubic");
    assert!(f(&v["max"]) <= 1e-4);
    for p in pieces(&v) {
        let w: Vec<f64> = p["weights"].as_array().unwrap().iter().map(f).collect();
        assert_eq!(w, [1.0; 4], "{p}");
    }
}

#[test]
fn usage_errors_are_one_line_json_with_exit_code_2() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["quasi", "--points", CORNER, "--alpha", "0.5", "--cubic"],
            "usage",
        ),
        (&["quasi", "--points", CORNER], "usage"),
        (
            &[
                "quasi", "--points", CORNER, "--alpha", "0.5", "--alpha0", "1",
            ],
            "usage",
        ),
        (
            &[
                "quasi", "--points", CORNER, "--alpha0", "0.5", "--alpha1", "1",
            ],
            "usage",
        ),
        (
            &["quasi", "--points", "0,0 1,0", "--alpha", "0.5"],
            "invalid_input",
        ),
        (
            &[
                "quasi",
                "--points",
                CORNER,
                "--alpha",
                "0.5",
                "--tolerance",
                "1e-13",
            ],
            "out_of_range",
        ),
        (
            &["quasi", "--points", "0,0 1,0 2,0", "--alpha", "0.5"],
            "collinear_points",
        ),
    ];
    for (args, kind) in cases {
        assert_failure(&lac(args), 2, kind);
    }
    // A triangle the segment cannot fill is the library's verdict: exit 3.
    let run = lac(&["quasi", "--points", "0,0 1,0 1,0.1", "--alpha", "-1"]);
    assert_failure(&run, 3, "not_drawable");
}

fn svg(args: &[&str]) -> String {
    let mut all = vec!["quasi", "--format", "svg"];
    all.extend_from_slice(args);
    let run = lac(&all);
    assert_eq!(run.code, 0, "{}", run.stderr);
    run.stdout
}

/// The `d` attributes of the Bézier pieces' paths.
fn piece_paths(doc: &str) -> Vec<&str> {
    doc.split(r#"<path class="piece""#)
        .skip(1)
        .map(|rest| {
            let start = rest.find(" d=\"").unwrap() + 4;
            &rest[start..start + rest[start..].find('"').unwrap()]
        })
        .collect()
}

/// The SVG is well-formed and renderable: usvg parses it.
fn assert_renders(doc: &str) {
    let tree = resvg::usvg::Tree::from_str(doc, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("usvg parses the SVG: {e}"));
    assert!(tree.size().width() > 500.0);
}

#[test]
fn the_svg_draws_each_piece_both_combs_and_the_deviation() {
    let args = ["--points", CORNER, "--alpha", "-1", "--tolerance", "1e-7"];
    let doc = svg(&args);
    let count = pieces(&quasi(&args)).len();
    assert!(count > 1);
    assert!(doc.starts_with("<?xml") && doc.trim_end().ends_with("</svg>"));
    assert!(doc.contains(r#"xmlns="http://www.w3.org/2000/svg""#));
    assert_renders(&doc);
    let paths = piece_paths(&doc);
    assert_eq!(paths.len(), count, "one path per piece");
    // Rational pieces are polylines.
    assert!(paths.iter().all(|d| d.starts_with('M') && d.contains('L')));
    // Both comb envelopes (the curve's in red, the pieces' in blue) and the joints.
    assert!(doc.contains(r##"<polyline stroke="#d0342c" stroke-width="1.25""##));
    assert!(doc.contains(r##"<polyline stroke="#1f6fd1" stroke-width="1.25""##));
    assert_eq!(doc.matches(r#"class="joint""#).count(), count - 1);
    assert!(doc.contains("rms = ") && doc.contains("max = "), "caption");
    assert!(doc.contains("curvature increasing, proven"), "caption");
    assert!(!doc.contains("NaN") && !doc.contains("inf"));
}

#[test]
fn plain_cubics_are_drawn_as_c_commands_and_the_file_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("quasi.svg");
    let run = lac(&[
        "quasi",
        "--points",
        "0,0 2,0 2.6,1.2",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
        "--ratio",
        "0.5",
        "--tolerance",
        "1e-3",
        "--cubic",
        "--format",
        "svg",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.is_empty());
    let doc = std::fs::read_to_string(&path).unwrap();
    assert_renders(&doc);
    let paths = piece_paths(&doc);
    assert!(!paths.is_empty());
    for d in paths {
        assert!(d.starts_with('M') && d.matches('C').count() == 1, "{d}");
    }
    assert!(doc.contains("α0 = -1") && doc.contains("plain cubic"));
}

#[test]
fn the_one_piece_svg_of_a_circular_arc_has_no_joints() {
    let doc = svg(&["--points", ISOSCELES, "--alpha", "2"]);
    assert_renders(&doc);
    assert_eq!(piece_paths(&doc).len(), 1);
    assert!(!doc.contains(r#"class="joint""#));
    assert!(doc.contains("curvature constant"), "caption");
}
