//! A chain of log-aesthetic pieces as a fit sees it: a vector of numbers (start pose, the
//! curvature at every joint, the pieces' lengths and slopes) and the chain they describe,
//! tabulated for fast evaluation and differentiation.
//!
//! The chain is G2 by construction: neighbouring pieces share the curvature of their joint
//! (G1 chains carry a curvature on each side). Each piece follows [`Law`]; its points are
//! the integral of e^{iθ} by 4-point Gauss–Legendre over stations that each turn by at most
//! [`STATION_TURN`], and between stations a quintic Hermite interpolant (points, tangents
//! and curvatures at both ends) places any point to about STATION_TURN⁶/46080 of a station's
//! length (1e-13 of it).
//!
//! Derivatives for the solver: a piece's own numbers change its shape (tabulated by forward
//! differences at its stations) and move everything after it rigidly, by its end's shift
//! δE and turn δθ: a point X downstream moves by δE + δθ · i(X − E).

use crate::foundation::gauss::{GAUSS_2, GAUSS_4};
use crate::foundation::numeric::Complex;
use crate::path::Continuity;

use super::law::{inflects_with, Law};

/// Largest turning of one station interval, radians.
const STATION_TURN: f64 = 0.05;

/// Largest turning of one piece of a chain, radians.
const MAX_PIECE_TURN: f64 = 2.0 * std::f64::consts::TAU;

/// The shortest station interval, as a share of the piece.
const SHORTEST_STATION: f64 = 1e-6;

/// Most station intervals of one piece.
const MAX_STATIONS: usize = 4000;

/// How the slopes of the pieces are chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum AlphaMode {
    /// Given, not fitted.
    Fixed(f64),
    /// One slope for every piece, fitted.
    Shared,
    /// A slope per piece, fitted.
    Each,
}

/// Where each number of a chain lives in the parameter vector.
#[derive(Clone, Copy, Debug)]
pub(super) struct Layout {
    /// Pieces.
    pub(super) n: usize,
    pub(super) continuity: Continuity,
    pub(super) alpha: AlphaMode,
    pub(super) closed: bool,
    /// Tabulate at stations [`COARSE`] times as far apart: for a search that looks for a
    /// valley, not its floor (about 1e-9 of a station's length instead of 1e-13).
    pub(super) coarse: bool,
}

/// How much farther apart a coarse table's stations are.
const COARSE: usize = 4;

/// The parameter indices of one piece's numbers: start and end curvature, ln length, α.
pub(super) type Slots = [Option<usize>; 4];

impl Layout {
    fn curvatures(&self) -> usize {
        match (self.continuity, self.closed) {
            (Continuity::G2, false) => self.n + 1,
            (Continuity::G2, true) => self.n,
            (Continuity::G1, _) => 2 * self.n,
        }
    }

    fn first_length(&self) -> usize {
        3 + self.curvatures()
    }

    fn first_alpha(&self) -> usize {
        self.first_length() + self.n
    }

    /// Length of the parameter vector.
    pub(super) fn len(&self) -> usize {
        self.first_alpha()
            + match self.alpha {
                AlphaMode::Fixed(_) => 0,
                AlphaMode::Shared => 1,
                AlphaMode::Each => self.n,
            }
    }

    /// Parameter indices of piece `i`'s curvatures, ln length and α.
    pub(super) fn slots(&self, i: usize) -> Slots {
        let (ka, kb) = match self.continuity {
            Continuity::G2 => (
                3 + i,
                3 + if self.closed { (i + 1) % self.n } else { i + 1 },
            ),
            Continuity::G1 => (3 + 2 * i, 4 + 2 * i),
        };
        let alpha = match self.alpha {
            AlphaMode::Fixed(_) => None,
            AlphaMode::Shared => Some(self.first_alpha()),
            AlphaMode::Each => Some(self.first_alpha() + i),
        };
        [Some(ka), Some(kb), Some(self.first_length() + i), alpha]
    }

