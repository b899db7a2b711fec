//! The server under concurrent use on a real socket (127.0.0.1 only, a bounded number of
//! requests, each with a read timeout): several clients, valid and invalid requests mixed,
//! every answer checked; the throughput and latencies are printed, not asserted.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::time::{Duration, Instant};

use lac::Curve;
use lac_io::json::SegmentInput;
use serde_json::Value;

const CLIENTS: usize = 8;
const PER_CLIENT: usize = 450;

/// One kind of request: path, body, expected status, and a check of the answer.
struct Case {
    name: &'static str,
    path: &'static str,
    body: String,
    status: u16,
    check: fn(&Value) -> bool,
}

fn cases() -> Vec<Case> {
    let segment = r#"{"points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5,"samples":65}"#;
    vec![
        Case {
            name: "segment",
            path: "/api/segment",
            body: segment.to_string(),
            status: 200,
            check: |v| {
                // The arc length the library gives, bit for bit.
                let input: SegmentInput =
                    serde_json::from_str(r#"{"points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5}"#)
                        .unwrap();
                let length = input.solve().unwrap().arc_length();
                v["arc_length"].as_f64() == Some(length)
                    && v["samples"].as_array().map(Vec::len) == Some(65)
            },
        },
        Case {
            name: "compound4",
            path: "/api/compound",
            body: r#"{"points":[[0,0],[2,0],[3,1],[3.2,2.4]],"alpha0":-1,"alpha1":2}"#.to_string(),
            status: 200,
            check: |v| v["joint_s"].as_f64().is_some_and(|s| s > 0.0),
        },
        Case {
            name: "quasi",
            path: "/api/quasi",
            body: r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-6}"#.to_string(),
            status: 200,
            check: |v| v["pieces"].as_array().is_some_and(|p| !p.is_empty()),
        },
        Case {
            name: "region",
            path: "/api/region",
            body: r#"{"alpha":-1,"size":64}"#.to_string(),
            status: 200,
            check: |v| v["drawable"].as_array().map(Vec::len) == Some(64),
        },
        Case {
            name: "space",
            path: "/api/space",
            body:
                r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":0.3}"#
                    .to_string(),
            status: 200,
            check: |v| v["planar"] == Value::Bool(false),
        },
        Case {
            name: "undrawable",
            path: "/api/segment",
            body: r#"{"points":[[-1,0],[0.9,0.9],[1,0]],"alpha":-1}"#.to_string(),
            status: 422,
            check: |v| v["error"]["kind"] == "not_drawable",
        },
        Case {
            name: "malformed",
            path: "/api/segment",
            body: r#"{"points":[[-1,0],[0.9,0.9],[1,0]],"alpha":"#.to_string(),
            status: 400,
            check: |v| v["error"]["kind"] == "invalid_input",
        },
        Case {
            name: "limit",
            path: "/api/segment",
            body: r#"{"points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5,"samples":99999999}"#
                .to_string(),
            status: 400,
            check: |v| v["error"]["kind"] == "limit",
        },
        Case {
            name: "too large",
            path: "/api/segment",
            body: format!(r#"{{"pad":"{}"}}"#, "x".repeat(80_000)),
            status: 413,
            check: |v| v["error"]["kind"] == "limit",
        },
        Case {
            name: "not found",
            path: "/api/nothing",
            body: "{}".to_string(),
            status: 404,
            check: |v| v["error"]["kind"] == "not_found",
        },
    ]
}

/// Send one request on `stream` (keep-alive) and read the answer: status and JSON body.
fn exchange(stream: &mut BufReader<TcpStream>, case: &Case, close: bool) -> (u16, Value) {
    let request = format!(
        "POST {} HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: {}\r\n{}\r\n{}",
        case.path,
        case.body.len(),
        if close { "Connection: close\r\n" } else { "" },
        case.body
    );
    stream.get_mut().write_all(request.as_bytes()).unwrap();
    let mut line = String::new();
    stream.read_line(&mut line).unwrap();
    let status: u16 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    let mut length = 0;
    loop {
        line.clear();
        stream.read_line(&mut line).unwrap();
        if line == "\r\n" {
            break;
        }
        let lower = line.to_ascii_lowercase();
        if let Some(v) = lower.strip_prefix("content-length:") {
            length = v.trim().parse().unwrap();
        }
    }
    let mut body = vec![0; length];
    stream.read_exact(&mut body).unwrap();
    (status, serde_json::from_slice(&body).unwrap_or(Value::Null))
}

fn connect(addr: SocketAddr) -> BufReader<TcpStream> {
    let stream = TcpStream::connect(addr).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(20)))
        .unwrap();
    stream.set_nodelay(true).unwrap();
    BufReader::new(stream)
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

#[test]
fn thousands_of_mixed_requests_from_several_clients_are_all_answered_correctly() {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap();
    let listener = runtime
        .block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))
        .unwrap();
    let addr = listener.local_addr().unwrap();
    runtime.spawn(lac_serve::serve(listener, lac_serve::Limits::default()));

    let started = Instant::now();
    let clients: Vec<_> = (0..CLIENTS)
        .map(|client| {
            std::thread::spawn(move || {
                let cases = cases();
                let mut stream = connect(addr);
                let mut latencies: Vec<(usize, f64)> = Vec::with_capacity(PER_CLIENT);
                for i in 0..PER_CLIENT {
                    let k = (i * 7 + client * 3) % cases.len();
                    let case = &cases[k];
                    // Oversized bodies get a connection of their own (the server may close
                    // it without reading the rest); every fifth client reconnects each time.
                    let fresh = case.status == 413 || client % 5 == 4;
                    let t = Instant::now();
                    let (status, json) = if fresh {
                        exchange(&mut connect(addr), case, true)
                    } else {
                        exchange(&mut stream, case, false)
                    };
                    latencies.push((k, t.elapsed().as_secs_f64() * 1e3));
                    assert_eq!(status, case.status, "{}: {json}", case.name);
                    assert!((case.check)(&json), "{}: {json}", case.name);
                }
                latencies
            })
        })
        .collect();
    let mut all: Vec<(usize, f64)> = Vec::new();
    for c in clients {
        all.extend(c.join().expect("a client failed"));
    }
    let elapsed = started.elapsed().as_secs_f64();
    let total = all.len();
    assert_eq!(total, CLIENTS * PER_CLIENT);
    println!(
        "{total} requests from {CLIENTS} clients in {elapsed:.2} s: {:.0} requests/s",
        total as f64 / elapsed
    );
    let names: Vec<&str> = cases().iter().map(|c| c.name).collect();
    for (k, name) in names.iter().enumerate() {
        let mut ms: Vec<f64> = all
            .iter()
            .filter(|(c, _)| *c == k)
            .map(|(_, t)| *t)
            .collect();
        ms.sort_by(f64::total_cmp);
        println!(
            "  {name:>11}: {:4} requests, latency median {:6.2} ms, p95 {:6.2} ms, max {:6.2} ms",
            ms.len(),
            percentile(&ms, 0.5),
            percentile(&ms, 0.95),
            ms[ms.len() - 1]
        );
    }
    let mut ms: Vec<f64> = all.iter().map(|(_, t)| *t).collect();
    ms.sort_by(f64::total_cmp);
    println!(
        "  {:>11}: median {:.2} ms, p95 {:.2} ms, p99 {:.2} ms",
        "all",
        percentile(&ms, 0.5),
        percentile(&ms, 0.95),
        percentile(&ms, 0.99)
    );
    // The server still answers a plain request afterwards.
    let (status, json) = exchange(&mut connect(addr), &cases()[0], true);
    assert_eq!(status, 200, "{json}");
}
