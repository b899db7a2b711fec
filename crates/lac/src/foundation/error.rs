//! The crate's error type.

use std::fmt;

use crate::foundation::turn::Turn;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong when building or evaluating a log-aesthetic curve.
///
/// Every public function returns one of these for bad input instead of panicking.
///
/// ```
/// use lac::{Error, Segment};
/// use kurbo::Point;
/// let err = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(2.0, 0.0)], -1.0,
/// ).unwrap_err();
/// assert!(matches!(err, Error::CollinearPoints));
/// assert_eq!(err.kind(), lac::ErrorKind::CollinearPoints);
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An input number is NaN or infinite.
    #[error("{what} must be a finite number, got {value}")]
    NonFinite {
        /// Which input was not finite.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// Two control points coincide, so a tangent direction is undefined.
    #[error("control points {first} and {second} coincide; move them apart")]
    CoincidentPoints {
        /// Index of the first point (0-based).
        first: usize,
        /// Index of the second point (0-based).
        second: usize,
    },
    /// The three control points are collinear: a straight line (or a reversal) is not a
    /// log-aesthetic curve.
    #[error(
        "the control points are collinear; a straight line is not a log-aesthetic curve: \
         move the middle point off the line through the other two"
    )]
    CollinearPoints,
    /// The control polygon turns left at one vertex and right at another: a log-aesthetic
    /// curve (or compound curve) has monotone curvature of one sign and no inflection.
    #[error(
        "the control polygon turns {} at P1 but {} at P2; a log-aesthetic curve \
         cannot have an inflection: move P1 or P2 so that the polygon turns one way only",
        word(*first),
        word(*second)
    )]
    InflectedPolygon {
        /// Turning direction at the first inner vertex.
        first: Turn,
        /// Turning direction at the second inner vertex.
        second: Turn,
    },
    /// A parameter is outside the range the operation accepts.
    #[error("{name} = {} is out of range: {expected}", Num(*value))]
    OutOfRange {
        /// The parameter's name.
        name: &'static str,
        /// The offending value.
        value: f64,
        /// What would be accepted.
        expected: &'static str,
    },
    /// The control points and α admit no log-aesthetic segment.
    #[error("not drawable: {0}")]
    NotDrawable(NotDrawable),
    /// No cubic with the curve's end points, end tangents and end curvatures follows it
    /// (the least-squares fit left the admissible region, or the G2 Hermite system has no
    /// admissible root): the curve changes curvature too much for one piece.
    #[error(
        "no single cubic with the curve's end points, tangents and curvatures follows it \
         (its curvature changes too much); give a tolerance so that it can be split"
    )]
    FitFailed,
    /// Pieces within the requested tolerance could not be found.
    #[error(
        "no chain of cubics with monotone curvature meets the tolerance {tolerance:e} (best \
         deviation reached {reached:e}, relative to the arc length); use a larger tolerance"
    )]
    ToleranceNotMet {
        /// The requested maximum deviation, relative to the arc length.
        tolerance: f64,
        /// The smallest deviation reached for the piece that failed, relative.
        reached: f64,
    },
    /// The curvature of a Bézier piece is undefined (or beyond double range) at a parameter:
    /// its speed vanishes there (a repeated control point, a cusp).
    #[error(
        "the curvature of piece {piece} is undefined at t = {t} (the curve stops there: a \
         repeated control point or a cusp), or beyond the range of double precision; move \
         the control points apart"
    )]
    CurvatureUndefined {
        /// The piece, from 0.
        piece: usize,
        /// The parameter.
        t: f64,
    },
    /// A quantity of a valid curve is beyond the range of double precision (the curve is
    /// too small or too large for it): scale the control points.
    #[error(
        "the {what} of this curve is beyond the range of double precision (the curve is too \
         small or too large for it); scale the control points toward size 1"
    )]
    Unrepresentable {
        /// What could not be represented.
        what: &'static str,
    },
    /// A chain within the tolerance would need more than [`MAX_PIECES`](crate::MAX_PIECES)
    /// pieces.
    #[error(
        "a chain of cubics within the tolerance {tolerance:e} (relative to the arc length) \
         would need more than {max_pieces} pieces; use a larger tolerance"
    )]
    TooManyPieces {
        /// The requested maximum deviation, relative to the arc length.
        tolerance: f64,
        /// The most pieces a chain may have.
        max_pieces: usize,
    },
    /// The segment of a path at polygon vertex `vertex` cannot be drawn.
    #[error("the segment at polygon vertex P{vertex} cannot be drawn: {source}")]
    PathSegment {
        /// The vertex (0-based) that carries the segment.
        vertex: usize,
        /// Why its control triangle has no segment.
        source: Box<Error>,
    },
    /// No path with continuous curvature (G2) was found: the joint on polygon leg `leg`
    /// (from P_leg to the next vertex) is where it fails.
    #[error("no G2 path: at the joint on leg P{leg}-P{}, {reason}", leg + 1)]
    NoG2Path {
        /// The leg, from 0 (leg i runs from P_i to P_{i+1}).
        leg: usize,
        /// Why.
        reason: G2Failure,
    },
    /// The span of a G2 spline from point `span` to the next cannot be drawn as one
    /// segment.
    #[error("the span from point P{span} cannot be drawn: {source}")]
    SplineSpan {
        /// The span (0-based): from point `span` to the next.
        span: usize,
        /// Why its segment cannot be drawn.
        source: Box<Error>,
    },
    /// No spline through the points with continuous curvature (G2) was found: the span
    /// from point `span` to the next is where it fails.
    #[error("no G2 spline: on the span from point P{span} to the next, {reason}")]
    NoG2Spline {
        /// The span (0-based): from point `span` to the next.
        span: usize,
        /// Why.
        reason: G2Failure,
    },
    /// A spline's point whose type (or a straight span or end condition there) cannot be
    /// met: the point and what to change.
    #[error("no spline: at point P{point}, {reason}")]
    SplinePoint {
        /// The point (0-based).
        point: usize,
        /// Why.
        reason: PointFailure,
    },
    /// Too few points to fit a curve to.
    #[error("a fit needs at least {needed} distinct points, got {got}; give more points")]
    TooFewPoints {
        /// The fewest points the fit needs.
        needed: usize,
        /// How many distinct points were given.
        got: usize,
    },
    /// No log-aesthetic path of the allowed number of segments stays within the tolerance of
    /// the points.
    #[error(
        "no log-aesthetic path of at most {segments} segment{} stays within {} of the points: \
         the best fit found is {} from them at worst, between points {from} and {to}; raise \
         the tolerance or allow more segments",
        if *segments == 1 { "" } else { "s" },
        Num(*tolerance),
        Num(*reached)
    )]
    FitToleranceNotMet {
        /// The tolerance asked, in the points' units.
        tolerance: f64,
        /// The largest distance of a point from the best fit found, in the points' units.
        reached: f64,
        /// The most segments allowed.
        segments: usize,
        /// The stretch of the points (0-based, inclusive) that stays farther than the
        /// tolerance from the best fit.
        from: usize,
        /// Its last point.
        to: usize,
    },
    /// A closed fit did not close: no closed chain of that many segments was found near the
    /// points.
    #[error(
        "no closed log-aesthetic path of {segments} segments was found near these points (the \
         fitted chain does not close up); allow more segments, or fit the points open"
    )]
    FitNotClosed {
        /// The segments of the chain that did not close.
        segments: usize,
    },
    /// A computation that should succeed for a solved curve did not (an overflow, or a
    /// bound of the family reached through rounding). This is a defect: please report the
    /// input that caused it.
    #[error("the computation of {what} failed numerically; please report this input")]
    NumericalFailure {
        /// What was being computed.
        what: &'static str,
    },
}

