//! Rational cubic Bézier curves (seed 001 §4): evaluation, signed curvature and its
//! derivative in arc length.
//!
//! With homogeneous control points Qᵢ = (wᵢ bᵢ, wᵢ) the curve is the projection of the
//! polynomial P(t) = Σ Bᵢ³(t) Qᵢ = (p(t), w(t)). Writing V = p′w − p w′ (so x′ = V/w²) and
//! D = det[P, P′, P″] (so det(x′, x″) = D/w³),
//!
//! ```text
//! κ = w³ D / |V|³,        dκ/ds = w⁴ N / |V|⁶,
//! N = (3 w′ D + w D′) |V|² − 3 w D (V·V′),   D′ = det[P, P′, P‴],
//! ```
//!
//! and N is a polynomial of degree 12 in t (the t¹³ terms cancel). `monotone.rs` decides its
//! sign on [0, 1]. Everything here is evaluated relative to b₀, so a curve far from the
//! origin loses no digits to its offset.

use kurbo::{CubicBez, Point, Vec2};

use crate::error::{finite, Error, Result};
use crate::gauss::GAUSS_16;

/// A rational cubic Bézier curve with positive weights:
///
/// `x(t) = Σ Bᵢ³(t) wᵢ bᵢ / Σ Bᵢ³(t) wᵢ`, t ∈ [0, 1], Bᵢ³ the Bernstein polynomials.
///
/// Equal weights give the ordinary (polynomial) cubic Bézier curve; scaling all weights by
/// the same factor does not change the curve.
///
/// ```
/// use kurbo::Point;
/// use lac::RationalCubic;
///
/// // A quarter circle of radius 1: the degree-elevated conic with weights 1, √2/2, 1.
/// let c = std::f64::consts::FRAC_1_SQRT_2;
/// let w = (2.0 * c + 1.0) / 3.0;
/// let arc = RationalCubic::new(
///     [
///         Point::new(1.0, 0.0),
///         Point::new(1.0, 2.0 * c / (1.0 + 2.0 * c)),
///         Point::new(2.0 * c / (1.0 + 2.0 * c), 1.0),
///         Point::new(0.0, 1.0),
///     ],
///     [1.0, w, w, 1.0],
/// )?;
/// assert!((arc.curvature(0.3) - 1.0).abs() < 1e-14);
/// assert!((arc.eval(0.7).to_vec2().hypot() - 1.0).abs() < 1e-15);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RationalCubic {
    points: [Point; 4],
    weights: [f64; 4],
}

/// A homogeneous point (x·w, y·w, w).
pub(crate) type Hom = [f64; 3];

/// P, P′, P″, P‴ at one parameter, relative to b₀.
#[derive(Clone, Copy, Debug)]
pub(crate) struct HomJet {
    pub(crate) p: Hom,
    pub(crate) d1: Hom,
    pub(crate) d2: Hom,
    pub(crate) d3: Hom,
}

impl RationalCubic {
    /// The curve with control points `points = [b0, b1, b2, b3]` and `weights`.
    ///
    /// Errors: a non-finite coordinate or weight ([`Error::NonFinite`]); a weight that is not
    /// positive ([`Error::OutOfRange`]).
    pub fn new(points: [Point; 4], weights: [f64; 4]) -> Result<Self> {
        for p in &points {
            finite("a control point coordinate", p.x)?;
            finite("a control point coordinate", p.y)?;
        }
        for &w in &weights {
            finite("a weight", w)?;
            if w <= 0.0 {
                return Err(Error::OutOfRange {
                    name: "weight",
                    value: w,
                    expected: "weights must be positive",
                });
            }
        }
        Ok(RationalCubic { points, weights })
    }

    /// The polynomial cubic Bézier curve `c` (all weights 1).
    pub fn from_cubic(c: CubicBez) -> Result<Self> {
        Self::new([c.p0, c.p1, c.p2, c.p3], [1.0; 4])
    }

    /// The control points `[b0, b1, b2, b3]`.
    pub fn points(&self) -> [Point; 4] {
        self.points
    }

    /// The weights `[w0, w1, w2, w3]`.
    pub fn weights(&self) -> [f64; 4] {
        self.weights
    }

