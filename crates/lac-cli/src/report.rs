//! The JSON result of one segment or compound curve: its scalars and its samples, in the
//! caller's frame.

use kurbo::Point;
use lac::Curve;
use lac::{CompoundCurve, LcgLine, Sample, Segment};
use serde::Serialize;

use crate::failure::Failure;

/// What `lac segment --format json` prints, and each good line of `--batch`.
///
/// Floats are written by serde_json as the shortest decimal that reads back to the same
/// `f64`.
#[derive(Debug, Serialize)]
pub(crate) struct SegmentReport {
    /// The slope of the logarithmic curvature graph.
    pub(crate) alpha: f64,
    /// Λ of the solved standard-form piece.
    pub(crate) lambda: f64,
    /// Arc length from the first to the last control point.
    pub(crate) arc_length: f64,
    /// Signed curvature (+ for a left turn) at the first control point.
    pub(crate) curvature_start: f64,
    /// Signed curvature at the last control point.
    pub(crate) curvature_end: f64,
    /// Turning angle of the control polygon, radians, in (0, π).
    pub(crate) turning_angle: f64,
    /// The control points as given.
    pub(crate) points: [[f64; 2]; 3],
    /// Samples equally spaced in arc length, first and last at the end points.
    pub(crate) samples: Vec<SampleRow>,
}

/// One sample: arc length, position, tangent direction (radians) and signed curvature.
#[derive(Debug, Serialize)]
pub(crate) struct SampleRow {
    /// Arc length from the first control point.
    pub(crate) s: f64,
    /// Position, x.
    pub(crate) x: f64,
    /// Position, y.
    pub(crate) y: f64,
    /// Tangent direction, radians, continuous from the first control point.
    pub(crate) theta: f64,
    /// Signed curvature, + for a left turn.
    pub(crate) kappa: f64,
}

impl From<&Sample> for SampleRow {
    fn from(s: &Sample) -> Self {
        SampleRow {
            s: s.s,
            x: s.point.x,
            y: s.point.y,
            theta: s.theta,
            kappa: s.kappa,
        }
    }
}

impl SegmentReport {
    /// Solve the segment for `points` and `alpha` and sample it at `n` arc lengths.
    pub(crate) fn solve(points: [Point; 3], alpha: f64, n: usize) -> Result<Self, Failure> {
        let segment = Segment::from_control_points(points, alpha)?;
        let samples = segment.sample_by_arc_length(n)?;
        Ok(SegmentReport {
            alpha,
            lambda: segment.lambda(),
            arc_length: segment.arc_length(),
            curvature_start: segment.curvature_start(),
            curvature_end: segment.curvature_end(),
            turning_angle: segment.turning_angle(),
            points: points.map(|p| [p.x, p.y]),
            samples: samples.iter().map(SampleRow::from).collect(),
        })
    }

    /// The report as one line of JSON, without a newline.
    pub(crate) fn to_json_line(&self) -> String {
        serde_json::to_string(self).expect("a report of numbers always serializes")
    }

    /// The samples as CSV (see [`samples_csv`]).
    pub(crate) fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

/// What `lac compound --format json` prints, and each good line of its `--batch`.
#[derive(Debug, Serialize)]
pub(crate) struct CompoundReport {
    /// The slope of the piece from the first point to the joint.
    pub(crate) alpha0: f64,
    /// The slope of the piece from the joint to the last point.
    pub(crate) alpha1: f64,
    /// The share of the turning made by the α0 piece, as given (three-point form only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) ratio: Option<f64>,
    /// Λ of the joint-reference standard form (ρ = 1 at the joint).
    pub(crate) lambda: f64,
    /// Arc length from the first to the last point.
    pub(crate) arc_length: f64,
    /// Arc length from the first point to the joint.
    pub(crate) joint_s: f64,
    /// Signed curvature (+ for a left turn) at the first point.
    pub(crate) curvature_start: f64,
    /// Signed curvature at the joint (the same from both pieces: G2 and G3 there).
    pub(crate) curvature_joint: f64,
    /// Signed curvature at the last point.
    pub(crate) curvature_end: f64,
    /// Total turning of the control polygon, radians, in (0, 2π) (below π for three points).
    pub(crate) turning_angle: f64,
    /// The joint.
    pub(crate) joint: [f64; 2],
    /// The logarithmic curvature graph of each piece; `null` for a circular arc.
    pub(crate) lcg: [Option<LcgRow>; 2],
    /// The control points as given: three, or four.
    pub(crate) points: Vec<[f64; 2]>,
    /// Samples equally spaced in arc length over the whole curve, first and last at the end
    /// points.
    pub(crate) samples: Vec<SampleRow>,
}

/// One piece's logarithmic curvature graph: log(ρ ds/dρ) = alpha log ρ + intercept over
/// log ρ ∈ log_rho (natural logarithms, in the order of travel).
#[derive(Debug, Serialize)]
pub(crate) struct LcgRow {
    /// The slope α of the piece.
    pub(crate) alpha: f64,
    /// log(ρ ds/dρ) at log ρ = 0.
    pub(crate) intercept: f64,
    /// The range of log ρ covered by the piece, [from, to] in the order of travel.
    pub(crate) log_rho: [f64; 2],
}

impl From<LcgLine> for LcgRow {
    fn from(line: LcgLine) -> Self {
        LcgRow {
            alpha: line.alpha,
            intercept: line.intercept,
            log_rho: [line.log_rho.0, line.log_rho.1],
        }
    }
}

impl CompoundReport {
    /// The report of `curve`, solved from `points` (and `ratio` for three points), sampled at
    /// `n` arc lengths.
    pub(crate) fn new(
        curve: &CompoundCurve,
        points: &[Point],
        ratio: Option<f64>,
        n: usize,
    ) -> Result<Self, Failure> {
        let samples = curve.sample_by_arc_length(n)?;
        let [alpha0, alpha1] = curve.alpha();
        let joint = curve.joint();
        let pieces = curve.pieces();
        Ok(CompoundReport {
            alpha0,
            alpha1,
            ratio,
            lambda: curve.lambda(),
            arc_length: curve.arc_length(),
            joint_s: curve.joint_s(),
            curvature_start: curve.curvature_start(),
            curvature_joint: curve.curvature_joint(),
            curvature_end: curve.curvature_end(),
            turning_angle: pieces[0].turning_angle() + pieces[1].turning_angle(),
            joint: [joint.x, joint.y],
            lcg: curve.lcg().map(|line| line.map(LcgRow::from)),
            points: points.iter().map(|p| [p.x, p.y]).collect(),
            samples: samples.iter().map(SampleRow::from).collect(),
        })
    }

    /// The report as one line of JSON, without a newline.
    pub(crate) fn to_json_line(&self) -> String {
        serde_json::to_string(self).expect("a report of numbers always serializes")
    }

    /// The samples as CSV (see [`samples_csv`]).
    pub(crate) fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

/// Samples as CSV with the header `s,x,y,theta,kappa`.
///
/// Numbers use Rust's `{:?}` form: shortest round-trip, with an exponent for very small or
/// large magnitudes.
fn samples_csv(samples: &[SampleRow]) -> String {
    let mut out = String::from("s,x,y,theta,kappa\n");
    for r in samples {
        out.push_str(&format!(
            "{:?},{:?},{:?},{:?},{:?}\n",
            r.s, r.x, r.y, r.theta, r.kappa
        ));
    }
    out
}
