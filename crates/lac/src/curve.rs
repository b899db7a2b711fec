//! What every planar log-aesthetic curve offers, written once: a chain of log-aesthetic
//! [`Segment`]s joined end to end, evaluated and sampled by arc length.
//!
//! A [`Segment`] is a chain of one piece, a [`CompoundCurve`](crate::CompoundCurve) a chain
//! of two joined with G3 continuity. Only [`Curve::pieces`] is required; everything else is
//! provided, so a new kind of curve built from segments gets all of it by naming its pieces.
//!
//! Arc length `s` runs from 0 at the first point to [`Curve::arc_length`] at the last. A
//! sample at `s` inside piece `i` is placed from that piece's nearer end, so that the digits
//! of a short piece's position are not lost to the rounding of the whole length.

use kurbo::{Point, Vec2};

use crate::analysis::CurvaturePoint;
use crate::error::{finite, Error, NotDrawable, Result};
use crate::numeric::clamp;
use crate::quasi::{self, Kind, QuasiCurve};
use crate::segment::sampling::{check_count, Sample, MAX_ADAPTIVE_SAMPLES};
use crate::segment::Segment;
use crate::tolerance::Tolerance;

/// A planar log-aesthetic curve: one or more log-aesthetic [`Segment`]s joined end to end
/// (at least G1: each piece starts where the previous one ends, with its tangent).
///
/// Signed curvature is positive where the curve turns left (docs/math.md §1); `theta` is the tangent
/// direction in radians, continuous from the first point.
///
/// The method names avoid kurbo's (`eval`, `start`, `end`, `curvature`, `arclen`), which
/// every curve type also implements with kurbo's conventions (parameter t ∈ [0, 1]
/// proportional to arc length, kurbo's curvature sign).
///
/// ```
/// use kurbo::Point;
/// use lac::{CompoundCurve, Curve, Segment};
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
/// assert_eq!(compound.joints(), vec![compound.pieces()[0].arc_length()]);
/// # Ok::<(), lac::Error>(())
/// ```
pub trait Curve {
    /// The log-aesthetic pieces in order from the first point (at least one).
    fn pieces(&self) -> &[Segment];

    /// Arc length from the first to the last point.
    fn arc_length(&self) -> f64 {
        self.pieces().iter().map(Segment::length).sum()
    }

    /// The arc lengths of the joints between consecutive pieces (empty for one piece).
    fn joints(&self) -> Vec<f64> {
        let pieces = self.pieces();
        let mut s = 0.0;
        pieces[..pieces.len().saturating_sub(1)]
            .iter()
            .map(|p| {
                s += p.length();
                s
            })
            .collect()
    }

    /// The first point.
    fn start_point(&self) -> Point {
        self.pieces()[0].first_point()
    }

    /// The last point.
    fn end_point(&self) -> Point {
        self.pieces()[self.pieces().len() - 1].last_point()
    }

    /// Signed curvature at the first point.
    fn curvature_start(&self) -> f64 {
        self.pieces()[0].end_curvatures().0
    }

    /// Signed curvature at the last point.
    fn curvature_end(&self) -> f64 {
        self.pieces()[self.pieces().len() - 1].end_curvatures().1
    }

    /// Total turning of the tangent from the first to the last point, radians, signed
    /// (positive for a left turn).
    fn turning(&self) -> f64 {
        self.pieces()
            .iter()
            .map(|p| p.turn().sign() * p.turning_angle())
            .sum()
    }

