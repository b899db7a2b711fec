//! Log-aesthetic paths from a control polygon (seed 000 §5, "G1 continuity can be easily
//! achieved by placing the three consecutive control points such that they are collinear").
//!
//! A control polygon P0 … Pn is read like a quadratic B-spline's: every interior vertex Pj
//! carries one log-aesthetic [`Segment`] whose control triangle is (Qj, Pj, Qj+1), where the
//! joints Q lie on the legs — Qj = Pj−1 + tj (Pj − Pj−1) with the *leg fraction* tj ∈ (0, 1) —
//! and the ends of an open path are P0 and Pn. Consecutive segments share a joint and its
//! tangent (the leg's direction), so the path is G1 by construction. A closed polygon has a
//! joint on every leg.
//!
//! * [`Path::from_polygon_g1`]: the joints at given fractions (the leg midpoints by default).
//! * [`Path::from_polygon_g2`]: the fractions solved so that the curvature is continuous at every joint.
//!   The curvature jump at a joint depends on its own fraction and on those of the two
//!   neighbouring joints only (each segment is fixed by the fractions of its two legs), so
//!   the system is tridiagonal (cyclic for closed paths) and Newton's method solves it in
//!   O(n) per step, from the leg midpoints or from a previous solution (warm start: after a
//!   drag only the joints near the moved vertex change much).
//!
//! Unknowns and equations. A segment's shape depends only on its turning angle (fixed by
//! the polygon) and the ratio r = a/b of its legs a = |Pj − Qj|, b = |Qj+1 − Pj|; so its end
//! curvatures are κ0 = e^{G0(ln r)}/a and κ1 = e^{G1(ln r)}/b with G0, G1 scale-free. With
//! x = ln(t/(1 − t)) on each free leg, the joint equation between the segment ending and the
//! one starting on that leg is `G1(before) − G0(after) − x = 0` (ln of the curvature ratio),
//! whose derivatives follow from dG/d ln r (exact, from the segment's own chord-angle
//! solution: its μ moves with the chord angle by 1/(dφ/dμ), and its end curvatures and
//! chord with μ) and d ln r / dx = −t (start leg), −(1 − t) (end leg).
//!
//! The segments are not solved at every step: Newton's method runs on the fractions and
//! each segment's μ together, one chord-angle evaluation per segment a step (a solve takes
//! 2–3), each segment's end curvatures corrected to first order for the chord angle it
//! still misses. It stops when the joints are continuous and every segment's chord angle is
//! its triangle's to 1e-14 rad; where that iteration does not end at a G2 path, the
//! iteration with every segment solved at every step is the fallback.
//!
//! Inflections. Where the polygon's turning changes direction (an *inflection leg*), a G2
//! path's curvature passes through zero: the segments on either side (α < 0 only) end at
//! their inflection end, and a [`StraightPiece`] runs along the leg between them. Such a
//! segment is fixed up to scale by α and its turning angle, so the ratio of its legs is
//! fixed (solved once, see `inflection.rs`); the joints on the other legs stay the
//! unknowns, and the straight piece must fit on its leg (its length is whatever the chains
//! on either side leave; a zero length is the exception). A vertex whose two legs both
//! inflect has no G2 path (its segment would need zero curvature at both ends). The
//! segments stop where |κ| is 1e-12 of their other end's (`Segment` has no station at
//! ρ = ∞), which the checks hold to [`INFLECTION_LIMIT`] of the path's curvature scale.
//!
//! Every result is checked before it is returned: position, tangent and (in G2) curvature
//! continuity at every joint ([`Joint`]), and on every straight piece its ends, the tangents
//! of its neighbours and their zero curvature ([`StraightPiece`]).

mod banded;
mod g2;
mod inflection;
mod point_type;
mod polygon;
mod run;
mod s_span;
mod spline;

use kurbo::Point;

