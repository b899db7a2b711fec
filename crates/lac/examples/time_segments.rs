//! Time `Segment::from_control_points` alone on the segments of a `lac segment --batch`
//! input file (one `{"points":[[x,y],[x,y],[x,y]],"alpha":A}` per line), with no I/O or
//! parsing in the timing: the solver's own speed, for `tools/bench_vs_clothoids.py`.
//!
//! ```text
//! cargo run --release -p lac --example time_segments -- FILE [ROUNDS]
//! ```
//!
//! Each round times every configuration once (a loop of `repeat` solves, `repeat` chosen so
//! that a loop lasts about 20 µs, divided by `repeat`); a configuration's time is its median
//! over the rounds, and the line printed is JSON with the median and mean over the
//! configurations, in microseconds, and how many solved.

use std::hint::black_box;
use std::time::Instant;

use kurbo::Point;
use lac::Segment;

#[derive(serde::Deserialize)]
struct Input {
    points: [[f64; 2]; 3],
    alpha: f64,
}

fn main() {
    let mut args = std::env::args().skip(1);
    let Some(path) = args.next() else {
        eprintln!("usage: time_segments FILE [ROUNDS]");
        std::process::exit(2);
    };
    let rounds: usize = args.next().and_then(|r| r.parse().ok()).unwrap_or(5);
    let text = std::fs::read_to_string(&path).expect("read the input file");
    let inputs: Vec<([Point; 3], f64)> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let i: Input = serde_json::from_str(l).expect("a segment input line");
            (i.points.map(|[x, y]| Point::new(x, y)), i.alpha)
        })
        .collect();
    let solved = inputs
        .iter()
        .filter(|(p, a)| Segment::from_control_points(*p, *a).is_ok())
        .count();
    // Calibrate: solves per timed loop so that one loop lasts about 20 µs.
    let start = Instant::now();
    for (p, a) in &inputs {
        let _ = black_box(Segment::from_control_points(black_box(*p), *a));
    }
    let mean_guess = start.elapsed().as_secs_f64() / inputs.len().max(1) as f64;
    let repeat = ((20e-6 / mean_guess.max(1e-9)) as usize).clamp(1, 1000);
    let mut times = vec![Vec::with_capacity(rounds); inputs.len()];
    for _ in 0..rounds {
        for ((p, a), t) in inputs.iter().zip(&mut times) {
            let start = Instant::now();
            for _ in 0..repeat {
                let _ = black_box(Segment::from_control_points(black_box(*p), *a));
            }
            t.push(start.elapsed().as_secs_f64() / repeat as f64);
        }
    }
    let mut per_config: Vec<f64> = times
        .iter_mut()
        .map(|t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
        .collect();
    let mean = per_config.iter().sum::<f64>() / per_config.len().max(1) as f64;
    per_config.sort_by(f64::total_cmp);
    let median = per_config.get(per_config.len() / 2).copied().unwrap_or(0.0);
    println!(
        "{{\"configurations\":{},\"solved\":{solved},\"rounds\":{rounds},\"repeat\":{repeat},\
         \"median_us\":{:.4},\"mean_us\":{:.4}}}",
        inputs.len(),
        median * 1e6,
        mean * 1e6
    );
}
