//! `lac export`: the report on standard error, the format from `-o`'s extension, a solved
//! result read from standard input, and the refusals (exit codes and kinds). The files' own
//! correctness is `lac_io`'s tests and the CAD readers' (tools/reference/test_export.py).

use crate::common;

use common::{assert_failure, assert_keys, lac, lac_with_input};

const SEGMENT: [&str; 4] = ["--points", "0,0 3,0 4.2,1.9", "--alpha", "0.5"];
const SPACE: [&str; 8] = [
    "--points",
    "0,0,0 3,0,0 3,3,1.5 0,3,3",
    "--alpha",
    "0.5",
    "--beta",
    "0",
    "--omega",
    "0.3",
];
const REPORT_KEYS: [&str; 13] = [
    "format",
    "kind",
    "pieces",
    "single_spans",
    "tolerance",
    "max_deviation",
    "fit_deviation",
    "samples_per_piece",
    "arc_length",
    "continuity",
    "monotone_proven",
    "polynomial",
    "units",
];

fn args<'a>(curve: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec!["export"];
    v.extend_from_slice(curve);
    v.extend_from_slice(extra);
    v
}

/// The first curve of an exported JSON document ends where it starts (to 1e-12).
fn assert_closes(doc: &serde_json::Value) {
    let points = doc["curves"][0]["control_points"].as_array().unwrap();
    let (first, last) = (&points[0], &points[points.len() - 1]);
    for k in 0..2 {
        let d = first[k].as_f64().unwrap() - last[k].as_f64().unwrap();
        assert!(d.abs() < 1e-12, "{first} vs {last}");
    }
}

#[test]
fn the_report_goes_to_standard_error_and_the_format_follows_the_extension() {
    let dir = tempfile::tempdir().unwrap();
    for (ext, format) in [
        ("dxf", "dxf"),
        ("stp", "step"),
        ("IGS", "iges"),
        ("svg", "svg"),
    ] {
        let path = dir.path().join(format!("curve.{ext}"));
        let run = lac(&args(&SEGMENT, &["-o", path.to_str().unwrap()]));
        assert_eq!(run.code, 0, "{}", run.stderr);
        assert!(run.stdout.is_empty());
        let report: serde_json::Value = serde_json::from_str(&run.stderr).unwrap();
        assert_keys(&run.stderr, &report, &REPORT_KEYS);
        assert_eq!(report["format"], format);
        assert_eq!(report["tolerance"], 1e-6, "the default tolerance");
        assert!(report["max_deviation"].as_f64().unwrap() <= 1e-6);
        assert_eq!(report["continuity"], "G2");
        assert_eq!(report["monotone_proven"], true);
        assert!(std::fs::metadata(&path).unwrap().len() > 0);
    }
    let run = lac(&args(&SEGMENT, &["-o", "curve.txt"]));
    assert_failure(&run, 2, "usage");
}

#[test]
fn standard_output_holds_the_document_and_a_piped_result_exports_the_same() {
    let direct = lac(&args(&SPACE, &["--format", "json", "--tolerance", "1e-8"]));
    assert_eq!(direct.code, 0, "{}", direct.stderr);
    let doc: serde_json::Value = serde_json::from_str(&direct.stdout).unwrap();
    assert_eq!(doc["curves"][0]["dimension"], 3);
    assert_eq!(doc["continuity"], "C1");
    assert_eq!(doc["monotone_proven"], serde_json::Value::Null);
    let mut space = vec!["space"];
    space.extend_from_slice(&SPACE);
    let solved = lac(&space);
    assert_eq!(solved.code, 0);
    let piped = lac_with_input(
        &["export", "--format", "json", "--tolerance", "1e-8"],
        solved.stdout.as_bytes(),
    );
    assert_eq!(piped.code, 0, "{}", piped.stderr);
    assert_eq!(piped.stdout, direct.stdout);
}

