//! Where a fit starts: the data's tangent angle and curvature along their chord length,
//! smoothed over a window wide enough that noise does not show, and a chain of pieces read
//! off those profiles for any split of the data.
//!
//! The tangent at a point is the direction of the chord between the points w before and w
//! after it (w about a fortieth of the points): for noise of size σ on points h apart it
//! errs by about σ/(w h) instead of σ/h. The curvature is the slope of a straight line
//! fitted to the tangent angles over the same window.

use crate::foundation::numeric::Complex;

use super::law::{inflects_with, Law};
use super::model::{every, spread, AlphaMode};

/// The data's smoothed profiles along their chord length.
#[derive(Clone, Debug)]
pub(super) struct Profile {
    /// Chord length from the first point to each point.
    pub(super) s: Vec<f64>,
    /// Total chord length (a closed set's includes the closing chord).
    pub(super) total: f64,
    /// Smoothed tangent angle at each point, unwrapped.
    pub(super) theta: Vec<f64>,
    /// Smoothed curvature at each point.
    pub(super) kappa: Vec<f64>,
    /// Tangent angle after the whole closed set, where it returns to the first point's
    /// (the first angle plus a whole number of turns).
    pub(super) closed_turn: Option<f64>,
    /// The half-width of the smoothing window, in points.
    pub(super) window: usize,
}

fn sub(a: Complex, b: Complex) -> Complex {
    Complex::new(a.re - b.re, a.im - b.im)
}

/// The most points a profile smooths; more are thinned to about this many (every k-th and
/// the last) and the profile read off them, each point's values interpolated between theirs.
/// (The window, a fortieth of the points, then spans the same share of the curve however
/// many points there are; over all of a million points the smoothing would cost a million
/// times the window.)
const PROFILE_POINTS: usize = 8000;

impl Profile {
    pub(super) fn new(data: &[Complex], closed: bool) -> Profile {
        let n = data.len();
        if n <= PROFILE_POINTS {
            return Profile::of_all(data, closed);
        }
        let k = n.div_ceil(PROFILE_POINTS);
        let indices = every(&(0..n).collect::<Vec<_>>(), k);
        let thin: Vec<Complex> = indices.iter().map(|&i| data[i]).collect();
        let p = Profile::of_all(&thin, closed);
        let spread = |values: &[f64]| spread(&indices, values);
        Profile {
            s: spread(&p.s),
            total: p.total,
            theta: spread(&p.theta),
            kappa: spread(&p.kappa),
            closed_turn: p.closed_turn,
            window: p.window * k,
        }
    }

