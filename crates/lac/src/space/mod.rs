//! Log-aesthetic space curves (seed 003, docs/math.md §6): the family in standard form, the
//! classification of its ends, and segments from four control points.

mod classify;
mod cubics;
mod family;
mod mat3;
mod segment;
mod shoot;
mod similarity;
mod solver;
mod taylor;

pub use classify::{
    BoundBy, EndBehaviour, RadiusCell, RadiusLimit, RatioLimit, SeedRow, SpaceClassification,
    SpaceEnd, TurningCell,
};
pub use cubics::{SpaceCubic, SpaceCubics};
pub use family::{SpaceForm, SpaceFormParams, TorsionType};
pub use segment::{GraphPoint, SpaceSegment, SpaceShape, PLANAR_TOLERANCE};
pub use similarity::Similarity3;

use crate::foundation::error::Result;
use crate::foundation::numeric::times_ratio;
use crate::foundation::vec3::Vec3;

/// A point of a space curve with its Frenet frame, curvature and torsion.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Frame {
    /// Arc length.
    pub s: f64,
    /// Position.
    pub point: Vec3,
    /// Unit tangent t.
    pub tangent: Vec3,
    /// Unit principal normal n.
    pub normal: Vec3,
    /// Unit binormal b = t × n.
    pub binormal: Vec3,
    /// Curvature κ = 1/ρ ≥ 0.
    pub curvature: f64,
    /// Torsion τ = 1/μ (negative for a left-handed, mirrored curve).
    pub torsion: f64,
}

/// A space curve, by arc length: what it can do (the 3-D counterpart of
/// [`Curve`](crate::Curve)). Arc length `s` runs from 0 at the first point to
/// [`SpaceCurve::arc_length`] at the last; curvature is κ ≥ 0 and torsion τ signed.
pub trait SpaceCurve {
    /// Arc length from the first point to the last.
    fn arc_length(&self) -> f64;

    /// Point, Frenet frame, curvature and torsion at each of the arc lengths `s_values`,
    /// each within [0, arc length].
    fn frames(&self, s_values: &[f64]) -> Result<Vec<Frame>>;

    /// The logarithmic curvature graph at `n ≥ 2` points equally spaced in arc length:
    /// `(ln ρ, ln(ρ |ds/dρ|))` in the caller's units.
    fn log_curvature_graph(&self, n: usize) -> Result<Vec<GraphPoint>>;

    /// The logarithmic torsion graph at `n ≥ 2` points equally spaced in arc length:
    /// `(ln μ, ln(μ |ds/dμ|))`, μ = 1/|τ|.
    fn log_torsion_graph(&self, n: usize) -> Result<Vec<GraphPoint>>;

    /// [`SpaceCurve::frames`] at one arc length.
    fn frame_at_s(&self, s: f64) -> Result<Frame> {
        Ok(self.frames(&[s])?.remove(0))
    }

    /// `n ≥ 2` frames equally spaced in arc length from the first point to the last.
    fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Frame>> {
        if !(2..=10_000_000).contains(&n) {
            return Err(crate::foundation::error::Error::OutOfRange {
                name: "samples",
                value: n as f64,
                expected: "between 2 and 10000000",
            });
        }
        let len = self.arc_length();
        let at: Vec<f64> = (0..n)
            .map(|i| {
                if i == n - 1 {
                    len
                } else {
                    times_ratio(len, i as f64, (n - 1) as f64)
                }
            })
            .collect();
        self.frames(&at)
    }
}
