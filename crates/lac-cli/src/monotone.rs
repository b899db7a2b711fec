//! `lac monotone`: is the curvature of a (rational) cubic Bézier curve monotone? The
//! library's decision with a proof (seed 001 §5, SPEC §5).

use kurbo::Point;
use lac::RationalCubic;
use serde::Serialize;

use crate::cli::MonotoneArgs;
use crate::failure::Failure;
use crate::output::write_to;
use crate::points::{parse_point_list, parse_weights};
use crate::quasi::sign_change;

/// What `lac monotone` prints.
#[derive(Debug, Serialize)]
struct MonotoneReport {
    /// increasing, decreasing, constant or not_monotone.
    verdict: &'static str,
    /// Whether the verdict is proven for the exact curve the numbers describe.
    proven: bool,
    /// Not monotone: a parameter where dκ/ds changes sign.
    #[serde(skip_serializing_if = "Option::is_none")]
    t: Option<f64>,
}

/// Run `lac monotone`.
pub(crate) fn run(args: &MonotoneArgs) -> Result<(), Failure> {
    let points = parse_point_list(&args.points, &[4])?;
    let points: [Point; 4] = [points[0], points[1], points[2], points[3]];
    let weights = match &args.weights {
        Some(text) => parse_weights(text)?,
        None => [1.0; 4],
    };
    let report = RationalCubic::new(points, weights)?.curvature_monotonicity()?;
    let line = serde_json::to_string(&MonotoneReport {
        verdict: report.verdict.name(),
        proven: report.proven,
        t: sign_change(report.verdict),
    })
    .expect("a report of numbers always serializes");
    write_to(None, |out| writeln!(out, "{line}"))
}
