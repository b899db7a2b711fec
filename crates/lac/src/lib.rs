//! Log-aesthetic curves.
//!
//! A log-aesthetic curve (LAC) has a straight logarithmic curvature graph:
//! `log(ρ ds/dρ) = α log ρ + c`, i.e. `dρ/ds = Λ ρ^(1−α)`. The clothoid (α = −1), Nielsen
//! spiral (α = 0), logarithmic spiral (α = 1), circle involute (α = 2) and circle (Λ = 0)
//! are members. This crate implements the planar family of Yoshida & Saito, *Interactive
//! Aesthetic Curve Segments* (2006):
//!
//! * [`StandardForm`]: ρ(s), θ(s), s(θ), ρ(θ), bounds, points, and the
//!   [`Classification`] of seed 000 Table 2;
//! * [`Segment`]: a segment drawn from three control points and α, with evaluation,
//!   sampling (by arc length, by tangent angle, adaptively) and the evolute;
//! * [`CompoundCurve`]: two pieces of slopes α0 and α1 joined with G3 continuity, from
//!   three control points and a turning ratio (seed 004) or from four control points
//!   (seed 002), with the logarithmic curvature graph of each piece ([`LcgLine`]);
//! * [`region`]: the drawable region of seed 000 Fig. 9, and of compound curves;
//! * [`RationalCubic`]: rational cubic Bézier curves, with a curvature-monotonicity test
//!   whose verdict is a proof ([`RationalCubic::curvature_monotonicity`], seed 001 §5);
//! * [`QuasiCurve`]: quasi-aesthetic curves (seed 001 §4), one rational cubic fitted as in
//!   the seed ([`Segment::to_rational_cubic`]) or G2 chains of rational or plain cubics
//!   within a tolerance ([`Segment::to_rational_cubics`], [`Segment::to_cubics`]), as one
//!   curve ([`BezierChain`]) or a kurbo path ([`QuasiCurve::to_bez_path`]);
//! * [`curvature_plot`] and [`log_curvature_graph`]: the curvature plot and logarithmic
//!   curvature graph of any chain of Bézier pieces, with a least-squares α ([`LcgFit`]).
//!
//! The crate does no I/O. Signed curvature is positive for left turns; kurbo's
//! [`ParamCurveCurvature`](kurbo::ParamCurveCurvature), where this crate implements it for
//! Bézier curves ([`RationalCubic`], [`BezierChain`]), keeps kurbo's sign, positive for right
//! turns.
//!
//! ```
//! use kurbo::Point;
//! use lac::Segment;
//!
//! let seg = Segment::from_control_points(
//!     [Point::new(-1.0, 0.0), Point::new(-0.2, 0.8), Point::new(1.0, 0.0)],
//!     0.5,
//! )
//! .unwrap();
//! let end = seg.point_at_s(seg.arc_length()).unwrap();
//! assert!((end - Point::new(1.0, 0.0)).hypot() < 1e-12);
//! // The curve turns right (clockwise) from (-1,0) via (-0.2,0.8) to (1,0).
//! assert!(seg.curvature_start() < 0.0);
//! ```

mod analysis;
mod bezier;
mod bezier_chain;
mod compound;
mod error;
mod gauss;
mod integrate;
mod kurbo_impl;
mod lcg;
mod monotone;
mod numeric;
mod quasi;
pub mod region;
mod sampling;
mod segment;
mod solve;
mod space;
mod standard_form;

pub use analysis::{
    curvature_plot, log_curvature_graph, CurvaturePoint, LcgFit, LogCurvatureGraph,
};
pub use bezier::{RationalCubic, RationalCubicDerivative};
pub use bezier_chain::{BezierChain, BezierChainDerivative};
pub use compound::CompoundCurve;
pub use error::{Error, NotDrawable, Result};
pub use kurbo_impl::SegmentDerivative;
pub use lcg::LcgLine;
pub use monotone::{Monotonicity, MonotonicityReport};
pub use quasi::{QuasiCurve, QuasiPiece};
pub use sampling::Sample;
pub use segment::Segment;
pub use space::{
    BoundBy, EndBehaviour, RadiusCell, RadiusLimit, RatioLimit, SpaceClassification, SpaceEnd,
    TurningCell,
};
pub use space::{
    Frame, GraphPoint, Similarity3, SpaceForm, SpaceSegment, TorsionType, PLANAR_TOLERANCE,
};
pub use standard_form::{Classification, InfiniteRadiusEnd, StandardForm, ZeroRadiusEnd};

/// The README's Rust examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
