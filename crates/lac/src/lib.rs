//! Log-aesthetic curves.
//!
//! A log-aesthetic curve (LAC) has a straight logarithmic curvature graph:
//! `log(ρ ds/dρ) = α log ρ + c`, i.e. `dρ/ds = Λ ρ^(1−α)`. The clothoid (α = −1), Nielsen
//! spiral (α = 0), logarithmic spiral (α = 1), circle involute (α = 2) and circle (Λ = 0)
//! are members. This crate implements the systems of the papers by Yoshida, Saito, Miura and
//! colleagues ("seed 000" … "seed 004" in the docs; see the README's references):
//!
//! * [`StandardForm`]: ρ(s), θ(s), s(θ), ρ(θ), bounds, points, and the
//!   [`Classification`] of seed 000 Table 2;
//! * [`Curve`]: what a planar curve can do — its arc length and ends, its point, tangent
//!   direction, signed curvature and dκ/ds at an arc length — with sampling (equally,
//!   adaptively), the evolute, the curvature plot and the logarithmic curvature graph on top;
//!   every planar curve type implements it, a chain of log-aesthetic segments through its
//!   pieces ([`SegmentChain`]);
//! * [`Segment`]: a segment drawn from three control points and α (seed 000 §4);
//! * [`CompoundCurve`]: two pieces of slopes α0 and α1 joined with G3 continuity, from
//!   three control points and a turning ratio (seed 004) or from four control points
//!   (seed 002), with the logarithmic curvature graph of each piece ([`LcgLine`]);
//! * [`region`]: the drawable region of seed 000 Fig. 9, and of compound curves;
//! * [`RationalCubic`]: rational cubic Bézier curves, with a curvature-monotonicity test
//!   whose verdict is a proof ([`RationalCubic::curvature_monotonicity`], seed 001 §5);
//! * [`QuasiCurve`]: quasi-aesthetic curves (seed 001 §4) of any [`TurningCurve`] (through
//!   [`ToBezier`]), one rational cubic fitted as in
//!   the seed ([`ToBezier::to_rational_cubic`]) or G2 chains of rational or plain cubics
//!   within a [`Tolerance`] ([`ToBezier::to_rational_cubics`], [`ToBezier::to_cubics`]), as one
//!   curve ([`BezierChain`]) or a kurbo path ([`QuasiCurve::to_bez_path`]);
//! * [`curvature_plot`] and [`log_curvature_graph`]: the curvature plot and logarithmic
//!   curvature graph of any chain of Bézier pieces, with a least-squares α ([`LcgFit`]);
//! * [`Path`] and [`Spline`]: G1 or G2 paths of segments from a control polygon, and G2
//!   splines through points;
//! * [`SpaceSegment`] and [`SpaceForm`]: log-aesthetic space curves (seed 003), whose
//!   curvature and torsion graphs are both straight ([`SpaceCurve`]).
//!
//! The modules form layers, each using only those below it (docs/architecture.md):
//! foundations (errors, numerics, tolerances), the families (standard form, chord angle,
//! rational cubics), segments, curves and analysis, replacement and paths, and on top the
//! space curves and drawable regions.
//!
//! # Conventions
//!
//! * Signed curvature is positive for left turns ([`Turn`]), in the caller's coordinates,
//!   traversed from the first control point. Inside kurbo's `ParamCurveCurvature`, which every
//!   curve type implements, kurbo's sign is used instead (negative for a left turn).
//! * kurbo's traits take t ∈ [0, 1] proportional to arc length for log-aesthetic curves, and
//!   clamp it there; a NaN t gives NaN. They cannot report errors; everything else returns a
//!   [`Result`] with an [`Error`] that says what was wrong and what would fix it.
//! * **Accuracy**: a parameter named `accuracy` is an absolute distance in the caller's units
//!   (as in kurbo); a [`Tolerance`] is either [`Tolerance::Absolute`] (caller's units) or
//!   [`Tolerance::Relative`] (a fraction of the curve's arc length); reported deviations say
//!   which they are in their names (`max_deviation` in the caller's units, `rms` and `max`
//!   relative). Exact quantities (arc length, curvature, points) carry no tolerance: they are
//!   computed to within a few ulps of their condition (see docs/accuracy.md).
//! * With the `serde` feature, the types whose names a format needs (error kinds, turning
//!   directions, monotonicity verdicts, tolerances, space-curve types) serialise with stable
//!   snake_case names; the crate itself does no I/O.
//!
//! ```
//! use kurbo::Point;
//! use lac::{Curve, Segment};
//!
//! let seg = Segment::from_control_points(
//!     [Point::new(-1.0, 0.0), Point::new(-0.2, 0.8), Point::new(1.0, 0.0)],
//!     0.5,
//! )
//! .unwrap();
//! let end = seg.point_at_s(seg.arc_length()).unwrap();
//! assert!((end - Point::new(1.0, 0.0)).hypot() < 1e-12);
//! // The curve turns right (clockwise) from (-1,0) via (-0.2,0.8) to (1,0).
//! assert!(seg.signed_curvature_start() < 0.0);
//! ```

