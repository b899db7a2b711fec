//! `lac serve`: it prints the URL it serves on loopback, answers there, and refuses other
//! addresses without --allow-remote.

use crate::common;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Command, Stdio};
use std::time::Duration;

use common::lac;

#[test]
fn a_non_loopback_host_needs_allow_remote() {
    let run = lac(&["serve", "--host", "0.0.0.0", "--port", "0"]);
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(
        run.stderr.starts_with(r#"{"error":{"kind":"usage""#),
        "{}",
        run.stderr
    );
    assert!(run.stderr.contains("--allow-remote"), "{}", run.stderr);
}

#[test]
fn it_prints_its_url_and_serves_the_page_and_the_api_there() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lac"))
        .args(["serve", "--port", "0"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("lac serve starts");
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let url = line
        .split_whitespace()
        .find(|w| w.starts_with("http://127.0.0.1:"))
        .unwrap_or_else(|| panic!("no URL in {line:?}"))
        .to_string();
    let addr = url.trim_start_matches("http://").trim_end_matches('/');
    let ask = |request: &str| {
        let mut stream = TcpStream::connect(addr).unwrap();
        stream
            .set_read_timeout(Some(Duration::from_secs(10)))
            .unwrap();
        stream.write_all(request.as_bytes()).unwrap();
        let mut answer = String::new();
        stream.read_to_string(&mut answer).unwrap();
        answer
    };
    let page = ask("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    let body = r#"{"points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5,"samples":3}"#;
    let api = ask(&format!(
        "POST /api/segment HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    ));
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(page.starts_with("HTTP/1.1 200"), "{page}");
    assert!(page.contains("<title>lac"), "{page}");
    assert!(api.starts_with("HTTP/1.1 200"), "{api}");
    assert!(api.contains(r#""arc_length":2.16196069304536"#), "{api}");
}

/// Issue 35: `--open` without a display says that no browser could be opened, beside the URL.
#[test]
fn open_without_a_display_says_that_no_browser_was_opened() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lac"))
        .args(["serve", "--port", "0", "--open"])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("lac serve starts");
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    assert!(line.contains("http://127.0.0.1:"), "{line:?}");
    let mut message = String::new();
    BufReader::new(child.stderr.take().unwrap())
        .read_line(&mut message)
        .unwrap();
    child.kill().unwrap();
    let _ = child.wait();
    assert!(
        message.contains("could not open a browser") && message.contains("no display"),
        "{message:?}"
    );
}
