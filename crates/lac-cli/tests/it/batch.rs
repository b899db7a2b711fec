//! `--batch` of every solving subcommand: one output line per input line, in order, each
//! bad line answered in its place with its line number, a summary and a non-zero exit code
//! when any line failed, and answers streamed as they are ready.

use crate::common;

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

use common::{assert_failure, lac, lac_with_env, lac_with_input, Run};
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
    let summary = failed_batch(&run, 2, "collinear_points");
    assert!(
        summary.starts_with("2 of 3 lines failed") && summary.contains("line 2: "),
        "{summary}"
    );
    let out = lines(&run.stdout);
    assert_eq!(out.len(), 3);
    assert_eq!(out[0]["samples"].as_array().unwrap().len(), 5);
    assert_eq!(out[1]["error"]["kind"], "collinear_points");
    assert_eq!(out[2]["error"]["kind"], "invalid_input");
    // Each bad line's message starts with its line number, and the column is the column.
    let message = |i: usize| out[i]["error"]["message"].as_str().unwrap().to_string();
    assert!(message(1).starts_with("line 2: "), "{}", message(1));
    assert!(message(2).starts_with("line 3: "), "{}", message(2));
    assert!(!message(2).contains("line 1 column"), "{}", message(2));
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
    failed_batch(&run, 2, "invalid_input");
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

/// Assert that the batch `run` failed with exit code `code`: standard output has the
/// answers, standard error one line `{"error":{"kind":kind,…}}`; return its message.
fn failed_batch(run: &Run, code: i32, kind: &str) -> String {
    assert_eq!(run.code, code, "exit code; stderr: {}", run.stderr);
    assert_eq!(
        run.stderr.lines().count(),
        1,
        "one summary line: {}",
        run.stderr
    );
    let v: Value = serde_json::from_str(&run.stderr).expect("the summary is JSON");
    assert_eq!(v["error"]["kind"], kind, "{v}");
    v["error"]["message"].as_str().unwrap().to_string()
}

#[test]
fn a_batch_whose_first_failure_has_no_curve_exits_3_and_one_without_failures_exits_0() {
    let far = r#"{"points":[[-1,0],[0.9,0.9],[1,0]],"alpha":-1}"#;
    let input = format!("{GOOD}\n{far}\n{COLLINEAR}\n");
    let run = lac_with_input(
        &["segment", "--batch", "-", "--samples", "2"],
        input.as_bytes(),
    );
    let summary = failed_batch(&run, 3, "not_drawable");
    assert!(summary.contains("2 of 3 lines failed"), "{summary}");
    assert!(summary.contains("line 2: "), "{summary}");
    let good = format!("{GOOD}\n{GOOD}\n");
    let run = lac_with_input(
        &["segment", "--batch", "-", "--samples", "2"],
        good.as_bytes(),
    );
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert_eq!(lines(&run.stdout).len(), 2);
    // An empty batch is a batch without failures.
    let run = lac_with_input(&["segment", "--batch", "-"], b"");
    assert_eq!((run.code, run.stdout.as_str()), (0, ""));
}