    /// Point at arc length `s`, 0 ≤ s ≤ [`Curve::arc_length`].
    fn point_at_s(&self, s: f64) -> Result<Point> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.point_of(&piece.station_at_s(s)?))
    }

    /// Unit tangent at arc length `s`, in the direction of travel.
    fn tangent_at_s(&self, s: f64) -> Result<Vec2> {
        Ok(Vec2::from_angle(self.theta_at_s(s)?))
    }

    /// Tangent direction at arc length `s` (radians, continuous from the first point).
    fn theta_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.theta_of(&piece.station_at_s(s)?))
    }

    /// Signed curvature at arc length `s` (positive for a left turn).
    fn curvature_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.kappa_of(&piece.station_at_s(s)?))
    }

    /// `n ≥ 2` samples equally spaced in arc length, the first at the first point and the
    /// last at the last.
    fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        let len = self.arc_length();
        let step = len / (n - 1) as f64;
        let at = (0..n).map(|i| if i == n - 1 { len } else { i as f64 * step });
        if let [piece] = self.pieces() {
            // What `by_piece` does for one piece, without its copies.
            let length = piece.length();
            let local: Vec<f64> = at.map(|s| local_s(s, 0.0, length, length)).collect();
            let mut samples = piece.samples_at_local(&local)?;
            for sample in &mut samples {
                sample.s += 0.0; // (as by_piece adds the piece's start: no −0)
            }
            return Ok(samples);
        }
        let at: Vec<f64> = at.collect();
        Ok(by_piece(self.pieces(), &at)?
            .into_iter()
            .map(|(_, s)| s)
            .collect())
    }

    /// Samples at the given arc lengths, which must ascend within [0, arc_length].
    fn samples_at_arc_lengths(&self, at: &[f64]) -> Result<Vec<Sample>> {
        Ok(by_piece(self.pieces(), at)?
            .into_iter()
            .map(|(_, s)| s)
            .collect())
    }

    /// Samples such that the polyline through them stays within `accuracy` (an absolute
    /// distance, caller's units) of the curve; every joint is a sample.
    ///
    /// The work is bounded: a polyline within d of a curve of length L turning by Θ needs
    /// about √(LΘ/(8d)) chords at most (∫√κ ds ≤ √(LΘ)), so an accuracy that would need
    /// more than [`MAX_ADAPTIVE_SAMPLES`](crate::MAX_ADAPTIVE_SAMPLES) samples is refused.
    fn sample_adaptive(&self, accuracy: f64) -> Result<Vec<Sample>> {
        finite("accuracy", accuracy)?;
        let needed = (self.arc_length() * self.turning().abs() / (8.0 * accuracy)).sqrt();
        if needed.is_nan() || needed > MAX_ADAPTIVE_SAMPLES as f64 {
            return Err(Error::OutOfRange {
                name: "accuracy",
                value: accuracy,
                expected: "an accuracy reachable with at most 50000 samples (about \
                           arc_length * turning / 2e10 or more)",
            });
        }
        let mut out: Vec<Sample> = Vec::new();
        let mut start = 0.0;
        for piece in self.pieces() {
            let samples = piece.adaptive_samples(accuracy)?;
            let skip = usize::from(!out.is_empty());
            out.extend(samples.into_iter().skip(skip).map(|s| Sample {
                s: s.s + start,
                ..s
            }));
            start += piece.length();
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

    /// `n ≥ 2` points of the curvature plot equally spaced in arc length, with the exact
    /// dκ/ds (dρ/ds = Λρ^(1−α) in each piece's standard form).
    fn curvature_plot(&self, n: usize) -> Result<Vec<CurvaturePoint>> {
        check_count(n)?;
        let pieces = self.pieces();
        let len = self.arc_length();
        let step = len / (n - 1) as f64;
        let at: Vec<f64> = (0..n)
            .map(|i| if i == n - 1 { len } else { i as f64 * step })
            .collect();
        let plot: Vec<CurvaturePoint> = by_piece(pieces, &at)?
            .into_iter()
            .map(|(i, s)| pieces[i].curvature_point(&s))
            .collect();
        // dκ/ds scales as 1/length²: for a curve of size 1e-155 it exceeds double range.
        if plot.iter().all(|p| p.dkappa_ds.is_finite()) {
            Ok(plot)
        } else {
            Err(Error::Unrepresentable {
                what: "dκ/ds (it scales as 1/length²)",
            })
        }
    }

    /// One rational cubic with the curve's ends, end tangents and end curvatures, closest
    /// to it in the least-squares sense of seed 001 §4 (see [`QuasiCurve`]).
    fn to_rational_cubic(&self) -> Result<QuasiCurve> {
        quasi::replace(self.pieces(), None, Kind::Seed)
    }

    /// As few rational cubics as needed for a maximum deviation within `tolerance`, each
    /// with curvature proven monotone in the curve's direction, joined G2.
    fn to_rational_cubics(&self, tolerance: Tolerance) -> Result<QuasiCurve> {
        quasi::replace(self.pieces(), Some(tolerance), Kind::Rational)
    }

    /// As few plain (polynomial) cubics as needed for a maximum deviation within
    /// `tolerance`, each with curvature proven monotone, joined G2: for consumers that only
    /// take cubics (SVG paths, fonts). Their chain is a kurbo `BezPath`
    /// ([`QuasiCurve::to_bez_path`]).
    fn to_cubics(&self, tolerance: Tolerance) -> Result<QuasiCurve> {
        quasi::replace(self.pieces(), Some(tolerance), Kind::Polynomial)
    }
}

/// The share of a curve's arc length next to each end in which it may not turn by more
/// than [`HIDDEN_TURNING`]: a feature below a trillionth of the curve's size is resolved by
/// its own coordinates (16 digits) to 4 digits or fewer, so no sample, polyline or export
/// shows it.
pub const HIDDEN_SHARE: f64 = 1e-12;

/// The largest turning (radians) allowed within [`HIDDEN_SHARE`] of an end. A cusp end
/// (α > 1, ρ → 0 with a definite tangent) turns by O(share^((α−1)/α)) there, well below it
/// for α ≥ 1.2; a hook (all the turning at a radius far below the curve's size, as when a
/// flat triangle meets α near 1) turns by tens of degrees.
pub const HIDDEN_TURNING: f64 = 1e-2;

/// A solver's check that no turning hides at an end of the chain: the turning within
/// [`HIDDEN_SHARE`] of the arc length from the first and from the last point.
pub(crate) fn check_visible_ends(pieces: &[Segment]) -> Result<()> {
    let len: f64 = pieces.iter().map(Segment::length).sum();
    let near = HIDDEN_SHARE * len;
    // Curvature is monotone along each piece, so no stretch of the chain is more curved
    // than its most curved piece end: the turning within `near` of an end is at most that
    // curvature times `near`. Far below the limit (all but extreme curvature ratios) there
    // is nothing to measure.
    let most_curved = pieces.iter().fold(0.0f64, |m, p| {
        let (k0, k1) = p.end_curvatures();
        m.max(k0.abs()).max(k1.abs())
    });
    if most_curved * near <= 0.5 * HIDDEN_TURNING {
        return Ok(());
    }
    let (first, last) = (&pieces[0], &pieces[pieces.len() - 1]);
    let at_start = {
        let s = near.min(first.length());
        (first.theta_of(&first.station_at_s(s)?) - first.theta_of(&first.station_at_s(0.0)?)).abs()
    };
    let at_end = {
        let l = last.length();
        let s = (l - near).max(0.0);
        (last.theta_of(&last.station_at_s(l)?) - last.theta_of(&last.station_at_s(s)?)).abs()
    };
    for (turning, at_first) in [(at_start, true), (at_end, false)] {
        if turning > HIDDEN_TURNING {
            let (k0, k1) = (first.end_curvatures().0, last.end_curvatures().1);
            return Err(Error::NotDrawable(NotDrawable::HiddenTurn {
                at_first,
                turning,
                curvature_ratio: if at_first { k0 / k1 } else { k1 / k0 }.abs(),
            }));
        }
    }
    Ok(())
}

/// Any run of consecutive segments (each starting where the last ends, as those of a
/// compound curve or a path between straight pieces do), as a curve.
pub struct Chain<'a>(pub &'a [Segment]);

