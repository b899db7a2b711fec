//! The unknowns and equations of a spline with point types (docs/math.md, splines with
//! point types): its *nodes* (the given points, and a *knot* inside each span next to a
//! point whose conditions take a tangent away), the tangent at each node (given or
//! unknown), what each span is (a curve, a half S that ends at its inflection, a straight
//! line) and the condition each node adds.
//!
//! Counting. A span with both end tangents known is fixed (one segment or an S), so a
//! smooth point brings one unknown (its tangent) and one equation (G2). A tangent point
//! keeps G2 but loses its unknown; a G2 Hermite end adds its curvature to a given angle; a
//! point that ends a straight span has the line's direction and needs zero curvature. Each
//! such *constrained end* of a span is paid for by a knot in that span: a point of the span
//! with its own tangent and G2 there, moving on the perpendicular bisector of the span's
//! chord (two unknowns, one equation: one unknown to spare), or anywhere (three unknowns)
//! when both ends of the span are constrained. The spline with one segment per span is a
//! member of this family (a knot where the segment crosses the bisector), and is where the
//! solver starts.

use std::f64::consts::{PI, TAU};

use kurbo::{Point, Vec2};

use crate::foundation::error::{Error, PointFailure, Result};
use crate::foundation::numeric::length;

use super::super::point_type::{PointType, SplineOptions};

/// The wrapped angle in (−π, π].
pub(super) fn wrap(a: f64) -> f64 {
    a - TAU * ((a + PI) / TAU).floor()
}

/// The direction of a vector, radians.
pub(super) fn dir(v: Vec2) -> f64 {
    v.y.atan2(v.x)
}

/// A tangent direction: given, or the unknown of this index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Tangent {
    Given(f64),
    Free(usize),
}

/// The equation a node adds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Condition {
    /// The curvature is continuous.
    G2,
    /// The curvature on one side (`after`: the span leaving it) is `value`.
    Curvature { after: bool, value: f64 },
    /// The span on one side is a half S ending here at its inflection (zero curvature, the
    /// tangent given): its tangent at its other end (a knot) is that knot's.
    Inflection { after: bool },
}

impl Condition {
    /// The condition in words, for a refusal.
    pub(super) fn what(&self) -> &'static str {
        match self {
            Condition::G2 => "continuous curvature",
            Condition::Curvature { .. } => "the given end curvature",
            Condition::Inflection { .. } => "zero curvature where it meets the straight span",
        }
    }
}

/// A knot: the point mid + along·u + across·h of a span (`along` half its chord, `across`
/// the same turned left), u fixed at 0 unless it is an unknown.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Knot {
    pub(super) mid: Point,
    pub(super) along: Vec2,
    pub(super) across: Vec2,
    pub(super) u: Option<usize>,
    pub(super) h: usize,
}

/// Where a node is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum At {
    /// The given point of this index.
    Point(usize),
    /// A knot, in the span of this index.
    Knot(usize, Knot),
}

/// A node: where it is, its tangent arriving and leaving (the same but at corners), and
/// its condition with a length that makes the curvature equations scale-free.
#[derive(Clone, Copy, Debug)]
pub(super) struct Node {
    pub(super) at: At,
    pub(super) tangent: [Tangent; 2],
    pub(super) condition: Option<Condition>,
    pub(super) weight: f64,
}

/// What a span between two nodes is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// A segment or an S, fixed by its end tangents.
    Curve,
    /// A straight line.
    Line,
    /// A half S from its start to its inflection at its end: fixed by its end's tangent.
    HalfToEnd,
    /// A half S from its inflection at its start: fixed by its start's tangent.
    HalfFromStart,
}

/// The span from node `k` to the next: its kind and the caller's span it lies in.
#[derive(Clone, Copy, Debug)]
pub(super) struct Span {
    pub(super) kind: Kind,
    pub(super) span: usize,
}

