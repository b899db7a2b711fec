//! A 3-D point or vector, the one geometric type of the space curves.

use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A point or vector in 3-D space, `(x, y, z)`.
///
/// One type serves for both, as positions of a space curve are vectors from the origin of
/// its coordinates (the standard form's origin is its start, seed 003 §3). Arithmetic is
/// componentwise; [`Vec3::dot`], [`Vec3::cross`] and [`Vec3::length`] are the Euclidean
/// ones.
///
/// ```
/// use lac::Vec3;
/// let t = Vec3::new(3.0, 0.0, 4.0);
/// assert_eq!(t.length(), 5.0);
/// assert_eq!(Vec3::X.cross(Vec3::Y), Vec3::Z);
/// assert!(t.normalize().distance(Vec3::new(0.6, 0.0, 0.8)) < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Vec3 {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
    /// The z coordinate.
    pub z: f64,
}

impl Vec3 {
    /// The origin, or the zero vector.
    pub const ZERO: Vec3 = Vec3::new(0.0, 0.0, 0.0);
    /// The unit vector along +x.
    pub const X: Vec3 = Vec3::new(1.0, 0.0, 0.0);
    /// The unit vector along +y.
    pub const Y: Vec3 = Vec3::new(0.0, 1.0, 0.0);
    /// The unit vector along +z.
    pub const Z: Vec3 = Vec3::new(0.0, 0.0, 1.0);

    /// The vector `(x, y, z)`.
    #[inline]
    pub const fn new(x: f64, y: f64, z: f64) -> Vec3 {
        Vec3 { x, y, z }
    }

    /// The vector `[x, y, z]`.
    #[inline]
    pub const fn from_array([x, y, z]: [f64; 3]) -> Vec3 {
        Vec3 { x, y, z }
    }

    /// The coordinates `[x, y, z]`.
    #[inline]
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    /// The dot product `x·x′ + y·y′ + z·z′`.
    #[inline]
    pub fn dot(self, other: Vec3) -> f64 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// The cross product `self × other`, right-handed: `X × Y = Z`.
    #[inline]
    pub fn cross(self, other: Vec3) -> Vec3 {
        Vec3::new(
            self.y * other.z - self.z * other.y,
            self.z * other.x - self.x * other.z,
            self.x * other.y - self.y * other.x,
        )
    }

    /// The squared length `self · self`.
    #[inline]
    pub fn length_squared(self) -> f64 {
        self.dot(self)
    }

    /// The Euclidean length.
    ///
    /// `√(self · self)` where the square neither overflows nor underflows (lengths between
    /// about 1e-154 and 1e154); outside that range the vector is first scaled by its largest
    /// component, so that the result is finite and accurate for every finite vector, as
    /// `f64::hypot` is in 2-D.
    #[inline]
    pub fn length(self) -> f64 {
        let squared = self.length_squared();
        if (f64::MIN_POSITIVE..f64::INFINITY).contains(&squared) || !self.is_finite() {
            return squared.sqrt();
        }
        let largest = self.x.abs().max(self.y.abs()).max(self.z.abs());
        if largest == 0.0 {
            return 0.0;
        }
        largest * (self / largest).length_squared().sqrt()
    }

    /// The distance to `other`, `|self − other|`.
    #[inline]
    pub fn distance(self, other: Vec3) -> f64 {
        (self - other).length()
    }

    /// The unit vector along `self`: `self` times the reciprocal of its length.
    ///
    /// Components are NaN or infinite for the zero vector (and for non-finite ones); see
    /// [`Vec3::try_normalize`].
    #[inline]
    pub fn normalize(self) -> Vec3 {
        self * self.length().recip()
    }

    /// The unit vector along `self`, or `None` when there is none: the vector is zero, not
    /// finite, or so short (below about 1e-308) that the reciprocal of its length overflows.
    #[inline]
    pub fn try_normalize(self) -> Option<Vec3> {
        let unit = self.normalize();
        unit.is_finite().then_some(unit)
    }

    /// The angle between `self` and `other` in [0, π], radians; 0 when either is zero.
    ///
    /// `atan2(|a × b|, a · b)`, accurate near 0 and π, where `acos` of the normalised dot
    /// product loses half the digits.
    #[inline]
    pub fn angle_to(self, other: Vec3) -> f64 {
        self.cross(other).length().atan2(self.dot(other))
    }

