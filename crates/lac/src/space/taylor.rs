//! Taylor-series integration of the Frenet–Serret system.
//!
//! With κ and τ as power laws ([`super::family::PowerLaw`]) every Taylor coefficient of the
//! solution follows from a recurrence: for `x(s0 + h) = Σ x_k hᵏ` and likewise t, n, b,
//!
//! ```text
//! x_(k+1) = t_k / (k+1)
//! t_(k+1) = Σⱼ κⱼ n_(k−j) / (k+1)
//! n_(k+1) = Σⱼ (τⱼ b_(k−j) − κⱼ t_(k−j)) / (k+1)
//! b_(k+1) = −Σⱼ τⱼ n_(k−j) / (k+1)
//! ```
//!
//! A step is as long as the last two terms allow at the [`Accuracy`] asked (Jorba & Zou's
//! rule); near a bound of the valid range the coefficients grow like the inverse distance to
//! it and the steps shrink accordingly. The series is the dense output inside a step.
//!
//! The solver's shots step in σ = ln(1 + Λαs)/(Λα) instead of s wherever Λα ≥ 1e-3 (see
//! [`Expansion::stepping`]): the same recurrence with κ, τ and x′ multiplied by ds/dσ.

use super::family::SpaceForm;
use crate::foundation::gauss::GAUSS_4;
use crate::foundation::vec3::Vec3;

/// Order of the series.
pub(crate) const ORDER: usize = 20;

/// How exactly a step's series must hold: the largest size of each of its last two terms,
/// for unit frame vectors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Accuracy {
    /// To rounding (2e-16): every segment and every converged solve.
    Full,
    /// To 1e-10, with steps about twice as long: the solver's search (scans and Newton
    /// iterations far from a root), whose shots only have to point the way.
    Search,
    /// To 1e-6, with steps about 1.6 times as long as [`Accuracy::Search`]'s: the ν scans,
    /// whose residuals only rank starting points.
    Scan,
}

impl Accuracy {
    /// How closely a shot's crossing of the cone is located, relative to its arc length:
    /// to rounding in full, well below the integration's own error otherwise.
    pub(crate) fn crossing_tolerance(self) -> f64 {
        match self {
            Accuracy::Full => 1e-16,
            Accuracy::Search => 1e-13,
            Accuracy::Scan => 1e-9,
        }
    }

    /// The largest size allowed each of a step's last two terms, for unit frame vectors.
    pub(crate) fn tolerance(self) -> f64 {
        match self {
            Accuracy::Full => 2e-16,
            Accuracy::Search => 1e-10,
            Accuracy::Scan => 1e-6,
        }
    }
}

/// Position and Frenet frame at arc length `s`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct State {
    pub(crate) s: f64,
    pub(crate) x: Vec3,
    pub(crate) t: Vec3,
    pub(crate) n: Vec3,
    pub(crate) b: Vec3,
}

impl State {
    /// The standard form's start: origin, t = +x, n = +y, b = +z.
    pub(crate) fn start() -> State {
        State {
            s: 0.0,
            x: Vec3::ZERO,
            t: Vec3::X,
            n: Vec3::Y,
            b: Vec3::Z,
        }
    }
}

/// The variable a series runs in.
///
/// Where κ has a pole behind the curve (α > 0, Λ > 0: κ ∝ (1 + Λαs)^(−1/α)), a series in s
/// converges only to the pole, so steps grow like the distance to it and a curve whose
/// radius of curvature grows by 10⁴ takes some 40 steps at the search accuracy. In
/// `σ = ln(1 + Λαs)/(Λα)` (the turning angle θ at α = 1) the pole recedes to σ = −∞: ds/dσ
/// is `u = 1 + Λαs = e^(Λασ)` and κ ds/dσ is `u^(1 − 1/α)`, both exponentials, entire, and
/// such a curve takes a few steps. A step in σ costs about a quarter more (x′ = u t is a
/// product too, and τ ds/dσ a composition, [`composed`]); where u stays small the steps are
/// about as long as in s. Segments are evaluated in s, from checkpoints.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Variable {
    /// s itself.
    ArcLength,
    /// σ, with `rate` = Λα > 0 and `u0` = 1 + Λα s0 at the series' start.
    LogRadius { rate: f64, u0: f64 },
}

