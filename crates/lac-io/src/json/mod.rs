//! The JSON shapes of log-aesthetic curves, defined once for every front end.
//!
//! *Inputs* are what a request (or one line of a `--batch`) holds: [`SegmentInput`],
//! [`CompoundInput`], [`CurveInput`] (either of them), [`QuasiInput`], [`MonotoneInput`],
//! [`PiecesInput`]. Each solves itself with the core library. *Reports* are what is printed
//! or answered: [`SegmentReport`], [`CompoundReport`], [`QuasiReport`], [`MonotoneReport`],
//! [`LcgReport`], [`RegionReport`], and on failure [`ErrorReport`].
//!
//! Numbers are written by serde_json as the shortest decimal that reads back to the same
//! `f64`, and read correctly rounded; points are `[x, y]` arrays; names are snake_case.
//! Reports never hold NaN or infinities (serde_json would write `null`): a front end checks
//! [`Report::is_finite`] before it answers.
//!
//! One file per family of shapes: `segment.rs`, `compound.rs` (with [`CurveInput`] and
//! [`Solved`], either kind of planar curve), `quasi.rs`, `monotone.rs`, `lcg.rs`,
//! `region.rs`, `space.rs`, `path.rs`, `spline.rs`, `fit.rs` ([`FitInput`], [`FitReport`]); the `--batch` fast path of segments in
//! `fast.rs`, and the geometry verdicts of `lac lcg` in `verdict.rs`. This file holds what
//! every shape shares: points, errors, parsing and writing lines, and the [`Report`] trait.

use kurbo::Point;
use lac::Sample;
use serde::{Deserialize, Serialize};

mod compound;
mod fast;
mod fit;
#[macro_use]
mod kind;
mod lcg;
mod monotone;
mod path;
mod quasi;
mod region;
mod segment;
mod space;
mod spline;

pub use compound::{CompoundInput, CompoundKind, CompoundReport, CurveInput, LcgRow, Solved};
pub use fit::{
    FarPointRow, FitInput, FitJointRow, FitKind, FitPieceRow, FitReport, FitSegmentRow, FittedPath,
    DEFAULT_MAX_SEGMENTS, FARTHEST_LISTED,
};
pub use kind::{fields, Kind, ANY_SHAPE};
pub use lcg::{FitRow, LcgInput, LcgReport, PieceFitRow, PlotRow};
pub use monotone::{
    verdict_name, MonotoneDocument, MonotoneInput, MonotonePiecesReport, MonotoneReport,
};
pub use path::{PathInput, PathJointRow, PathKind, PathReport, PathSegmentRow, PathStraightRow};
pub use quasi::{PieceInput, PiecesInput, QuasiInput, QuasiPieceRow, QuasiReport};
pub use region::{PointRegionInput, PointRegionReport, RegionInput, RegionReport};
pub use segment::{SegmentInput, SegmentKind, SegmentReport};
pub use space::{
    planar_control_points, GraphFitRow, GraphRow, LineFitRow, PlanarRow, SpaceFormRow,
    SpaceGraphsReport, SpaceInput, SpaceKind, SpaceLcgReport, SpaceReport, SpaceSampleRow,
    TransformRow, PLANAR_NOTE,
};
pub use spline::{
    point_type_named, SplineEndRow, SplineInflectionRow, SplineInput, SplineKind, SplineKnotRow,
    SplinePieceRow, SplinePointRow, SplineReport, SplineRequest,
};

// The curve kinds, in the order they are asked to claim a document (`kind.rs`): a new kind
// is its file here, its `mod` line above and one line in this list.
kinds! {
    Fit: FitKind,
    Spline: SplineKind,
    Path: PathKind,
    Space: SpaceKind,
    Compound: CompoundKind,
    Segment: SegmentKind,
}

/// Its path before the CSV writers moved to [`crate::csv`].
pub use crate::csv::samples_csv;

/// A planar point, `[x, y]`.
pub type Xy = [f64; 2];

fn xy(p: Point) -> Xy {
    [p.x, p.y]
}

fn point(p: Xy) -> Point {
    Point::new(p[0], p[1])
}

/// A 3-D point, `[x, y, z]`.
pub type Xyz = [f64; 3];

// ---------------------------------------------------------------------------------------
// Errors

