//! `lac lcg`: the curvature plot and logarithmic curvature graph of `lac quasi`, `lac
//! segment` and `lac compound` output, as JSON, CSV, SVG and PNG.

mod common;

use common::{assert_failure, json, lac, lac_with_input, Run};
use serde_json::Value;

const POINTS: &str = "0,0 3,0 4.2,1.9";

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

/// The standard output of a successful run of `lac args…`.
fn stdout(args: &[&str]) -> String {
    let run = lac(args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    run.stdout
}

/// `lac lcg args…` reading `input` from standard input.
fn lcg(input: &str, args: &[&str]) -> Run {
    let mut all = vec!["lcg"];
    all.extend_from_slice(args);
    lac_with_input(&all, input.as_bytes())
}

fn lcg_json(input: &str, args: &[&str]) -> Value {
    let run = lcg(input, args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1);
    json(&run)
}

fn points(v: &Value) -> &Vec<Value> {
    v["points"].as_array().expect("points")
}

#[test]
fn a_segment_result_gives_back_its_alpha_to_1e_9() {
    for alpha in ["-1", "0", "0.5", "1", "2"] {
        let segment = stdout(&["segment", "--points", POINTS, "--alpha", alpha]);
        let line = lcg(&segment, &[]).stdout;
        let v = lcg_json(&segment, &[]);
        common::assert_keys(&line, &v, &["points", "fit"]);
        assert_eq!(points(&v).len(), 257, "default samples along a curve");
        let fit = &v["fit"];
        let fit_text = &line[line.find("\"fit\":").unwrap()..];
        common::assert_keys(
            fit_text,
            fit,
            &[
                "alpha",
                "intercept",
                "rms_residual",
                "max_residual",
                "log_rho",
            ],
        );
        let want: f64 = alpha.parse().unwrap();
        assert!((f(&fit["alpha"]) - want).abs() < 1e-9, "{alpha}: {fit}");
        assert!(f(&fit["rms_residual"]) < 1e-9);
        // The segment's own LCG intercept, −ln Λ in its units, from `lac segment`.
        let first = &points(&v)[0];
        common::assert_keys(
            &line,
            first,
            &["s", "kappa", "dkappa_ds", "log_rho", "log_lcg"],
        );
        let kappa = f(&first["kappa"]);
        assert!((f(&first["log_rho"]) + kappa.abs().ln()).abs() < 1e-14);
        assert_eq!(f(&first["s"]), 0.0);
        let seg: Value = serde_json::from_str(&segment).unwrap();
        assert!((kappa - f(&seg["curvature_start"])).abs() < 1e-14 * kappa.abs());
        let last = &points(&v)[256];
        assert!((f(&last["s"]) - f(&seg["arc_length"])).abs() < 1e-13);
    }
}

#[test]
fn the_output_of_lac_quasi_gives_alpha_within_0_05() {
    for alpha in ["-1", "0.5", "2"] {
        let quasi = stdout(&[
            "quasi",
            "--points",
            POINTS,
            "--alpha",
            alpha,
            "--tolerance",
            "1e-6",
        ]);
        let pieces = serde_json::from_str::<Value>(&quasi).unwrap()["pieces"]
            .as_array()
            .unwrap()
            .len();
        let v = lcg_json(&quasi, &[]);
        assert_eq!(points(&v).len(), pieces * 63 + 1, "64 a piece, joints once");
        let want: f64 = alpha.parse().unwrap();
        let got = f(&v["fit"]["alpha"]);
        assert!((got - want).abs() < 0.05, "{alpha}: {got}");
        let v = lcg_json(&quasi, &["--samples", "9"]);
        assert_eq!(points(&v).len(), pieces * 8 + 1);
    }
}

#[test]
fn a_compound_result_is_solved_again_from_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("compound.json");
    let compound = stdout(&[
        "compound",
        "--points",
        "0,0 2,0 2.5,2 0,1.5",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
    ]);
    std::fs::write(&path, &compound).unwrap();
    let run = lac(&["lcg", path.to_str().unwrap(), "--samples", "101"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    let rows = points(&v);
    assert_eq!(rows.len(), 101);
    let c: Value = serde_json::from_str(&compound).unwrap();
    assert!((f(&rows[100]["s"]) - f(&c["arc_length"])).abs() < 1e-13);
    // One line through a "valley" of slopes −1 and 2 fits badly, but it is a line.
    assert!(f(&v["fit"]["rms_residual"]) > 0.01);
}

#[test]
fn pieces_without_weights_are_plain_cubics() {
    let piece = r#"{"points":[[0,0],[1.2,0],[2,0.4],[2.4,1]]"#;
    let plain = lcg_json(&format!(r#"{{"pieces":[{piece}}}]}}"#), &["-"]);
    let ones = lcg_json(
        &format!(r#"{{"pieces":[{piece},"weights":[1,1,1,1]}}]}}"#),
        &[],
    );
    assert_eq!(plain, ones);
    assert_eq!(points(&plain).len(), 64);
}

#[test]
fn a_circle_has_no_graph_points_and_no_fit() {
    let segment = stdout(&["segment", "--points", "0,0 1,1 2,0", "--alpha", "0.5"]);
    let v = lcg_json(&segment, &["--samples", "5"]);
    assert_eq!(v["fit"], Value::Null);
    for row in points(&v) {
        assert_eq!(row["log_rho"], Value::Null);
        assert_eq!(row["log_lcg"], Value::Null);
        assert!((f(&row["kappa"]) + 1.0 / std::f64::consts::SQRT_2).abs() < 1e-14);
    }
    let run = lcg(&segment, &["--samples", "5", "--format", "csv"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines.len(), 6);
    assert!(lines[1..].iter().all(|l| l.ends_with(",,")), "{lines:?}");
}

#[test]
fn csv_has_the_header_and_one_row_per_point() {
    let segment = stdout(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    let run = lcg(&segment, &["--format", "csv", "--samples", "33"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines[0], "s,kappa,dkappa_ds,log_rho,log_lcg");
    assert_eq!(lines.len(), 34);
    let v = lcg_json(&segment, &["--samples", "33"]);
    for (line, row) in lines[1..].iter().zip(points(&v)) {
        let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let want = ["s", "kappa", "dkappa_ds", "log_rho", "log_lcg"].map(|k| f(&row[k]));
        assert_eq!(cells, want, "CSV and JSON carry the same numbers");
    }
}

/// The `width` and `height` of an SVG document.
fn svg_size(doc: &str) -> (u32, u32) {
    let attr = |name: &str| -> u32 {
        let start = doc.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        doc[start..start + doc[start..].find('"').unwrap()]
            .parse()
            .unwrap()
    };
    (attr("width"), attr("height"))
}

#[test]
fn the_svg_has_both_panels_the_fitted_line_and_alpha() {
    let segment = stdout(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    let run = lcg(&segment, &["--format", "svg"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let doc = &run.stdout;
    assert!(doc.starts_with("<?xml") && doc.trim_end().ends_with("</svg>"));
    resvg::usvg::Tree::from_str(doc, &resvg::usvg::Options::default())
        .expect("usvg parses the SVG");
    assert!(doc.contains("Curvature plot") && doc.contains("Logarithmic curvature graph"));
    assert!(doc.contains(r#"class="fit""#), "the fitted line");
    assert!(doc.contains("α = 0.5 (rms residual"), "the slope");
    assert_eq!(
        doc.matches("<circle ").count(),
        257,
        "a dot per graph point"
    );
    assert!(!doc.contains("NaN") && !doc.contains("inf"));
    // Bézier input marks the joints between pieces in the curvature plot.
    let quasi = stdout(&[
        "quasi",
        "--points",
        POINTS,
        "--alpha",
        "-1",
        "--tolerance",
        "1e-9",
    ]);
    let pieces = serde_json::from_str::<Value>(&quasi).unwrap()["pieces"]
        .as_array()
        .unwrap()
        .len();
    let run = lcg(&quasi, &["--format", "svg"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.matches(r#"class="joint""#).count(), pieces - 1);
}

#[test]
fn the_png_is_the_svg_rendered_at_its_size() {
    let segment = stdout(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    let (width, height) = svg_size(&lcg(&segment, &["--format", "svg"]).stdout);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lcg.png");
    let run = lcg(&segment, &["--format", "png", "-o", path.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes[..]))
        .read_info()
        .unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    assert_eq!((info.width, info.height), (width, height));
    // Something is drawn on the white background.
    assert!(pixels.chunks(4).any(|p| p[0] < 128 && p[3] == 255));
    // To a pipe, the same bytes go to standard output.
    let piped = lcg(&segment, &["--format", "png"]);
    assert_eq!(piped.code, 0, "{}", piped.stderr);
    assert_eq!(piped.stdout_bytes, bytes);
}

#[test]
fn bad_input_is_a_one_line_json_error() {
    let cases: &[(&str, &[&str], i32, &str)] = &[
        ("not json", &[], 2, "invalid_input"),
        (r#"{"curve":1}"#, &[], 2, "invalid_input"),
        (
            r#"{"pieces":[{"points":[[0,0],[1,0],[1,1]]}]}"#,
            &[],
            2,
            "invalid_input",
        ),
        (r#"{"pieces":[]}"#, &[], 2, "invalid_input"),
        (
            r#"{"pieces":[{"points":[[0,0],[1,0],[1,1],[2,1]],"weights":[1,0,1,1]}]}"#,
            &[],
            2,
            "out_of_range",
        ),
        (
            r#"{"alpha":0.5,"points":[[0,0],[1,0]]}"#,
            &[],
            2,
            "invalid_input",
        ),
        (
            r#"{"alpha0":-1,"alpha1":2,"points":[[0,0],[2,0],[2.6,1.2]]}"#,
            &[],
            2,
            "invalid_input",
        ),
        (
            r#"{"alpha":-1,"points":[[0,0],[1,0],[1,0.1]]}"#,
            &[],
            3,
            "not_drawable",
        ),
    ];
    for (input, args, code, kind) in cases {
        assert_failure(&lcg(input, args), *code, kind);
    }
    // Refused before reading: no standard input to feed.
    assert_failure(&lac(&["lcg", "--samples", "1"]), 2, "usage");
    let missing = lac(&["lcg", "/nonexistent/lcg.json"]);
    assert_failure(&missing, 1, "io");
}
