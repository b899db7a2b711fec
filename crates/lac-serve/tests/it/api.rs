//! The API without a socket (tower's `oneshot`): every endpoint answers what the library
//! gives, bit for bit; every bad request is a 4xx with a JSON error body; nothing is a 5xx.

use crate::common;

use std::time::Duration;

use axum::http::StatusCode;
use common::{post, send};
use lac::Curve;
use lac_io::json::{
    CompoundInput, CompoundReport, LcgReport, PathInput, PathReport, SegmentInput, SegmentReport,
    SpaceInput, SpaceReport,
};
use serde_json::Value;

fn app() -> axum::Router {
    lac_serve::router()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[tokio::test]
async fn a_segment_answer_is_the_library_report_bit_for_bit_with_its_plot() {
    // Awkward decimals: they must reach the solver and come back exactly.
    let body = r#"{"points":[[-1,0],[-0.30000000000000004,0.8000000000000002],[1e-7,1e-300]],"alpha":0.1,"samples":17}"#;
    let answer = post(&app(), "/api/segment", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    assert_eq!(answer.content_type, "application/json");
    let input: SegmentInput = serde_json::from_str(body).unwrap();
    let segment = input.solve().unwrap();
    let report = SegmentReport::new(&segment, 17)
        .unwrap()
        .with_points(input.points);
    let expected = serde_json::to_value(&report).unwrap();
    for key in [
        "alpha",
        "lambda",
        "arc_length",
        "curvature_start",
        "curvature_end",
        "points",
        "samples",
    ] {
        assert_eq!(answer.json[key], expected[key], "{key}");
    }
    assert_eq!(f(&answer.json["points"][1][0]), -0.30000000000000004);
    assert_eq!(f(&answer.json["points"][2][1]), 1e-300);
    let plot = LcgReport::new(&segment.curvature_plot(17).unwrap());
    assert_eq!(answer.json["plot"], serde_json::to_value(&plot).unwrap());
    assert!((f(&answer.json["plot"]["fit"]["alpha"]) - 0.1).abs() < 1e-9);
}

#[tokio::test]
async fn compound_curves_from_three_points_and_a_ratio_or_from_four_points() {
    for body in [
        r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2,"ratio":0.5}"#,
        r#"{"points":[[0,0],[2,0],[2.5,2],[0,1.5]],"alpha0":-1,"alpha1":2,"samples":33}"#,
    ] {
        let answer = post(&app(), "/api/compound", body).await;
        assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
        let input: CompoundInput = serde_json::from_str(body).unwrap();
        let curve = input.solve().unwrap();
        let n = answer.json["samples"].as_array().unwrap().len();
        let report = serde_json::to_value(CompoundReport::new(&curve, &input, n).unwrap()).unwrap();
        for key in [
            "arc_length",
            "joint_s",
            "joint",
            "lcg",
            "samples",
            "curvature_joint",
        ] {
            assert_eq!(answer.json[key], report[key], "{key}");
        }
        assert_eq!(answer.json["plot"]["points"].as_array().unwrap().len(), n);
    }
    let missing = post(
        &app(),
        "/api/compound",
        r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2}"#,
    )
    .await;
    assert_eq!(missing.status, StatusCode::BAD_REQUEST);
    assert!(missing.message().contains("ratio"), "{}", missing.text);
}

