//! Chains of log-aesthetic segments joined end to end (at least G1: each piece starts where
//! the previous one ends, with its tangent): a segment is a chain of one piece, a compound
//! curve one of two joined with G3 continuity, a spline one of a piece per span (two where a
//! span inflects). Naming the pieces ([`SegmentChain`]) makes a chain a [`Curve`], written
//! once here.
//!
//! A sample at `s` inside piece `i` is placed from that piece's nearer end, so that the
//! digits of a short piece's position are not lost to the rounding of the whole length.

use kurbo::Point;

use crate::curve::analysis::CurvaturePoint;
use crate::curve::{
    check_adaptive, check_arc_length, check_ascending, checked_plot, equally_spaced, Curve,
};
use crate::family::sample::{check_count, Sample};
use crate::foundation::error::Result;
use crate::foundation::numeric::clamp;
use crate::segment::Segment;

/// A curve made of log-aesthetic [`Segment`]s joined end to end, at least G1: through its
/// pieces it is a [`Curve`], and a Bézier replacement's input
/// ([`TurningCurve`](crate::TurningCurve)) when it turns one way with monotone curvature.
pub trait SegmentChain {
    /// The log-aesthetic pieces in order from the first point (at least one).
    fn pieces(&self) -> &[Segment];
}

/// Any run of consecutive segments (each starting where the last ends, as those of a
/// compound curve or a path between straight pieces do), as a curve.
pub struct Chain<'a>(pub &'a [Segment]);

impl SegmentChain for Chain<'_> {
    fn pieces(&self) -> &[Segment] {
        self.0
    }
}

impl SegmentChain for Segment {
    fn pieces(&self) -> &[Segment] {
        std::slice::from_ref(self)
    }
}

impl<C: SegmentChain + ?Sized> Curve for C {
    fn arc_length(&self) -> f64 {
        self.pieces().iter().map(Segment::length).sum()
    }

    fn start_point(&self) -> Point {
        self.pieces()[0].first_point()
    }

    fn end_point(&self) -> Point {
        let pieces = self.pieces();
        pieces[pieces.len() - 1].last_point()
    }

    fn signed_curvature_start(&self) -> f64 {
        self.pieces()[0].end_curvatures().0
    }

    fn signed_curvature_end(&self) -> f64 {
        let pieces = self.pieces();
        pieces[pieces.len() - 1].end_curvatures().1
    }

    fn turning(&self) -> f64 {
        self.pieces()
            .iter()
            .map(|p| p.turn().sign() * p.turning_angle())
            .sum()
    }

    fn point_at_s(&self, s: f64) -> Result<Point> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.point_of(&piece.station_at_s(s)?))
    }

    fn theta_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.theta_of(&piece.station_at_s(s)?))
    }

    fn signed_curvature_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.kappa_of(&piece.station_at_s(s)?))
    }

    fn curvature_derivative_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = locate(self.pieces(), s)?;
        Ok(piece.dkappa_ds_at(piece.kappa_of(&piece.station_at_s(s)?)))
    }

    fn joint_arc_lengths(&self) -> Vec<f64> {
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

    fn samples_at_arc_lengths(&self, at: &[f64]) -> Result<Vec<Sample>> {
        Ok(by_piece(self.pieces(), at)?
            .into_iter()
            .map(|(_, s)| s)
            .collect())
    }

    fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        let len = self.arc_length();
        let at = equally_spaced(len, n);
        if let [piece] = self.pieces() {
            // What `by_piece` does for one piece, without its copies.
            let length = piece.length();
            let local: Vec<f64> = at
                .iter()
                .map(|&s| local_s(s, 0.0, length, length))
                .collect();
            let mut samples = piece.samples_at_local(&local)?;
            for sample in &mut samples {
                sample.s += 0.0; // (as by_piece adds the piece's start: no −0)
            }
            return Ok(samples);
        }
        self.samples_at_arc_lengths(&at)
    }

    fn sample_adaptive(&self, accuracy: f64) -> Result<Vec<Sample>> {
        check_adaptive(self.arc_length(), self.turning(), accuracy)?;
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

    /// With the exact dκ/ds of each piece (dρ/ds = Λρ^(1−α) in its standard form).
    fn curvature_plot(&self, n: usize) -> Result<Vec<CurvaturePoint>> {
        check_count(n)?;
        let pieces = self.pieces();
        let at = equally_spaced(self.arc_length(), n);
        let plot: Vec<CurvaturePoint> = by_piece(pieces, &at)?
            .into_iter()
            .map(|(i, s)| pieces[i].curvature_point(&s))
            .collect();
        checked_plot(plot)
    }
}

/// The piece holding arc length `s` and the arc length within it, measured from whichever
/// end of the piece is nearer (see the module documentation), within [0, piece length]. A
/// joint belongs to the piece after it, so the last point is always on the last piece.
pub(crate) fn locate(pieces: &[Segment], s: f64) -> Result<(&Segment, f64)> {
    let len: f64 = pieces.iter().map(Segment::length).sum();
    check_arc_length(s, len)?;
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
    check_ascending(at, len)?;
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
