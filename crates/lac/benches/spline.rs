//! Benchmarks for splines with point types (issue 32): a 20-point glyph-like outline
//! (closed, corners, straight spans, horizontal extrema; `common/glyphs.rs`) re-solved after
//! one point is moved, warm from the previous solution (target ≤ 100 µs) and from scratch.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::Vec2;
use lac::{Closure, Spline};
use std::hint::black_box;

mod common;
use common::glyphs::{glyph, Glyph};
use common::{median_per_call, Rng};

/// Seeded 20-point outlines with a spline for `alpha`, each with a copy whose one point
/// moved by up to 0.01 (of a size about 2) that has one too, and the first one's spline.
fn set(alpha: f64) -> Vec<(Glyph, Vec<kurbo::Point>, Spline)> {
    let mut rng = Rng(0x0059_114E ^ alpha.to_bits());
    let mut out = Vec::new();
    while out.len() < 24 {
        let g = glyph(&mut rng);
        if g.points.len() != 20 {
            continue;
        }
        let Ok(first) = Spline::from_points_with(&g.points, alpha, Closure::Closed, &g.options)
        else {
            continue;
        };
        let mut moved = g.points.clone();
        let k = (rng.next() * 20.0) as usize;
        moved[k] += Vec2::new(0.02 * rng.next() - 0.01, 0.02 * rng.next() - 0.01);
        if Spline::from_points_with(&moved, alpha, Closure::Closed, &g.options).is_ok() {
            out.push((g, moved, first));
        }
    }
    out
}

fn bench_spline(c: &mut Criterion) {
    for (name, warm) in [
        ("spline_types_20_points_warm", true),
        ("spline_types_20_points_cold", false),
    ] {
        let mut group = c.benchmark_group(name);
        for alpha in [-1.0, -0.5] {
            let set = set(alpha);
            group.bench_with_input(BenchmarkId::from_parameter(alpha), &set, |b, set| {
                b.iter_custom(|iters| {
                    median_per_call(iters, set, |(g, moved, first)| {
                        black_box(if warm {
                            Spline::from_points_near(
                                moved,
                                alpha,
                                Closure::Closed,
                                &g.options,
                                first,
                            )
                            .unwrap()
                        } else {
                            Spline::from_points_with(moved, alpha, Closure::Closed, &g.options)
                                .unwrap()
                        });
                    })
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_spline);
criterion_main!(benches);