    /// The profile smoothed over every point.
    fn of_all(data: &[Complex], closed: bool) -> Profile {
        let n = data.len();
        let mut s = Vec::with_capacity(n);
        let mut acc = 0.0;
        for k in 0..n {
            if k > 0 {
                acc += sub(data[k], data[k - 1]).norm();
            }
            s.push(acc);
        }
        let total = if closed {
            acc + sub(data[0], data[n - 1]).norm()
        } else {
            acc
        };
        let w = (n / 40).clamp(1, 200).min((n.saturating_sub(3) / 2).max(1));
        let at = |k: isize| -> (Complex, f64) {
            if closed {
                let m = k.rem_euclid(n as isize) as usize;
                let laps = k.div_euclid(n as isize) as f64;
                (data[m], s[m] + laps * total)
            } else {
                let m = k.clamp(0, n as isize - 1) as usize;
                (data[m], s[m])
            }
        };
        // Tangent angles where the window is whole: every point of a closed set, the points
        // at least w from either end of an open one.
        let (lo, hi) = if closed {
            (0, n as isize - 1)
        } else {
            (w as isize, n as isize - 1 - w as isize)
        };
        let (lo, hi) = if lo <= hi {
            (lo, hi)
        } else {
            (n as isize / 2, n as isize / 2)
        };
        let mut raw: Vec<(f64, f64)> = Vec::with_capacity((hi - lo + 1) as usize);
        for k in lo..=hi {
            let mut width = w as isize;
            let dir = loop {
                let (a, _) = at(k - width);
                let (b, _) = at(k + width);
                let d = sub(b, a);
                if d.norm() > 0.0 || width as usize >= n {
                    break d.arg();
                }
                width *= 2;
            };
            raw.push((at(k).1, dir));
        }
        // Unwrap.
        for k in 1..raw.len() {
            raw[k].1 = raw[k - 1].1 + principal(raw[k].1 - raw[k - 1].1);
        }
        let closed_turn = closed.then(|| {
            let (first, last) = (raw[0].1, raw[raw.len() - 1].1);
            let turned = last + principal(first - last) - first;
            std::f64::consts::TAU * (turned / std::f64::consts::TAU).round()
        });
        let turn_after = closed_turn.unwrap_or(0.0);
        let count = raw.len() as isize;
        // The raw angle at index j of `raw` (wrapping round a closed set).
        let raw_at = |j: isize| -> (f64, f64) {
            if closed {
                let m = j.rem_euclid(count) as usize;
                let laps = j.div_euclid(count) as f64;
                (raw[m].0 + laps * total, raw[m].1 + laps * turn_after)
            } else {
                raw[j.clamp(0, count - 1) as usize]
            }
        };
        // At every few points (a tenth of the window apart, the rest interpolated between
        // them), a quadratic in arc length fitted to the 2w + 1 nearest raw angles
        // (one-sided near an open end, where it extrapolates): its value and slope.
        let indices = every(&(0..n).collect::<Vec<_>>(), (w / 10).max(1));
        let mut theta = Vec::with_capacity(indices.len());
        let mut kappa = Vec::with_capacity(indices.len());
        for &k in &indices {
            let k = k as isize;
            let centre = k - lo;
            let (a, b) = if closed {
                (centre - w as isize, centre + w as isize)
            } else {
                let a = (centre - w as isize).clamp(0, (count - 1 - 2 * w as isize).max(0));
                (a, (a + 2 * w as isize).min(count - 1))
            };
            let sk = at(k).1;
            let mut m = [[0.0f64; 3]; 3];
            let mut v = [0.0f64; 3];
            for j in a..=b {
                let (sj, tj) = raw_at(j);
                let x = sj - sk;
                let pw = [1.0, x, x * x];
                for r in 0..3 {
                    for c in 0..3 {
                        m[r][c] += pw[r] * pw[c];
                    }
                    v[r] += pw[r] * tj;
                }
            }
            let (t, slope) = quadratic_value_and_slope(m, v)
                .or_else(|| Some((raw_at(centre.clamp(0, count - 1)).1, 0.0)))
                .unwrap();
            theta.push(t);
            kappa.push(if slope.is_finite() { slope } else { 0.0 });
        }
        Profile {
            s,
            total,
            theta: spread(&indices, &theta),
            kappa: spread(&indices, &kappa),
            closed_turn,
            window: w,
        }
    }

    /// The chord lengths where the smoothed curvature turns from rising to falling or back
    /// (by more than a fifth of its whole range): where one log-aesthetic segment,
    /// whose curvature is monotone, must end and the next begin.
    pub(super) fn curvature_extrema(&self) -> Vec<f64> {
        let (lo, hi) = self
            .kappa
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &k| {
                (a.min(k), b.max(k))
            });
        let band = 0.2 * (hi - lo);
        if band.is_nan() || band <= 0.0 {
            return Vec::new();
        }
        let mut cuts = Vec::new();
        // The running extreme since the last turn, and the direction (+1 rising).
        let (mut ext, mut at, mut dir) = (self.kappa[0], 0usize, 0.0f64);
        for (k, &v) in self.kappa.iter().enumerate() {
            if dir >= 0.0 && v > ext || dir <= 0.0 && v < ext {
                if dir == 0.0 && (v - self.kappa[0]).abs() > band {
                    dir = (v - self.kappa[0]).signum();
                }
                ext = v;
                at = k;
            } else if (ext - v) * dir.signum() > band && dir != 0.0 {
                cuts.push(self.s[at]);
                dir = -dir;
                ext = v;
                at = k;
            }
        }
        // Not within a window of an open end (where the curvature is extrapolated), nor
        // within a window of each other.
        let n = self.s.len();
        let margin = self.total * (self.window as f64 * 2.0 + 1.0) / n as f64;
        let end = self.s[n - 1];
        cuts.retain(|&c| c > margin && c < end - margin);
        let mut kept: Vec<f64> = Vec::with_capacity(cuts.len());
        for c in cuts {
            if kept.last().is_none_or(|&k| c - k > margin) {
                kept.push(c);
            }
        }
        kept
    }

    /// The smoothed curvature at chord length `x`, interpolated.
    pub(super) fn kappa_at(&self, x: f64) -> f64 {
        interpolate(&self.s, &self.kappa, x)
    }

    /// The smoothed tangent angle at chord length `x`, interpolated.
    pub(super) fn theta_at(&self, x: f64) -> f64 {
        interpolate(&self.s, &self.theta, x)
    }
}

