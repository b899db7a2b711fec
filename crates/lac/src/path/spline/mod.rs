//! G2 splines through points (the interpolating mode, like Clothoids' G2 spline and Spiro):
//! every span between consecutive points is one log-aesthetic [`Segment`], whose control
//! triangle is the chord and the intersection of the tangent lines at its ends, or, for
//! α < 0, one log-aesthetic curve continued through its inflection (an S: two segments that
//! meet at zero curvature, see `s_span`). The unknowns are the tangent angles at the points;
//! the equations, curvature continuity at the interior points (every point of a closed
//! spline). The curvatures at the ends of span i depend on the angles at its two ends only,
//! so the Jacobian is tridiagonal (cyclic when closed) and Newton's method solves it like a
//! path's joints.
//!
//! A span is a single segment where one fits its end tangents (they leave the chord on
//! opposite sides and the triangle is drawable) and an S otherwise. For α ≥ 0 no curve
//! reaches zero curvature, so a span that would need an S is refused, named, with
//! [`G2Failure::SpanInflects`]; so is a point where the curvature would have to be zero.
//!
//! Point types ([`SplineOptions`]): a tangent point, a corner, a straight span, an end
//! curvature. Their conditions and the knots that pay for them are laid out in `layout`;
//! the solver (`solve`) first solves the *relaxed* spline (every given direction fixed, G2
//! at the smooth points: the smooth spline between them) and from it the full problem, by a
//! homotopy from the relaxed answer's residuals when Newton's method from it does not
//! converge at once; `build` makes the segments and lines and checks every condition on
//! them.

mod build;
mod layout;
mod solve;

use kurbo::Point;

use super::point_type::{PointType, SplineOptions};
use super::run::{Item, Run};
use super::{Closure, MAX_POLYGON_POINTS};
use crate::curve::chain::Chain;
use crate::curve::{check_total_length, Curve};
use crate::family::sample::Sample;
use crate::foundation::error::{finite, Error, Result};
use crate::segment::{check_alpha, Segment};

/// The most points of a spline whose point types need knots or free ends (its equations
/// are solved densely).
pub const MAX_TYPED_SPLINE_POINTS: usize = 2_000;

/// A G2 spline of log-aesthetic segments through given points, with point types (smooth,
/// tangent, corner), straight spans and end conditions ([`SplineOptions`]).
///
/// ```
/// use kurbo::Point;
/// use lac::{Closure, Curve, Spline};
///
/// let points = [
///     Point::new(0.0, 0.0), Point::new(2.0, 0.3), Point::new(3.5, 1.5), Point::new(4.0, 3.0),
/// ];
/// let spline = Spline::from_points(&points, 0.5, Closure::Open, None)?;
/// assert!(spline.max_curvature_jump() <= 1e-9);
/// assert!((spline.end_point() - points[3]).hypot() < 1e-12);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Spline {
    points: Vec<Point>,
    closed: bool,
    alpha: f64,
    options: SplineOptions,
    angles: Vec<f64>,
    /// Control triangle of every piece.
    triangles: Vec<[Point; 3]>,
    segments: Vec<Segment>,
    /// The span of every piece.
    spans_of_pieces: Vec<usize>,
    /// The segments and straight spans in order.
    items: Vec<Item>,
    /// Whether `items` are the segments alone, joined with continuous tangents.
    plain: bool,
    jumps: Vec<f64>,
    inflections: Vec<SplineInflection>,
    knots: Vec<SplineKnot>,
    reports: Vec<SplinePoint>,
    /// The solver's unknowns at the answer and where its knots' lines cross their chords
    /// (the warm start of a re-solve).
    unknowns: Vec<f64>,
    knot_share: f64,
    tangents_before: bool,
    /// The last Jacobian of the point conditions (empty: none).
    jacobian: solve::Entries,
    /// Where each span's own search ended (the warm start of a re-solve's spans).
    memo: Vec<solve::Memo>,
    /// The solver's spans at the answer (a re-solve at the same slope does not solve again
    /// those whose ends stay).
    reached: Vec<solve::Reached>,
    /// Each span's pieces as built, and what the span is a function of (a re-solve at the
    /// same slope does not build again those whose ends stay).
    built: Vec<(solve::Key, build::Built)>,
}

/// Where a span of a [`Spline`] passes through an inflection, as measured on its two
/// segments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplineInflection {
    /// The span (from point `span` to the next).
    pub span: usize,
    /// The inflection point.
    pub point: Point,
    /// Signed curvature at the end of the segment before it and the start of the one after
    /// it (within [`INFLECTION_LIMIT`](super::INFLECTION_LIMIT) of the spline's largest |κ|
    /// at a point).
    pub curvatures: [f64; 2],
    /// Distance between the two segments' ends there, caller's units.
    pub gap: f64,
}