    /// The same curve as a polynomial cubic, when all weights are equal.
    pub fn to_cubic(&self) -> Option<CubicBez> {
        let w = self.weights;
        (w[1] == w[0] && w[2] == w[0] && w[3] == w[0]).then(|| {
            let [p0, p1, p2, p3] = self.points;
            CubicBez::new(p0, p1, p2, p3)
        })
    }

    /// Homogeneous control points relative to b₀.
    pub(crate) fn homogeneous(&self) -> [Hom; 4] {
        let b0 = self.points[0];
        std::array::from_fn(|i| {
            let (d, w) = (self.points[i] - b0, self.weights[i]);
            [w * d.x, w * d.y, w]
        })
    }

    /// P and its derivatives at `t` (relative to b₀).
    pub(crate) fn jet(&self, t: f64) -> HomJet {
        hom_jet(&self.homogeneous(), t)
    }

    /// The point at parameter `t`.
    pub fn eval(&self, t: f64) -> Point {
        let j = self.jet(t);
        self.points[0] + Vec2::new(j.p[0] / j.p[2], j.p[1] / j.p[2])
    }

    /// The derivative dx/dt at `t`.
    pub fn derivative(&self, t: f64) -> Vec2 {
        let j = self.jet(t);
        let w = j.p[2];
        let v = hodograph(&j);
        Vec2::new(v[0], v[1]) / (w * w)
    }

    /// Signed curvature at `t` (positive where the curve turns left).
    pub fn curvature(&self, t: f64) -> f64 {
        let j = self.jet(t);
        let v = hodograph(&j);
        let speed = v[0].hypot(v[1]);
        j.p[2].powi(3) * det3(&j.p, &j.d1, &j.d2) / (speed * speed * speed)
    }

    /// dκ/ds, the derivative of the signed curvature in arc length, at `t`.
    pub fn curvature_derivative(&self, t: f64) -> f64 {
        let j = self.jet(t);
        let v = hodograph(&j);
        let vv = v[0] * v[0] + v[1] * v[1];
        let w = j.p[2];
        (w * w) * (w * w) * numerator(&j) / (vv * vv * vv)
    }

    /// Arc length from t = 0 to t = 1 (16-point Gauss–Legendre on 8 panels; relative error
    /// below 1e-14 unless the speed varies by orders of magnitude).
    pub fn arc_length(&self) -> f64 {
        self.arc_length_between(0.0, 1.0)
    }

    /// Arc length from `t0` to `t1`.
    pub fn arc_length_between(&self, t0: f64, t1: f64) -> f64 {
        const PANELS: usize = 8;
        let h = (t1 - t0) / PANELS as f64;
        let mut sum = 0.0;
        for k in 0..PANELS {
            let mid = t0 + (k as f64 + 0.5) * h;
            for &(x, w) in GAUSS_16.iter() {
                let dx = 0.5 * h * x;
                sum += w * (self.derivative(mid - dx).hypot() + self.derivative(mid + dx).hypot());
            }
        }
        0.5 * h * sum
    }
}

/// Power-basis coefficients of P(t) = c0 + c1 t + c2 t² + c3 t³ from Bernstein ones.
pub(crate) fn power_basis(q: &[Hom; 4]) -> [Hom; 4] {
    std::array::from_fn(|k| {
        std::array::from_fn(|i| {
            let (a, b, c, d) = (q[0][i], q[1][i], q[2][i], q[3][i]);
            match k {
                0 => a,
                1 => 3.0 * (b - a),
                2 => 3.0 * (c - 2.0 * b + a),
                _ => d - 3.0 * c + 3.0 * b - a,
            }
        })
    })
}

pub(crate) fn hom_jet(q: &[Hom; 4], t: f64) -> HomJet {
    power_jet(&power_basis(q), t)
}

/// P and its derivatives at `t` from the power-basis coefficients `c`.
pub(crate) fn power_jet(c: &[Hom; 4], t: f64) -> HomJet {
    let p = std::array::from_fn(|i| c[0][i] + t * (c[1][i] + t * (c[2][i] + t * c[3][i])));
    let d1 = std::array::from_fn(|i| c[1][i] + t * (2.0 * c[2][i] + 3.0 * t * c[3][i]));
    let d2 = std::array::from_fn(|i| 2.0 * c[2][i] + 6.0 * t * c[3][i]);
    let d3 = std::array::from_fn(|i| 6.0 * c[3][i]);
    HomJet { p, d1, d2, d3 }
}

