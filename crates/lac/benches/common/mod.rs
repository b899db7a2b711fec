//! Shared by the benchmarks: a small deterministic generator, so the benchmark sets never
//! change between runs or machines, and a timer that reports medians.

use std::time::{Duration, Instant};

/// SplitMix64.
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    /// A uniform number in [0, 1).
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Time each call on its own and report the median over the calls, i.e. over the
/// configurations of the set, as criterion's time per iteration (a group that cycles through
/// the set inside `iter` reports the mean instead). Includes ~20 ns of `Instant::now` per call.
#[allow(dead_code)] // not every benchmark reports medians
pub(crate) fn median_per_call<T>(iters: u64, set: &[T], mut f: impl FnMut(&T)) -> Duration {
    let mut times: Vec<Duration> = (0..iters as usize)
        .map(|k| {
            let start = Instant::now();
            f(&set[k % set.len()]);
            start.elapsed()
        })
        .collect();
    times.sort_unstable();
    times[times.len() / 2] * iters as u32
}
#[allow(dead_code)] // the benchmark `spline` and the tests use it
pub(crate) mod glyphs;