impl Curve for Chain<'_> {
    fn pieces(&self) -> &[Segment] {
        self.0
    }
}

impl Curve for Segment {
    fn pieces(&self) -> &[Segment] {
        std::slice::from_ref(self)
    }
}

/// The piece holding arc length `s` and the arc length within it, measured from whichever
/// end of the piece is nearer (see the module documentation), within [0, piece length]. A
/// joint belongs to the piece after it, so the last point is always on the last piece.
pub(crate) fn locate(pieces: &[Segment], s: f64) -> Result<(&Segment, f64)> {
    finite("s", s)?;
    let len: f64 = pieces.iter().map(Segment::length).sum();
    let slack = 1e-12 * len;
    if !(s >= -slack && s <= len + slack) {
        return Err(Error::OutOfRange {
            name: "s",
            value: s,
            expected: "an arc length between 0 and arc_length()",
        });
    }
    let mut start = 0.0;
    for (i, piece) in pieces.iter().enumerate() {
        let length = piece.length();
        let end = start + length;
        if s < end || i + 1 == pieces.len() {
            return Ok((piece, local_s(s, start, end, length)));
        }
        start = end;
    }
    unreachable!("a curve has at least one piece")
}

/// Arc length `s` of the whole curve within the piece spanning [start, end].
fn local_s(s: f64, start: f64, end: f64, length: f64) -> f64 {
    let from_end = end - s;
    if from_end < 0.5 * length {
        clamp(length - from_end, 0.0, length)
    } else {
        clamp(s - start, 0.0, length)
    }
}

/// Samples at ascending arc lengths `at`, each with the index of its piece; a sample on a
/// joint belongs to the piece after it.
fn by_piece(pieces: &[Segment], at: &[f64]) -> Result<Vec<(usize, Sample)>> {
    let len: f64 = pieces.iter().map(Segment::length).sum();
    let slack = 1e-12 * len;
    for (k, &s) in at.iter().enumerate() {
        finite("s", s)?;
        if !(s >= -slack && s <= len + slack) || (k > 0 && s < at[k - 1]) {
            return Err(Error::OutOfRange {
                name: "s",
                value: s,
                expected: "ascending arc lengths between 0 and arc_length()",
            });
        }
    }
    let mut out = Vec::with_capacity(at.len());
    let (mut next, mut start) = (0, 0.0);
    for (i, piece) in pieces.iter().enumerate() {
        let length = piece.length();
        let end = start + length;
        let last = i + 1 == pieces.len();
        let mut local = Vec::new();
        while next < at.len() && (last || at[next] < end) {
            local.push(local_s(at[next], start, end, length));
            next += 1;
        }
        out.extend(piece.samples_at_local(&local)?.into_iter().map(|s| {
            (
                i,
                Sample {
                    s: s.s + start,
                    ..s
                },
            )
        }));
        start = end;
    }
    Ok(out)
}
