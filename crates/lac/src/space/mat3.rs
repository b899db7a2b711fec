//! Row-major 3×3 matrices: the rotation of a [`super::Similarity3`] and how it is built.

use std::ops::Mul;

use crate::foundation::vec3::Vec3;

/// A 3×3 matrix, stored by rows as [`super::Similarity3::rotation`] is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Mat3(pub(crate) [[f64; 3]; 3]);

impl Mat3 {
    /// The matrix whose columns are `c0, c1, c2`.
    pub(crate) fn from_columns(c0: Vec3, c1: Vec3, c2: Vec3) -> Mat3 {
        Mat3([[c0.x, c1.x, c2.x], [c0.y, c1.y, c2.y], [c0.z, c1.z, c2.z]])
    }

    /// The transpose (the inverse of a rotation).
    pub(crate) fn transpose(self) -> Mat3 {
        let [r0, r1, r2] = self.0.map(Vec3::from_array);
        Mat3::from_columns(r0, r1, r2)
    }
}

impl Mul for Mat3 {
    type Output = Mat3;
    fn mul(self, other: Mat3) -> Mat3 {
        let (a, b) = (self.0, other.0);
        let mut m = [[0.0; 3]; 3];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
            }
        }
        Mat3(m)
    }
}

impl Mul<Vec3> for Mat3 {
    type Output = Vec3;
    fn mul(self, v: Vec3) -> Vec3 {
        let [r0, r1, r2] = self.0.map(Vec3::from_array);
        Vec3::new(r0.dot(v), r1.dot(v), r2.dot(v))
    }
}
