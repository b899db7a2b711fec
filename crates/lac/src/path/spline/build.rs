//! A solved spline's segments and straight spans, built and checked: every node's position,
//! tangent and condition measured on the pieces as built (not on the solver's values), and
//! every span through an inflection at zero curvature.

use kurbo::Point;

use super::super::run::Item;
use super::super::s_span::HAIR;
use super::super::{joint_limits, G2_JUMP_LIMIT, INFLECTION_LIMIT};
use super::layout::{dir, wrap, At, Condition, Kind, Layout, Plan, Tangent};
use super::solve::{point_of, segments_of, Key, Memo, Problem, Reached, Shape};
use super::{Spline, SplineInflection, SplineKnot, SplinePoint};
use crate::foundation::error::{Error, G2Failure, PointFailure, Result};
use crate::foundation::numeric::length;
use crate::segment::{Segment, SegmentSolution};

/// An S whose half turns by less than this (radians) has its inflection within a hair of
/// a point.
const TINY_HALF: f64 = 1e-3;

/// The share of a half S's length left out where it meets a straight span: its curvature
/// there is a share LINE_HAIR^(1/|α|) of its other end's, 1e-13 for α = −1 (`HAIR`, 1e-12,
/// would put it at 1e-12 of the other end's, not of the spline's largest |κ|).
const LINE_HAIR: f64 = 1e-13;

/// The hair a shape's halves stop short of its inflection.
fn hair(shape: &Shape) -> f64 {
    match shape {
        Shape::S(s) if s.is_half() => LINE_HAIR,
        _ => HAIR,
    }
}

/// Whether every span of the answer `x` can be built as segments.
pub(super) fn builds(points: &[Point], layout: &Layout, alpha: f64, x: &[f64]) -> bool {
    let p = Problem::new(points, layout, alpha);
    (0..layout.spans.len()).all(|k| built_span(&p, x, k, None).is_ok())
}

/// The segments of span `k` (none for a line), as `segments_of` builds them, a plain
/// segment that fails continued by the S family (at the edge of the drawable region, where
/// a segment's curvature reaches zero at one end), and the span's S if it has one.
/// A span's segments, their control triangles and its S, if it has one.
pub(super) type Built = (Vec<Segment>, Vec<[Point; 3]>, Option<Shape>);

fn built_span(p: &Problem, x: &[f64], k: usize, reached: Option<&Reached>) -> Result<Built> {
    let l = p.layout;
    let span = l.spans[k].span;
    let (a, b) = (
        l.position(p.points, x, k),
        l.position(p.points, x, l.end_of(k)),
    );
    let value = match reached {
        Some(r) => r.value,
        None => p.span(x, k)?,
    };
    let s_failure = |shape: &Shape| {
        let Shape::S(s) = shape else {
            unreachable!("an S")
        };
        // A half that cannot be built from its curvatures and length: its numbers leave
        // double range or its ends disagree on the points between them (the curvature
        // falls by 1e-12 and more to the hair), and when it turns by almost nothing, the
        // inflection falls within a hair of a point.
        let turning = if s.is_half() {
            s.theta[0].max(s.theta[1])
        } else {
            s.theta[0].min(s.theta[1])
        };
        Error::NoG2Spline {
            span,
            reason: if turning < TINY_HALF {
                G2Failure::InflectionAtPoint
            } else {
                G2Failure::InflectionUnresolved { alpha: p.alpha }
            },
        }
    };
    let s_triangles = |shape: &Shape| match shape {
        Shape::S(s) => s.turning_halves(a, b, hair(shape)),
        _ => Vec::new(),
    };
    match value.shape {
        Shape::Line => Ok((Vec::new(), Vec::new(), None)),
        Shape::Plain(t) => {
            // The solver's own segment where it has it (the same triangle), else solved.
            let solved = reached
                .and_then(|r| r.made.clone())
                .filter(|s| s.points() == t)
                .map_or_else(
                    || SegmentSolution::near(t, p.alpha, (p.mu_of(k), false)),
                    Ok,
                );
            match solved.and_then(|s| s.into_segment()) {
                Ok(seg) => Ok((vec![seg], vec![t], None)),
                Err(e) => {
                    let psi = dir(b - a);
                    let (ta, tb) = (
                        wrap(l.tangent(x, k, true) - psi),
                        wrap(l.tangent(x, l.end_of(k), false) - psi),
                    );
                    let s = p.unit.and_then(|u| u.s_span(ta, tb, length(b - a))).ok_or(
                        Error::SplineSpan {
                            span,
                            source: Box::new(e),
                        },
                    )?;
                    let shape = Shape::S(s);
                    let segs =
                        segments_of(&shape, a, b, p.alpha, HAIR).map_err(|_| s_failure(&shape))?;
                    Ok((segs, s_triangles(&shape), Some(shape)))
                }
            }
        }
        shape @ Shape::S(_) => {
            let segs =
                segments_of(&shape, a, b, p.alpha, hair(&shape)).map_err(|_| s_failure(&shape))?;
            Ok((segs, s_triangles(&shape), Some(shape)))
        }
    }
}

