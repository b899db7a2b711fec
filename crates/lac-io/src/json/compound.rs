//! Compound-rhythm curves (seeds 004 and 002): [`CompoundInput`] and [`CompoundReport`],
//! what `lac compound` reads and prints, and either kind of planar curve: [`CurveInput`]
//! (a segment's or a compound curve's fields) and the [`Solved`] curve.

use lac::{CompoundCurve, Curve, LcgLine, Segment, SegmentChain};
use serde::{Deserialize, Serialize};

use lac_export::ExportCurve;

use super::kind::{fields, Kind};
use super::SegmentKind;
use super::{all_finite, point, xy, ErrorBody, Report, SampleRow, SegmentInput, Xy};
use serde_json::{Map, Value};

/// A compound-rhythm curve (seeds 004 and 002): three points with `ratio`, or four points
/// without: `{"points":[…],"alpha0":A,"alpha1":B,"ratio":R}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CompoundInput {
    /// Three points (ends and the end tangents' intersection) or four control points.
    pub points: Vec<Xy>,
    /// Slope of the piece from the first point.
    pub alpha0: f64,
    /// Slope of the piece to the last point.
    pub alpha1: f64,
    /// Share of the turning made by the α0 piece (three points only).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
}

impl CompoundInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha0":A,"alpha1":B,"ratio":R} or {"points":[[x,y],[x,y],[x,y],[x,y]],"alpha0":A,"alpha1":B}"#;

    /// Solve it.
    pub fn solve(&self) -> Result<CompoundCurve, ErrorBody> {
        let p = &self.points;
        match (p.len(), self.ratio) {
            (3, Some(ratio)) => Ok(CompoundCurve::from_three_points(
                [point(p[0]), point(p[1]), point(p[2])],
                self.alpha0,
                self.alpha1,
                ratio,
            )?),
            (4, None) => Ok(CompoundCurve::from_four_points(
                [point(p[0]), point(p[1]), point(p[2]), point(p[3])],
                self.alpha0,
                self.alpha1,
            )?),
            (3, None) => Err(ErrorBody::invalid_input(
                "three points need a ratio (the share of the turning made by the alpha0 \
                 piece, between 0 and 1); or give four control points",
            )),
            (4, Some(_)) => Err(ErrorBody::invalid_input(
                "four control points fix the joint's tangent; a ratio applies to three \
                 points only: drop it",
            )),
            (n, _) => Err(ErrorBody::invalid_input(format!(
                "a compound curve takes three points (with a ratio) or four, not {n}"
            ))),
        }
    }
}

/// Either kind of planar log-aesthetic curve: a [`SegmentInput`] (with `alpha`) or a
/// [`CompoundInput`] (with `alpha0` and `alpha1`). Other fields are ignored, so a report
/// reads back as the input it was solved from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum CurveInput {
    /// A segment.
    Segment(SegmentInput),
    /// A compound curve.
    Compound(CompoundInput),
}

/// A solved planar curve of either kind.
#[derive(Clone, Debug)]
pub enum Solved {
    /// A segment.
    Segment(Segment),
    /// A compound curve.
    Compound(CompoundCurve),
}

impl Solved {
    /// The curve, whatever its kind.
    pub fn curve(&self) -> &dyn SegmentChain {
        match self {
            Solved::Segment(s) => s,
            Solved::Compound(c) => c,
        }
    }
}

impl Solved {
    /// The curve for CAD export.
    pub fn export_curve(&self) -> ExportCurve<'_> {
        match self {
            Solved::Segment(s) => ExportCurve::whole(SegmentKind::NAME, s),
            Solved::Compound(c) => ExportCurve::whole(CompoundKind::NAME, c),
        }
    }
}

impl CurveInput {
    /// Solve it.
    pub fn solve(&self) -> Result<Solved, ErrorBody> {
        match self {
            CurveInput::Segment(s) => s.solve().map(Solved::Segment),
            CurveInput::Compound(c) => c.solve().map(Solved::Compound),
        }
    }

    /// The control points as given.
    pub fn points(&self) -> Vec<Xy> {
        match self {
            CurveInput::Segment(s) => s.points.to_vec(),
            CurveInput::Compound(c) => c.points.clone(),
        }
    }
}

/// One piece's logarithmic curvature graph: log(ρ ds/dρ) = alpha log ρ + intercept over
/// log ρ ∈ log_rho (natural logarithms, in the order of travel).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LcgRow {
    /// The slope α of the piece.
    pub alpha: f64,
    /// log(ρ ds/dρ) at log ρ = 0.
    pub intercept: f64,
    /// The range of log ρ covered by the piece, [from, to] in the order of travel.
    pub log_rho: [f64; 2],
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

