//! Unit tests of the fit on curves it must find again exactly.

use kurbo::Point;

use super::*;
use crate::curve::Curve;

fn points_of(curve: &impl Curve, n: usize) -> Vec<Point> {
    curve
        .sample_by_arc_length(n)
        .unwrap()
        .iter()
        .map(|s| s.point)
        .collect()
}

#[test]
fn a_segment_is_found_again_for_every_kind_of_alpha() {
    for alpha in [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 4.0] {
        let truth =
            Segment::from_curvatures(Point::new(1.0, 2.0), 0.3, [0.8, 2.0], 1.5, alpha).unwrap();
        let points = points_of(&truth, 300);
        let fit = Fit::from_points(&points, &FitOptions::default()).unwrap();
        assert!(
            fit.max_distance() < 1e-9,
            "α = {alpha}: {:e}",
            fit.max_distance()
        );
        let piece = fit.pieces()[0];
        assert!(
            (piece.alpha - alpha).abs() < 1e-4,
            "α = {alpha}: {}",
            piece.alpha
        );
        assert!(
            (piece.length - 1.5).abs() < 1e-8,
            "α = {alpha}: {}",
            piece.length
        );
    }
}

#[test]
fn a_two_piece_chain_is_found_again() {
    let a = Segment::from_curvatures(Point::ORIGIN, 0.0, [0.5, 1.5], 1.0, 1.0).unwrap();
    let b = Segment::from_curvatures(
        a.end_point(),
        a.theta_at_s(1.0).unwrap(),
        [1.5, 0.7],
        1.2,
        1.0,
    )
    .unwrap();
    let mut points = points_of(&a, 200);
    points.extend(points_of(&b, 200).into_iter().skip(1));
    let options = FitOptions {
        max_segments: 2,
        ..FitOptions::default()
    };
    let fit = Fit::from_points(&points, &options).unwrap();
    assert!(fit.max_distance() < 1e-8, "{:e}", fit.max_distance());
}

#[test]
fn scratch_counts() {
    use std::sync::atomic::Ordering;
    let truth = Segment::from_curvatures(Point::ORIGIN, 0.0, [1.0, 3.0], 1.0, 1.0).unwrap();
    let mut seed = 1u64;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let samples = truth.sample_by_arc_length(1000).unwrap();
    let points: Vec<Point> = samples
        .iter()
        .map(|s| s.point + 3.4e-4 * rnd() * kurbo::Vec2::from_angle(s.theta + 1.57))
        .collect();
    for c in &solve::COUNTS {
        c.store(0, Ordering::Relaxed);
    }
    let t0 = std::time::Instant::now();
    let fit = Fit::from_points(&points, &FitOptions::default()).unwrap();
    eprintln!(
        "sens {} µs chain {} µs normal eq {} µs",
        solve::COUNTS[3].load(Ordering::Relaxed) / 1000,
        solve::COUNTS[4].load(Ordering::Relaxed) / 1000,
        solve::COUNTS[5].load(Ordering::Relaxed) / 1000
    );
    let t1 = std::time::Instant::now();
    let input = build::Input::new(&points, &FitOptions::default()).unwrap();
    let _profile = guess::Profile::new(&input.data, false);
    eprintln!("profile {:?}", t1.elapsed());
    eprintln!(
        "{:?} newton {} states {} iterations {} ; alpha {} rms {:e}",
        t0.elapsed(),
        solve::COUNTS[0].load(Ordering::Relaxed),
        solve::COUNTS[1].load(Ordering::Relaxed),
        solve::COUNTS[2].load(Ordering::Relaxed),
        fit.pieces()[0].alpha,
        fit.rms()
    );
}