use crate::curve::{check_arc_length, check_ascending, check_total_length, Curve};
use crate::family::sample::Sample;
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::length;
use crate::segment::Segment;

use crate::foundation::error::G2Failure;
pub use g2::{G2Outcome, G2_TOLERANCE};
pub use point_type::{PointType, SplineEnd, SplineOptions};
pub use polygon::{Alphas, Closure, ControlPolygon, MAX_POLYGON_POINTS};
pub use spline::{Spline, SplineInflection, SplineKnot, SplinePoint, MAX_TYPED_SPLINE_POINTS};

/// The largest relative curvature jump a G2 path may have at a joint,
/// |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|).
pub const G2_JUMP_LIMIT: f64 = 1e-9;

/// Largest gap between the ends of two segments at a joint, relative to the polygon's size,
/// and largest tangent jump (radians), for any path (beyond what the rounding of the
/// polygon's coordinates allows).
const G1_LIMIT: f64 = 1e-10;

/// How continuous a path is at its joints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
pub enum Continuity {
    /// Position and tangent.
    G1,
    /// Position, tangent and curvature.
    G2,
}

/// What the solver measured at one joint of a path (its own check, see [`Path`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Joint {
    /// The polygon leg the joint lies on (leg i runs from P_i to P_{i+1}).
    pub leg: usize,
    /// Arc length from the path's start (a closed path's last joint is at its full length).
    pub s: f64,
    /// The fraction of the leg from P_i, in (0, 1).
    pub fraction: f64,
    /// The joint.
    pub point: Point,
    /// Signed curvature at the end of the segment before the joint.
    pub curvature_before: f64,
    /// Signed curvature at the start of the segment after it.
    pub curvature_after: f64,
    /// Distance between the two segments' ends, caller's units.
    pub gap: f64,
    /// Angle between the two segments' tangents, radians.
    pub tangent_jump: f64,
    /// |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|) (0 when both are 0).
    pub curvature_jump: f64,
}

/// The straight piece of a path on a leg where its turning changes direction: it runs along
/// the leg from where the segment before it ends to where the segment after it starts, both
/// of them at their inflection end (curvature within [`INFLECTION_LIMIT`] of zero).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StraightPiece {
    /// The polygon leg it lies on.
    pub leg: usize,
    /// Arc length from the path's start to where it starts.
    pub s: f64,
    /// Fractions of the leg from P_leg where it starts and ends.
    pub fractions: [f64; 2],
    /// Where it starts (the end of the segment before it).
    pub from: Point,
    /// Where it ends (the start of the segment after it).
    pub to: Point,
    /// Signed curvature at the end of the segment before it.
    pub curvature_before: f64,
    /// Signed curvature at the start of the segment after it.
    pub curvature_after: f64,
    /// Distance between each neighbouring segment's end and the piece's end, caller's units.
    pub gap: f64,
    /// Largest angle between a neighbouring segment's tangent and the leg, radians.
    pub tangent_jump: f64,
}

impl StraightPiece {
    /// Its length (0 when the segments meet).
    pub fn length(&self) -> f64 {
        length(self.to - self.from)
    }
}

/// The largest |κ| at a path's inflection, relative to the largest |κ| at any segment end of
/// the path (a G2 path's straight piece has κ = 0).
pub const INFLECTION_LIMIT: f64 = 1e-9;

