//! Benchmarks for the path issue (15): a 10-segment G2 path from a control polygon re-solved
//! after a drag from the previous solution (warm, ≤ 50 µs) and from scratch (cold, ≤ 200 µs).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::{Point, Vec2};
use lac::{Alphas, Closure, ControlPolygon, Path};
use std::hint::black_box;

mod common;
use common::Rng;

/// Seeded open polygons of 12 points (10 segments) turning left by 20°–60° at each vertex,
/// legs 0.6–1.4, that have a G2 path for `alpha`; each with a dragged copy (one interior
/// vertex moved by up to 0.05) that has one too, and the first one's joint fractions.
fn set(alpha: f64) -> Vec<(ControlPolygon, ControlPolygon, Vec<f64>)> {
    let mut rng = Rng(0x9A7A ^ alpha.to_bits());
    let mut out = Vec::new();
    while out.len() < 32 {
        let mut p = vec![Point::ZERO];
        let mut dir = 0.0f64;
        for _ in 0..11 {
            let len = 0.6 + 0.8 * rng.next();
            let last = *p.last().unwrap();
            p.push(last + Vec2::from_angle(dir) * len);
            dir += (20.0 + 40.0 * rng.next()).to_radians();
        }
        let poly = ControlPolygon::from_points(&p, Closure::Open).unwrap();
        let Ok(path) = Path::from_polygon_g2(&poly, &Alphas::One(alpha)) else {
            continue;
        };
        let k = 1 + (rng.next() * 10.0) as usize;
        p[k] += Vec2::new(0.1 * rng.next() - 0.05, 0.1 * rng.next() - 0.05);
        let dragged = ControlPolygon::from_points(&p, Closure::Open).unwrap();
        if Path::from_polygon_g2(&dragged, &Alphas::One(alpha)).is_ok() {
            out.push((poly, dragged, path.joint_fractions()));
        }
    }
    out
}

fn bench_path(c: &mut Criterion) {
    for (name, warm) in [
        ("path_g2_10_segments_warm", true),
        ("path_g2_10_segments_cold", false),
    ] {
        let mut group = c.benchmark_group(name);
        for alpha in [-0.5, 0.5, 2.0] {
            let set = set(alpha);
            group.bench_with_input(BenchmarkId::from_parameter(alpha), &set, |b, set| {
                let mut i = 0;
                b.iter(|| {
                    let (_, dragged, fractions) = &set[i % set.len()];
                    i += 1;
                    let alphas = Alphas::One(alpha);
                    black_box(if warm {
                        Path::from_polygon_g2_near(dragged, &alphas, fractions).unwrap()
                    } else {
                        Path::from_polygon_g2(dragged, &alphas).unwrap()
                    })
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_path);
criterion_main!(benches);
