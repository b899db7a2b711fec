//! Quasi-aesthetic curves: rational (or plain) cubic Bézier replacements of a
//! log-aesthetic segment or compound curve (seed 001 §4, docs/math.md §5), one piece as in the
//! seed or as many as a tolerance needs.
//!
//! * `fit.rs`: one piece over a span of the curve, the seed's least-squares rational cubic;
//! * `hermite.rs`: the plain cubic of the span's G2 Hermite data;
//! * `deviation.rs`: how far a piece strays from the curve, point by point where both have
//!   turned by the same angle;
//! * `chain.rs`: as few pieces as a tolerance allows, joined G2.

mod chain;
pub use chain::MAX_PIECES;
mod deviation;
mod fit;
mod hermite;

use kurbo::BezPath;

use crate::curve::bezier_chain::BezierChain;
use crate::curve::chain::SegmentChain;
use crate::family::bezier::RationalCubic;
use crate::family::monotone::{Monotonicity, MonotonicityReport};
use crate::family::sample::Sample;
use crate::foundation::error::{Error, Result};
use crate::foundation::tolerance::Tolerance;
use crate::foundation::turn::Turn;
use crate::segment::Segment;

use chain::greedy;
use fit::fit_span;

/// One piece of a [`QuasiCurve`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuasiPiece {
    /// The rational cubic (all weights equal for plain cubics).
    pub curve: RationalCubic,
    /// Its curvature monotonicity, decided with a proof.
    pub monotonicity: MonotonicityReport,
    /// The turning of the original curve, from its start, at the piece's two ends (radians,
    /// non-negative, ascending).
    pub turning: (f64, f64),
    /// Largest distance d(φ) to the original curve over the piece (caller's units). For a
    /// curve with an end of (nearly) zero curvature, an inflection, where points that have
    /// turned by the same angle lie far apart along a nearly straight stretch, the largest
    /// distance from the curve's points to the piece (their closest points) instead: see
    /// `deviation.rs`.
    pub max_deviation: f64,
}

/// A chain of cubic Bézier pieces replacing a log-aesthetic curve, with its deviation.
///
/// ```
/// use kurbo::Point;
/// use lac::{Monotonicity, Segment, ToBezier, Tolerance};
///
/// let seg = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.0, 0.8)],
///     -1.0,
/// )?;
/// // The seed's single rational cubic …
/// let one = seg.to_rational_cubic()?;
/// assert_eq!(one.pieces.len(), 1);
/// assert!(one.max < 1e-2);
/// // … or as many as a tolerance of 1e-9 of the arc length needs.
/// let fine = seg.to_rational_cubics(Tolerance::Relative(1e-9))?;
/// assert!(fine.max <= 1e-9);
/// assert!(fine.pieces.iter().all(|p| p.monotonicity.proven
///     && p.monotonicity.verdict == Monotonicity::Increasing));
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct QuasiCurve {
    /// The pieces in order from the curve's first control point.
    pub pieces: Vec<QuasiPiece>,
    /// √(∫ d(φ)² dφ / Θ) divided by the original curve's arc length.
    pub rms: f64,
    /// max d(φ) divided by the original curve's arc length.
    pub max: f64,
}

impl QuasiCurve {
    /// The pieces as one curve for kurbo's traits, piece i of n covering the parameter
    /// range [i/n, (i + 1)/n] (see [`BezierChain`]).
    ///
    /// Errors: no pieces ([`Error::OutOfRange`]; never for a curve this crate made).
    pub fn chain(&self) -> Result<BezierChain> {
        BezierChain::new(self.pieces.iter().map(|p| p.curve).collect())
    }

    /// The chain as a kurbo path when every piece is a plain cubic (all its weights equal),
    /// as [`ToBezier::to_cubics`] makes them, e.g. for [`BezPath::to_svg`]; None when a piece
    /// is rational (or there are none).
    pub fn to_bez_path(&self) -> Option<BezPath> {
        self.chain().ok()?.to_bez_path()
    }
}

/// Bézier replacements of a curve with monotone curvature of one sign (seed 001 §4): every
/// [`TurningCurve`] has them, e.g. a [`Segment`](crate::Segment) or a
/// [`CompoundCurve`](crate::CompoundCurve).
///
/// Each answer is checked before it is returned: every number finite, and the G2 joins as a
/// reader of the control points sees them.
pub trait ToBezier: TurningCurve {
    /// One rational cubic with the curve's ends, end tangents and end curvatures, closest
    /// to it in the least-squares sense of seed 001 §4 (see [`QuasiCurve`]).
    fn to_rational_cubic(&self) -> Result<QuasiCurve> {
        replace(self, None, Kind::Seed)
    }

    /// As few rational cubics as needed for a maximum deviation within `tolerance`, each
    /// with curvature proven monotone in the curve's direction, joined G2.
    fn to_rational_cubics(&self, tolerance: Tolerance) -> Result<QuasiCurve> {
        replace(self, Some(tolerance), Kind::Rational)
    }

