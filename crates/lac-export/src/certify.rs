//! The achieved deviation of an exported curve, measured densely and independently of how
//! it was fitted: a sampled two-sided (Hausdorff) distance between the B-spline as written
//! and the exact curve.
//!
//! * B-spline → curve: on `per_span` + 1 equal parameter steps of every span, the point's
//!   distance to the exact curve, by Newton's method on g(s) = (X(s) − q) · X′(s) from the
//!   arc length the knots give (the knots are cumulative arc lengths).
//! * Curve → B-spline: at as many points equally spaced in arc length, the distance to the
//!   span whose knot interval holds that arc length (and to its neighbours when the foot
//!   lands on a join), by Newton's method on the span's parameter.
//!
//! Every iterate's distance is the distance to a point of the other curve, so the smallest
//! one seen bounds the true distance from above even where Newton does not settle: the
//! result never understates the sampled deviation.

use super::nurbs::{Jet, Nurbs};
use kurbo::Point;
use std::borrow::Cow;

use lac::{times_ratio, Curve, Result, Segment, SpaceCurve, SpaceSegment};

/// Newton iterations per projection.
const ITERATIONS: usize = 8;

/// An exact curve evaluated by arc length: point, unit tangent and curvature vector.
pub trait Exact {
    /// Arc length.
    fn length(&self) -> f64;
    /// Jets (point, X′, X″ with respect to arc length) at `s`, in any order, each within
    /// [0, length].
    fn jets(&self, s: &[f64]) -> Result<Vec<Jet>>;
}

/// A planar log-aesthetic curve (z = 0).
pub struct PlaneExact<'a, C: Curve + ?Sized>(pub &'a C);

impl<C: Curve + ?Sized> Exact for PlaneExact<'_, C> {
    fn length(&self) -> f64 {
        self.0.arc_length()
    }

    fn jets(&self, s: &[f64]) -> Result<Vec<Jet>> {
        // One evaluation per station, in ascending order as the sampler asks.
        let len = self.length();
        let (order, sorted) = ascending(s, len);
        let samples = self.0.samples_at_arc_lengths(&sorted)?;
        let mut out = vec![ZERO_JET; s.len()];
        for (q, &i) in samples.iter().zip(&order) {
            let (sin, cos) = q.theta.sin_cos();
            let k = q.kappa;
            out[i] = Jet {
                point: [q.point.x, q.point.y, 0.0],
                d1: [cos, sin, 0.0],
                d2: [-k * sin, k * cos, 0.0],
            };
        }
        Ok(out)
    }
}

const ZERO_JET: Jet = Jet {
    point: [0.0; 3],
    d1: [0.0; 3],
    d2: [0.0; 3],
};

/// The permutation that sorts `s`, and the sorted values clamped to [0, len].
fn ascending(s: &[f64], len: f64) -> (Vec<usize>, Vec<f64>) {
    let mut order: Vec<usize> = (0..s.len()).collect();
    order.sort_by(|&a, &b| s[a].total_cmp(&s[b]));
    let sorted = order.iter().map(|&i| s[i].clamp(0.0, len)).collect();
    (order, sorted)
}

/// One piece of a planar curve fitted piece by piece, in the order of travel: a segment
/// (borrowed, or made for the export, as a spline's shortened half), or a straight piece
/// from one point to another.
#[derive(Clone, Debug)]
pub enum Piece<'a> {
    /// A log-aesthetic segment.
    Segment(Cow<'a, Segment>),
    /// A straight piece.
    Line(Point, Point),
}

impl Piece<'_> {
    /// Its arc length.
    pub fn length(&self) -> f64 {
        match self {
            Piece::Segment(seg) => seg.arc_length(),
            Piece::Line(a, b) => (b.x - a.x).hypot(b.y - a.y),
        }
    }
}

/// A curve of pieces (a path's segments and straight pieces, a spline's pieces) in the order
/// of travel.
pub struct PiecesExact<'a, 'b>(pub &'a [Piece<'b>]);

impl Exact for PiecesExact<'_, '_> {
    fn length(&self) -> f64 {
        self.0.iter().map(Piece::length).sum()
    }

