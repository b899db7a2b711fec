//! A first μ for a single clothoid piece (α = −1), from a table of the solutions.
//!
//! The chord angle φ of the standard-form clothoid piece turning by θd grows with μ from
//! θd/2 (the circle, μ = 0) towards a limit φmax(θd) (the far end at the inflection, μ → ∞),
//! which it approaches like e^{−μ}. So with r = (θe − θd/2)/(φmax − θd/2) ∈ [0, 1), the
//! solution is μ = m(θd, r) − ln(1 − r) with m smooth on [0, 1] in r (m → 0 at the circle,
//! a finite limit at r = 1). [`table`] holds φmax and m on a grid of θd and r, made by this
//! crate's own solver (`LAC_WRITE_GUESS_TABLE=1 cargo test -p lac --release guess_table`);
//! cubic interpolation there gives μ within 4.3e-4 (relative) up to r = 1 − 1e-4 (μ ≈ 10),
//! 2e-2 beyond, where the model of the circle is 10% off beyond μ ≈ 1. Newton's method
//! takes it from there, so the table affects only how many evaluations a solve takes (2.2
//! instead of 3.5 on average over the 20,000 configurations of
//! `tools/bench_vs_clothoids.py`: most guesses are within 1e-9 and need one Newton step),
//! not the accuracy of its answer (the same convergence and residual tests end every
//! solve).

pub(super) mod table;

use table::{M, NR, NT, PHI_MAX};

/// The table's range of turning angles: from the clothoid path's smallest to just below π.
const TURN_MIN: f64 = 0.05;
const TURN_MAX: f64 = std::f64::consts::PI - 1e-3;

/// θd at grid column `i`.
#[cfg(test)]
pub(super) fn turn_at(i: usize) -> f64 {
    TURN_MIN + (TURN_MAX - TURN_MIN) * i as f64 / (NT - 1) as f64
}

/// r at grid row `j` (the last row is r = 1, the limit).
#[cfg(test)]
pub(super) fn ratio_at(j: usize) -> f64 {
    j as f64 / (NR - 1) as f64
}

/// The weights of 4-point Lagrange interpolation at `x` (in grid units, on a grid of `n`
/// nodes), and the first of the four nodes.
fn stencil(x: f64, n: usize) -> (usize, [f64; 4]) {
    let k = (x.floor() as isize - 1).clamp(0, n as isize - 4) as usize;
    let t = x - k as f64;
    let (a, b, c, d) = (t, t - 1.0, t - 2.0, t - 3.0);
    (
        k,
        [
            -b * c * d / 6.0,
            a * c * d / 2.0,
            -a * b * d / 2.0,
            a * b * c / 6.0,
        ],
    )
}

/// The first μ for the clothoid piece turning by `theta_d` whose chord angle is `theta_e`,
/// or `None` outside the table (or where it would not be a number).
pub(super) fn clothoid(theta_d: f64, theta_e: f64) -> Option<f64> {
    if !(TURN_MIN..=TURN_MAX).contains(&theta_d) {
        return None;
    }
    let x = (theta_d - TURN_MIN) / (TURN_MAX - TURN_MIN) * (NT - 1) as f64;
    let (i, wx) = stencil(x, NT);
    let phi_max: f64 = (0..4).map(|a| wx[a] * PHI_MAX[i + a]).sum();
    let half = 0.5 * theta_d;
    let r = (theta_e - half) / (phi_max - half);
    if !(0.0..1.0).contains(&r) {
        return None;
    }
    let (j, wy) = stencil(r * (NR - 1) as f64, NR);
    let m: f64 = (0..4)
        .map(|a| wx[a] * (0..4).map(|b| wy[b] * M[i + a][j + b]).sum::<f64>())
        .sum();
    let mu = m - (-r).ln_1p();
    (mu.is_finite() && mu > 0.0).then_some(mu)
}
