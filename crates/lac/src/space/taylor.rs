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
//! A step is as long as the last two terms allow at [`STEP_TOLERANCE`] (Jorba & Zou's rule);
//! near a bound of the valid range the coefficients grow like the inverse distance to it and
//! the steps shrink accordingly. The series is the dense output inside a step.

use super::family::SpaceForm;
use super::vec3::{cross, dot, scale, V3};

/// Order of the series.
pub(crate) const ORDER: usize = 20;

/// Largest size of each of the last two terms of a step's series, for unit frame vectors.
const STEP_TOLERANCE: f64 = 2e-16;

/// Position and Frenet frame at arc length `s`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct State {
    pub(crate) s: f64,
    pub(crate) x: V3,
    pub(crate) t: V3,
    pub(crate) n: V3,
    pub(crate) b: V3,
}

impl State {
    /// The standard form's start: origin, t = +x, n = +y, b = +z.
    pub(crate) fn start() -> State {
        State {
            s: 0.0,
            x: [0.0; 3],
            t: [1.0, 0.0, 0.0],
            n: [0.0, 1.0, 0.0],
            b: [0.0, 0.0, 1.0],
        }
    }
}

/// The Taylor series of the solution about one state.
#[derive(Clone, Debug)]
pub(crate) struct Expansion {
    pub(crate) s0: f64,
    /// Coefficients of x, t, n, b, order 0..=ORDER.
    pub(crate) x: [V3; ORDER + 1],
    pub(crate) t: [V3; ORDER + 1],
    pub(crate) n: [V3; ORDER + 1],
    pub(crate) b: [V3; ORDER + 1],
}

impl Expansion {
    /// The series about `state` for the curve `form`.
    pub(crate) fn new(form: &SpaceForm, state: &State) -> Expansion {
        let mut kappa = [0.0; ORDER + 1];
        let mut tau = [0.0; ORDER + 1];
        form.kappa_law().taylor(state.s, &mut kappa);
        form.tau_law().taylor(state.s, &mut tau);
        let zero = [[0.0; 3]; ORDER + 1];
        let mut e = Expansion {
            s0: state.s,
            x: zero,
            t: zero,
            n: zero,
            b: zero,
        };
        e.x[0] = state.x;
        e.t[0] = state.t;
        e.n[0] = state.n;
        e.b[0] = state.b;
        for k in 0..ORDER {
            let mut dt = [0.0; 3];
            let mut dn = [0.0; 3];
            let mut db = [0.0; 3];
            for j in 0..=k {
                let (kj, tj) = (kappa[j], tau[j]);
                let (t, n, b) = (e.t[k - j], e.n[k - j], e.b[k - j]);
                for c in 0..3 {
                    dt[c] += kj * n[c];
                    dn[c] += tj * b[c] - kj * t[c];
                    db[c] -= tj * n[c];
                }
            }
            let inv = 1.0 / (k + 1) as f64;
            e.x[k + 1] = scale(e.t[k], inv);
            e.t[k + 1] = scale(dt, inv);
            e.n[k + 1] = scale(dn, inv);
            e.b[k + 1] = scale(db, inv);
        }
        e
    }

    /// The longest step whose last two terms stay within [`STEP_TOLERANCE`].
    pub(crate) fn step_size(&self) -> f64 {
        let size = |k: usize| {
            [self.t[k], self.n[k], self.b[k]]
                .iter()
                .flat_map(|v| v.iter())
                .fold(0.0f64, |m, c| m.max(c.abs()))
        };
        let h1 = (STEP_TOLERANCE / size(ORDER - 1)).powf(1.0 / (ORDER - 1) as f64);
        let h2 = (STEP_TOLERANCE / size(ORDER)).powf(1.0 / ORDER as f64);
        // Both infinite only when κ and τ vanish identically, which they never do.
        0.9 * h1.min(h2)
    }

    /// The position at `s0 + h`.
    pub(crate) fn point_at(&self, h: f64) -> V3 {
        horner(&self.x, h)
    }

    /// The unit tangent at `s0 + h` (normalised).
    pub(crate) fn tangent_at(&self, h: f64) -> V3 {
        let t = horner(&self.t, h);
        scale(t, 1.0 / dot(t, t).sqrt())
    }

    /// The state at `s0 + h`, its frame made orthonormal again (Gram–Schmidt on t, n, then
    /// b = t × n).
    pub(crate) fn state_at(&self, h: f64) -> State {
        let t = horner(&self.t, h);
        let t = scale(t, 1.0 / dot(t, t).sqrt());
        let n = horner(&self.n, h);
        let n = super::vec3::axpy(n, -dot(n, t), t);
        let n = scale(n, 1.0 / dot(n, n).sqrt());
        State {
            s: self.s0 + h,
            x: horner(&self.x, h),
            t,
            n,
            b: cross(t, n),
        }
    }
}

fn horner(c: &[V3; ORDER + 1], h: f64) -> V3 {
    let mut v = c[ORDER];
    for k in (0..ORDER).rev() {
        for i in 0..3 {
            v[i] = v[i] * h + c[k][i];
        }
    }
    v
}