/// The nodes, spans, unknowns and equations of one spline problem.
#[derive(Clone, Debug)]
pub(super) struct Layout {
    pub(super) nodes: Vec<Node>,
    pub(super) spans: Vec<Span>,
    pub(super) closed: bool,
    /// The node of each unknown.
    pub(super) owner: Vec<usize>,
    /// The nodes with a condition, in order: the rows of the system.
    pub(super) rows: Vec<usize>,
    /// The plan's knot share it was laid out with.
    pub(super) knot_share: f64,
    /// Whether its tangent points' knots are in the spans before them.
    pub(super) tangents_before: bool,
}

/// What the options ask at each point, checked: the plan both layouts are made from.
#[derive(Clone, Debug)]
pub(super) struct Plan {
    pub(super) types: Vec<PointType>,
    /// Whether span i is straight.
    pub(super) line: Vec<bool>,
    /// The tangent on each side of each point when it is given (or a heuristic), `None`
    /// where it is an unknown; the two sides are equal except at corners.
    pub(super) tangents: Vec<[Option<f64>; 2]>,
    /// The condition at each point in the full problem.
    pub(super) conditions: Vec<Option<Condition>>,
    /// The constrained ends of each span (its start, its end): each wants a knot there.
    pub(super) constrained: Vec<[bool; 2]>,
    /// Whether an open end's tangent is an unknown in the full problem (its curvature given,
    /// its angle not).
    pub(super) free_ends: [bool; 2],
    /// Whether its tangent points' knots are in the spans before them.
    pub(super) tangents_before: bool,
    /// Where along its chord, from its constrained end, the line across which a knot moves
    /// lies, in a span with one constrained end.
    pub(super) knot_share: f64,
}