    /// As few plain (polynomial) cubics as needed for a maximum deviation within
    /// `tolerance`, each with curvature proven monotone, joined G2: for consumers that only
    /// take cubics (SVG paths, fonts). Their chain is a kurbo `BezPath`
    /// ([`QuasiCurve::to_bez_path`]).
    fn to_cubics(&self, tolerance: Tolerance) -> Result<QuasiCurve> {
        replace(self, Some(tolerance), Kind::Polynomial)
    }
}

impl<C: TurningCurve + ?Sized> ToBezier for C {}

/// The quasi-aesthetic replacement of `curve` (see [`ToBezier`]).
fn replace(
    curve: &(impl TurningCurve + ?Sized),
    tolerance: Option<Tolerance>,
    kind: Kind,
) -> Result<QuasiCurve> {
    let tolerance = tolerance
        .map(|t| t.relative_to(curve.length()))
        .transpose()?;
    let quasi = approximate(curve, tolerance, kind)?;
    // Every number of the answer finite, or no answer: a near-straight curve with a hook
    // at an end asks the single rational cubic for weights ~1e152 and an infinite deviation.
    let finite = quasi.rms.is_finite()
        && quasi.max.is_finite()
        && quasi.pieces.iter().all(|p| {
            let b = p.curve.points();
            b.iter().all(|q| q.is_finite())
                && p.curve.weights().iter().all(|w| w.is_finite())
                && p.turning.0.is_finite()
                && p.turning.1.is_finite()
                && p.max_deviation.is_finite()
        });
    if !finite {
        return Err(Error::Unrepresentable {
            what: "Bézier replacement (its weights or deviation overflow)",
        });
    }
    // A piece is evaluated in the power basis of its homogeneous control points relative to
    // the first, whose coefficients reach 24 times those: beyond 2^1018 they leave double
    // range (pieces of a curve 1e307 across).
    let evaluable = quasi.pieces.iter().all(|p| {
        let (b, w) = (p.curve.points(), p.curve.weights());
        b.iter().zip(w).all(|(q, w)| {
            let d = (q.x - b[0].x).abs().max((q.y - b[0].y).abs());
            w * d <= LARGEST_HOMOGENEOUS
        })
    });
    if !evaluable {
        return Err(Error::Unrepresentable {
            what: "Bézier replacement (its control points too near the largest double to \
                   evaluate)",
        });
    }
    check_joins(&quasi)?;
    Ok(quasi)
}

/// The largest homogeneous coordinate of a piece's control point (relative to its first)
/// that its evaluation keeps within double range: 2^1018.
const LARGEST_HOMOGENEOUS: f64 = 2.8e306;

/// The G2 joins as a reader sees them: each piece's end curvature evaluated from its
/// control points as written must match the next piece's start curvature, within 1e-6 of the
/// chain's largest end curvature plus what rounding the control points' coordinates can
/// do there. (The fit joins pieces exactly in its own frame; a piece with a very short
/// first or last leg, as extreme weights make it, can lose that in world coordinates.)
fn check_joins(quasi: &QuasiCurve) -> Result<()> {
    let ends = |c: &RationalCubic| [c.signed_curvature(0.0), c.signed_curvature(1.0)];
    let kmax = quasi
        .pieces
        .iter()
        .flat_map(|p| ends(&p.curve))
        .fold(0.0f64, |m, k| m.max(k.abs()));
    for w in quasi.pieces.windows(2) {
        let (a, b) = (&w[0].curve, &w[1].curve);
        let (ka, kb) = (ends(a)[1], ends(b)[0]);
        let allowed =
            1e-6 * kmax + end_curvature_rounding(a, false) + end_curvature_rounding(b, true);
        if (ka - kb).abs() > allowed {
            return Err(Error::NumericalFailure {
                what: "G2 joins of the Bézier replacement (a piece's end curvature is too \
                       sensitive to its control points' rounding)",
            });
        }
    }
    Ok(())
}

/// How far rounding the control points (by a few ulps of their largest coordinate) can move
/// a rational cubic's curvature at an end: with L the first leg, D the distance to the
/// third point and h that point's distance from the tangent, κ ∝ h/L², so
/// |Δκ| ≲ |κ| (2δ/L + δ(1 + D/L)/h).
fn end_curvature_rounding(c: &RationalCubic, at_start: bool) -> f64 {
    let p = c.points();
    let (b0, b1, b2) = if at_start {
        (p[0], p[1], p[2])
    } else {
        (p[3], p[2], p[1])
    };
    let big = p
        .iter()
        .fold(0.0f64, |m, q| m.max(q.x.abs()).max(q.y.abs()));
    let delta = 4.0 * f64::EPSILON * big;
    let (leg, far) = (b1 - b0, b2 - b0);
    let l = leg.x.hypot(leg.y);
    let d = far.x.hypot(far.y);
    let h = (leg.x / l * far.y - leg.y / l * far.x).abs();
    let k = c.signed_curvature(if at_start { 0.0 } else { 1.0 }).abs();
    let bound = k * (2.0 * delta / l + delta * (1.0 + d / l) / h);
    if bound.is_nan() {
        f64::INFINITY
    } else {
        bound
    }
}