/// The smallest Λα for which the solver's steps run in σ: below it κ's pole is more than
/// 1,000 behind the start, steps in s reach as far as in σ, and σ's conversions
/// (`ln(1 + Λα Δs)/(Λα)`) would lose digits to underflow as Λα nears the smallest doubles.
const LOG_RADIUS_RATE: f64 = 1e-3;

/// The Taylor series of the solution about one state, in s or in σ (see [`Variable`]): for
/// `v` the variable, `x(v0 + h) = Σ x_k hᵏ` and likewise t, n, b.
#[derive(Clone, Debug)]
pub(crate) struct Expansion {
    pub(crate) s0: f64,
    variable: Variable,
    /// Coefficients of x, t, n, b, order 0..=ORDER.
    pub(crate) x: [Vec3; ORDER + 1],
    pub(crate) t: [Vec3; ORDER + 1],
    pub(crate) n: [Vec3; ORDER + 1],
    pub(crate) b: [Vec3; ORDER + 1],
    /// Coefficients of κ ds/dv, τ ds/dv, ds/dv and s (κ, τ, 1 and s0 + h in s).
    turn: [f64; ORDER + 1],
    twist: [f64; ORDER + 1],
    speed: [f64; ORDER + 1],
    arc: [f64; ORDER + 1],
}

impl Expansion {
    /// The series in s about `state` for the curve `form`.
    pub(crate) fn new(form: &SpaceForm, state: &State) -> Expansion {
        Expansion::in_variable(form, state, Variable::ArcLength)
    }

    /// The series about `state` for a step of the solver's integrations: in σ wherever
    /// Λα ≥ [`LOG_RADIUS_RATE`], in s elsewhere.
    pub(crate) fn stepping(form: &SpaceForm, state: &State) -> Expansion {
        let law = form.kappa_law();
        let rate = law.a * law.e;
        let variable = if rate >= LOG_RADIUS_RATE {
            Variable::LogRadius {
                rate,
                u0: 1.0 + rate * state.s,
            }
        } else {
            Variable::ArcLength
        };
        Expansion::in_variable(form, state, variable)
    }

    fn in_variable(form: &SpaceForm, state: &State, variable: Variable) -> Expansion {
        let zero = [0.0; ORDER + 1];
        let (mut turn, mut twist, mut speed, mut arc) = (zero, zero, zero, zero);
        arc[0] = state.s;
        match variable {
            Variable::ArcLength => {
                form.kappa_law().taylor(state.s, &mut turn);
                form.tau_law().taylor(state.s, &mut twist);
                speed[0] = 1.0;
                arc[1] = 1.0;
            }
            Variable::LogRadius { rate, u0 } => {
                // ds/dσ = u0 e^(rate h); κ ds/dσ = κ0 u0 e^((rate − Λ) h).
                let lambda = form.kappa_law().a;
                let kappa0 = form.kappa_law().value(state.s);
                exponential_series(u0, rate, &mut speed);
                exponential_series(kappa0 * u0, rate - lambda, &mut turn);
                for k in 1..=ORDER {
                    arc[k] = speed[k - 1] / k as f64;
                }
                twist = composed(form.tau_law(), &arc, &speed);
            }
        }
        let vectors = [Vec3::ZERO; ORDER + 1];
        let mut e = Expansion {
            s0: state.s,
            variable,
            x: vectors,
            t: vectors,
            n: vectors,
            b: vectors,
            turn,
            twist,
            speed,
            arc,
        };
        e.x[0] = state.x;
        e.t[0] = state.t;
        e.n[0] = state.n;
        e.b[0] = state.b;
        match variable {
            Variable::ArcLength => e.recur_in_arc_length(),
            Variable::LogRadius { .. } => e.recur_in_log_radius(),
        }
        e
    }

