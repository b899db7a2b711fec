//! Calling the router without a socket.

#![allow(dead_code, unreachable_pub)]

use axum::body::Body;
use axum::http::{header, Request, StatusCode};
use axum::Router;
use serde_json::Value;
use tower::ServiceExt;

/// The answer's status, headers' content type and body (as JSON when it is JSON, else as a
/// string value).
pub struct Answer {
    pub status: StatusCode,
    pub content_type: String,
    pub headers: axum::http::HeaderMap,
    pub json: Value,
    pub text: String,
}

impl Answer {
    /// The error body's kind; panics (failing the test) when there is none.
    pub fn kind(&self) -> &str {
        self.json["error"]["kind"]
            .as_str()
            .unwrap_or_else(|| panic!("no error kind in {}", self.text))
    }

    /// The error body's message.
    pub fn message(&self) -> &str {
        self.json["error"]["message"].as_str().unwrap_or("")
    }
}

/// Send one request to `app`.
pub async fn send(
    app: &Router,
    method: &str,
    path: &str,
    content_type: Option<&str>,
    body: Vec<u8>,
) -> Answer {
    let mut request = Request::builder().method(method).uri(path);
    if let Some(ct) = content_type {
        request = request.header(header::CONTENT_TYPE, ct);
    }
    let response = app
        .clone()
        .oneshot(request.body(Body::from(body)).unwrap())
        .await
        .unwrap();
    let status = response.status();
    let content_type = response
        .headers()
        .get(header::CONTENT_TYPE)
        .map(|v| v.to_str().unwrap().to_string())
        .unwrap_or_default();
    let headers = response.headers().clone();
    let bytes = axum::body::to_bytes(response.into_body(), usize::MAX)
        .await
        .unwrap();
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let json = serde_json::from_str(&text).unwrap_or(Value::Null);
    Answer {
        status,
        content_type,
        headers,
        json,
        text,
    }
}

/// POST JSON text.
pub async fn post(app: &Router, path: &str, body: &str) -> Answer {
    send(
        app,
        "POST",
        path,
        Some("application/json"),
        body.as_bytes().to_vec(),
    )
    .await
}
