//! Benchmarks for the promises of the planar-core issue: solve ≤ 2 µs, solve + 65 samples
//! ≤ 6 µs (medians over a fixed seeded set of drawable configurations per α), and the
//! 512×512 drawable-region map (≤ 0.1 s in `lac region`, which spreads its rows over the
//! cores; here in one thread).
//!
//! `solve/α` and `solve_and_65_samples/α` cycle through the set inside each timing, so they
//! measure the mean over the set; `median_over_configurations/…` times calls one by one and
//! reports the median over the set.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::Point;
use lac::Curve;
use lac::Segment;
use std::hint::black_box;

mod common;
use common::{median_per_call, Rng};

/// 256 drawable configurations with P0 = (−1, 0), P2 = (1, 0) and P1 uniform in the
/// upper half of the square [−1, 1]², as in seed 000's Fig. 9 and Table 3.
fn configurations(alpha: f64) -> Vec<[Point; 3]> {
    let mut rng = Rng(0x1AC0_FFEE ^ alpha.to_bits());
    let mut out = Vec::new();
    while out.len() < 256 {
        let p = [
            Point::new(-1.0, 0.0),
            Point::new(2.0 * rng.next() - 1.0, rng.next()),
            Point::new(1.0, 0.0),
        ];
        if Segment::from_control_points(p, alpha).is_ok() {
            out.push(p);
        }
    }
    out
}

fn bench_solve(c: &mut Criterion) {
    let mut group = c.benchmark_group("solve");
    for alpha in [-1.0, 0.0, 0.5, 1.0, 2.0] {
        let set = configurations(alpha);
        group.bench_with_input(BenchmarkId::from_parameter(alpha), &set, |b, set| {
            let mut i = 0;
            b.iter(|| {
                i = (i + 1) % set.len();
                black_box(Segment::from_control_points(black_box(set[i]), alpha).unwrap())
            })
        });
    }
    group.finish();
}

fn bench_solve_and_sample(c: &mut Criterion) {
    let mut group = c.benchmark_group("solve_and_65_samples");
    for alpha in [-1.0, 0.0, 0.5, 1.0, 2.0] {
        let set = configurations(alpha);
        group.bench_with_input(BenchmarkId::from_parameter(alpha), &set, |b, set| {
            let mut i = 0;
            b.iter(|| {
                i = (i + 1) % set.len();
                let seg = Segment::from_control_points(black_box(set[i]), alpha).unwrap();
                black_box(seg.sample_by_arc_length(65).unwrap())
            })
        });
    }
    group.finish();
}

fn bench_medians(c: &mut Criterion) {
    let mut group = c.benchmark_group("median_over_configurations");
    for alpha in [-1.0, 0.0, 0.5, 1.0, 2.0] {
        let set = configurations(alpha);
        group.bench_with_input(BenchmarkId::new("solve", alpha), &set, |b, set| {
            b.iter_custom(|iters| {
                median_per_call(iters, set, |p| {
                    black_box(Segment::from_control_points(black_box(*p), alpha).unwrap());
                })
            })
        });
        group.bench_with_input(
            BenchmarkId::new("solve_and_65_samples", alpha),
            &set,
            |b, set| {
                b.iter_custom(|iters| {
                    median_per_call(iters, set, |p| {
                        let seg = Segment::from_control_points(black_box(*p), alpha).unwrap();
                        black_box(seg.sample_by_arc_length(65).unwrap());
                    })
                })
            },
        );
    }
    group.finish();
}

/// The whole 512×512 region map in a single thread: its top rows' left halves solved, the
/// rest mirrored (`lac region` spreads the rows over the cores).
fn bench_region_map(c: &mut Criterion) {
    let mut group = c.benchmark_group("region_map_512_one_thread");
    group.sample_size(10);
    for alpha in [-1.0, 0.5, 2.0] {
        group.bench_with_input(BenchmarkId::from_parameter(alpha), &alpha, |b, &alpha| {
            b.iter(|| {
                let size = 512;
                let top = (0..lac::region::top_rows(size))
                    .map(|r| lac::region::row(alpha, size, r))
                    .collect();
                black_box(lac::region::mirror_rows(size, top))
            })
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    bench_solve,
    bench_solve_and_sample,
    bench_medians,
    bench_region_map
);
criterion_main!(benches);
