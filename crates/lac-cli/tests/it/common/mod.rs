//! Running the built `lac` binary from integration tests.

#![allow(dead_code)] // each test file uses its own subset

use std::io::Write;
use std::process::{Command, Stdio};

/// What a run of `lac` produced.
pub(crate) struct Run {
    pub(crate) code: i32,
    pub(crate) stdout: String,
    pub(crate) stdout_bytes: Vec<u8>,
    pub(crate) stderr: String,
}

/// Run `lac` with `args` and standard input `stdin`.
pub(crate) fn lac_with_input(args: &[&str], stdin: &[u8]) -> Run {
    lac_with_env(args, stdin, &[])
}

/// Run `lac` with `args`, standard input `stdin` and the environment variables `env`.
pub(crate) fn lac_with_env(args: &[&str], stdin: &[u8], env: &[(&str, &str)]) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lac"))
        .args(args)
        .envs(env.iter().copied())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the lac binary runs");
    // Feed standard input from another thread: lac writes while it reads, and a full
    // stdout pipe would otherwise block both sides.
    let mut pipe = child.stdin.take().unwrap();
    let input = stdin.to_vec();
    let feeder = std::thread::spawn(move || pipe.write_all(&input));
    let out = child.wait_with_output().unwrap();
    // lac may exit before reading its input (a usage error): a broken pipe is its answer.
    match feeder.join().unwrap() {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {}
        other => other.unwrap(),
    }
    Run {
        code: out.status.code().expect("lac exits normally"),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stdout_bytes: out.stdout,
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Run `lac` with `args` and empty standard input.
pub(crate) fn lac(args: &[&str]) -> Run {
    lac_with_input(args, b"")
}

/// The number `v` (the test fails when it is not one).
pub(crate) fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

/// Standard output as JSON.
pub(crate) fn json(run: &Run) -> serde_json::Value {
    serde_json::from_str(&run.stdout)
        .unwrap_or_else(|e| panic!("stdout is not JSON ({e}): {}", run.stdout))
}

/// Assert that the run failed with `code`, nothing on standard output, and exactly one line
/// `{"error":{"kind":kind,"message":…}}` on standard error; return the message.
pub(crate) fn assert_failure(run: &Run, code: i32, kind: &str) -> String {
    assert_eq!(run.code, code, "exit code; stderr: {}", run.stderr);
    assert!(
        run.stdout.is_empty(),
        "stdout should be empty: {}",
        run.stdout
    );
    assert_eq!(
        run.stderr.lines().count(),
        1,
        "one line on stderr: {:?}",
        run.stderr
    );
    assert!(run.stderr.ends_with('\n'));
    let v: serde_json::Value = serde_json::from_str(&run.stderr).expect("stderr is JSON");
    let obj = v.as_object().unwrap();
    assert_eq!(obj.len(), 1, "only the error key: {v}");
    assert_eq!(v["error"]["kind"], kind, "{v}");
    let message = v["error"]["message"]
        .as_str()
        .expect("a message")
        .to_string();
    assert!(!message.is_empty());
    message
}

/// Assert that `text` names `keys` (each as `"key":`), first occurrences in this order, and
/// that `v` has exactly these keys.
pub(crate) fn assert_keys(text: &str, v: &serde_json::Value, keys: &[&str]) {
    let at: Vec<usize> = keys
        .iter()
        .map(|k| {
            text.find(&format!("\"{k}\":"))
                .unwrap_or_else(|| panic!("{k} in {text}"))
        })
        .collect();
    assert!(
        at.windows(2).all(|w| w[0] < w[1]),
        "{keys:?} in order: {text}"
    );
    let mut have: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    let mut want = keys.to_vec();
    have.sort_unstable();
    want.sort_unstable();
    assert_eq!(have, want);
}
