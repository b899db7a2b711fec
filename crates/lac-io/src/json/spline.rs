//! G2 splines through points: [`SplineInput`], what makes one, and [`SplineReport`], what
//! `lac spline` prints.

use kurbo::Point;
use lac::{Closure, Curve, Spline};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use lac_export::{spline_pieces, ExportCurve};

use super::kind::{fields, Kind};
use super::{all_finite, point, xy, ErrorBody, Report, SampleRow, Xy};

/// A spline's points, slope, closure and end tangents, as `lac spline` takes them.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineInput {
    /// The points it passes through.
    pub points: Vec<Point>,
    /// The slope of every segment.
    pub alpha: f64,
    /// Whether it is closed.
    pub closed: bool,
    /// An open spline's end tangent directions, radians (default: those of the circles
    /// through its first and last three points).
    pub ends: Option<[f64; 2]>,
}

impl SplineInput {
    /// Solve it.
    pub fn solve(&self) -> Result<Spline, ErrorBody> {
        let closure = if self.closed {
            Closure::Closed
        } else {
            Closure::Open
        };
        Ok(Spline::from_points(
            &self.points,
            self.alpha,
            closure,
            self.ends,
        )?)
    }
}

/// One piece of a spline through points: the segment of a span, or one half of a span
/// through an inflection.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplinePieceRow {
    /// The span it belongs to (span i runs from point i to the next).
    pub span: usize,
    /// Its control triangle: the point it starts at, the tangents' intersection, the point
    /// it ends at (a hair short of the inflection, for a half).
    pub control_points: [Xy; 3],
    /// Λ of its standard-form piece.
    pub lambda: f64,
    /// Arc length.
    pub arc_length: f64,
    /// Signed curvature at its start and end.
    pub curvature: [f64; 2],
}

/// Where a span of a spline passes through an inflection.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplineInflectionRow {
    /// The span.
    pub span: usize,
    /// The inflection point.
    pub point: Xy,
    /// Signed curvature of the two halves where they meet (zero within 1e-9 of the
    /// spline's largest |κ| at a point).
    pub curvature: [f64; 2],
}

/// A solved G2 spline through points: `lac spline`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplineReport {
    /// Whether it is closed.
    pub closed: bool,
    /// The slope of every segment.
    pub alpha: f64,
    /// Arc length of the whole spline.
    pub arc_length: f64,
    /// The largest relative curvature jump at a joint.
    pub max_curvature_jump: f64,
    /// The points it passes through.
    pub points: Vec<Xy>,
    /// The tangent direction at each point, radians.
    pub angles: Vec<f64>,
    /// The pieces in order: one per span, two for a span through an inflection.
    pub pieces: Vec<SplinePieceRow>,
    /// The inflections (only for alpha < 0), in order.
    pub inflections: Vec<SplineInflectionRow>,
    /// The relative curvature jump measured at each joint.
    pub curvature_jumps: Vec<f64>,
    /// Samples equally spaced in arc length over the whole spline.
    pub samples: Vec<SampleRow>,
}

impl SplineReport {
    /// The report of `spline` with `n` samples.
    pub fn new(spline: &lac::Spline, alpha: f64, n: usize) -> Result<Self, ErrorBody> {
        let samples = spline.sample_by_arc_length(n)?;
        SplineReport {
            closed: spline.is_closed(),
            alpha,
            arc_length: spline.arc_length(),
            max_curvature_jump: spline.max_curvature_jump(),
            points: spline.points().iter().map(|&p| xy(p)).collect(),
            angles: spline.angles().to_vec(),
            pieces: spline
                .pieces()
                .iter()
                .zip(spline.control_triangles())
                .zip(spline.spans_of_pieces())
                .map(|((seg, tri), &span)| SplinePieceRow {
                    span,
                    control_points: tri.map(xy),
                    lambda: seg.lambda(),
                    arc_length: seg.arc_length(),
                    curvature: [seg.signed_curvature_start(), seg.signed_curvature_end()],
                })
                .collect(),
            inflections: spline
                .inflections()
                .iter()
                .map(|f| SplineInflectionRow {
                    span: f.span,
                    point: xy(f.point),
                    curvature: f.curvatures,
                })
                .collect(),
            curvature_jumps: spline.curvature_jumps().to_vec(),
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }
}

impl SplineReport {
    /// The spline it reports, as an input: its points, slope and closure, and an open one's
    /// end tangents.
    pub fn input(&self) -> SplineInput {
        let ends = match (self.closed, self.angles.first(), self.angles.last()) {
            (false, Some(&a), Some(&b)) => Some([a, b]),
            _ => None,
        };
        SplineInput {
            points: self.points.iter().map(|&p| point(p)).collect(),
            alpha: self.alpha,
            closed: self.closed,
            ends,
        }
    }
}

/// A spline through points: `lac spline`'s result, told by its `"pieces"` and `"angles"`,
/// solved again through its points with its end tangents.
pub struct SplineKind;

impl Kind for SplineKind {
    const NAME: &'static str = "spline";
    type Curve = Spline;

    fn claims(document: &Map<String, Value>) -> bool {
        document.contains_key("pieces") && document.contains_key("angles")
    }

    fn solve(document: Map<String, Value>) -> Result<Spline, ErrorBody> {
        let report: SplineReport =
            fields(document, "a lac spline result", "what lac spline prints")?;
        report.input().solve()
    }

    /// Piece by piece, like a path: every point, and the two halves of a span through an
    /// inflection (with the straight piece where they are flat), is a knot.
    fn export(spline: &Spline) -> Result<ExportCurve<'_>, ErrorBody> {
        Ok(ExportCurve::pieces(
            Self::NAME,
            spline.arc_length(),
            "G2",
            spline_pieces(spline)?,
        ))
    }
}

impl Report for SplineReport {
    fn is_finite(&self) -> bool {
        all_finite([self.arc_length, self.max_curvature_jump, self.alpha])
            && all_finite(self.points.iter().flatten().copied())
            && all_finite(self.angles.iter().copied())
            && all_finite(self.curvature_jumps.iter().copied())
            && self.pieces.iter().all(|g| {
                all_finite([g.lambda, g.arc_length, g.curvature[0], g.curvature[1]])
                    && all_finite(g.control_points.iter().flatten().copied())
            })
            && self
                .inflections
                .iter()
                .all(|f| all_finite(f.point.iter().copied().chain(f.curvature.iter().copied())))
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}
