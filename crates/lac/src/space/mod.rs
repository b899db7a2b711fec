//! Log-aesthetic space curves (seed 003, SPEC §6): the family in standard form, the
//! classification of its ends, and segments from four control points.

mod classify;
mod family;
mod segment;
mod shoot;
mod taylor;
pub(crate) mod vec3;

pub use classify::{
    BoundBy, EndBehaviour, RadiusCell, RadiusLimit, RatioLimit, SpaceClassification, SpaceEnd,
    TurningCell,
};
pub use family::{SpaceForm, TorsionType};
pub use segment::{GraphPoint, Similarity3, SpaceSegment, PLANAR_TOLERANCE};

/// A point of a space curve with its Frenet frame, curvature and torsion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Arc length.
    pub s: f64,
    /// Position.
    pub point: [f64; 3],
    /// Unit tangent t.
    pub tangent: [f64; 3],
    /// Unit principal normal n.
    pub normal: [f64; 3],
    /// Unit binormal b = t × n.
    pub binormal: [f64; 3],
    /// Curvature κ = 1/ρ ≥ 0.
    pub curvature: f64,
    /// Torsion τ = 1/μ (negative for a left-handed, mirrored curve).
    pub torsion: f64,
}