/// A log-aesthetic path: one [`Segment`] per interior vertex of a [`ControlPolygon`], joined
/// at points on the legs with continuous position and tangent (G1), and curvature too when
/// solved by [`Path::from_polygon_g2`]. See the module documentation for the construction.
///
/// Arc length runs from the start of the first segment (P0 when open; the joint on the last
/// leg when closed) through the segments and straight pieces in order. A path is a
/// [`Curve`] through its segments and straight pieces together (κ = 0 on the straight
/// pieces), and each of its [`Path::segments`] is one too.
///
/// ```
/// use kurbo::Point;
/// use lac::{Alphas, Closure, ControlPolygon, Curve, Path};
///
/// let polygon = ControlPolygon::from_points(&[
///     Point::new(0.0, 0.0), Point::new(2.0, 0.0), Point::new(3.0, 1.5), Point::new(3.0, 3.0),
/// ], Closure::Open)?;
/// let path = Path::from_polygon_g2(&polygon, &Alphas::One(0.5))?;
/// let joint = path.joints()[0];
/// assert!(joint.curvature_jump <= 1e-9);
/// assert!((path.end_point() - Point::new(3.0, 3.0)).hypot() < 1e-12);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Path {
    polygon: ControlPolygon,
    alphas: Vec<f64>,
    /// Fraction of every leg where the segment starting on it starts (0 and 1 on an open
    /// polygon's end legs).
    fractions: Vec<f64>,
    /// Fraction of every leg where the segment ending on it ends (differs on inflection
    /// legs).
    fractions_end: Vec<f64>,
    segments: Vec<Segment>,
    joints: Vec<Joint>,
    straight: Vec<StraightPiece>,
    continuity: Continuity,
}

impl Path {
    /// The G1 path with joints at `fractions` of the joint legs (in the order of
    /// [`ControlPolygon::joint_legs`], each in (0, 1)), or at the leg midpoints.
    ///
    /// Errors: [`Error::PathSegment`] naming the vertex whose segment cannot be drawn (and
    /// why), or a fraction out of range.
    pub fn from_polygon_g1(
        polygon: &ControlPolygon,
        alphas: &Alphas,
        fractions: Option<&[f64]>,
    ) -> Result<Path> {
        let alphas = alphas.resolve(polygon)?;
        let joints = polygon.joint_legs().len();
        let fractions = match fractions {
            Some(f) => {
                if f.len() != joints {
                    return Err(Error::OutOfRange {
                        name: "number of fractions",
                        value: f.len() as f64,
                        expected: "one fraction per joint leg (every leg of a closed polygon, \
                                   all but the first and last of an open one)",
                    });
                }
                for &t in f {
                    finite("fraction", t)?;
                    if !(t > 0.0 && t < 1.0) {
                        return Err(Error::OutOfRange {
                            name: "fraction",
                            value: t,
                            expected: "a leg fraction strictly between 0 and 1",
                        });
                    }
                }
                f.to_vec()
            }
            None => vec![0.5; joints],
        };
        let t = polygon.leg_fractions(&fractions);
        let segments = (0..polygon.segment_count())
            .map(|k| segment(polygon, &alphas, &t, &t, k))
            .collect::<Result<Vec<_>>>()?;
        Path::assemble(
            polygon.clone(),
            alphas,
            [t.clone(), t],
            segments,
            Continuity::G1,
        )
    }

    /// The G2 path: the joints placed so that the curvature is continuous at every one
    /// (relative jump ≤ [`G2_JUMP_LIMIT`]), by Newton's method on the joint fractions from the
    /// leg midpoints.
    ///
    /// Errors: [`Error::NoG2Path`] naming the joint where no continuous curvature was
    /// reached, and why; [`Error::PathSegment`] when a segment cannot be drawn at the start.
    /// [`Path::from_polygon_g2_or_nearest_g1`] offers the nearest G1 path instead.
    pub fn from_polygon_g2(polygon: &ControlPolygon, alphas: &Alphas) -> Result<Path> {
        g2::solve(polygon, &alphas.resolve(polygon)?, None)?.into_result()
    }

    /// [`Path::from_polygon_g2`] with a warm start: Newton's method starts from `near`, the
    /// [`Path::joint_fractions`] of an earlier solution for a polygon with the same number
    /// of points (e.g. before a drag), which takes fewer steps than the leg midpoints.
    pub fn from_polygon_g2_near(
        polygon: &ControlPolygon,
        alphas: &Alphas,
        near: &[f64],
    ) -> Result<Path> {
        g2::solve(polygon, &alphas.resolve(polygon)?, Some(near))?.into_result()
    }

