//! Seeded random glyph-like outlines for splines with point types: closed, 8–20 points
//! around a wobbly oval (counter-clockwise), about a quarter of them corners or the ends of
//! straight spans, the topmost and bottommost points, where smooth, horizontal (tangent points).
//! Shared by the benchmark `spline` and the test module `spline_types` (the Python
//! comparison with libspiro, `tools/spiro/compare.py`, draws the same outlines).

use kurbo::Point;
use lac::{PointType, SplineOptions};

use super::Rng;

/// One outline: its points and point types.
pub(crate) struct Glyph {
    pub(crate) points: Vec<Point>,
    pub(crate) options: SplineOptions,
}

/// The outline drawn from `rng`.
pub(crate) fn glyph(rng: &mut Rng) -> Glyph {
    use std::f64::consts::{PI, TAU};
    let n = 8 + (13.0 * rng.next()) as usize;
    let (p2, p3) = (TAU * rng.next(), TAU * rng.next());
    let (w2, w3) = (0.08 * rng.next(), 0.05 * rng.next());
    let points: Vec<Point> = (0..n)
        .map(|k| {
            let t = TAU * (k as f64 + 0.35 * (rng.next() - 0.5)) / n as f64;
            let r = 1.0 + w2 * (2.0 * t + p2).sin() + w3 * (3.0 * t + p3).sin();
            Point::new(r * t.cos(), 1.4 * r * t.sin())
        })
        .collect();
    let mut types = vec![PointType::Smooth; n];
    let mut taken = vec![false; n];
    let mut lines = Vec::new();
    for k in 0..n {
        let r = rng.next();
        if taken[k] {
            continue;
        }
        if r < 0.1 {
            types[k] = PointType::CORNER;
            taken[k] = true;
        } else if r < 0.18 && !taken[(k + 1) % n] {
            lines.push(k);
            taken[k] = true;
            taken[(k + 1) % n] = true;
        }
    }
    // The extrema, where they are smooth points.
    let by_y = |a: &usize, b: &usize| points[*a].y.total_cmp(&points[*b].y);
    for (extreme, angle) in [((0..n).max_by(by_y), PI), ((0..n).min_by(by_y), 0.0)] {
        if let Some(k) = extreme.filter(|k| !taken[*k]) {
            types[k] = PointType::Tangent(angle);
        }
    }
    Glyph {
        points,
        options: SplineOptions {
            types,
            lines,
            ..SplineOptions::default()
        },
    }
}
