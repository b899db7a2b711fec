//! Failures as HTTP answers: `{"error":{"kind","message"}}` with the status its class
//! ([`ErrorBody::class`]) or the protocol calls for.

use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use lac_io::json::{ErrorBody, ErrorClass};
use tower::BoxError;

/// A failed request: the status and the shared error body.
#[derive(Debug)]
pub(crate) struct ApiError {
    pub(crate) status: StatusCode,
    pub(crate) body: ErrorBody,
}

impl ApiError {
    pub(crate) fn new(status: StatusCode, kind: &str, message: impl Into<String>) -> Self {
        ApiError {
            status,
            body: ErrorBody::new(kind, message),
        }
    }
}

impl From<ErrorBody> for ApiError {
    fn from(body: ErrorBody) -> Self {
        let status = match body.class() {
            ErrorClass::Invalid => StatusCode::BAD_REQUEST,
            ErrorClass::Undrawable => StatusCode::UNPROCESSABLE_ENTITY,
            ErrorClass::Io | ErrorClass::Internal => StatusCode::INTERNAL_SERVER_ERROR,
        };
        ApiError { status, body }
    }
}

impl From<lac::Error> for ApiError {
    fn from(err: lac::Error) -> Self {
        ApiError::from(ErrorBody::from(err))
    }
}

impl From<lac_export::Error> for ApiError {
    fn from(err: lac_export::Error) -> Self {
        ApiError::from(ErrorBody::from(err))
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        json_response(self.status, self.body.to_json_line())
    }
}

/// A JSON answer.
pub(crate) fn json_response(status: StatusCode, json: String) -> Response {
    (
        status,
        [
            (header::CONTENT_TYPE, "application/json"),
            (header::CACHE_CONTROL, "no-store"),
        ],
        json,
    )
        .into_response()
}

/// No such page or endpoint.
pub(crate) async fn not_found() -> ApiError {
    ApiError::new(
        StatusCode::NOT_FOUND,
        "not_found",
        "no such page or endpoint: the editor is at /, the API under /api/ (see API.md)",
    )
}

/// A known path with the wrong method.
pub(crate) async fn method_not_allowed() -> ApiError {
    ApiError::new(
        StatusCode::METHOD_NOT_ALLOWED,
        "method_not_allowed",
        "wrong method: the API's endpoints take POST with a JSON body, the page GET",
    )
}

/// The timeout and concurrency layers' failures.
pub(crate) async fn overloaded(err: BoxError) -> ApiError {
    if err.is::<tower::timeout::error::Elapsed>() {
        ApiError::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "timeout",
            "the request waited or worked too long; the server is busy, try again",
        )
    } else {
        ApiError::new(
            StatusCode::INTERNAL_SERVER_ERROR,
            "internal",
            format!("the server failed: {err}"),
        )
    }
}