    /// Piece `i`'s (κ_a, κ_b, length, α).
    pub(super) fn piece(&self, x: &[f64], i: usize) -> (f64, f64, f64, f64) {
        let [ka, kb, ln_len, alpha] = self.slots(i);
        let alpha = match (alpha, self.alpha) {
            (Some(j), _) => x[j],
            (None, AlphaMode::Fixed(a)) => a,
            (None, _) => unreachable!("a fitted slope has a slot"),
        };
        (
            x[ka.unwrap()],
            x[kb.unwrap()],
            x[ln_len.unwrap()].exp(),
            alpha,
        )
    }

    /// The index of α for piece `i`, if fitted.
    pub(super) fn alpha_slot(&self, i: usize) -> Option<usize> {
        self.slots(i)[3]
    }

    /// The index of piece `i`'s ln length.
    pub(super) fn length_slot(&self, i: usize) -> usize {
        self.first_length() + i
    }

    /// The parameter vector of a chain whose pieces have these numbers (`pieces[i]` =
    /// (κ_a, κ_b, length, α); a shared α is the first piece's).
    pub(super) fn pack(&self, start: (Complex, f64), pieces: &[(f64, f64, f64, f64)]) -> Vec<f64> {
        let mut x = vec![0.0; self.len()];
        x[0] = start.0.re;
        x[1] = start.0.im;
        x[2] = start.1;
        for (i, &(ka, kb, len, alpha)) in pieces.iter().enumerate() {
            let [sa, sb, sl, salpha] = self.slots(i);
            x[sa.unwrap()] = ka;
            x[sb.unwrap()] = kb;
            x[sl.unwrap()] = len.ln();
            if let Some(j) = salpha {
                x[j] = alpha;
            }
        }
        // A joint shared by two pieces keeps the later piece's start curvature; make it the
        // mean of both sides.
        if self.continuity == Continuity::G2 {
            for i in 1..pieces.len() {
                x[3 + i] = 0.5 * (pieces[i - 1].1 + pieces[i].0);
            }
            if self.closed && !pieces.is_empty() {
                x[3] = 0.5 * (pieces[pieces.len() - 1].1 + pieces[0].0);
            }
        }
        x
    }
}

/// Every `k`-th item and the last.
pub(super) fn every<T: Copy>(items: &[T], k: usize) -> Vec<T> {
    let mut out: Vec<T> = items.iter().step_by(k).copied().collect();
    if (items.len() - 1) % k != 0 {
        out.extend(items.last());
    }
    out
}

/// Values at every index from `values` at the increasing `indices` (the first 0, the last
/// the last index), by linear interpolation in the index: the inverse of [`every`].
pub(super) fn spread(indices: &[usize], values: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(indices.last().map_or(0, |i| i + 1));
    for (w, v) in indices.windows(2).zip(values.windows(2)) {
        for i in w[0]..w[1] {
            out.push(v[0] + (v[1] - v[0]) * (i - w[0]) as f64 / (w[1] - w[0]) as f64);
        }
    }
    out.extend(values.last());
    out
}

/// One piece tabulated at stations t_0 = 0 < t_1 < … < t_m = 1, placed so that each
/// interval turns by at most [`STATION_TURN`] and the curvature changes across it by at most
/// [`STATION_CHANGE`] of itself (a log-aesthetic piece's curvature can change fastest near
/// one end, where equal steps would leave the interpolant short of its accuracy).
#[derive(Clone, Debug)]
pub(super) struct Table {
    pub(super) law: Law,
    pub(super) len: f64,
    pub(super) ts: Vec<f64>,
    pub(super) points: Vec<Complex>,
    pub(super) thetas: Vec<f64>,
    pub(super) kappas: Vec<f64>,
    /// Unit tangents at the stations.
    pub(super) tangents: Vec<Complex>,
    /// The quintic Hermite interpolant of each station interval in powers of u ∈ [0, 1]:
    /// P(u) = P_j + c₁u + c₂u² + … + c₅u⁵ (see [`Table::frame`]).
    pub(super) coefficients: Vec<[Complex; 5]>,
}

