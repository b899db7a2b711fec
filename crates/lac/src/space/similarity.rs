//! The similarity that places a standard-form space curve in the caller's coordinates.

use super::mat3::Mat3;
use crate::foundation::vec3::Vec3;

/// The similarity from the standard form to the caller's coordinates:
/// `caller = translation + scale · rotation · M · standard`, with `M = diag(1, 1, −1)` when
/// `mirror_z` and the identity otherwise.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Similarity3 {
    /// Standard-form lengths to the caller's.
    pub scale: f64,
    /// A proper rotation, stored by rows: `rotation[i][j]` is row i, column j, so the
    /// rotated vector's i-th coordinate is `rotation[i] · v`.
    pub rotation: [[f64; 3]; 3],
    /// Where the standard form's origin lands: the first control point, or the last when
    /// `reversed`.
    pub translation: Vec3,
    /// The standard form is mirrored in its xy plane first (a left-handed segment, τ < 0).
    pub mirror_z: bool,
    /// The standard form runs from the last control point to the first (seed 003 §4 swaps
    /// the ends when θ0 < θ1).
    pub reversed: bool,
}

impl Similarity3 {
    /// A standard-form point in the caller's coordinates.
    pub fn apply(&self, p: Vec3) -> Vec3 {
        self.translation + self.scale * self.apply_vector(p)
    }

    /// A standard-form direction in the caller's coordinates (rotation and mirror only).
    pub fn apply_vector(&self, v: Vec3) -> Vec3 {
        Mat3(self.rotation) * mirror(v, self.mirror_z)
    }
}

/// `v` mirrored in the xy plane when `mirror_z`.
pub(super) fn mirror(v: Vec3, mirror_z: bool) -> Vec3 {
    if mirror_z {
        Vec3::new(v.x, v.y, -v.z)
    } else {
        v
    }
}