/// What a Bézier replacement needs of a curve ([`ToBezier`]): a curve with monotone
/// curvature of one sign, evaluated by its turning φ ∈ [0, Θ] from the start tangent, as
/// kurbo's `fit_to_bezpath` asks `ParamCurveFit` of its input. Every chain of log-aesthetic
/// segments ([`SegmentChain`]) is one.
pub trait TurningCurve {
    /// Total turning Θ, radians, in (0, 2π).
    fn total_turning(&self) -> f64;
    /// Does it turn left (positive curvature)?
    fn turns_left(&self) -> bool;
    /// Arc length.
    fn length(&self) -> f64;
    /// Signed curvature at the start and at the end.
    fn end_curvatures(&self) -> (f64, f64);
    /// Samples where the tangent has turned by each of `phi` (ascending, within [0, Θ]).
    fn at_turning(&self, phi: &[f64]) -> Result<Vec<Sample>>;
    /// Samples at the arc lengths `s` (ascending, within [0, length]).
    fn at_arc_lengths(&self, s: &[f64]) -> Result<Vec<Sample>>;
    /// Is every piece of slope α < 0 (a curve that can reach zero curvature)?
    fn can_inflect(&self) -> bool;
}

impl<C: SegmentChain + ?Sized> TurningCurve for C {
    fn total_turning(&self) -> f64 {
        self.pieces().iter().map(Segment::turning_angle).sum()
    }

    fn turns_left(&self) -> bool {
        self.pieces()[0].turn() == Turn::Left
    }

    fn length(&self) -> f64 {
        self.pieces().iter().map(Segment::length).sum()
    }

    fn end_curvatures(&self) -> (f64, f64) {
        let pieces = self.pieces();
        (
            pieces[0].end_curvatures().0,
            pieces[pieces.len() - 1].end_curvatures().1,
        )
    }

    fn at_turning(&self, phi: &[f64]) -> Result<Vec<Sample>> {
        let pieces = self.pieces();
        let mut out = Vec::with_capacity(phi.len());
        let (mut next, mut turned, mut start) = (0, 0.0, 0.0);
        for (i, piece) in pieces.iter().enumerate() {
            let turning = piece.turning_angle();
            let last = i + 1 == pieces.len();
            let mut stations = Vec::new();
            while next < phi.len() && (last || phi[next] <= turned + turning) {
                stations.push(piece.station_at_turning(phi[next] - turned)?);
                next += 1;
            }
            if !stations.is_empty() {
                out.extend(piece.samples_at(&stations).into_iter().map(|s| Sample {
                    s: s.s + start,
                    ..s
                }));
            }
            turned += turning;
            start += piece.length();
        }
        Ok(out)
    }

    fn at_arc_lengths(&self, s: &[f64]) -> Result<Vec<Sample>> {
        crate::curve::Curve::samples_at_arc_lengths(self, s)
    }

    fn can_inflect(&self) -> bool {
        self.pieces().iter().all(|p| p.alpha() < 0.0)
    }
}

/// Which cubic a span gets.
#[derive(Clone, Copy, PartialEq)]
pub(crate) enum Kind {
    /// The seed's least-squares rational cubic.
    Seed,
    /// The better of the seed's fit and the G2 cubic.
    Rational,
    /// The G2 plain cubic.
    Polynomial,
}

fn approximate(
    curve: &(impl TurningCurve + ?Sized),
    tolerance: Option<f64>,
    kind: Kind,
) -> Result<QuasiCurve> {
    let length = curve.length();
    let total = curve.total_turning();
    let (k0, k1) = curve.end_curvatures();
    let expected = expected_direction(k0, k1);
    let pieces = match tolerance {
        None => vec![fit_span(curve, 0.0, total, kind)?.fitted],
        Some(tol) => greedy(curve, tol * length, kind, expected)?,
    };
    let (mut integral, mut max) = (0.0, 0.0f64);
    for p in &pieces {
        integral += p.integral;
        max = max.max(p.piece.max_deviation);
    }
    Ok(QuasiCurve {
        pieces: pieces.into_iter().map(|p| p.piece).collect(),
        // The integrals are relative to the length squared already.
        rms: (integral / total).sqrt(),
        max: max / length,
    })
}

/// The verdict a faithful piece must have: that of the curve (constant for an arc).
fn expected_direction(k0: f64, k1: f64) -> Monotonicity {
    if (k1 - k0).abs() <= 1e-12 * k0.abs().max(k1.abs()) {
        Monotonicity::Constant
    } else if k1 > k0 {
        Monotonicity::Increasing
    } else {
        Monotonicity::Decreasing
    }
}

/// The error of a span no cubic follows.
fn unfittable() -> Error {
    Error::FitFailed
}