    /// [`Path::from_polygon_g2`], or when no G2 path is found, the G1 path whose curvature
    /// jumps were the smallest the search reached (never a silent kink: the outcome says why
    /// G2 failed and the path's [`Path::continuity`] is [`Continuity::G1`]).
    pub fn from_polygon_g2_or_nearest_g1(
        polygon: &ControlPolygon,
        alphas: &Alphas,
    ) -> Result<G2Outcome> {
        g2::solve(polygon, &alphas.resolve(polygon)?, None)
    }

    /// Check every joint and build the path: positions within 1e-10 of the polygon's size,
    /// tangents within 1e-10 rad, and in G2 the curvature jump within [`G2_JUMP_LIMIT`]; a
    /// leg whose start and end fractions differ carries a straight piece, whose neighbours'
    /// curvatures must be within [`INFLECTION_LIMIT`] of zero.
    fn assemble(
        polygon: ControlPolygon,
        alphas: Vec<f64>,
        [fractions, fractions_end]: [Vec<f64>; 2],
        segments: Vec<Segment>,
        continuity: Continuity,
    ) -> Result<Path> {
        let size = polygon.size();
        let (gap_limit, tangent_limit) = joint_limits(polygon.points(), size);
        let scale = segments
            .iter()
            .map(|s| {
                let (a, b) = s.end_curvatures();
                a.abs().max(b.abs())
            })
            .fold(0.0, f64::max);
        let mut joints = Vec::new();
        let mut straight = Vec::new();
        for leg in polygon.joint_legs() {
            if fractions[leg] != fractions_end[leg] {
                let piece = straight_piece(&polygon, &segments, &fractions, &fractions_end, leg)?;
                let ok = piece.gap <= gap_limit
                    && piece.tangent_jump <= tangent_limit
                    && fractions_end[leg] <= fractions[leg];
                if !ok {
                    return Err(Error::NumericalFailure {
                        what: "the path's inflection check (a straight piece's ends or \
                               tangents do not match)",
                    });
                }
                // A segment whose end could not be brought to zero curvature (α near the
                // bottom of the range that resolves it): the inflection is unresolved there.
                let (before, after) = polygon.segments_at_leg(leg);
                for (k, i) in [
                    (piece.curvature_before, before),
                    (piece.curvature_after, after),
                ] {
                    // (A NaN curvature fails too.)
                    if k.abs() > INFLECTION_LIMIT * scale || k.is_nan() {
                        return Err(Error::NoG2Path {
                            leg,
                            reason: G2Failure::InflectionUnresolved { alpha: alphas[i] },
                        });
                    }
                }
                straight.push(piece);
                continue;
            }
            let (before, after) = polygon.segments_at_leg(leg);
            let (a, b) = (&segments[before], &segments[after]);
            let kb = a.end_curvatures().1;
            let ka = b.end_curvatures().0;
            let end_theta = a.theta_of(&a.station_at_turning(a.turning_angle())?);
            let start_theta = b.theta_of(&b.station_at_turning(0.0)?);
            let d = end_theta - start_theta;
            let tangent_jump =
                (d - std::f64::consts::TAU * (d / std::f64::consts::TAU).round()).abs();
            let big = kb.abs().max(ka.abs());
            let joint = Joint {
                leg,
                s: f64::NAN, // (set by `Path::place_joints`)
                fraction: fractions[leg],
                point: polygon.at(leg, fractions[leg]),
                curvature_before: kb,
                curvature_after: ka,
                gap: length(a.last_point() - b.first_point()),
                tangent_jump,
                curvature_jump: if big > 0.0 {
                    (kb - ka).abs() / big
                } else {
                    0.0
                },
            };
            let g1_ok = joint.gap <= gap_limit && joint.tangent_jump <= tangent_limit;
            let g2_ok = continuity == Continuity::G1 || joint.curvature_jump <= G2_JUMP_LIMIT;
            if !(g1_ok && g2_ok) {
                return Err(Error::NumericalFailure {
                    what: "the path's joint check (a joint's position, tangent or curvature \
                           does not match)",
                });
            }
            joints.push(joint);
        }
        let mut path = Path {
            polygon,
            alphas,
            fractions,
            fractions_end,
            segments,
            joints,
            straight,
            continuity,
        };
        check_total_length(&path)?;
        path.place_joints();
        Ok(path)
    }

