//! `/api/fit`: the library's fit of the points, as `lac fit` reports it, with each point's
//! distance; a bad request is a 4xx with a one-line JSON error.

use crate::common::{self, post};

use axum::http::StatusCode;
use lac_io::json::{FitInput, FitReport};
use serde_json::{json, Value};

/// `n` points on a quarter of the unit circle, each moved along the radius by ±`noise`.
fn arc_points(n: usize, noise: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_2 * k as f64 / (n - 1) as f64;
            let r = 1.0 + if k % 2 == 0 { noise } else { -noise };
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

#[tokio::test]
async fn a_fit_answer_is_the_library_report_with_every_distance_within_the_tolerance() {
    let points = arc_points(60, 1e-5);
    let body = json!({"points": points, "tolerance": 1e-3, "samples": 33}).to_string();
    let answer = post(&lac_serve::router(), "/api/fit", &body).await;
    assert_eq!(answer.status, StatusCode::OK, "{}", answer.text);
    assert_eq!(answer.content_type, "application/json");

    let input: FitInput = serde_json::from_str(&body).unwrap();
    let fit = input.solve().unwrap();
    let report = FitReport::new(&fit, &input.points, input.tolerance, 33).unwrap();
    let expected = serde_json::to_value(&report).unwrap();
    for key in [
        "fitted_segments",
        "rms",
        "max_distance",
        "worst_point",
        "segments",
    ] {
        assert_eq!(answer.json[key], expected[key], "{key}");
    }
    assert_eq!(answer.json["samples"].as_array().unwrap().len(), 33);
    let distances: Vec<f64> = answer.json["distances"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d.as_f64().unwrap())
        .collect();
    assert_eq!(distances, fit.distances());
    let largest = distances.iter().copied().fold(0.0, f64::max);
    assert_eq!(largest, answer.json["max_distance"].as_f64().unwrap());
    assert!(largest <= 1e-3, "largest distance {largest}");
}

#[tokio::test]
async fn a_bad_fit_request_is_a_4xx_with_a_one_line_json_error() {
    let app = lac_serve::router();
    for (body, kind) in [
        (r#"{"tolerance":0.1}"#, "invalid_input"),
        (
            r#"{"points":[[0,0],[1,0],[2,1]],"alpha":1,"alpha_range":[0,2]}"#,
            "invalid_input",
        ),
    ] {
        let answer = post(&app, "/api/fit", body).await;
        assert!(answer.status.is_client_error(), "{body}: {}", answer.text);
        assert_eq!(answer.kind(), kind, "{body}: {}", answer.text);
        assert!(!answer.text.trim_end().contains('\n'), "{}", answer.text);
    }
}

#[tokio::test]
async fn more_points_than_the_limit_are_refused_with_the_limit_named() {
    let app = lac_serve::router_with(lac_serve::Limits {
        max_fit_points: 50,
        ..lac_serve::Limits::default()
    });
    let body = json!({"points": arc_points(51, 0.0), "tolerance": 1e-3}).to_string();
    let answer = post(&app, "/api/fit", &body).await;
    assert!(answer.status.is_client_error(), "{}", answer.text);
    assert_eq!(answer.kind(), "limit");
    assert!(
        answer.message().contains("51 points"),
        "{}",
        answer.message()
    );
    assert!(answer.message().contains("(50)"), "{}", answer.message());
    let version = common::send(&app, "GET", "/api/version", None, vec![]).await;
    assert_eq!(version.json["limits"]["max_fit_points"], Value::from(50));
}