#[tokio::test]
async fn undrawable_input_is_422_with_what_to_move() {
    let answer = post(
        &app(),
        "/api/segment",
        r#"{"points":[[-1,0],[0.9,0.9],[1,0]],"alpha":-1}"#,
    )
    .await;
    assert_eq!(answer.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(answer.kind(), "not_drawable");
    assert!(
        answer.message().contains("move the middle control point"),
        "{}",
        answer.text
    );
    // Collinear points are the request's fault: 400, with the library's advice.
    let line = post(
        &app(),
        "/api/segment",
        r#"{"points":[[0,0],[1,0],[2,0]],"alpha":0.5}"#,
    )
    .await;
    assert_eq!(line.status, StatusCode::BAD_REQUEST);
    assert_eq!(line.kind(), "collinear_points");
}

#[tokio::test]
async fn malformed_requests_are_400_with_a_json_error_that_names_the_shape() {
    let cases: &[(&str, &str, &str)] = &[
        ("/api/segment", "{", "EOF"),
        ("/api/segment", "", "empty"),
        ("/api/segment", "[1,2,3]", "expected"),
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":"half"}"#,
            "invalid type",
        ),
        ("/api/segment", r#"{"points":[[0,0],[1,1],[2,0]]}"#, "alpha"),
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1]],"alpha":0.5}"#,
            "expected",
        ),
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":1e999}"#,
            "number",
        ),
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":0.5,"samples":-3}"#,
            "invalid value",
        ),
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":0.5,"samples":2.5}"#,
            "invalid type",
        ),
        ("/api/quasi", r#"{"points":[[0,0],[1,1],[2,0]]}"#, "alpha"),
        (
            "/api/quasi",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":0.5,"tolerance":"small"}"#,
            "tolerance",
        ),
        ("/api/lcg", r#"{"pieces":[]}"#, "no pieces"),
        ("/api/lcg", r#"{"pieces":[{"points":[[0,0]]}]}"#, "expected"),
        ("/api/region", r#"{"alpha":0.5,"alpha1":2}"#, "both"),
        ("/api/region", r#"{"size":4}"#, "alpha"),
        (
            "/api/region/point",
            r#"{"curve":[1],"index":0,"extent":[0,1,0,1]}"#,
            "curve",
        ),
        (
            "/api/region/point",
            r#"{"curve":{"points":[[0,0],[1,1],[2,0]],"alpha":0.5},"index":7,"extent":[0,1,0,1]}"#,
            "index 7",
        ),
        (
            "/api/region/point",
            r#"{"curve":{"points":[[0,0],[1,1],[2,0]],"alpha":0.5},"index":1,"extent":[1,0,0,1]}"#,
            "extent",
        ),
        (
            "/api/space",
            r#"{"points":[[0,0,0],[1,0,0],[1,1,1],[0,1,2]],"alpha":0.5,"beta":0,"type":3}"#,
            "type",
        ),
    ];
    for (path, body, needle) in cases {
        let answer = post(&app(), path, body).await;
        assert_eq!(
            answer.status,
            StatusCode::BAD_REQUEST,
            "{path} {body}: {}",
            answer.text
        );
        assert!(
            answer.message().contains(needle),
            "{path} {body}: {} lacks {needle:?}",
            answer.text
        );
    }
    let not_utf8 = send(
        &app(),
        "POST",
        "/api/segment",
        Some("application/json"),
        vec![b'{', 0xff, b'}'],
    )
    .await;
    assert_eq!(
        (not_utf8.status, not_utf8.kind()),
        (StatusCode::BAD_REQUEST, "invalid_input")
    );
}

#[tokio::test]
async fn bodies_over_the_limit_and_bodies_not_json_are_refused() {
    let big = format!(
        r#"{{"points":[[0,0],[1,1],[2,0]],"alpha":0.5,"pad":"{}"}}"#,
        "x".repeat(70_000)
    );
    let answer = post(&app(), "/api/segment", &big).await;
    assert_eq!(answer.status, StatusCode::PAYLOAD_TOO_LARGE);
    assert_eq!(answer.kind(), "limit");
    let form = send(
        &app(),
        "POST",
        "/api/segment",
        Some("text/plain"),
        b"{}".to_vec(),
    )
    .await;
    assert_eq!(form.status, StatusCode::UNSUPPORTED_MEDIA_TYPE);
    let none = send(&app(), "POST", "/api/segment", None, b"{}".to_vec()).await;
    assert_eq!(none.status, StatusCode::UNSUPPORTED_MEDIA_TYPE);
    assert!(none.message().contains("application/json"));
    let charset = send(
        &app(),
        "POST",
        "/api/segment",
        Some("application/json; charset=utf-8"),
        br#"{"points":[[0,0],[1,1],[2,0]],"alpha":0.5}"#.to_vec(),
    )
    .await;
    assert_eq!(charset.status, StatusCode::OK);
}

#[tokio::test]
async fn absurd_sample_counts_and_map_sizes_are_limits_not_work() {
    let cases = [
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":0.5,"samples":100000000}"#,
        ),
        (
            "/api/segment",
            r#"{"points":[[0,0],[1,1],[2,0]],"alpha":0.5,"samples":1}"#,
        ),
        (
            "/api/compound",
            r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2,"ratio":0.5,"samples":18446744073709551615}"#,
        ),
        ("/api/region", r#"{"alpha":0.5,"size":100000}"#),
        ("/api/region", r#"{"alpha":0.5,"size":0}"#),
        (
            "/api/region/point",
            r#"{"curve":{"points":[[0,0],[1,1],[2,0]],"alpha":0.5},"index":1,"extent":[0,1,0,1],"size":5000}"#,
        ),
        (
            "/api/space",
            r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"samples":1000000}"#,
        ),
    ];
    for (path, body) in cases {
        let answer = post(&app(), path, body).await;
        assert_eq!(
            answer.status,
            StatusCode::BAD_REQUEST,
            "{path} {body}: {}",
            answer.text
        );
        assert!(
            ["limit", "invalid_input"].contains(&answer.kind()),
            "{}",
            answer.text
        );
    }
    let pieces: Vec<String> = (0..400)
        .map(|i| format!(r#"{{"points":[[{i},0],[{i}.3,0.2],[{i}.6,0.2],[{i}.9,0]]}}"#))
        .collect();
    let body = format!(r#"{{"pieces":[{}],"samples":1000}}"#, pieces.join(","));
    let answer = post(&app(), "/api/lcg", &body).await;
    assert_eq!(
        (answer.status, answer.kind()),
        (StatusCode::BAD_REQUEST, "limit"),
        "{}",
        answer.text
    );
}

#[tokio::test]
async fn the_canonical_region_is_the_library_map_and_is_cached() {
    let app = app();
    let first = post(&app, "/api/region", r#"{"alpha":-1,"size":24}"#).await;
    assert_eq!(first.status, StatusCode::OK, "{}", first.text);
    let rows = first.json["drawable"].as_array().unwrap();
    assert_eq!(rows.len(), 24);
    for (r, row) in rows.iter().enumerate() {
        let expected: Vec<Value> = lac::region::row(-1.0, 24, r)
            .into_iter()
            .map(Value::Bool)
            .collect();
        assert_eq!(row.as_array().unwrap(), &expected, "row {r}");
    }
    let fraction = f(&first.json["drawable_fraction"]);
    assert!(fraction > 0.1 && fraction < 0.9, "{fraction}");
    let again = post(&app, "/api/region", r#"{"alpha":-1,"size":24}"#).await;
    assert_eq!(again.text, first.text);
    let compound = post(
        &app,
        "/api/region",
        r#"{"alpha":-1,"alpha1":2,"ratio":0.5,"size":8}"#,
    )
    .await;
    assert_eq!(compound.status, StatusCode::OK);
    let expected: Vec<Value> = lac::region::compound_row(-1.0, 2.0, 0.5, 8, 3)
        .into_iter()
        .map(Value::Bool)
        .collect();
    assert_eq!(compound.json["drawable"][3].as_array().unwrap(), &expected);
}

#[tokio::test]
async fn a_point_region_says_where_the_four_point_curve_solves() {
    let body = r#"{"curve":{"points":[[0,0],[2,0],[3,1],[3.2,2.4]],"alpha0":-1,"alpha1":2},"index":2,"extent":[0,4,-1,3],"size":20}"#;
    let answer = post(&app(), "/api/region/point", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let rows = answer.json["drawable"].as_array().unwrap();
    let mut seen = [0, 0];
    for (r, row) in rows.iter().enumerate() {
        for (c, cell) in row.as_array().unwrap().iter().enumerate() {
            let x = 0.0 + (c as f64 + 0.5) * 4.0 / 20.0;
            let y = 3.0 - (r as f64 + 0.5) * 4.0 / 20.0;
            let p =
                [(0.0, 0.0), (2.0, 0.0), (x, y), (3.2, 2.4)].map(|(x, y)| kurbo::Point::new(x, y));
            let solves = lac::CompoundCurve::from_four_points(p, -1.0, 2.0).is_ok();
            assert_eq!(cell.as_bool(), Some(solves), "pixel {r},{c} at ({x}, {y})");
            seen[usize::from(solves)] += 1;
        }
    }
    assert!(seen[0] > 0 && seen[1] > 0, "{seen:?}");
}

#[tokio::test]
async fn quasi_pieces_meet_the_tolerance_and_carry_their_verdicts_and_samples() {
    let body = r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-6,"samples":9}"#;
    let answer = post(&app(), "/api/quasi", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let j = &answer.json;
    let length = f(&j["arc_length"]);
    let pieces = j["pieces"].as_array().unwrap();
    assert!(pieces.len() >= 2);
    for p in pieces {
        assert!(
            f(&p["max_deviation"]) <= 1e-6 * length * (1.0 + 1e-9),
            "{p}"
        );
        assert_eq!(p["monotone"], "increasing");
        assert_eq!(p["proven"], true);
    }
    let samples = j["piece_samples"].as_array().unwrap();
    assert_eq!(samples.len(), pieces.len());
    // Each piece's samples start and end at its control points b0 and b3.
    for (rows, p) in samples.iter().zip(pieces) {
        let rows = rows.as_array().unwrap();
        let (a, b) = (&rows[0], &rows[rows.len() - 1]);
        assert!((f(&a["x"]) - f(&p["points"][0][0])).abs() < 1e-12);
        assert!((f(&b["y"]) - f(&p["points"][3][1])).abs() < 1e-12);
    }
    assert_eq!(j["curve"]["samples"].as_array().unwrap().len(), 9);
    assert!((f(&j["curve"]["plot"]["fit"]["alpha"]) + 1.0).abs() < 1e-9);
    assert!((f(&j["piece_plot"]["fit"]["alpha"]) + 1.0).abs() < 0.05);
    let fails = post(
        &app(),
        "/api/quasi",
        r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-20}"#,
    )
    .await;
    assert_eq!(fails.status, StatusCode::BAD_REQUEST, "{}", fails.text);
}

#[tokio::test]
async fn lcg_of_pieces_and_of_curves() {
    let pieces = post(
        &app(),
        "/api/lcg",
        r#"{"pieces":[{"points":[[0,0],[1,0],[2,0.5],[2.5,1.5]]}],"samples":16}"#,
    )
    .await;
    assert_eq!(pieces.status, StatusCode::OK, "{}", pieces.text);
    assert_eq!(pieces.json["points"].as_array().unwrap().len(), 16);
    let curve = post(
        &app(),
        "/api/lcg",
        r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2,"ratio":0.5,"samples":40}"#,
    )
    .await;
    assert_eq!(curve.status, StatusCode::OK, "{}", curve.text);
    assert_eq!(curve.json["points"].as_array().unwrap().len(), 40);
}

#[tokio::test]
async fn a_space_answer_is_lac_space_with_frames_and_both_graphs() {
    let body = r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":0.3,"samples":11}"#;
    let answer = post(&app(), "/api/space", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let input: SpaceInput = serde_json::from_str(body).unwrap();
    let report =
        serde_json::to_value(SpaceReport::new(&input.solve().unwrap(), 11, true).unwrap()).unwrap();
    for key in [
        "standard_form",
        "transform",
        "arc_length",
        "planar",
        "samples",
    ] {
        assert_eq!(answer.json[key], report[key], "{key}");
    }
    let lcg = answer.json["graphs"]["curvature"].as_array().unwrap();
    let slope = (f(&lcg[10]["y"]) - f(&lcg[0]["y"])) / (f(&lcg[10]["x"]) - f(&lcg[0]["x"]));
    assert!((slope - 0.5).abs() < 1e-9, "{slope}");
    let too_much = post(
        &app(),
        "/api/space",
        r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":30}"#,
    )
    .await;
    assert_eq!(too_much.status, StatusCode::UNPROCESSABLE_ENTITY);
    let omega_max = f(&too_much.json["error"]["omega_max"]);
    assert!(omega_max > 0.3 && omega_max < 30.0, "{omega_max}");
}

#[tokio::test]
async fn the_page_and_its_files_are_served_with_a_strict_policy_and_others_are_json_404() {
    let page = send(&app(), "GET", "/", None, vec![]).await;
    assert_eq!(page.status, StatusCode::OK);
    assert!(page.content_type.starts_with("text/html"));
    assert!(page
        .text
        .contains(r#"<script type="module" src="/app/main.js">"#));
    for (file, kind) in [
        ("main.js", "text/javascript"),
        ("style.css", "text/css"),
        ("space.js", "text/javascript"),
        ("modes/index.js", "text/javascript"),
        ("modes/segment.js", "text/javascript"),
    ] {
        let answer = send(&app(), "GET", &format!("/app/{file}"), None, vec![]).await;
        assert_eq!(answer.status, StatusCode::OK, "{file}");
        assert!(
            answer.content_type.starts_with(kind),
            "{file}: {}",
            answer.content_type
        );
    }
    let missing = send(&app(), "GET", "/app/../Cargo.toml", None, vec![]).await;
    assert!(missing.status.is_client_error());
    let nothing = send(&app(), "GET", "/nothing", None, vec![]).await;
    assert_eq!(
        (nothing.status, nothing.kind()),
        (StatusCode::NOT_FOUND, "not_found")
    );
    let get = send(&app(), "GET", "/api/segment", None, vec![]).await;
    assert_eq!(
        (get.status, get.kind()),
        (StatusCode::METHOD_NOT_ALLOWED, "method_not_allowed")
    );
    let version = send(&app(), "GET", "/api/version", None, vec![]).await;
    assert_eq!(version.json["limits"]["body_bytes"], 65536);
}

#[tokio::test]
async fn a_request_past_the_timeout_is_503_json() {
    let app = lac_serve::router_with(lac_serve::Limits {
        timeout: Duration::ZERO,
        ..lac_serve::Limits::default()
    });
    let answer = post(&app, "/api/region", r#"{"alpha":0.25,"size":200}"#).await;
    assert_eq!(
        answer.status,
        StatusCode::SERVICE_UNAVAILABLE,
        "{}",
        answer.text
    );
    assert_eq!(answer.kind(), "timeout");
}

#[test]
fn only_loopback_without_allow_remote() {
    use std::net::IpAddr;
    let any: IpAddr = "0.0.0.0".parse().unwrap();
    let err = lac_serve::check_bind(any, false).unwrap_err();
    assert!(err.message.contains("--allow-remote"));
    assert!(lac_serve::check_bind(any, true).is_ok());
    for ip in ["127.0.0.1", "::1", "127.0.0.2"] {
        assert!(
            lac_serve::check_bind(ip.parse().unwrap(), false).is_ok(),
            "{ip}"
        );
    }
}

/// A tiny deterministic generator (xorshift), so the fuzz below needs no crate.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

#[tokio::test]
async fn mangled_requests_get_json_answers_and_no_5xx_of_the_server() {
    let valid = [
        (
            "/api/segment",
            r#"{"points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5,"samples":9}"#,
        ),
        (
            "/api/compound",
            r#"{"points":[[0,0],[2,0],[2.5,2],[0,1.5]],"alpha0":-1,"alpha1":2,"samples":9}"#,
        ),
        (
            "/api/quasi",
            r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-4,"samples":9}"#,
        ),
        (
            "/api/region",
            r#"{"alpha":-1,"alpha1":2,"ratio":0.5,"size":6}"#,
        ),
        (
            "/api/region/point",
            r#"{"curve":{"points":[[0,0],[2,0],[3,1],[3.2,2.4]],"alpha0":-1,"alpha1":2},"index":2,"extent":[0,4,-1,3],"size":6}"#,
        ),
        (
            "/api/lcg",
            r#"{"pieces":[{"points":[[0,0],[1,0],[2,0.5],[2.5,1.5]],"weights":[1,2,2,1]}],"samples":9}"#,
        ),
        (
            "/api/space",
            r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":0.3,"samples":9}"#,
        ),
    ];
    let replacements: [&[u8]; 12] = [
        b"0",
        b"-1",
        b"1e308",
        b"-0",
        b"null",
        b"\"x\"",
        b"[]",
        b"{}",
        b"1e-320",
        b"2",
        b"99999999999",
        b"0.5",
    ];
    let app = app();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut counts = std::collections::BTreeMap::new();
    for round in 0..700 {
        let (path, body) = valid[round % valid.len()];
        let mut bytes = body.as_bytes().to_vec();
        if rng.next() % 4 == 0 {
            // Break the syntax: delete or insert a byte.
            let at = (rng.next() as usize) % bytes.len();
            if rng.next() % 2 == 0 {
                bytes.remove(at);
            } else {
                bytes.insert(at, b"[]{},:\"0-e."[(rng.next() % 11) as usize]);
            }
        } else {
            // Keep the syntax, change a value: replace one number by another value.
            let numbers = number_spans(&bytes);
            let (a, b) = numbers[(rng.next() as usize) % numbers.len()];
            let with = replacements[(rng.next() as usize) % replacements.len()];
            bytes.splice(a..b, with.iter().copied());
        }
        let answer = send(&app, "POST", path, Some("application/json"), bytes.clone()).await;
        // A 500 is allowed only as the library's own typed verdict `numerical_failure`
        // (coordinates near 1e308 overflow inside it); `internal` would be this server's
        // defect (a panic, a non-finite report).
        let library_verdict = answer.status == StatusCode::INTERNAL_SERVER_ERROR
            && answer.json["error"]["kind"] == "numerical_failure";
        assert!(
            answer.status.is_success() || answer.status.is_client_error() || library_verdict,
            "{path} {} answered {}: {}",
            String::from_utf8_lossy(&bytes),
            answer.status,
            answer.text
        );
        if !answer.status.is_success() {
            assert!(
                answer.json["error"]["message"].is_string(),
                "{}",
                answer.text
            );
        }
        *counts.entry(answer.status.as_u16()).or_insert(0) += 1;
    }
    println!("mangled requests by status: {counts:?}");
    for status in [200, 400, 422] {
        assert!(
            counts.contains_key(&status),
            "the mangling should reach {status}: {counts:?}"
        );
    }
}

/// The byte ranges of the numbers in a JSON text.
fn number_spans(text: &[u8]) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut i = 0;
    while i < text.len() {
        if text[i] == b'-' || text[i].is_ascii_digit() {
            let start = i;
            while i < text.len() && (text[i].is_ascii_digit() || b"-+.eE".contains(&text[i])) {
                i += 1;
            }
            spans.push((start, i));
        } else {
            i += 1;
        }
    }
    spans
}

/// The header `name` of `answer` as text.
fn header<'a>(answer: &'a common::Answer, name: &str) -> &'a str {
    answer
        .headers
        .get(name)
        .unwrap_or_else(|| panic!("no {name} header"))
        .to_str()
        .unwrap()
}

#[tokio::test]
async fn export_answers_the_cad_file_with_its_type_name_and_report() {
    // The page's own bodies (with its "samples", ignored) plus a format and a tolerance.
    let cases = [
        (
            r#"{"points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5,"samples":201,"format":"step"}"#,
            "model/step",
            "lac-curve.step",
            "ISO-10303-21;",
            "segment",
        ),
        (
            r#"{"points":[[0,0],[2,0],[2.6,1.2]],"alpha0":-1,"alpha1":2,"ratio":0.5,"format":"dxf","tolerance":1e-8,"name":"valley"}"#,
            "image/vnd.dxf",
            "valley.dxf",
            "  0\nSECTION",
            "compound",
        ),
        (
            r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":0.3,"type":1,"format":"iges","pieces":true}"#,
            "model/iges",
            "lac-curve.igs",
            "",
            "space",
        ),
        (
            r#"{"points":[[0,0],[3,0],[4,2],[2,4],[-1,2]],"alpha":0.5,"closed":true,"g2":true,"format":"json","relative_tolerance":1e-7}"#,
            "application/json",
            "lac-curve.json",
            "{\"curves\":",
            "path",
        ),
        (
            r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"format":"svg"}"#,
            "image/svg+xml",
            "lac-curve.svg",
            "<?xml",
            "segment",
        ),
    ];
    for (body, content_type, file, start, kind) in cases {
        let answer = post(&app(), "/api/export", body).await;
        assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
        assert_eq!(answer.content_type, content_type);
        assert_eq!(
            header(&answer, "content-disposition"),
            format!("attachment; filename=\"{file}\"")
        );
        assert!(
            answer.text.starts_with(start),
            "{file}: {}",
            &answer.text[..40]
        );
        let report: Value = serde_json::from_str(header(&answer, "x-lac-export")).unwrap();
        assert_eq!(report["kind"], kind);
        assert!(f(&report["max_deviation"]) <= f(&report["tolerance"]));
        assert!(report["pieces"].as_u64().unwrap() >= 1);
    }
}

#[tokio::test]
async fn export_writes_what_lac_export_writes() {
    // DXF carries no timestamp: the answer is lac_export's document byte for byte.
    let body = r#"{"points":[[0,0],[3,0],[4.2,1.9]],"alpha":0.5,"format":"dxf","tolerance":1e-7}"#;
    let answer = post(&app(), "/api/export", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let input: SegmentInput =
        serde_json::from_str(r#"{"points":[[0,0],[3,0],[4.2,1.9]],"alpha":0.5}"#).unwrap();
    let segment = input.solve().unwrap();
    let expected = lac_export::export(
        &lac_export::ExportCurve::whole("segment", &segment),
        lac_export::Format::Dxf,
        lac::Tolerance::Absolute(1e-7),
        false,
        &lac_export::Meta::now("x"),
    )
    .unwrap();
    assert_eq!(answer.text, expected.document);
}

#[tokio::test]
async fn export_of_a_spline_design_is_the_spline_lac_export_through_writes() {
    // The Spline mode's design (its "types" tell it from a path through the same points):
    // P4 a corner, the span from P2 to P3 straight.
    let design = r#""points":[[0,0],[1,2],[3,2.5],[5,2.5],[6,1.5],[7,2.5],[8,4.5]],"alpha":-1,"closed":false,"types":["s","s","s","s","c","s","s"],"angles":[[null,null],[null,null],[null,null],[null,null],[null,null],[null,null],[null,null]],"lines":[2]"#;
    let answer = post(
        &app(),
        "/api/export",
        &format!(r#"{{{design},"samples":257,"format":"dxf"}}"#),
    )
    .await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let report: Value = serde_json::from_str(header(&answer, "x-lac-export")).unwrap();
    assert_eq!(report["kind"], "spline");
    assert_eq!(report["continuity"], "G0", "the corner breaks the tangent");
    // What `lac export --through "…" --alpha -1 --types "s s s s c s s" --lines 2-3` writes.
    let spline = lac_io::json::SplineInput {
        points: [
            (0., 0.),
            (1., 2.),
            (3., 2.5),
            (5., 2.5),
            (6., 1.5),
            (7., 2.5),
            (8., 4.5),
        ]
        .map(kurbo::Point::from)
        .to_vec(),
        alpha: -1.0,
        closed: false,
        options: lac::SplineOptions {
            types: (0..7)
                .map(|i| {
                    if i == 4 {
                        lac::PointType::CORNER
                    } else {
                        lac::PointType::Smooth
                    }
                })
                .collect(),
            lines: vec![2],
            ..Default::default()
        },
    }
    .solve()
    .unwrap();
    let curve = lac_io::json::AnyCurve::Spline(spline);
    let expected = lac_export::export(
        &curve.export_curve().unwrap(),
        lac_export::Format::Dxf,
        lac::Tolerance::Absolute(lac_export::DEFAULT_TOLERANCE),
        false,
        &lac_export::Meta::now("x"),
    )
    .unwrap();
    assert_eq!(answer.text, expected.document);
    // One B-spline a piece: the straight span's control points all lie on its line.
    let answer = post(
        &app(),
        "/api/export",
        &format!(r#"{{{design},"format":"json","pieces":true}}"#),
    )
    .await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let document: lac_export::json::ExportDocument = serde_json::from_str(&answer.text).unwrap();
    let on_span = |row: &lac_export::json::NurbsRow| {
        row.control_points
            .iter()
            .all(|p| (p[1] - 2.5).abs() < 1e-9 && (3.0 - 1e-9..=5.0 + 1e-9).contains(&p[0]))
    };
    assert!(document.curves.iter().any(on_span), "{}", answer.text);
    // Every format the editor's menu offers.
    for format in ["step", "iges", "svg"] {
        let answer = post(
            &app(),
            "/api/export",
            &format!(r#"{{{design},"format":"{format}"}}"#),
        )
        .await;
        assert_eq!(answer.status, StatusCode::OK, "{format}: {}", answer.text);
        let report: Value = serde_json::from_str(header(&answer, "x-lac-export")).unwrap();
        assert_eq!(report["kind"], "spline");
    }
    // A type that is none, and a tangent point without its direction: 400 with the point.
    for (types, says) in [
        (r#"["s","s","s","s","x","s","s"]"#, "types[4]"),
        (r#"["s","t","s","s","c","s","s"]"#, "point 1"),
    ] {
        let body = design.replace(r#"["s","s","s","s","c","s","s"]"#, types);
        let answer = post(
            &app(),
            "/api/export",
            &format!(r#"{{{body},"format":"step"}}"#),
        )
        .await;
        assert_eq!(answer.status, StatusCode::BAD_REQUEST, "{}", answer.text);
        assert_eq!(answer.content_type, "application/json");
        assert_eq!(answer.kind(), "invalid_input");
        assert!(answer.text.contains(says), "{}", answer.text);
    }
}

#[tokio::test]
async fn export_refusals_are_json_4xx() {
    let segment = r#""points":[[-1,0],[-0.2,0.8],[1,0]],"alpha":0.5"#;
    for (extra, status, kind) in [
        ("", StatusCode::BAD_REQUEST, "invalid_input"),
        (
            r#","format":"pdf""#,
            StatusCode::BAD_REQUEST,
            "invalid_input",
        ),
        (
            r#","format":"step","tolerance":1e-6,"relative_tolerance":1e-6"#,
            StatusCode::BAD_REQUEST,
            "invalid_input",
        ),
        (
            r#","format":"step","tolerance":0"#,
            StatusCode::BAD_REQUEST,
            "out_of_range",
        ),
        // Finer than the server's limit (1e-10 of the arc length, about 2.3).
        (
            r#","format":"step","tolerance":1e-11"#,
            StatusCode::BAD_REQUEST,
            "limit",
        ),
        (
            r#","format":"step","name":"../etc/passwd""#,
            StatusCode::BAD_REQUEST,
            "invalid_input",
        ),
    ] {
        let answer = post(&app(), "/api/export", &format!("{{{segment}{extra}}}")).await;
        assert_eq!(answer.status, status, "{extra}: {}", answer.text);
        assert_eq!(answer.content_type, "application/json");
        assert_eq!(answer.kind(), kind, "{extra}: {}", answer.text);
    }
    let space = r#"{"points":[[0,0,0],[3,0,0],[3,3,1.5],[0,3,3]],"alpha":0.5,"beta":0,"omega":0.3,"format":"svg"}"#;
    let answer = post(&app(), "/api/export", space).await;
    assert_eq!(answer.status, StatusCode::BAD_REQUEST);
    assert_eq!(answer.kind(), "usage");
    // Not drawable: 422, as /api/segment answers it.
    let answer = post(
        &app(),
        "/api/export",
        r#"{"points":[[0,0],[1,0],[1.01,2]],"alpha":3,"format":"dxf"}"#,
    )
    .await;
    assert_eq!(
        answer.status,
        StatusCode::UNPROCESSABLE_ENTITY,
        "{}",
        answer.text
    );
    // A path without a G2 solution: 422 with the solver's kind.
    let answer = post(
        &app(),
        "/api/export",
        r#"{"points":[[0,0],[1,0],[2,1],[3,0]],"alpha":1,"g2":true,"format":"dxf"}"#,
    )
    .await;
    assert_eq!(
        answer.status,
        StatusCode::UNPROCESSABLE_ENTITY,
        "{}",
        answer.text
    );
    assert_eq!(answer.kind(), "no_g2_path");
}

#[tokio::test]
async fn a_path_answer_is_lac_paths_report_with_each_segments_lcg_line() {
    // The README's S-shaped G2 path: through an inflection (a straight piece on one leg).
    let body = r#"{"points":[[0,0],[1.5,0],[3,0.8],[6,3.2],[7.5,4],[9,4]],"alpha":-0.5,"g2":true,"samples":33}"#;
    let answer = post(&app(), "/api/path", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    let input: PathInput = serde_json::from_str(body).unwrap();
    let path = input.solve().unwrap();
    let mut expected = serde_json::to_value(PathReport::new(&path, 33).unwrap()).unwrap();
    let lcg = answer.json["lcg"].as_array().unwrap().clone();
    let mut got = answer.json.clone();
    got.as_object_mut().unwrap().remove("lcg");
    assert_eq!(got, expected.take());
    assert_eq!(lcg.len(), path.segments().len());
    for (row, seg) in lcg.iter().zip(path.segments()) {
        assert_eq!(f(&row["alpha"]), seg.alpha());
    }
    assert_eq!(answer.json["straight_pieces"].as_array().unwrap().len(), 1);
    assert!(f(&answer.json["max_curvature_jump"]) <= 1e-9);
    // No G2 path (alpha >= 0 cannot pass through zero curvature): 422, naming the leg and
    // giving the nearest G1 path; that G1 path is drawn.
    let refused = post(&app(), "/api/path", &body.replace("-0.5", "0.5")).await;
    assert_eq!(
        refused.status,
        StatusCode::UNPROCESSABLE_ENTITY,
        "{}",
        refused.text
    );
    assert_eq!(refused.kind(), "no_g2_path");
    assert!(
        refused.message().contains("nearest G1 path"),
        "{}",
        refused.text
    );
    let g1 = post(
        &app(),
        "/api/path",
        &body.replace("-0.5", "0.5").replace("true", "false"),
    )
    .await;
    assert_eq!(g1.status, StatusCode::OK, "{}", g1.text);
    assert_eq!(g1.json["continuity"], "g1");
    // Its joint fractions come as numbers too (the page offers the G1 path only then).
    let fractions = refused.json["error"]["g1_fractions"].as_array().unwrap();
    assert_eq!(fractions.len(), g1.json["joints"].as_array().unwrap().len());
    // Where no G1 path can be drawn either (α = −1.8: not even the midpoint one), the
    // refusal says why G2 failed and carries no fractions.
    let neither = post(
        &app(),
        "/api/path",
        r#"{"points":[[0,0],[1,0],[1.5,1],[4,1.2],[4.5,2]],"alpha":-1.8,"g2":true}"#,
    )
    .await;
    assert_eq!(neither.kind(), "no_g2_path", "{}", neither.text);
    assert!(
        neither.json["error"].get("g1_fractions").is_none(),
        "{}",
        neither.text
    );
    let short = post(
        &app(),
        "/api/path",
        r#"{"points":[[0,0],[1,0]],"alpha":0.5}"#,
    )
    .await;
    assert_eq!(short.status, StatusCode::BAD_REQUEST, "{}", short.text);
}

/// Issue 35: a segment and a path near the largest double are answered (or refused with a
/// 4xx that names the problem), never a 500.
#[tokio::test]
async fn curves_near_the_largest_double_are_answered_never_an_internal_error() {
    let body = r#"{"points":[[0,0],[1e308,0],[1e308,1e308]],"alpha":0.5,"samples":5}"#;
    let answer = post(&app(), "/api/segment", body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    for (p, status) in [
        ("1e305", StatusCode::OK),
        ("5e307", StatusCode::BAD_REQUEST),
    ] {
        let body = format!(
            r#"{{"points":[[0,0],[{p},0],[{p},{p}],[0,{p}]],"alpha":0.5,"g2":true,
               "format":"json","relative_tolerance":1e-6}}"#
        );
        let answer = post(&app(), "/api/export", &body).await;
        assert_eq!(answer.status, status, "{p}: {}", answer.text);
        if status != StatusCode::OK {
            assert!(answer.text.contains("unrepresentable"), "{}", answer.text);
        }
    }
}