    /// The arc length of each joint and straight piece from the path's start.
    fn place_joints(&mut self) {
        let (mut s, mut joints, mut straight) = (0.0, Vec::new(), Vec::new());
        for item in self.items() {
            match item {
                Item::Segment(k) => {
                    s += self.item_length(&item);
                    let (_, end_leg) = self.polygon.legs_of_segment(k);
                    if self.joints.iter().any(|j| j.leg == end_leg) {
                        joints.push(s);
                    }
                }
                Item::Line(p) => {
                    straight.push(s);
                    s += p.length();
                }
            }
        }
        for (joint, s) in self.joints.iter_mut().zip(joints) {
            joint.s = s;
        }
        for (piece, s) in self.straight.iter_mut().zip(straight) {
            piece.s = s;
        }
    }

    /// The control polygon.
    pub fn polygon(&self) -> &ControlPolygon {
        &self.polygon
    }

    /// α of each segment.
    pub fn alphas(&self) -> &[f64] {
        &self.alphas
    }

    /// The fraction of each joint leg at which its joint lies (the order of
    /// [`ControlPolygon::joint_legs`]; on an inflection leg, where its straight piece
    /// starts): the warm start for [`Path::from_polygon_g2_near`].
    pub fn joint_fractions(&self) -> Vec<f64> {
        self.polygon
            .joint_legs()
            .into_iter()
            .map(|leg| self.fractions_end[leg])
            .collect()
    }

    /// The straight pieces on the inflection legs of a G2 path (empty when it turns one way).
    pub fn straight_pieces(&self) -> &[StraightPiece] {
        &self.straight
    }

    /// The segments in order from the path's start.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// The fraction of every leg (an open polygon's first leg 0, its last 1: the path
    /// starts at P0 and ends at Pn).
    pub fn leg_fractions(&self) -> &[f64] {
        &self.fractions
    }

    /// The control triangle of each segment as the solver placed it: (start joint, vertex,
    /// end joint), the joints exactly shared by consecutive segments.
    pub fn control_triangles(&self) -> Vec<[Point; 3]> {
        (0..self.segments.len())
            .map(|k| {
                self.polygon
                    .control_points(&self.fractions, &self.fractions_end, k)
            })
            .collect()
    }

    /// The joints, with what the solver's check measured there.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The segments and straight pieces in order from the path's start.
    fn items(&self) -> Vec<Item<'_>> {
        let mut out = Vec::new();
        for k in 0..self.segments.len() {
            out.push(Item::Segment(k));
            let (_, el) = self.polygon.legs_of_segment(k);
            if let Some(p) = self.straight.iter().find(|p| p.leg == el) {
                out.push(Item::Line(p));
            }
        }
        out
    }

    fn item_length(&self, item: &Item) -> f64 {
        match item {
            Item::Segment(k) => self.segments[*k].arc_length(),
            Item::Line(p) => p.length(),
        }
    }

    /// The item holding arc length `s` (a joint belongs to the item after it), the tangent
    /// direction where it starts (continuous from the first point), and `s` within it
    /// (clamped to its length).
    fn locate(&self, s: f64) -> Result<(Item<'_>, f64, f64)> {
        let items = self.items();
        check_arc_length(s, self.arc_length())?;
        let (mut start, mut theta) = (0.0, self.segments[0].theta_at_s(0.0)?);
        for (i, item) in items.iter().enumerate() {
            let length = self.item_length(item);
            if s < start + length || i + 1 == items.len() {
                return Ok((*item, theta, (s - start).clamp(0.0, length)));
            }
            start += length;
            if let Item::Segment(k) = item {
                theta += self.segments[*k].turning();
            }
        }
        unreachable!("a path has at least one segment")
    }

    /// G1 or G2.
    pub fn continuity(&self) -> Continuity {
        self.continuity
    }

    /// The largest relative curvature jump over the joints (0 without joints).
    pub fn max_curvature_jump(&self) -> f64 {
        self.joints
            .iter()
            .map(|j| j.curvature_jump)
            .fold(0.0, f64::max)
    }
}

