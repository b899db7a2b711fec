//! Claim: whatever body arrives, every endpoint answers 200 with finite JSON or a 4xx with a
//! JSON error body — never a 5xx, never a panic, never a hang.
//!
//! Bodies are valid requests mutated by the seeded generator of `lac-fuzz` (numbers swapped
//! for extreme magnitudes and edge values, leaves for values of the wrong type, keys dropped
//! or added, arrays shortened or lengthened, deep nesting, truncated or corrupted text).
//! `LAC_SERVE_FUZZ_COUNT` changes the count per endpoint.

use crate::common;

use std::time::{Duration, Instant};

use common::send;
use lac_fuzz::Rng;
use serde_json::{json, Map, Value};

fn count() -> u64 {
    std::env::var("LAC_SERVE_FUZZ_COUNT")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000)
}

/// A valid request of each endpoint, the start of every mutation.
fn templates() -> Vec<(&'static str, Value)> {
    vec![
        (
            "/api/segment",
            json!({"points": [[-1, 0], [-0.2, 0.8], [1, 0]], "alpha": 0.5, "samples": 33}),
        ),
        (
            "/api/compound",
            json!({"points": [[0, 0], [2, 0], [2.6, 1.2]], "alpha0": -1, "alpha1": 2, "ratio": 0.5}),
        ),
        (
            "/api/compound",
            json!({"points": [[0, 0], [2, 0], [2.5, 2], [0, 1.5]], "alpha0": -1, "alpha1": 2}),
        ),
        (
            "/api/path",
            json!({"points": [[0, 0], [1.5, 0], [3, 0.8], [6, 3.2], [7.5, 4], [9, 4]],
                   "alpha": -0.5, "g2": true, "samples": 33}),
        ),
        (
            "/api/quasi",
            json!({"points": [[-1, 0], [-0.2, 0.8], [1, 0]], "alpha": 0.5, "tolerance": 1e-4}),
        ),
        (
            "/api/lcg",
            json!({"pieces": [{"points": [[0, 0], [1, 1], [2, 1], [3, 0]],
                               "weights": [1, 1.2, 1.1, 1]}], "samples": 17}),
        ),
        ("/api/region", json!({"alpha": 0.5, "size": 24})),
        (
            "/api/region/point",
            json!({"curve": {"points": [[-1, 0], [-0.2, 0.8], [1, 0]], "alpha": 0.5},
                   "index": 1, "extent": [-2, 2, -2, 2], "size": 24}),
        ),
        (
            "/api/space",
            json!({"points": [[0, 0, 0], [1, 0, 0], [1.5, 0.8, 0.2], [1.6, 1.6, 0.6]],
                   "alpha": 0.5, "beta": 0.5, "omega": 0.1}),
        ),
        (
            "/api/export",
            json!({"points": [[-1, 0], [-0.2, 0.8], [1, 0]], "alpha": 0.5, "format": "step",
                   "tolerance": 1e-4}),
        ),
        (
            "/api/export",
            json!({"points": [[0, 0], [3, 0], [4, 2], [2, 4], [-1, 2]], "alpha": 0.5,
                   "closed": true, "g2": true, "format": "dxf", "relative_tolerance": 1e-5}),
        ),
    ]
}

/// A number chosen to hurt: edge values, extreme magnitudes, or an ordinary one.
fn number(rng: &mut Rng) -> Value {
    match rng.below(8) {
        0 => json!(rng.pick(&[0.0, -0.0, 1e308, -1e308, 5e-324, 1e-300, 2.0f64.powi(53)])),
        1 => json!(rng.pick(&[u64::MAX, 1 << 40, 0])),
        2 => json!(rng.pick(&[-1i64, i64::MIN])),
        3 => json!(rng.log_uniform(-300.0, 300.0)),
        _ => json!(rng.number()),
    }
}

/// A value of some type, to stand where another type belongs.
fn wrong_type(rng: &mut Rng) -> Value {
    match rng.below(7) {
        0 => Value::Null,
        1 => json!(rng.chance(0.5)),
        2 => json!(rng.pick(&["", "NaN", "inf", "1e999", "-0", "0x10", "ναι"])),
        3 => json!([]),
        4 => json!({}),
        5 => json!([[1, 2], [3]]),
        _ => number(rng),
    }
}

