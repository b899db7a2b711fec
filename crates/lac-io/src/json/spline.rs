//! G2 splines through points: [`SplineReport`], what `lac spline` prints.

use lac::Curve;
use lac::SegmentChain;
use serde::{Deserialize, Serialize};

use super::{all_finite, xy, ErrorBody, Report, SampleRow, Xy};

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