/// What went wrong, in every front end's words: `{"kind":…,"message":…}`.
///
/// `kind` is the library's [`lac::ErrorKind`] in snake_case (`"not_drawable"`,
/// `"collinear_points"`, …) or one of the front ends' own: `"usage"`, `"invalid_input"`
/// (unreadable JSON or numbers, wrong shapes), `"limit"` (a request over a stated limit),
/// `"io"`, `"internal"`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ErrorBody {
    /// A stable snake_case name.
    pub kind: String,
    /// What was wrong and what would fix it.
    pub message: String,
    /// For `not_drawable` space segments found at Ω = 0 but not at the Ω asked: where the
    /// Ω = 0 segment, followed as Ω grows, ends (a segment exists for every Ω up to it).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub omega_max: Option<f64>,
    /// For a `no_g2_path` path: the joint fractions of the nearest G1 path, where one can
    /// be drawn (pass them as `fractions` without `g2`); absent where none can.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub g1_fractions: Option<Vec<f64>>,
}

/// How a front end should treat a failure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorClass {
    /// The request itself is wrong (syntax, NaN, coincident points, a limit): exit code 2,
    /// HTTP 400.
    Invalid,
    /// The request is valid but no curve (or fit) exists for it: exit code 3, HTTP 422.
    Undrawable,
    /// Reading or writing failed: exit code 1.
    Io,
    /// A defect of lac: exit code 70, HTTP 500.
    Internal,
}

impl ErrorBody {
    /// A failure of `kind` with `message`.
    pub fn new(kind: impl Into<String>, message: impl Into<String>) -> Self {
        ErrorBody {
            kind: kind.into(),
            message: message.into(),
            omega_max: None,
            g1_fractions: None,
        }
    }

    /// Unreadable or ill-shaped input.
    pub fn invalid_input(message: impl Into<String>) -> Self {
        ErrorBody::new("invalid_input", message)
    }

    /// A request over a stated limit.
    pub fn limit(message: impl Into<String>) -> Self {
        ErrorBody::new("limit", message)
    }

    /// How a front end should treat it.
    pub fn class(&self) -> ErrorClass {
        match self.kind.as_str() {
            "not_drawable"
            | "fit_failed"
            | "tolerance_not_met"
            | "too_many_pieces"
            | "no_g2_path"
            | "fit_tolerance_not_met"
            | "fit_not_closed" => ErrorClass::Undrawable,
            "io" => ErrorClass::Io,
            "internal" | "numerical_failure" => ErrorClass::Internal,
            _ => ErrorClass::Invalid,
        }
    }

    /// The one line `{"error":{…}}`, without a newline.
    pub fn to_json_line(&self) -> String {
        to_line(&ErrorReport {
            error: self.clone(),
        })
    }
}

impl From<lac::Error> for ErrorBody {
    fn from(err: lac::Error) -> Self {
        let omega_max = match &err {
            lac::Error::NotDrawable(lac::NotDrawable::TorsionTooLarge { omega_max, .. }) => {
                Some(*omega_max)
            }
            _ => None,
        };
        let kind = match serde_json::to_value(err.kind()) {
            Ok(serde_json::Value::String(name)) => name,
            _ => "internal".to_string(),
        };
        ErrorBody {
            kind,
            message: err.to_string(),
            omega_max,
            g1_fractions: None,
        }
    }
}

/// A refused CAD export: the library's errors as [`From<lac::Error>`] gives them, the
/// export's own (`usage`, `tolerance_not_met`) by their [`lac_export::Error::kind`] and
/// message.
impl From<lac_export::Error> for ErrorBody {
    fn from(err: lac_export::Error) -> Self {
        match err {
            lac_export::Error::Lac(err) => ErrorBody::from(err),
            err => ErrorBody::new(err.kind(), err.to_string()),
        }
    }
}

impl std::fmt::Display for ErrorBody {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.kind, self.message)
    }
}

impl std::error::Error for ErrorBody {}

/// `{"error":{"kind":…,"message":…}}`: a failed command's standard error line, a failed
/// batch line, a server's error body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ErrorReport {
    /// What went wrong.
    pub error: ErrorBody,
}

/// Parse one JSON document as a `T`, or say what was wrong and that `shape` was expected.
pub fn parse<T: serde::de::DeserializeOwned>(text: &str, shape: &str) -> Result<T, ErrorBody> {
    if text.trim().is_empty() {
        return Err(ErrorBody::invalid_input(format!(
            "empty input; expected {shape}"
        )));
    }
    serde_json::from_str(text)
        .map_err(|e| ErrorBody::invalid_input(format!("{e}; expected {shape}")))
}

/// A report as one line of JSON, without a newline.
pub fn to_line<T: Serialize>(report: &T) -> String {
    // Reports are plain numbers, strings and arrays: serialising them cannot fail.
    serde_json::to_string(report).unwrap_or_else(|e| {
        ErrorBody::new("internal", format!("a report did not serialise: {e}")).to_json_line()
    })
}

