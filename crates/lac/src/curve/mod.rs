//! Layer 3, curves and analysis: what a planar curve can do, and what is built on it.
//!
//! [`Curve`] asks a curve for what it alone knows (its arc length and ends; its point, tangent
//! direction, signed curvature and dκ/ds at an arc length) and provides the rest on top:
//! sampling (equally in arc length, at given arc lengths, adaptively to a chordal accuracy),
//! the evolute, the curvature plot and the logarithmic curvature graph. Every planar curve
//! implements it: a [`Segment`](crate::Segment), a [`CompoundCurve`](crate::CompoundCurve), a
//! [`Path`](crate::Path), a [`Spline`](crate::Spline) and a [`BezierChain`](crate::BezierChain).
//!
//! A curve made of log-aesthetic segments joined end to end says so by naming its pieces
//! ([`SegmentChain`], in `chain.rs`), and is a [`Curve`] through them, sampled piece by
//! piece with each sample placed from its piece's nearer end.
//!
//! * `chain.rs`: chains of segments;
//! * `compound.rs`: the compound-rhythm curve of two segments;
//! * `bezier_chain.rs`: rational cubic pieces as one curve;
//! * `analysis.rs`: the curvature plot of Bézier pieces and the logarithmic curvature graph;
//! * `verdict.rs`: whether a curvature plot or a chain of Bézier pieces is monotone, and why
//!   not.

pub(crate) mod analysis;
pub(crate) mod bezier_chain;
pub(crate) mod chain;
pub(crate) mod compound;
pub(crate) mod verdict;

use kurbo::{Point, Vec2};

use crate::curve::analysis::{log_curvature_graph, CurvaturePoint, LogCurvatureGraph};
use crate::family::sample::{check_count, Sample, MAX_ADAPTIVE_SAMPLES};
use crate::foundation::error::{finite, Error, Result};

/// A planar curve, by arc length: what it can do.
///
/// Arc length `s` runs from 0 at the first point to [`Curve::arc_length`] at the last.
/// Signed curvature is positive where the curve turns left (counter-clockwise, docs/math.md
/// §1): the opposite of kurbo's `ParamCurveCurvature::curvature`, which every curve type
/// also implements with kurbo's conventions (a parameter t ∈ [0, 1]). `theta` is the tangent
/// direction in radians, continuous from the first point.
///
/// The required methods are what a curve alone knows; the provided ones (sampling, the
/// evolute, the curvature plot and the logarithmic curvature graph) are built on them, and
/// a curve may provide faster or more exact ones of its own, as the chains of segments do.
///
/// ```
/// use kurbo::Point;
/// use lac::{CompoundCurve, Curve, SegmentChain, Segment};
///
/// let segment = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.6, 0.9)], -1.0)?;
/// let compound = CompoundCurve::from_three_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.6, 0.9)], -1.0, 2.0, 0.5)?;
/// // Both are curves: the same questions, the same answers' shapes.
/// for curve in [&segment as &dyn Curve, &compound] {
///     let samples = curve.sample_by_arc_length(9)?;
///     assert!((samples[8].point - Point::new(1.6, 0.9)).hypot() < 1e-12);
///     assert!((curve.end_point() - Point::new(1.6, 0.9)).hypot() < 1e-12);
/// }
/// assert_eq!(compound.joint_arc_lengths(), vec![compound.pieces()[0].arc_length()]);
/// # Ok::<(), lac::Error>(())
/// ```
pub trait Curve {
    /// Arc length from the first to the last point.
    fn arc_length(&self) -> f64;

    /// The first point.
    fn start_point(&self) -> Point;

    /// The last point.
    fn end_point(&self) -> Point;

    /// Signed curvature at the first point (positive for a left turn).
    fn signed_curvature_start(&self) -> f64;

    /// Signed curvature at the last point (positive for a left turn).
    fn signed_curvature_end(&self) -> f64;

    /// Total turning of the tangent from the first to the last point, radians, signed
    /// (positive for a left turn).
    fn turning(&self) -> f64;

    /// Point at arc length `s`, 0 ≤ s ≤ [`Curve::arc_length`].
    fn point_at_s(&self, s: f64) -> Result<Point>;