/// A knot of a [`Spline`]: a joint inside a span, with continuous curvature, that gives the
/// solver the freedom a tangent point, a straight span or an end curvature takes away.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplineKnot {
    /// The span it lies in.
    pub span: usize,
    /// Where it is.
    pub point: Point,
    /// The tangent direction there, radians.
    pub angle: f64,
    /// The relative curvature jump measured there.
    pub curvature_jump: f64,
}

/// What a [`Spline`] measured at one of its points: everything a reader needs to check its
/// type's conditions. A side with no curve (an open end's outside) is `None`; a straight
/// span's side has its direction and zero curvature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplinePoint {
    /// The point.
    pub point: Point,
    /// Its type, as given.
    pub kind: PointType,
    /// Whether the span before it and the one after it are straight.
    pub straight: [bool; 2],
    /// The tangent direction arriving and leaving, radians, measured on the pieces.
    pub angles: [Option<f64>; 2],
    /// The signed curvature arriving and leaving, measured on the pieces.
    pub curvatures: [Option<f64>; 2],
    /// Distance from the point to the pieces' ends there, caller's units.
    pub gap: f64,
}

impl Spline {
    /// The G2 spline through `points` (at least 3; the first repeated last of a closed one
    /// is dropped) with slope `alpha`, open or closed (`closure`); an open spline's end tangent
    /// directions are `ends` (radians) or those of the circles through its first and last
    /// three points.
    ///
    /// Errors: [`Error::NoG2Spline`] naming the span (from point `span` to the next) that
    /// must inflect ([`G2Failure::SpanInflects`](crate::G2Failure::SpanInflects)) or where
    /// the curvature could not be made continuous, or [`Error::SplineSpan`] naming the span
    /// whose segment cannot be drawn; bad input.
    pub fn from_points(
        points: &[Point],
        alpha: f64,
        closure: Closure,
        ends: Option<[f64; 2]>,
    ) -> Result<Spline> {
        Spline::from_points_with(points, alpha, closure, &SplineOptions::with_ends(ends))
    }

    /// The spline through `points` with point types, straight spans and end conditions
    /// (`options`; see [`SplineOptions`] and docs/math.md for the conditions and how they are
    /// solved).
    ///
    /// Errors: those of [`Spline::from_points`], and [`Error::SplinePoint`] naming the point
    /// whose conditions cannot be met and what to change (a straight span or a zero end
    /// curvature for α ≥ 0, two straight spans not in line at a point that is not a corner,
    /// an angle at a straight span's end, a condition the solver could not meet).
    pub fn from_points_with(
        points: &[Point],
        alpha: f64,
        closure: Closure,
        options: &SplineOptions,
    ) -> Result<Spline> {
        Spline::checked(points, alpha, closure, options)?.solved(None, &[])
    }

    /// [`Spline::from_points_with`] warm-started from `near`, an earlier spline with the
    /// same number of points, types and straight spans (e.g. before a point was dragged):
    /// Newton's method starts from its answer and its last Jacobian, which takes a few
    /// residuals instead of a solve from the circles. At the same slope it also takes the
    /// earlier spans whose ends have not moved (with their pieces), and solves only the parts
    /// of the spline the change touches (corners with given tangents and straight spans
    /// separate them). The answer is the cold solve's (to the solver's tolerance, 1e-12).
    /// Falls back to the cold solve when that does not converge.
    pub fn from_points_near(
        points: &[Point],
        alpha: f64,
        closure: Closure,
        options: &SplineOptions,
        near: &Spline,
    ) -> Result<Spline> {
        let s = Spline::checked(points, alpha, closure, options)?;
        let same = near.points.len() == s.points.len()
            && near.closed == s.closed
            && near.options.types.len() == options.types.len()
            && near
                .options
                .types
                .iter()
                .zip(&options.types)
                .all(|(a, b)| a.name() == b.name())
            && near.options.lines == options.lines
            && near.options.start.curvature.is_some() == options.start.curvature.is_some()
            && near.options.end.curvature.is_some() == options.end.curvature.is_some();
        let built = if same && near.alpha == alpha {
            &near.built[..]
        } else {
            &[]
        };
        s.solved(
            same.then_some(solve::Warm {
                unknowns: &near.unknowns,
                share: near.knot_share,
                before: near.tangents_before,
                jacobian: &near.jacobian,
                memo: &near.memo,
                points: &near.points,
                reached: if near.alpha == alpha {
                    &near.reached
                } else {
                    &[]
                },
            }),
            built,
        )
    }