/// The kind of an [`Error`], without its details: what a program branches on. With the
/// `serde` feature it serialises as a snake_case name (`"not_drawable"`, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
#[non_exhaustive]
pub enum ErrorKind {
    /// [`Error::NonFinite`].
    NonFinite,
    /// [`Error::CoincidentPoints`].
    CoincidentPoints,
    /// [`Error::CollinearPoints`].
    CollinearPoints,
    /// [`Error::InflectedPolygon`].
    InflectedPolygon,
    /// [`Error::OutOfRange`].
    OutOfRange,
    /// [`Error::NotDrawable`].
    NotDrawable,
    /// [`Error::FitFailed`].
    FitFailed,
    /// [`Error::ToleranceNotMet`].
    ToleranceNotMet,
    /// [`Error::TooManyPieces`].
    TooManyPieces,
    /// [`Error::CurvatureUndefined`].
    CurvatureUndefined,
    /// [`Error::Unrepresentable`].
    Unrepresentable,
    /// [`Error::NumericalFailure`].
    NumericalFailure,
    /// [`Error::NoG2Path`], [`Error::NoG2Spline`] and [`Error::SplinePoint`].
    NoG2Path,
    /// [`Error::TooFewPoints`].
    TooFewPoints,
    /// [`Error::FitToleranceNotMet`].
    FitToleranceNotMet,
    /// [`Error::FitNotClosed`].
    FitNotClosed,
}

