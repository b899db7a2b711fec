//! Orthogonal-distance least squares over a chain's numbers: Levenberg–Marquardt on the
//! points' distances to the chain, each point's foot (nearest point of the chain) found
//! again at every evaluation, with equality constraints (a closed chain's end on its start,
//! a pinned end) moving by the KKT system of each step.
//!
//! A point's residual is its distance along the chain's normal at its foot, whose
//! derivative in any number is the normal component of how the foot moves (the foot's own
//! slide along the chain is second order). A point whose foot is an open chain's end also
//! has the tangential component, which pulls the end onto the data's end. Weights: the
//! caller's, times Huber's (1, or δ/|r| beyond δ) when a robust loss is asked, recomputed
//! at every step (iteratively reweighted least squares).

use crate::foundation::numeric::Complex;

use super::law::{INFLECTION_ALPHA_MAX, INFLECTION_ALPHA_MIN};
use super::model::{Chain, Hint, Layout, Sensitivity};

/// How much the damping's floor (twice the last damping whose step was refused) eases at
/// each accepted step: a descent lowers its damping towards the one that failed again
/// slowly, not by tenfold steps that overshoot and are refused four or five times over
/// (the curved valleys of paths with a slope per piece).
const FLOOR_DECAY: f64 = 0.7;

/// The loss applied to each distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Loss {
    Squares,
    /// Huber's loss with this δ (in the normalized units of the problem).
    Huber(f64),
}

/// What the fit is asked to hold besides fitting.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Constraints {
    /// The chain starts here (its start point is not fitted).
    pub(super) start: Option<Complex>,
    /// The chain ends here.
    pub(super) end: Option<Complex>,
    /// Closed: the end point and tangent on the start's, after turning this much.
    pub(super) closed_turn: Option<f64>,
}

/// A least-squares problem: data, weights, loss, the layout of the numbers and their ranges.
pub(super) struct Problem<'a> {
    pub(super) layout: Layout,
    pub(super) data: &'a [Complex],
    pub(super) weights: &'a [f64],
    pub(super) loss: Loss,
    pub(super) alpha_range: (f64, f64),
    /// The longest a piece may grow: beyond the data's ends a chain runs on at no cost, so
    /// that a descent could lengthen it without end.
    pub(super) longest: f64,
    pub(super) constraints: Constraints,
}

/// A chain and how the data lie against it.
#[derive(Clone, Debug)]
pub(super) struct State {
    pub(super) x: Vec<f64>,
    pub(super) chain: Chain,
    /// Each point's foot, as arc length along the chain.
    pub(super) feet: Vec<f64>,
    /// Each point's distance to its foot.
    pub(super) distances: Vec<f64>,
    /// Σ weight × loss(distance).
    pub(super) cost: f64,
    /// Each point against the chain.
    contacts: Vec<Contact>,
}

/// One point against the chain.
#[derive(Clone, Copy, Debug)]
pub(super) struct Contact {
    piece: usize,
    t: f64,
    point: Complex,
    tangent: Complex,
    /// Normal and tangential components of data − foot (the tangential one is zero at a
    /// foot inside the chain, to the foot search's accuracy; the distance is both's, so
    /// that a search that did not converge never reports a point nearer than it is).
    rn: f64,
    rt: f64,
    /// At an open chain's end.
    at_end: bool,
}

fn sub(a: Complex, b: Complex) -> Complex {
    Complex::new(a.re - b.re, a.im - b.im)
}

/// The foot of `d` on the chain near `s` (Newton on (P(s) − d)·T(s) = 0).
fn contact(chain: &Chain, d: Complex, s: &mut f64, hint: &mut Hint, closed: bool) -> Contact {
    let total = chain.length();
    let wrap = |s: f64| {
        if closed {
            s.rem_euclid(total)
        } else {
            s.clamp(0.0, total)
        }
    };
    let mut x = wrap(*s);
    let mut frame = chain.frame(x, hint);
    for _ in 0..12 {
        let (_, _, p, tangent, kappa) = frame;
        let diff = sub(p, d);
        let f = diff.re * tangent.re + diff.im * tangent.im;
        let across = -diff.re * tangent.im + diff.im * tangent.re;
        let slope = 1.0 + kappa * across;
        let newton = slope > 0.2;
        let step = if newton { -f / slope } else { -f };
        let step = step.clamp(-0.1 * total, 0.1 * total);
        // A Newton step this short leaves the distance as it is to rounding (the normal
        // distance changes by about κh²/2 across it): the frame at hand is the foot's.
        if newton && step.abs() <= 1e-9 * total {
            x = wrap(x + step);
            break;
        }
        let next = wrap(x + step);
        let moved = (next - x).abs();
        x = next;
        frame = chain.frame(x, hint);
        // Newton's error after a step of size h is about κh²: below 1e-7 of the length the
        // point just found is the foot to rounding.
        if moved <= 1e-7 * total {
            break;
        }
    }
    *s = x;
    let (piece, t, point, tangent, _) = frame;
    let r = sub(d, point);
    let rn = -r.re * tangent.im + r.im * tangent.re;
    let rt = r.re * tangent.re + r.im * tangent.im;
    let at_end = !closed && (x <= 0.0 || x >= total);
    Contact {
        piece,
        t,
        point,
        tangent,
        rn,
        rt,
        at_end,
    }
}

