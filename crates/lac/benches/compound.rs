//! Benchmarks for the compound-curve issue: three-point (+ r_θ) and four-point solves
//! ≤ 4 µs, over fixed seeded sets of drawable configurations per (α0, α1).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::Point;
use lac::CompoundCurve;
use std::hint::black_box;

mod common;
use common::Rng;

const PAIRS: [(f64, f64); 4] = [(-1.0, 2.0), (2.0, -1.0), (0.5, 1.0), (-0.5, -0.5)];

/// 256 drawable three-point configurations: P0 = (−1, 0), P2 = (1, 0), P1 uniform in the
/// upper half of [−1, 1]², r_θ uniform in [0.2, 0.8].
fn three_point_set(a0: f64, a1: f64) -> Vec<([Point; 3], f64)> {
    let mut rng = Rng(0x3C0_FFEE ^ a0.to_bits() ^ a1.to_bits().rotate_left(7));
    let mut out = Vec::new();
    while out.len() < 256 {
        let p = [
            Point::new(-1.0, 0.0),
            Point::new(2.0 * rng.next() - 1.0, rng.next()),
            Point::new(1.0, 0.0),
        ];
        let r = 0.2 + 0.6 * rng.next();
        if CompoundCurve::from_three_points(p, a0, a1, r).is_ok() {
            out.push((p, r));
        }
    }
    out
}

/// 256 drawable four-point configurations: a left-turning polygon with legs of random
/// length (0.5 to 1.5) and turns of 10° to 110° at each inner vertex.
fn four_point_set(a0: f64, a1: f64) -> Vec<[Point; 4]> {
    let mut rng = Rng(0x4C0_FFEE ^ a0.to_bits() ^ a1.to_bits().rotate_left(7));
    let mut out = Vec::new();
    while out.len() < 256 {
        let mut p = [Point::ZERO; 4];
        let mut dir = 0.0f64;
        for i in 1..4 {
            let len = 0.5 + rng.next();
            p[i] = p[i - 1] + kurbo::Vec2::from_angle(dir) * len;
            dir += (10.0 + 100.0 * rng.next()).to_radians();
        }
        if CompoundCurve::from_four_points(p, a0, a1).is_ok() {
            out.push(p);
        }
    }
    out
}

fn bench_three_points(c: &mut Criterion) {
    let mut group = c.benchmark_group("compound_three_point_solve");
    for (a0, a1) in PAIRS {
        let set = three_point_set(a0, a1);
        let id = BenchmarkId::from_parameter(format!("{a0},{a1}"));
        group.bench_with_input(id, &set, |b, set| {
            let mut i = 0;
            b.iter(|| {
                i = (i + 1) % set.len();
                let (p, r) = set[i];
                black_box(CompoundCurve::from_three_points(black_box(p), a0, a1, r).unwrap())
            })
        });
    }
    group.finish();
}

fn bench_four_points(c: &mut Criterion) {
    let mut group = c.benchmark_group("compound_four_point_solve");
    for (a0, a1) in PAIRS {
        let set = four_point_set(a0, a1);
        let id = BenchmarkId::from_parameter(format!("{a0},{a1}"));
        group.bench_with_input(id, &set, |b, set| {
            let mut i = 0;
            b.iter(|| {
                i = (i + 1) % set.len();
                black_box(CompoundCurve::from_four_points(black_box(set[i]), a0, a1).unwrap())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_three_points, bench_four_points);
criterion_main!(benches);
