//! `lac segment --batch`: one output line per input line, in order.

mod common;

use common::{assert_failure, lac, lac_with_input};
use serde_json::Value;

const GOOD: &str = r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":0.5}"#;
const COLLINEAR: &str = r#"{"points":[[0,0],[1,0],[2,0]],"alpha":0.5}"#;
const MALFORMED: &str = r#"{"points":[[0,0],[1,0]"#;

fn lines(stdout: &str) -> Vec<Value> {
    stdout
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[test]
fn good_bad_and_malformed_lines_give_one_line_each_in_order() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.jsonl");
    std::fs::write(&input, format!("{GOOD}\n{COLLINEAR}\n{MALFORMED}\n")).unwrap();
    let run = lac(&[
        "segment",
        "--batch",
        input.to_str().unwrap(),
        "--samples",
        "5",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let out = lines(&run.stdout);
    assert_eq!(out.len(), 3);
    assert_eq!(out[0]["samples"].as_array().unwrap().len(), 5);
    assert_eq!(out[1]["error"]["kind"], "collinear_points");
    assert_eq!(out[2]["error"]["kind"], "invalid_input");
    // The good line is exactly what single mode prints.
    let single = lac(&[
        "segment",
        "--points",
        "-1,0 0.2,0.8 1,0",
        "--alpha",
        "0.5",
        "--samples",
        "5",
    ]);
    assert_eq!(run.stdout.lines().next(), single.stdout.lines().next());
}

#[test]
fn blank_lines_keep_their_place_and_crlf_is_accepted() {
    let input = format!("{GOOD}\r\n\n   \n{GOOD}");
    let run = lac_with_input(
        &["segment", "--batch", "-", "--samples", "2"],
        input.as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let out = lines(&run.stdout);
    assert_eq!(out.len(), 4);
    assert!(out[0]["lambda"].is_f64() && out[3]["lambda"].is_f64());
    assert_eq!(out[1]["error"]["kind"], "invalid_input");
    assert_eq!(out[2]["error"]["kind"], "invalid_input");
}

#[test]
fn thousands_of_lines_come_back_in_order_with_their_inputs_exactly() {
    let n = 3000;
    // Far from the origin, where a parser that is not correctly rounded loses the last bit.
    let ys: Vec<f64> = (0..n)
        .map(|i| 1e7 + 0.1 + 0.8 * (i as f64 / 2999.0).sqrt())
        .collect();
    let input: String = ys
        .iter()
        .map(|y| format!("{{\"points\":[[-1,1e7],[0.1,{y:?}],[1,1e7]],\"alpha\":-1}}\n"))
        .collect();
    let run = lac_with_input(
        &["segment", "--batch", "-", "--samples", "2"],
        input.as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let out = lines(&run.stdout);
    assert_eq!(out.len(), n);
    for (i, (y, v)) in ys.iter().zip(&out).enumerate() {
        assert_eq!(
            v["points"][1][1].as_f64(),
            Some(*y),
            "line {i}: read back bit for bit"
        );
    }
}

#[test]
fn an_unreadable_batch_file_is_an_io_error() {
    let run = lac(&["segment", "--batch", "/nonexistent/lac/input.jsonl"]);
    assert_failure(&run, 1, "io");
}

#[test]
fn batch_excludes_points_alpha_and_drawing_formats() {
    assert_failure(
        &lac(&["segment", "--batch", "-", "--alpha", "1"]),
        2,
        "usage",
    );
    assert_failure(
        &lac(&["segment", "--batch", "-", "--format", "svg"]),
        2,
        "usage",
    );
}

#[test]
fn compound_batches_mix_three_and_four_point_lines_and_keep_errors_in_place() {
    let lines_in = [
        r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2,"ratio":0.5}"#,
        r#"{"points":[[0,0],[2,0],[2.5,2],[0,1.5]],"alpha0":-1,"alpha1":2}"#,
        r#"{"points":[[0,0],[2,0],[2.5,2],[4,2.2]],"alpha0":0.5,"alpha1":1}"#,
        r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2}"#,
        r#"{"points":[[0,0],[2,0],[2.5,2],[0,1.5]],"alpha0":-1,"alpha1":2,"ratio":0.5}"#,
        r#"{"points":[[-1,0],[0.9,0.9],[1,0]],"alpha0":-1,"alpha1":2,"ratio":0.5}"#,
        r#"{"points":[[0,0],[2,0]],"alpha0":-1,"alpha1":2,"ratio":0.5}"#,
        "",
        r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha":-1}"#,
    ];
    let run = lac_with_input(
        &["compound", "--batch", "-", "--samples", "5"],
        lines_in.join("\n").as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let out = lines(&run.stdout);
    assert_eq!(out.len(), lines_in.len());
    let kinds: Vec<&str> = out
        .iter()
        .map(|v| v["error"]["kind"].as_str().unwrap_or("ok"))
        .collect();
    assert_eq!(
        kinds,
        [
            "ok",
            "ok",
            "inflected_polygon",
            "invalid_input",
            "invalid_input",
            "not_drawable",
            "invalid_input",
            "invalid_input",
            "invalid_input",
        ]
    );
    assert!(out[3]["error"]["message"]
        .as_str()
        .unwrap()
        .contains("three points need \"ratio\""));
    // The good lines are exactly what single mode prints.
    let single = |points: &str, ratio: &[&str]| {
        let mut args = vec![
            "compound",
            "--points",
            points,
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
            "--samples",
            "5",
        ];
        args.extend_from_slice(ratio);
        lac(&args).stdout
    };
    let mut printed = run.stdout.lines();
    assert_eq!(
        printed.next().unwrap(),
        single("0,0 2,0 2.6,1.2", &["--ratio", "0.5"]).trim_end()
    );
    assert_eq!(
        printed.next().unwrap(),
        single("0,0 2,0 2.5,2 0,1.5", &[]).trim_end()
    );
    assert!(out[1].get("ratio").is_none());
}
