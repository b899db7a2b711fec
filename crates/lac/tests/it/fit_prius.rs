//! The published data: the five Prius silhouette lines of Graiff Zurita, Kajiwara and Miura
//! (tools/data/prius), fitted by one segment against the best segment with the α they
//! published, and by a G2 path within 3 mm.

use kurbo::Point;
use lac::{Fit, FitAlpha, FitOptions};

/// The lines, and the α the authors fitted to each.
const LINES: [(&str, f64); 5] = [
    (include_str!("../../../../tools/data/prius/ps_1.txt"), 4.08),
    (include_str!("../../../../tools/data/prius/ps_2.txt"), 1.57),
    (include_str!("../../../../tools/data/prius/ps_3.txt"), 0.30),
    (include_str!("../../../../tools/data/prius/ps_4.txt"), -4.99),
    (include_str!("../../../../tools/data/prius/ps_5.txt"), 0.67),
];

/// The points rotated into the plane of the lines, as the authors do (their normal onto +z).
fn planar(text: &str) -> Vec<Point> {
    let n: [f64; 3] = [
        -0.998_562_791_831_263_3,
        -0.053_576_789_718_464_81,
        0.001_370_537_710_815_138_8,
    ];
    let nxy = n[0].hypot(n[1]);
    let nxyz = nxy.hypot(n[2]);
    let (cp, sp) = (n[0] / nxy, n[1] / nxy);
    let (ca, sa) = (n[2] / nxyz, nxy / nxyz);
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            let (x, y) = (cp * v[0] + sp * v[1], -sp * v[0] + cp * v[1]);
            Point::new(ca * x - sa * v[2], y)
        })
        .collect()
}

#[test]
fn one_segment_is_at_least_as_close_as_the_published_alpha_and_a_g2_path_is_within_3_mm() {
    eprintln!(
        "line  points  their α  RMS at their α  lac α  lac RMS  3 mm G2 path: segments, largest"
    );
    for (k, (text, theirs)) in LINES.iter().enumerate() {
        let points = planar(text);
        let at_theirs = Fit::from_points(
            &points,
            &FitOptions {
                alpha: FitAlpha::Fixed(*theirs),
                ..FitOptions::default()
            },
        )
        .unwrap();
        let free = Fit::from_points(&points, &FitOptions::default()).unwrap();
        let path = Fit::from_points(
            &points,
            &FitOptions {
                tolerance: Some(3.0),
                max_segments: 20,
                ..FitOptions::default()
            },
        )
        .unwrap();
        eprintln!(
            "ps_{}  {:>6}  {:>7.2}  {:>11.3} mm  {:>5.2}  {:.3} mm  {}, {:.2} mm",
            k + 1,
            points.len(),
            theirs,
            at_theirs.rms(),
            free.pieces()[0].alpha,
            free.rms(),
            path.pieces().len(),
            path.max_distance()
        );
        assert!(
            free.rms() <= at_theirs.rms() * (1.0 + 1e-9),
            "line {}",
            k + 1
        );
        assert!(path.max_distance() <= 3.0);
        assert!(path.joints().iter().all(|j| j.curvature_jump <= 1e-9));
    }
}

/// Within 0.1 mm (the scanner's noise) every line but the first is a G2 path of a few
/// segments; the first ends in a curl that no piece reaches, and is refused. Its search once
/// split the piece at the curl, saw the new piece shrink to nothing, and split it again,
/// round after round (3,000 rounds, 52 s before the rounds were counted).
#[test]
fn within_a_tenth_of_a_millimetre_four_lines_fit_and_the_first_is_refused() {
    let options = FitOptions {
        tolerance: Some(0.1),
        max_segments: 64,
        ..FitOptions::default()
    };
    for (k, (text, _)) in LINES.iter().enumerate() {
        let points = planar(text);
        let fit = Fit::from_points(&points, &options);
        match (k, fit) {
            (0, Err(lac::Error::FitToleranceNotMet { reached, .. })) => {
                eprintln!("ps_1 refused, {reached:.3} mm reached");
                assert!(reached > 0.1);
            }
            (0, other) => panic!("ps_1: {other:?}"),
            (_, Ok(fit)) => {
                eprintln!(
                    "ps_{}: {} segments, largest {:.3} mm",
                    k + 1,
                    fit.pieces().len(),
                    fit.max_distance()
                );
                assert!(fit.max_distance() <= 0.1);
                assert!(fit.pieces().len() <= 16, "ps_{}", k + 1);
            }
            (_, Err(e)) => panic!("ps_{}: {e}", k + 1),
        }
    }
}
