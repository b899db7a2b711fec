//! Monotone curvature of (rational) cubics: what `lac monotone` reads
//! ([`MonotoneInput`], [`MonotoneDocument`]) and prints ([`MonotoneReport`],
//! [`MonotonePiecesReport`]).

use lac::{Monotonicity, MonotonicityReport};
use serde::{Deserialize, Serialize};

use super::{parse, to_line, ErrorBody, PieceInput, PiecesInput, Report};

/// The monotonicity question for one (rational) cubic: `{"points":[[x,y]×4],"weights":…}`.
pub type MonotoneInput = PieceInput;

/// The name of a monotonicity verdict: `increasing`, `decreasing`, `constant`,
/// `not_monotone`.
pub fn verdict_name(verdict: Monotonicity) -> &'static str {
    match verdict {
        Monotonicity::Increasing => "increasing",
        Monotonicity::Decreasing => "decreasing",
        Monotonicity::Constant => "constant",
        Monotonicity::NotMonotone { .. } => "not_monotone",
    }
}

/// Whether the curvature of a (rational) cubic is monotone: `lac monotone`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MonotoneReport {
    /// `increasing`, `decreasing`, `constant` or `not_monotone`.
    pub verdict: String,
    /// Whether the verdict is proven for the exact curve the numbers describe.
    pub proven: bool,
    /// Not monotone: a parameter where dκ/ds changes sign.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub t: Option<f64>,
}

impl From<&MonotonicityReport> for MonotoneReport {
    fn from(m: &MonotonicityReport) -> Self {
        MonotoneReport {
            verdict: verdict_name(m.verdict).to_string(),
            proven: m.proven,
            t: match m.verdict {
                Monotonicity::NotMonotone { t } => Some(t),
                _ => None,
            },
        }
    }
}

/// What `lac monotone` reads as one document (or one `--batch` line): one piece
/// ([`PieceInput`]) or a chain of them ([`PiecesInput`], what `lac quasi` prints).
#[derive(Clone, Debug, PartialEq)]
pub enum MonotoneDocument {
    /// One (rational) cubic.
    Piece(PieceInput),
    /// A chain: a verdict for each piece.
    Pieces(PiecesInput),
}

impl MonotoneDocument {
    /// The shapes, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]} (weights optional) or {"pieces":[…such pieces…]} (lac quasi output)"#;

    /// Read one document.
    pub fn parse(text: &str) -> Result<MonotoneDocument, ErrorBody> {
        let value: serde_json::Value = parse(text, Self::SHAPE)?;
        let pieces = value.get("pieces").is_some();
        let document = if pieces {
            serde_json::from_value(value).map(MonotoneDocument::Pieces)
        } else {
            serde_json::from_value(value).map(MonotoneDocument::Piece)
        };
        document.map_err(|e| ErrorBody::invalid_input(format!("{e}; expected {}", Self::SHAPE)))
    }

    /// Its verdicts as one line of JSON: a [`MonotoneReport`] or a [`MonotonePiecesReport`].
    pub fn report_line(&self) -> Result<String, ErrorBody> {
        match self {
            MonotoneDocument::Piece(piece) => Ok(to_line(&MonotoneReport::of(piece)?)),
            MonotoneDocument::Pieces(pieces) => Ok(to_line(&MonotonePiecesReport::new(pieces)?)),
        }
    }
}

impl MonotoneReport {
    /// The verdict on one piece.
    pub fn of(piece: &PieceInput) -> Result<Self, ErrorBody> {
        let verdict = piece.to_rational_cubic()?.curvature_monotonicity()?;
        MonotoneReport::from(&verdict).checked()
    }
}

impl Report for MonotoneReport {
    fn is_finite(&self) -> bool {
        self.t.is_none_or(f64::is_finite)
    }
}

/// The verdict on each piece of a chain: `{"pieces":[{"verdict":…,"proven":…},…]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MonotonePiecesReport {
    /// One verdict a piece, in order.
    pub pieces: Vec<MonotoneReport>,
}

impl MonotonePiecesReport {
    /// The verdict on each piece of `input`.
    pub fn new(input: &PiecesInput) -> Result<Self, ErrorBody> {
        if input.pieces.is_empty() {
            return Err(ErrorBody::invalid_input("no pieces given"));
        }
        let pieces = input
            .pieces
            .iter()
            .map(MonotoneReport::of)
            .collect::<Result<Vec<_>, _>>()?;
        MonotonePiecesReport { pieces }.checked()
    }
}

impl Report for MonotonePiecesReport {
    fn is_finite(&self) -> bool {
        self.pieces.iter().all(MonotoneReport::is_finite)
    }
}
