//! Reading a request's JSON body within the size limit.

use axum::body::{Body, Bytes};
use axum::http::{header, HeaderMap, StatusCode};
use http_body_util::LengthLimitError;

use crate::error::ApiError;

/// The body of a POST, if it says it is JSON and is at most `limit` bytes.
///
/// Requiring `Content-Type: application/json` also keeps other web pages out: a browser
/// sends such a request across origins only after a preflight, which this server does not
/// answer.
pub(crate) async fn read_json(
    headers: &HeaderMap,
    body: Body,
    limit: usize,
) -> Result<Bytes, ApiError> {
    let content_type = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .unwrap_or("");
    let mime = content_type.split(';').next().unwrap_or("").trim();
    if !mime.eq_ignore_ascii_case("application/json") {
        return Err(ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "invalid_input",
            format!(
                "the body must be JSON, sent with Content-Type: application/json (got {:?})",
                content_type
            ),
        ));
    }
    let too_large = || {
        ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            "limit",
            format!("the body is larger than {limit} bytes: send one curve per request"),
        )
    };
    let declared = headers
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > limit as u64) {
        return Err(too_large());
    }
    axum::body::to_bytes(body, limit).await.map_err(|err| {
        let over = std::error::Error::source(&err)
            .is_some_and(|source| source.is::<LengthLimitError>())
            || err.to_string().contains("length limit");
        if over {
            too_large()
        } else {
            ApiError::new(
                StatusCode::BAD_REQUEST,
                "invalid_input",
                format!("the body could not be read: {err}"),
            )
        }
    })
}