impl Plan {
    /// The plan of `options` for `points` (validated), or the point whose options cannot be
    /// met and why.
    pub(super) fn new(
        points: &[Point],
        closed: bool,
        alpha: f64,
        options: &SplineOptions,
    ) -> Result<Plan> {
        let n = points.len();
        let spans = if closed { n } else { n - 1 };
        let types = if options.types.is_empty() {
            vec![PointType::Smooth; n]
        } else if options.types.len() == n {
            options.types.clone()
        } else {
            return Err(Error::OutOfRange {
                name: "number of point types",
                value: options.types.len() as f64,
                expected: "one type per point (or none: every point smooth)",
            });
        };
        let mut line = vec![false; spans];
        for &i in &options.lines {
            if i >= spans {
                return Err(Error::OutOfRange {
                    name: "straight span",
                    value: i as f64,
                    expected: "the index of a span: i for the span from point i to point i + 1",
                });
            }
            line[i] = true;
        }
        let misplaced = |point: usize, what: &'static str| Error::SplinePoint {
            point,
            reason: PointFailure::Misplaced { what },
        };
        for t in &types {
            let angles = match *t {
                PointType::Smooth => [None, None],
                PointType::Tangent(a) => [Some(a), None],
                PointType::Corner { before, after } => [before, after],
            };
            for a in angles.into_iter().flatten() {
                crate::foundation::error::finite("tangent angle", a)?;
            }
        }
        for end in [&options.start, &options.end] {
            if let Some(a) = end.angle {
                crate::foundation::error::finite("end angle", a)?;
            }
            if let Some(k) = end.curvature {
                crate::foundation::error::finite("end curvature", k)?;
            }
        }
        if closed && (options.start != Default::default() || options.end != Default::default()) {
            return Err(misplaced(
                0,
                "a closed spline has no ends: drop the start and end angles and curvatures",
            ));
        }
        let at = |i: isize| points[i.rem_euclid(n as isize) as usize];
        let has = |i: isize| closed || (0..n as isize).contains(&i);
        // The tangent at B of the circle through A, B, C, and at its ends.
        let circle_mid = |a: Point, b: Point, c: Point| {
            dir(b - a) + wrap(dir(c - b) - dir(b - a)) - wrap(dir(c - a) - dir(b - a))
        };
        let circle_start =
            |a: Point, b: Point, c: Point| dir(c - a) - wrap(dir(c - b) - dir(b - a));
        let circle_end = |a: Point, b: Point, c: Point| dir(c - a) + wrap(dir(c - b) - dir(b - a));
        let side_circle = |i: usize, after: bool| -> f64 {
            let i = i as isize;
            if after && has(i + 2) {
                circle_start(at(i), at(i + 1), at(i + 2))
            } else if !after && has(i - 2) {
                circle_end(at(i - 2), at(i - 1), at(i))
            } else if has(i - 1) && has(i + 1) {
                circle_mid(at(i - 1), at(i), at(i + 1))
            } else if after {
                dir(at(i + 1) - at(i))
            } else {
                dir(at(i) - at(i - 1))
            }
        };
        let span_before = |i: usize| {
            if i > 0 {
                Some(i - 1)
            } else if closed {
                Some(n - 1)
            } else {
                None
            }
        };
        let span_after = |i: usize| if i + 1 < n || closed { Some(i) } else { None };
        let line_dir = |s: usize| dir(points[(s + 1) % n] - points[s]);
        let mut tangents = vec![[None, None]; n];
        let mut conditions = vec![None; n];
        let mut constrained = vec![[false, false]; spans];
        let mut free_ends = [false, false];
        for i in 0..n {
            let (before, after) = (span_before(i), span_after(i));
            let line_before = before.filter(|&s| line[s]);
            let line_after = after.filter(|&s| line[s]);
            let corner = matches!(types[i], PointType::Corner { .. });
            let end = if closed {
                None
            } else if i == 0 {
                Some((0, &options.start))
            } else if i + 1 == n {
                Some((1, &options.end))
            } else {
                None
            };
            if corner {
                let PointType::Corner {
                    before: b,
                    after: a,
                } = types[i]
                else {
                    unreachable!()
                };
                tangents[i] = [
                    line_before
                        .map(line_dir)
                        .or(b)
                        .or(before.map(|_| side_circle(i, false))),
                    line_after
                        .map(line_dir)
                        .or(a)
                        .or(after.map(|_| side_circle(i, true))),
                ];
                if let Some((_, e)) = end {
                    if e.curvature.is_some() || e.angle.is_some() {
                        return Err(misplaced(
                            i,
                            "an open end that is a corner takes its direction from its type: \
                             drop the end's angle and curvature, or make the point smooth",
                        ));
                    }
                }
                // The side with no span of an open end.
                if before.is_none() {
                    tangents[i][0] = tangents[i][1];
                }
                if after.is_none() {
                    tangents[i][1] = tangents[i][0];
                }
                continue;
            }
            let given = match types[i] {
                PointType::Tangent(a) => Some(a),
                _ => None,
            };
            if let (Some(lb), Some(la)) = (line_before, line_after) {
                if wrap(line_dir(lb) - line_dir(la)).abs() > 1e-12 {
                    return Err(Error::SplinePoint {
                        point: i,
                        reason: PointFailure::StraightSpansNotInLine,
                    });
                }
            }
            if let Some(s) = line_before.or(line_after) {
                if given.is_some() || end.is_some_and(|(_, e)| e.angle.is_some()) {
                    return Err(Error::SplinePoint {
                        point: i,
                        reason: PointFailure::AngleOnStraightSpan,
                    });
                }
                if end.is_some_and(|(_, e)| e.curvature.is_some()) {
                    return Err(misplaced(
                        i,
                        "an end on a straight span has no curve there to give a curvature: \
                         drop the end curvature",
                    ));
                }
                let d = line_dir(s);
                tangents[i] = [Some(d), Some(d)];
                // The curve on the other side (if any) meets the line with zero curvature.
                let curve_side = match (line_before, line_after) {
                    (Some(_), None) => after.map(|s| (s, true)),
                    (None, Some(_)) => before.map(|s| (s, false)),
                    _ => None,
                };
                if let Some((s, after_side)) = curve_side {
                    if alpha >= 0.0 {
                        return Err(Error::SplinePoint {
                            point: i,
                            reason: PointFailure::ZeroCurvature { alpha },
                        });
                    }
                    conditions[i] = Some(Condition::Inflection { after: after_side });
                    constrained[s][if after_side { 0 } else { 1 }] = true;
                }
                continue;
            }
            if let Some((e, opts)) = end {
                if given.is_some() && opts.angle.is_some() {
                    return Err(misplaced(
                        i,
                        "its direction is given twice (its type and the end angle): give one",
                    ));
                }
                let angle = given.or(opts.angle);
                let heuristic = side_circle(i, e == 0);
                tangents[i] = [Some(angle.unwrap_or(heuristic)); 2];
                if let Some(k) = opts.curvature {
                    let after_side = e == 0;
                    let span = if after_side { 0 } else { spans - 1 };
                    match angle {
                        Some(_) if k == 0.0 => {
                            if alpha >= 0.0 {
                                return Err(Error::SplinePoint {
                                    point: i,
                                    reason: PointFailure::ZeroCurvature { alpha },
                                });
                            }
                            conditions[i] = Some(Condition::Inflection { after: after_side });
                            constrained[span][e] = true;
                        }
                        Some(_) => {
                            conditions[i] = Some(Condition::Curvature {
                                after: after_side,
                                value: k,
                            });
                            constrained[span][e] = true;
                        }
                        None => {
                            conditions[i] = Some(Condition::Curvature {
                                after: after_side,
                                value: k,
                            });
                            free_ends[e] = true;
                        }
                    }
                }
                continue;
            }
            conditions[i] = Some(Condition::G2);
            match given {
                Some(a) => {
                    tangents[i] = [Some(a); 2];
                    constrained[i][0] = true;
                }
                None => tangents[i] = [None, None],
            }
        }
        Ok(Plan {
            types,
            line,
            tangents,
            conditions,
            constrained,
            free_ends,
            knot_share: 0.5,
            tangents_before: false,
        })
    }

    /// The frame of span `s`'s knot: the point of the chord it moves across from (nearer the
    /// constrained end, where the curve must change most, when only one end is), half the
    /// chord, and the same turned left.
    pub(super) fn knot_frame(&self, points: &[Point], s: usize) -> (Point, Vec2, Vec2) {
        let n = points.len();
        let (a, b) = (points[s], points[(s + 1) % n]);
        let share = match self.constrained[s] {
            [true, false] => self.knot_share,
            [false, true] => 1.0 - self.knot_share,
            _ => 0.5,
        };
        let along = (b - a) * 0.5;
        (a.lerp(b, share), along, Vec2::new(-along.y, along.x))
    }

    /// The plan with each tangent point's knot in the span before it instead of the one after
    /// it, where that span is curved and its end free; `None` when no knot moves.
    pub(super) fn tangent_knots_before(&self) -> Option<Plan> {
        let n = self.types.len();
        let spans = self.line.len();
        let mut plan = self.clone();
        let mut moved = false;
        for i in 0..n {
            if !matches!(self.types[i], PointType::Tangent(_))
                || self.conditions[i] != Some(Condition::G2)
            {
                continue;
            }
            let before = if i > 0 {
                i - 1
            } else if spans == n {
                n - 1
            } else {
                continue;
            };
            if self.line[before] || plan.constrained[before][1] || !plan.constrained[i][0] {
                continue;
            }
            plan.constrained[i][0] = false;
            plan.constrained[before][1] = true;
            moved = true;
        }
        plan.tangents_before = true;
        moved.then_some(plan)
    }

    /// Where its knots are, for the layout: the share, and whether the tangent points' knots
    /// are before them.
    fn placing(&self) -> (f64, bool) {
        (self.knot_share, self.tangents_before)
    }

    /// Whether the full problem is the relaxed one (nothing asks for a knot or frees an end).
    pub(super) fn is_relaxed(&self) -> bool {
        self.constrained.iter().all(|c| !c[0] && !c[1]) && self.free_ends == [false, false]
    }
}