impl Contact {
    /// The distance of the point to its foot. (The problem's units are the points' extent:
    /// the squares neither overflow nor lose a distance that matters by underflowing, and
    /// hypot's care is not needed where every point of every evaluation calls this.)
    #[inline]
    fn distance(&self) -> f64 {
        (self.rn * self.rn + self.rt * self.rt).sqrt()
    }
}

impl Problem<'_> {
    fn loss(&self, r: f64) -> f64 {
        match self.loss {
            Loss::Squares => r * r,
            Loss::Huber(delta) => {
                if r <= delta {
                    r * r
                } else {
                    2.0 * delta * r - delta * delta
                }
            }
        }
    }

    fn irls_weight(&self, r: f64) -> f64 {
        match self.loss {
            Loss::Huber(delta) if r > delta => delta / r,
            _ => 1.0,
        }
    }

    /// The state of the numbers `x`, the feet found from `feet`; `None` where `x`
    /// describes no chain.
    pub(super) fn state(&self, x: Vec<f64>, feet: &[f64]) -> Option<State> {
        let chain = Chain::new(&self.layout, &x)?;
        let closed = self.layout.closed;
        let mut feet = feet.to_vec();
        let mut distances = Vec::with_capacity(self.data.len());
        let mut contacts = Vec::with_capacity(self.data.len());
        let mut cost = 0.0;
        let mut hint = Hint::default();
        for (k, &d) in self.data.iter().enumerate() {
            let c = contact(&chain, d, &mut feet[k], &mut hint, closed);
            let r = c.distance();
            distances.push(r);
            contacts.push(c);
            cost += self.weights[k] * self.loss(r);
        }
        cost.is_finite().then_some(State {
            x,
            chain,
            feet,
            distances,
            cost,
            contacts,
        })
    }

    /// The constraint values at a state, and their derivatives in every number.
    /// The constraint values alone (closing gap and turn, gap to a pinned end).
    fn constraint_values(&self, state: &State) -> Vec<f64> {
        let chain = &state.chain;
        let (end, theta_end) = chain.end();
        let start = chain.start;
        let mut values = Vec::new();
        if let Some(turn) = self.constraints.closed_turn {
            values.extend([
                end.re - start.re,
                end.im - start.im,
                theta_end - chain.theta0 - turn,
            ]);
        }
        if let Some(p) = self.constraints.end {
            values.extend([end.re - p.re, end.im - p.im]);
        }
        values
    }

    /// The constraint values and their derivatives in every number.
    fn constraints(
        &self,
        state: &State,
        sens: &[[Option<Sensitivity>; 4]],
    ) -> (Vec<f64>, Vec<Vec<f64>>) {
        let np = self.layout.len();
        let chain = &state.chain;
        let (end, _) = chain.end();
        let start = chain.start;
        // ∂E/∂x and ∂θ_end/∂x.
        let mut de = vec![Complex::ZERO; np];
        let mut dtheta = vec![0.0; np];
        de[0] = Complex::new(1.0, 0.0);
        de[1] = Complex::new(0.0, 1.0);
        de[2] = sub(end, start).mul_i();
        dtheta[2] = 1.0;
        for (j, piece_sens) in sens.iter().enumerate() {
            let (ej, _) = chain.pieces[j].end();
            let arm = sub(end, ej).mul_i();
            for (slot, s) in self.layout.slots(j).iter().zip(piece_sens) {
                let (Some(b), Some(s)) = (slot, s) else {
                    continue;
                };
                let (shift, turn) = s.end();
                de[*b] = Complex::new(
                    de[*b].re + shift.re + turn * arm.re,
                    de[*b].im + shift.im + turn * arm.im,
                );
                dtheta[*b] += turn;
            }
        }
        let values = self.constraint_values(state);
        let mut rows = Vec::new();
        if self.constraints.closed_turn.is_some() {
            let mut rx: Vec<f64> = de.iter().map(|d| d.re).collect();
            let mut ry: Vec<f64> = de.iter().map(|d| d.im).collect();
            rx[0] -= 1.0;
            ry[1] -= 1.0;
            let mut rt = dtheta.clone();
            rt[2] -= 1.0;
            rows.extend([rx, ry, rt]);
        }
        if self.constraints.end.is_some() {
            rows.push(de.iter().map(|d| d.re).collect());
            rows.push(de.iter().map(|d| d.im).collect());
        }
        (values, rows)
    }

    /// Which numbers are fitted.
    fn free(&self) -> Vec<usize> {
        let pinned = self.constraints.start.is_some();
        (0..self.layout.len())
            .filter(|&j| !(pinned && j < 2))
            .collect()
    }

    /// The range of the number at index `j` of `x`, where it has one: each α within the
    /// range (and between [`INFLECTION_ALPHA_MIN`] and [`INFLECTION_ALPHA_MAX`] on a piece
    /// through zero curvature, where the range reaches there), each ln length at most
    /// ln [`Problem::longest`].
    fn bounds(&self, x: &[f64], j: usize) -> Option<(f64, f64)> {
        let mut range: Option<(f64, f64)> = None;
        for i in 0..self.layout.n {
            if self.layout.length_slot(i) == j {
                return Some((-30.0, self.longest.ln()));
            }
            if self.layout.alpha_slot(i) != Some(j) {
                continue;
            }
            let (lo, hi) = range.unwrap_or(self.alpha_range);
            let (ka, kb, _, _) = self.layout.piece(x, i);
            let inflects = !(ka != 0.0 && kb != 0.0 && ka.signum() == kb.signum());
            range = Some(
                if inflects && hi >= INFLECTION_ALPHA_MIN && lo <= INFLECTION_ALPHA_MAX {
                    (INFLECTION_ALPHA_MIN.max(lo), INFLECTION_ALPHA_MAX.min(hi))
                } else {
                    (lo, hi)
                },
            );
        }
        range
    }

    /// Keep the numbers in range (see [`Problem::bounds`]), and the start's angle within a
    /// turn of zero.
    fn clamp(&self, x: &mut [f64]) {
        // The start's tangent angle within a turn of zero: a step that turned it by many
        // turns (geometrically nothing) would leave its sine and cosine rounded to 1e-3.
        x[2] -= std::f64::consts::TAU * (x[2] / std::f64::consts::TAU).round();
        for j in 3..x.len() {
            if let Some((lo, hi)) = self.bounds(x, j) {
                x[j] = x[j].clamp(lo, hi);
            }
        }
    }

    /// Whether a step `d` of the number at index `j` would leave its range from its bound.
    fn leaves_range(&self, x: &[f64], j: usize, d: f64) -> bool {
        self.bounds(x, j)
            .is_some_and(|(lo, hi)| (x[j] <= lo && d < 0.0) || (x[j] >= hi && d > 0.0))
    }

    /// Normal equations (JᵀWJ, JᵀWr) over all numbers at `state`, and the sensitivities.
    ///
    /// A number of piece j moves every point after piece j rigidly, so that the row of a
    /// point on piece c, for every number but c's own, is a fixed combination of three of the
    /// point's features f = (ν_x, ν_y, ν·iX), ν the normal at its foot X: −(u_b·f), u_b summed
    /// over the pieces before c. The points of each piece are therefore gathered into the
    /// moments of f and of their own rows (3 + 4 numbers a point), and the equations
    /// assembled piece by piece: a point costs a few dozen products, not the square of the
    /// numbers. The points at an open chain's end (a tangential residual too) are added one
    /// by one ([`Problem::normal_equations_by_point`]).
    fn normal_equations(
        &self,
        state: &State,
    ) -> (Vec<f64>, Vec<f64>, Vec<[Option<Sensitivity>; 4]>) {
        let np = self.layout.len();
        let n = self.layout.n;
        let chain = &state.chain;
        let sens: Vec<_> = (0..n)
            .map(|i| chain.sensitivities(&self.layout, &state.x, i))
            .collect();
        let ends = self.end_moves(&sens);
        let (mut a, mut g) = self.normal_equations_by_point(state, &sens, &ends, true);
        let mut moments = vec![Moments::default(); n];
        for (k, c) in state.contacts.iter().enumerate() {
            if c.at_end {
                continue;
            }
            let w = self.weights[k] * self.irls_weight(c.distance());
            if w == 0.0 {
                continue;
            }
            let nu = c.tangent.mul_i();
            let f = [nu.re, nu.im, nu.im * c.point.re - nu.re * c.point.im];
            let mut own = [0.0; 4];
            let table = &chain.pieces[c.piece];
            let place = table.locate(c.t);
            for (q, s) in sens[c.piece].iter().enumerate() {
                if let Some(s) = s {
                    let shift = s.shift_at(table, place);
                    own[q] = nu.re * shift.re + nu.im * shift.im;
                }
            }
            moments[c.piece].add(w, f, own, c.rn);
        }
        // The rigid coefficients u_b of every number for the points of the piece at hand:
        // the start's pose first, then each piece's end moves as the chain is walked.
        let mut u = vec![[0.0f64; 3]; np];
        let start = chain.start;
        u[0] = [1.0, 0.0, 0.0];
        u[1] = [0.0, 1.0, 0.0];
        u[2] = [start.im, -start.re, 1.0];
        let mut moving: Vec<usize> = vec![0, 1, 2];
        let dot = |x: [f64; 3], y: [f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        for (c, m) in moments.iter().enumerate() {
            if m.points > 0 {
                for &p in &moving {
                    let uf = [dot(u[p], m.ff[0]), dot(u[p], m.ff[1]), dot(u[p], m.ff[2])];
                    g[p] -= dot(u[p], m.fr);
                    for &q in &moving {
                        a[p * np + q] += dot(uf, u[q]);
                    }
                }
                let slots = self.layout.slots(c);
                for q in 0..4 {
                    let (Some(bq), Some(_)) = (slots[q], &sens[c][q]) else {
                        continue;
                    };
                    g[bq] -= m.or[q];
                    for &p in &moving {
                        let v = dot(u[p], [m.fo[0][q], m.fo[1][q], m.fo[2][q]]);
                        a[p * np + bq] += v;
                        a[bq * np + p] += v;
                    }
                    for r in 0..4 {
                        if let (Some(br), Some(_)) = (slots[r], &sens[c][r]) {
                            a[bq * np + br] += m.oo[q][r];
                        }
                    }
                }
            }
            let (e, _) = chain.pieces[c].end();
            for &(b, shift, turn) in &ends[c] {
                u[b][0] += shift.re + turn * e.im;
                u[b][1] += shift.im - turn * e.re;
                u[b][2] += turn;
                if !moving.contains(&b) {
                    moving.push(b);
                }
            }
        }
        (a, g, sens)
    }

    /// Each piece's end shift and turn per number.
    fn end_moves(&self, sens: &[[Option<Sensitivity>; 4]]) -> Vec<Vec<(usize, Complex, f64)>> {
        sens.iter()
            .enumerate()
            .map(|(j, s)| {
                self.layout
                    .slots(j)
                    .iter()
                    .zip(s)
                    .filter_map(|(slot, s)| {
                        let (shift, turn) = s.as_ref()?.end();
                        Some(((*slot)?, shift, turn))
                    })
                    .collect()
            })
            .collect()
    }

    /// The normal equations point by point (each point's row over every number): for the
    /// points at an open chain's end, or (`only_ends` false) for all, as a reference.
    fn normal_equations_by_point(
        &self,
        state: &State,
        sens: &[[Option<Sensitivity>; 4]],
        ends: &[Vec<(usize, Complex, f64)>],
        only_ends: bool,
    ) -> (Vec<f64>, Vec<f64>) {
        let np = self.layout.len();
        let chain = &state.chain;
        let mut a = vec![0.0; np * np];
        let mut g = vec![0.0; np];
        let mut dn = vec![0.0; np];
        let mut dt = vec![0.0; np];
        let mut touched: Vec<usize> = Vec::with_capacity(np);
        for (k, c) in state.contacts.iter().enumerate() {
            if only_ends && !c.at_end {
                continue;
            }
            let w = self.weights[k] * self.irls_weight(c.distance());
            if w == 0.0 {
                continue;
            }
            let tangent = c.tangent;
            let normal = tangent.mul_i();
            touched.clear();
            let mut add = |b: usize, dp: Complex, dn: &mut [f64], dt: &mut [f64]| {
                if dn[b] == 0.0 && dt[b] == 0.0 {
                    touched.push(b);
                }
                dn[b] -= normal.re * dp.re + normal.im * dp.im;
                dt[b] -= tangent.re * dp.re + tangent.im * dp.im;
            };
            add(0, Complex::new(1.0, 0.0), &mut dn, &mut dt);
            add(1, Complex::new(0.0, 1.0), &mut dn, &mut dt);
            add(2, sub(c.point, chain.start).mul_i(), &mut dn, &mut dt);
            for (j, end_moves) in ends.iter().enumerate().take(c.piece) {
                let (ej, _) = chain.pieces[j].end();
                let arm = sub(c.point, ej).mul_i();
                for &(b, shift, turn) in end_moves {
                    let dp = Complex::new(shift.re + turn * arm.re, shift.im + turn * arm.im);
                    add(b, dp, &mut dn, &mut dt);
                }
            }
            let table = &chain.pieces[c.piece];
            let place = table.locate(c.t);
            for (slot, s) in self.layout.slots(c.piece).iter().zip(&sens[c.piece]) {
                if let (Some(b), Some(s)) = (slot, s) {
                    add(*b, s.shift_at(table, place), &mut dn, &mut dt);
                }
            }
            for (ii, &p) in touched.iter().enumerate() {
                let (np_, tp) = (dn[p], dt[p]);
                g[p] += w * (np_ * c.rn + if c.at_end { tp * c.rt } else { 0.0 });
                for &q in &touched[..=ii] {
                    let v = w * (np_ * dn[q] + if c.at_end { tp * dt[q] } else { 0.0 });
                    a[p * np + q] += v;
                    if p != q {
                        a[q * np + p] += v;
                    }
                }
            }
            for &p in touched.iter() {
                dn[p] = 0.0;
                dt[p] = 0.0;
            }
        }
        (a, g)
    }

    /// The share of the cost below which a step's foretold decrease ends the descent. For
    /// coarse tables (see [`Layout::coarse`]), the floor of their accuracy; for fine ones, a
    /// thousandth of one point's share of the cost (noise of deviation σ on N points costs
    /// about Nσ², and a change of σ² in the cost moves the numbers by about their standard
    /// error: a thousandth of it is nothing the data can tell), but no less than 1e-9
    /// (rounding) nor more than 1e-6.
    fn settled(&self) -> f64 {
        if self.layout.coarse {
            1e-6
        } else {
            (1e-3 / self.data.len() as f64).clamp(1e-9, 1e-6)
        }
    }

    /// The share of the cost below which a refused step's foretold decrease ends the
    /// descent: ten times [`Problem::settled`], a hundred for coarse tables.
    fn refused_settles(&self) -> f64 {
        if self.layout.coarse {
            100.0 * self.settled()
        } else {
            10.0 * self.settled()
        }
    }

    /// The share of the cost that four steps must gain for the descent to go on.
    fn crawl(&self) -> f64 {
        if self.layout.coarse {
            1e-3
        } else {
            1e-4
        }
    }

    /// Whether the constraints hold at `state` (to rounding).
    fn constraints_hold(&self, state: &State) -> bool {
        self.constraint_values(state)
            .iter()
            .all(|v| v.abs() <= 1e-14)
    }

    /// Levenberg–Marquardt from `state` for at most `iterations` steps; the best state seen.
    pub(super) fn minimize(&self, state: State, iterations: usize) -> State {
        self.descend(state, iterations, 1e-3)
    }

    /// [`Problem::minimize`] from a state near the minimum (another sampling's answer): the
    /// damping starts low (1e-5, not 1e-3: the first steps nearly Gauss–Newton's; from 1e-8
    /// an overshooting first step was refused seven times on every point before it was
    /// damped enough).
    pub(super) fn polish(&self, state: State, iterations: usize) -> State {
        self.descend(state, iterations, 1e-5)
    }

    /// Levenberg–Marquardt from `state`, the damping starting at `lambda`.
    fn descend(&self, mut state: State, iterations: usize, mut lambda: f64) -> State {
        let free = self.free();
        let np = self.layout.len();
        let mut merit_weight = 0.0;
        let mut raise = 2.0;
        let mut floor: f64 = 0.0;
        // The costs after the last accepted steps, for the crawl test.
        let mut recent: Vec<f64> = Vec::with_capacity(iterations);
        for _ in 0..iterations {
            // A descent that crawls (a long, curved, nearly flat valley: the slope of a
            // piece that bends evenly) is ended: what it would still gain is below what the
            // fit can tell.
            if let [.., before, _, _, _, now] = recent[..] {
                if before - now <= self.crawl() * now && self.constraints_hold(&state) {
                    return state;
                }
            }
            let (a, g, sens) = self.normal_equations(&state);
            let (c, crow) = self.constraints(&state, &sens);
            let nc = c.len();

            let violation = |c: &[f64]| c.iter().map(|v| v.abs()).sum::<f64>();
            let merit = |s: &State, c: &[f64], mw: f64| s.cost + mw * violation(c);
            let mut improved = false;
            // The damped KKT system over the numbers `moving` (the free ones off their bounds).
            let solve = |moving: &[usize], lambda: f64| -> Option<Vec<f64>> {
                let nf = moving.len();
                let n = nf + nc;
                let mut m = vec![0.0; n * n];
                let mut rhs = vec![0.0; n];
                for (ii, &p) in moving.iter().enumerate() {
                    for (jj, &q) in moving.iter().enumerate() {
                        m[ii * n + jj] = a[p * np + q];
                    }
                    let diag = a[p * np + p];
                    m[ii * n + ii] += lambda * diag.max(1e-12) + 1e-300;
                    rhs[ii] = -g[p];
                    for (ci, row) in crow.iter().enumerate() {
                        m[ii * n + nf + ci] = row[p];
                        m[(nf + ci) * n + ii] = row[p];
                    }
                }
                for (ci, v) in c.iter().enumerate() {
                    rhs[nf + ci] = -v;
                }
                // g was Jᵀr with r = data − foot and J = ∂r/∂x: the step solves
                // (JᵀJ + λD) δ = −Jᵀr.
                solve_dense(&mut m, &mut rhs, n)
            };
            while lambda < 1e12 {
                // A number on its bound that the step would take beyond it is moving there
                // (the step of the rest solved again): clamped afterwards, the step would
                // not be the one the model foretold, and the descent would crawl along
                // the bound.
                let mut moving = free.clone();
                let sol = loop {
                    let Some(sol) = solve(&moving, lambda) else {
                        break None;
                    };
                    let before = moving.len();
                    let mut ii = 0;
                    moving.retain(|&p| {
                        ii += 1;
                        !self.leaves_range(&state.x, p, sol[ii - 1])
                    });
                    if moving.len() == before {
                        break Some(sol);
                    }
                };
                let Some(sol) = sol else {
                    lambda *= 10.0;
                    continue;
                };
                let nf = moving.len();
                if nc > 0 {
                    let mu = sol[nf..].iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    merit_weight = f64::max(merit_weight, 2.0 * mu + 1e-12);
                }
                // The decrease the linear model predicts, 2 gᵀδ + δᵀAδ below the cost: when
                // it is below rounding of the cost and the constraints hold, this is the
                // minimum (a trial would only be rejected, and λ raised, again and again).
                let mut predicted = 0.0;
                for (ii, &p) in moving.iter().enumerate() {
                    let mut ad = 0.0;
                    for (jj, &q) in moving.iter().enumerate() {
                        ad += a[p * np + q] * sol[jj];
                    }
                    predicted -= sol[ii] * (2.0 * g[p] + ad);
                }
                if predicted <= self.settled() * state.cost && violation(&c) <= 1e-14 {
                    return state;
                }
                let mut x = state.x.clone();
                for (ii, &p) in moving.iter().enumerate() {
                    x[p] += sol[ii];
                }
                self.clamp(&mut x);
                let before = merit(&state, &c, merit_weight);
                if let Some(trial) = self.state(x, &state.feet) {
                    let tc = self.constraint_values(&trial);
                    let after = merit(&trial, &tc, merit_weight);
                    if after < before {
                        let gain = (before - after) / before.max(1e-300);
                        let step: f64 = sol[..nf].iter().map(|v| v * v).sum::<f64>().sqrt();
                        // The model's worth ρ (the decrease seen over the decrease foretold)
                        // sets the damping, smoothly (Nielsen's rule): λ times
                        // 1 − (2ρ − 1)³, down to a tenth for a model borne out (the valley
                        // along α is long and flat), up to twice for one barely so; each
                        // refusal in a row raises it twice as much as the one before. (A
                        // stepwise rule, λ/10 or ×4, refused every other step in the
                        // curved valleys of paths with a slope per piece.)
                        let worth = if nc == 0 && predicted > 0.0 {
                            (before - after) / predicted
                        } else {
                            0.5
                        };
                        let factor = (1.0 - (2.0 * worth - 1.0).powi(3)).max(0.1);
                        lambda = (lambda * factor).max(floor).max(1e-12);
                        floor *= FLOOR_DECAY;
                        raise = 2.0;
                        state = trial;
                        recent.push(state.cost);
                        improved = true;
                        if gain < 1e-12 || step < 1e-13 {
                            return state;
                        }
                        break;
                    }
                }
                // A refused step whose foretold gain is this small: the model and the cost
                // part at the floor of what either can tell.
                if predicted <= self.refused_settles() * state.cost && violation(&c) <= 1e-14 {
                    return state;
                }
                floor = floor.max(2.0 * lambda);
                lambda *= raise;
                raise *= 2.0;
            }
            if !improved {
                break;
            }
        }
        state
    }
}