/// The power coefficients c₁…c₅ of the quintic Hermite interpolant on u ∈ [0, 1] from
/// P(0) = `a`, P(1) = `b`, P'(0) = `c`, P'(1) = `d`, P''(0) = `e`, P''(1) = `f` (derivatives
/// in u): the Hermite basis functions expanded, with b − a in place of each ±(b, a) pair.
fn quintic(a: Complex, b: Complex, c: Complex, d: Complex, e: Complex, f: Complex) -> [Complex; 5] {
    let delta = b - a;
    let mix = |k: [f64; 5]| {
        Complex::new(
            k[0] * delta.re + k[1] * c.re + k[2] * d.re + k[3] * e.re + k[4] * f.re,
            k[0] * delta.im + k[1] * c.im + k[2] * d.im + k[3] * e.im + k[4] * f.im,
        )
    };
    [
        c,
        e.scale(0.5),
        mix([10.0, -6.0, -4.0, -1.5, 0.5]),
        mix([-15.0, 8.0, 7.0, 1.5, -1.0]),
        mix([6.0, -3.0, -3.0, -0.5, 0.5]),
    ]
}

/// Largest relative change of curvature across one station interval.
const STATION_CHANGE: f64 = 0.05;

/// The stations of a piece; see [`Table`].
fn stations(law: &Law, len: f64) -> Option<Vec<f64>> {
    let mut ts = vec![0.0];
    let mut t = 0.0;
    let largest = law.curvature(0.0).0.abs().max(law.curvature(1.0).0.abs());
    // Near zero curvature the relative change means nothing: a piece that reaches zero is
    // held to its change relative to a thousandth of its largest curvature there. (One whose
    // curvature keeps its sign, up to a ratio of 1e6, is held to its own all along.)
    let reaches_zero = !law.keeps_sign();
    let bound = |t: f64| {
        let (k, slope) = law.curvature(t);
        let floor = if reaches_zero {
            k.abs().max(1e-3 * largest)
        } else {
            k.abs()
        };
        let by_turn = STATION_TURN / (floor * len);
        // The curvature's higher derivatives are larger than its first by a factor |α|
        // more than the first is by itself (κ ∝ (1 + te)^(−1/α): each derivative brings
        // a factor (1/α + j)), and they bound the interpolant's error: the change per
        // station is held to STATION_CHANGE / |α| for |α| > 1.
        let by_change = STATION_CHANGE * floor / (slope.abs() * law.alpha().abs().max(1.0));
        (by_turn.min(by_change).min(0.25), k)
    };
    // The shortest station interval: the steps of a law that changes fast near one end
    // grow geometrically from there (a few hundred stations in all), and at a point of
    // zero curvature, where the relative change means nothing, they are not shorter.
    let shortest = SHORTEST_STATION;
    // Each step bounded where it starts and, once, where it would land.
    let (mut h, _) = bound(0.0);
    while t < 1.0 {
        let (there, k) = bound((t + h).min(1.0));
        let wanted = h.min(there);
        // A piece whose curvature changes faster than the most stations can follow (a
        // curl of a radius far below the piece's length) away from zero curvature (where
        // the relative change means nothing) cannot be tabulated to its accuracy.
        if wanted < shortest && k.abs() > 1e-2 * largest {
            return None;
        }
        let step = wanted.max(shortest);
        t = if t + step > 1.0 - 1e-3 * step {
            1.0
        } else {
            t + step
        };
        ts.push(t);
        h = there;
        if ts.len() > MAX_STATIONS + 1 {
            return None;
        }
    }
    Some(ts)
}