impl Layout {
    /// The relaxed problem: every given tangent (and every end's) fixed, G2 at the smooth
    /// points only, no knots: a smooth spline between the fixed tangents.
    pub(super) fn relaxed(points: &[Point], closed: bool, plan: &Plan) -> Layout {
        let n = points.len();
        let mut nodes = Vec::with_capacity(n);
        let mut owner = Vec::new();
        for i in 0..n {
            let tangent = match plan.tangents[i] {
                [Some(a), Some(b)] => [Tangent::Given(a), Tangent::Given(b)],
                _ => {
                    owner.push(i);
                    [Tangent::Free(owner.len() - 1); 2]
                }
            };
            let condition = match tangent[0] {
                Tangent::Free(_) => Some(Condition::G2),
                Tangent::Given(_) => None,
            };
            nodes.push(Node {
                at: At::Point(i),
                tangent,
                condition,
                weight: 0.0,
            });
        }
        let spans = (0..plan.line.len())
            .map(|s| Span {
                kind: if plan.line[s] {
                    Kind::Line
                } else {
                    Kind::Curve
                },
                span: s,
            })
            .collect();
        Layout::finished(points, nodes, spans, closed, owner, plan.placing())
    }

    /// The full problem with knots in the spans that have a constrained end; `knot_at(s)`
    /// gives the knot's starting place in span s (its u, h and tangent), which sets the
    /// values in `x` that it returns with the layout (the points' unknowns from `tangent`,
    /// the tangent each point starts from).
    pub(super) fn full(
        points: &[Point],
        closed: bool,
        plan: &Plan,
        tangent: impl Fn(usize) -> f64,
        knot_at: impl Fn(usize) -> Result<(f64, f64, f64)>,
    ) -> Result<(Layout, Vec<f64>)> {
        let n = points.len();
        let mut nodes = Vec::new();
        let mut spans = Vec::new();
        let mut owner = Vec::new();
        let mut x = Vec::new();
        let mut unknown = |node: usize, value: f64, owner: &mut Vec<usize>| {
            owner.push(node);
            x.push(value);
            owner.len() - 1
        };
        for i in 0..n {
            let free = plan.tangents[i] == [None, None]
                || (!closed
                    && ((i == 0 && plan.free_ends[0]) || (i + 1 == n && plan.free_ends[1])));
            let t = if free {
                [Tangent::Free(unknown(nodes.len(), tangent(i), &mut owner)); 2]
            } else {
                let [a, b] = plan.tangents[i];
                [
                    Tangent::Given(a.expect("given")),
                    Tangent::Given(b.expect("given")),
                ]
            };
            nodes.push(Node {
                at: At::Point(i),
                tangent: t,
                condition: plan.conditions[i],
                weight: 0.0,
            });
            if i + 1 == n && !closed {
                break;
            }
            let s = i;
            let [c0, c1] = plan.constrained[s];
            if plan.line[s] || !(c0 || c1) {
                spans.push(Span {
                    kind: if plan.line[s] {
                        Kind::Line
                    } else {
                        Kind::Curve
                    },
                    span: s,
                });
                continue;
            }
            let (mid, along, across) = plan.knot_frame(points, s);
            let knot_node = nodes.len();
            let (u0, h0, phi0) = knot_at(s)?;
            let u = (c0 && c1).then(|| unknown(knot_node, u0, &mut owner));
            let h = unknown(knot_node, h0, &mut owner);
            let phi = unknown(knot_node, phi0, &mut owner);
            let inflects = |end: usize| {
                let p = if end == 0 { s } else { (s + 1) % n };
                matches!(plan.conditions[p], Some(Condition::Inflection { .. }))
                    && plan.constrained[s][end]
            };
            for (end, half) in [(0, Kind::HalfFromStart), (1, Kind::HalfToEnd)] {
                spans.push(Span {
                    kind: if inflects(end) { half } else { Kind::Curve },
                    span: s,
                });
            }
            nodes.push(Node {
                at: At::Knot(
                    s,
                    Knot {
                        mid,
                        along,
                        across,
                        u,
                        h,
                    },
                ),
                tangent: [Tangent::Free(phi); 2],
                condition: Some(Condition::G2),
                weight: 0.0,
            });
        }
        Ok((
            Layout::finished(points, nodes, spans, closed, owner, plan.placing()),
            x,
        ))
    }

