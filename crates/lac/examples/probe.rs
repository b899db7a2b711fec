//! probe (not committed)
use kurbo::Point;
use std::time::Instant;
fn main() {
    let alpha: f64 = std::env::args().nth(1).unwrap().parse().unwrap();
    let mut x = 0.123f64;
    let mut times = vec![];
    for _ in 0..1500 {
        x = (x * 9301.0 + 49297.0) % 233280.0;
        let a = x / 233280.0;
        x = (x * 9301.0 + 49297.0) % 233280.0;
        let b = x / 233280.0;
        let p = [
            Point::new(-1.0, 0.0),
            Point::new(2.0 * a - 1.0, b),
            Point::new(1.0, 0.0),
        ];
        let Ok(seg) = lac::Segment::from_control_points(p, alpha) else {
            continue;
        };
        let t = Instant::now();
        for _ in 0..20 {
            let s = lac::Segment::from_control_points(p, alpha).unwrap();
            std::hint::black_box(s.sample_by_arc_length(65).unwrap());
        }
        let k = seg.curvature_start() / seg.curvature_end();
        let el = t.elapsed().as_secs_f64() / 20.0 * 1e6;
        if el > 100.0 {
            println!(
                "slow {el:.1} {:?} lambda {} ln ratio {}",
                p[1],
                seg.lambda(),
                k.abs().ln()
            );
        }
        times.push((el, k.abs().ln().abs()));
    }
    times.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap());
    let n = times.len();
    let mean: f64 = times.iter().map(|t| t.0).sum::<f64>() / n as f64;
    println!("n {n} mean {mean:.2} median {:.2} p75 {:.2} p90 {:.2} max {:.2} (ln ratio at median {:.1}, at p90 {:.1})", times[n/2].0, times[n*3/4].0, times[n*9/10].0, times[n-1].0, times[n/2].1, times[n*9/10].1);
}