    /// Tangent direction at arc length `s` (radians, continuous from the first point).
    fn theta_at_s(&self, s: f64) -> Result<f64>;

    /// Signed curvature at arc length `s` (positive for a left turn).
    fn signed_curvature_at_s(&self, s: f64) -> Result<f64>;

    /// dκ/ds of the signed curvature at arc length `s`.
    fn curvature_derivative_at_s(&self, s: f64) -> Result<f64>;

    /// The arc lengths at which consecutive pieces meet, ascending (empty for a curve of one
    /// piece): where the curvature may jump or its formula changes.
    fn joint_arc_lengths(&self) -> Vec<f64> {
        Vec::new()
    }

    /// Unit tangent at arc length `s`, in the direction of travel.
    fn tangent_at_s(&self, s: f64) -> Result<Vec2> {
        Ok(Vec2::from_angle(self.theta_at_s(s)?))
    }

    /// Samples at the given arc lengths, which must ascend within [0, arc_length].
    fn samples_at_arc_lengths(&self, at: &[f64]) -> Result<Vec<Sample>> {
        check_ascending(at, self.arc_length())?;
        at.iter()
            .map(|&s| {
                Ok(Sample {
                    s,
                    point: self.point_at_s(s)?,
                    theta: self.theta_at_s(s)?,
                    kappa: self.signed_curvature_at_s(s)?,
                })
            })
            .collect()
    }

