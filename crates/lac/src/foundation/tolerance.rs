//! How approximations are asked to be accurate.

use crate::foundation::error::{finite, Error, Result};

/// The accuracy asked of an approximation (a chain of Bézier pieces replacing a curve, an
/// export): the largest distance allowed between the approximation and the exact curve.
///
/// The crate's one convention: a parameter named `accuracy` (as in kurbo) is an absolute
/// distance in the caller's units; a [`Tolerance`] says which of the two it is, because CAD
/// users think in model units (`Absolute`, e.g. 1e-6 mm) and the seeds state errors relative
/// to the arc length (`Relative`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
pub enum Tolerance {
    /// A distance in the caller's units.
    Absolute(f64),
    /// A fraction of the curve's arc length.
    Relative(f64),
}

/// Smallest accepted tolerance, relative to the arc length (below it the deviation cannot
/// be measured reliably in double precision).
pub const MIN_RELATIVE_TOLERANCE: f64 = 1e-12;

impl Tolerance {
    /// The tolerance as a fraction of `arc_length`, checked: finite, and between
    /// [`MIN_RELATIVE_TOLERANCE`] and 1 of the arc length.
    pub fn relative_to(self, arc_length: f64) -> Result<f64> {
        let relative = match self {
            Tolerance::Absolute(t) => finite("tolerance", t)? / arc_length,
            Tolerance::Relative(t) => finite("tolerance", t)?,
        };
        if !(MIN_RELATIVE_TOLERANCE..=1.0).contains(&relative) {
            return Err(Error::OutOfRange {
                name: "tolerance",
                value: match self {
                    Tolerance::Absolute(t) | Tolerance::Relative(t) => t,
                },
                expected: "a tolerance between 1e-12 and 1 times the arc length",
            });
        }
        Ok(relative)
    }
}
