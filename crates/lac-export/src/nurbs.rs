//! A rational degree-3 B-spline curve with clamped knots, built from Bézier pieces: what
//! every CAD format of this module writes.
//!
//! Piece i of n, with control points b₀ … b₃ and weights w₀ … w₃, becomes the knot span
//! [tᵢ, tᵢ₊₁]; the knot vector is (t₀, t₀, t₀, t₀, t₁, t₁, t₁, …, tₙ, tₙ, tₙ, tₙ), every interior
//! knot of multiplicity 3 (= the degree), so the B-spline is exactly the chain of Bézier
//! pieces and the control points are the pieces' (a join's point shared). The knots are the
//! pieces' cumulative arc lengths, so that the parameter runs about as arc length.
//!
//! A join's control point has one weight, so each piece is first reparametrised (a Möbius
//! transformation of its parameter, which leaves the curve unchanged) so that its end weights
//! are 1: wᵢ ← wᵢ ρ^i / w₀ with ρ = (w₀/w₃)^(1/3).

use lac::{Error, RationalCubic, Result};

/// The degree of every curve written.
pub const DEGREE: usize = 3;

/// A rational B-spline curve of degree 3 with clamped knots, in 2-D (z = 0) or 3-D.
#[derive(Clone, Debug, PartialEq)]
pub struct Nurbs {
    /// The control points (z = 0 for a planar curve): 3n + 1 for n spans.
    pub control_points: Vec<[f64; 3]>,
    /// One positive weight per control point.
    pub weights: Vec<f64>,
    /// The knot vector, 3n + 5 values, non-decreasing, the ends of multiplicity 4.
    pub knots: Vec<f64>,
    /// Does the curve lie in the plane z = 0 (a planar result)?
    pub planar: bool,
}

/// One rational Bézier piece in homogeneous-ready form: control points and weights.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span {
    /// b₀ … b₃.
    pub points: [[f64; 3]; 4],
    /// w₀ … w₃ (positive).
    pub weights: [f64; 4],
}

/// A point and its first two derivatives with respect to a parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet {
    /// The point.
    pub point: [f64; 3],
    /// First derivative.
    pub d1: [f64; 3],
    /// Second derivative.
    pub d2: [f64; 3],
}

impl Span {
    /// A planar rational cubic at z = 0.
    pub fn from_rational_cubic(c: &RationalCubic) -> Span {
        let p = c.points();
        Span {
            points: p.map(|q| [q.x, q.y, 0.0]),
            weights: c.weights(),
        }
    }

    /// The same curve with end weights 1 (see the module documentation); None when a weight
    /// is not positive and finite or the result is not finite.
    pub fn normalized(&self) -> Option<Span> {
        let w = self.weights;
        if !w.iter().all(|&x| x.is_finite() && x > 0.0) {
            return None;
        }
        let rho = (w[0] / w[3]).cbrt();
        let weights = [1.0, w[1] * rho / w[0], w[2] * rho * rho / w[0], 1.0];
        weights
            .iter()
            .all(|x| x.is_finite() && *x > 0.0)
            .then_some(Span { weights, ..*self })
    }