impl Table {
    /// The piece with `law` and length `len` from `start` with tangent angle `theta0`, at
    /// stations chosen from the law (`coarse`: see [`Layout::coarse`]).
    fn new(law: Law, len: f64, start: Complex, theta0: f64, coarse: bool) -> Option<Table> {
        // Coarse tables keep every few of the fine stations: they refuse exactly the
        // pieces the fine ones do, so that no search finds an answer the fine tables
        // cannot follow.
        let ts = stations(&law, len)?;
        let ts = if coarse { every(&ts, COARSE) } else { ts };
        let m = ts.len() - 1;
        let mut points = Vec::with_capacity(m + 1);
        let mut thetas = Vec::with_capacity(m + 1);
        let mut kappas = Vec::with_capacity(m + 1);
        let mut p = start;
        for j in 0..=m {
            let t = ts[j];
            let (turn, kappa) = law.at(t);
            points.push(p);
            thetas.push(theta0 + turn);
            kappas.push(kappa);
            if j == m {
                break;
            }
            let half = 0.5 * (ts[j + 1] - t);
            let mid = t + half;
            let mut sum = Complex::ZERO;
            for &(x, w) in GAUSS_4.iter() {
                for u in [mid - x * half, mid + x * half] {
                    let c = Complex::cis(theta0 + law.at(u).0);
                    sum = Complex::new(sum.re + w * c.re, sum.im + w * c.im);
                }
            }
            let k = len * half;
            p = Complex::new(p.re + k * sum.re, p.im + k * sum.im);
        }
        let ok = p.re.is_finite() && p.im.is_finite() && thetas.iter().all(|t| t.is_finite());
        let tangents: Vec<Complex> = thetas.iter().map(|&a| Complex::cis(a)).collect();
        let coefficients = (0..m)
            .map(|j| {
                let h = len * (ts[j + 1] - ts[j]);
                let (t0, t1) = (tangents[j], tangents[j + 1]);
                quintic(
                    points[j],
                    points[j + 1],
                    t0.scale(h),
                    t1.scale(h),
                    t0.mul_i().scale(h * h * kappas[j]),
                    t1.mul_i().scale(h * h * kappas[j + 1]),
                )
            })
            .collect();
        ok.then_some(Table {
            law,
            len,
            ts,
            points,
            thetas,
            kappas,
            tangents,
            coefficients,
        })
    }

    /// The end point and tangent angle.
    pub(super) fn end(&self) -> (Complex, f64) {
        (*self.points.last().unwrap(), *self.thetas.last().unwrap())
    }

    /// The station interval of the share `t` and the position u ∈ [0, 1] in it.
    #[inline]
    pub(super) fn locate(&self, t: f64) -> (usize, f64) {
        self.locate_near(t, usize::MAX)
    }

    /// [`Table::locate`], looking first in the interval `near` (where the last search
    /// of a nearby share ended).
    #[inline]
    fn locate_near(&self, t: f64, near: usize) -> (usize, f64) {
        let m = self.ts.len() - 1;
        let t = t.clamp(0.0, 1.0);
        let j = if near < m && self.ts[near] <= t && t <= self.ts[near + 1] {
            near
        } else {
            self.ts.partition_point(|&v| v <= t).clamp(1, m) - 1
        };
        let width = self.ts[j + 1] - self.ts[j];
        (j, ((t - self.ts[j]) / width).clamp(0.0, 1.0))
    }

    /// Point, tangent angle and curvature at the share `t` ∈ [0, 1] (the angle and the
    /// curvature from the law itself).
    #[inline]
    pub(super) fn at(&self, t: f64) -> (Complex, f64, f64) {
        let mut anywhere = usize::MAX;
        let (point, _, _) = self.frame(t, &mut anywhere);
        let (turn, kappa) = self.law.at(t.clamp(0.0, 1.0));
        (point, self.thetas[0] + turn, kappa)
    }
}

impl Table {
    /// Point, unit tangent and (interpolated) curvature at the share `t`: the tangent from
    /// the interpolant's own derivative, so that no transcendental function is evaluated
    /// (the foot search calls this for every point at every step). The search for the
    /// station interval starts at `station`, and leaves there the one found.
    #[inline]
    pub(super) fn frame(&self, t: f64, station: &mut usize) -> (Complex, Complex, f64) {
        let (j, u) = self.locate_near(t, *station);
        *station = j;
        let [c1, c2, c3, c4, c5] = self.coefficients[j];
        let p0 = self.points[j];
        let (k0, k1) = (self.kappas[j], self.kappas[j + 1]);
        // Horner's rule for the point and its derivative in u.
        let re = p0.re + u * (c1.re + u * (c2.re + u * (c3.re + u * (c4.re + u * c5.re))));
        let im = p0.im + u * (c1.im + u * (c2.im + u * (c3.im + u * (c4.im + u * c5.im))));
        let dre =
            c1.re + u * (2.0 * c2.re + u * (3.0 * c3.re + u * (4.0 * c4.re + u * 5.0 * c5.re)));
        let dim =
            c1.im + u * (2.0 * c2.im + u * (3.0 * c3.im + u * (4.0 * c4.im + u * 5.0 * c5.im)));
        // The speed is of the order of the station's length: its square neither overflows
        // nor underflows, and hypot's care is not needed where every foot search calls it.
        let speed = (dre * dre + dim * dim).sqrt();
        let tangent = if speed > 0.0 {
            Complex::new(dre / speed, dim / speed)
        } else {
            self.tangents[j]
        };
        (Complex::new(re, im), tangent, k0 + u * (k1 - k0))
    }
}