/// One random change somewhere inside `v`.
fn mutate(v: &mut Value, rng: &mut Rng, depth: usize) {
    let descend = depth < 6 && rng.chance(0.7);
    match v {
        Value::Object(map) if descend && !map.is_empty() => {
            let key = map.keys().nth(rng.below(map.len())).cloned().unwrap();
            match rng.below(6) {
                0 => {
                    map.remove(&key);
                }
                1 => {
                    map.insert(format!("extra{}", rng.below(3)), wrong_type(rng));
                }
                _ => mutate(map.get_mut(&key).unwrap(), rng, depth + 1),
            }
        }
        Value::Array(items) if descend && !items.is_empty() => match rng.below(6) {
            0 => {
                items.pop();
            }
            1 => {
                let copy = items[rng.below(items.len())].clone();
                items.push(copy);
            }
            _ => {
                let i = rng.below(items.len());
                mutate(&mut items[i], rng, depth + 1);
            }
        },
        Value::Number(_) if rng.chance(0.7) => *v = number(rng),
        _ => {
            *v = match rng.below(4) {
                0 => {
                    // Deep nesting around the old value.
                    let mut nested = v.take();
                    for _ in 0..rng.below(200) {
                        nested = Value::Array(vec![nested]);
                    }
                    nested
                }
                1 => Value::Object(Map::new()),
                _ => wrong_type(rng),
            }
        }
    }
}

/// The body: the mutated document, sometimes truncated or with a byte corrupted (not
/// always UTF-8 then).
fn body(template: &Value, rng: &mut Rng) -> Vec<u8> {
    let mut doc = template.clone();
    for _ in 0..1 + rng.below(3) {
        mutate(&mut doc, rng, 0);
    }
    let mut bytes = doc.to_string().into_bytes();
    match rng.below(10) {
        0 => bytes.truncate(rng.below(bytes.len() + 1)),
        1 => {
            let i = rng.below(bytes.len().max(1));
            if let Some(b) = bytes.get_mut(i) {
                *b = rng.pick(b"{}[],:\"\\0e-.9 \x00\xff");
            }
        }
        _ => {}
    }
    bytes
}

/// True when a JSON value holds a number that is not finite (serde_json cannot hold NaN, so
/// this catches the `null`s a non-finite float would have become only where none belongs).
fn all_finite(v: &Value) -> bool {
    match v {
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(items) => items.iter().all(all_finite),
        Value::Object(map) => map.values().all(all_finite),
        _ => true,
    }
}

#[tokio::test]
async fn mutated_requests_get_an_answer_or_a_json_4xx_never_a_5xx_or_a_hang() {
    let app = lac_serve::router();
    let mut failures = Vec::new();
    let mut answered = 0;
    let mut refused = 0;
    for (t, (path, template)) in templates().iter().enumerate() {
        for index in 0..count() {
            let mut rng = Rng::new(20261123 + t as u64, index);
            let bytes = body(template, &mut rng);
            let start = Instant::now();
            let answer = send(&app, "POST", path, Some("application/json"), bytes.clone()).await;
            let elapsed = start.elapsed();
            let status = answer.status.as_u16();
            let ok = match status {
                200 => {
                    answered += 1;
                    all_finite(&answer.json)
                }
                400..=499 => {
                    refused += 1;
                    answer.json["error"]["kind"].is_string()
                        && answer.json["error"]["message"].is_string()
                }
                _ => false,
            };
            // A hang detector, not a timing claim (the machine is shared).
            if !ok || elapsed > Duration::from_secs(10) {
                failures.push(format!(
                    "{path} {status} in {elapsed:?}: {}\n  body: {}",
                    answer.text.chars().take(300).collect::<String>(),
                    String::from_utf8_lossy(&bytes)
                ));
            }
        }
    }
    eprintln!("{answered} answered, {refused} refused");
    assert!(answered > 0 && refused > 0);
    assert!(
        failures.is_empty(),
        "{} bad answers:\n{}",
        failures.len(),
        failures[..failures.len().min(5)].join("\n")
    );
}