/// A number for a message: plain where that is short, in exponent form otherwise (a plain
/// 1e300 has 301 digits).
struct Num(f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = self.0.abs();
        if a == 0.0 || (1e-5..1e15).contains(&a) || !a.is_finite() {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}

/// A turning direction in words, for messages.
fn word(turn: Turn) -> &'static str {
    match turn {
        Turn::Left => "left",
        Turn::Right => "right",
    }
}

impl Error {
    /// The kind of error, for programs that branch on it.
    pub fn kind(&self) -> ErrorKind {
        match self {
            Error::NonFinite { .. } => ErrorKind::NonFinite,
            Error::CoincidentPoints { .. } => ErrorKind::CoincidentPoints,
            Error::CollinearPoints => ErrorKind::CollinearPoints,
            Error::InflectedPolygon { .. } => ErrorKind::InflectedPolygon,
            Error::OutOfRange { .. } => ErrorKind::OutOfRange,
            Error::NotDrawable(_) => ErrorKind::NotDrawable,
            Error::FitFailed => ErrorKind::FitFailed,
            Error::ToleranceNotMet { .. } => ErrorKind::ToleranceNotMet,
            Error::TooManyPieces { .. } => ErrorKind::TooManyPieces,
            Error::CurvatureUndefined { .. } => ErrorKind::CurvatureUndefined,
            Error::Unrepresentable { .. } => ErrorKind::Unrepresentable,
            Error::NumericalFailure { .. } => ErrorKind::NumericalFailure,
            Error::TooFewPoints { .. } => ErrorKind::TooFewPoints,
            Error::FitToleranceNotMet { .. } => ErrorKind::FitToleranceNotMet,
            Error::FitNotClosed { .. } => ErrorKind::FitNotClosed,
            Error::PathSegment { source, .. } => source.kind(),
            Error::NoG2Path { .. } | Error::NoG2Spline { .. } | Error::SplinePoint { .. } => {
                ErrorKind::NoG2Path
            }
            Error::SplineSpan { source, .. } => source.kind(),
        }
    }
}