/// How one of a piece's numbers moves the piece: its stations' shifts and turns per unit
/// change of the number, to first order.
#[derive(Clone, Debug)]
pub(super) struct Sensitivity {
    pub(super) points: Vec<Complex>,
    pub(super) thetas: Vec<f64>,
    /// The shifts' derivatives along the piece, d(δP)/dt.
    pub(super) slopes: Vec<Complex>,
}

impl Sensitivity {
    /// Shift at the place `(j, u)` of `table` (see [`Table::locate`]: one search for all of
    /// a point's numbers), by cubic Hermite interpolation between stations (the
    /// conditioning of α against the end curvatures asks for more than a straight line).
    #[inline]
    pub(super) fn shift_at(&self, table: &Table, (j, u): (usize, f64)) -> Complex {
        let width = table.ts[j + 1] - table.ts[j];
        let (a, b) = (self.points[j], self.points[j + 1]);
        let (da, db) = (self.slopes[j], self.slopes[j + 1]);
        let (u2, u3) = (u * u, u * u * u);
        let h00 = 1.0 - 3.0 * u2 + 2.0 * u3;
        let h10 = (u - 2.0 * u2 + u3) * width;
        let h01 = 1.0 - h00;
        let h11 = (u3 - u2) * width;
        Complex::new(
            h00 * a.re + h01 * b.re + h10 * da.re + h11 * db.re,
            h00 * a.im + h01 * b.im + h10 * da.im + h11 * db.im,
        )
    }

    /// Shift and turn of the piece's end.
    pub(super) fn end(&self) -> (Complex, f64) {
        (*self.points.last().unwrap(), *self.thetas.last().unwrap())
    }
}

/// Where a search along a chain last ended (a piece, a station interval in it), where the
/// next search of a nearby arc length starts.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Hint {
    piece: usize,
    station: usize,
}

/// A chain tabulated from a parameter vector.
#[derive(Clone, Debug)]
pub(super) struct Chain {
    pub(super) start: Complex,
    pub(super) theta0: f64,
    pub(super) pieces: Vec<Table>,
    /// Arc length where each piece starts, and the total at the end.
    pub(super) starts: Vec<f64>,
    /// The pieces' numbers (κ_a, κ_b, length, α).
    pub(super) numbers: Vec<(f64, f64, f64, f64)>,
}

impl Chain {
    /// The chain of `x`, or `None` where a piece has no log-aesthetic law or a number
    /// overflows.
    pub(super) fn new(layout: &Layout, x: &[f64]) -> Option<Chain> {
        let mut start = Complex::new(x[0], x[1]);
        let mut theta = x[2];
        let (chain_start, theta0) = (start, theta);
        let mut pieces = Vec::with_capacity(layout.n);
        let mut starts = Vec::with_capacity(layout.n + 1);
        let mut numbers = Vec::with_capacity(layout.n);
        let mut s = 0.0;
        for i in 0..layout.n {
            let (ka, kb, len, alpha) = layout.piece(x, i);
            let law = Law::new(ka, kb, len, alpha)?;
            // A fit has no use for a piece that winds round more than once (a solver step
            // that makes one is refused); a piece that turns by π or more is placed as
            // several segments.
            // Nor for end curvatures a million apart (no segment places such a piece's points
            // to the accuracy it is checked to).
            let ratio = (kb / ka).abs();
            let one_sign = ka != 0.0 && kb != 0.0 && ka.signum() == kb.signum();
            if one_sign && !(1e-6..=1e6).contains(&ratio) {
                return None;
            }
            // Nor for a piece through zero curvature whose halves cannot reach it.
            if !one_sign && !inflects_with(alpha) {
                return None;
            }
            let turn = law.at(1.0).0.abs();
            if turn.is_nan() || turn >= MAX_PIECE_TURN {
                return None;
            }
            let table = Table::new(law, len, start, theta, layout.coarse)?;
            (start, theta) = table.end();
            starts.push(s);
            s += len;
            pieces.push(table);
            numbers.push((ka, kb, len, alpha));
        }
        starts.push(s);
        s.is_finite().then_some(Chain {
            start: chain_start,
            theta0,
            pieces,
            starts,
            numbers,
        })
    }

