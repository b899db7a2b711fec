//! Quasi-aesthetic replacements (seed 001): [`QuasiInput`] and [`QuasiReport`], what `lac
//! quasi` reads and prints, and the Bézier pieces it prints read back ([`PieceInput`],
//! [`PiecesInput`]), which `lac monotone` and `lac lcg` read too.

use lac::ToBezier;
use lac::{QuasiCurve, QuasiPiece, RationalCubic, Tolerance};
use serde::{Deserialize, Serialize};

use super::{all_finite, point, xy, CurveInput, ErrorBody, MonotoneReport, Report, Solved, Xy};

/// A quasi-aesthetic replacement of a curve (seed 001): the curve's fields, plus
/// `"tolerance"` (relative to the arc length; absent for the seed's single rational cubic)
/// and `"cubic"` (plain cubics, all weights 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuasiInput {
    /// The curve to replace.
    #[serde(flatten)]
    pub curve: CurveInput,
    /// Largest deviation, relative to the arc length.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub tolerance: Option<f64>,
    /// Plain cubics instead of rational ones.
    #[serde(default)]
    pub cubic: bool,
}

/// One (rational) cubic Bézier piece: `{"points":[[x,y]×4],"weights":[w0,w1,w2,w3]}`
/// (weights optional: a plain cubic).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PieceInput {
    /// Control points b0..b3.
    pub points: [Xy; 4],
    /// Weights w0..w3 (all 1 when absent).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub weights: Option<[f64; 4]>,
}

impl PieceInput {
    /// The rational cubic.
    pub fn to_rational_cubic(&self) -> Result<RationalCubic, ErrorBody> {
        Ok(RationalCubic::new(
            self.points.map(point),
            self.weights.unwrap_or([1.0; 4]),
        )?)
    }
}

/// A chain of Bézier pieces, `{"pieces":[…]}`: what `lac quasi` prints, read back.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PiecesInput {
    /// The pieces in order.
    pub pieces: Vec<PieceInput>,
}

impl PiecesInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"pieces":[{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]},…]}"#;

    /// The rational cubics.
    pub fn to_rational_cubics(&self) -> Result<Vec<RationalCubic>, ErrorBody> {
        if self.pieces.is_empty() {
            return Err(ErrorBody::invalid_input("no pieces given"));
        }
        self.pieces
            .iter()
            .map(PieceInput::to_rational_cubic)
            .collect()
    }
}

/// One Bézier piece of a [`QuasiReport`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuasiPieceRow {
    /// Control points b0..b3.
    pub points: [Xy; 4],
    /// Weights w0..w3.
    pub weights: [f64; 4],
    /// How its curvature varies: increasing, decreasing, constant, not_monotone.
    pub monotone: String,
    /// Whether `monotone` is proven for the exact curve the numbers describe.
    pub proven: bool,
    /// Not monotone: a parameter where dκ/ds changes sign.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub t: Option<f64>,
    /// The turning of the log-aesthetic curve at the piece's ends, radians from its start.
    pub turning: [f64; 2],
    /// Largest distance to the log-aesthetic curve over the piece, in the points' units.
    pub max_deviation: f64,
}

impl From<&QuasiPiece> for QuasiPieceRow {
    fn from(p: &QuasiPiece) -> Self {
        let m = MonotoneReport::from(&p.monotonicity);
        QuasiPieceRow {
            points: p.curve.points().map(xy),
            weights: p.curve.weights(),
            monotone: m.verdict,
            proven: m.proven,
            t: m.t,
            turning: [p.turning.0, p.turning.1],
            max_deviation: p.max_deviation,
        }
    }
}

/// A quasi-aesthetic replacement: `lac quasi`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuasiReport {
    /// The pieces in order from the first control point.
    pub pieces: Vec<QuasiPieceRow>,
    /// Root mean square deviation, relative to the arc length.
    pub rms: f64,
    /// Largest deviation, relative to the arc length.
    pub max: f64,
    /// Arc length of the log-aesthetic curve.
    pub arc_length: f64,
    /// The tolerance asked for (relative); `null` for the single piece of seed 001.
    pub tolerance: Option<f64>,
    /// `rational`, or `cubic` (all weights 1).
    pub kind: String,
}

impl QuasiReport {
    /// The report of `quasi`, the replacement of a curve of length `arc_length`.
    pub fn new(quasi: &QuasiCurve, arc_length: f64, tolerance: Option<f64>, cubic: bool) -> Self {
        QuasiReport {
            pieces: quasi.pieces.iter().map(QuasiPieceRow::from).collect(),
            rms: quasi.rms,
            max: quasi.max,
            arc_length,
            tolerance,
            kind: if cubic { "cubic" } else { "rational" }.to_string(),
        }
    }
}

impl Report for QuasiReport {
    fn is_finite(&self) -> bool {
        all_finite([self.rms, self.max, self.arc_length])
            && self.pieces.iter().all(|p| {
                all_finite(p.points.iter().flatten().copied())
                    && all_finite(p.weights)
                    && all_finite(p.turning)
                    && p.max_deviation.is_finite()
                    && p.t.is_none_or(f64::is_finite)
            })
    }
}

impl QuasiInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha":A,"tolerance":T,"cubic":false} (or a compound curve's fields instead of "alpha")"#;

    /// Solve the curve and replace it by Bézier pieces: the seed's single rational cubic
    /// without a tolerance, else rational (or, with `cubic`, plain) cubics within
    /// `tolerance` × arc length.
    pub fn solve(&self) -> Result<(Solved, QuasiCurve), ErrorBody> {
        let solved = self.curve.solve()?;
        let quasi = match (&solved, self.tolerance, self.cubic) {
            (Solved::Segment(s), None, _) => s.to_rational_cubic(),
            (Solved::Segment(s), Some(t), false) => s.to_rational_cubics(Tolerance::Relative(t)),
            (Solved::Segment(s), Some(t), true) => s.to_cubics(Tolerance::Relative(t)),
            (Solved::Compound(c), None, _) => c.to_rational_cubic(),
            (Solved::Compound(c), Some(t), false) => c.to_rational_cubics(Tolerance::Relative(t)),
            (Solved::Compound(c), Some(t), true) => c.to_cubics(Tolerance::Relative(t)),
        }?;
        Ok((solved, quasi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::parse;
    use lac::Curve;

    #[test]
    fn a_quasi_input_fits_within_its_tolerance() {
        let input: QuasiInput = parse(
            r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-5}"#,
            QuasiInput::SHAPE,
        )
        .unwrap();
        let (solved, quasi) = input.solve().unwrap();
        assert!(quasi.max <= 1e-5);
        let report = QuasiReport::new(&quasi, solved.curve().arc_length(), input.tolerance, false);
        assert!(report.is_finite() && !report.pieces.is_empty());
    }
}
