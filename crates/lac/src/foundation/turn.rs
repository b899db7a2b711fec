//! The turning direction of a planar curve.

/// Which way a planar curve turns: its signed curvature is positive for [`Turn::Left`]
/// (counter-clockwise) and negative for [`Turn::Right`] (docs/math.md §1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
pub enum Turn {
    /// Counter-clockwise: positive curvature.
    Left,
    /// Clockwise: negative curvature.
    Right,
}

impl Turn {
    /// +1 for a left turn, −1 for a right turn: the sign of the curvature.
    #[inline]
    pub fn sign(self) -> f64 {
        match self {
            Turn::Left => 1.0,
            Turn::Right => -1.0,
        }
    }

    /// The turning direction of a signed angle or cross product (`None` for 0 or NaN).
    pub fn of(signed: f64) -> Option<Turn> {
        if signed > 0.0 {
            Some(Turn::Left)
        } else if signed < 0.0 {
            Some(Turn::Right)
        } else {
            None
        }
    }

    /// The opposite direction.
    pub fn reversed(self) -> Turn {
        match self {
            Turn::Left => Turn::Right,
            Turn::Right => Turn::Left,
        }
    }
}