/// A report as one line of JSON appended to `out`, without a newline: the bytes of
/// [`to_line`] without an intermediate `String` (for `--batch`, which writes many).
pub fn write_line<T: Serialize>(report: &T, out: &mut Vec<u8>) {
    let mark = out.len();
    if let Err(e) = serde_json::to_writer(&mut *out, report) {
        out.truncate(mark);
        let body = ErrorBody::new("internal", format!("a report did not serialise: {e}"));
        out.extend_from_slice(body.to_json_line().as_bytes());
    }
}

/// Reports that can say whether all their numbers are finite (JSON has no NaN).
pub trait Report: Serialize {
    /// Are all numbers finite?
    fn is_finite(&self) -> bool;

    /// The report, or an `internal` error when a number is not finite.
    fn checked(self) -> Result<Self, ErrorBody>
    where
        Self: Sized,
    {
        if self.is_finite() {
            Ok(self)
        } else {
            Err(ErrorBody::new(
                "internal",
                "a result is not finite (NaN or infinite); please report this input",
            ))
        }
    }
}

fn all_finite(values: impl IntoIterator<Item = f64>) -> bool {
    values.into_iter().all(f64::is_finite)
}

/// One sample: arc length, position, tangent direction (radians) and signed curvature.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampleRow {
    /// Arc length from the first control point.
    pub s: f64,
    /// Position, x.
    pub x: f64,
    /// Position, y.
    pub y: f64,
    /// Tangent direction, radians, continuous from the first control point.
    pub theta: f64,
    /// Signed curvature, + for a left turn.
    pub kappa: f64,
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

impl From<Sample> for SampleRow {
    fn from(s: Sample) -> Self {
        SampleRow::from(&s)
    }
}

impl SampleRow {
    /// The five values in the order of the CSV columns and the JSON fields.
    pub(crate) fn values(&self) -> [f64; 5] {
        [self.s, self.x, self.y, self.theta, self.kappa]
    }
}

/// A number with six significant digits at most, for messages.
pub use lac::short_number as short;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_carry_the_library_kind_in_snake_case() {
        let input = SegmentInput {
            points: [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]],
            alpha: 0.5,
        };
        let err = input.solve().unwrap_err();
        assert_eq!(err.kind, "collinear_points");
        assert_eq!(err.class(), ErrorClass::Invalid);
        let far = SegmentInput {
            points: [[-1.0, 0.0], [0.9, 0.9], [1.0, 0.0]],
            alpha: -1.0,
        };
        let err = far.solve().unwrap_err();
        assert_eq!(
            (err.kind.as_str(), err.class()),
            ("not_drawable", ErrorClass::Undrawable)
        );
        assert!(err
            .to_json_line()
            .starts_with(r#"{"error":{"kind":"not_drawable","message":"#));
    }

    #[test]
    fn a_fit_that_is_not_found_is_undrawable_not_invalid() {
        for err in [
            lac::Error::FitToleranceNotMet {
                tolerance: 0.01,
                reached: 0.02,
                segments: 1,
                from: 3,
                to: 9,
            },
            lac::Error::FitNotClosed { segments: 3 },
        ] {
            assert_eq!(ErrorBody::from(err).class(), ErrorClass::Undrawable);
        }
    }

    #[test]
    fn export_errors_keep_their_kinds_messages_and_classes() {
        let svg = ErrorBody::from(lac_export::Error::SvgOfSpaceCurve);
        assert_eq!(
            (svg.kind.as_str(), svg.class(), svg.message.as_str()),
            (
                "usage",
                ErrorClass::Invalid,
                "SVG holds planar curves only: export a space curve as step, iges, dxf or json"
            )
        );
        let fine = ErrorBody::from(lac_export::Error::ToleranceBelowPrecision {
            tolerance: 1e-14,
            relative: 1e-14,
            length: 4.456290862831389,
        });
        assert_eq!(
            (fine.kind.as_str(), fine.class()),
            ("tolerance_not_met", ErrorClass::Undrawable)
        );
        assert!(fine
            .message
            .starts_with("a tolerance of 1e-14 is 1.0e-14 of the arc length"));
        for err in [
            lac::Error::TooManyPieces {
                tolerance: 1e-12,
                max_pieces: 1000,
            },
            lac::Error::NumericalFailure { what: "x" },
        ] {
            let wrapped = ErrorBody::from(lac_export::Error::from(err.clone()));
            assert_eq!(wrapped, ErrorBody::from(err));
        }
    }

    #[test]
    fn short_numbers_keep_six_significant_digits() {
        assert_eq!(short(0.30000000000000004), "0.3");
        assert_eq!(short(-2.345678901), "-2.34568");
        assert_eq!(short(1.7e308), "1.7e308");
        assert_eq!(short(1.5e-7), "1.5e-7");
        assert_eq!(short(0.0), "0");
    }
}