    /// The layout with each node's weight (the mean chord of its spans) and its rows.
    fn finished(
        points: &[Point],
        mut nodes: Vec<Node>,
        spans: Vec<Span>,
        closed: bool,
        owner: Vec<usize>,
        (knot_share, tangents_before): (f64, bool),
    ) -> Layout {
        let m = nodes.len();
        let place = |node: &Node| match node.at {
            At::Point(i) => points[i],
            At::Knot(_, k) => k.mid,
        };
        let chords: Vec<f64> = (0..spans.len())
            .map(|k| length(place(&nodes[(k + 1) % m]) - place(&nodes[k])))
            .collect();
        for (k, node) in nodes.iter_mut().enumerate() {
            let before = if k > 0 || closed {
                chords.get((k + m - 1) % m)
            } else {
                None
            };
            let after = chords.get(k);
            node.weight = match (before, after) {
                (Some(a), Some(b)) => 0.5 * (a + b),
                (Some(a), None) | (None, Some(a)) => *a,
                (None, None) => 1.0,
            };
        }
        let rows = (0..m).filter(|&k| nodes[k].condition.is_some()).collect();
        Layout {
            nodes,
            spans,
            closed,
            owner,
            rows,
            knot_share,
            tangents_before,
        }
    }

    /// The independent parts of the system: the part of each row and of each unknown (the
    /// root of its set), where a part is closed under "a row reads a span that reads an
    /// unknown". Corners with given tangents and straight spans cut a spline into parts,
    /// and a part whose spans do not change needs no Newton step.
    pub(super) fn parts(&self) -> (Vec<usize>, Vec<usize>) {
        let rows = self.rows.len();
        // Rows first, then unknowns, in one union–find.
        let mut parent: Vec<usize> = (0..rows + self.owner.len()).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        let mut row_of = vec![None; self.nodes.len()];
        for (r, &k) in self.rows.iter().enumerate() {
            row_of[k] = Some(r);
        }
        for (s, span) in self.spans.iter().enumerate() {
            if span.kind == Kind::Line {
                continue;
            }
            let (a, b) = (s, self.end_of(s));
            let mut reads: Vec<usize> = Vec::with_capacity(8);
            // The unknowns the span reads: its ends' places and tangents on its side.
            for (k, side) in [(a, 1), (b, 0)] {
                let node = &self.nodes[k];
                if let Tangent::Free(v) = node.tangent[side] {
                    reads.push(rows + v);
                }
                if let At::Knot(_, knot) = node.at {
                    reads.extend(knot.u.iter().chain([&knot.h]).map(|v| rows + v));
                }
            }
            // The rows that read the span: a condition on the side it lies.
            for (k, after) in [(a, true), (b, false)] {
                let reads_side = match self.nodes[k].condition {
                    Some(Condition::G2) => true,
                    Some(
                        Condition::Curvature { after: side, .. }
                        | Condition::Inflection { after: side },
                    ) => side == after,
                    None => false,
                };
                if let (true, Some(r)) = (reads_side, row_of[k]) {
                    reads.push(r);
                }
            }
            if let Some((&first, rest)) = reads.split_first() {
                for &i in rest {
                    let (p, q) = (root(&mut parent, first), root(&mut parent, i));
                    parent[q] = p;
                }
            }
        }
        let part: Vec<usize> = (0..parent.len()).map(|i| root(&mut parent, i)).collect();
        (part[..rows].to_vec(), part[rows..].to_vec())
    }

