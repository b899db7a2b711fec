//! `/api/space`: a log-aesthetic space curve segment (seed 003) with its Frenet frames (for
//! the curvature comb) and its logarithmic curvature and torsion graphs.

use lac_io::json::{parse, to_line, SpaceGraphsReport, SpaceInput, SpaceReport, Xyz};
use serde::Serialize;

use super::request::WithSamples;
use super::App;
use crate::error::ApiError;

/// `{…SpaceReport with frames…, "points":[…], "graphs":{"curvature":[…],"torsion":[…]}}`.
#[derive(Debug, Serialize)]
struct SpaceAnswer {
    #[serde(flatten)]
    report: SpaceReport,
    /// The control points as given.
    points: [Xyz; 4],
    /// The logarithmic curvature and torsion graphs at the samples' arc lengths.
    graphs: SpaceGraphsReport,
}

/// `POST /api/space`: `{"points":[[x,y,z]×4],"alpha":A,"beta":B,"omega":W,"type":1,"samples":N}`.
pub(crate) fn space(app: &App, text: &str) -> Result<String, ApiError> {
    let request: WithSamples<SpaceInput> = parse(text, SpaceInput::SHAPE)?;
    let n = app.limits.samples(request.samples)?;
    let segment = request.input.solve()?;
    Ok(to_line(&SpaceAnswer {
        report: SpaceReport::new(&segment, n, true)?,
        points: request.input.points,
        graphs: SpaceGraphsReport::new(&segment, n)?,
    }))
}
