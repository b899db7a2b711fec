//! A chain of rational cubic Bézier pieces as one curve for kurbo's traits: the pieces of a
//! [`QuasiCurve`](crate::QuasiCurve), or any pieces joined end to end.
//!
//! The chain's parameter t ∈ [0, 1] is cut at knots 0 = k₀ < k₁ < … < kₙ = 1, piece i
//! covering [kᵢ, kᵢ₊₁] with its own parameter (t − kᵢ)/(kᵢ₊₁ − kᵢ). A new chain has the
//! knots i/n; a subsegment keeps the parametrisation (it is affine in t), so its knots are
//! the old ones mapped onto [0, 1].

use std::ops::Range;

use kurbo::{BezPath, ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, Point};

use crate::curve::{check_arc_length, Curve};
use crate::family::bezier::RationalCubic;
use crate::foundation::error::{Error, Result};

/// Rational cubic Bézier pieces x₀, …, xₙ₋₁ as one curve, x(t) = xᵢ((t − kᵢ)/(kᵢ₊₁ − kᵢ))
/// for t ∈ [kᵢ, kᵢ₊₁], with kurbo's [`ParamCurve`], [`ParamCurveDeriv`],
/// [`ParamCurveArclen`] and [`ParamCurveCurvature`].
///
/// A new chain has the knots kᵢ = i/n: piece i covers t ∈ [i/n, (i + 1)/n]. At a knot the
/// chain is the piece that starts there (and at t = 1 the last piece's end). The pieces are
/// meant to join end to end, as those of a [`QuasiCurve`](crate::QuasiCurve) do (within
/// rounding); the chain does not check it. As for [`RationalCubic`], t is clamped to
/// [0, 1] and NaN gives NaN, and kurbo's curvature is positive for a right turn.
///
/// ```
/// use kurbo::{ParamCurve, ParamCurveArclen, Point};
/// use lac::{Curve, Segment, ToBezier, Tolerance};
///
/// let seg = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(3.0, 0.0), Point::new(4.0, 1.5)],
///     -1.0,
/// )?;
/// let quasi = seg.to_cubics(Tolerance::Relative(1e-5))?;
/// let chain = quasi.chain()?;
/// assert_eq!(chain.pieces().len(), quasi.pieces.len());
/// assert!((chain.arclen(1e-9) - seg.arc_length()).abs() < 1e-4 * seg.arc_length());
/// assert!((chain.end() - Point::new(4.0, 1.5)).hypot() < 1e-12);
/// // Plain cubics, so kurbo writes the SVG path.
/// assert!(quasi.to_bez_path().unwrap().to_svg().starts_with("M0,0 C"));
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierChain {
    pieces: Vec<RationalCubic>,
    /// n + 1 ascending knots from 0 to 1.
    knots: Vec<f64>,
}

impl BezierChain {
    /// The chain of `pieces` in order, piece i covering t ∈ [i/n, (i + 1)/n].
    ///
    /// Errors: no pieces ([`Error::OutOfRange`]).
    pub fn new(pieces: Vec<RationalCubic>) -> Result<BezierChain> {
        if pieces.is_empty() {
            return Err(Error::OutOfRange {
                name: "pieces",
                value: 0.0,
                expected: "at least one Bézier piece",
            });
        }
        let n = pieces.len();
        let knots = (0..=n).map(|i| i as f64 / n as f64).collect();
        Ok(BezierChain { pieces, knots })
    }

    /// The pieces, in order.
    pub fn pieces(&self) -> &[RationalCubic] {
        &self.pieces
    }

    /// The knots k₀ = 0 < k₁ < … < kₙ = 1: piece i covers [kᵢ, kᵢ₊₁].
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The chain as a kurbo path, when every piece is a plain cubic (all its weights equal):
    /// a move to the first point, then one cubic per piece, each starting where the previous
    /// one ends. None when a piece is rational.
    pub fn to_bez_path(&self) -> Option<BezPath> {
        let mut path = BezPath::new();
        path.move_to(self.pieces[0].start());
        for piece in &self.pieces {
            let c = piece.to_cubic()?;
            path.curve_to(c.p1, c.p2, c.p3);
        }
        Some(path)
    }

    /// The piece at `t` (clamped to [0, 1]) and its own parameter there; NaN for NaN.
    fn locate(&self, t: f64) -> (usize, f64) {
        let t = t.clamp(0.0, 1.0);
        let n = self.pieces.len();
        let i = self.knots[1..n].partition_point(|&k| k <= t);
        (i, (t - self.knots[i]) / self.width(i))
    }

    /// kᵢ₊₁ − kᵢ.
    fn width(&self, i: usize) -> f64 {
        self.knots[i + 1] - self.knots[i]
    }
}

impl ParamCurve for BezierChain {
    fn eval(&self, t: f64) -> Point {
        let (i, u) = self.locate(t);
        self.pieces[i].eval(u)
    }