/// Solve the 3 × 3 normal equations of a quadratic fit: its value and slope at 0 (the
/// slope 0 and a straight fit when the points do not fix a curvature).
fn quadratic_value_and_slope(m: [[f64; 3]; 3], v: [f64; 3]) -> Option<(f64, f64)> {
    let det3 = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det3(m);
    let scale = m[0][0] * m[1][1] * m[2][2];
    if d.abs() > 1e-12 * scale.abs() && d.is_finite() {
        let mut m0 = m;
        let mut m1 = m;
        for r in 0..3 {
            m0[r][0] = v[r];
            m1[r][1] = v[r];
        }
        return Some((det3(m0) / d, det3(m1) / d));
    }
    // A straight line.
    let d2 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if d2.abs() > 0.0 && d2.is_finite() {
        let a = (v[0] * m[1][1] - m[0][1] * v[1]) / d2;
        let b = (m[0][0] * v[1] - m[1][0] * v[0]) / d2;
        return Some((a, b));
    }
    (m[0][0] > 0.0).then(|| (v[0] / m[0][0], 0.0))
}

/// An angle difference brought into [−π, π].
fn principal(d: f64) -> f64 {
    d - std::f64::consts::TAU * (d / std::f64::consts::TAU).round()
}

fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let k = xs.partition_point(|&v| v <= x);
    if k == 0 {
        return ys[0];
    }
    if k >= xs.len() {
        return ys[xs.len() - 1];
    }
    let (x0, x1) = (xs[k - 1], xs[k]);
    let u = if x1 > x0 { (x - x0) / (x1 - x0) } else { 0.0 };
    ys[k - 1] + u * (ys[k] - ys[k - 1])
}

/// The slopes tried for a first guess.
const ALPHA_GRID: [f64; 15] = [
    -3.0, -2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0,
];

/// The pieces (κ_a, κ_b, length, α) of a first chain with joints at the chord lengths
/// `cuts` (ascending, inside the data), read off the profile.
pub(super) fn pieces(
    profile: &Profile,
    cuts: &[f64],
    alpha: AlphaMode,
    range: (f64, f64),
) -> Vec<(f64, f64, f64, f64)> {
    let mut bounds = vec![0.0];
    bounds.extend_from_slice(cuts);
    bounds.push(profile.total);
    let scale = 1.0 / profile.total.max(f64::MIN_POSITIVE);
    let mut out = Vec::with_capacity(bounds.len() - 1);
    for w in bounds.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = (b - a).max(1e-9 * profile.total);
        let mut ka = profile.kappa_at(a);
        let mut kb = profile.kappa_at(b);
        // Never exactly zero, never so small that the law's powers underflow.
        let floor = 1e-6 * scale;
        for k in [&mut ka, &mut kb] {
            if k.abs() < floor {
                *k = floor.copysign(if *k == 0.0 { 1.0 } else { *k });
            }
        }
        let samples: Vec<(f64, f64)> = (1..16)
            .map(|j| {
                let t = j as f64 / 16.0;
                (t, profile.kappa_at(a + t * len))
            })
            .collect();
        let candidates: Vec<f64> = match alpha {
            AlphaMode::Fixed(v) => vec![v],
            _ => ALPHA_GRID
                .iter()
                .copied()
                .chain([range.0, range.1])
                .filter(|v| *v >= range.0 && *v <= range.1)
                .collect(),
        };
        let opposite = ka.signum() != kb.signum();
        let mut best = (f64::INFINITY, candidates[0]);
        for &alpha in &candidates {
            if opposite && !inflects_with(alpha) && alpha != candidates[0] {
                continue;
            }
            let Some(law) = Law::new(ka, kb, len, alpha) else {
                continue;
            };
            let err: f64 = samples
                .iter()
                .map(|&(t, k)| (law.at(t).1 - k).powi(2))
                .sum();
            if err < best.0 {
                best = (err, alpha);
            }
        }
        let mut alpha_guess = best.1;
        if !best.0.is_finite() {
            // No law with these ends in the range (opposite signs and α ≥ 0): start from the
            // circle of the piece's mean curvature (its turning over its length), which
            // every α has.
            let mean = (profile.theta_at(b) - profile.theta_at(a)) / len;
            let mean = if mean.abs() < floor {
                floor.copysign(if mean == 0.0 { 1.0 } else { mean })
            } else {
                mean
            };
            (ka, kb) = (mean, mean);
            alpha_guess = candidates[candidates.len() / 2];
        }
        out.push((ka, kb, len, alpha_guess));
    }
    out
}
