//! Claim: a fit's input maps onto the library's options as documented, its report holds the
//! fit's figures consistently, and a report read back (by `lac export`) places the same
//! segments again.

use kurbo::Point;
use lac::{Curve, FitAlpha, Segment, SegmentChain};
use lac_io::json::{to_line, AnyCurve, FitInput, FitReport, DEFAULT_MAX_SEGMENTS};

/// 200 points on a known segment (α = 0.5, curvature 1 to 3), every seventh moved off it by
/// a ten-thousandth of its length, alternately left and right.
fn points() -> Vec<[f64; 2]> {
    let truth = Segment::from_curvatures(Point::new(2.0, -1.0), 0.3, [1.0, 3.0], 1.2, 0.5).unwrap();
    truth
        .sample_by_arc_length(200)
        .unwrap()
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let off = if k % 7 == 3 {
                1.2e-4 * if k % 2 == 0 { 1.0 } else { -1.0 }
            } else {
                0.0
            };
            let n = s.tangent().turn_90();
            [s.point.x + off * n.x, s.point.y + off * n.y]
        })
        .collect()
}

#[test]
fn without_a_tolerance_one_segment_with_one_at_most_sixteen() {
    let input = FitInput {
        points: points(),
        ..FitInput::default()
    };
    let options = input.options().unwrap();
    assert_eq!((options.tolerance, options.max_segments), (None, 1));
    assert_eq!(options.alpha, FitAlpha::default());
    let with = FitInput {
        tolerance: Some(1e-3),
        ..input.clone()
    };
    assert_eq!(with.options().unwrap().max_segments, DEFAULT_MAX_SEGMENTS);
    let fixed = FitInput {
        alpha: Some(0.5),
        max_segments: Some(3),
        ..with.clone()
    };
    let options = fixed.options().unwrap();
    assert_eq!(
        (options.max_segments, options.alpha),
        (3, FitAlpha::Fixed(0.5))
    );
    let both = FitInput {
        alpha_range: Some([0.0, 1.0]),
        ..fixed
    };
    assert_eq!(both.options().unwrap_err().kind, "invalid_input");
}

#[test]
fn the_report_holds_the_fits_figures_consistently() {
    let input = FitInput {
        points: points(),
        ..FitInput::default()
    };
    let fit = input.solve().unwrap();
    let report = FitReport::new(&fit, &input.points, None, 33).unwrap();
    assert_eq!(report.point_count, 200);
    assert_eq!(report.fitted_segments, 1);
    assert_eq!(report.samples.len(), 33);
    assert_eq!(report.tolerance, None);
    assert_eq!(report.farthest.len(), 10);
    assert_eq!(report.farthest[0].index, report.worst_point);
    assert_eq!(report.farthest[0].distance, report.max_distance);
    assert_eq!(report.farthest[0].point, input.points[report.worst_point]);
    assert!(report
        .farthest
        .windows(2)
        .all(|w| w[0].distance >= w[1].distance));
    assert!(report.rms > 0.0 && report.rms <= report.max_distance);
    // The moved points are the farthest ones.
    assert!(
        report.farthest.iter().all(|f| f.index % 7 == 3),
        "{:?}",
        report.farthest
    );
    assert!(
        (report.pieces[0].alpha - 0.5).abs() < 0.01,
        "α {}",
        report.pieces[0].alpha
    );
    let line = to_line(&report);
    assert!(line.contains(r#""tolerance":null"#) && line.contains(r#""continuity":"g2""#));
}

#[test]
fn a_report_read_back_places_the_same_segments() {
    let input = FitInput {
        points: points(),
        tolerance: Some(1.5e-4),
        max_segments: Some(4),
        ..FitInput::default()
    };
    let fit = input.solve().unwrap();
    let report = FitReport::new(&fit, &input.points, input.tolerance, 9).unwrap();
    assert!(report.max_distance <= 1.5e-4);
    let AnyCurve::Fit(path) = AnyCurve::read(&to_line(&report)).unwrap() else {
        panic!("a fit's report is not read as a fit");
    };
    let (mine, theirs) = (SegmentChain::pieces(&path), SegmentChain::pieces(&fit));
    assert_eq!(mine.len(), theirs.len());
    let size = fit.arc_length();
    for (a, b) in mine.iter().zip(theirs) {
        for t in [0.0, 0.5, 1.0] {
            let p = a.point_at_s(t * a.arc_length()).unwrap();
            let q = b.point_at_s(t * b.arc_length()).unwrap();
            assert!((p - q).hypot() <= 1e-12 * size, "{p:?} {q:?}");
        }
    }
}

#[test]
fn a_fits_input_is_told_by_its_own_keys_and_a_paths_stays_a_paths() {
    let text = format!(r#"{{"points":{:?},"max_segments":1}}"#, points());
    assert_eq!(AnyCurve::read(&text).unwrap().name(), "fit");
    let path = r#"{"points":[[0,0],[1,0],[2,1]],"alpha":0.5,"closed":false}"#;
    assert_eq!(AnyCurve::read(path).unwrap().name(), "path");
    let bad = format!(
        r#"{{"points":{:?},"max_segments":1,"alpha":1,"alpha_range":[0,1]}}"#,
        points()
    );
    assert_eq!(AnyCurve::read(&bad).unwrap_err().kind, "invalid_input");
}
