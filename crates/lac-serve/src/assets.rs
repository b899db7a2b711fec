//! The page: HTML, JavaScript modules and CSS from `web/`, compiled into the binary.

use axum::extract::Path;
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};

use crate::error::ApiError;

/// One embedded file: name under `/app/`, content, media type.
type Asset = (&'static str, &'static str, &'static str);

/// Every file the page loads besides `index.html`, by its path under `web/`: every `.js`,
/// `.css` and `.svg` file there, listed by `build.rs`.
const FILES: &[Asset] = include!(concat!(env!("OUT_DIR"), "/assets.rs"));

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

/// `GET /app/{*file}`: a file of the list, by its path under `web/` (`modes/segment.js`).
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

#[cfg(test)]
mod tests {
    use super::FILES;
    use std::path::Path;

    /// The files under `dir` (relative to `web/`), subfolders too.
    fn files_under(web: &Path, dir: &Path, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                files_under(web, &path, out);
            } else {
                let name = path.strip_prefix(web).unwrap().to_string_lossy();
                out.push(name.replace('\\', "/"));
            }
        }
    }

    /// Every script, style sheet and icon of `web/` is served (`build.rs` lists them): a new
    /// module of the page needs no list of its own.
    #[test]
    fn every_file_of_the_page_is_served() {
        let web = Path::new(env!("CARGO_MANIFEST_DIR")).join("web");
        let mut on_disk = Vec::new();
        files_under(&web, &web, &mut on_disk);
        assert!(on_disk.iter().any(|n| n == "modes/segment.js"));
        for name in on_disk {
            let listed = name == "index.html"
                || name.ends_with(".md")
                || FILES.iter().any(|(n, _, _)| *n == name);
            assert!(listed, "web/{name} is not served");
        }
    }
}
