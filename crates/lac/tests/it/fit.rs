//! Fits against curves made forward: points sampled from known log-aesthetic segments and
//! G2 paths (built by the segment and path constructors, not by the fit), with noise normal
//! to the curve, and the fit found again.

use kurbo::{Point, Vec2};
use lac::{Alphas, Closure, ControlPolygon, Curve, Fit, FitOptions, Path, Segment};

use crate::common::space_inputs::Rng;

/// A standard normal number (Box–Muller).
fn normal(rng: &mut Rng) -> f64 {
    let u = rng.next().max(1e-300);
    let v = rng.next();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// `n` points equally spaced in arc length along `curve`, each moved along the normal by
/// noise of deviation `sigma`; and the noise-free points.
fn noisy(curve: &impl Curve, n: usize, sigma: f64, rng: &mut Rng) -> (Vec<Point>, Vec<Point>) {
    let samples = curve.sample_by_arc_length(n).unwrap();
    let clean: Vec<Point> = samples.iter().map(|s| s.point).collect();
    let moved = samples
        .iter()
        .map(|s| {
            let across = Vec2::from_angle(s.theta + std::f64::consts::FRAC_PI_2);
            s.point + sigma * normal(rng) * across
        })
        .collect();
    (moved, clean)
}

/// The largest distance from the fit to the noise-free curve, at the clean points' feet:
/// the distance of each clean point to the fit.
fn distance_to_truth(fit: &Fit, clean: &[Point]) -> f64 {
    let samples = fit.sample_by_arc_length(4000).unwrap();
    clean
        .iter()
        .map(|p| {
            samples
                .windows(2)
                .map(|w| segment_distance(*p, w[0].point, w[1].point))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

fn segment_distance(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.hypot2()).clamp(0.0, 1.0);
    (p - (a + t * ab)).hypot()
}

#[test]
fn alpha_is_recovered_from_noisy_single_segments() {
    let mut rng = Rng(7);
    let mut worst: f64 = 0.0;
    for case in 0..40 {
        let alpha = [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0][case % 6];
        let ratio = 2.5 + 1.5 * rng.next();
        let k0 = 0.5 + rng.next();
        // About 1.5 rad of turning (a segment turns by less than π).
        let len = 3.0 / (k0 * (1.0 + ratio));
        let truth =
            Segment::from_curvatures(Point::ORIGIN, 0.0, [k0, k0 * ratio], len, alpha).unwrap();
        let (points, _) = noisy(&truth, 1000, 1e-4 * len, &mut rng);
        let fit = Fit::from_points(&points, &FitOptions::default()).unwrap();
        let err = (fit.pieces()[0].alpha - alpha).abs();
        assert!(fit.rms() < 1.2e-4 * len, "α = {alpha}: rms {:e}", fit.rms());
        worst = worst.max(err);
    }
    eprintln!("largest α error over 40 noisy segments: {worst:.4}");
    assert!(worst <= 0.05, "worst α error {worst}");
}

#[test]
fn noisy_g2_paths_are_fitted_within_three_sigma_with_at_most_one_extra_segment() {
    let mut rng = Rng(11);
    for case in 0..12 {
        let alpha = [-0.5, 0.5, 1.0, 2.0][case % 4];
        // A polygon turning one way: 5–9 vertices.
        let vertices = 5 + (rng.next() * 5.0) as usize;
        let mut pts = vec![Point::ORIGIN];
        let mut dir: f64 = 0.0;
        for _ in 1..vertices {
            let leg = 0.6 + 0.8 * rng.next();
            let last = *pts.last().unwrap();
            pts.push(last + leg * Vec2::from_angle(dir));
            dir += 0.3 + 0.6 * rng.next();
        }
        let polygon = ControlPolygon::from_points(&pts, Closure::Open).unwrap();
        let Ok(path) = Path::from_polygon_g2(&polygon, &Alphas::One(alpha)) else {
            continue;
        };
        let truth_segments = path.segments().len();
        let len = path.arc_length();
        let sigma = 1e-4 * len;
        let (points, clean) = noisy(&path, 1000, sigma, &mut rng);
        let options = FitOptions {
            tolerance: Some(4.0 * sigma),
            max_segments: 30,
            ..FitOptions::default()
        };
        let fit = Fit::from_points(&points, &options).unwrap();
        let d = distance_to_truth(&fit, &clean);
        eprintln!(
            "α {alpha}: truth {truth_segments} segments, fit {}, largest distance {:.2}σ, \
             to the noise-free curve {:.2}σ",
            fit.pieces().len(),
            fit.max_distance() / sigma,
            d / sigma
        );
        assert!(fit.max_distance() <= 4.0 * sigma);
        assert!(
            d <= 3.0 * sigma,
            "α = {alpha}: {:.2}σ from the noise-free curve",
            d / sigma
        );
        assert!(
            fit.pieces().len() <= truth_segments + 1,
            "α = {alpha}: {} segments for {truth_segments}",
            fit.pieces().len()
        );
    }
}

#[test]
fn a_closed_g2_path_is_fitted_closed() {
    let pts = [
        Point::new(0.0, 0.0),
        Point::new(2.0, -0.2),
        Point::new(2.6, 1.2),
        Point::new(1.4, 2.2),
        Point::new(-0.4, 1.4),
    ];
    let polygon = ControlPolygon::from_points(&pts, Closure::Closed).unwrap();
    let path = Path::from_polygon_g2(&polygon, &Alphas::One(-0.5)).unwrap();
    let mut rng = Rng(3);
    let sigma = 1e-4 * path.arc_length();
    let (mut points, clean) = noisy(&path, 600, sigma, &mut rng);
    points.pop(); // The last sample repeats the first.
    let options = FitOptions {
        tolerance: Some(4.0 * sigma),
        max_segments: 20,
        closure: Closure::Closed,
        ..FitOptions::default()
    };
    let fit = Fit::from_points(&points, &options).unwrap();
    let closing = fit.joints().last().unwrap();
    eprintln!(
        "closed: {} segments, closing gap {:e}, curvature jump {:e}",
        fit.pieces().len(),
        closing.gap,
        closing.curvature_jump
    );
    assert!(fit.max_distance() <= 4.0 * sigma);
    assert!(closing.gap < 1e-9 && closing.curvature_jump < 1e-9);
    assert!(distance_to_truth(&fit, &clean) <= 3.0 * sigma);
}

#[test]
fn pinned_ends_stay_on_the_first_and_last_points() {
    let truth = Segment::from_curvatures(Point::ORIGIN, 0.2, [1.0, 2.6], 1.0, 0.5).unwrap();
    let mut rng = Rng(5);
    let (points, _) = noisy(&truth, 300, 1e-3, &mut rng);
    let options = FitOptions {
        pin_ends: true,
        ..FitOptions::default()
    };
    let fit = Fit::from_points(&points, &options).unwrap();
    assert!((fit.start_point() - points[0]).hypot() < 1e-12);
    assert!(
        (fit.end_point() - points[299]).hypot() < 1e-9,
        "{:?}",
        fit.end_point()
    );
}

#[test]
fn huber_loss_keeps_outliers_from_pulling_the_fit() {
    let truth = Segment::from_curvatures(Point::ORIGIN, 0.0, [1.0, 3.0], 1.0, -1.0).unwrap();
    let mut rng = Rng(9);
    let (mut points, clean) = noisy(&truth, 400, 1e-4, &mut rng);
    for k in [50, 51, 200, 330] {
        points[k].y += 0.05;
    }
    let plain = Fit::from_points(&points, &FitOptions::default()).unwrap();
    let robust = Fit::from_points(
        &points,
        &FitOptions {
            loss: lac::FitLoss::Huber { delta: 3e-4 },
            ..FitOptions::default()
        },
    )
    .unwrap();
    let (d_plain, d_robust) = (
        distance_to_truth(&plain, &clean),
        distance_to_truth(&robust, &clean),
    );
    eprintln!("outliers: least squares {d_plain:e} from the truth, Huber {d_robust:e}");
    assert!(d_robust < 0.3 * d_plain);
    let mut far = robust.farthest_points(4);
    far.sort();
    assert_eq!(far, [50, 51, 200, 330]);
}

#[test]
fn bad_points_are_refused_with_a_typed_error() {
    use lac::ErrorKind;
    let fit = |pts: &[Point]| {
        Fit::from_points(pts, &FitOptions::default())
            .unwrap_err()
            .kind()
    };
    let p = |x: f64, y: f64| Point::new(x, y);
    assert_eq!(fit(&[p(0.0, 0.0), p(1.0, 0.0)]), ErrorKind::TooFewPoints);
    assert_eq!(fit(&[p(0.0, 0.0); 10]), ErrorKind::TooFewPoints);
    assert_eq!(
        fit(&[p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0), p(3.0, 3.0)]),
        ErrorKind::CollinearPoints
    );
    assert_eq!(
        fit(&[p(0.0, 0.0), p(f64::NAN, 1.0), p(2.0, 0.0)]),
        ErrorKind::NonFinite
    );
    let arc: Vec<Point> = (0..50)
        .map(|k| p((k as f64 * 0.1).cos(), (k as f64 * 0.1).sin()))
        .collect();
    let zigzag: Vec<Point> = arc
        .iter()
        .enumerate()
        .map(|(k, q)| p(q.x, q.y + if k % 2 == 0 { 0.01 } else { -0.01 }))
        .collect();
    let err = Fit::from_points(
        &zigzag,
        &FitOptions {
            tolerance: Some(1e-4),
            max_segments: 2,
            ..FitOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(err.kind(), ErrorKind::FitToleranceNotMet);
    eprintln!("{err}");
}

/// A hundred thousand points (the search looks at a few hundred, the polish at 20,000, and
/// every point is measured): a noisy G2 path of three segments is fitted within 4σ, as near
/// the noise-free curve and with as few segments as from a thousand.
#[test]
fn a_hundred_thousand_points_are_fitted_like_a_thousand() {
    let polygon = ControlPolygon::from_points(
        &[
            Point::ORIGIN,
            Point::new(1.0, 0.0),
            Point::new(1.8, 0.5),
            Point::new(2.3, 1.3),
            Point::new(2.4, 2.2),
        ],
        Closure::Open,
    )
    .unwrap();
    let path = Path::from_polygon_g2(&polygon, &Alphas::One(0.5)).unwrap();
    let truth_segments = path.segments().len();
    let sigma = 1e-4 * path.arc_length();
    let mut rng = Rng(29);
    let (points, clean) = noisy(&path, 100_000, sigma, &mut rng);
    let options = FitOptions {
        tolerance: Some(5.0 * sigma),
        max_segments: 20,
        ..FitOptions::default()
    };
    let fit = Fit::from_points(&points, &options).unwrap();
    let every_hundredth: Vec<Point> = clean.iter().step_by(100).copied().collect();
    let d = distance_to_truth(&fit, &every_hundredth);
    eprintln!(
        "100,000 points: truth {truth_segments} segments, fit {}, largest distance {:.2}σ, \
         to the noise-free curve {:.2}σ",
        fit.pieces().len(),
        fit.max_distance() / sigma,
        d / sigma
    );
    assert_eq!(fit.distances().len(), 100_000);
    assert!(fit.max_distance() <= 5.0 * sigma);
    assert!(
        d <= 3.0 * sigma,
        "{:.2}σ from the noise-free curve",
        d / sigma
    );
    assert!(fit.pieces().len() <= truth_segments + 1);
}

/// Two segments meeting with a curvature jump (G1): a G1 fit keeps a jump, with at most one
/// segment more than the truth, within 4σ and 3σ of the noise-free curve, its joints
/// continuous in position and tangent. (The G2 fit of the same points, printed, rounds the
/// jump off with a short piece.)
#[test]
fn a_g1_fit_keeps_a_curvature_jump() {
    use lac::Continuity;
    let a = Segment::from_curvatures(Point::ORIGIN, 0.0, [1.0, 1.5], 1.0, 1.0).unwrap();
    let b = Segment::from_curvatures(
        a.end_point(),
        a.theta_at_s(a.arc_length()).unwrap(),
        [3.0, 2.5],
        0.8,
        0.5,
    )
    .unwrap();
    let sigma = 1e-4 * (a.arc_length() + b.arc_length());
    let mut rng = Rng(41);
    let (mut points, mut clean) = noisy(&a, 500, sigma, &mut rng);
    let (more, more_clean) = noisy(&b, 400, sigma, &mut rng);
    points.extend(more.into_iter().skip(1));
    clean.extend(more_clean.into_iter().skip(1));
    let fit_with = |continuity: Continuity| {
        let options = FitOptions {
            tolerance: Some(4.0 * sigma),
            max_segments: 12,
            continuity,
            ..FitOptions::default()
        };
        Fit::from_points(&points, &options).unwrap()
    };
    let g1 = fit_with(Continuity::G1);
    let g2 = fit_with(Continuity::G2);
    let d = distance_to_truth(&g1, &clean);
    let jump = g1
        .joints()
        .iter()
        .map(|j| j.curvature_jump)
        .fold(0.0, f64::max);
    eprintln!(
        "G1: {} segments (G2: {}), largest distance {:.2}σ, to the noise-free curve {:.2}σ, \
         largest curvature jump {jump:.2}",
        g1.pieces().len(),
        g2.pieces().len(),
        g1.max_distance() / sigma,
        d / sigma
    );
    assert!(g1.max_distance() <= 4.0 * sigma);
    assert!(
        d <= 3.0 * sigma,
        "{:.2}σ from the noise-free curve",
        d / sigma
    );
    assert!(g1.pieces().len() <= 3);
    assert!(jump > 0.3, "the jump from 1.5 to 3 is kept: {jump}");
    assert!(g1
        .joints()
        .iter()
        .all(|j| j.gap < 1e-9 && j.tangent_jump < 1e-9));
}