    /// Where node `k` is for unknowns `x`.
    pub(super) fn position(&self, points: &[Point], x: &[f64], k: usize) -> Point {
        match self.nodes[k].at {
            At::Point(i) => points[i],
            At::Knot(_, knot) => {
                let u = knot.u.map_or(0.0, |u| x[u]);
                knot.mid + knot.along * u + knot.across * x[knot.h]
            }
        }
    }

    /// The tangent of node `k` arriving (`after` false) or leaving, for unknowns `x`.
    pub(super) fn tangent(&self, x: &[f64], k: usize, after: bool) -> f64 {
        match self.nodes[k].tangent[usize::from(after)] {
            Tangent::Given(a) => a,
            Tangent::Free(v) => x[v],
        }
    }

    /// The span before node `k` and the one after it, where they exist.
    pub(super) fn spans_at(&self, k: usize) -> (Option<usize>, Option<usize>) {
        let m = self.nodes.len();
        let before = if k > 0 {
            Some(k - 1)
        } else if self.closed {
            Some(m - 1)
        } else {
            None
        };
        let after = (k < self.spans.len()).then_some(k);
        (before, after)
    }

    /// The node a span ends at.
    pub(super) fn end_of(&self, span: usize) -> usize {
        (span + 1) % self.nodes.len()
    }

