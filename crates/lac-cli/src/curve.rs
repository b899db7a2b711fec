//! A log-aesthetic curve of either kind the commands take: a segment (three points and α)
//! or a compound-rhythm curve (two pieces, α0 and α1).

use lac::Curve;
use lac::{CompoundCurve, CurvaturePoint, QuasiCurve, Sample, Segment, Tolerance};

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
    /// The curve, whatever its kind.
    pub(crate) fn curve(&self) -> &dyn Curve {
        match self {
            Lac::Segment(segment) => segment,
            Lac::Compound(curve) => curve,
        }
    }

    /// The log-aesthetic pieces in order from the first point: one, or two.
    pub(crate) fn pieces(&self) -> &[Segment] {
        self.curve().pieces()
    }

    /// Arc length from the first to the last point.
    pub(crate) fn arc_length(&self) -> f64 {
        self.curve().arc_length()
    }

    /// Arc length from the first point to the joint of a compound curve.
    pub(crate) fn joint_s(&self) -> Option<f64> {
        self.curve().joints().first().copied()
    }

    /// `n ≥ 2` samples equally spaced in arc length over the whole curve.
    pub(crate) fn sample_by_arc_length(&self, n: usize) -> lac::Result<Vec<Sample>> {
        self.curve().sample_by_arc_length(n)
    }

    /// `n ≥ 2` curvature points equally spaced in arc length, with the exact dκ/ds.
    pub(crate) fn curvature_plot(&self, n: usize) -> lac::Result<Vec<CurvaturePoint>> {
        self.curve().curvature_plot(n)
    }

    /// The Bézier replacement asked for by `fit`.
    pub(crate) fn quasi(&self, fit: Fit) -> lac::Result<QuasiCurve> {
        match fit {
            Fit::One => self.curve().to_rational_cubic(),
            Fit::Rational(tol) => self.curve().to_rational_cubics(Tolerance::Relative(tol)),
            Fit::Cubic(tol) => self.curve().to_cubics(Tolerance::Relative(tol)),
        }
    }
}