    /// Total arc length.
    pub(super) fn length(&self) -> f64 {
        *self.starts.last().unwrap()
    }

    /// The piece and share of the arc length `s` (clamped to the chain).
    #[inline]
    pub(super) fn locate(&self, s: f64, hint: usize) -> (usize, f64) {
        let n = self.pieces.len();
        let mut i = hint.min(n - 1);
        while i > 0 && s < self.starts[i] {
            i -= 1;
        }
        while i + 1 < n && s >= self.starts[i + 1] {
            i += 1;
        }
        let t = (s - self.starts[i]) / self.pieces[i].len;
        (i, t.clamp(0.0, 1.0))
    }

    /// Point, unit tangent and curvature at arc length `s` (see [`Table::frame`]), the
    /// search starting from `hint` and leaving there where it ended.
    #[inline]
    pub(super) fn frame(&self, s: f64, hint: &mut Hint) -> (usize, f64, Complex, Complex, f64) {
        let (i, t) = self.locate(s, hint.piece);
        if i != hint.piece {
            *hint = Hint {
                piece: i,
                station: usize::MAX,
            };
        }
        let (p, tangent, kappa) = self.pieces[i].frame(t, &mut hint.station);
        (i, t, p, tangent, kappa)
    }

    /// End point and tangent angle of the chain.
    pub(super) fn end(&self) -> (Complex, f64) {
        self.pieces.last().unwrap().end()
    }