// The layers, each using only those above it in this list (docs/architecture.md; the
// test `architecture` in tests/it checks it).
mod curve;
mod family;
mod fit;
mod foundation;
mod path;
mod quasi;
pub mod region;
mod segment;
mod space;

pub use curve::analysis::{
    curvature_plot, log_curvature_graph, CurvaturePoint, LcgFit, LogCurvatureGraph,
};
pub use curve::bezier_chain::{BezierChain, BezierChainDerivative};
pub use curve::chain::{Chain, SegmentChain};
pub use curve::compound::{CompoundCurve, CompoundDerivative, MIN_PIECE_SHARE};
pub use curve::verdict::{NotMonotone, Place, PLOT_ZERO};
pub use curve::Curve;
pub use family::bezier::{RationalCubic, RationalCubicDerivative};
pub use family::lcg::LcgLine;
pub use family::monotone::{Monotonicity, MonotonicityReport};
pub use family::sample::{Sample, MAX_ADAPTIVE_SAMPLES};
pub use family::standard_form::{Classification, InfiniteRadiusEnd, StandardForm, ZeroRadiusEnd};
pub use fit::{
    Fit, FitAlpha, FitJoint, FitLoss, FitOptions, FitPiece, DEFAULT_ALPHA_RANGE, MAX_FIT_SEGMENTS,
};
pub use foundation::error::{Error, ErrorKind, G2Failure, NotDrawable, PointFailure, Result};
pub use foundation::numeric::{short_number, times_ratio};
pub use foundation::tolerance::{Tolerance, MIN_RELATIVE_TOLERANCE};
pub use foundation::turn::Turn;
pub use foundation::vec3::Vec3;
pub use path::{
    Alphas, Closure, Continuity, ControlPolygon, G2Outcome, Joint, Path, PointType, Spline,
    SplineEnd, SplineInflection, SplineKnot, SplineOptions, SplinePoint, StraightPiece,
    G2_JUMP_LIMIT, G2_TOLERANCE, INFLECTION_LIMIT, MAX_POLYGON_POINTS, MAX_TYPED_SPLINE_POINTS,
};
pub use quasi::{QuasiCurve, QuasiPiece, ToBezier, TurningCurve, MAX_PIECES};
pub use segment::visible::{HIDDEN_SHARE, HIDDEN_TURNING};
pub use segment::{Segment, SegmentDerivative, MAX_ABS_ALPHA};
pub use space::{
    BoundBy, EndBehaviour, RadiusCell, RadiusLimit, RatioLimit, SeedRow, SpaceClassification,
    SpaceEnd, TurningCell,
};
pub use space::{
    Frame, GraphPoint, Similarity3, SpaceCubic, SpaceCubics, SpaceCurve, SpaceForm,
    SpaceFormParams, SpaceSegment, SpaceShape, TorsionType, PLANAR_TOLERANCE,
};

/// The README's Rust examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;

/// The Rust examples of docs/library.md, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../../../docs/library.md")]
pub struct DocsLibraryDoctests;