    /// The frame's recurrence in s (x′ = t).
    fn recur_in_arc_length(&mut self) {
        // κ or τ is a polynomial when its slope is −1/m (κ linear for α = −1): its series
        // ends in exact zeros, and the sums below stop at its last nonzero term.
        let (kappa_terms, tau_terms) = (last_nonzero(&self.turn), last_nonzero(&self.twist));
        for k in 0..ORDER {
            let mut dt = Vec3::ZERO;
            let mut dn = Vec3::ZERO;
            let mut db = Vec3::ZERO;
            let both = k.min(kappa_terms).min(tau_terms);
            for j in 0..=both {
                let (kj, tj) = (self.turn[j], self.twist[j]);
                let (t, n, b) = (self.t[k - j], self.n[k - j], self.b[k - j]);
                dt += kj * n;
                dn += tj * b - kj * t;
                db -= tj * n;
            }
            for j in both + 1..=k.min(kappa_terms) {
                let kj = self.turn[j];
                dt += kj * self.n[k - j];
                dn -= kj * self.t[k - j];
            }
            for j in both + 1..=k.min(tau_terms) {
                let tj = self.twist[j];
                dn += tj * self.b[k - j];
                db -= tj * self.n[k - j];
            }
            let inv = 1.0 / (k + 1) as f64;
            self.x[k + 1] = self.t[k] * inv;
            self.t[k + 1] = dt * inv;
            self.n[k + 1] = dn * inv;
            self.b[k + 1] = db * inv;
        }
    }

