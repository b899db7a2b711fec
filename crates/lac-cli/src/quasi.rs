//! `lac quasi`: a segment or compound curve replaced by rational (or plain) cubic Bézier
//! pieces (seed 001, SPEC §5), as JSON or drawn over the curve.

use kurbo::Point;
use lac::{Monotonicity, QuasiCurve, QuasiPiece, Segment};
use serde::Serialize;

use crate::cli::{QuasiArgs, QuasiFormat};
use crate::compound;
use crate::curve::{Fit, Lac};
use crate::failure::Failure;
use crate::output::write_to;
use crate::points::parse_points;
use crate::svg;

/// What `lac quasi --format json` prints.
#[derive(Debug, Serialize)]
struct QuasiReport {
    /// The pieces in order from the first control point.
    pieces: Vec<PieceRow>,
    /// Root mean square deviation, relative to the arc length.
    rms: f64,
    /// Largest deviation, relative to the arc length.
    max: f64,
    /// Arc length of the log-aesthetic curve.
    arc_length: f64,
    /// `--tolerance` as given; `null` for the single piece of seed 001.
    tolerance: Option<f64>,
    /// "rational" or "cubic" (all weights 1).
    kind: &'static str,
}

/// One Bézier piece.
#[derive(Debug, Serialize)]
struct PieceRow {
    /// Control points b0..b3.
    points: [[f64; 2]; 4],
    /// Weights w0..w3.
    weights: [f64; 4],
    /// How its curvature varies: increasing, decreasing, constant, not_monotone.
    monotone: &'static str,
    /// Whether `monotone` is proven for the exact curve the numbers describe.
    proven: bool,
    /// Not monotone: a parameter where dκ/ds changes sign.
    #[serde(skip_serializing_if = "Option::is_none")]
    t: Option<f64>,
    /// The turning of the log-aesthetic curve at the piece's ends, radians from its start.
    turning: [f64; 2],
    /// Largest distance to the log-aesthetic curve over the piece, in the points' units.
    max_deviation: f64,
}

impl From<&QuasiPiece> for PieceRow {
    fn from(p: &QuasiPiece) -> Self {
        let verdict = p.monotonicity.verdict;
        PieceRow {
            points: p.curve.points().map(|b| [b.x, b.y]),
            weights: p.curve.weights(),
            monotone: verdict.name(),
            proven: p.monotonicity.proven,
            t: sign_change(verdict),
            turning: [p.turning.0, p.turning.1],
            max_deviation: p.max_deviation,
        }
    }
}

/// The parameter where dκ/ds changes sign, for a verdict that has one.
pub(crate) fn sign_change(verdict: Monotonicity) -> Option<f64> {
    match verdict {
        Monotonicity::NotMonotone { t } => Some(t),
        _ => None,
    }
}

/// Run `lac quasi`.
///
/// The whole result is computed before the output file is created, so a failed run leaves
/// an existing file untouched.
pub(crate) fn run(args: &QuasiArgs) -> Result<(), Failure> {
    let (curve, points) = solve(args)?;
    let fit = match (args.tolerance, args.cubic) {
        (None, _) => Fit::One,
        (Some(tol), false) => Fit::Rational(tol),
        (Some(tol), true) => Fit::Cubic(tol),
    };
    let quasi = curve.quasi(fit)?;
    let document = match args.format {
        QuasiFormat::Json => to_json_line(&curve, &quasi, args) + "\n",
        QuasiFormat::Svg => {
            let comb = curve.sample_by_arc_length(svg::quasi::LAC_SAMPLES)?;
            svg::quasi::render(curve.pieces(), &points, &comb, &quasi, args.cubic)?
        }
    };
    write_to(args.file.as_deref(), |out| {
        out.write_all(document.as_bytes())
    })
}

/// The curve for `--points` with `--alpha`, or with `--alpha0`, `--alpha1` (and `--ratio`).
fn solve(args: &QuasiArgs) -> Result<(Lac, Vec<Point>), Failure> {
    match (args.alpha, args.alpha0, args.alpha1) {
        (Some(alpha), None, None) => {
            let points = parse_points(&args.points)?;
            let segment = Segment::from_control_points(points, alpha)?;
            Ok((Lac::Segment(segment), points.to_vec()))
        }
        (None, Some(alpha0), Some(alpha1)) => {
            let (curve, points) =
                compound::from_arguments(&args.points, alpha0, alpha1, args.ratio)?;
            Ok((Lac::Compound(curve), points))
        }
        _ => Err(Failure::usage(
            "give --alpha for a segment, or --alpha0 and --alpha1 (and --ratio for three \
             points) for a compound curve",
        )),
    }
}

fn to_json_line(curve: &Lac, quasi: &QuasiCurve, args: &QuasiArgs) -> String {
    let report = QuasiReport {
        pieces: quasi.pieces.iter().map(PieceRow::from).collect(),
        rms: quasi.rms,
        max: quasi.max,
        arc_length: curve.arc_length(),
        tolerance: args.tolerance,
        kind: if args.cubic { "cubic" } else { "rational" },
    };
    serde_json::to_string(&report).expect("a report of numbers always serializes")
}