    /// The sensitivities of piece `i` to each of its four numbers (`None` for a number
    /// that is not fitted), holding its start. A number turns the tangent by δθ(t) (for
    /// ln L, the turning itself, which is proportional to the length; for κ_a, κ_b and α a
    /// central difference of the law, cheap and exact to h²) and moves the points by
    /// δP(t) = iL ∫₀ᵗ e^{iθ} δθ dτ (plus P(t) − P(0) for ln L), integrated over the
    /// table's stations by the 2-point Gauss rule (exact to about 1e-9 of the shift over
    /// stations that turn by 0.05: a derivative for the solver's steps, not a point of the
    /// answer) with each node's e^{iθ} evaluated once for every number.
    pub(super) fn sensitivities(
        &self,
        layout: &Layout,
        x: &[f64],
        i: usize,
    ) -> [Option<Sensitivity>; 4] {
        let table = &self.pieces[i];
        let slots = layout.slots(i);
        let (ka, kb, len, alpha) = self.numbers[i];
        // Central differences: α is poorly conditioned against the end curvatures, and a
        // forward difference's error (≈ h) stalls the solver at distances near 1e-10. A
        // coarse table's search, which looks for a valley and not its floor, takes forward
        // differences (four laws evaluated at each node, not seven).
        let central = !layout.coarse;
        let mut moved: [Option<(Law, Option<Law>, f64)>; 4] = [None; 4];
        for k in [0, 1, 3] {
            let Some(j) = slots[k] else { continue };
            let h = 1e-5 * x[j].abs().max(1e-2);
            let law = |step: f64| {
                let mut numbers = [ka, kb, len, alpha];
                numbers[k] += step;
                Law::new(numbers[0], numbers[1], len, numbers[3])
            };
            moved[k] = match (law(h), central) {
                (Some(up), false) => Some((up, None, 1.0 / h)),
                (Some(up), true) => law(-h).map(|down| (up, Some(down), 0.5 / h)),
                (None, _) => None,
            };
        }
        let active: Vec<usize> = (0..4)
            .filter(|&k| slots[k].is_some() && (k == 2 || moved[k].is_some()))
            .collect();
        let turn_of = |k: usize, t: f64, turn: f64| match moved[k] {
            Some((up, Some(down), inv)) => (up.at(t).0 - down.at(t).0) * inv,
            Some((up, None, inv)) => (up.at(t).0 - turn) * inv,
            None => turn,
        };
        let m = table.ts.len() - 1;
        let mut points: [Vec<Complex>; 4] = Default::default();
        let mut thetas: [Vec<f64>; 4] = Default::default();
        let mut sums = [Complex::ZERO; 4];
        let theta0 = table.thetas[0];
        for j in 0..=m {
            let t = table.ts[j];
            let turn = table.thetas[j] - theta0;
            for &k in &active {
                thetas[k].push(turn_of(k, t, turn));
                // iL ∫ e^{iθ} δθ, and for ln L the shift P − P(0) the longer piece adds.
                let mut p = sums[k].mul_i();
                if k == 2 {
                    p += table.points[j] - table.points[0];
                }
                points[k].push(p);
            }
            if j == m {
                break;
            }
            let half = 0.5 * (table.ts[j + 1] - t);
            let mid = t + half;
            let scale = len * half;
            for &(node, w) in GAUSS_2.iter() {
                for u in [mid - node * half, mid + node * half] {
                    let turn = table.law.at(u).0;
                    let c = Complex::cis(theta0 + turn).scale(w * scale);
                    for &k in &active {
                        sums[k] += c.scale(turn_of(k, u, turn));
                    }
                }
            }
        }
        let mut out: [Option<Sensitivity>; 4] = [None, None, None, None];
        for k in active {
            let thetas = std::mem::take(&mut thetas[k]);
            // d(δP)/dt = L·iT·δθ (+ L·T for ln L, whose unit change scales the length by e).
            let along = if k == 2 { len } else { 0.0 };
            let slopes = table
                .tangents
                .iter()
                .zip(&thetas)
                .map(|(tangent, dtheta)| {
                    Complex::new(
                        along * tangent.re - len * dtheta * tangent.im,
                        along * tangent.im + len * dtheta * tangent.re,
                    )
                })
                .collect();
            out[k] = Some(Sensitivity {
                points: std::mem::take(&mut points[k]),
                thetas,
                slopes,
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tables against the segments of the same numbers (the segment module's own
    /// evaluation, checked against mpmath elsewhere), across α and curvature ratios: the
    /// points between stations to 1e-11 of the length (the quintic interpolant's error at
    /// stations that turn by 0.05 is about 1e-12 of it). A slope of 9 whose curvature
    /// halves was 1e-9 off between stations before the change per station was held to
    /// 1/|α| of its share: its higher derivatives outgrow its first.
    #[test]
    fn tables_agree_with_segments_between_stations() {
        use crate::curve::Curve;
        use crate::segment::Segment;
        use kurbo::Point;
        let cases = [
            (1.0, 3.0, 1.0, -1.0),
            (0.55, 0.238, 1.5, 8.96),
            (2.0, 1.5, 1.0, 20.0),
            (1.0, 4.0, 0.8, -5.0),
            (3.0, 1.0, 0.8, 0.0),
            (1.0, 1.5, 2.0, 2.0),
            // A ratio of 3e4 at α = 1: 1e-8 off at its flat end while the change per station
            // was measured against a thousandth of the largest curvature there.
            (263.6, 0.00917, 0.837, 1.0),
            (-3.0097003358782537, -2.0, 1.2, 5.31812856974461),
        ];
        for (ka, kb, len, alpha) in cases {
            let law = Law::new(ka, kb, len, alpha).unwrap();
            let table = Table::new(law, len, Complex::ZERO, 0.0, false).unwrap();
            let segment =
                Segment::from_curvatures(Point::ORIGIN, 0.0, [ka, kb], len, alpha).unwrap();
            let mut worst: f64 = 0.0;
            for j in 0..=200 {
                let t = j as f64 / 200.0;
                let (p, _, _) = table.at(t);
                let q = segment.point_at_s(t * len).unwrap();
                let d = (p.re - q.x).hypot(p.im - q.y);
                worst = worst.max(d / len);
            }
            eprintln!(
                "κ {ka}→{kb}, α {alpha}: {worst:e} stations {}",
                table.ts.len()
            );
            assert!(worst < 1e-11, "κ {ka}→{kb}, α {alpha}: {worst:e}");
        }
    }

    /// A piece through zero curvature against the two segments of its halves (as a fit
    /// places it), for slopes across the window an S may have: the interpolant near the
    /// inflection, where the curvature's second (α > −1) or first (α < −1) derivative is
    /// singular, to 1e-11 of the length.
    #[test]
    fn s_pieces_agree_with_their_halves() {
        use crate::curve::Curve;
        use crate::segment::Segment;
        use kurbo::Point;
        let cases = [
            (2.0, -3.0, 1.3, -0.5),
            (2.0, -3.0, 1.3, -0.56),
            (2.0, -3.0, 1.3, -0.75),
            (2.0, -3.0, 1.3, -1.0),
            (2.0, -3.0, 1.3, -1.3),
            (2.0, -3.0, 1.3, -1.5),
            (-0.9738, 6.649, 1.774, -0.5575),
        ];
        for (ka, kb, len, alpha) in cases {
            let law = Law::new(ka, kb, len, alpha).unwrap();
            let table = Table::new(law, len, Complex::ZERO, 0.0, false).unwrap();
            let inflection = law.inflection().unwrap();
            let eta = 1e-12;
            let mut worst: f64 = 0.0;
            // (The second half up to where it has turned by less than π.)
            let rising_end = inflection + 0.8 * (1.0 - inflection);
            for (a, b) in [(0.0, inflection - eta), (inflection + eta, rising_end)] {
                let (p, theta, _) = table.at(a);
                let start = Point::new(p.re, p.im);
                let kappas = [law.at(a).1, law.at(b).1];
                let half =
                    Segment::from_curvatures(start, theta, kappas, (b - a) * len, alpha).unwrap();
                for j in 0..=200 {
                    let t = a + (b - a) * j as f64 / 200.0;
                    let (p, _, _) = table.at(t);
                    let q = half.point_at_s((t - a) * len).unwrap();
                    worst = worst.max((p.re - q.x).hypot(p.im - q.y) / len);
                }
            }
            eprintln!("S, α {alpha}: {worst:e} stations {}", table.ts.len());
            assert!(worst < 1e-11, "S, α {alpha}: {worst:e}");
        }
    }

    /// The tabulated clothoid against its closed form (Fresnel integrals by a fine sum).
    #[test]
    fn stations_and_interpolation_place_points_to_1e_12() {
        let law = Law::new(0.5, 6.0, 1.2, -1.0).unwrap();
        let table = Table::new(law, 1.2, Complex::ZERO, 0.3, false).unwrap();
        // Reference: composite Simpson with 200,000 panels of the exact tangent angle.
        let reference = |t_end: f64| {
            let n = 200_000;
            let h = t_end / n as f64;
            let mut sum = Complex::ZERO;
            for i in 0..n {
                let t = i as f64 * h;
                for (u, w) in [(t, 1.0), (t + 0.5 * h, 4.0), (t + h, 1.0)] {
                    let c = Complex::cis(0.3 + law.at(u).0);
                    sum = Complex::new(sum.re + w * c.re, sum.im + w * c.im);
                }
            }
            Complex::new(sum.re * 1.2 * h / 6.0, sum.im * 1.2 * h / 6.0)
        };
        for t in [0.0, 0.137, 0.5, 0.861, 1.0] {
            let (p, theta, kappa) = table.at(t);
            let q = reference(t);
            let d = ((p.re - q.re).powi(2) + (p.im - q.im).powi(2)).sqrt();
            assert!(d < 1e-12, "t = {t}: {d:e}");
            let (turn, k) = law.at(t);
            assert!((theta - 0.3 - turn).abs() < 1e-9, "t = {t}");
            assert!((kappa - k).abs() < 1e-2 * k.abs(), "t = {t}");
        }
    }
}
