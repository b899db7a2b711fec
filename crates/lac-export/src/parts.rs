//! What CAD export takes ([`ExportCurve`]): a curve as the parts it is fitted by, with the
//! name and continuity its report gives. Export knows three ways to fit a curve, not the
//! kinds of curves: a kind describes itself once, in lac-io's list of kinds, by choosing one
//! ([`ExportCurve::whole`], [`ExportCurve::pieces`], [`ExportCurve::space`]); the pieces of
//! a path and of a spline are made here ([`path_pieces`], [`spline_pieces`]), and those of a
//! chain of segments such as a fitted path ([`segment_pieces`]).
//!
//! A segment or a compound curve is one chain of segments, fitted whole (the quasi chain of
//! seed 001 keeps its G2 joint). A path and a spline are fitted piece by piece, so that
//! every joint is a knot with the curve's own continuity; a space segment by cubic Hermite
//! pieces.

use std::borrow::Cow;

use kurbo::Point;
use lac::{Curve, Path, Segment, SegmentChain, SpaceCurve, SpaceSegment, Spline};

use crate::certify::Piece;
use crate::Result;

/// A curve to export: its parts, and what the report says of it.
pub struct ExportCurve<'a> {
    /// Its name in the export's report: `"segment"`, `"path"`, ….
    pub kind: &'static str,
    /// Its arc length (a relative tolerance is a share of it).
    pub length: f64,
    /// The continuity the B-spline has at the knots between parts: `"G2"`, `"G1"` (a G1
    /// path), `"G0"` (a spline with corners) or `"C1"` (space curves).
    pub continuity: &'static str,
    /// The parts it is fitted by.
    pub parts: Parts<'a>,
}

/// How a curve is fitted.
pub enum Parts<'a> {
    /// One chain of segments, fitted whole by quasi-aesthetic cubics joined G2.
    Whole(&'a dyn SegmentChain),
    /// Planar pieces in the order of travel, each fitted on its own (within the smaller of
    /// the tolerance and its length), every boundary a knot.
    Pieces(Vec<Piece<'a>>),
    /// A space segment, by cubic Hermite pieces joined C1.
    Space(&'a SpaceSegment),
}

impl<'a> ExportCurve<'a> {
    /// A chain of segments (a segment, a compound curve) fitted whole, joined G2.
    pub fn whole(kind: &'static str, chain: &'a dyn SegmentChain) -> ExportCurve<'a> {
        ExportCurve {
            kind,
            length: chain.arc_length(),
            continuity: "G2",
            parts: Parts::Whole(chain),
        }
    }

    /// A planar curve of `length` fitted piece by piece, its knots with `continuity`.
    pub fn pieces(
        kind: &'static str,
        length: f64,
        continuity: &'static str,
        pieces: Vec<Piece<'a>>,
    ) -> ExportCurve<'a> {
        ExportCurve {
            kind,
            length,
            continuity,
            parts: Parts::Pieces(pieces),
        }
    }

    /// A space segment, joined C1.
    pub fn space(kind: &'static str, segment: &'a SpaceSegment) -> ExportCurve<'a> {
        ExportCurve {
            kind,
            length: SpaceCurve::arc_length(segment),
            continuity: "C1",
            parts: Parts::Space(segment),
        }
    }
}

/// The pieces of `path` in the order of travel: each straight piece follows the segment
/// whose end it starts from (the wrap-around one, of a closed path, comes last).
pub fn path_pieces(path: &Path) -> Vec<Piece<'_>> {
    let mut lines: Vec<(Point, Point)> = path
        .straight_pieces()
        .iter()
        .map(|l| (l.from, l.to))
        .collect();
    let mut out = Vec::new();
    for seg in path.segments() {
        out.push(Piece::Segment(Cow::Borrowed(seg)));
        let end = seg.end_point();
        let nearest = lines.iter().enumerate().min_by(|(_, a), (_, b)| {
            let (da, db) = ((a.0 - end).hypot(), (b.0 - end).hypot());
            da.total_cmp(&db)
        });
        if let Some((i, &(from, to))) = nearest {
            if (from.x - end.x).hypot(from.y - end.y) <= 1e-9 * Curve::arc_length(path) {
                out.push(Piece::Line(from, to));
                lines.remove(i);
            }
        }
    }
    out
}

