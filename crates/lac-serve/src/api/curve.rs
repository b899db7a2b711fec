//! `/api/segment`, `/api/compound`, `/api/path`, `/api/spline` and `/api/lcg`: a curve
//! solved and sampled, with its curvature plot and logarithmic curvature graph.

use lac::Curve;
use lac_io::json::{
    parse, to_line, CompoundInput, CompoundReport, LcgReport, LcgRow, PathInput, PathReport,
    PiecesInput, Report, SegmentInput, SegmentReport, SplineReport, SplineRequest,
};
use serde::Serialize;

use super::request::{self, WithSamples};
use super::App;
use crate::error::ApiError;

/// A curve's report with what the page draws beside it: `{…report…, "plot": LcgReport}`.
#[derive(Debug, Serialize)]
pub(crate) struct CurveAnswer<R> {
    /// The report, as `lac segment` or `lac compound` prints it.
    #[serde(flatten)]
    pub(crate) report: R,
    /// The curvature plot (κ against s, at the samples' arc lengths) and the logarithmic
    /// curvature graph with its fitted slope.
    pub(crate) plot: LcgReport,
}

/// The curvature plot of `curve` at `n` points.
pub(crate) fn plot(curve: &(impl Curve + ?Sized), n: usize) -> Result<LcgReport, ApiError> {
    Ok(LcgReport::new(&curve.curvature_plot(n)?).checked()?)
}

/// The answer of `/api/segment` for `input`.
pub(crate) fn segment_answer(
    input: &SegmentInput,
    n: usize,
) -> Result<CurveAnswer<SegmentReport>, ApiError> {
    let segment = input.solve()?;
    Ok(CurveAnswer {
        report: SegmentReport::of_input(&segment, n, input.points)?,
        plot: plot(&segment, n)?,
    })
}

/// The answer of `/api/compound` for `input`.
pub(crate) fn compound_answer(
    input: &CompoundInput,
    n: usize,
) -> Result<CurveAnswer<CompoundReport>, ApiError> {
    let curve = input.solve()?;
    Ok(CurveAnswer {
        report: CompoundReport::new(&curve, input, n)?,
        plot: plot(&curve, n)?,
    })
}

/// `POST /api/segment`: `{"points":[[x,y]×3],"alpha":A,"samples":N}`.
pub(crate) fn segment(app: &App, text: &str) -> Result<String, ApiError> {
    let request: WithSamples<SegmentInput> = parse(text, SegmentInput::SHAPE)?;
    let n = app.limits.samples(request.samples)?;
    Ok(to_line(&segment_answer(&request.input, n)?))
}

/// `POST /api/compound`: `{"points":[…3 or 4…],"alpha0":A,"alpha1":B,"ratio":R,"samples":N}`.
pub(crate) fn compound(app: &App, text: &str) -> Result<String, ApiError> {
    let request: WithSamples<CompoundInput> = parse(text, CompoundInput::SHAPE)?;
    let n = app.limits.samples(request.samples)?;
    Ok(to_line(&compound_answer(&request.input, n)?))
}

/// A path's or spline's report with each segment's line of the logarithmic curvature graph
/// (null for a circular arc): `{…lac path's or lac spline's report…, "lcg":[…]}`.
#[derive(Debug, Serialize)]
pub(crate) struct LcgAnswer<R> {
    /// The report, as `lac path` or `lac spline` prints it.
    #[serde(flatten)]
    pub(crate) report: R,
    /// Each segment's line ln(ρ ds/dρ) = α ln ρ + c over its range of ln ρ.
    pub(crate) lcg: Vec<Option<LcgRow>>,
}

impl<R> LcgAnswer<R> {
    /// `report` with the lines of `segments`.
    fn new(report: R, segments: &[lac::Segment]) -> Self {
        LcgAnswer {
            report,
            lcg: segments.iter().map(|s| s.lcg().map(LcgRow::from)).collect(),
        }
    }
}

/// `POST /api/path`: `{"points":[[x,y],…],"alpha":A (or "alphas":[…]),"g2":true,
/// "closed":false,"samples":N}` (a G1 path may give `"fractions"`).
pub(crate) fn path(app: &App, text: &str) -> Result<String, ApiError> {
    let request: WithSamples<PathInput> = parse(text, PathInput::SHAPE)?;
    let n = app.limits.samples(request.samples)?;
    let path = request.input.solve()?;
    Ok(to_line(&LcgAnswer::new(
        PathReport::new(&path, n)?,
        path.segments(),
    )))
}

/// `POST /api/spline`: a spline through points with point types ([`SplineRequest`]), answered
/// as `lac spline` prints it with each piece's line of the logarithmic curvature graph.
pub(crate) fn spline(app: &App, text: &str) -> Result<String, ApiError> {
    let request: WithSamples<SplineRequest> = parse(text, SplineRequest::SHAPE)?;
    let n = app.limits.samples(request.samples)?;
    let input = request.input.input()?;
    let spline = input.solve()?;
    Ok(to_line(&LcgAnswer::new(
        SplineReport::new(&spline, input.alpha, n)?,
        spline.pieces(),
    )))
}

/// The shapes `/api/lcg` reads, for error messages.
const LCG_SHAPES: &str = r#"{"pieces":[{"points":[[x,y]×4],"weights":[w0,w1,w2,w3]},…],"samples":N} (N per piece), or a segment or compound curve with "samples""#;

/// `POST /api/lcg`: the curvature plot and logarithmic curvature graph of Bézier pieces
/// (`lac quasi` output) or of a log-aesthetic curve, as `lac lcg` prints it.
pub(crate) fn lcg(app: &App, text: &str) -> Result<String, ApiError> {
    let map = request::object(text, LCG_SHAPES)?;
    let samples: Option<usize> = request::optional(&map, "samples", "a count")?;
    if map.contains_key("pieces") {
        let pieces: PiecesInput = request::field_shape(&map, PiecesInput::SHAPE)?;
        let cubics = pieces.to_rational_cubics()?;
        let per_piece = samples.unwrap_or(64);
        let limit = app.limits.max_piece_points;
        if per_piece < 2 || per_piece.saturating_mul(cubics.len()) > limit {
            return Err(lac_io::json::ErrorBody::limit(format!(
                "{} pieces × {per_piece} samples each is outside what this server computes: \
                 give 2 or more samples per piece and at most {limit} in all",
                cubics.len()
            ))
            .into());
        }
        let plot = lac::curvature_plot(&cubics, per_piece)?;
        let report = LcgReport::new(&plot);
        // Any finite pieces are accepted, but their curvature (and its derivative, up to a
        // fifth power of the coordinates) leaves the range of a double when the coordinates
        // are extreme: the request's numbers, not a defect.
        if !report.is_finite() {
            return Err(lac_io::json::ErrorBody::new(
                "out_of_range",
                "the curvature of these pieces overflows double precision (coordinates or \
                 weights too large or too small); scale the pieces toward unit size",
            )
            .into());
        }
        return Ok(to_line(&report));
    }
    let n = app.limits.samples(samples)?;
    let solved = request::curve(&map)?.solve()?;
    Ok(to_line(&plot(solved.curve(), n)?))
}
