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
