//! `/api/quasi`: a curve replaced by (rational) cubic Bézier pieces (seed 001), with the
//! exact curve, each piece's samples for its curvature comb, and both curvature plots.

use kurbo::Vec2;
use lac::{Curve, RationalCubic};
use lac_io::json::{to_line, CurveInput, ErrorBody, QuasiInput, QuasiReport, Report, SampleRow};
use serde::Serialize;

use super::curve::{compound_answer, segment_answer, CurveAnswer};
use super::request;
use super::App;
use crate::error::ApiError;

/// The exact curve, either kind.
#[derive(Debug, Serialize)]
#[serde(untagged)]
enum ExactCurve {
    Segment(CurveAnswer<lac_io::json::SegmentReport>),
    Compound(CurveAnswer<lac_io::json::CompoundReport>),
}

/// `{…QuasiReport…, "curve":{…}, "piece_samples":[[SampleRow…]…], "piece_plot":LcgReport}`.
#[derive(Debug, Serialize)]
struct QuasiAnswer {
    #[serde(flatten)]
    report: QuasiReport,
    /// The log-aesthetic curve the pieces replace, with its plot.
    curve: ExactCurve,
    /// Each piece sampled equally in its parameter t (first and last at its ends), with
    /// the arc length along the chain and the tangent direction continuous from the start.
    piece_samples: Vec<Vec<SampleRow>>,
    /// The curvature plot and logarithmic curvature graph of the chain of pieces.
    piece_plot: lac_io::json::LcgReport,
}

/// The shape, for error messages.
const SHAPE: &str = r#"{"points":[[x,y]×3],"alpha":A,"tolerance":T,"cubic":false,"samples":N} or a compound curve's fields ("alpha0","alpha1", "ratio" for three points) instead of "alpha""#;

/// `POST /api/quasi`.
pub(crate) fn quasi(app: &App, text: &str) -> Result<String, ApiError> {
    let map = request::object(text, SHAPE)?;
    let input = QuasiInput {
        curve: request::curve(&map)?,
        tolerance: request::optional(&map, "tolerance", "a relative tolerance")?,
        cubic: request::optional(&map, "cubic", "true or false")?.unwrap_or(false),
    };
    let n = app
        .limits
        .samples(request::optional(&map, "samples", "a count")?)?;
    let (solved, quasi) = input.solve()?;
    let curve = solved.curve();
    let report =
        QuasiReport::new(&quasi, curve.arc_length(), input.tolerance, input.cubic).checked()?;
    let exact = match &input.curve {
        CurveInput::Segment(s) => ExactCurve::Segment(segment_answer(s, n)?),
        CurveInput::Compound(c) => ExactCurve::Compound(compound_answer(c, n)?),
    };
    let cubics: Vec<RationalCubic> = quasi.pieces.iter().map(|p| p.curve).collect();
    // Enough points per piece to draw it, few enough for a chain of many pieces.
    let per_piece = (app.limits.max_piece_points / cubics.len().max(1)).clamp(2, 65);
    let piece_plot = lac::curvature_plot(&cubics, per_piece)?;
    let theta0 = curve.theta_at_s(0.0)?;
    let piece_samples = piece_samples(&cubics, &piece_plot, per_piece, theta0);
    let answer = QuasiAnswer {
        report,
        curve: exact,
        piece_samples,
        piece_plot: lac_io::json::LcgReport::new(&piece_plot).checked()?,
    };
    if answer.piece_samples.iter().flatten().all(|r| {
        [r.s, r.x, r.y, r.theta, r.kappa]
            .iter()
            .all(|v| v.is_finite())
    }) {
        Ok(to_line(&answer))
    } else {
        Err(ErrorBody::new(
            "internal",
            "a Bézier sample is not finite; please report this input",
        )
        .into())
    }
}

/// The samples of each piece, from the chain's curvature plot (`per_piece` points per
/// piece, consecutive pieces sharing their end point) and the tangent at each t, with the
/// direction unwrapped to stay continuous from `theta0`.
fn piece_samples(
    cubics: &[RationalCubic],
    plot: &[lac::CurvaturePoint],
    per_piece: usize,
    theta0: f64,
) -> Vec<Vec<SampleRow>> {
    let mut theta = theta0;
    cubics
        .iter()
        .enumerate()
        .map(|(k, cubic)| {
            (0..per_piece)
                .map(|i| {
                    let t = i as f64 / (per_piece - 1) as f64;
                    let p = &plot[k * (per_piece - 1) + i];
                    theta = unwrap(theta, cubic.derivative(t));
                    SampleRow {
                        s: p.s,
                        x: p.point.x,
                        y: p.point.y,
                        theta,
                        kappa: p.kappa,
                    }
                })
                .collect()
        })
        .collect()
}

/// The direction of `d`, within π of `previous`.
fn unwrap(previous: f64, d: Vec2) -> f64 {
    let angle = d.atan2();
    let turns = ((previous - angle) / std::f64::consts::TAU).round();
    angle + turns * std::f64::consts::TAU
}