    /// The part between `range.start` and `range.end` (each clamped to [0, 1]; reversed when
    /// start > end): the pieces it overlaps, each cut with [`RationalCubic`]'s subsegment,
    /// with the knots mapped so that `c.subsegment(a..b).eval(u) = c.eval(a + u (b − a))`.
    /// A NaN end gives a one-piece chain of NaN.
    fn subsegment(&self, range: Range<f64>) -> BezierChain {
        let (a, b) = (range.start.clamp(0.0, 1.0), range.end.clamp(0.0, 1.0));
        if a.is_nan() || b.is_nan() || a == b {
            let (i, u) = self.locate(if a.is_nan() { a } else { b });
            return BezierChain {
                pieces: vec![self.pieces[i].subsegment(u..u)],
                knots: vec![0.0, 1.0],
            };
        }
        let (lo, hi) = (a.min(b), a.max(b));
        // The overlapped part of each piece, as the chain's t and as the piece's own.
        let mut parts: Vec<(RationalCubic, f64)> = Vec::new();
        for (i, piece) in self.pieces.iter().enumerate() {
            let (k0, k1) = (self.knots[i], self.knots[i + 1]);
            let (s, e) = (lo.max(k0), hi.min(k1));
            if s >= e {
                continue;
            }
            let (us, ue) = ((s - k0) / self.width(i), (e - k0) / self.width(i));
            // Where the part starts in the new parameter.
            if a < b {
                parts.push((piece.subsegment(us..ue), (s - a) / (b - a)));
            } else {
                parts.push((piece.subsegment(ue..us), (e - a) / (b - a)));
            }
        }
        if a > b {
            parts.reverse();
        }
        let mut pieces = Vec::with_capacity(parts.len());
        let mut knots = Vec::with_capacity(parts.len() + 1);
        for (piece, start) in parts {
            let start = if knots.is_empty() { 0.0 } else { start };
            // A part that rounding makes empty in the new parameter is never reached.
            if knots.last().is_some_and(|&k| start <= k) || start >= 1.0 {
                continue;
            }
            pieces.push(piece);
            knots.push(start);
        }
        knots.push(1.0);
        BezierChain { pieces, knots }
    }

    fn start(&self) -> Point {
        self.pieces[0].start()
    }

    fn end(&self) -> Point {
        self.pieces[self.pieces.len() - 1].end()
    }
}

impl ParamCurveArclen for BezierChain {
    /// The sum of the pieces' arc lengths, each within `accuracy` / n.
    fn arclen(&self, accuracy: f64) -> f64 {
        let share = accuracy / self.pieces.len() as f64;
        self.pieces.iter().map(|p| p.arclen(share)).sum()
    }

    /// The parameter at arc length `arclen` from the start, within `accuracy`: the piece
    /// where the running sum of lengths reaches it (each length within `accuracy` / 2n),
    /// then that piece's [`ParamCurveArclen::inv_arclen`] within `accuracy` / 2. 0 for
    /// `arclen` ≤ 0, 1 from the length on, NaN for NaN.
    fn inv_arclen(&self, arclen: f64, accuracy: f64) -> f64 {
        if arclen.is_nan() {
            return f64::NAN;
        }
        if arclen <= 0.0 {
            return 0.0;
        }
        let share = 0.5 * accuracy / self.pieces.len() as f64;
        let mut before = 0.0;
        for (i, piece) in self.pieces.iter().enumerate() {
            let length = piece.arclen(share);
            if length.is_nan() {
                return f64::NAN;
            }
            if arclen < before + length {
                let u = piece.inv_arclen(arclen - before, 0.5 * accuracy);
                return self.knots[i] + u * self.width(i);
            }
            before += length;
        }
        1.0
    }
}

/// By arc length, each piece's length by its fixed Gauss rule ([`RationalCubic::arc_length`])
/// and a point at `s` by the piece's inverse arc length (to 1e-13 of its length); the
/// tangent direction is followed along each piece in 16 steps, so it stays continuous while
/// no step turns by π or more (no cusp).
impl Curve for BezierChain {
    fn arc_length(&self) -> f64 {
        self.pieces.iter().map(RationalCubic::arc_length).sum()
    }

    fn start_point(&self) -> Point {
        self.start()
    }

    fn end_point(&self) -> Point {
        self.end()
    }

    fn signed_curvature_start(&self) -> f64 {
        self.pieces[0].signed_curvature(0.0)
    }

    fn signed_curvature_end(&self) -> f64 {
        self.pieces[self.pieces.len() - 1].signed_curvature(1.0)
    }

    fn turning(&self) -> f64 {
        self.pieces.iter().map(|p| turning_to(p, 1.0)).sum()
    }

    fn point_at_s(&self, s: f64) -> Result<Point> {
        let (i, t) = self.at_s(s)?;
        Ok(self.pieces[i].eval(t))
    }

    fn theta_at_s(&self, s: f64) -> Result<f64> {
        let (i, t) = self.at_s(s)?;
        let first = self.pieces[0].derivative(0.0);
        let before: f64 = self.pieces[..i].iter().map(|p| turning_to(p, 1.0)).sum();
        let theta = first.y.atan2(first.x) + before + turning_to(&self.pieces[i], t);
        if self.pieces[i].derivative(t).hypot() > 0.0 && theta.is_finite() {
            Ok(theta)
        } else {
            Err(Error::CurvatureUndefined { piece: i, t })
        }
    }

