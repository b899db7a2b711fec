//! The page: HTML, JavaScript modules and CSS from `web/`, compiled into the binary.

use axum::extract::Path;
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};

use crate::error::ApiError;

/// One embedded file: name under `/app/`, content, media type.
type Asset = (&'static str, &'static str, &'static str);

const JS: &str = "text/javascript; charset=utf-8";

/// Every file the page loads besides `index.html`.
const FILES: &[Asset] = &[
    (
        "style.css",
        include_str!("../web/style.css"),
        "text/css; charset=utf-8",
    ),
    ("main.js", include_str!("../web/main.js"), JS),
    ("api.js", include_str!("../web/api.js"), JS),
    ("design.js", include_str!("../web/design.js"), JS),
    ("view.js", include_str!("../web/view.js"), JS),
    ("draw.js", include_str!("../web/draw.js"), JS),
    ("plots.js", include_str!("../web/plots.js"), JS),
    ("space.js", include_str!("../web/space.js"), JS),
    ("export.js", include_str!("../web/export.js"), JS),
    (
        "favicon.svg",
        include_str!("../web/favicon.svg"),
        "image/svg+xml",
    ),
];

/// Only this page's own files, no inline code: what a browser may load and run.
const POLICY: &str = "default-src 'self'; img-src 'self' data: blob:; style-src 'self'; \
                      script-src 'self'; connect-src 'self'; object-src 'none'; \
                      base-uri 'none'; frame-ancestors 'none'";

fn page(content: &'static str, media_type: &'static str) -> Response {
    (
        StatusCode::OK,
        [
            (header::CONTENT_TYPE, media_type),
            (header::CACHE_CONTROL, "no-cache"),
            (header::CONTENT_SECURITY_POLICY, POLICY),
            (header::X_CONTENT_TYPE_OPTIONS, "nosniff"),
        ],
        content,
    )
        .into_response()
}

/// `GET /`: the editor.
pub(crate) async fn index() -> Response {
    page(
        include_str!("../web/index.html"),
        "text/html; charset=utf-8",
    )
}

/// `GET /app/{file}`.
pub(crate) async fn file(Path(name): Path<String>) -> Response {
    match FILES.iter().find(|(n, _, _)| *n == name) {
        Some((_, content, media_type)) => page(content, media_type),
        None => ApiError::new(
            StatusCode::NOT_FOUND,
            "not_found",
            format!("the page has no file {name:?}"),
        )
        .into_response(),
    }
}