/// Why a three-point configuration has no log-aesthetic segment for the requested α.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum NotDrawable {
    /// The angle at the end with the shorter leg, θe, is larger than any segment of this α
    /// can make: the segment would have to reach past the inflection point (α < 0) or past
    /// the point of zero radius (α > 1).
    ChordAngleTooLarge {
        /// The slope of the logarithmic curvature graph.
        alpha: f64,
        /// The required angle at the shorter-leg end, radians.
        theta_e: f64,
        /// The largest angle this α can make for this turning angle, radians.
        max: f64,
    },
    /// The chord from the first to the last point leaves the first point outside the angle
    /// swept by the tangents (possible with four control points): no convex curve fits.
    ChordOutsideTangents {
        /// Angle from the start tangent to the chord, in the turning direction, radians.
        theta_e: f64,
        /// Total turning of the control polygon, radians.
        turning: f64,
    },
    /// A compound curve of these slopes and this turning split cannot make the angle the
    /// control points need between the tangent at an end and the chord.
    CompoundChordAngleTooLarge {
        /// Slope of the piece at the first control point.
        alpha0: f64,
        /// Slope of the piece at the last control point.
        alpha1: f64,
        /// Whether the angle is the one at the first control point (else at the last).
        at_first: bool,
        /// The required angle, radians.
        theta_e: f64,
        /// The largest angle these slopes can make, radians.
        max: f64,
    },
    /// The radius of curvature would have to vary by more than `e^max_log_ratio` along the
    /// curve, beyond floating point (or the required angle is not reached at all).
    CurvatureRatioTooLarge {
        /// The slope of the piece that limits the search.
        alpha: f64,
        /// The natural logarithm of the largest supported ratio.
        max_log_ratio: f64,
        /// The required angle between the tangent at the sharper end and the chord, radians.
        theta_e: f64,
        /// The largest angle reached within that ratio, radians.
        reached: f64,
    },
    /// One piece of a compound curve would be too short to draw: shorter than
    /// [`MIN_PIECE_SHARE`](crate::MIN_PIECE_SHARE) of the curve, yet turning by its share of
    /// the polygon's turning.
    PieceTooShort {
        /// Which piece, in the caller's order (0: slope α0, from the first point).
        piece: usize,
        /// Its slope.
        alpha: f64,
        /// Its arc length as a share of the whole curve's.
        share: f64,
        /// Its turning, radians.
        turning: f64,
    },
    /// The curve would make a turn too small to draw at one of its ends: more than
    /// [`HIDDEN_TURNING`](crate::HIDDEN_TURNING) within [`HIDDEN_SHARE`](crate::HIDDEN_SHARE)
    /// of its length, at a radius of curvature far below its size. Its points would not
    /// show the end tangent asked for.
    HiddenTurn {
        /// At the first point (else at the last).
        at_first: bool,
        /// The turning within that share of the length, radians.
        turning: f64,
        /// The curvature at that end divided by the curvature at the other.
        curvature_ratio: f64,
    },
    /// No segment was found for the Ω asked, but one was for Ω = 0, and following it as Ω
    /// grows (seed 003 §4) reached `omega_max` and no further. That says where the search
    /// ended, not that no segment exists at the Ω asked: another branch, not connected to
    /// that segment, may have one.
    TorsionTooLarge {
        /// The Ω asked for.
        omega: f64,
        /// The largest Ω reached by following the segment found at Ω = 0 as Ω grows (to
        /// 0.1% of `omega`): there is a segment for every Ω up to it.
        omega_max: f64,
    },
    /// No log-aesthetic space segment of these α, β and type was found for the four points,
    /// nor with Ω = 0, in either order of the ends: the solver's search is bounded (a fixed
    /// budget of integration steps per solve, so that every call returns in bounded time),
    /// so this is what it found, not a proof that none exists.
    NoSpaceSegment {
        /// The Ω asked for.
        omega: f64,
    },
    /// The four control points are coplanar (no space segment: ν would be infinite) and the
    /// planar segment through the first point, the tangents' intersection and the last point
    /// does not exist: the tangents do not meet ahead of both ends.
    PlanarTangentsApart {
        /// Angle between the start and end tangent directions, radians (0 to π).
        turning: f64,
        /// Angle from the start tangent to the chord P3 − P0, radians (0 to π).
        chord_angle: f64,
    },
}

impl fmt::Display for NotDrawable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            NotDrawable::ChordAngleTooLarge {
                alpha,
                theta_e,
                max,
            } => write!(
                f,
                "with alpha = {alpha} the angle between the shorter leg and the chord can be at \
                 most {max:.6} rad ({:.4} deg), but the control points need {theta_e:.6} rad \
                 ({:.4} deg); move the middle control point toward the perpendicular bisector of \
                 the end points (a more isosceles triangle), or choose alpha between 0 and 1",
                max.to_degrees(),
                theta_e.to_degrees()
            ),
            NotDrawable::ChordOutsideTangents { theta_e, turning } => write!(
                f,
                "the chord P3 - P0 makes {:.4} deg with the start tangent, outside the \
                 {:.4} deg swept by the tangents; move P3 (or P0) so that the chord lies \
                 between the start and end tangent directions",
                theta_e.to_degrees(),
                turning.to_degrees()
            ),
            NotDrawable::CompoundChordAngleTooLarge {
                alpha0,
                alpha1,
                at_first,
                theta_e,
                max,
            } => write!(
                f,
                "with alpha0 = {alpha0}, alpha1 = {alpha1} and this split of the turning, the \
                 chord can make at most {:.4} deg with the tangent at the {} point, but the \
                 control points need {:.4} deg; make the control polygon more symmetric, move \
                 the joint (ratio) toward the {} point, or use slopes closer to the range 0..1",
                max.to_degrees(),
                if at_first { "first" } else { "last" },
                theta_e.to_degrees(),
                if at_first { "last" } else { "first" },
            ),
            NotDrawable::CurvatureRatioTooLarge {
                alpha,
                max_log_ratio,
                theta_e,
                reached,
            } => write!(
                f,
                "with alpha = {alpha} the curve would need its radius of curvature to vary by more \
                 than e^{max_log_ratio} (it reaches an angle of {:.6} deg between the sharper end's \
                 tangent and the chord there, and the control points need {:.6} deg); make the \
                 control polygon more symmetric",
                reached.to_degrees(),
                theta_e.to_degrees()
            ),
            NotDrawable::PieceTooShort {
                piece,
                alpha,
                share,
                turning,
            } => write!(
                f,
                "the alpha{piece} = {alpha} piece would be only {share:.1e} of the curve's length \
                 while turning {:.2} deg: the slopes need an extreme curvature ratio to meet \
                 these points, and no drawing could show that piece; make the control polygon \
                 more symmetric, change the turning ratio, or use slopes closer to the range \
                 0..1",
                turning.to_degrees(),
            ),
            NotDrawable::HiddenTurn {
                at_first,
                turning,
                curvature_ratio,
            } => write!(
                f,
                "the curve would turn by {:.2} deg within a trillionth of its length at its {} \
                 point, where its curvature is {} times that at the other end: no drawing \
                 could show that turn, and its points would not show the tangent asked for \
                 there; make the legs of the control polygon more alike, or choose another \
                 alpha",
                turning.to_degrees(),
                if at_first { "first" } else { "last" },
                Num(curvature_ratio),
            ),
            NotDrawable::TorsionTooLarge { omega, omega_max } => write!(
                f,
                "no space segment found for omega = {omega}; the segment of these points \
                 found by continuing from omega = 0 ends near omega = {omega_max:.6}; use an \
                 omega up to that, or move the control points"
            ),
            NotDrawable::NoSpaceSegment { omega } => write!(
                f,
                "no log-aesthetic space segment of these alpha, beta and type found for the four \
                 points (omega = {omega}{}); make the end angles to the chord more alike \
                 (theta0 close to theta1), or use alpha and beta nearer 0",
                if omega > 0.0 { ", nor with omega = 0" } else { "" }
            ),
            NotDrawable::PlanarTangentsApart {
                turning,
                chord_angle,
            } => write!(
                f,
                "the four points are coplanar, so only a planar segment could fit (beta and \
                 omega do not apply), but the tangents turn by {:.4} deg and the chord makes {:.4} \
                 deg with the start tangent: their lines do not meet ahead of both ends (the \
                 planar segment needs a turning below 180 deg with the chord between the \
                 tangents); move P1 or P2 so that the tangent lines meet",
                turning.to_degrees(),
                chord_angle.to_degrees()
            ),
        }
    }
}

