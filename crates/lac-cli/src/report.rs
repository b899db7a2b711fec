//! The JSON result of one segment: its scalars and its samples, in the caller's frame.

use kurbo::Point;
use lac::{Sample, Segment};
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

    /// The samples as CSV with the header `s,x,y,theta,kappa`.
    ///
    /// Numbers use Rust's `{:?}` form: shortest round-trip, with an exponent for very small
    /// or large magnitudes.
    pub(crate) fn to_csv(&self) -> String {
        let mut out = String::from("s,x,y,theta,kappa\n");
        for r in &self.samples {
            out.push_str(&format!(
                "{:?},{:?},{:?},{:?},{:?}\n",
                r.s, r.x, r.y, r.theta, r.kappa
            ));
        }
        out
    }
}