impl Curve for Path {
    /// Arc length from the first point to the last (segments and straight pieces).
    fn arc_length(&self) -> f64 {
        self.items().iter().map(|i| self.item_length(i)).sum()
    }

    fn start_point(&self) -> Point {
        self.segments[0].start_point()
    }

    /// The last segment's end, or where the straight piece after it ends (a closed path
    /// whose closing leg is an inflection leg ends on it, where its first segment starts).
    fn end_point(&self) -> Point {
        match self.items().last() {
            Some(Item::Line(p)) => p.to,
            _ => self.segments[self.segments.len() - 1].end_point(),
        }
    }

    fn signed_curvature_start(&self) -> f64 {
        self.segments[0].signed_curvature_start()
    }

    fn signed_curvature_end(&self) -> f64 {
        match self.items().last() {
            Some(Item::Line(_)) => 0.0,
            _ => self.segments[self.segments.len() - 1].signed_curvature_end(),
        }
    }

    /// The segments' turning (the straight pieces do not turn).
    fn turning(&self) -> f64 {
        self.segments.iter().map(Curve::turning).sum()
    }

    fn point_at_s(&self, s: f64) -> Result<Point> {
        match self.locate(s)? {
            (Item::Segment(k), _, local) => self.segments[k].point_at_s(local),
            (Item::Line(p), _, local) => Ok(line_point(p, local)),
        }
    }

    fn theta_at_s(&self, s: f64) -> Result<f64> {
        Ok(match self.locate(s)? {
            (Item::Segment(k), at_start, local) => {
                let seg = &self.segments[k];
                at_start + (seg.theta_at_s(local)? - seg.theta_at_s(0.0)?)
            }
            (Item::Line(_), at_start, _) => at_start,
        })
    }

    fn signed_curvature_at_s(&self, s: f64) -> Result<f64> {
        match self.locate(s)? {
            (Item::Segment(k), _, local) => self.segments[k].signed_curvature_at_s(local),
            (Item::Line(_), _, _) => Ok(0.0),
        }
    }

    fn curvature_derivative_at_s(&self, s: f64) -> Result<f64> {
        match self.locate(s)? {
            (Item::Segment(k), _, local) => self.segments[k].curvature_derivative_at_s(local),
            (Item::Line(_), _, _) => Ok(0.0),
        }
    }

    /// Where consecutive segments and straight pieces meet.
    fn joint_arc_lengths(&self) -> Vec<f64> {
        let items = self.items();
        let mut s = 0.0;
        items[..items.len() - 1]
            .iter()
            .map(|item| {
                s += self.item_length(item);
                s
            })
            .collect()
    }