/// Why a spline's point cannot have what its type, a straight span or an end condition asks
/// (docs/math.md, splines with point types).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PointFailure {
    /// The point ends a straight span (or has an end curvature of zero), where the curve
    /// must reach zero curvature, which a log-aesthetic curve does only for α < 0.
    ZeroCurvature {
        /// The spline's slope.
        alpha: f64,
    },
    /// The point joins two straight spans that are not in line, so its tangent breaks.
    StraightSpansNotInLine,
    /// The point ends a straight span, whose direction is its tangent, and has an angle of
    /// its own.
    AngleOnStraightSpan,
    /// The type or option does not fit where the point is (e.g. a corner's two directions
    /// at an open spline's end).
    Misplaced {
        /// What does not fit.
        what: &'static str,
    },
    /// The solver could not meet the condition at this point: `what`, missed by `miss`
    /// (relative, or radians for a direction).
    Unmet {
        /// The condition, in words.
        what: &'static str,
        /// How far from it the best answer reached stayed.
        miss: f64,
    },
}

impl fmt::Display for PointFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PointFailure::ZeroCurvature { alpha } => write!(
                f,
                "the curve must reach zero curvature (it meets a straight span, or its end \
                 curvature is 0), which a log-aesthetic curve does only for alpha < 0 (here \
                 alpha = {alpha}): use alpha < 0, or make this point a corner"
            ),
            PointFailure::StraightSpansNotInLine => write!(
                f,
                "it joins two straight spans that are not in line: make it a corner"
            ),
            PointFailure::AngleOnStraightSpan => write!(
                f,
                "it ends a straight span, whose direction is its tangent there: drop its \
                 angle (make it smooth) or make it a corner"
            ),
            PointFailure::Misplaced { what } => write!(f, "{what}"),
            PointFailure::Unmet { what, miss } => write!(
                f,
                "the curve could not be made to meet {what} there (missed by {miss:.1e}); \
                 move this point or its neighbours, give it another tangent, or make it a \
                 corner"
            ),
        }
    }
}

/// Reject NaN and infinities with a message that names the input.
pub(crate) fn finite(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NonFinite { what, value })
    }
}