    /// The frame's recurrence in σ (x′ = t ds/dσ; ds/dσ and τ ds/dσ have every term, κ ds/dσ
    /// only its first at α = 1).
    fn recur_in_log_radius(&mut self) {
        let kappa_terms = last_nonzero(&self.turn);
        for k in 0..ORDER {
            let (mut dx, mut dt, mut dn, mut db) = (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
            for j in 0..=k {
                let (vj, tj) = (self.speed[j], self.twist[j]);
                let (t, n, b) = (self.t[k - j], self.n[k - j], self.b[k - j]);
                dx += vj * t;
                dn += tj * b;
                db -= tj * n;
            }
            for j in 0..=k.min(kappa_terms) {
                let kj = self.turn[j];
                dt += kj * self.n[k - j];
                dn -= kj * self.t[k - j];
            }
            let inv = 1.0 / (k + 1) as f64;
            self.x[k + 1] = dx * inv;
            self.t[k + 1] = dt * inv;
            self.n[k + 1] = dn * inv;
            self.b[k + 1] = db * inv;
        }
    }

    /// The longest step whose last two terms stay within the tolerance of `accuracy` (in
    /// σ, the position's terms too, per unit of ds/dσ).
    pub(crate) fn step_size(&self, accuracy: Accuracy) -> f64 {
        let position = match self.variable {
            Variable::ArcLength => 0.0,
            Variable::LogRadius { u0, .. } => 1.0 / u0,
        };
        let size = |k: usize| {
            [self.t[k], self.n[k], self.b[k], self.x[k] * position]
                .iter()
                .flat_map(|v| v.to_array())
                .fold(0.0f64, |m, c| m.max(c.abs()))
        };
        let tolerance = accuracy.tolerance();
        let h1 = (tolerance / size(ORDER - 1)).powf(1.0 / (ORDER - 1) as f64);
        let h2 = (tolerance / size(ORDER)).powf(1.0 / ORDER as f64);
        // Both infinite only when κ and τ vanish identically, which they never do.
        0.9 * h1.min(h2)
    }

    /// The variable's value at the start: s0, or σ0 = ln(u0)/(Λα).
    pub(crate) fn start(&self) -> f64 {
        match self.variable {
            Variable::ArcLength => self.s0,
            Variable::LogRadius { rate, u0 } => u0.ln() / rate,
        }
    }

    /// The offset of the variable at which the arc length is `s` (infinite for s = ∞).
    pub(crate) fn offset_to(&self, s: f64) -> f64 {
        match self.variable {
            Variable::ArcLength => s - self.s0,
            Variable::LogRadius { rate, u0 } => (rate * (s - self.s0) / u0).ln_1p() / rate,
        }
    }

    /// The arc length at offset `h`.
    fn s_at(&self, h: f64) -> f64 {
        match self.variable {
            Variable::ArcLength => self.s0 + h,
            Variable::LogRadius { rate, u0 } => self.s0 + u0 * (rate * h).exp_m1() / rate,
        }
    }

    /// ds/dv at offset `h`.
    fn speed_at(&self, h: f64) -> f64 {
        match self.variable {
            Variable::ArcLength => 1.0,
            Variable::LogRadius { rate, u0 } => u0 * (rate * h).exp(),
        }
    }

    /// The positions at offset h for each of `hs`, in one pass of Horner's rule (the
    /// independent chains overlap, where one at a time each waits on its last term).
    pub(crate) fn points_at<const M: usize>(&self, hs: [f64; M]) -> [Vec3; M] {
        let mut v = [Vec3::ZERO; M];
        for c in self.x.iter().rev() {
            for (v, h) in v.iter_mut().zip(hs) {
                *v = *v * h + *c;
            }
        }
        v
    }

    /// The position and its derivative in the variable (the unit tangent times ds/dv) at
    /// offset `h`.
    pub(crate) fn point_and_velocity_at(&self, h: f64) -> (Vec3, Vec3) {
        let (mut x, mut t) = (Vec3::ZERO, Vec3::ZERO);
        for k in (0..=ORDER).rev() {
            x = x * h + self.x[k];
            t = t * h + self.t[k];
        }
        (x, t.normalize() * self.speed_at(h))
    }

    /// The state at offset `h`, its frame made orthonormal again (Gram–Schmidt on t, n,
    /// then b = t × n).
    pub(crate) fn state_at(&self, h: f64) -> State {
        let (mut x, mut t, mut n) = (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
        for k in (0..=ORDER).rev() {
            x = x * h + self.x[k];
            t = t * h + self.t[k];
            n = n * h + self.n[k];
        }
        let t = t.normalize();
        let n = (n - n.dot(t) * t).normalize();
        State {
            s: self.s_at(h),
            x,
            t,
            n,
            b: t.cross(n),
        }
    }

    /// The series of the sensitivities' kernels `∂κ/∂Λ · ds/dv / (−s)` = κ/u ds/dv and
    /// `∂τ/∂ln ν · ds/dv / (−1)` = τ/w ds/dv, with u, w the laws' linear factors
    /// (see [`Sensitivity`]); and of s.
    fn kernels(&self, form: &SpaceForm) -> [[f64; ORDER + 1]; 2] {
        // The series of f/(1 + rate s) for a series f in s: dividing by a linear factor.
        let over_linear = |f: &[f64; ORDER + 1], rate: f64| {
            let u0 = 1.0 + rate * self.s0;
            let mut q = [0.0; ORDER + 1];
            let mut prev = 0.0;
            for (qk, fk) in q.iter_mut().zip(f) {
                prev = (fk - rate * prev) / u0;
                *qk = prev;
            }
            q
        };
        let (kappa, tau) = (form.kappa_law(), form.tau_law());
        match self.variable {
            Variable::ArcLength => [
                over_linear(&self.turn, kappa.a * kappa.e),
                over_linear(&self.twist, tau.a * tau.e),
            ],
            Variable::LogRadius { .. } => {
                // κ/u · u = κ = κ0 e^(−Λh); τ/w ds/dσ is the twist over w(σ) = 1 + a e s(σ).
                let mut q_kappa = [0.0; ORDER + 1];
                exponential_series(kappa.value(self.s0), -kappa.a, &mut q_kappa);
                let rate = tau.a * tau.e;
                let w0 = 1.0 + rate * self.s0;
                let mut q_tau = self.twist;
                for i in 0..=ORDER {
                    q_tau[i] /= w0;
                    let carry = rate * q_tau[i];
                    for (q, &a) in q_tau[i + 1..].iter_mut().zip(&self.arc[1..]) {
                        *q -= carry * a;
                    }
                }
                [q_kappa, q_tau]
            }
        }
    }
}

/// `out[k] = c rᵏ / k!`, the series of `c e^(r h)`. (`PowerLaw::taylor` at slope 0 gives
/// the same, but spends an `exp` on its first term; this runs twice in every step in σ.)
fn exponential_series(c: f64, r: f64, out: &mut [f64; ORDER + 1]) {
    let mut term = c;
    for (k, slot) in out.iter_mut().enumerate() {
        if k > 0 {
            term *= r / k as f64;
        }
        *slot = term;
    }
}

/// The index of the last nonzero coefficient (0 for none).
fn last_nonzero(c: &[f64; ORDER + 1]) -> usize {
    c.iter().rposition(|&x| x != 0.0).unwrap_or(0)
}

/// The series of `f(s(v)) ds/dv` for a power law f, from the series of s(v) and ds/dv:
/// `F = f(s(v))` solves `W F′ = −a s′ F` with `W = 1 + a e s(v)` (from `w f′ = −a f`,
/// w = 1 + a e s), term by term; each term, once known, is added to the sums of the later
/// ones (independent updates, not one long chain of additions).
fn composed(
    law: &super::family::PowerLaw,
    arc: &[f64; ORDER + 1],
    speed: &[f64; ORDER + 1],
) -> [f64; ORDER + 1] {
    let rate = law.a * law.e;
    let inv_w0 = 1.0 / (1.0 + rate * arc[0]);
    // 1/i, off the chain of dependent terms.
    let inverse: [f64; ORDER + 1] = std::array::from_fn(|i| 1.0 / i.max(1) as f64);
    let mut sums = [0.0; ORDER + 1];
    let mut out = [0.0; ORDER + 1];
    let mut f = law.value(arc[0]);
    for i in 0..=ORDER {
        if i > 0 {
            f = sums[i] * (inverse[i] * inv_w0);
        }
        let (drive, carry) = (-law.a * f, rate * i as f64 * f);
        // sums[m] gains −a s′_(m−1−i) F_i − W_(m−i) i F_i for every later m.
        let later = sums[i + 1..].iter_mut().zip(speed.iter().zip(&arc[1..]));
        if carry == 0.0 {
            for (sum, (&v, _)) in later {
                *sum += drive * v;
            }
        } else {
            for (sum, (&v, &a)) in later {
                *sum += drive * v - carry * a;
            }
        }
        for (o, &v) in out[i..].iter_mut().zip(speed) {
            *o += f * v;
        }
    }
    out
}
/// How a point of the curve moves with the solver's unknowns Λ and ln ν and with Ω, to
/// first order: a change δκ, δτ of the curvature and torsion turns the frame at s by the
/// rotation vector `Θ(s) = ∫₀ˢ δω` with `δω = δτ t + δκ b` (the change of the Darboux vector
/// τ t + κ b), so `δt = Θ × t`, and moves the point by `δx = Θ(s) × x(s) − ∫₀ˢ δω × x` (each
/// turn pivots the rest of the curve about the point where it acts). With `u = 1 + a e s`
/// of each law: Λ changes only κ, by `∂κ/∂Λ = −s κ/u`; ln ν and Ω only τ, by
/// `∂τ/∂ln ν = −τ/u` and `∂τ/∂Ω = −s τ/u · ∂a/∂Ω`. Both integrals are taken step by step by
/// four-point Gauss–Legendre on the step's series, in the step's variable (ds = ds/dσ dσ in σ) (to about 1e-7 of a step's share at the
/// search accuracy): a Jacobian for Newton in one integration instead of three.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Sensitivity {
    /// `Θ` for Λ, ln ν and Ω.
    turn: [Vec3; 3],
    /// `∫ δω × x` for Λ, ln ν and Ω.
    moment: [Vec3; 3],
}

/// The change of a point and its unit tangent per unit change of Λ (`[0]`), of ln ν (`[1]`)
/// and of Ω (`[2]`).
pub(crate) type EndDerivatives = [(Vec3, Vec3); 3];

impl Sensitivity {
    /// This one carried on along `e` from its start to `s0 + sigma`.
    pub(crate) fn along(&self, form: &SpaceForm, e: &Expansion, sigma: f64) -> Sensitivity {
        let [q_kappa, q_tau] = e.kernels(form);
        let per_omega = form.tau_rate_per_omega();
        let mut out = *self;
        // Four-point Gauss–Legendre: each stored node and its mirror image.
        let nodes = GAUSS_4.iter().flat_map(|&(x, w)| [(-x, w), (x, w)]);
        for (xi, w) in nodes {
            let at = 0.5 * sigma * (1.0 + xi);
            let weight = 0.5 * sigma * w;
            let s = e.s_at(at);
            // One pass of Horner for all five series: independent chains, not one at a time.
            let (mut x, mut t, mut b) = (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
            let (mut qk, mut qt) = (0.0, 0.0);
            for k in (0..=ORDER).rev() {
                x = x * at + e.x[k];
                t = t * at + e.t[k];
                b = b * at + e.b[k];
                qk = qk * at + q_kappa[k];
                qt = qt * at + q_tau[k];
            }
            let d_lambda = -s * qk * b;
            let d_nu = -qt * t;
            let d_omega = (-s * qt * per_omega) * t;
            for (k, d) in [d_lambda, d_nu, d_omega].into_iter().enumerate() {
                out.turn[k] += weight * d;
                out.moment[k] += weight * d.cross(x);
            }
        }
        out
    }

    /// The derivatives of `state`'s point and tangent, `state` being where this one ends.
    pub(crate) fn at(&self, state: &State) -> EndDerivatives {
        [0, 1, 2].map(|k| {
            let turn = self.turn[k];
            (turn.cross(state.x) - self.moment[k], turn.cross(state.t))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::space::family::{SpaceFormParams, TorsionType};

    /// The series in σ of ds/dσ, s, κ ds/dσ and τ ds/dσ (the last from the recurrence of
    /// [`composed`]) against the closed forms at points inside a step.
    #[test]
    fn log_radius_series_match_closed_forms() {
        let horner = |c: &[f64; ORDER + 1], h: f64| c.iter().rev().fold(0.0, |v, &c| v * h + c);
        let mut worst: f64 = 0.0;
        for (alpha, beta) in [(1.0, 0.0), (0.5, -1.0), (2.0, 1.0), (1.0, 0.5), (3.0, -0.5)] {
            for torsion in [TorsionType::One, TorsionType::Two] {
                for (lambda, s0) in [(0.3, 0.0), (4.5, 20.0), (1.0, 3.0)] {
                    let form = SpaceForm::new_unchecked(SpaceFormParams {
                        alpha,
                        beta,
                        lambda,
                        omega: 0.2,
                        nu: 1.5,
                        torsion,
                    });
                    let (lo, hi) = form.s_range();
                    if !(lo < s0 && s0 < hi) {
                        continue;
                    }
                    let state = State {
                        s: s0,
                        ..State::start()
                    };
                    let e = Expansion::stepping(&form, &state);
                    let Variable::LogRadius { .. } = e.variable else {
                        panic!("Λα > 0 steps in σ");
                    };
                    let (kappa, tau) = (form.kappa_law(), form.tau_law());
                    // Across a full-accuracy step, and back as far.
                    let step = e.step_size(Accuracy::Full);
                    for h in [0.3 * step, -0.5 * step, step] {
                        let s = e.s_at(h);
                        if !(lo < s && s < hi) {
                            continue;
                        }
                        let v = e.speed_at(h);
                        for (series, exact) in [
                            (&e.speed, v),
                            (&e.arc, s),
                            (&e.turn, kappa.value(s) * v),
                            (&e.twist, tau.value(s) * v),
                        ] {
                            let err = (horner(series, h) - exact).abs() / exact.abs().max(1.0);
                            assert!(
                                err < 1e-13,
                                "alpha {alpha} beta {beta} {torsion:?} lambda {lambda} s0 {s0} h {h}: {err:e}"
                            );
                            worst = worst.max(err);
                        }
                    }
                }
            }
        }
        assert!(worst > 0.0, "no case was checked");
    }
}
