//! Clipping the evolute to a window around the drawing.
//!
//! The evolute P + N/κ runs off towards infinity where κ → 0 (a segment that ends near an
//! inflection, α < 0) and may hold non-finite points there; it is cut into the runs that lie
//! inside the window, each piece clipped exactly at the window's edge.

use kurbo::{Point, Rect};

/// The parts of the polyline `points` inside `window`, as separate polylines.
pub(crate) fn clip_polyline(points: &[Point], window: Rect) -> Vec<Vec<Point>> {
    let mut runs: Vec<Vec<Point>> = Vec::new();
    let mut run: Vec<Point> = Vec::new();
    for pair in points.windows(2) {
        match clip_segment(pair[0], pair[1], window) {
            Some((a, b)) if run.last() == Some(&a) => run.push(b),
            Some((a, b)) => {
                flush(&mut runs, &mut run);
                run.extend([a, b]);
            }
            None => flush(&mut runs, &mut run),
        }
    }
    flush(&mut runs, &mut run);
    runs
}

fn flush(runs: &mut Vec<Vec<Point>>, run: &mut Vec<Point>) {
    if run.len() >= 2 {
        runs.push(std::mem::take(run));
    } else {
        run.clear();
    }
}

/// Liang–Barsky: the part of segment `a`–`b` inside `window`, if any. An end inside the
/// window is returned unchanged, so consecutive pieces join exactly.
fn clip_segment(a: Point, b: Point, window: Rect) -> Option<(Point, Point)> {
    let d = b - a;
    if !(d.x.is_finite() && d.y.is_finite()) {
        return None;
    }
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    let edges = [
        (-d.x, a.x - window.x0),
        (d.x, window.x1 - a.x),
        (-d.y, a.y - window.y0),
        (d.y, window.y1 - a.y),
    ];
    for (p, q) in edges {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            a + d * t
        }
    };
    Some((at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polyline_leaving_and_reentering_the_window_becomes_two_clipped_runs() {
        let window = Rect::new(0.0, 0.0, 1.0, 1.0);
        let pts = [
            Point::new(0.5, 0.5),
            Point::new(0.5, 3.0),
            Point::new(f64::INFINITY, 0.0),
            Point::new(0.7, 3.0),
            Point::new(0.7, 0.5),
            Point::new(0.8, 0.5),
        ];
        let runs = clip_polyline(&pts, window);
        assert_eq!(
            runs,
            vec![
                vec![Point::new(0.5, 0.5), Point::new(0.5, 1.0)],
                vec![
                    Point::new(0.7, 1.0),
                    Point::new(0.7, 0.5),
                    Point::new(0.8, 0.5)
                ],
            ]
        );
    }
}
