//! Cubic Bézier pieces replacing a space segment within a tolerance, for CAD export.
//!
//! Each piece over arc lengths [a, b] (h = b − a) is the cubic Hermite interpolant of the
//! segment's points and unit tangents at its ends with the parameter running at unit speed
//! there: b₀ = X(a), b₁ = X(a) + (h/3) t(a), b₂ = X(b) − (h/3) t(b), b₃ = X(b). Consecutive
//! pieces share their join's point and tangent and, with knots spaced by the pieces' arc
//! lengths, its first derivative: the chain is C1 (G1). Curvature is matched only to the
//! order of the interpolation (a space cubic has too few degrees of freedom for a G2
//! Hermite fit where the curve twists), so the joins are G2 only within the tolerance; and no
//! monotonicity of curvature or torsion is proven for space pieces (the planar test of
//! `monotone.rs` has no 3-D counterpart here).
//!
//! The deviation of a piece is measured by pairs: the cubic at u and the curve at a + u h,
//! for u on 48 equal steps. A pair's distance bounds both the distance of the cubic's point
//! from the curve and that of the curve's point from the cubic, so the largest one bounds
//! the (sampled) Hausdorff distance from above. The interpolation error is smooth in u
//! (about u²(1 − u)² h⁴ X⁗/24), so 48 steps find its maximum to well under a percent; pieces
//! are accepted below 0.98 of the tolerance to cover that. A piece over the tolerance is
//! halved, until at most [`MAX_PIECES`] pieces.

use super::segment::SpaceSegment;
use super::SpaceCurve;
use crate::foundation::error::{Error, Result};
use crate::foundation::tolerance::Tolerance;
use crate::foundation::vec3::Vec3;
use crate::quasi::MAX_PIECES;

/// Pairs compared per piece.
const CHECK_STEPS: usize = 48;

/// Share of the tolerance a piece's measured deviation may reach (the rest covers the
/// sampling of the maximum).
const ACCEPT: f64 = 0.98;

/// One cubic Bézier piece of a [`SpaceCubics`] chain.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpaceCubic {
    /// The control points b₀ … b₃.
    pub points: [Vec3; 4],
    /// The arc lengths of the segment at the piece's ends, from P0.
    pub s: (f64, f64),
    /// The largest distance between paired points of the piece and the segment (caller's
    /// units; see the module documentation).
    pub max_deviation: f64,
}

impl SpaceCubic {
    /// The point at parameter `u` ∈ [0, 1].
    pub fn eval(&self, u: f64) -> Vec3 {
        let [p0, p1, p2, p3] = self.points;
        let v = 1.0 - u;
        p0 * (v * v * v) + p1 * (3.0 * v * v * u) + p2 * (3.0 * v * u * u) + p3 * (u * u * u)
    }
}

/// A space segment replaced by C1 cubic Bézier pieces within a tolerance
/// ([`SpaceSegment::to_cubics`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SpaceCubics {
    /// The pieces in order from P0.
    pub pieces: Vec<SpaceCubic>,
    /// The largest of the pieces' deviations (caller's units).
    pub max_deviation: f64,
}

impl SpaceSegment {
    /// As few cubic Bézier pieces as halving needs for a deviation within `tolerance`,
    /// joined C1 (points and unit tangents of the segment at every join).
    ///
    /// ```
    /// use lac::{SpaceSegment, SpaceShape, TorsionType, Tolerance, Vec3};
    ///
    /// let points = [
    ///     Vec3::new(0.0, 0.0, 0.0),
    ///     Vec3::new(3.0, 0.0, 0.0),
    ///     Vec3::new(3.0, 3.0, 1.5),
    ///     Vec3::new(0.0, 3.0, 3.0),
    /// ];
    /// let shape = SpaceShape { alpha: 0.5, beta: 0.0, omega: 0.3, torsion: TorsionType::One };
    /// let seg = SpaceSegment::from_control_points(points, shape)?;
    /// let cubics = seg.to_cubics(Tolerance::Absolute(1e-6))?;
    /// assert!(cubics.max_deviation <= 1e-6);
    /// assert_eq!(cubics.pieces[0].points[0], points[0]);
    /// # Ok::<(), lac::Error>(())
    /// ```
    ///
    /// Errors: a tolerance outside 1e-12 … 1 of the arc length ([`Error::OutOfRange`]), or
    /// one that would need more than [`MAX_PIECES`] pieces ([`Error::TooManyPieces`]).
    pub fn to_cubics(&self, tolerance: Tolerance) -> Result<SpaceCubics> {
        let length = self.arc_length();
        let relative = tolerance.relative_to(length)?;
        let tol = relative * length;
        let mut pieces = Vec::new();
        // Intervals still to cover, the next one last.
        let mut todo = vec![(0.0, length)];
        while let Some((a, b)) = todo.pop() {
            let piece = self.hermite_piece(a, b)?;
            if piece.max_deviation <= ACCEPT * tol {
                pieces.push(piece);
            } else {
                let mid = 0.5 * (a + b);
                if pieces.len() + todo.len() + 2 > MAX_PIECES || !(a < mid && mid < b) {
                    return Err(Error::TooManyPieces {
                        tolerance: relative,
                        max_pieces: MAX_PIECES,
                    });
                }
                todo.push((mid, b));
                todo.push((a, mid));
            }
        }
        let max_deviation = pieces.iter().fold(0.0f64, |m, p| m.max(p.max_deviation));
        Ok(SpaceCubics {
            pieces,
            max_deviation,
        })
    }

    /// The Hermite cubic over [a, b] and its paired deviation.
    fn hermite_piece(&self, a: f64, b: f64) -> Result<SpaceCubic> {
        let h = b - a;
        let at: Vec<f64> = (0..=CHECK_STEPS)
            .map(|i| match i {
                0 => a,
                i if i == CHECK_STEPS => b,
                i => a + h * (i as f64 / CHECK_STEPS as f64),
            })
            .collect();
        let frames = self.frames(&at)?;
        let (f0, f1) = (&frames[0], &frames[CHECK_STEPS]);
        let piece = SpaceCubic {
            points: [
                f0.point,
                f0.point + f0.tangent * (h / 3.0),
                f1.point - f1.tangent * (h / 3.0),
                f1.point,
            ],
            s: (a, b),
            max_deviation: 0.0,
        };
        let max_deviation = frames
            .iter()
            .enumerate()
            .map(|(i, f)| piece.eval(i as f64 / CHECK_STEPS as f64).distance(f.point))
            .fold(0.0f64, f64::max);
        if !max_deviation.is_finite() || !piece.points.iter().all(|p| p.is_finite()) {
            return Err(Error::NumericalFailure {
                what: "a space cubic's deviation is not finite",
            });
        }
        Ok(SpaceCubic {
            max_deviation,
            ..piece
        })
    }
}