    /// `n ≥ 2` samples equally spaced in arc length, the first at the first point and the
    /// last at the last.
    fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        self.samples_at_arc_lengths(&equally_spaced(self.arc_length(), n))
    }

    /// Samples such that the polyline through them stays within `accuracy` (an absolute
    /// distance, caller's units) of the curve; every joint is a sample.
    ///
    /// The work is bounded: a polyline within d of a curve of length L turning by Θ needs
    /// about √(LΘ/(8d)) chords at most (∫√κ ds ≤ √(LΘ)), so an accuracy that would need
    /// more than [`MAX_ADAPTIVE_SAMPLES`](crate::MAX_ADAPTIVE_SAMPLES) samples is refused.
    ///
    /// Provided: each span between joints is halved until the sagitta bound h²·κ/8, with κ
    /// the largest |κ| at its ends and middle, is within `accuracy` (a bound wherever the
    /// curvature is monotone between joints, as in every curve of this crate).
    fn sample_adaptive(&self, accuracy: f64) -> Result<Vec<Sample>> {
        check_adaptive(self.arc_length(), self.turning(), accuracy)?;
        let len = self.arc_length();
        let mut ends = vec![0.0];
        ends.extend(self.joint_arc_lengths());
        ends.push(len);
        let mut out = self.samples_at_arc_lengths(&[0.0])?;
        for span in ends.windows(2) {
            let right = self.samples_at_arc_lengths(&[span[1]])?[0];
            let mut stack = vec![right];
            while let Some(&end) = stack.last() {
                let start = out[out.len() - 1];
                let h = end.s - start.s;
                let middle = self.samples_at_arc_lengths(&[start.s + 0.5 * h])?[0];
                let kappa = start
                    .kappa
                    .abs()
                    .max(end.kappa.abs())
                    .max(middle.kappa.abs());
                let sagitta = h * h * kappa / 8.0;
                if sagitta > accuracy && h > 1e-14 * len {
                    if out.len() + stack.len() >= 2 * MAX_ADAPTIVE_SAMPLES {
                        return Err(Error::OutOfRange {
                            name: "accuracy",
                            value: accuracy,
                            expected: "an accuracy reachable with at most 50000 samples",
                        });
                    }
                    stack.push(middle);
                } else {
                    stack.pop();
                    out.push(end);
                }
            }
        }
        Ok(out)
    }

    /// `n ≥ 2` points of the evolute (the locus of centres of curvature) at the arc-length
    /// samples: `P + N/κ` with N the left normal.
    fn evolute(&self, n: usize) -> Result<Vec<Point>> {
        let centers: Vec<Point> = self
            .sample_by_arc_length(n)?
            .iter()
            .map(Sample::center_of_curvature)
            .collect();
        // A curve near the end of double range can have its centres beyond it.
        if centers.iter().all(|c| c.is_finite()) {
            Ok(centers)
        } else {
            Err(Error::Unrepresentable {
                what: "the evolute (a centre of curvature beyond double range)",
            })
        }
    }

    /// `n ≥ 2` points of the curvature plot equally spaced in arc length, with the curve's
    /// own dκ/ds ([`Curve::curvature_derivative_at_s`]).
    fn curvature_plot(&self, n: usize) -> Result<Vec<CurvaturePoint>> {
        let plot = self
            .sample_by_arc_length(n)?
            .into_iter()
            .map(|s| {
                Ok(CurvaturePoint {
                    s: s.s,
                    point: s.point,
                    kappa: s.kappa,
                    dkappa_ds: self.curvature_derivative_at_s(s.s)?,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        checked_plot(plot)
    }

    /// The logarithmic curvature graph of the curvature plot at `n ≥ 2` points, with its
    /// fitted line (see [`log_curvature_graph`](crate::log_curvature_graph)).
    fn log_curvature_graph(&self, n: usize) -> Result<LogCurvatureGraph> {
        Ok(log_curvature_graph(&self.curvature_plot(n)?))
    }
}

/// `n ≥ 2` arc lengths equally spaced over [0, `length`], the last exactly `length`.
pub(crate) fn equally_spaced(length: f64, n: usize) -> Vec<f64> {
    let step = length / (n - 1) as f64;
    (0..n)
        .map(|i| if i == n - 1 { length } else { i as f64 * step })
        .collect()
}

/// An error unless every arc length of `at` is finite, within [0, `length`] (to 1e-12 of
/// it) and no smaller than the one before.
pub(crate) fn check_ascending(at: &[f64], length: f64) -> Result<()> {
    let slack = 1e-12 * length;
    for (k, &s) in at.iter().enumerate() {
        finite("s", s)?;
        if !(s >= -slack && s <= length + slack) || (k > 0 && s < at[k - 1]) {
            return Err(Error::OutOfRange {
                name: "s",
                value: s,
                expected: "ascending arc lengths between 0 and arc_length()",
            });
        }
    }
    Ok(())
}

/// An error unless `s` is finite and within [0, `length`] (to 1e-12 of it).
pub(crate) fn check_arc_length(s: f64, length: f64) -> Result<()> {
    finite("s", s)?;
    let slack = 1e-12 * length;
    if s >= -slack && s <= length + slack {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            name: "s",
            value: s,
            expected: "an arc length between 0 and arc_length()",
        })
    }
}

/// The adaptive sampling's refusals: an accuracy that is not a number, or one that would
/// need more than [`MAX_ADAPTIVE_SAMPLES`] samples for a curve of this length and turning.
pub(crate) fn check_adaptive(length: f64, turning: f64, accuracy: f64) -> Result<()> {
    finite("accuracy", accuracy)?;
    let needed = (length * turning.abs() / (8.0 * accuracy)).sqrt();
    if needed.is_nan() || needed > MAX_ADAPTIVE_SAMPLES as f64 {
        return Err(Error::OutOfRange {
            name: "accuracy",
            value: accuracy,
            expected: "an accuracy reachable with at most 50000 samples (about \
                       arc_length * turning / 2e10 or more)",
        });
    }
    Ok(())
}

/// A constructor's last look at a curve of several pieces: each piece's length is finite
/// (the segments check their own), their sum may not be, for points near 1e308.
pub(crate) fn check_total_length(curve: &(impl Curve + ?Sized)) -> Result<()> {
    if curve.arc_length().is_finite() {
        Ok(())
    } else {
        Err(Error::Unrepresentable { what: "arc length" })
    }
}

/// The plot, or an error when a dκ/ds is beyond double range (it scales as 1/length²: for a
/// curve of size 1e-155 it overflows).
pub(crate) fn checked_plot(plot: Vec<CurvaturePoint>) -> Result<Vec<CurvaturePoint>> {
    if plot.iter().all(|p| p.dkappa_ds.is_finite()) {
        Ok(plot)
    } else {
        Err(Error::Unrepresentable {
            what: "dκ/ds (it scales as 1/length²)",
        })
    }
}