#[test]
fn a_relative_tolerance_is_a_share_of_the_arc_length() {
    let run = lac(&args(
        &SEGMENT,
        &[
            "--format",
            "json",
            "--relative-tolerance",
            "1e-8",
            "--pieces",
        ],
    ));
    assert_eq!(run.code, 0, "{}", run.stderr);
    let doc: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let (tol, len) = (
        doc["tolerance"].as_f64().unwrap(),
        doc["arc_length"].as_f64().unwrap(),
    );
    assert!((tol - 1e-8 * len).abs() <= 1e-22);
    assert_eq!(doc["single_spans"], true);
    assert_eq!(
        doc["curves"].as_array().unwrap().len() as u64,
        doc["pieces"].as_u64().unwrap()
    );
}

#[test]
fn refusals_say_why_and_leave_an_existing_file_alone() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kept.step");
    std::fs::write(&path, "old").unwrap();
    let out = path.to_str().unwrap();
    let run = lac(&args(&SEGMENT, &["--tolerance", "1e-15", "-o", out]));
    let message = assert_failure(&run, 3, "tolerance_not_met");
    assert!(message.contains("1e-12"), "{message}");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
    assert_failure(
        &lac(&args(&SEGMENT, &["--tolerance", "0", "-o", out])),
        2,
        "out_of_range",
    );
    assert_failure(&lac(&args(&SPACE, &["--format", "svg"])), 2, "usage");
    assert_failure(
        &lac(&args(
            &SEGMENT,
            &[
                "--format",
                "json",
                "--tolerance",
                "1e-6",
                "--relative-tolerance",
                "1e-6",
            ],
        )),
        2,
        "usage",
    );
    assert_failure(
        &lac(&args(&SEGMENT, &["--format", "json", "--omega", "0.3"])),
        2,
        "usage",
    );
    // Bézier pieces are not an exact curve.
    let quasi = lac(&["quasi", "--points", "0,0 3,0 4.2,1.9", "--alpha", "0.5"]);
    let run = lac_with_input(&["export", "--format", "json"], quasi.stdout.as_bytes());
    assert_failure(&run, 2, "invalid_input");
}

/// A convex polygon, so that a G2 path exists (the turning keeps its direction).
const POLYGON: &str = "0,0 3,0 4,2 2,4 -1,2";

#[test]
fn a_path_exports_from_its_arguments_or_from_lac_paths_result_with_its_joints_as_knots() {
    for (extra, continuity) in [
        (vec!["--alpha", "1", "--g2"], "G2"),
        (vec!["--alphas", "1,0.5,0.8"], "G1"),
    ] {
        let mut curve = vec!["--polygon", POLYGON];
        curve.extend_from_slice(&extra);
        let direct = lac(&args(&curve, &["--format", "json", "--tolerance", "1e-8"]));
        assert_eq!(direct.code, 0, "{}", direct.stderr);
        let doc: serde_json::Value = serde_json::from_str(&direct.stdout).unwrap();
        assert_eq!(doc["kind"], "path");
        assert_eq!(doc["continuity"], continuity);
        assert_eq!(doc["monotone_proven"], true);
        assert!(doc["max_deviation"].as_f64().unwrap() <= 1e-8);
        // lac path's JSON, piped in, is the same path and the same file.
        let mut path = vec!["path"];
        path.extend_from_slice(&curve);
        let solved = lac(&path);
        assert_eq!(solved.code, 0, "{}", solved.stderr);
        let piped = lac_with_input(
            &["export", "--format", "json", "--tolerance", "1e-8"],
            solved.stdout.as_bytes(),
        );
        assert_eq!(piped.code, 0, "{}", piped.stderr);
        assert_eq!(piped.stdout, direct.stdout);
        // Every joint of the path is a knot of the B-spline (the knots are the pieces'
        // cumulative arc lengths: within the tolerance's effect on length).
        let report: serde_json::Value = serde_json::from_str(&solved.stdout).unwrap();
        let knots: Vec<f64> = doc["curves"][0]["knots"]
            .as_array()
            .unwrap()
            .iter()
            .map(|k| k.as_f64().unwrap())
            .collect();
        for joint in report["joints"].as_array().unwrap() {
            let s = joint["s"].as_f64().unwrap();
            let near = knots
                .iter()
                .fold(f64::INFINITY, |m, k| m.min((k - s).abs()));
            assert!(near < 1e-6, "joint at s = {s}: nearest knot {near} away");
        }
        assert!(
            doc["pieces"].as_u64().unwrap() >= 3,
            "one chain per segment at least"
        );
    }
}