    /// Whether the layout has knots or frees an end (the system is not one unknown per
    /// G2 point).
    pub(super) fn is_tridiagonal(&self) -> bool {
        self.rows.len() == self.owner.len()
            && self.rows.iter().zip(&self.owner).all(|(r, o)| r == o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// How many parts the full layout of `types` on eight points round a circle has, and
    /// whether every row's part holds as many unknowns as rows.
    fn parts_of(types: &[PointType], lines: &[usize]) -> (usize, bool) {
        let points: Vec<Point> = (0..8)
            .map(|k| {
                let t = TAU * k as f64 / 8.0;
                Point::new(t.cos(), 1.3 * t.sin())
            })
            .collect();
        let options = SplineOptions {
            types: types.to_vec(),
            lines: lines.to_vec(),
            ..SplineOptions::default()
        };
        let plan = Plan::new(&points, true, -1.0, &options).unwrap();
        let (layout, _) =
            Layout::full(&points, true, &plan, |_| 0.0, |_| Ok((0.0, 0.0, 0.0))).unwrap();
        let (rows, unknowns) = layout.parts();
        let mut roots: Vec<usize> = rows.clone();
        roots.sort_unstable();
        roots.dedup();
        let square = roots.iter().all(|p| {
            rows.iter().filter(|r| *r == p).count() == unknowns.iter().filter(|u| *u == p).count()
        });
        (roots.len(), square)
    }

    /// Smooth and tangent points couple the whole ring; corners (their tangents given on
    /// both sides) and straight spans cut it into square parts.
    #[test]
    fn corners_and_straight_spans_cut_a_spline_into_parts() {
        let s = PointType::Smooth;
        let c = PointType::CORNER;
        let t = PointType::Tangent(0.3);
        assert_eq!(parts_of(&[s; 8], &[]), (1, true));
        assert_eq!(parts_of(&[s, s, t, s, s, s, t, s], &[]), (1, true));
        assert_eq!(parts_of(&[c, s, s, s, c, s, s, s], &[]), (2, true));
        assert_eq!(parts_of(&[c, s, s, s, s, s, s, s], &[4]), (2, true));
        assert_eq!(parts_of(&[s; 8], &[1, 5]), (2, true));
    }
}
