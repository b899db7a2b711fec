//! `lac lcg`: the curvature plot and logarithmic curvature graph of `lac quasi`, `lac
//! segment` and `lac compound` output, as JSON, CSV, SVG and PNG.

use crate::common;

use common::{assert_failure, f, json, lac, lac_with_input, Run};
use serde_json::Value;

const POINTS: &str = "0,0 3,0 4.2,1.9";

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

#[test]
fn a_compound_curve_gets_each_pieces_own_line_as_well_as_the_whole() {
    let compound = stdout(&[
        "compound",
        "--points",
        "0,0 2,0 2.5,2 0,1.5",
        "--alpha0",
        "-1",
        "--alpha1",
        "2",
    ]);
    let c: Value = serde_json::from_str(&compound).unwrap();
    let v = lcg_json(&compound, &[]);
    let pieces = v["pieces"].as_array().expect("pieces");
    assert_eq!(pieces.len(), 2);
    for (piece, alpha) in pieces.iter().zip([-1.0, 2.0]) {
        let fit = &piece["fit"];
        assert!((f(&fit["alpha"]) - alpha).abs() < 1e-9, "{piece}");
        assert!(f(&fit["rms_residual"]) < 1e-9, "{piece}");
    }
    let joint = f(&c["joint_s"]);
    assert_eq!(f(&pieces[0]["s"][0]), 0.0);
    assert!((f(&pieces[0]["s"][1]) - joint).abs() < 1e-13 * joint);
    assert_eq!(pieces[0]["s"][1], pieces[1]["s"][0]);
    assert!((f(&pieces[1]["s"][1]) - f(&c["arc_length"])).abs() < 1e-13);
    // The whole curve's line is still there, and a segment has no "pieces".
    assert!(v["fit"]["alpha"].is_f64());
    let segment = stdout(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    assert!(lcg_json(&segment, &[]).get("pieces").is_none());
    // The drawing shows both pieces' lines and their slopes.
    let svg = lcg(&compound, &["--format", "svg"]).stdout;
    assert_eq!(svg.matches(r#"class="piece-fit""#).count(), 2);
    assert_eq!(svg.matches(r#"class="fit""#).count(), 1);
    assert!(svg.contains("piece\u{a0}1 α\u{a0}=\u{a0}-1") && svg.contains("α\u{a0}=\u{a0}2"));
}

/// Two proven-monotone cubics whose curvature runs in opposite directions (the second is the
/// mirror image of the first), and an S-shaped cubic.
const OPPOSITE: &str = r#"{"pieces":[{"points":[[0,0],[1.2,0],[2,0.4],[2.4,1]]},{"points":[[0,0],[1.2,0],[2,-0.4],[2.4,-1]]}]}"#;
const S_CURVE: &str = r#"{"pieces":[{"points":[[0,0],[1,1],[2,-1],[3,0]]}]}"#;

#[test]
fn a_curvature_that_is_not_monotone_gets_no_slope_and_says_so() {
    for (input, why) in [(OPPOSITE, "piece 1 of 2"), (S_CURVE, "piece 1 of 1")] {
        let run = lcg(input, &[]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let v = json(&run);
        assert_eq!(v["fit"], Value::Null, "{input}");
        assert_eq!(v["monotone"], false);
        let note = v["note"].as_str().unwrap();
        assert!(
            note.contains("not monotone") && note.contains(why),
            "{note}"
        );
        // The graph's points are still there.
        assert!(points(&v).iter().any(|p| p["log_rho"].is_f64()));
        let csv = lcg(input, &["--format", "csv"]).stdout;
        assert_eq!(csv.lines().next(), Some(format!("# {note}").as_str()));
        assert_eq!(
            csv.lines().nth(1),
            Some("s,kappa,dkappa_ds,log_rho,log_lcg")
        );
        let svg = lcg(input, &["--format", "svg"]).stdout;
        assert!(svg.contains("no line: the curvature is not monotone"));
        assert!(!svg.contains(r#"class="fit""#) && !svg.contains("α = "));
    }
    // A monotone curve says nothing of the kind.
    let segment = stdout(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    let v = lcg_json(&segment, &[]);
    assert!(v.get("monotone").is_none() && v.get("note").is_none());
    let csv = lcg(&segment, &["--format", "csv"]).stdout;
    assert!(csv.starts_with("s,kappa"));
}

/// `lac space` output for these points, slopes and Ω.
fn space(points: &str, alpha: &str, beta: &str, omega: &str) -> String {
    stdout(&[
        "space", "--points", points, "--alpha", alpha, "--beta", beta, "--omega", omega,
    ])
}

const SPACE_POINTS: &str = "0,0,0 3,0,0 3,3,1.5 0,3,3";

#[test]
fn a_space_curve_gives_its_curvature_and_torsion_graphs_with_slopes_alpha_and_beta() {
    for (alpha, beta) in [("0.5", "-0.5"), ("-1", "1"), ("2", "0")] {
        let input = space(SPACE_POINTS, alpha, beta, "0.3");
        let run = lcg(&input, &["--samples", "65"]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let v = json(&run);
        common::assert_keys(&run.stdout, &v, &["curvature", "torsion"]);
        for (graph, want) in [("curvature", alpha), ("torsion", beta)] {
            let g = &v[graph];
            assert_eq!(g["points"].as_array().unwrap().len(), 65);
            let fit = &g["fit"];
            let want: f64 = want.parse().unwrap();
            assert!((f(&fit["slope"]) - want).abs() < 1e-9, "{graph}: {fit}");
            assert!(f(&fit["rms_residual"]) < 1e-9);
        }
        let csv = lcg(&input, &["--samples", "9", "--format", "csv"]).stdout;
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], "s,log_rho,log_lcg,log_mu,log_ltg");
        assert_eq!(lines.len(), 10);
        assert!(lines[1..]
            .iter()
            .all(|l| l.split(',').all(|c| c.parse::<f64>().is_ok())));
        let svg = lcg(&input, &["--format", "svg"]).stdout;
        assert!(svg.contains("Logarithmic curvature graph"));
        assert!(svg.contains("Logarithmic torsion graph"));
        assert!(svg.contains(&format!("α = {alpha} (rms")), "{alpha}");
        assert!(svg.contains(&format!("β = {beta} (rms")), "{beta}");
        assert_eq!(svg.matches(r#"class="fit""#).count(), 2);
    }
    // Ω = 0: the radius of torsion is constant, so there is no torsion graph; coplanar
    // points: the planar segment, no torsion at all.
    for (input, why) in [
        (space(SPACE_POINTS, "0.5", "0", "0"), "Ω = 0"),
        (
            space("0,0,0 1,0,0 2,0.5,0 2.5,2,0", "0.5", "0", "0.3"),
            "coplanar",
        ),
    ] {
        let v = lcg_json(&input, &[]);
        assert!(v["torsion"]["points"].as_array().unwrap().is_empty());
        assert_eq!(v["torsion"]["fit"], Value::Null);
        assert!((f(&v["curvature"]["fit"]["slope"]) - 0.5).abs() < 1e-9);
        assert!(v["note"].as_str().unwrap().contains(why), "{v}");
        let svg = lcg(&input, &["--format", "svg"]).stdout;
        assert!(svg.contains("no graph: the radius of torsion is constant"));
    }
}

#[test]
fn the_number_of_curvature_points_is_limited() {
    let segment = stdout(&["segment", "--points", POINTS, "--alpha", "0.5"]);
    let message = assert_failure(&lcg(&segment, &["--samples", "1000001"]), 2, "limit");
    assert!(message.contains("--allow-large"), "{message}");
    // For Bézier pieces the limit is on the points of all pieces together.
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
    assert!(pieces >= 2);
    let per_piece = (1_000_000 / pieces + 2).to_string();
    assert_failure(&lcg(&quasi, &["--samples", &per_piece]), 2, "limit");
}