/// Why no G2 path was found at a joint.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum G2Failure {
    /// Newton's method did not bring the curvature jump at this joint to zero: the best
    /// relative jump reached is `jump` (no G2 path nearby, e.g. the legs are too unequal for
    /// the segments' curvature ratios).
    NoConvergence {
        /// The smallest |ln(κ⁻/κ⁺)| reached at this joint.
        jump: f64,
    },
    /// The polygon turns one way before this leg and the other way after it: the curvature
    /// must pass through zero, which a log-aesthetic segment does only for α < 0.
    Inflection {
        /// The slopes of the segments before and after the leg.
        alphas: [f64; 2],
    },
    /// A segment next to this inflection (a path's leg, a spline's span) has α < 0, but its
    /// zero-curvature end cannot be resolved in double precision (the curvature there falls
    /// like d^(1/|α|) with the distance d from the inflection point: for α below about −1.7
    /// not to 1e-10 in a path, below about −1.3 not to 1e-9 in a spline).
    InflectionUnresolved {
        /// The segment's slope.
        alpha: f64,
    },
    /// The polygon's turning changes direction on both legs of one vertex: its segment would
    /// need zero curvature at both ends, which a monotone-curvature segment cannot have.
    InflectionsAtOneVertex {
        /// The vertex.
        vertex: usize,
    },
    /// A spline's span whose end tangents leave the chord on the same side (or where no
    /// single segment fits them): it needs an inflection, which a log-aesthetic curve has
    /// only for α < 0; for α < 0, no S-shaped span whose halves turn by at most π fits.
    SpanInflects,
    /// A spline's span passes through an inflection within a hair of one of its points (one
    /// half of its S turns by less than 1e-3 rad): the half is too flat to be drawn in double
    /// precision.
    InflectionAtPoint,
    /// The two segments that reach zero curvature on this leg need more than its length:
    /// they overlap by `overlap` (a share of the leg).
    InflectionLegTooShort {
        /// How much of the leg is missing, as a share of it.
        overlap: f64,
    },
    /// The segments on either side of a spline's point, solved from the same tangent
    /// direction there, leave it in directions `jump` radians apart (more than 1e-10): one of
    /// them is too flat or too sharply curved for double precision to place its tangent.
    TangentUnresolved {
        /// The angle between the two segments' tangents at the point, radians.
        jump: f64,
    },
}

impl fmt::Display for G2Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            G2Failure::NoConvergence { jump } => write!(
                f,
                "the curvature could not be made continuous there (smallest jump reached \
                 ln(k-/k+) = {jump:.3e}); make the neighbouring legs more alike in length or \
                 the turning angles at their vertices more alike"
            ),
            G2Failure::Inflection { alphas } => write!(
                f,
                "the polygon's turning changes direction on this leg, so the curvature must \
                 pass through zero; the segments there have alpha = {} and {}, and a \
                 log-aesthetic segment reaches zero curvature only for alpha < 0: use \
                 alpha < 0 for the segments next to this leg or use the G1 path",
                alphas[0], alphas[1]
            ),
            G2Failure::InflectionUnresolved { alpha } => write!(
                f,
                "the curve passes through an inflection here; a segment with alpha = {alpha} \
                 that ends there cannot be brought to zero curvature in double precision \
                 (use an alpha closer to 0: above about -1.5 next to a path's inflections, \
                 above about -1.3 in a spline's)"
            ),
            G2Failure::InflectionsAtOneVertex { vertex } => write!(
                f,
                "the polygon's turning changes direction on both legs of vertex {vertex}: \
                 its segment would need zero curvature at both ends; add a vertex that turns \
                 the same way next to it"
            ),
            G2Failure::SpanInflects => write!(
                f,
                "it would have to inflect: no single segment fits its end tangents; a \
                 log-aesthetic curve passes through an inflection only for alpha < 0 (and \
                 then its two halves may turn by at most 180 deg each): use alpha < 0, or \
                 add points where the curve turns"
            ),
            G2Failure::InflectionAtPoint => write!(
                f,
                "it passes through an inflection almost at one of its points (one half \
                 of its S turns by less than 0.001 rad, too flat to draw in double precision); \
                 move that point off the curve's inflection, or add a point"
            ),
            G2Failure::TangentUnresolved { jump } => write!(
                f,
                "the segments on either side of this point leave it {jump:.1e} rad apart, \
                 beyond what double precision resolves for segments this flat or this sharply \
                 curved; move the point a little, or use an alpha closer to 0"
            ),
            G2Failure::InflectionLegTooShort { overlap } => write!(
                f,
                "the polygon's turning changes direction on this leg, and the two segments \
                 that reach zero curvature there need {:.1}% more than its length; make the \
                 leg longer or its neighbours shorter",
                100.0 * overlap
            ),
        }
    }
}
