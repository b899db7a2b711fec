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

use super::family::SpaceForm;
use crate::gauss::GAUSS_4;
use crate::Vec3;

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

    fn tolerance(self) -> f64 {
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

/// The Taylor series of the solution about one state.
#[derive(Clone, Debug)]
pub(crate) struct Expansion {
    pub(crate) s0: f64,
    /// Coefficients of x, t, n, b, order 0..=ORDER.
    pub(crate) x: [Vec3; ORDER + 1],
    pub(crate) t: [Vec3; ORDER + 1],
    pub(crate) n: [Vec3; ORDER + 1],
    pub(crate) b: [Vec3; ORDER + 1],
    /// Coefficients of κ and τ.
    kappa: [f64; ORDER + 1],
    tau: [f64; ORDER + 1],
}

impl Expansion {
    /// The series about `state` for the curve `form`.
    pub(crate) fn new(form: &SpaceForm, state: &State) -> Expansion {
        let mut kappa = [0.0; ORDER + 1];
        let mut tau = [0.0; ORDER + 1];
        form.kappa_law().taylor(state.s, &mut kappa);
        form.tau_law().taylor(state.s, &mut tau);
        let zero = [Vec3::ZERO; ORDER + 1];
        let mut e = Expansion {
            s0: state.s,
            x: zero,
            t: zero,
            n: zero,
            b: zero,
            kappa,
            tau,
        };
        e.x[0] = state.x;
        e.t[0] = state.t;
        e.n[0] = state.n;
        e.b[0] = state.b;
        // κ or τ is a polynomial when its slope is −1/m (κ linear for α = −1): its series
        // ends in exact zeros, and the sums below stop at its last nonzero term.
        let last_nonzero = |c: &[f64; ORDER + 1]| c.iter().rposition(|&x| x != 0.0).unwrap_or(0);
        let (kappa_terms, tau_terms) = (last_nonzero(&e.kappa), last_nonzero(&e.tau));
        for k in 0..ORDER {
            let mut dt = Vec3::ZERO;
            let mut dn = Vec3::ZERO;
            let mut db = Vec3::ZERO;
            let both = k.min(kappa_terms).min(tau_terms);
            for j in 0..=both {
                let (kj, tj) = (e.kappa[j], e.tau[j]);
                let (t, n, b) = (e.t[k - j], e.n[k - j], e.b[k - j]);
                dt += kj * n;
                dn += tj * b - kj * t;
                db -= tj * n;
            }
            for j in both + 1..=k.min(kappa_terms) {
                let kj = e.kappa[j];
                dt += kj * e.n[k - j];
                dn -= kj * e.t[k - j];
            }
            for j in both + 1..=k.min(tau_terms) {
                let tj = e.tau[j];
                dn += tj * e.b[k - j];
                db -= tj * e.n[k - j];
            }
            let inv = 1.0 / (k + 1) as f64;
            e.x[k + 1] = e.t[k] * inv;
            e.t[k + 1] = dt * inv;
            e.n[k + 1] = dn * inv;
            e.b[k + 1] = db * inv;
        }
        e
    }

    /// The longest step whose last two terms stay within the tolerance of `accuracy`.
    pub(crate) fn step_size(&self, accuracy: Accuracy) -> f64 {
        let size = |k: usize| {
            [self.t[k], self.n[k], self.b[k]]
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

    /// The positions at `s0 + h` for each of `hs`, in one pass of Horner's rule (the
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

    /// The position and unit tangent (normalised) at `s0 + h`.
    pub(crate) fn point_and_tangent_at(&self, h: f64) -> (Vec3, Vec3) {
        let (mut x, mut t) = (Vec3::ZERO, Vec3::ZERO);
        for k in (0..=ORDER).rev() {
            x = x * h + self.x[k];
            t = t * h + self.t[k];
        }
        (x, t.normalize())
    }

    /// The state at `s0 + h`, its frame made orthonormal again (Gram–Schmidt on t, n, then
    /// b = t × n).
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
            s: self.s0 + h,
            x,
            t,
            n,
            b: t.cross(n),
        }
    }
}

/// How a point of the curve moves with the solver's unknowns Λ and ln ν and with Ω, to
/// first order: a change δκ, δτ of the curvature and torsion turns the frame at s by the
/// rotation vector `Θ(s) = ∫₀ˢ δω` with `δω = δτ t + δκ b` (the change of the Darboux vector
/// τ t + κ b), so `δt = Θ × t`, and moves the point by `δx = Θ(s) × x(s) − ∫₀ˢ δω × x` (each
/// turn pivots the rest of the curve about the point where it acts). With `u = 1 + a e s`
/// of each law: Λ changes only κ, by `∂κ/∂Λ = −s κ/u`; ln ν and Ω only τ, by
/// `∂τ/∂ln ν = −τ/u` and `∂τ/∂Ω = −s τ/u · ∂a/∂Ω`. Both integrals are taken step by step by
/// four-point Gauss–Legendre on the step's series (to about 1e-7 of a step's share at the
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
        // The series of f/u for κ and τ: dividing by a linear factor.
        let quotient = |f: &[f64; ORDER + 1], law: &super::family::PowerLaw| {
            let rate = law.a * law.e;
            let u0 = 1.0 + rate * e.s0;
            let mut q = [0.0; ORDER + 1];
            let mut prev = 0.0;
            for (qk, fk) in q.iter_mut().zip(f) {
                prev = (fk - rate * prev) / u0;
                *qk = prev;
            }
            q
        };
        let q_kappa = quotient(&e.kappa, form.kappa_law());
        let q_tau = quotient(&e.tau, form.tau_law());
        let per_omega = form.tau_rate_per_omega();
        let mut out = *self;
        // Four-point Gauss–Legendre: each stored node and its mirror image.
        let nodes = GAUSS_4.iter().flat_map(|&(x, w)| [(-x, w), (x, w)]);
        for (xi, w) in nodes {
            let at = 0.5 * sigma * (1.0 + xi);
            let weight = 0.5 * sigma * w;
            let s = e.s0 + at;
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