    /// Are all three coordinates finite?
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl From<[f64; 3]> for Vec3 {
    #[inline]
    fn from(a: [f64; 3]) -> Vec3 {
        Vec3::from_array(a)
    }
}

impl From<Vec3> for [f64; 3] {
    #[inline]
    fn from(v: Vec3) -> [f64; 3] {
        v.to_array()
    }
}

impl Add for Vec3 {
    type Output = Vec3;
    #[inline]
    fn add(self, other: Vec3) -> Vec3 {
        Vec3::new(self.x + other.x, self.y + other.y, self.z + other.z)
    }
}

impl AddAssign for Vec3 {
    #[inline]
    fn add_assign(&mut self, other: Vec3) {
        *self = *self + other;
    }
}

impl Sub for Vec3 {
    type Output = Vec3;
    #[inline]
    fn sub(self, other: Vec3) -> Vec3 {
        Vec3::new(self.x - other.x, self.y - other.y, self.z - other.z)
    }
}

impl SubAssign for Vec3 {
    #[inline]
    fn sub_assign(&mut self, other: Vec3) {
        *self = *self - other;
    }
}

impl Neg for Vec3 {
    type Output = Vec3;
    #[inline]
    fn neg(self) -> Vec3 {
        Vec3::new(-self.x, -self.y, -self.z)
    }
}

impl Mul<f64> for Vec3 {
    type Output = Vec3;
    #[inline]
    fn mul(self, k: f64) -> Vec3 {
        Vec3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl Mul<Vec3> for f64 {
    type Output = Vec3;
    #[inline]
    fn mul(self, v: Vec3) -> Vec3 {
        v * self
    }
}

impl MulAssign<f64> for Vec3 {
    #[inline]
    fn mul_assign(&mut self, k: f64) {
        *self = *self * k;
    }
}

/// Componentwise division (each coordinate divided by `k`, not multiplied by `1/k`).
impl Div<f64> for Vec3 {
    type Output = Vec3;
    #[inline]
    fn div(self, k: f64) -> Vec3 {
        Vec3::new(self.x / k, self.y / k, self.z / k)
    }
}

impl DivAssign<f64> for Vec3 {
    #[inline]
    fn div_assign(&mut self, k: f64) {
        *self = *self / k;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_follow_the_right_hand_rule() {
        let (a, b) = (Vec3::new(1.0, 2.0, 3.0), Vec3::new(-2.0, 0.5, 4.0));
        assert_eq!(a.dot(b), -2.0 + 1.0 + 12.0);
        let c = a.cross(b);
        assert_eq!(c, Vec3::new(8.0 - 1.5, -6.0 - 4.0, 0.5 + 4.0));
        assert_eq!(c.dot(a), 0.0);
        assert_eq!(c.dot(b), 0.0);
        assert_eq!(Vec3::Y.cross(Vec3::Z), Vec3::X);
        assert_eq!(Vec3::Z.cross(Vec3::X), Vec3::Y);
    }

    #[test]
    fn length_is_the_plain_formula_in_range_and_survives_outside_it() {
        let v = Vec3::new(0.1, -0.7, 2.3);
        assert_eq!(v.length(), v.length_squared().sqrt());
        // The squares overflow and underflow; the scaled sum does not.
        for k in [1e200, 1e-200] {
            let length = Vec3::new(3.0 * k, 4.0 * k, 12.0 * k).length();
            assert!((length / (13.0 * k) - 1.0).abs() < 4e-16, "{length:e}");
        }
        assert_eq!(Vec3::new(0.0, -5e-324, 0.0).length(), 5e-324);
        assert_eq!(Vec3::ZERO.length(), 0.0);
        assert_eq!(Vec3::new(1.0, f64::INFINITY, 0.0).length(), f64::INFINITY);
        assert!(Vec3::new(1.0, f64::NAN, 0.0).length().is_nan());
    }

    #[test]
    fn normalize_gives_a_unit_vector_or_none() {
        let u = Vec3::new(1e250, -2e250, 2e250).try_normalize().unwrap();
        assert!((u.length() - 1.0).abs() < 1e-15);
        assert!((u - Vec3::new(1.0, -2.0, 2.0) / 3.0).length() < 1e-16);
        assert_eq!(Vec3::ZERO.try_normalize(), None);
        assert_eq!(Vec3::new(f64::NAN, 1.0, 0.0).try_normalize(), None);
        assert_eq!(Vec3::new(1.0, f64::INFINITY, 0.0).try_normalize(), None);
    }

    #[test]
    fn angle_to_is_accurate_near_zero_and_pi() {
        let a = Vec3::new(1.0, 0.0, 0.0);
        let b = Vec3::new(1.0, 1e-10, 0.0);
        assert!((a.angle_to(b) - 1e-10).abs() < 1e-25);
        assert!((a.angle_to(-b) - (std::f64::consts::PI - 1e-10)).abs() < 1e-15);
        assert_eq!(a.angle_to(Vec3::ZERO), 0.0);
    }

    #[test]
    fn arithmetic_is_componentwise() {
        let mut v = Vec3::new(1.0, 2.0, 3.0);
        v += Vec3::X;
        v -= 2.0 * Vec3::Z;
        v *= 3.0;
        v /= 2.0;
        assert_eq!(v, Vec3::new(3.0, 3.0, 1.5));
        assert_eq!(-v + v, Vec3::ZERO);
        assert_eq!(Vec3::from([1.0, 2.0, 3.0]).to_array(), [1.0, 2.0, 3.0]);
        assert_eq!(<[f64; 3]>::from(Vec3::Y), [0.0, 1.0, 0.0]);
        assert!(!Vec3::new(0.0, 0.0, f64::NEG_INFINITY).is_finite());
    }
}
