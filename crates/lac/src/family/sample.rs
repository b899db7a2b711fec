//! A sample of a planar curve (arc length, point, tangent direction, signed curvature), and
//! the limits on how many samples one call returns.

use kurbo::{Point, Vec2};

use crate::foundation::error::{Error, Result};

/// One sample of a planar curve, in the caller's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Arc length from the first control point.
    pub s: f64,
    /// Position.
    pub point: Point,
    /// Tangent direction, radians, continuous from the first control point.
    pub theta: f64,
    /// Signed curvature (positive for a left turn).
    pub kappa: f64,
}

impl Sample {
    /// The unit tangent (cos θ, sin θ).
    pub fn tangent(&self) -> Vec2 {
        Vec2::from_angle(self.theta)
    }

    /// The centre of curvature, `P + N/κ` with N the left normal: a point of the evolute.
    pub fn center_of_curvature(&self) -> Point {
        self.point + self.tangent().turn_90() * (1.0 / self.kappa)
    }
}

/// Largest number of samples any sampling call returns.
const MAX_SAMPLES: usize = 10_000_000;

/// Most samples adaptive sampling may need (see `Curve::sample_adaptive`): about 0.2 s of
/// work on one core.
pub const MAX_ADAPTIVE_SAMPLES: usize = 50_000;

/// An error unless `2 ≤ n ≤` the largest number of samples a call returns.
pub(crate) fn check_count(n: usize) -> Result<()> {
    if (2..=MAX_SAMPLES).contains(&n) {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            name: "samples",
            value: n as f64,
            expected: "between 2 and 10000000 samples",
        })
    }
}
