//! One tool: every subcommand that prints curves offers `--format json|csv|svg` and
//! `-o FILE`, `-o -` is standard output everywhere, the same flags mean the same things, and
//! `--help` documents each format.

use crate::common;

use common::{assert_failure, lac, lac_with_input};
use serde_json::Value;

/// The curve-printing subcommands with a valid single-curve argument list each.
fn curve_commands() -> Vec<Vec<&'static str>> {
    vec![
        vec!["segment", "--points", "0,0 3,0 4.2,1.9", "--alpha", "0.5"],
        vec![
            "compound",
            "--points",
            "0,0 2,0 2.5,2 0,1.5",
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
        ],
        vec![
            "quasi",
            "--points",
            "0,0 3,0 4,1.5",
            "--alpha",
            "-1",
            "--tolerance",
            "1e-6",
        ],
        vec![
            "space",
            "--points",
            "0,0,0 3,0,0 3,3,1.5 0,3,3",
            "--alpha",
            "0.5",
            "--beta",
            "0",
            "--omega",
            "0.3",
        ],
    ]
}

/// Standard output of a successful `lac args…`.
fn stdout(args: &[&str]) -> String {
    let run = lac(args);
    assert_eq!(run.code, 0, "lac {args:?}: {}", run.stderr);
    assert!(run.stderr.is_empty(), "{}", run.stderr);
    run.stdout
}

fn with<'a>(base: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
    [base, extra].concat()
}

#[test]
fn every_curve_command_prints_json_csv_and_svg() {
    for base in curve_commands() {
        let json = stdout(&with(&base, &["--format", "json"]));
        assert_eq!(json, stdout(&base), "{base:?}: json is the default");
        let v: Value = serde_json::from_str(&json).unwrap();
        assert!(v.is_object(), "{base:?}");
        let csv = stdout(&with(&base, &["--format", "csv"]));
        let mut rows = csv.lines();
        let header = rows.next().unwrap();
        let columns = header.split(',').count();
        assert!(columns >= 5, "{base:?}: {header}");
        let rows: Vec<&str> = rows.collect();
        assert!(!rows.is_empty(), "{base:?}");
        assert!(
            rows.iter().all(|r| r.split(',').count() == columns),
            "{base:?}: every row has the header's {columns} cells"
        );
        let svg = stdout(&with(&base, &["--format", "svg"]));
        assert!(svg.starts_with("<?xml") && svg.trim_end().ends_with("</svg>"));
        resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default())
            .unwrap_or_else(|e| panic!("{base:?}: usvg parses the SVG: {e}"));
    }
}

#[test]
fn quasi_csv_has_one_row_per_piece_with_its_control_points_weights_verdict_and_deviation() {
    let base = curve_commands()[2].clone();
    let v: Value = serde_json::from_str(&stdout(&base)).unwrap();
    let csv = stdout(&with(&base, &["--format", "csv"]));
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "piece,x0,y0,x1,y1,x2,y2,x3,y3,w0,w1,w2,w3,monotone,proven,t,turning0,turning1,\
         max_deviation"
    );
    let pieces = v["pieces"].as_array().unwrap();
    assert_eq!(lines.len(), pieces.len() + 1);
    for (i, (line, piece)) in lines[1..].iter().zip(pieces).enumerate() {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells[0], i.to_string());
        let number = |k: usize| cells[k].parse::<f64>().unwrap();
        assert_eq!(number(1), piece["points"][0][0].as_f64().unwrap());
        assert_eq!(number(8), piece["points"][3][1].as_f64().unwrap());
        assert_eq!(number(10), piece["weights"][1].as_f64().unwrap());
        assert_eq!(cells[13], piece["monotone"].as_str().unwrap());
        assert_eq!(cells[14], piece["proven"].to_string());
        assert_eq!(cells[15], "", "no sign change in a monotone piece");
        assert_eq!(number(18), piece["max_deviation"].as_f64().unwrap());
    }
}

#[test]
fn space_csv_has_the_samples_and_with_frames_their_frames() {
    let base = curve_commands()[3].clone();
    let v: Value =
        serde_json::from_str(&stdout(&with(&base, &["--samples", "9", "--frames"]))).unwrap();
    let csv = stdout(&with(
        &base,
        &["--samples", "9", "--frames", "--format", "csv"],
    ));
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "s,x,y,z,kappa,tau,tx,ty,tz,nx,ny,nz,bx,by,bz");
    assert_eq!(lines.len(), 10);
    let samples = v["samples"].as_array().unwrap();
    for (line, sample) in lines[1..].iter().zip(samples) {
        let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let want: Vec<f64> = ["s", "x", "y", "z", "kappa", "tau"]
            .iter()
            .map(|k| sample[*k].as_f64().unwrap())
            .chain(
                ["t", "n", "b"]
                    .iter()
                    .flat_map(|k| (0..3).map(move |i| sample[*k][i].as_f64().unwrap())),
            )
            .collect();
        assert_eq!(cells, want, "CSV and JSON carry the same numbers");
    }
    let plain = stdout(&with(&base, &["--samples", "3", "--format", "csv"]));
    assert!(plain.starts_with("s,x,y,z,kappa,tau\n"));
    // Frames are for the samples' formats only.
    assert_failure(
        &lac(&with(&base, &["--frames", "--format", "obj"])),
        2,
        "usage",
    );
}