/// A solved compound curve: `lac compound`'s JSON and each good line of its `--batch`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CompoundReport {
    /// The slope of the piece from the first point to the joint.
    pub alpha0: f64,
    /// The slope of the piece from the joint to the last point.
    pub alpha1: f64,
    /// The share of the turning made by the α0 piece, as given (three-point form only).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
    /// Λ of the joint-reference standard form (ρ = 1 at the joint).
    pub lambda: f64,
    /// Arc length from the first to the last point.
    pub arc_length: f64,
    /// Arc length from the first point to the joint.
    pub joint_s: f64,
    /// Signed curvature (+ for a left turn) at the first point.
    pub curvature_start: f64,
    /// Signed curvature at the joint (the same from both pieces: G2 and G3 there).
    pub curvature_joint: f64,
    /// Signed curvature at the last point.
    pub curvature_end: f64,
    /// Total turning of the control polygon, radians, in (0, 2π) (below π for three points).
    pub turning_angle: f64,
    /// The joint.
    pub joint: Xy,
    /// The logarithmic curvature graph of each piece; `null` for a circular arc.
    pub lcg: [Option<LcgRow>; 2],
    /// The control points as given: three, or four.
    pub points: Vec<Xy>,
    /// Samples equally spaced in arc length over the whole curve.
    pub samples: Vec<SampleRow>,
}

impl CompoundReport {
    /// The report of `curve`, solved from `input`, with `n` samples.
    pub fn new(curve: &CompoundCurve, input: &CompoundInput, n: usize) -> Result<Self, ErrorBody> {
        let samples = curve.sample_by_arc_length(n)?;
        let [alpha0, alpha1] = curve.alpha();
        CompoundReport {
            alpha0,
            alpha1,
            ratio: input.ratio,
            lambda: curve.lambda(),
            arc_length: curve.arc_length(),
            joint_s: curve.joint_s(),
            curvature_start: curve.signed_curvature_start(),
            curvature_joint: curve.signed_curvature_joint(),
            curvature_end: curve.signed_curvature_end(),
            turning_angle: curve.turning().abs(),
            joint: xy(curve.joint()),
            lcg: curve.lcg().map(|line| line.map(LcgRow::from)),
            points: input.points.clone(),
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }
}

impl Report for CompoundReport {
    fn is_finite(&self) -> bool {
        all_finite([
            self.alpha0,
            self.alpha1,
            self.ratio.unwrap_or(0.0),
            self.lambda,
            self.arc_length,
            self.joint_s,
            self.curvature_start,
            self.curvature_joint,
            self.curvature_end,
            self.turning_angle,
        ]) && all_finite(self.joint)
            && self
                .lcg
                .iter()
                .flatten()
                .all(|l| all_finite([l.alpha, l.intercept, l.log_rho[0], l.log_rho[1]]))
            && all_finite(self.points.iter().flatten().copied())
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}

/// A compound-rhythm curve: a document with `"alpha0"` or `"alpha1"`.
pub struct CompoundKind;

impl Kind for CompoundKind {
    const NAME: &'static str = "compound";
    type Curve = CompoundCurve;

    fn claims(document: &Map<String, Value>) -> bool {
        document.contains_key("alpha0") || document.contains_key("alpha1")
    }

    fn solve(document: Map<String, Value>) -> Result<CompoundCurve, ErrorBody> {
        fields::<CompoundInput>(document, "a compound curve", CompoundInput::SHAPE)?.solve()
    }

    fn export(curve: &CompoundCurve) -> Result<ExportCurve<'_>, ErrorBody> {
        Ok(ExportCurve::whole(Self::NAME, curve))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compound_inputs_say_what_is_missing() {
        let three = CompoundInput {
            points: vec![[0.0, 0.0], [2.0, 0.0], [2.6, 1.2]],
            alpha0: -1.0,
            alpha1: 2.0,
            ratio: None,
        };
        assert!(three.solve().unwrap_err().message.contains("ratio"));
        let curve = CompoundInput {
            ratio: Some(0.5),
            ..three
        };
        let report = CompoundReport::new(&curve.solve().unwrap(), &curve, 9).unwrap();
        assert_eq!(report.samples.len(), 9);
        assert!(report.is_finite());
    }
}
