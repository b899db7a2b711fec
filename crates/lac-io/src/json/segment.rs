//! Segments (seed 000): [`SegmentInput`], three control points and α, and
//! [`SegmentReport`], what `lac segment` prints. The `--batch` fast path that reads and
//! writes these without serde is in `fast.rs`.

use lac::{Curve, Segment};
use serde::{Deserialize, Serialize};

use lac_export::ExportCurve;

use super::kind::{fields, Kind};
use super::{all_finite, point, xy, ErrorBody, Report, SampleRow, Xy};
use serde_json::{Map, Value};

/// A segment from three control points and α (seed 000): `{"points":[[x,y]×3],"alpha":A}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SegmentInput {
    /// P0 (start), P1 (the end tangents' intersection), P2 (end).
    pub points: [Xy; 3],
    /// The slope α of the logarithmic curvature graph.
    pub alpha: f64,
}

impl SegmentInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha":A}"#;

    /// Solve it.
    pub fn solve(&self) -> Result<Segment, ErrorBody> {
        Ok(Segment::from_control_points(
            self.points.map(point),
            self.alpha,
        )?)
    }
}

/// A solved segment: `lac segment`'s JSON and each good line of its `--batch`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SegmentReport {
    /// The slope of the logarithmic curvature graph.
    pub alpha: f64,
    /// Λ of the solved standard-form piece.
    pub lambda: f64,
    /// Arc length from the first to the last control point.
    pub arc_length: f64,
    /// Signed curvature (+ for a left turn) at the first control point.
    pub curvature_start: f64,
    /// Signed curvature at the last control point.
    pub curvature_end: f64,
    /// Turning angle of the control polygon, radians, in (0, π).
    pub turning_angle: f64,
    /// The control points as given.
    pub points: [Xy; 3],
    /// Samples equally spaced in arc length, first and last at the end points.
    pub samples: Vec<SampleRow>,
}

impl SegmentReport {
    /// The report of `segment` with `n` samples.
    pub fn new(segment: &Segment, n: usize) -> Result<Self, ErrorBody> {
        Self::of_input(segment, n, segment.control_points().map(xy))
    }

    /// The report of `segment` with `n` samples, and with the control points exactly as the
    /// caller gave them (`points`: the solved segment's own are within rounding of them, and
    /// are not computed).
    pub fn of_input(segment: &Segment, n: usize, points: [Xy; 3]) -> Result<Self, ErrorBody> {
        let samples = segment.sample_by_arc_length(n)?;
        SegmentReport {
            alpha: segment.alpha(),
            lambda: segment.lambda(),
            arc_length: segment.arc_length(),
            curvature_start: segment.signed_curvature_start(),
            curvature_end: segment.signed_curvature_end(),
            turning_angle: segment.turning_angle(),
            points,
            // (In place: a sample and a row are the same size.)
            samples: samples.into_iter().map(SampleRow::from).collect(),
        }
        .checked()
    }

    /// The report with the control points exactly as the caller gave them (the solved
    /// segment's own are within rounding of them).
    pub fn with_points(mut self, points: [Xy; 3]) -> Self {
        self.points = points;
        self
    }
}

impl Report for SegmentReport {
    fn is_finite(&self) -> bool {
        all_finite([
            self.alpha,
            self.lambda,
            self.arc_length,
            self.curvature_start,
            self.curvature_end,
            self.turning_angle,
        ]) && all_finite(self.points.iter().flatten().copied())
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}

/// A segment from three control points and α: a document with `"alpha"` (and none of the
/// keys that a kind asked before claims).
pub struct SegmentKind;

impl Kind for SegmentKind {
    const NAME: &'static str = "segment";
    type Curve = Segment;

    fn claims(document: &Map<String, Value>) -> bool {
        document.contains_key("alpha")
    }

    fn solve(document: Map<String, Value>) -> Result<Segment, ErrorBody> {
        fields::<SegmentInput>(document, "a segment", SegmentInput::SHAPE)?.solve()
    }

    fn export(segment: &Segment) -> Result<ExportCurve<'_>, ErrorBody> {
        Ok(ExportCurve::whole(Self::NAME, segment))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::{parse, to_line, CurveInput};

    #[test]
    fn a_segment_report_reads_back_as_its_input() {
        let input: SegmentInput = parse(
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":0.5}"#,
            SegmentInput::SHAPE,
        )
        .unwrap();
        let report = SegmentReport::new(&input.solve().unwrap(), 5)
            .unwrap()
            .with_points(input.points);
        let line = to_line(&report);
        let back: CurveInput = parse(&line, "a curve").unwrap();
        assert_eq!(back, CurveInput::Segment(input));
    }
}
