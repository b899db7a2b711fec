//! probe2 (not committed)
use kurbo::Point;
use std::time::Instant;
fn main() {
    let v: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().unwrap())
        .collect();
    let p = [
        Point::new(-1.0, 0.0),
        Point::new(v[1], v[2]),
        Point::new(1.0, 0.0),
    ];
    for _ in 0..3 {
        let t = Instant::now();
        for _ in 0..200 {
            let s = lac::Segment::from_control_points(p, v[0]).unwrap();
            std::hint::black_box(s.sample_by_arc_length(65).unwrap());
        }
        println!(
            "with samples {:.3} us",
            t.elapsed().as_secs_f64() / 200.0 * 1e6
        );
    }
}