/// What a node sees on one side: the piece's end point, tangent direction and curvature.
#[derive(Clone, Copy)]
struct Side {
    point: Point,
    theta: f64,
    kappa: f64,
}

fn end_of(seg: &Segment) -> Result<Side> {
    Ok(Side {
        point: seg.last_point(),
        theta: seg.theta_of(&seg.station_at_turning(seg.turning_angle())?),
        kappa: seg.end_curvatures().1,
    })
}

fn start_of(seg: &Segment) -> Result<Side> {
    Ok(Side {
        point: seg.first_point(),
        theta: seg.theta_of(&seg.station_at_turning(0.0)?),
        kappa: seg.end_curvatures().0,
    })
}

/// Build the segments and lines of answer `x` into `s`, checking every node and inflection.
pub(super) fn build(
    s: &mut Spline,
    plan: &Plan,
    layout: &Layout,
    x: Vec<f64>,
    memo: &[Memo],
    reached: &[Reached],
    earlier: &[(Key, Built)],
) -> Result<()> {
    let points = s.points.clone();
    let alpha = s.alpha;
    let p = Problem::new(&points, layout, alpha);
    p.seed(memo);
    let m = layout.nodes.len();
    let spans = layout.spans.len();
    let (mut segments, mut triangles, mut spans_of_pieces, mut items) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    // Per layout span: its pieces' range, and its S (two halves) if any.
    let mut ranges = Vec::with_capacity(spans);
    let mut inflection_points = Vec::new();
    let mut built = Vec::with_capacity(spans);
    for k in 0..spans {
        // An earlier build's span (at the same slope) where its ends have not moved.
        let key = p.key(&x, k);
        let made = match earlier.get(k) {
            Some((was, b)) if *was == key && earlier.len() == spans => b.clone(),
            _ => built_span(&p, &x, k, reached.get(k))?,
        };
        built.push((key, made.clone()));
        let (segs, tris, shape) = made;
        let start = segments.len();
        if layout.spans[k].kind == Kind::Line {
            let (a, b) = (
                layout.position(&points, &x, k),
                layout.position(&points, &x, layout.end_of(k)),
            );
            items.push(Item::Line(a, b));
        }
        let tris = if tris.is_empty() {
            match p.span(&x, k)?.shape {
                Shape::Plain(t) => vec![t],
                _ => Vec::new(),
            }
        } else {
            tris
        };
        for (seg, tri) in segs.into_iter().zip(tris) {
            items.push(Item::Segment(segments.len()));
            segments.push(seg);
            triangles.push(tri);
            spans_of_pieces.push(layout.spans[k].span);
        }
        if let Some(Shape::S(sp)) = shape {
            if !sp.is_half() {
                let (a, b) = (
                    layout.position(&points, &x, k),
                    layout.position(&points, &x, layout.end_of(k)),
                );
                inflection_points.push((k, sp.inflection(a, b)));
            }
        }
        ranges.push(start..segments.len());
    }
    if segments.is_empty() {
        return Err(Error::SplinePoint {
            point: 0,
            reason: PointFailure::Misplaced {
                what: "every span is straight: a spline needs at least one curved span",
            },
        });
    }
    let size = points
        .iter()
        .map(|q| length(*q - points[0]))
        .fold(0.0, f64::max);
    let (gap_limit, tangent_limit) = joint_limits(&points, size);
    // The curvature scale: the largest |κ| at a node.
    let scale = ranges
        .iter()
        .filter(|r| !r.is_empty())
        .flat_map(|r| {
            [
                segments[r.start].end_curvatures().0,
                segments[r.end - 1].end_curvatures().1,
            ]
        })
        .fold(0.0f64, |m, k| m.max(k.abs()));
    // What each node sees before and after it: a piece's end, a line, or nothing.
    let line_side = |k: usize, after: bool| -> Side {
        let (a, b) = (
            layout.position(&points, &x, k),
            layout.position(&points, &x, layout.end_of(k)),
        );
        Side {
            point: if after { b } else { a },
            theta: dir(b - a),
            kappa: 0.0,
        }
    };
    // What node k sees arriving (`after` false) or leaving: a piece's end, a line, nothing.
    let side = |k: usize, after: bool| -> Result<Option<Side>> {
        let (before, next) = layout.spans_at(k);
        let Some(sp) = (if after { next } else { before }) else {
            return Ok(None);
        };
        if layout.spans[sp].kind == Kind::Line {
            return Ok(Some(line_side(sp, !after)));
        }
        let r = &ranges[sp];
        Ok(Some(if after {
            start_of(&segments[r.start])?
        } else {
            end_of(&segments[r.end - 1])?
        }))
    };
    let unmet = |k: usize, what: &'static str, miss: f64| Error::SplinePoint {
        point: point_of(layout, k),
        reason: PointFailure::Unmet { what, miss },
    };
    let (mut jumps, mut knots) = (Vec::new(), Vec::new());
    let mut reports = Vec::new();
    let mut angles = Vec::with_capacity(points.len());
    for k in 0..m {
        let node = &layout.nodes[k];
        let at = layout.position(&points, &x, k);
        let (before, after) = (side(k, false)?, side(k, true)?);
        let gap = [before, after]
            .iter()
            .flatten()
            .map(|e| length(e.point - at))
            .fold(0.0, f64::max);
        if gap.is_nan() || gap > gap_limit {
            // A span through its inflection whose curvature here is zero to rounding has its
            // inflection at this point: a half too flat to place (κ ∝ u^(−1/α) from the
            // inflection, flattest as α nears 0), which Newton's method can reach as a G2
            // join at zero curvature. Say so; any other miss is lac's own failure.
            let (sb, sa) = layout.spans_at(k);
            let flat = [(sb, before), (sa, after)].into_iter().find_map(|(sp, e)| {
                let (sp, e) = (sp?, e?);
                (matches!(built[sp].1 .2, Some(Shape::S(_)))
                    && e.kappa.abs() <= INFLECTION_LIMIT * scale)
                    .then_some(sp)
            });
            return Err(match flat {
                Some(sp) => Error::NoG2Spline {
                    span: layout.spans[sp].span,
                    reason: G2Failure::InflectionAtPoint,
                },
                None => Error::NumericalFailure {
                    what: "the spline's joint check (a point's position, tangent or curvature \
                           does not match)",
                },
            });
        }
        let corner = node.tangent[0] != node.tangent[1];
        if let (Some(b), Some(a)) = (before, after) {
            let dt = wrap(b.theta - a.theta);
            if !corner && (dt.is_nan() || dt.abs() > tangent_limit) {
                let (_, next) = layout.spans_at(k);
                return Err(Error::NoG2Spline {
                    span: layout.spans[next.unwrap_or(0)].span,
                    reason: G2Failure::TangentUnresolved { jump: dt.abs() },
                });
            }
        }
        // A given direction, as built.
        for (side, t) in [(before, node.tangent[0]), (after, node.tangent[1])] {
            if let (Some(e), Tangent::Given(g)) = (side, t) {
                let miss = wrap(e.theta - g).abs();
                if miss.is_nan() || miss > tangent_limit {
                    return Err(unmet(k, "the given tangent", miss));
                }
            }
        }
        match node.condition {
            Some(Condition::G2) => {
                let (b, a) = (before.expect("a side"), after.expect("a side"));
                let jump = (b.kappa - a.kappa).abs() / b.kappa.abs().max(a.kappa.abs());
                if !(jump <= G2_JUMP_LIMIT && jump.is_finite()) {
                    // Newton's answer met the tolerance on the curvatures it computed; the
                    // segments as built differ from them (a curvature near zero at a
                    // point, where both ends' digits are few).
                    return Err(match node.at {
                        At::Point(_) if plan.is_relaxed() => {
                            let (_, next) = layout.spans_at(k);
                            Error::NoG2Spline {
                                span: layout.spans[next.unwrap_or(0)].span,
                                reason: G2Failure::NoConvergence { jump },
                            }
                        }
                        _ => unmet(k, "continuous curvature", jump),
                    });
                }
                jumps.push(jump);
                if let At::Knot(span, _) = node.at {
                    knots.push(SplineKnot {
                        span,
                        point: at,
                        angle: a.theta,
                        curvature_jump: jump,
                    });
                }
            }
            Some(Condition::Curvature {
                after: on_after,
                value,
            }) => {
                let e = if on_after { after } else { before }.expect("a side");
                let miss = (e.kappa - value).abs() / value.abs().max(e.kappa.abs());
                if miss.is_nan() || miss > G2_JUMP_LIMIT {
                    return Err(unmet(k, "the given end curvature", miss));
                }
            }
            Some(Condition::Inflection { after: on_after }) => {
                let e = if on_after { after } else { before }.expect("a side");
                let flat = e.kappa.abs() / scale;
                if flat.is_nan() || flat > INFLECTION_LIMIT {
                    return Err(unmet(
                        k,
                        "zero curvature where it meets the straight span",
                        flat,
                    ));
                }
            }
            None => {}
        }
        if let At::Point(i) = node.at {
            let straight =
                |sp: Option<usize>| sp.is_some_and(|sp| layout.spans[sp].kind == Kind::Line);
            let (sb, sa) = layout.spans_at(k);
            reports.push(SplinePoint {
                point: at,
                kind: plan.types[i],
                straight: [straight(sb), straight(sa)],
                angles: [before.map(|e| e.theta), after.map(|e| e.theta)],
                curvatures: [before.map(|e| e.kappa), after.map(|e| e.kappa)],
                gap,
            });
            let leaving = after.is_some() || before.is_none();
            angles.push(layout.tangent(&x, k, leaving));
        }
    }
    // The two halves of every S, at its inflection.
    let mut inflections = Vec::new();
    for (k, point) in inflection_points {
        let r = &ranges[k];
        let (a, b) = (&segments[r.start], &segments[r.start + 1]);
        let (k0, k1) = (a.end_curvatures().1, b.end_curvatures().0);
        let gap = length(a.last_point() - b.first_point());
        let dt = wrap(end_of(a)?.theta - start_of(b)?.theta);
        let flat = k0.abs().max(k1.abs());
        if gap.is_nan() || gap > gap_limit {
            return Err(Error::NumericalFailure {
                what: "the spline's joint check (a point's position, tangent or curvature does \
                       not match)",
            });
        }
        if dt.is_nan() || dt.abs() > tangent_limit {
            return Err(Error::NoG2Spline {
                span: layout.spans[k].span,
                reason: G2Failure::TangentUnresolved { jump: dt.abs() },
            });
        }
        if !(flat <= INFLECTION_LIMIT * scale && k0 * k1 <= 0.0) {
            return Err(Error::NoG2Spline {
                span: layout.spans[k].span,
                reason: G2Failure::InflectionUnresolved { alpha },
            });
        }
        inflections.push(SplineInflection {
            span: layout.spans[k].span,
            point,
            curvatures: [k0, k1],
            gap,
        });
    }
    // A closed spline's joint at its first point is its last.
    if layout.closed && layout.nodes[0].condition == Some(Condition::G2) {
        jumps.rotate_left(1);
    }
    s.plain = items.iter().all(|i| matches!(i, Item::Segment(_)))
        && layout.nodes.iter().all(|n| n.tangent[0] == n.tangent[1]);
    s.angles = angles;
    s.triangles = triangles;
    s.segments = segments;
    s.spans_of_pieces = spans_of_pieces;
    s.items = items;
    s.jumps = jumps;
    s.inflections = inflections;
    s.knots = knots;
    s.reports = reports;
    s.unknowns = x;
    s.knot_share = layout.knot_share;
    s.tangents_before = layout.tangents_before;
    s.built = built;
    Ok(())
}
