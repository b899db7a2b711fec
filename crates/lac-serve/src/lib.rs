//! The interactive editor of log-aesthetic curves: `lac serve`.
//!
//! A small HTTP server (axum on tokio) that serves one page, whose HTML, JavaScript and CSS
//! are compiled into the binary (`web/`, embedded with `include_str!`: it works offline), and
//! a JSON API that speaks the shapes of [`lac_io::json`]: a request is an input shape
//! (`SegmentInput`, `CompoundInput`, `QuasiInput`, …) plus options such as `"samples"`, an
//! answer is the matching report (`SegmentReport`, …) plus what the page draws (the
//! curvature plot and logarithmic curvature graph with its fitted slope), and a failure is
//! `{"error":{"kind","message"}}` with status 400 (invalid request), 413/415 (body too large,
//! not JSON), 422 (valid but not drawable: the message says what to move), 500 (a defect) or
//! 503 (too busy, timed out). `API.md` beside this crate documents every endpoint.
//!
//! [`router`] builds the whole application as an axum [`Router`] (tests drive it without a
//! socket through tower's `ServiceExt::oneshot`); [`serve`] runs it on a listener, and
//! [`run`] binds an address (loopback unless [`check_bind`] is told otherwise) and serves
//! until the process ends.
//!
//! Every request is bounded ([`Limits`]): body size, sample counts, map sizes; solving runs
//! on the blocking pool with at most [`Limits::compute_slots`] at once, and a request that
//! waits or works longer than [`Limits::timeout`] is answered 503.

mod api;
mod assets;
mod body;
mod cache;
mod error;
mod limits;

use std::io;
use std::net::{IpAddr, SocketAddr};
use std::sync::Arc;

use axum::error_handling::HandleErrorLayer;
use axum::extract::{Request, State};
use axum::routing::{get, post};
use axum::serve::ListenerExt;
use axum::Router;
use lac_io::json::ErrorBody;
use tower::ServiceBuilder;

pub use limits::Limits;

/// The application with the default [`Limits`].
pub fn router() -> Router {
    router_with(Limits::default())
}

/// The application: the page (`GET /`, `GET /app/{*file}`) and the API (`/api/…`).
pub fn router_with(limits: Limits) -> Router {
    let timeout = limits.timeout;
    let in_flight = limits.in_flight.max(1);
    let app = Arc::new(api::App::new(limits));
    let mut router = Router::new()
        .route("/", get(assets::index))
        .route("/app/{*file}", get(assets::file))
        .route("/api/version", get(api::version))
        .route("/api/export", post(api::export));
    for &(path, endpoint) in api::ENDPOINTS {
        router = router.route(
            path,
            post(move |State(app): State<Arc<api::App>>, request: Request| {
                api::answer(app, request, endpoint)
            }),
        );
    }
    router
        .fallback(error::not_found)
        .method_not_allowed_fallback(error::method_not_allowed)
        .with_state(app)
        .layer(
            ServiceBuilder::new()
                .layer(HandleErrorLayer::new(error::overloaded))
                .timeout(timeout)
                .concurrency_limit(in_flight),
        )
}

/// Serve [`router_with`]`(limits)` on `listener` until the process ends.
pub async fn serve(listener: tokio::net::TcpListener, limits: Limits) -> io::Result<()> {
    // No Nagle delay: an answer is one small write that the page waits for.
    let listener = listener.tap_io(|tcp| {
        let _ = tcp.set_nodelay(true);
    });
    axum::serve(listener, router_with(limits)).await
}

/// May the server listen on `ip`? Loopback addresses always; anything else only with
/// `allow_remote`, since the editor has no authentication and anyone who can reach the
/// port can make it compute.
pub fn check_bind(ip: IpAddr, allow_remote: bool) -> Result<(), ErrorBody> {
    if ip.is_loopback() || allow_remote {
        Ok(())
    } else {
        Err(ErrorBody::new(
            "usage",
            format!(
                "{ip} is not a loopback address: the editor has no authentication, so anyone \
                 who can reach it could use it; bind 127.0.0.1, or add --allow-remote if that \
                 is what you want"
            ),
        ))
    }
}

/// Bind `addr` (after [`check_bind`]), call `ready` with the address actually bound (port 0
/// picks a free one), and serve until the process ends, on a runtime of its own.
pub fn run(
    addr: SocketAddr,
    allow_remote: bool,
    limits: Limits,
    ready: impl FnOnce(SocketAddr),
) -> Result<(), ErrorBody> {
    check_bind(addr.ip(), allow_remote)?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| ErrorBody::new("io", format!("cannot start the server's runtime: {e}")))?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(addr).await.map_err(|e| {
            ErrorBody::new(
                "io",
                format!("cannot listen on {addr}: {e} (another port: --port P, or --port 0 for any free one)"),
            )
        })?;
        let bound = listener
            .local_addr()
            .map_err(|e| ErrorBody::new("io", format!("cannot read the bound address: {e}")))?;
        ready(bound);
        serve(listener, limits)
            .await
            .map_err(|e| ErrorBody::new("io", format!("the server stopped: {e}")))
    })
}