#[test]
fn a_line_over_the_length_limit_is_answered_in_its_place_and_the_rest_go_on() {
    // 1 MiB a line: a longer one is skipped to its end, not kept.
    let long = format!(
        r#"{{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":0.5,"pad":"{}"}}"#,
        "x".repeat(1 << 20)
    );
    let input = format!("{GOOD}\n{long}\n{GOOD}\n");
    let run = lac_with_input(
        &["segment", "--batch", "-", "--samples", "2"],
        input.as_bytes(),
    );
    failed_batch(&run, 2, "limit");
    let out = lines(&run.stdout);
    assert_eq!(out.len(), 3);
    assert_eq!(out[1]["error"]["kind"], "limit");
    let message = out[1]["error"]["message"].as_str().unwrap();
    assert!(
        message.starts_with("line 2: ") && message.contains("1 MiB"),
        "{message}"
    );
    assert!(out[0]["lambda"].is_f64() && out[2]["lambda"].is_f64());
    // --allow-large takes it.
    let run = lac_with_input(
        &["segment", "--batch", "-", "--samples", "2", "--allow-large"],
        input.as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
}

#[test]
fn answers_stream_out_before_the_input_ends() {
    // Feed one line, wait for its answer, and only then send the next: a batch that held
    // its answers until the end of its input (or of a chunk) would never answer.
    let mut child = Command::new(env!("CARGO_BIN_EXE_lac"))
        .args(["segment", "--batch", "-", "--samples", "3"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let stdout = child.stdout.take().unwrap();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            if tx.send(line.unwrap()).is_err() {
                return;
            }
        }
    });
    for round in 0..3 {
        writeln!(stdin, "{GOOD}").unwrap();
        stdin.flush().unwrap();
        let answer = rx
            .recv_timeout(Duration::from_secs(60))
            .unwrap_or_else(|_| panic!("no answer to line {} before more input", round + 1));
        assert!(answer.starts_with(r#"{"alpha":0.5,"#), "{answer}");
    }
    drop(stdin);
    assert!(child.wait().unwrap().success());
}

#[test]
fn every_solving_subcommand_takes_a_batch() {
    let cases: [(&[&str], &str, &str); 4] = [
        (
            &["quasi", "--batch", "-"],
            r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-6}"#,
            "pieces",
        ),
        (
            &["quasi", "--batch", "-"],
            r#"{"points":[[0,0],[2,0],[2.5,2],[0,1.5]],"alpha0":-1,"alpha1":2,"tolerance":1e-5,"cubic":true}"#,
            "pieces",
        ),
        (
            &["space", "--batch", "-", "--samples", "5"],
            r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":0.3}"#,
            "standard_form",
        ),
        (
            &["monotone", "--batch", "-"],
            r#"{"points":[[0,0],[1.2,0],[2,0.4],[2.4,1]]}"#,
            "verdict",
        ),
    ];
    for (args, good, key) in cases {
        let input = format!("{good}\n{{\"points\":1}}\n\n{good}\n");
        let run = lac_with_input(args, input.as_bytes());
        failed_batch(&run, 2, "invalid_input");
        let out = lines(&run.stdout);
        assert_eq!(out.len(), 4, "{args:?}");
        assert!(
            out[0].get(key).is_some() && out[3].get(key).is_some(),
            "{args:?}: {out:?}"
        );
        assert_eq!(out[0], out[3]);
        for (i, bad) in [(1, &out[1]), (2, &out[2])] {
            let message = bad["error"]["message"].as_str().unwrap();
            assert!(
                message.starts_with(&format!("line {}: ", i + 1)),
                "{message}"
            );
        }
    }
    // The good lines are what the single commands print.
    let single = lac(&[
        "quasi",
        "--points",
        "0,0 3,0 4,1.5",
        "--alpha",
        "-1",
        "--tolerance",
        "1e-6",
    ]);
    let batch = lac_with_input(&["quasi", "--batch", "-"], cases[0].1.as_bytes());
    assert_eq!(batch.code, 0, "{}", batch.stderr);
    assert_eq!(batch.stdout, single.stdout);
    let single = lac(&[
        "space",
        "--points",
        "0,0,0 3,0,0 3,3,1.5 0,3,3",
        "--alpha",
        "0.5",
        "--beta",
        "0",
        "--omega",
        "0.3",
        "--samples",
        "5",
    ]);
    let batch = lac_with_input(
        &["space", "--batch", "-", "--samples", "5"],
        cases[2].1.as_bytes(),
    );
    assert_eq!(batch.stdout, single.stdout);
    // A line of lac quasi output gives a verdict on each of its pieces.
    let quasi = lac(&[
        "quasi",
        "--points",
        "0,0 3,0 4,1.5",
        "--alpha",
        "-1",
        "--tolerance",
        "1e-6",
    ]);
    let run = lac_with_input(&["monotone", "--batch", "-"], quasi.stdout.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    let pieces = lines(&run.stdout)[0]["pieces"].as_array().unwrap().len();
    let want = serde_json::from_str::<Value>(&quasi.stdout).unwrap()["pieces"]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(pieces, want);
}

#[test]
fn a_panic_in_one_line_is_that_lines_internal_error_and_the_batch_exits_70() {
    let input = format!("{GOOD}\n{GOOD}\n{GOOD}\n");
    let run = lac_with_env(
        &["segment", "--batch", "-", "--samples", "2"],
        input.as_bytes(),
        &[("LAC_DEBUG_PANIC", "line 2")],
    );
    let summary = failed_batch(&run, 70, "internal");
    assert!(summary.contains("1 of 3 lines failed"), "{summary}");
    let out = lines(&run.stdout);
    assert_eq!(out.len(), 3);
    assert_eq!(out[1]["error"]["kind"], "internal");
    assert!(out[0]["lambda"].is_f64() && out[2]["lambda"].is_f64());
    assert!(!run.stderr.contains("panicked at"), "{}", run.stderr);
}

#[test]
fn batches_write_json_lines_only_and_take_no_single_curve_arguments() {
    for args in [
        &["quasi", "--batch", "-", "--format", "svg"][..],
        &["quasi", "--batch", "-", "--alpha", "1"],
        &["space", "--batch", "-", "--format", "obj"],
        &["space", "--batch", "-", "--beta", "0"],
        &["monotone", "--batch", "-", "--points", "0,0 1,0 2,1 3,3"],
        &["compound", "--batch", "-", "--format", "csv"],
    ] {
        assert_failure(&lac(args), 2, "usage");
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
    let summary = failed_batch(&run, 2, "inflected_polygon");
    assert!(summary.starts_with("7 of 9 lines failed"), "{summary}");
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
        .contains("three points need a ratio"));
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