    /// The validated input solved (from `warm`, an earlier answer's unknowns, if given),
    /// built and checked.
    fn solved(
        mut self,
        warm: Option<solve::Warm<'_>>,
        earlier: &[(solve::Key, build::Built)],
    ) -> Result<Spline> {
        let plan = layout::Plan::new(&self.points, self.closed, self.alpha, &self.options)?;
        // A smooth spline's answer built on the way (where the solver tries one at α
        // directly), kept when it is the answer.
        let mut built: Option<(Vec<f64>, Spline)> = None;
        let mut accept = |l: &layout::Layout, x: &[f64]| {
            let mut trial = self.clone();
            let ok = build::build(&mut trial, &plan, l, x.to_vec(), &[], &[], &[]).is_ok();
            if ok {
                built = Some((x.to_vec(), trial));
            }
            ok
        };
        let (layout, x, jacobian, memo, reached) = solve::solve(
            &self.points,
            self.closed,
            self.alpha,
            &plan,
            warm,
            &mut accept,
        )?;
        match built {
            Some((bx, trial)) if bx == x => self = trial,
            _ => build::build(&mut self, &plan, &layout, x, &memo, &reached, earlier)?,
        }
        self.jacobian = jacobian.unwrap_or_default();
        self.memo = memo;
        self.reached = reached;
        check_total_length(&self)?;
        Ok(self)
    }

    /// The validated input, not yet solved.
    fn checked(
        points: &[Point],
        alpha: f64,
        closure: Closure,
        options: &SplineOptions,
    ) -> Result<Spline> {
        check_alpha("alpha", alpha)?;
        let closed = closure == Closure::Closed;
        let mut points = points.to_vec();
        if closed && points.len() > 3 && points.first() == points.last() {
            points.pop();
        }
        let n = points.len();
        if !(3..=MAX_POLYGON_POINTS).contains(&n) {
            return Err(Error::OutOfRange {
                name: "number of points",
                value: n as f64,
                expected: "at least 3 points and at most 100000",
            });
        }
        if !options.is_smooth() && n > MAX_TYPED_SPLINE_POINTS {
            return Err(Error::OutOfRange {
                name: "number of points",
                value: n as f64,
                expected: "at most 2000 points for a spline with point types, straight spans \
                           or end curvatures",
            });
        }
        for p in &points {
            finite("point x", p.x)?;
            finite("point y", p.y)?;
        }
        let spans = if closed { n } else { n - 1 };
        for i in 0..spans {
            let j = (i + 1) % n;
            if points[i] == points[j] {
                return Err(Error::CoincidentPoints {
                    first: i,
                    second: j,
                });
            }
            let d = points[j] - points[i];
            if !d.x.hypot(d.y).is_finite() {
                return Err(Error::OutOfRange {
                    name: "points",
                    value: f64::INFINITY,
                    expected: "coordinates whose differences do not overflow",
                });
            }
        }
        if let (Some(a), Some(b)) = (options.start.angle, options.end.angle) {
            finite("start angle", a)?;
            finite("end angle", b)?;
        }
        Ok(Spline {
            points,
            closed,
            alpha,
            options: options.clone(),
            angles: Vec::new(),
            triangles: Vec::new(),
            segments: Vec::new(),
            spans_of_pieces: Vec::new(),
            items: Vec::new(),
            plain: true,
            jumps: Vec::new(),
            inflections: Vec::new(),
            knots: Vec::new(),
            reports: Vec::new(),
            unknowns: Vec::new(),
            knot_share: 0.5,
            tangents_before: false,
            jacobian: Vec::new(),
            memo: Vec::new(),
            reached: Vec::new(),
            built: Vec::new(),
        })
    }

    /// The points it passes through.
    pub fn points(&self) -> &[Point] {
        &self.points
    }

    /// Whether it is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// Its slope α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The point types, straight spans and end conditions it was solved with.
    pub fn options(&self) -> &SplineOptions {
        &self.options
    }

    /// The tangent direction at each point, radians (at a corner, the direction in which
    /// the curve leaves it; at an open spline's last point, the one it arrives in).
    pub fn angles(&self) -> &[f64] {
        &self.angles
    }

    /// The segments in order (one per span, two for a span through an inflection, and one
    /// more on each side of a knot; none on a straight span).
    pub fn pieces(&self) -> &[Segment] {
        &self.segments
    }

