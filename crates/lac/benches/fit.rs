//! Benchmarks for the fit issue (30): a single-segment fit of 1,000 noisy points (target
//! ≤ 2 ms median) and a path fit of 1,000 noisy points from a G2 path of 4–8 segments
//! within 4σ, into at most 10 segments (target ≤ 50 ms).

use criterion::{criterion_group, criterion_main, Criterion};
use kurbo::{Point, Vec2};
use lac::{Alphas, Closure, ControlPolygon, Curve, Fit, FitOptions, Path, Segment};
use std::hint::black_box;

mod common;
use common::Rng;

fn normal(rng: &mut Rng) -> f64 {
    let u = rng.next().max(1e-300);
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * rng.next()).cos()
}

/// 1,000 points along `curve` with normal noise of deviation `sigma`, and the largest
/// noise drawn (in σ).
fn noisy_with_largest(curve: &impl Curve, sigma: f64, rng: &mut Rng) -> (Vec<Point>, f64) {
    let mut largest: f64 = 0.0;
    let points = curve
        .sample_by_arc_length(1000)
        .unwrap()
        .iter()
        .map(|s| {
            let z = normal(rng);
            largest = largest.max(z.abs());
            s.point + sigma * z * Vec2::from_angle(s.theta + std::f64::consts::FRAC_PI_2)
        })
        .collect();
    (points, largest)
}

/// 1,000 points along `curve` with normal noise of deviation `sigma`.
fn noisy(curve: &impl Curve, sigma: f64, rng: &mut Rng) -> Vec<Point> {
    noisy_with_largest(curve, sigma, rng).0
}

fn bench(c: &mut Criterion) {
    let mut rng = Rng(0xF17);
    let singles: Vec<Vec<Point>> = [-1.0, 0.0, 1.0, 2.0]
        .iter()
        .map(|&alpha| {
            let seg = Segment::from_curvatures(Point::ORIGIN, 0.0, [1.0, 3.0], 1.0, alpha).unwrap();
            noisy(&seg, 1e-4, &mut rng)
        })
        .collect();
    c.bench_function("fit_single_segment_1000_points", |b| {
        let mut k = 0;
        b.iter(|| {
            k = (k + 1) % singles.len();
            black_box(Fit::from_points(&singles[k], &FitOptions::default()).unwrap())
        })
    });
    let mut paths = Vec::new();
    while paths.len() < 4 {
        let mut pts = vec![Point::ORIGIN];
        let mut dir: f64 = 0.0;
        for _ in 0..(6 + paths.len()) {
            let last = *pts.last().unwrap();
            pts.push(last + (0.6 + 0.8 * rng.next()) * Vec2::from_angle(dir));
            dir += 0.3 + 0.6 * rng.next();
        }
        let polygon = ControlPolygon::from_points(&pts, Closure::Open).unwrap();
        if let Ok(path) = Path::from_polygon_g2(&polygon, &Alphas::One(-0.5)) {
            let sigma = 1e-4 * path.arc_length();
            // Only sets whose noise stays within 3.5σ, so that the path they were drawn from
            // lies within the tolerance of 4σ (the set does not depend on the fit).
            let (points, largest) = noisy_with_largest(&path, sigma, &mut rng);
            if largest <= 3.5 {
                paths.push((points, sigma));
            }
        }
    }
    c.bench_function("fit_path_1000_points", |b| {
        let mut k = 0;
        b.iter(|| {
            k = (k + 1) % paths.len();
            let (points, sigma) = &paths[k];
            let options = FitOptions {
                tolerance: Some(4.0 * sigma),
                max_segments: 10,
                ..FitOptions::default()
            };
            black_box(Fit::from_points(points, &options).unwrap())
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench
}
criterion_main!(benches);