#[test]
fn a_closed_path_is_a_curve_whose_ends_meet() {
    for g in [&["--g2"][..], &[][..]] {
        let mut curve = vec!["--polygon", POLYGON, "--alpha", "0.5", "--closed"];
        curve.extend_from_slice(g);
        let run = lac(&args(&curve, &["--format", "json"]));
        assert_eq!(run.code, 0, "{}", run.stderr);
        let doc: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
        assert_closes(&doc);
        assert_eq!(doc["continuity"], if g.is_empty() { "G1" } else { "G2" });
    }
}

#[test]
fn path_refusals() {
    // Path flags need --polygon; a path takes no compound or space slopes.
    assert_failure(
        &lac(&args(&SEGMENT, &["--alphas", "1,2", "--format", "json"])),
        2,
        "usage",
    );
    assert_failure(
        &lac(&[
            "export",
            "--polygon",
            POLYGON,
            "--alpha0",
            "1",
            "--alpha1",
            "2",
            "--format",
            "json",
        ]),
        2,
        "usage",
    );
    assert_failure(
        &lac(&["export", "--polygon", POLYGON, "--format", "json"]),
        2,
        "usage",
    );
    // A polygon whose turning changes direction has no G2 path: the solver's refusal.
    let run = lac(&[
        "export",
        "--polygon",
        "0,0 1,0 2,1 3,0",
        "--alpha",
        "1",
        "--g2",
        "--format",
        "dxf",
    ]);
    assert_ne!(run.code, 0);
    assert!(run.stderr.contains("no_g2_path"), "{}", run.stderr);
    assert!(run.stdout.is_empty());
    // A G2 path through an inflection (the README's S) is written G2 within the tolerance,
    // the straight piece a knot span of its own, every piece's curvature proven monotone.
    for (alpha, tolerance) in [("-0.5", "1e-6"), ("-1", "1e-8"), ("-0.75", "1e-4")] {
        let run = lac(&[
            "export",
            "--polygon",
            "0,0 1.5,0 3,0.8 6,3.2 7.5,4 9,4",
            "--alpha",
            alpha,
            "--g2",
            "--tolerance",
            tolerance,
            "--format",
            "step",
        ]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let report: serde_json::Value = serde_json::from_str(run.stderr.trim()).unwrap();
        assert_eq!(report["continuity"], "G2", "{report}");
        assert_eq!(report["monotone_proven"], true, "{report}");
        let max = report["max_deviation"].as_f64().unwrap();
        assert!(max <= tolerance.parse::<f64>().unwrap(), "{report}");
        assert!(run.stdout.starts_with("ISO-10303-21;"));
    }
}

/// A closed polygon in a figure eight: its G2 path passes through two inflections, with
/// a straight piece on each crossing leg, one of them the leg that closes the polygon (so
/// the curve's last piece is straight and ends where its first segment starts).
const FIGURE_EIGHT: &str = "1.5,-1 3,-1.8 4.5,-1 4.5,1 3,1.8 1.5,1 -1.5,-1 -3,-1.8 -4.5,-1 \
                            -4.5,1 -3,1.8 -1.5,1";

#[test]
fn a_closed_path_through_inflections_is_one_closed_g2_curve() {
    for (alpha, tolerance) in [("-1", "1e-6"), ("-0.5", "1e-8")] {
        let curve = [
            "--polygon",
            FIGURE_EIGHT,
            "--closed",
            "--g2",
            "--alpha",
            alpha,
        ];
        let run = lac(&args(
            &curve,
            &["--format", "json", "--tolerance", tolerance],
        ));
        assert_eq!(run.code, 0, "{}", run.stderr);
        let doc: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
        assert_eq!(doc["continuity"], "G2", "{doc}");
        assert_eq!(doc["monotone_proven"], true);
        let max = doc["max_deviation"].as_f64().unwrap();
        assert!(max <= tolerance.parse::<f64>().unwrap(), "{max}");
        // One curve that closes on itself, through every joint and straight piece of the
        // path in its order of travel: the path's own points are on it.
        assert_closes(&doc);
        let path = lac(&[&["path"][..], &curve, &["--format", "json"]].concat());
        assert_eq!(path.code, 0, "{}", path.stderr);
        let report: serde_json::Value = serde_json::from_str(&path.stdout).unwrap();
        let straight = report["straight_pieces"].as_array().unwrap();
        let legs: Vec<u64> = straight
            .iter()
            .map(|p| p["leg"].as_u64().unwrap())
            .collect();
        assert_eq!(legs, [5, 11], "{report}");
        // The curve starts where the first segment does (the end of the closing leg's
        // straight piece).
        let start = &report["segments"][0]["control_points"][0];
        let first = &doc["curves"][0]["control_points"][0];
        for k in 0..2 {
            let d = first[k].as_f64().unwrap() - start[k].as_f64().unwrap();
            assert!(d.abs() < 1e-12, "{first} vs {start}");
        }
        // The length of the exported curve is the path's.
        let length = doc["arc_length"].as_f64().unwrap();
        let path_length = report["arc_length"].as_f64().unwrap();
        assert!((length - path_length).abs() <= 1e-9 * path_length);
    }
}

/// A wave of points whose turning changes direction: for α < 0 its spline passes through
/// an inflection.
const WAVE: &str = "0,0.2955 1,0.9320 2,0.8632 3,0.1411 4,-0.6878 5,-0.9962 6,-0.5507 7,0.3115";

#[test]
fn a_spline_exports_from_its_arguments_or_from_lac_splines_result() {
    for alpha in ["-1", "-0.5", "-0.25", "0.5"] {
        let points = if alpha == "0.5" {
            "0,0 2,0.3 3.5,1.5 4,3"
        } else {
            WAVE
        };
        let curve = ["--through", points, "--alpha", alpha];
        let direct = lac(&args(&curve, &["--format", "json", "--tolerance", "1e-7"]));
        assert_eq!(direct.code, 0, "{alpha}: {}", direct.stderr);
        let doc: serde_json::Value = serde_json::from_str(&direct.stdout).unwrap();
        assert_eq!(doc["kind"], "spline");
        assert_eq!(doc["continuity"], "G2");
        assert_eq!(doc["monotone_proven"], true, "{alpha}");
        assert!(doc["max_deviation"].as_f64().unwrap() <= 1e-7);
        // lac spline's JSON, piped in, is the same spline and the same file.
        let mut spline = vec!["spline"];
        spline.extend_from_slice(&curve);
        let solved = lac(&spline);
        assert_eq!(solved.code, 0, "{}", solved.stderr);
        let piped = lac_with_input(
            &["export", "--format", "json", "--tolerance", "1e-7"],
            solved.stdout.as_bytes(),
        );
        assert_eq!(piped.code, 0, "{}", piped.stderr);
        assert_eq!(piped.stdout, direct.stdout);
    }
    // Closed: a curve whose ends meet; given end tangents.
    let run = lac(&[
        "export",
        "--through",
        "1,0 0,1.2 -1,0 0,-0.8",
        "--closed",
        "--alpha",
        "-1",
        "--format",
        "json",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let doc: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    assert_closes(&doc);
    let run = lac(&[
        "export",
        "--through",
        "0,0 2,0.3 3.5,1.5 4,3",
        "--alpha",
        "0.5",
        "--start-angle",
        "0.1",
        "--end-angle",
        "2",
        "--format",
        "dxf",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    // Refusals: a spline needs --alpha; --closed needs a polygon or points to pass through;
    // a span that must inflect with α ≥ 0 is the solver's refusal.
    assert_failure(
        &lac(&["export", "--through", WAVE, "--format", "json"]),
        2,
        "usage",
    );
    assert_failure(
        &lac(&args(&SEGMENT, &["--closed", "--format", "json"])),
        2,
        "usage",
    );
    assert_failure(
        &lac(&[
            "export",
            "--through",
            WAVE,
            "--alpha",
            "0.5",
            "--format",
            "json",
        ]),
        3,
        "no_g2_path",
    );
}

/// A spline with a straight span from P2 to P3 and a corner at P4, for `lac export
/// --through` with the point-type flags of `lac spline`.
const TYPED: [&str; 8] = [
    "--through",
    "0,0 1,2 3,2.5 5,2.5 6,1.5 7,2.5 8,4.5",
    "--alpha",
    "-1",
    "--types",
    "s s s s c s s",
    "--lines",
    "2-3",
];

/// The pieces of the first curve of an exported JSON document: its clamped B-spline's
/// knot spans (interior knots of multiplicity 3), each a rational cubic Bézier as control
/// points and weights.
fn bezier_pieces(doc: &serde_json::Value) -> Vec<([[f64; 2]; 4], [f64; 4])> {
    let curve = &doc["curves"][0];
    let points: Vec<[f64; 2]> = curve["control_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()])
        .collect();
    let weights: Vec<f64> = curve["weights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_f64().unwrap())
        .collect();
    assert_eq!(curve["degree"], 3);
    assert_eq!(points.len() % 3, 1, "one shared end point between spans");
    let knots = curve["knots"].as_array().unwrap();
    assert_eq!(
        knots.len(),
        points.len() + 4,
        "a clamped B-spline, knots of multiplicity 3"
    );
    (0..points.len() / 3)
        .map(|k| {
            (
                [
                    points[3 * k],
                    points[3 * k + 1],
                    points[3 * k + 2],
                    points[3 * k + 3],
                ],
                [
                    weights[3 * k],
                    weights[3 * k + 1],
                    weights[3 * k + 2],
                    weights[3 * k + 3],
                ],
            )
        })
        .collect()
}

/// A rational cubic Bézier at `t`.
fn rational_at((points, weights): &([[f64; 2]; 4], [f64; 4]), t: f64) -> [f64; 2] {
    let b = [
        (1.0 - t).powi(3),
        3.0 * t * (1.0 - t).powi(2),
        3.0 * t * t * (1.0 - t),
        t.powi(3),
    ];
    let w: f64 = (0..4).map(|i| b[i] * weights[i]).sum();
    let coordinate = |c: usize| {
        (0..4)
            .map(|i| b[i] * weights[i] * points[i][c])
            .sum::<f64>()
            / w
    };
    [coordinate(0), coordinate(1)]
}

/// The direction, radians, from `a` to `b`.
fn direction(a: [f64; 2], b: [f64; 2]) -> f64 {
    (b[1] - a[1]).atan2(b[0] - a[0])
}

/// `lac export --through` takes lac spline's point types: the straight span is written as a
/// straight piece from P2 to P3 (every point of it on the line) and the corner's two
/// tangents are the solved spline's, different on either side; the report says G0. The
/// same file as exporting lac spline's result with the same flags.
#[test]
fn a_spline_exports_with_its_corners_and_straight_spans() {
    let direct = lac(&args(&TYPED, &["--format", "json", "--tolerance", "1e-7"]));
    assert_eq!(direct.code, 0, "{}", direct.stderr);
    let doc: serde_json::Value = serde_json::from_str(&direct.stdout).unwrap();
    assert_eq!(doc["kind"], "spline");
    assert_eq!(doc["continuity"], "G0", "a corner breaks the tangent");
    assert!(doc["max_deviation"].as_f64().unwrap() <= 1e-7);
    let pieces = bezier_pieces(&doc);
    assert_eq!(pieces.len() as u64, doc["pieces"].as_u64().unwrap());
    let near = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]) <= 1e-9;

    // The straight span: one piece from P2 to P3 whose every point is on y = 2.5.
    let (p2, p3) = ([3.0, 2.5], [5.0, 2.5]);
    let line = pieces
        .iter()
        .find(|(p, _)| near(p[0], p2) && near(p[3], p3))
        .expect("a piece from P2 to P3");
    for k in 0..=20 {
        let [x, y] = rational_at(line, f64::from(k) / 20.0);
        assert!((y - 2.5).abs() <= 1e-12, "({x}, {y}) is off the line");
        assert!((3.0 - 1e-12..=5.0 + 1e-12).contains(&x), "({x}, {y})");
    }
    // The curve meets the line along it.
    let before = pieces.iter().find(|(p, _)| near(p[3], p2)).unwrap();
    let after = pieces.iter().find(|(p, _)| near(p[0], p3)).unwrap();
    assert!(direction(before.0[2], before.0[3]).abs() <= 1e-9);
    assert!(direction(after.0[0], after.0[1]).abs() <= 1e-9);

    // The corner: the tangents on either side are the spline's, about 1.8 rad apart.
    let mut spline = vec!["spline"];
    spline.extend_from_slice(&TYPED);
    let solved = lac(&spline);
    assert_eq!(solved.code, 0, "{}", solved.stderr);
    let v: serde_json::Value = serde_json::from_str(&solved.stdout).unwrap();
    let at = &v["at_points"][4];
    assert_eq!(at["type"], "corner");
    let (in_, out) = (
        at["angles"][0].as_f64().unwrap(),
        at["angles"][1].as_f64().unwrap(),
    );
    assert!((out - in_).abs() > 1.0, "{in_} {out}");
    let p4 = [6.0, 1.5];
    let arriving = pieces.iter().find(|(p, _)| near(p[3], p4)).unwrap();
    let leaving = pieces.iter().find(|(p, _)| near(p[0], p4)).unwrap();
    let (a, b) = (
        direction(arriving.0[2], arriving.0[3]),
        direction(leaving.0[0], leaving.0[1]),
    );
    assert!((a - in_).abs() <= 1e-6, "arriving {a}, the spline's {in_}");
    assert!((b - out).abs() <= 1e-6, "leaving {b}, the spline's {out}");

    // lac spline's result with the same flags, piped in: the same file.
    let piped = lac_with_input(
        &["export", "--format", "json", "--tolerance", "1e-7"],
        solved.stdout.as_bytes(),
    );
    assert_eq!(piped.code, 0, "{}", piped.stderr);
    assert_eq!(piped.stdout, direct.stdout);
    // And as STEP, through -o.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("typed.step");
    let run = lac(&args(&TYPED, &["-o", path.to_str().unwrap()]));
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(std::fs::read_to_string(&path)
        .unwrap()
        .contains("B_SPLINE_CURVE_WITH_KNOTS"));
}

/// Malformed or misplaced point-type flags are usage errors (one line of JSON, exit code
/// 2) that leave an existing file alone, as in lac spline; so are the flags without
/// --through, where another curve is given.
#[test]
fn bad_point_type_flags_of_an_export_are_usage_errors() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kept.json");
    std::fs::write(&path, "old").unwrap();
    let out = path.to_str().unwrap();
    let through = TYPED[1];
    for (flags, says) in [
        (&["--types", "s s x s c s s"][..], "not a point type"),
        (&["--types", "s s s c"], "4 letters for 7 points"),
        (&["--lines", "2-4"], "between consecutive points"),
        (
            &["--types", "s s s s c s s", "--angles", "4:0"],
            "two sides",
        ),
        (&["--types", "s s t s s s s"], "give its direction"),
    ] {
        let mut all = vec!["export", "--through", through, "--alpha", "-1", "-o", out];
        all.extend_from_slice(flags);
        let message = assert_failure(&lac(&all), 2, "usage");
        assert!(message.contains(says), "{flags:?}: {message}");
    }
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
    // An end curvature of a closed spline; point types beside a segment's --points.
    assert_failure(
        &lac(&[
            "export",
            "--through",
            through,
            "--alpha",
            "-1",
            "--closed",
            "--end-curvature",
            "0.5",
            "-o",
            out,
        ]),
        2,
        "usage",
    );
    let message = assert_failure(
        &lac(&args(&SEGMENT, &["--types", "s c s", "--format", "json"])),
        2,
        "usage",
    );
    assert!(message.contains("--through"), "{message}");
}