    /// The control triangle of each piece as solved: (its first point, the intersection of
    /// its end tangents, its last point), the points exactly as given. A span through an
    /// inflection has two pieces, each ending a hair (1e-12 of its length) short of the
    /// inflection point; so does a piece that meets a straight span.
    pub fn control_triangles(&self) -> &[[Point; 3]] {
        &self.triangles
    }

    /// The span of each piece (span i runs from point i to the next): one piece per span,
    /// two for a span through an inflection or with a knot.
    pub fn spans_of_pieces(&self) -> &[usize] {
        &self.spans_of_pieces
    }

    /// The straight spans as lines in order: (span, from, to), from where the curve before
    /// it ends to where the curve after it starts.
    pub fn straight_spans(&self) -> Vec<(usize, Point, Point)> {
        let n = self.points.len();
        self.items
            .iter()
            .filter_map(|item| match *item {
                Item::Line(a, b) => {
                    let span = (0..self.points.len())
                        .find(|&i| {
                            self.options.lines.contains(&i) && {
                                let (p, q) = (self.points[i], self.points[(i + 1) % n]);
                                (p - a).hypot() + (q - b).hypot() <= 1e-9 * (q - p).hypot()
                            }
                        })
                        .unwrap_or(usize::MAX);
                    Some((span, a, b))
                }
                Item::Segment(_) => None,
            })
            .collect()
    }

    /// The inflections, one per span that passes through one (only for α < 0), in order.
    pub fn inflections(&self) -> &[SplineInflection] {
        &self.inflections
    }

    /// The knots, in order.
    pub fn knots(&self) -> &[SplineKnot] {
        &self.knots
    }

    /// What was measured at each point.
    pub fn point_reports(&self) -> &[SplinePoint] {
        &self.reports
    }

    /// The relative curvature jump measured at each joint with continuous curvature (the
    /// smooth and tangent points and the knots, in order; every point of a smooth closed
    /// spline, the last at the first point).
    pub fn curvature_jumps(&self) -> &[f64] {
        &self.jumps
    }

    /// The largest relative curvature jump over the joints.
    pub fn max_curvature_jump(&self) -> f64 {
        self.jumps.iter().fold(0.0, |m, j| m.max(*j))
    }

    /// The largest |κ| at the ends of its pieces.
    pub fn max_abs_curvature(&self) -> f64 {
        self.segments
            .iter()
            .map(|s| {
                let (a, b) = s.end_curvatures();
                a.abs().max(b.abs())
            })
            .fold(0.0, f64::max)
    }

    /// The curve it is: its segments as a [`Chain`] when they are all of it, joined with
    /// continuous tangents (the old behaviour, bit for bit), else the [`Run`] of its
    /// segments and straight spans.
    fn curve(&self) -> Box<dyn Curve + '_> {
        if self.plain {
            Box::new(Chain(&self.segments))
        } else {
            Box::new(Run {
                segments: &self.segments,
                items: &self.items,
            })
        }
    }
}

/// The curve: the segments joined end to end (through [`Chain`]) when it has no straight
/// span and no corner, else segments and lines in order (θ breaking at corners).
impl Curve for Spline {
    fn arc_length(&self) -> f64 {
        self.curve().arc_length()
    }

    fn start_point(&self) -> Point {
        self.curve().start_point()
    }

    fn end_point(&self) -> Point {
        self.curve().end_point()
    }

    fn signed_curvature_start(&self) -> f64 {
        self.curve().signed_curvature_start()
    }

    fn signed_curvature_end(&self) -> f64 {
        self.curve().signed_curvature_end()
    }

    fn turning(&self) -> f64 {
        self.curve().turning()
    }

    fn point_at_s(&self, s: f64) -> Result<Point> {
        self.curve().point_at_s(s)
    }

    fn theta_at_s(&self, s: f64) -> Result<f64> {
        self.curve().theta_at_s(s)
    }

    fn signed_curvature_at_s(&self, s: f64) -> Result<f64> {
        self.curve().signed_curvature_at_s(s)
    }

    fn curvature_derivative_at_s(&self, s: f64) -> Result<f64> {
        self.curve().curvature_derivative_at_s(s)
    }

    fn joint_arc_lengths(&self) -> Vec<f64> {
        self.curve().joint_arc_lengths()
    }

    fn samples_at_arc_lengths(&self, at: &[f64]) -> Result<Vec<Sample>> {
        self.curve().samples_at_arc_lengths(at)
    }

    fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Sample>> {
        self.curve().sample_by_arc_length(n)
    }

    fn sample_adaptive(&self, accuracy: f64) -> Result<Vec<Sample>> {
        self.curve().sample_adaptive(accuracy)
    }
}
