//! A log-aesthetic curve of either kind the commands take: a segment (three points and α)
//! or a compound-rhythm curve (two pieces, α0 and α1).

use lac::Curve;
use lac::{CompoundCurve, CurvaturePoint, QuasiCurve, Sample, Segment};

/// A segment or a compound curve, for the commands that treat both alike.
#[derive(Clone, Debug)]
pub(crate) enum Lac {
    /// One segment (seed 000).
    Segment(Segment),
    /// A compound-rhythm curve (seeds 004 and 002).
    Compound(CompoundCurve),
}

/// Which Bézier replacement [`Lac::quasi`] makes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Fit {
    /// The single rational cubic of seed 001.
    One,
    /// Rational cubics within a tolerance (relative to the arc length).
    Rational(f64),
    /// Plain cubics within a tolerance.
    Cubic(f64),
}

impl Lac {
    /// The log-aesthetic pieces in order from the first point: one, or two.
    pub(crate) fn pieces(&self) -> &[Segment] {
        match self {
            Lac::Segment(segment) => std::slice::from_ref(segment),
            Lac::Compound(curve) => curve.pieces(),
        }
    }

    /// Arc length from the first to the last point.
    pub(crate) fn arc_length(&self) -> f64 {
        match self {
            Lac::Segment(segment) => segment.arc_length(),
            Lac::Compound(curve) => curve.arc_length(),
        }
    }

    /// Arc length from the first point to the joint of a compound curve.
    pub(crate) fn joint_s(&self) -> Option<f64> {
        match self {
            Lac::Segment(_) => None,
            Lac::Compound(curve) => Some(curve.joint_s()),
        }
    }

    /// `n ≥ 2` samples equally spaced in arc length over the whole curve.
    pub(crate) fn sample_by_arc_length(&self, n: usize) -> lac::Result<Vec<Sample>> {
        match self {
            Lac::Segment(segment) => segment.sample_by_arc_length(n),
            Lac::Compound(curve) => curve.sample_by_arc_length(n),
        }
    }

    /// `n ≥ 2` curvature points equally spaced in arc length, with the exact dκ/ds.
    pub(crate) fn curvature_plot(&self, n: usize) -> lac::Result<Vec<CurvaturePoint>> {
        match self {
            Lac::Segment(segment) => segment.curvature_plot(n),
            Lac::Compound(curve) => curve.curvature_plot(n),
        }
    }

    /// The Bézier replacement asked for by `fit`.
    pub(crate) fn quasi(&self, fit: Fit) -> lac::Result<QuasiCurve> {
        match (self, fit) {
            (Lac::Segment(s), Fit::One) => s.to_rational_cubic(),
            (Lac::Segment(s), Fit::Rational(tol)) => s.to_rational_cubics(tol),
            (Lac::Segment(s), Fit::Cubic(tol)) => s.to_cubics(tol),
            (Lac::Compound(c), Fit::One) => c.to_rational_cubic(),
            (Lac::Compound(c), Fit::Rational(tol)) => c.to_rational_cubics(tol),
            (Lac::Compound(c), Fit::Cubic(tol)) => c.to_cubics(tol),
        }
    }
}