#[test]
fn dash_o_dash_is_standard_output_and_dash_o_file_is_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut cases = curve_commands();
    cases.push(vec!["monotone", "--points", "0,0 1.2,0 2,0.4 2.4,1"]);
    cases.push(vec![
        "region", "--alpha", "0.5", "--size", "8", "--format", "json",
    ]);
    for base in cases {
        let plain = stdout(&base);
        assert_eq!(stdout(&with(&base, &["-o", "-"])), plain, "{base:?}");
        assert_eq!(stdout(&with(&base, &["--output", "-"])), plain, "{base:?}");
        let path = dir.path().join(format!("{}.out", base[0]));
        let run = lac(&with(&base, &["-o", path.to_str().unwrap()]));
        assert_eq!(run.code, 0, "{}", run.stderr);
        assert!(run.stdout.is_empty());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), plain, "{base:?}");
    }
    // lac lcg and a batch, too.
    let segment = stdout(&curve_commands()[0]);
    let lcg = lac_with_input(&["lcg", "-o", "-"], segment.as_bytes());
    assert_eq!(
        lcg.stdout,
        lac_with_input(&["lcg"], segment.as_bytes()).stdout
    );
    let line = r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":0.5}"#;
    let batch = lac_with_input(&["segment", "--batch", "-", "-o", "-"], line.as_bytes());
    assert_eq!(batch.code, 0, "{}", batch.stderr);
    assert_eq!(batch.stdout.lines().count(), 1);
    let path = dir.path().join("batch.jsonl");
    let to_file = lac_with_input(
        &["segment", "--batch", "-", "-o", path.to_str().unwrap()],
        line.as_bytes(),
    );
    assert!(to_file.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&path).unwrap(), batch.stdout);
}

#[test]
fn help_documents_every_format_and_the_shared_flags() {
    let cases: [(&str, &[&str]); 7] = [
        (
            "segment",
            &["json", "csv", "svg", "--batch", "--samples", "-o, --output"],
        ),
        (
            "compound",
            &["json", "csv", "svg", "--batch", "--samples", "-o, --output"],
        ),
        (
            "quasi",
            &[
                "json",
                "csv",
                "svg",
                "--batch",
                "--tolerance",
                "-o, --output",
            ],
        ),
        (
            "space",
            &[
                "json",
                "csv",
                "svg",
                "obj",
                "ply",
                "--batch",
                "--samples",
                "-o, --output",
            ],
        ),
        (
            "lcg",
            &["json", "csv", "svg", "png", "--samples", "-o, --output"],
        ),
        (
            "monotone",
            &["--points", "--weights", "--batch", "-o, --output"],
        ),
        (
            "region",
            &["png", "json", "--alpha0", "--size", "-o, --output"],
        ),
    ];
    for (command, words) in cases {
        let help = stdout(&[command, "--help"]);
        for word in words {
            assert!(help.contains(word), "{word} in lac {command} --help");
        }
        // The limits are stated where they apply, and "-" is standard output.
        assert!(
            help.contains("\"-\": standard output") || help.contains("\"-\" or nothing"),
            "lac {command} --help says what -o - means"
        );
    }
    for command in ["segment", "compound", "space", "lcg"] {
        let help = stdout(&[command, "--help"]);
        assert!(
            help.contains("1,000,000"),
            "the --samples limit in lac {command} --help"
        );
    }
    assert!(
        stdout(&["segment", "--help"]).contains("1 MiB"),
        "the batch line limit"
    );
    assert!(
        stdout(&["region", "--help"]).contains("2048"),
        "the --size limit"
    );
    let top = stdout(&["--help"]);
    for word in ["--allow-large", "exit code 2", "70"] {
        assert!(top.contains(word), "{word} in lac --help");
    }
}

#[test]
fn compound_slopes_are_alpha0_and_alpha1_in_every_subcommand() {
    for command in ["compound", "quasi", "region"] {
        let help = stdout(&[command, "--help"]);
        assert!(
            help.contains("--alpha0") && help.contains("--alpha1"),
            "{command}"
        );
    }
    // A segment's slope is --alpha, in every subcommand that draws segments.
    for command in ["segment", "quasi", "region"] {
        assert!(
            stdout(&[command, "--help"]).contains("--alpha <A>"),
            "{command}"
        );
    }
    let quasi = lac(&[
        "quasi",
        "--points",
        "0,0 2,0 2.6,1.2",
        "--alpha",
        "-1",
        "--alpha1",
        "2",
        "--ratio",
        "0.5",
    ]);
    assert_failure(&quasi, 2, "usage");
}
