//! `lac export`: the report on standard error, the format from `-o`'s extension, a solved
//! result read from standard input, and the refusals (exit codes and kinds). The files' own
//! correctness is `lac_io`'s tests and the CAD readers' (tools/reference/test_export.py).

mod common;

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
