//! Benchmarks for the promises of the quasi-aesthetic issue: a single rational cubic fit
//! ≤ 50 µs and the curvature-monotonicity test ≤ 5 µs (medians over fixed seeded sets), plus
//! the tolerance-driven chains for reference.
//!
//! The fit set is seed 001's setting: turning 90°, legs 1 and r with r uniform in
//! [0.5, 1], in either order, for α ∈ {−1, 0, 1, 2}; the segments are solved beforehand.
//! The monotonicity test runs on those fits (monotone, the usual case) and on random
//! rational cubics (points in [−1, 1]², weights in [0.1, 10]; often not monotone).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::Point;
use lac::ToBezier;
use lac::Tolerance;
use lac::{RationalCubic, Segment};
use std::hint::black_box;

mod common;
use common::{median_per_call, Rng};

fn segments(alpha: f64) -> Vec<Segment> {
    let mut rng = Rng(0x0A5E_1A11 ^ alpha.to_bits());
    let mut out = Vec::new();
    while out.len() < 128 {
        let r = 0.5 + 0.5 * rng.next();
        let (a, b) = if rng.next() < 0.5 { (1.0, r) } else { (r, 1.0) };
        let p = [Point::new(-a, 0.0), Point::ZERO, Point::new(0.0, b)];
        if let Ok(s) = Segment::from_control_points(p, alpha) {
            if s.to_rational_cubic().is_ok() {
                out.push(s);
            }
        }
    }
    out
}

fn random_cubics() -> Vec<RationalCubic> {
    let mut rng = Rng(0xB3_21E2);
    (0..256)
        .map(|_| {
            let p = [0; 4].map(|_| Point::new(2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0));
            let w = [0; 4].map(|_| 10f64.powf(2.0 * rng.next() - 1.0));
            RationalCubic::new(p, w).unwrap()
        })
        .collect()
}

fn bench_medians(c: &mut Criterion) {
    let mut group = c.benchmark_group("quasi_median");
    for alpha in [-1.0, 0.0, 1.0, 2.0] {
        let set = segments(alpha);
        group.bench_with_input(BenchmarkId::new("fit", alpha), &set, |b, set| {
            b.iter_custom(|iters| {
                median_per_call(iters, set, |s| {
                    black_box(black_box(s).to_rational_cubic().unwrap());
                })
            })
        });
        let fits: Vec<RationalCubic> = set
            .iter()
            .map(|s| s.to_rational_cubic().unwrap().pieces[0].curve)
            .collect();
        group.bench_with_input(BenchmarkId::new("monotone_fit", alpha), &fits, |b, set| {
            b.iter_custom(|iters| {
                median_per_call(iters, set, |q| {
                    black_box(black_box(q).curvature_monotonicity().unwrap());
                })
            })
        });
    }
    let random = random_cubics();
    group.bench_with_input(
        BenchmarkId::new("monotone_random", ""),
        &random,
        |b, set| {
            b.iter_custom(|iters| {
                median_per_call(iters, set, |q| {
                    black_box(black_box(q).curvature_monotonicity().unwrap());
                })
            })
        },
    );
    group.finish();
}

fn bench_chains(c: &mut Criterion) {
    let mut group = c.benchmark_group("quasi_chain");
    group.sample_size(20);
    let s = Segment::from_control_points(
        [Point::new(-1.0, 0.0), Point::ZERO, Point::new(0.0, 0.7)],
        0.0,
    )
    .unwrap();
    for tol in [1e-6, 1e-9] {
        group.bench_with_input(BenchmarkId::new("rational", tol), &tol, |b, &tol| {
            b.iter(|| black_box(s.to_rational_cubics(Tolerance::Relative(tol)).unwrap()))
        });
        group.bench_with_input(BenchmarkId::new("cubic", tol), &tol, |b, &tol| {
            b.iter(|| black_box(s.to_cubics(Tolerance::Relative(tol)).unwrap()))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_medians, bench_chains);
criterion_main!(benches);
