//! Benchmark for the promise of the space-curve issue: a segment solve from four points
//! ≤ 500 µs median over a seeded random set of solvable inputs, per (α, β) ∈ {−1, 0, 1}²,
//! with the share of the random inputs that are solved (printed before the timings).
//!
//! Inputs use seed 003's placement (P0 = (−1, 0, 0), P3 = (1, 0, 0)): θ0 and θ1 uniform in
//! [0.1, 1.4] rad, |θ2| uniform in [0.05, π − 0.05] with either sign, legs |P1 − P0| and
//! |P3 − P2| uniform in [0.3, 1], Ω uniform in [0, 0.5], type 1 or 2 with equal chance.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use lac::{SpaceSegment, SpaceShape, TorsionType, Vec3};
use std::hint::black_box;

mod common;
use common::{median_per_call, Rng};

/// One random input: points, Ω and type.
type Input = ([Vec3; 4], f64, TorsionType);

fn random_inputs(seed: u64, n: usize) -> Vec<Input> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|_| {
            let t0 = 0.1 + 1.3 * rng.next();
            let t1 = 0.1 + 1.3 * rng.next();
            let sign = if rng.next() < 0.5 { -1.0 } else { 1.0 };
            let t2 = sign * (0.05 + (std::f64::consts::PI - 0.1) * rng.next());
            let (l0, l1) = (0.3 + 0.7 * rng.next(), 0.3 + 0.7 * rng.next());
            let p = [
                Vec3::new(-1.0, 0.0, 0.0),
                Vec3::new(-1.0 + l0 * t0.cos(), l0 * t0.sin(), 0.0),
                Vec3::new(
                    1.0 - l1 * t1.cos(),
                    l1 * t1.sin() * t2.cos(),
                    l1 * t1.sin() * t2.sin(),
                ),
                Vec3::new(1.0, 0.0, 0.0),
            ];
            let omega = 0.5 * rng.next();
            let kind = if rng.next() < 0.5 {
                TorsionType::One
            } else {
                TorsionType::Two
            };
            (p, omega, kind)
        })
        .collect()
}

fn bench_solve(c: &mut Criterion) {
    let mut group = c.benchmark_group("space_median");
    for alpha in [-1.0, 0.0, 1.0] {
        for beta in [-1.0, 0.0, 1.0] {
            let inputs = random_inputs(0x3D_5EED, 256);
            let solve = |&(p, omega, torsion): &Input| {
                let shape = SpaceShape {
                    alpha,
                    beta,
                    omega,
                    torsion,
                };
                SpaceSegment::from_control_points(p, shape)
            };
            let (solvable, failing): (Vec<Input>, Vec<Input>) =
                inputs.iter().partition(|i| solve(i).is_ok());
            eprintln!(
                "alpha {alpha:>2} beta {beta:>2}: solved {}/{} ({:.0}%)",
                solvable.len(),
                inputs.len(),
                100.0 * solvable.len() as f64 / inputs.len() as f64
            );
            let id = format!("{alpha}/{beta}");
            group.bench_with_input(BenchmarkId::new("solve", &id), &solvable, |b, set| {
                b.iter_custom(|iters| {
                    median_per_call(iters, set, |i| {
                        black_box(solve(black_box(i)).unwrap());
                    })
                })
            });
            if !failing.is_empty() {
                group.bench_with_input(BenchmarkId::new("reject", &id), &failing, |b, set| {
                    b.iter_custom(|iters| {
                        median_per_call(iters, set, |i| {
                            black_box(solve(black_box(i)).unwrap_err());
                        })
                    })
                });
            }
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench_solve
}
criterion_main!(benches);