    fn jets(&self, s: &[f64]) -> Result<Vec<Jet>> {
        let (order, sorted) = ascending(s, self.length());
        let mut out = vec![ZERO_JET; s.len()];
        let (mut start, mut next) = (0.0, 0);
        for (k, item) in self.0.iter().enumerate() {
            let end = start + item.length();
            let last = k + 1 == self.0.len();
            // The stations of this piece: up to its end (all the rest for the last piece).
            let mut here = Vec::new();
            while next < sorted.len() && (last || sorted[next] <= end) {
                here.push(next);
                next += 1;
            }
            let local: Vec<f64> = here
                .iter()
                .map(|&j| (sorted[j] - start).clamp(0.0, item.length()))
                .collect();
            match item {
                Piece::Segment(seg) if !local.is_empty() => {
                    for (q, &j) in seg.samples_at_arc_lengths(&local)?.iter().zip(&here) {
                        let (sin, cos) = q.theta.sin_cos();
                        out[order[j]] = Jet {
                            point: [q.point.x, q.point.y, 0.0],
                            d1: [cos, sin, 0.0],
                            d2: [-q.kappa * sin, q.kappa * cos, 0.0],
                        };
                    }
                }
                Piece::Line(a, b) => {
                    let len = item.length();
                    let (ux, uy) = ((b.x - a.x) / len, (b.y - a.y) / len);
                    for (&t, &j) in local.iter().zip(&here) {
                        out[order[j]] = Jet {
                            point: [a.x + t * ux, a.y + t * uy, 0.0],
                            d1: [ux, uy, 0.0],
                            d2: [0.0; 3],
                        };
                    }
                }
                Piece::Segment(_) => {}
            }
            start = end;
        }
        Ok(out)
    }
}

/// A space segment.
pub struct SpaceExact<'a>(pub &'a SpaceSegment);