/// V = p′w − p w′ (x′ = V/w²).
pub(crate) fn hodograph(j: &HomJet) -> [f64; 2] {
    [
        j.d1[0] * j.p[2] - j.p[0] * j.d1[2],
        j.d1[1] * j.p[2] - j.p[1] * j.d1[2],
    ]
}

pub(crate) fn det3(a: &Hom, b: &Hom, c: &Hom) -> f64 {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

/// N = (3w′D + wD′)|V|² − 3wD(V·V′), whose sign is that of dκ/ds.
pub(crate) fn numerator(j: &HomJet) -> f64 {
    let v = hodograph(j);
    let dv = [
        j.d2[0] * j.p[2] - j.p[0] * j.d2[2],
        j.d2[1] * j.p[2] - j.p[1] * j.d2[2],
    ];
    let d = det3(&j.p, &j.d1, &j.d2);
    let dd = det3(&j.p, &j.d1, &j.d3);
    let (w, w1) = (j.p[2], j.d1[2]);
    let vv = v[0] * v[0] + v[1] * v[1];
    (3.0 * w1 * d + w * dd) * vv - 3.0 * w * d * (v[0] * dv[0] + v[1] * dv[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wavy() -> RationalCubic {
        RationalCubic::new(
            [
                Point::new(0.1, -0.3),
                Point::new(1.2, 0.9),
                Point::new(2.5, -0.4),
                Point::new(3.1, 1.7),
            ],
            [1.3, 0.4, 2.2, 0.8],
        )
        .unwrap()
    }

    #[test]
    fn derivatives_agree_with_central_differences() {
        let c = wavy();
        for &t in &[0.05, 0.3, 0.61, 0.97] {
            let h = 1e-5;
            let fd = (c.eval(t + h) - c.eval(t - h)) / (2.0 * h);
            assert!((fd - c.derivative(t)).hypot() < 1e-8 * fd.hypot());
            // dκ/ds = (dκ/dt) / |x′|.
            let dk = (c.curvature(t + h) - c.curvature(t - h)) / (2.0 * h);
            let want = dk / c.derivative(t).hypot();
            let got = c.curvature_derivative(t);
            assert!(
                (got - want).abs() < 1e-6 * want.abs().max(1.0),
                "{got} {want}"
            );
        }
    }

    #[test]
    fn curvature_matches_the_plane_curve_formula() {
        let c = wavy();
        let t = 0.42;
        let h = 1e-4;
        let d1 = c.derivative(t);
        let d2 = (c.derivative(t + h) - c.derivative(t - h)) / (2.0 * h);
        let want = d1.cross(d2) / d1.hypot().powi(3);
        assert!((c.curvature(t) - want).abs() < 1e-7 * want.abs());
    }

    #[test]
    fn arc_length_of_a_quarter_circle() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let w = (2.0 * c + 1.0) / 3.0;
        let k = 2.0 * c / (1.0 + 2.0 * c);
        let arc = RationalCubic::new(
            [
                Point::new(2.0, 0.0),
                Point::new(2.0, 2.0 * k),
                Point::new(2.0 * k, 2.0),
                Point::new(0.0, 2.0),
            ],
            [1.0, w, w, 1.0],
        )
        .unwrap();
        assert!((arc.arc_length() - std::f64::consts::PI).abs() < 1e-14);
    }

    #[test]
    fn weights_must_be_positive_and_finite() {
        let p = [
            Point::ZERO,
            Point::new(1.0, 0.0),
            Point::new(1.0, 1.0),
            Point::new(0.0, 1.0),
        ];
        assert!(matches!(
            RationalCubic::new(p, [1.0, 0.0, 1.0, 1.0]),
            Err(Error::OutOfRange { .. })
        ));
        assert!(matches!(
            RationalCubic::new(p, [1.0, f64::NAN, 1.0, 1.0]),
            Err(Error::NonFinite { .. })
        ));
    }
}
