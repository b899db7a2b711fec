//! `/api/fit`: a log-aesthetic path fitted to points (issue 30), as `lac fit` reports it,
//! with every point's distance to the fit (the page colours the points by it).

use lac_io::json::{parse, to_line, ErrorBody, FitInput, FitReport};
use serde::Serialize;

use super::request::WithSamples;
use super::App;
use crate::error::ApiError;

/// `{…FitReport…, "distances":[…]}`.
#[derive(Debug, Serialize)]
struct FitAnswer {
    /// The report, as `lac fit` prints it.
    #[serde(flatten)]
    report: FitReport,
    /// Each point's distance to the fit, in the input's order.
    distances: Vec<f64>,
}

/// `POST /api/fit`: `{"points":[[x,y],…],"tolerance":T,"max_segments":N,"alpha":A (or
/// "alpha_range":[a,b]),"g1":false,"closed":false,"samples":N}` (lac-io's [`FitInput`]).
pub(crate) fn fit(app: &App, text: &str) -> Result<String, ApiError> {
    let request: WithSamples<FitInput> = parse(text, FitInput::SHAPE)?;
    let n = app.limits.samples(request.samples)?;
    let input = &request.input;
    let most = app.limits.max_fit_points;
    if input.points.len() > most {
        return Err(ErrorBody::limit(format!(
            "{} points are more than this server fits at once ({most}): thin them out \
             (every k-th point) or fit the curve in parts",
            input.points.len()
        ))
        .into());
    }
    let fit = input.solve()?;
    Ok(to_line(&FitAnswer {
        report: FitReport::new(&fit, &input.points, input.tolerance, n)?,
        distances: fit.distances().to_vec(),
    }))
}