impl Exact for SpaceExact<'_> {
    fn length(&self) -> f64 {
        self.0.arc_length()
    }

    fn jets(&self, s: &[f64]) -> Result<Vec<Jet>> {
        // The integrator's dense output is cheapest in ascending order.
        let (order, sorted) = ascending(s, self.length());
        let frames = self.0.frames(&sorted)?;
        let mut out = vec![ZERO_JET; s.len()];
        for (f, &i) in frames.iter().zip(&order) {
            out[i] = Jet {
                point: f.point.to_array(),
                d1: f.tangent.to_array(),
                d2: (f.normal * f.curvature).to_array(),
            };
        }
        Ok(out)
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// |a|: the square root of the sum of squares where that sum is a normal number, and
/// otherwise the same scaled by the largest component (the differences of coordinates near
/// 1e308 square far beyond double range, those near 1e-308 below it).
pub(crate) fn norm(a: [f64; 3]) -> f64 {
    let squared = dot(a, a);
    if (f64::MIN_POSITIVE..f64::INFINITY).contains(&squared) {
        return squared.sqrt();
    }
    let big = a[0].abs().max(a[1].abs()).max(a[2].abs());
    if big == 0.0 || !big.is_finite() {
        return big;
    }
    let unit = [a[0] / big, a[1] / big, a[2] / big];
    big * dot(unit, unit).sqrt()
}

/// The Newton step for the foot of the perpendicular from `q` at a curve point with `jet`.
fn newton_step(jet: &Jet, q: [f64; 3]) -> f64 {
    let r = sub(jet.point, q);
    let terms = |r: [f64; 3], d1: [f64; 3], d2: [f64; 3]| {
        (dot(r, d1), dot(d1, d1), dot(d1, d1) + dot(r, d2))
    };
    let (mut g, mut speed, mut dg) = terms(r, jet.d1, jet.d2);
    if ![g, speed, dg].iter().all(|x| x.is_finite()) {
        // The step is the same for r, x′ and x″ scaled alike: a curve near 1e308, whose
        // squares leave double range, is measured at unit scale (a power of two, exactly).
        let big = jet.d1.iter().chain(&r).fold(0.0f64, |m, x| m.max(x.abs()));
        if big.is_finite() && big > 0.0 {
            let scale = 2f64.powi(-(big.log2().floor() as i32));
            let scaled = |v: [f64; 3]| v.map(|x| x * scale);
            (g, speed, dg) = terms(scaled(r), scaled(jet.d1), scaled(jet.d2));
        }
    }
    if dg > 0.0 {
        -g / dg
    } else {
        // Not convex here: a gradient step of the squared distance instead.
        -g / speed.max(f64::MIN_POSITIVE)
    }
}

/// The share of the polyline's length reached at each of its points (0 … 1).
fn chord_shares(points: &[[f64; 3]]) -> Vec<f64> {
    let mut out = Vec::with_capacity(points.len());
    let mut total = 0.0;
    out.push(0.0);
    for w in points.windows(2) {
        total += norm(sub(w[1], w[0]));
        out.push(total);
    }
    if total > 0.0 && total.is_finite() {
        out.iter_mut().for_each(|x| *x /= total);
    } else {
        let last = (points.len() - 1).max(1) as f64;
        out.iter_mut()
            .enumerate()
            .for_each(|(j, x)| *x = j as f64 / last);
    }
    out
}

/// Parameter steps per span of the table that starts the curve → B-spline projections.
const SHARE_STEPS: usize = 1024;

/// The span parameter where the share `f` of its length is reached, interpolated in the
/// table of `chord_shares` at equal parameter steps.
fn parameter_at_share(shares: &[f64], f: f64) -> f64 {
    let steps = (shares.len() - 1) as f64;
    let j = shares
        .partition_point(|&x| x < f)
        .clamp(1, shares.len() - 1);
    let (lo, hi) = (shares[j - 1], shares[j]);
    let within = if hi > lo { (f - lo) / (hi - lo) } else { 0.0 };
    ((j - 1) as f64 + within.clamp(0.0, 1.0)) / steps
}

/// The sampled two-sided deviation between `nurbs` and `exact` (caller's units), with
/// `per_span` steps per span in each direction.
pub fn deviation(exact: &dyn Exact, nurbs: &Nurbs, per_span: usize) -> Result<f64> {
    let n = nurbs.span_count();
    let len = exact.length();
    let per_span = per_span.max(2);
    // B-spline → curve.
    let mut queries = Vec::with_capacity(n * (per_span + 1));
    let mut s = Vec::with_capacity(queries.capacity());
    let (t0, t1) = (nurbs.knots[0], nurbs.knots[nurbs.knots.len() - 1]);
    // Each span's points at equal steps of its parameter, and the share of its chord
    // length reached at each: the starting arc lengths (a span with a weight far from 1,
    // as next to an inflection, moves along the curve very unevenly in its parameter).
    let mut shares = Vec::with_capacity(n);
    for i in 0..n {
        let span = nurbs.span(i);
        let (a, b) = nurbs.span_interval(i);
        let first = queries.len();
        for j in 0..=per_span {
            queries.push(span.jet(j as f64 / per_span as f64).point);
        }
        let share = chord_shares(&queries[first..]);
        for f in &share {
            let t = a + (b - a) * f;
            s.push(((t - t0) / (t1 - t0) * len).clamp(0.0, len));
        }
        // For the other direction, a finer table where a span's speed varies by orders of
        // magnitude (one coarse step holding over 8 steps' fair share of its length).
        let uneven = share
            .windows(2)
            .any(|w| w[1] - w[0] > 8.0 / per_span as f64);
        if uneven {
            let fine: Vec<[f64; 3]> = (0..=SHARE_STEPS)
                .map(|j| span.jet(j as f64 / SHARE_STEPS as f64).point)
                .collect();
            shares.push(chord_shares(&fine));
        } else {
            shares.push(share);
        }
    }
    let mut best = vec![f64::INFINITY; queries.len()];
    // Only the stations whose Newton step has not settled are evaluated again.
    let mut active: Vec<usize> = (0..queries.len()).collect();
    for _ in 0..ITERATIONS {
        let at: Vec<f64> = active.iter().map(|&k| s[k]).collect();
        let jets = exact.jets(&at)?;
        let mut still = Vec::with_capacity(active.len());
        for (&k, jet) in active.iter().zip(&jets) {
            best[k] = best[k].min(norm(sub(jet.point, queries[k])));
            let step = newton_step(jet, queries[k]);
            let next = (s[k] + step).clamp(0.0, len);
            if (next - s[k]).abs() > 1e-15 * len {
                still.push(k);
            }
            s[k] = next;
        }
        if still.is_empty() {
            break;
        }
        active = still;
    }
    let mut max = best.iter().fold(0.0f64, |m, &d| m.max(d));
    // Curve → B-spline.
    let count = n * per_span + 1;
    let at: Vec<f64> = (0..count)
        .map(|k| times_ratio(len, k as f64, (count - 1) as f64))
        .collect();
    let points = exact.jets(&at)?;
    for (k, jet) in points.iter().enumerate() {
        let q = jet.point;
        let t = t0 + times_ratio(t1 - t0, at[k], len);
        let mut i = (0..n)
            .find(|&i| t <= nurbs.span_interval(i).1)
            .unwrap_or(n - 1);
        let mut d = f64::INFINITY;
        // At most one move to a neighbouring span each way.
        for _ in 0..3 {
            let span = nurbs.span(i);
            let (a, b) = nurbs.span_interval(i);
            let mut u = parameter_at_share(&shares[i], ((t - a) / (b - a)).clamp(0.0, 1.0));
            for _ in 0..ITERATIONS {
                let j = span.jet(u);
                d = d.min(norm(sub(j.point, q)));
                let next = (u + newton_step(&j, q)).clamp(0.0, 1.0);
                let settled = (next - u).abs() <= 1e-15;
                u = next;
                if settled {
                    break;
                }
            }
            let j = span.jet(u);
            d = d.min(norm(sub(j.point, q)));
            if u == 0.0 && i > 0 {
                i -= 1;
            } else if u == 1.0 && i + 1 < n {
                i += 1;
            } else {
                break;
            }
        }
        max = max.max(d);
    }
    Ok(max)
}