/// A chain's segments in order, each a piece of its own, with a straight piece across any
/// gap between one's end and the next one's start (a fitted path's S meets across a hair
/// of at most 1e-12 of its length at its inflection).
pub fn segment_pieces(segments: &[Segment]) -> Vec<Piece<'_>> {
    let mut out = Vec::with_capacity(segments.len());
    for (k, seg) in segments.iter().enumerate() {
        if k > 0 {
            let (from, to) = (segments[k - 1].end_point(), seg.start_point());
            if from != to {
                out.push(Piece::Line(from, to));
            }
        }
        out.push(Piece::Segment(Cow::Borrowed(seg)));
    }
    out
}

/// The share of a spline half's length, next to its inflection, that the export takes as
/// straight: where |κ| is below 1e-12 of the half's other end (κ ∝ u^(1/|α|) in the arc
/// length u from the inflection, so a share 1e-12^|α|; nothing below `MIN_FLAT_SHARE`).
/// The curve there departs from its tangent by less than 1e-12 × the share² of the half's
/// length, far below any tolerance, while a quasi chain would need pieces down to 1e-48 of
/// its turning (α = −0.25) to follow its flattening.
fn flat_share(alpha: f64) -> f64 {
    let share = 1e-12f64.powf(-alpha);
    if alpha < 0.0 && share >= MIN_FLAT_SHARE {
        share
    } else {
        0.0
    }
}

/// The shortest flat stretch taken as straight (α ≥ −0.5): shorter ones, where the quasi
/// chains follow the halves to their ends, would leave a straight piece of a few 1e-9 of
/// the spline, too short for a knot span.
const MIN_FLAT_SHARE: f64 = 1e-6;

/// A spline's pieces in order for export: the halves of a span through an inflection, and
/// a piece that meets a straight span, shortened by `flat_share` of their length at their
/// flat end (solved again on their control triangles with the flat-side leg shortened by
/// as much: points so near a flat end are beyond the resolution of the tangent angle that
/// places them on the segment), with a straight piece across every gap that leaves (a
/// straight span, and the flat stretches).
pub fn spline_pieces(spline: &Spline) -> Result<Vec<Piece<'_>>> {
    let pieces = spline.pieces();
    let triangles = spline.control_triangles();
    let flat = lac::INFLECTION_LIMIT * spline.max_abs_curvature();
    // A gap longer than this is a straight span.
    let straight = 1e-9 * Curve::arc_length(spline);
    let mut out: Vec<Piece> = Vec::new();
    // An open spline that starts on a straight span.
    let start = Curve::start_point(spline);
    if (pieces[0].start_point() - start).hypot() > straight {
        out.push(Piece::Line(start, pieces[0].start_point()));
    }
    let end_of = |out: &[Piece]| match out.last() {
        Some(Piece::Segment(s)) => Some(s.end_point()),
        Some(Piece::Line(_, b)) => Some(*b),
        None => None,
    };
    for (k, seg) in pieces.iter().enumerate() {
        let cut = flat_share(seg.alpha()) * Curve::arc_length(seg);
        let (k0, k1) = (seg.signed_curvature_start(), seg.signed_curvature_end());
        let ends_flat = k1.abs() <= flat && cut > 0.0;
        let starts_flat = k0.abs() <= flat && cut > 0.0;
        let [a, p, b] = triangles[k];
        let piece = if ends_flat {
            Segment::from_control_points([a, p, b - (b - p).normalize() * cut], seg.alpha())?
        } else if starts_flat {
            Segment::from_control_points([a + (p - a).normalize() * cut, p, b], seg.alpha())?
        } else {
            seg.clone()
        };
        if let Some(from) = end_of(&out) {
            let gap = (piece.start_point() - from).hypot();
            if gap > 0.0 && (starts_flat || gap > straight) {
                out.push(Piece::Line(from, piece.start_point()));
            }
        }
        out.push(Piece::Segment(Cow::Owned(piece)));
    }
    // An open spline that ends on a straight span; a closed one whose last span is
    // straight.
    let end = Curve::end_point(spline);
    if !spline.is_closed() {
        if let Some(from) = end_of(&out) {
            if (end - from).hypot() > straight {
                out.push(Piece::Line(from, end));
            }
        }
    } else {
        if let (Some(from), Some(Piece::Segment(first))) = (end_of(&out), out.first()) {
            let to = first.start_point();
            if (to - from).hypot() > straight {
                out.push(Piece::Line(from, to));
            }
        }
    }
    Ok(out)
}
