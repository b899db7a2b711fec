//! Instruction-count probe (not committed): solves a fixed set, for callgrind.
use kurbo::Point;
use lac::{CompoundCurve, Segment};
fn main() {
    let what = std::env::args().nth(1).unwrap();
    let mut x = 0.123f64;
    let mut rnd = || {
        x = (x * 9301.0 + 49297.0) % 233280.0;
        x / 233280.0
    };
    let mut n = 0;
    for _ in 0..4000 {
        let p = [
            Point::new(-1.0, 0.0),
            Point::new(2.0 * rnd() - 1.0, rnd()),
            Point::new(1.0, 0.0),
        ];
        let r = 0.2 + 0.6 * rnd();
        match what.as_str() {
            "seg" => {
                for a in [-1.0, 0.0, 0.5, 1.0, 2.0] {
                    if Segment::from_control_points(p, a).is_ok() {
                        n += 1;
                    }
                }
            }
            "samples" => {
                for a in [-1.0, 0.0, 0.5, 1.0, 2.0] {
                    if let Ok(s) = Segment::from_control_points(p, a) {
                        n += 1;
                        std::hint::black_box(s.sample_by_arc_length(65).unwrap());
                    }
                }
            }
            _ => {
                for (a0, a1) in [(-1.0, 2.0), (2.0, -1.0), (0.5, 1.0), (-0.5, -0.5)] {
                    if CompoundCurve::from_three_points(p, a0, a1, r).is_ok() {
                        n += 1;
                    }
                }
            }
        }
    }
    eprintln!("N {n}");
}
