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
}

impl Accuracy {
    fn tolerance(self) -> f64 {
        match self {
            Accuracy::Full => 2e-16,
            Accuracy::Search => 1e-10,
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
        };
        e.x[0] = state.x;
        e.t[0] = state.t;
        e.n[0] = state.n;
        e.b[0] = state.b;
        for k in 0..ORDER {
            let mut dt = Vec3::ZERO;
            let mut dn = Vec3::ZERO;
            let mut db = Vec3::ZERO;
            for j in 0..=k {
                let (kj, tj) = (kappa[j], tau[j]);
                let (t, n, b) = (e.t[k - j], e.n[k - j], e.b[k - j]);
                dt += kj * n;
                dn += tj * b - kj * t;
                db -= tj * n;
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

    /// The position at `s0 + h`.
    pub(crate) fn point_at(&self, h: f64) -> Vec3 {
        horner(&self.x, h)
    }

    /// The unit tangent at `s0 + h` (normalised).
    pub(crate) fn tangent_at(&self, h: f64) -> Vec3 {
        horner(&self.t, h).normalize()
    }

    /// The state at `s0 + h`, its frame made orthonormal again (Gram–Schmidt on t, n, then
    /// b = t × n).
    pub(crate) fn state_at(&self, h: f64) -> State {
        let t = horner(&self.t, h).normalize();
        let n = horner(&self.n, h);
        let n = (n - n.dot(t) * t).normalize();
        State {
            s: self.s0 + h,
            x: horner(&self.x, h),
            t,
            n,
            b: t.cross(n),
        }
    }
}

fn horner(c: &[Vec3; ORDER + 1], h: f64) -> Vec3 {
    let mut v = c[ORDER];
    for k in (0..ORDER).rev() {
        v = v * h + c[k];
    }
    v
}