/// The moments of a piece's inner points: their features f (see
/// [`Problem::normal_equations`]), their own rows o and residuals r, weighted.
#[derive(Clone, Copy, Debug, Default)]
struct Moments {
    points: usize,
    ff: [[f64; 3]; 3],
    fo: [[f64; 4]; 3],
    oo: [[f64; 4]; 4],
    fr: [f64; 3],
    or: [f64; 4],
}

impl Moments {
    fn add(&mut self, w: f64, f: [f64; 3], o: [f64; 4], r: f64) {
        self.points += 1;
        for (i, &fi) in f.iter().enumerate() {
            let wf = w * fi;
            for (cell, &fj) in self.ff[i].iter_mut().zip(&f) {
                *cell += wf * fj;
            }
            for (cell, &oj) in self.fo[i].iter_mut().zip(&o) {
                *cell += wf * oj;
            }
            self.fr[i] += wf * r;
        }
        for (i, &oi) in o.iter().enumerate() {
            let wo = w * oi;
            for (cell, &oj) in self.oo[i].iter_mut().zip(&o) {
                *cell += wo * oj;
            }
            self.or[i] += wo * r;
        }
    }
}

/// Solve `m x = rhs` (n × n, row-major) by Gaussian elimination with partial pivoting;
/// `None` when singular.
fn solve_dense(m: &mut [f64], rhs: &mut [f64], n: usize) -> Option<Vec<f64>> {
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| {
            m[i * n + col]
                .abs()
                .partial_cmp(&m[j * n + col].abs())
                .unwrap_or(std::cmp::Ordering::Equal)
        })?;
        if m[pivot * n + col] == 0.0 || m[pivot * n + col].is_nan() {
            return None;
        }
        if pivot != col {
            for k in 0..n {
                m.swap(col * n + k, pivot * n + k);
            }
            rhs.swap(col, pivot);
        }
        let inv = 1.0 / m[col * n + col];
        for row in col + 1..n {
            let f = m[row * n + col] * inv;
            if f == 0.0 {
                continue;
            }
            for k in col..n {
                m[row * n + k] -= f * m[col * n + k];
            }
            rhs[row] -= f * rhs[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let mut v = rhs[row];
        for k in row + 1..n {
            v -= m[row * n + k] * x[k];
        }
        x[row] = v / m[row * n + row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::model::AlphaMode;
    use crate::path::Continuity;

    /// Points near a clothoid-like piece, a little off it (as noisy data are).
    fn data() -> Vec<Complex> {
        let layout = Layout {
            n: 1,
            continuity: Continuity::G2,
            alpha: AlphaMode::Each,
            closed: false,
            coarse: false,
        };
        let x = layout.pack((Complex::ZERO, 0.0), &[(1.0, 3.0, 1.0, -1.0)]);
        let chain = Chain::new(&layout, &x).unwrap();
        (0..200)
            .map(|k| {
                let s = 1.2 * k as f64 / 199.0 - 0.1;
                let (_, _, p, t, _) = chain.frame(s.clamp(0.0, 1.0), &mut Hint::default());
                let off = 1e-3 * ((k * 7919) % 13) as f64 / 13.0 - 5e-4;
                p + t.mul_i().scale(off)
            })
            .collect()
    }

    /// Least squares over `data`, α within −5 … 10, nothing moving.
    fn least_squares<'a>(layout: Layout, data: &'a [Complex], weights: &'a [f64]) -> Problem<'a> {
        Problem {
            layout,
            data,
            weights,
            loss: Loss::Squares,
            alpha_range: (-5.0, 10.0),
            longest: 10.0,
            constraints: Constraints::default(),
        }
    }

    /// The normal equations gathered piece by piece are those summed point by point, for
    /// open, closed and G1 chains of one to four pieces.
    #[test]
    fn gathered_normal_equations_are_the_summed_ones() {
        let data = data();
        let weights: Vec<f64> = (0..data.len()).map(|k| 0.5 + (k % 3) as f64).collect();
        let pieces: [(f64, f64, f64, f64); 4] = [
            (1.1, 1.6, 0.3, 0.5),
            (1.6, 2.2, 0.3, -1.0),
            (2.2, 2.8, 0.3, 2.0),
            (2.8, 2.4, 0.2, 0.0),
        ];
        for (n, continuity, closed, alpha) in [
            (1, Continuity::G2, false, AlphaMode::Each),
            (3, Continuity::G2, false, AlphaMode::Each),
            (4, Continuity::G1, false, AlphaMode::Shared),
            (2, Continuity::G2, true, AlphaMode::Fixed(0.5)),
        ] {
            let layout = Layout {
                n,
                continuity,
                alpha,
                closed,
                coarse: false,
            };
            let problem = least_squares(layout, &data, &weights);
            let x = layout.pack((Complex::new(0.01, -0.02), 0.05), &pieces[..n]);
            let feet: Vec<f64> = (0..data.len()).map(|k| k as f64 / 200.0).collect();
            let state = problem.state(x, &feet).unwrap();
            let (a, g, sens) = problem.normal_equations(&state);
            let ends = problem.end_moves(&sens);
            let (a0, g0) = problem.normal_equations_by_point(&state, &sens, &ends, false);
            let scale = a0.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let worst = a
                .iter()
                .zip(&a0)
                .chain(g.iter().zip(&g0))
                .map(|(x, y)| (x - y).abs())
                .fold(0.0f64, f64::max);
            assert!(
                worst <= 1e-12 * scale,
                "{n} pieces, {continuity:?}, closed {closed}: {worst:e} of {scale:e}"
            );
        }
    }

    /// The normal equations' gradient Jᵀr is half the cost's gradient, number by number,
    /// checked by central differences of the cost itself (feet found again each time).
    #[test]
    fn the_gradient_is_the_cost_gradient() {
        let data = data();
        let weights = vec![1.0; data.len()];
        let cases: [&[(f64, f64, f64, f64)]; 4] = [
            &[(1.1, 2.8, 1.05, -1.0)],
            &[(1.1, 2.8, 1.05, 0.5)],
            &[(1.1, 2.8, 1.05, 2.0)],
            // Three pieces: the rigid motion downstream of each.
            &[
                (1.1, 1.6, 0.35, 0.5),
                (1.6, 2.2, 0.35, -1.0),
                (2.2, 2.8, 0.35, 2.0),
            ],
        ];
        for pieces in cases {
            let layout = Layout {
                n: pieces.len(),
                continuity: Continuity::G2,
                alpha: AlphaMode::Each,
                closed: false,
                coarse: false,
            };
            let problem = least_squares(layout, &data, &weights);
            let x = layout.pack((Complex::new(0.01, -0.02), 0.05), pieces);
            let feet: Vec<f64> = (0..data.len()).map(|k| k as f64 / 200.0).collect();
            let state = problem.state(x.clone(), &feet).unwrap();
            let (_, g, _) = problem.normal_equations(&state);
            for j in 0..layout.len() {
                let h = 1e-6 * x[j].abs().max(1e-2);
                let cost = |sign: f64| {
                    let mut y = x.clone();
                    y[j] += sign * h;
                    problem.state(y, &state.feet).unwrap().cost
                };
                let numeric = (cost(1.0) - cost(-1.0)) / (2.0 * h);
                let model = 2.0 * g[j];
                assert!(
                    (model - numeric).abs() <= 1e-5 * numeric.abs().max(1e-6),
                    "{} pieces, number {j}: {model:e} against {numeric:e}",
                    pieces.len()
                );
            }
        }
    }
}
