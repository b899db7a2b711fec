//! The API's endpoints: each reads one JSON request, solves it with the library on the
//! blocking pool, and answers one JSON document.
//!
//! An endpoint is a plain function `fn(&App, &str) -> Result<String, ApiError>` from the
//! request's text to the answer's; [`answer`] does the HTTP around it (body limit, compute
//! slot, blocking thread, status).

mod curve;
mod export;
mod fit;
mod quasi;
mod region;
mod request;
mod space;

use std::sync::Arc;

use axum::extract::{Request, State};
use axum::http::StatusCode;
use axum::response::Response;
use serde::Serialize;
use tokio::sync::Semaphore;

use crate::body;
use crate::cache::RegionCache;
use crate::error::{json_response, ApiError};
use crate::limits::Limits;

/// What every request shares: the limits, the compute slots and the region maps.
#[derive(Debug)]
pub(crate) struct App {
    pub(crate) limits: Limits,
    compute: Arc<Semaphore>,
    pub(crate) regions: RegionCache,
}

impl App {
    pub(crate) fn new(limits: Limits) -> Self {
        App {
            compute: Arc::new(Semaphore::new(limits.compute_slots.max(1))),
            regions: RegionCache::new(limits.cached_regions),
            limits,
        }
    }
}

/// An endpoint: the request's text to the answer's JSON.
pub(crate) type Endpoint = fn(&App, &str) -> Result<String, ApiError>;

/// The JSON endpoints, each `POST` at its path: a new one (a new curve kind's) is one line
/// here and its function in its own file.
pub(crate) const ENDPOINTS: &[(&str, Endpoint)] = &[
    ("/api/segment", curve::segment),
    ("/api/compound", curve::compound),
    ("/api/path", curve::path),
    ("/api/spline", curve::spline),
    ("/api/quasi", quasi::quasi),
    ("/api/lcg", curve::lcg),
    ("/api/region", region::region),
    ("/api/region/point", region::point_region),
    ("/api/space", space::space),
    ("/api/fit", fit::fit),
];

/// Read the body, wait for a compute slot, run `endpoint` on the blocking pool (holding the
/// slot until it returns, even if the client has gone), and answer its JSON.
pub(crate) async fn answer(app: Arc<App>, request: Request, endpoint: Endpoint) -> Response {
    answer_with(app, request, endpoint, |json| {
        json_response(StatusCode::OK, json)
    })
    .await
}

/// [`answer`] for any kind of answer `T`, made a response by `respond`.
async fn answer_with<T: Send + 'static>(
    app: Arc<App>,
    request: Request,
    endpoint: fn(&App, &str) -> Result<T, ApiError>,
    respond: fn(T) -> Response,
) -> Response {
    let (parts, body) = request.into_parts();
    let bytes = match body::read_json(&parts.headers, body, app.limits.body_bytes).await {
        Ok(bytes) => bytes,
        Err(err) => return axum::response::IntoResponse::into_response(err),
    };
    let Ok(slot) = Arc::clone(&app.compute).acquire_owned().await else {
        return internal("the compute slots are closed");
    };
    let worker = Arc::clone(&app);
    let result = tokio::task::spawn_blocking(move || {
        let _slot = slot;
        let text = std::str::from_utf8(&bytes).map_err(|e| {
            ApiError::new(
                StatusCode::BAD_REQUEST,
                "invalid_input",
                format!("the body is not UTF-8: {e}"),
            )
        })?;
        endpoint(&worker, text)
    })
    .await;
    match result {
        Ok(Ok(answer)) => respond(answer),
        Ok(Err(err)) => axum::response::IntoResponse::into_response(err),
        Err(err) => internal(&format!("the solver stopped: {err}")),
    }
}

fn internal(message: &str) -> Response {
    axum::response::IntoResponse::into_response(ApiError::new(
        StatusCode::INTERNAL_SERVER_ERROR,
        "internal",
        format!("{message}; please report this input"),
    ))
}

/// `POST /api/export`: the curve as a CAD file.
pub(crate) async fn export(State(app): State<Arc<App>>, request: Request) -> Response {
    answer_with(app, request, export::export, export::File::into_response).await
}

/// `GET /api/version`: who answers, and the limits a client must respect.
#[derive(Serialize)]
struct Version {
    name: &'static str,
    version: &'static str,
    limits: LimitsRow,
}

/// The limits in a client's terms.
#[derive(Serialize)]
struct LimitsRow {
    body_bytes: usize,
    default_samples: usize,
    max_samples: usize,
    max_piece_points: usize,
    max_fit_points: usize,
    default_region_size: usize,
    max_region_size: usize,
    max_point_region_size: usize,
    timeout_ms: u128,
    min_export_relative_tolerance: f64,
}

/// `GET /api/version`.
pub(crate) async fn version(State(app): State<Arc<App>>) -> Response {
    let l = &app.limits;
    let version = Version {
        name: "lac-serve",
        version: env!("CARGO_PKG_VERSION"),
        limits: LimitsRow {
            body_bytes: l.body_bytes,
            default_samples: l.default_samples,
            max_samples: l.max_samples,
            max_piece_points: l.max_piece_points,
            max_fit_points: l.max_fit_points,
            default_region_size: l.default_region_size,
            max_region_size: l.max_region_size,
            max_point_region_size: l.max_point_region_size,
            timeout_ms: l.timeout.as_millis(),
            min_export_relative_tolerance: l.min_export_relative_tolerance,
        },
    };
    json_response(StatusCode::OK, lac_io::json::to_line(&version))
}