    fn signed_curvature_at_s(&self, s: f64) -> Result<f64> {
        let (i, t) = self.at_s(s)?;
        Ok(self.pieces[i].signed_curvature(t))
    }

    fn curvature_derivative_at_s(&self, s: f64) -> Result<f64> {
        let (i, t) = self.at_s(s)?;
        Ok(self.pieces[i].curvature_derivative(t))
    }

    fn joint_arc_lengths(&self) -> Vec<f64> {
        let mut s = 0.0;
        self.pieces[..self.pieces.len() - 1]
            .iter()
            .map(|p| {
                s += p.arc_length();
                s
            })
            .collect()
    }
}

impl BezierChain {
    /// The piece holding arc length `s` (a knot belongs to the piece after it) and the
    /// piece's own parameter there.
    fn at_s(&self, s: f64) -> Result<(usize, f64)> {
        let lengths: Vec<f64> = self.pieces.iter().map(RationalCubic::arc_length).collect();
        check_arc_length(s, lengths.iter().sum())?;
        let mut before = 0.0;
        for (i, (piece, &length)) in self.pieces.iter().zip(&lengths).enumerate() {
            if s < before + length || i + 1 == self.pieces.len() {
                let local = (s - before).clamp(0.0, length);
                return Ok((i, piece.inv_arclen(local, 1e-13 * length)));
            }
            before += length;
        }
        unreachable!("a chain has at least one piece")
    }
}

/// The signed turning of the tangent of `piece` from its start to `t`, in 16 steps each
/// taken as the smaller angle between the step's end tangents.
fn turning_to(piece: &RationalCubic, t: f64) -> f64 {
    let direction = |u: f64| {
        let d = piece.derivative(u);
        d.y.atan2(d.x)
    };
    let steps = 16;
    let mut turned = 0.0;
    let mut previous = direction(0.0);
    for k in 1..=steps {
        let next = direction(t * k as f64 / steps as f64);
        let d = next - previous;
        turned += d - std::f64::consts::TAU * (d / std::f64::consts::TAU).round();
        previous = next;
    }
    turned
}

impl ParamCurveCurvature for BezierChain {
    /// kurbo's signed curvature, **positive for a right turn**: the negative of the piece's
    /// [`RationalCubic::signed_curvature`] (curvature does not depend on the
    /// parametrisation).
    fn curvature(&self, t: f64) -> f64 {
        let (i, u) = self.locate(t);
        -self.pieces[i].signed_curvature(u)
    }
}

impl ParamCurveDeriv for BezierChain {
    type DerivResult = BezierChainDerivative;

    fn deriv(&self) -> BezierChainDerivative {
        BezierChainDerivative {
            chain: self.clone(),
            order: 1,
            t0: 0.0,
            t1: 1.0,
            scale: 1.0,
        }
    }
}

/// The `order`-th derivative of a [`BezierChain`] in its parameter t, as a curve (kurbo's
/// convention: the vectors are returned as points): on piece i,
/// x⁽ᵏ⁾(t) = xᵢ⁽ᵏ⁾(u) / (kᵢ₊₁ − kᵢ)ᵏ, exact up to rounding as for
/// [`RationalCubicDerivative`](crate::RationalCubicDerivative). Like the chain it is
/// clamped to t ∈ [0, 1] (NaN gives NaN) and takes a knot from the piece that starts there;
/// a subsegment keeps the parametrisation.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierChainDerivative {
    chain: BezierChain,
    order: u32,
    /// eval(u) = scale · x⁽ᵏ⁾(t₀ + u (t₁ − t₀)).
    t0: f64,
    t1: f64,
    scale: f64,
}

impl BezierChainDerivative {
    /// The order k ≥ 1 of the derivative.
    pub fn order(&self) -> u32 {
        self.order
    }
}

impl ParamCurve for BezierChainDerivative {
    fn eval(&self, u: f64) -> Point {
        let t = self.t0 + u.clamp(0.0, 1.0) * (self.t1 - self.t0);
        let (i, v) = self.chain.locate(t);
        let stretch = self
            .chain
            .width(i)
            .powi(self.order.min(i32::MAX as u32) as i32);
        (self.scale / stretch * self.chain.pieces[i].nth_derivative(v, self.order)).to_point()
    }

    fn subsegment(&self, range: Range<f64>) -> BezierChainDerivative {
        let at = |u: f64| self.t0 + u.clamp(0.0, 1.0) * (self.t1 - self.t0);
        BezierChainDerivative {
            t0: at(range.start),
            t1: at(range.end),
            ..self.clone()
        }
    }
}

impl ParamCurveDeriv for BezierChainDerivative {
    type DerivResult = BezierChainDerivative;

    fn deriv(&self) -> BezierChainDerivative {
        BezierChainDerivative {
            order: self.order.saturating_add(1),
            scale: self.scale * (self.t1 - self.t0),
            ..self.clone()
        }
    }
}
