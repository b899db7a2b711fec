//! The crate's error type.

use lac::MIN_RELATIVE_TOLERANCE;

/// Result alias of the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Why an export was refused.
///
/// [`Error::kind`] names it as the front ends' JSON errors do (`{"kind":…,"message":…}`),
/// and its message is the one they show.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// SVG was asked for a space curve: SVG holds planar curves only. Kind `usage`.
    #[error("SVG holds planar curves only: export a space curve as step, iges, dxf or json")]
    SvgOfSpaceCurve,
    /// A positive tolerance below [`MIN_RELATIVE_TOLERANCE`] of the arc length: double
    /// precision cannot measure a deviation that fine, so no fit can be certified to meet
    /// it. Kind `tolerance_not_met` (the request is valid; it cannot be met).
    #[error(
        "a tolerance of {tolerance:e} is {relative:.1e} of the arc length {arc_length}: below \
         {min:e} of it no deviation can be certified in double precision; ask for at least \
         {least:e}",
        arc_length = lac::short_number(*.length),
        min = MIN_RELATIVE_TOLERANCE,
        least = MIN_RELATIVE_TOLERANCE * .length
    )]
    ToleranceBelowPrecision {
        /// The tolerance as given (model units, or a share of the arc length).
        tolerance: f64,
        /// The tolerance as a share of the arc length.
        relative: f64,
        /// The curve's arc length.
        length: f64,
    },
    /// What the core library refused: a tolerance out of range or not finite, a fit that
    /// met no tolerance ([`lac::Error::ToleranceNotMet`]) or needed too many pieces, a
    /// numerical failure (a defect). Its kind is the library's.
    #[error(transparent)]
    Lac(#[from] lac::Error),
}

impl Error {
    /// The stable snake_case name of the error, as the front ends' JSON errors give it:
    /// `"usage"`, `"tolerance_not_met"`, or the library's [`lac::ErrorKind`] (`"out_of_range"`,
    /// `"tolerance_not_met"`, `"too_many_pieces"`, `"numerical_failure"`, …).
    pub fn kind(&self) -> String {
        match self {
            Error::SvgOfSpaceCurve => "usage".to_string(),
            Error::ToleranceBelowPrecision { .. } => "tolerance_not_met".to_string(),
            Error::Lac(err) => match serde_json::to_value(err.kind()) {
                Ok(serde_json::Value::String(name)) => name,
                _ => "internal".to_string(),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_are_the_snake_case_names_and_messages_name_the_numbers() {
        assert_eq!(Error::SvgOfSpaceCurve.kind(), "usage");
        let fine = Error::ToleranceBelowPrecision {
            tolerance: 1e-16,
            relative: 1e-16 / 4.456290862831389,
            length: 4.456290862831389,
        };
        assert_eq!(fine.kind(), "tolerance_not_met");
        assert_eq!(
            fine.to_string(),
            "a tolerance of 1e-16 is 2.2e-17 of the arc length 4.45629: below 1e-12 \
             of it no deviation can be certified in double precision; ask for at least \
             4.456290862831388e-12"
        );
        for (err, kind) in [
            (
                lac::Error::ToleranceNotMet {
                    tolerance: 1e-9,
                    reached: 1e-8,
                },
                "tolerance_not_met",
            ),
            (
                lac::Error::NumericalFailure { what: "x" },
                "numerical_failure",
            ),
            (
                lac::Error::TooManyPieces {
                    tolerance: 1e-12,
                    max_pieces: 1000,
                },
                "too_many_pieces",
            ),
            (lac::Error::FitFailed, "fit_failed"),
        ] {
            let message = err.to_string();
            let wrapped = Error::from(err);
            assert_eq!(
                (wrapped.kind().as_str(), wrapped.to_string()),
                (kind, message)
            );
        }
    }
}
