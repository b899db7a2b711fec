//! Log-aesthetic space curves (seed 003, docs/math.md §6): the family in standard form, the
//! classification of its ends, and segments from four control points.

mod classify;
mod cubics;
mod family;
mod mat3;
mod segment;
mod shoot;
mod taylor;

pub use classify::{
    BoundBy, EndBehaviour, RadiusCell, RadiusLimit, RatioLimit, SeedRow, SpaceClassification,
    SpaceEnd, TurningCell,
};
pub use cubics::{SpaceCubic, SpaceCubics};
pub use family::{SpaceForm, SpaceFormParams, TorsionType};
pub use segment::{GraphPoint, Similarity3, SpaceSegment, SpaceShape, PLANAR_TOLERANCE};

use crate::Vec3;

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