    /// The samples over the whole path (straight pieces included, with κ = 0 there); θ is
    /// continuous from the first point.
    fn samples_at_arc_lengths(&self, at: &[f64]) -> Result<Vec<Sample>> {
        let items = self.items();
        let lengths: Vec<f64> = items.iter().map(|i| self.item_length(i)).collect();
        let total: f64 = lengths.iter().sum();
        check_ascending(at, total)?;
        let mut out: Vec<Sample> = Vec::with_capacity(at.len());
        let (mut item, mut start) = (0, 0.0);
        for &s in at {
            while item + 1 < items.len() && s > start + lengths[item] {
                start += lengths[item];
                item += 1;
            }
            let local = (s - start).clamp(0.0, lengths[item]);
            let mut sample = match items[item] {
                Item::Segment(k) => {
                    let seg = &self.segments[k];
                    let mut smp = seg.samples_at_arc_lengths(&[local])?[0];
                    smp.s = s;
                    smp
                }
                Item::Line(p) => {
                    let (a, b) = self.polygon.leg(p.leg);
                    Sample {
                        s,
                        point: line_point(p, local),
                        theta: (b - a).atan2(),
                        kappa: 0.0,
                    }
                }
            };
            if let Some(prev) = out.last() {
                let tau = std::f64::consts::TAU;
                sample.theta -= tau * ((sample.theta - prev.theta) / tau).round();
            }
            out.push(sample);
        }
        Ok(out)
    }
}

/// The largest gap and tangent jump (radians) a joint may show: [`G1_LIMIT`] of the
/// polygon's size, plus what the coordinates' own rounding allows. A polygon far from the
/// origin compared to its size (points 2e5 from it, a millimetre apart) places its joints
/// and tangents only to that.
pub(crate) fn joint_limits(points: &[Point], size: f64) -> (f64, f64) {
    let magnitude = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let rounding = 64.0 * f64::EPSILON * magnitude;
    (
        G1_LIMIT * size + rounding,
        G1_LIMIT + 100.0 * rounding / size,
    )
}

/// The point at arc length `local` along a straight piece.
fn line_point(p: &StraightPiece, local: f64) -> Point {
    let len = p.length();
    let u = if len > 0.0 { local / len } else { 0.0 };
    p.from.lerp(p.to, u)
}

/// A segment or a straight piece of a path.
#[derive(Clone, Copy)]
enum Item<'a> {
    Segment(usize),
    Line(&'a StraightPiece),
}

/// The straight piece on inflection leg `leg` and what it measured against its neighbours.
fn straight_piece(
    polygon: &ControlPolygon,
    segments: &[Segment],
    start: &[f64],
    end: &[f64],
    leg: usize,
) -> Result<StraightPiece> {
    let (before, after) = polygon.segments_at_leg(leg);
    let (a, b) = (&segments[before], &segments[after]);
    let (from, to) = (polygon.at(leg, end[leg]), polygon.at(leg, start[leg]));
    let (p, q) = polygon.leg(leg);
    let dir = (q - p).atan2();
    let wrap = |d: f64| {
        let tau = std::f64::consts::TAU;
        (d - tau * (d / tau).round()).abs()
    };
    let end_theta = a.theta_of(&a.station_at_turning(a.turning_angle())?);
    let start_theta = b.theta_of(&b.station_at_turning(0.0)?);
    Ok(StraightPiece {
        leg,
        s: f64::NAN, // (set by `Path::place_joints`)
        fractions: [end[leg], start[leg]],
        from,
        to,
        curvature_before: a.end_curvatures().1,
        curvature_after: b.end_curvatures().0,
        gap: length(a.last_point() - from).max(length(b.first_point() - to)),
        tangent_jump: wrap(end_theta - dir).max(wrap(start_theta - dir)),
    })
}

/// Segment `k` of the polygon for leg fractions `start` (where segments start) and `end`
/// (where they end), its failure named by its vertex.
fn segment(
    polygon: &ControlPolygon,
    alphas: &[f64],
    start: &[f64],
    end: &[f64],
    k: usize,
) -> Result<Segment> {
    let points = polygon.control_points(start, end, k);
    let v = polygon.vertex_of_segment(k);
    Segment::from_control_points(points, alphas[k]).map_err(|e| Error::PathSegment {
        vertex: v,
        source: Box::new(e),
    })
}