    /// Point and derivatives at u ∈ [0, 1] (with respect to u).
    pub fn jet(&self, u: f64) -> Jet {
        let v = 1.0 - u;
        let b = [v * v * v, 3.0 * v * v * u, 3.0 * v * u * u, u * u * u];
        let d = [
            -3.0 * v * v,
            3.0 * v * (v - 2.0 * u),
            3.0 * u * (2.0 * v - u),
            3.0 * u * u,
        ];
        let dd = [
            6.0 * v,
            6.0 * (3.0 * u - 2.0),
            6.0 * (1.0 - 3.0 * u),
            6.0 * u,
        ];
        let (mut pw, mut dpw, mut ddpw) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        let (mut w, mut dw, mut ddw) = (0.0, 0.0, 0.0);
        for i in 0..4 {
            let wi = self.weights[i];
            w += b[i] * wi;
            dw += d[i] * wi;
            ddw += dd[i] * wi;
            for k in 0..3 {
                let q = wi * self.points[i][k];
                pw[k] += b[i] * q;
                dpw[k] += d[i] * q;
                ddpw[k] += dd[i] * q;
            }
        }
        let point = pw.map(|x| x / w);
        let mut d1 = [0.0; 3];
        let mut d2 = [0.0; 3];
        for k in 0..3 {
            d1[k] = (dpw[k] - dw * point[k]) / w;
            d2[k] = (ddpw[k] - 2.0 * dw * d1[k] - ddw * point[k]) / w;
        }
        Jet { point, d1, d2 }
    }
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    crate::certify::norm([a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

impl Nurbs {
    /// The B-spline of the chain of `spans` with span i over the parameter interval
    /// `[knots[i], knots[i + 1]]` (`breaks`: n + 1 increasing values).
    ///
    /// Errors: no spans, a count of breaks that does not match, breaks not increasing and
    /// finite, consecutive spans that do not share their join point (to 1e-9 of the larger
    /// span, the rounding of the curve's coordinates and `join_slack`, a distance: pieces
    /// fitted each within a tolerance of a curve may meet that far apart; the B-spline
    /// takes the earlier piece's end), or weights that are not positive
    /// ([`Error::OutOfRange`]).
    pub fn from_spans(
        spans: &[Span],
        breaks: &[f64],
        planar: bool,
        join_slack: f64,
    ) -> Result<Nurbs> {
        let bad = |expected: &'static str| Error::OutOfRange {
            name: "spans",
            value: spans.len() as f64,
            expected,
        };
        if spans.is_empty() || breaks.len() != spans.len() + 1 {
            return Err(bad("at least one span and one more break than spans"));
        }
        if !breaks.windows(2).all(|w| w[0] < w[1]) || !breaks.iter().all(|b| b.is_finite()) {
            return Err(bad("increasing finite breaks"));
        }
        let mut control_points = Vec::with_capacity(3 * spans.len() + 1);
        let mut weights = Vec::with_capacity(3 * spans.len() + 1);
        let mut last_size = 0.0f64;
        let magnitude = spans
            .iter()
            .flat_map(|s| s.points.iter().flatten())
            .fold(0.0f64, |m, x| m.max(x.abs()));
        for (i, span) in spans.iter().enumerate() {
            let span = span.normalized().ok_or(bad("positive finite weights"))?;
            let size = distance(span.points[0], span.points[3]);
            if i == 0 {
                control_points.push(span.points[0]);
                weights.push(1.0);
            } else {
                // The pieces of a chain are fitted each in its own frame: their join points
                // agree to rounding (of the larger of the two pieces, when one is tiny). The
                // join is written once (the earlier piece's).
                let last = control_points[control_points.len() - 1];
                let gap = distance(last, span.points[0]);
                let scale = size.max(last_size).max(f64::MIN_POSITIVE);
                // (And what the rounding of the curve's coordinates allows: a piece 1e-8 long
                // next to a hook, on a curve of size 1, meets its neighbour only to 1e-16.)
                let allowed = 1e-9 * scale + 64.0 * f64::EPSILON * magnitude + join_slack;
                if gap.is_nan() || gap > allowed {
                    return Err(bad("consecutive spans that share their join point"));
                }
            }
            control_points.extend_from_slice(&span.points[1..]);
            weights.extend_from_slice(&span.weights[1..]);
            last_size = size;
        }
        if !control_points.iter().flatten().all(|x| x.is_finite()) {
            return Err(bad("finite control points"));
        }
        let n = spans.len();
        let mut knots = Vec::with_capacity(3 * n + 5);
        knots.push(breaks[0]);
        for &b in breaks {
            knots.extend([b, b, b]);
        }
        knots.push(breaks[n]);
        Ok(Nurbs {
            control_points,
            weights,
            knots,
            planar,
        })
    }

    /// The number of knot spans (Bézier pieces).
    pub fn span_count(&self) -> usize {
        (self.control_points.len() - 1) / DEGREE
    }

    /// Span `i` as a rational Bézier piece.
    pub fn span(&self, i: usize) -> Span {
        let k = DEGREE * i;
        Span {
            points: [0, 1, 2, 3].map(|j| self.control_points[k + j]),
            weights: [0, 1, 2, 3].map(|j| self.weights[k + j]),
        }
    }

    /// The parameter interval of span `i`.
    pub fn span_interval(&self, i: usize) -> (f64, f64) {
        (self.knots[DEGREE * i + 1], self.knots[DEGREE * i + 4])
    }

    /// Each span as a curve of its own (one Bézier span, knots (a,a,a,a,b,b,b,b)): for
    /// readers that refuse interior knots of multiplicity above 1.
    pub fn single_spans(&self) -> Vec<Nurbs> {
        (0..self.span_count())
            .map(|i| {
                let s = self.span(i);
                let (a, b) = self.span_interval(i);
                Nurbs {
                    control_points: s.points.to_vec(),
                    weights: s.weights.to_vec(),
                    knots: vec![a, a, a, a, b, b, b, b],
                    planar: self.planar,
                }
            })
            .collect()
    }

    /// Are all weights 1 (a polynomial B-spline)?
    pub fn is_polynomial(&self) -> bool {
        self.weights.iter().all(|&w| w == 1.0)
    }

    /// The multiplicities of the distinct knots, with those knots (STEP's and DXF's form).
    pub fn knot_multiplicities(&self) -> (Vec<usize>, Vec<f64>) {
        let (mut mult, mut values): (Vec<usize>, Vec<f64>) = (Vec::new(), Vec::new());
        for &k in &self.knots {
            if values.last() == Some(&k) {
                *mult.last_mut().expect("a value has a count") += 1;
            } else {
                values.push(k);
                mult.push(1);
            }
        }
        (mult, values)
    }

    /// The largest absolute coordinate (for IGES's global section).
    pub fn max_coordinate(&self) -> f64 {
        self.control_points
            .iter()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()))
    }
}
