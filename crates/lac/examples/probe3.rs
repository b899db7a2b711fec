//! probe3 (not committed): our α = −1 solve on the Clothoids benchmark's configurations.
use kurbo::Point;
use std::time::Instant;
fn main() {
    let text = std::fs::read_to_string("/tmp/clothoid_cases.jsonl").unwrap();
    let mut times = vec![];
    for line in text.lines() {
        let v: Vec<f64> = line
            .replace(['[', ']', ' '], "")
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        let p = [
            Point::new(v[0], v[1]),
            Point::new(v[2], v[3]),
            Point::new(v[4], v[5]),
        ];
        if lac::Segment::from_control_points(p, -1.0).is_err() {
            continue;
        }
        let mut best = f64::INFINITY;
        for _ in 0..5 {
            let t = Instant::now();
            for _ in 0..200 {
                std::hint::black_box(
                    lac::Segment::from_control_points(std::hint::black_box(p), -1.0).unwrap(),
                );
            }
            best = best.min(t.elapsed().as_secs_f64() / 200.0 * 1e6);
        }
        times.push(best);
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!(
        "{} drawable configurations: median {:.3} us, p90 {:.3} us",
        times.len(),
        times[times.len() / 2],
        times[times.len() * 9 / 10]
    );
}
