//! Position integrals of the standard form: P(b) − P(a) = ∫ₐᵇ ρ(ψ) e^{iψ} dψ.
//!
//! Two methods, chosen by where the curve's singular point lies (docs/math.md §2 "Numerics"):
//!
//! * For α ≠ 1 and Λ > 0, ρ(ψ) = (1 + (α−1)Λψ)^γ with γ = 1/(α−1) has a branch point at
//!   ψₛ = −1/((α−1)Λ): ρ = ∞ (the inflection, α < 1) or ρ = 0 (α > 1). Writing σ = |ψ − ψₛ|,
//!   ρ ∝ σ^γ exactly, so near ψₛ the integral is a power series in σ,
//!   `Σₖ (∓i)^k/k! [ρ σ^(k+1)]/(k+1+γ)`, that is exact right up to the singular point.
//!   It is used for the part of [a, b] within distance 4 of ψₛ (where the terms stay small,
//!   so no precision is lost to cancellation).
//! * Everywhere else: Gauss–Legendre on panels laid from the large-ρ end, each narrow
//!   enough that ln ρ changes by at most `RATE_LIMIT` across it and the singular point is
//!   at least 4/3 of a panel away. A panel uses 8 nodes where the integrand is gentle
//!   (phase and ln ρ together change by at most `EASY` per half panel, and the singular
//!   point is 3 panels away: the rule's error is then below 1e-17), else 16. Panels whose contribution is below 1e-17 of the
//!   total are skipped (α ≈ 1 with large Λ, where ρ spans hundreds of orders of magnitude).
//!
//! Both also return ∂/∂Λ of the integral (θ limits fixed), which the solver uses for Newton
//! steps: ∂ρ/∂Λ = ρ ψ / (1 + (α−1)Λψ).

use std::cell::OnceCell;

use super::{StandardForm, Station};
use crate::foundation::gauss::{GAUSS_16, GAUSS_8};
use crate::foundation::numeric::{expm1_ratio, ln1p_ratio, Complex};

/// Below this distance (radians) from ψₛ the power series is used.
const SERIES_RADIUS: f64 = 4.0;
/// Largest change of ln ρ across one Gauss panel.
const RATE_LIMIT: f64 = 6.0;
/// Smallest ratio of (distance to ψₛ) to panel width, on the singular side.
const DISTANCE_RATIO: f64 = 0.75;
/// Widest Gauss panel, radians (keeps e^{iψ} well resolved).
const MAX_PANEL: f64 = 2.5;
/// The 8-point rule is used when (h/2)·|r + i| ≤ EASY, r the largest rate of ln ρ on the
/// panel: its error for e^{λx} on [−1, 1] is about 2e-18·|λ|^16.
const EASY: f64 = 1.1;

/// Most terms the power series may take (σ ≤ 4 needs about 30).
const MAX_TERMS: usize = 80;

/// 1/k for k = 0..=MAX_TERMS (1/0 unused), so the series multiplies instead of divides.
const RECIPROCALS: [f64; MAX_TERMS + 1] = {
    let mut r = [0.0; MAX_TERMS + 1];
    let mut k = 1;
    while k <= MAX_TERMS {
        r[k] = 1.0 / k as f64;
        k += 1;
    }
    r
};

/// An integral and its derivative with respect to Λ.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Integral {
    pub(crate) value: Complex,
    pub(crate) d_lambda: Complex,
}

/// e^{iψ} at the Gauss nodes of one panel spanning a whole interval, for repeated
/// integrals over the same θ range with different Λ (the solver's iterations); each rule's
/// table is built on first use.
pub(crate) struct NodeCache {
    theta: (f64, f64),
    cis8: OnceCell<Vec<Complex>>,
    cis16: OnceCell<Vec<Complex>>,
    /// e^{ia} and e^{ib}, for the clothoid's closed form.
    ends: OnceCell<[Complex; 2]>,
}

impl NodeCache {
    pub(crate) fn new(a: f64, b: f64) -> Self {
        NodeCache {
            theta: (a, b),
            cis8: OnceCell::new(),
            cis16: OnceCell::new(),
            ends: OnceCell::new(),
        }
    }

    fn ends(&self) -> [Complex; 2] {
        *self
            .ends
            .get_or_init(|| [Complex::cis(self.theta.0), Complex::cis(self.theta.1)])
    }

    fn table(&self, rule: &[(f64, f64)]) -> &[Complex] {
        let cell = if rule.len() == GAUSS_8.len() {
            &self.cis8
        } else {
            &self.cis16
        };
        cell.get_or_init(|| {
            let (a, b) = self.theta;
            let (half, mid) = (0.5 * (b - a), 0.5 * (a + b));
            rule.iter()
                .flat_map(|&(xi, _)| [Complex::cis(mid - xi * half), Complex::cis(mid + xi * half)])
                .collect()
        })
    }
}

/// ∫ₐᵇ ρ(ψ) e^{iψ} dψ for stations with `a.theta <= b.theta` (zero otherwise).
pub(crate) fn integrate(
    form: &StandardForm,
    a: &Station,
    b: &Station,
    derivative: bool,
) -> Integral {
    integrate_with(form, a, b, derivative, None)
}

/// [`integrate`], reusing `cache` when a single Gauss panel covers [a, b].
pub(crate) fn integrate_with(
    form: &StandardForm,
    a: &Station,
    b: &Station,
    derivative: bool,
    cache: Option<&NodeCache>,
) -> Integral {
    if b.theta <= a.theta {
        return Integral::default();
    }
    if form.alpha == -1.0 {
        let width = b.theta - a.theta;
        if width >= CLOTHOID_MIN_TURN && form.lambda * width >= CLOTHOID_MIN_LAMBDA_TURN {
            let ends = match cache.filter(|c| c.theta == (a.theta, b.theta)) {
                Some(c) => c.ends(),
                None => [Complex::cis(a.theta), Complex::cis(b.theta)],
            };
            return clothoid(form.lambda, a, b, ends, derivative);
        }
    }
    general(form, a, b, derivative, cache)
}

/// The series near the singular point and Gauss panels elsewhere, for every α.
fn general(
    form: &StandardForm,
    a: &Station,
    b: &Station,
    derivative: bool,
    cache: Option<&NodeCache>,
) -> Integral {
    let am1 = form.alpha - 1.0;
    let bl = am1.abs() * form.lambda;
    if bl > 0.0 && bl.is_finite() {
        // For α < 1 the singular point lies beyond b, for α > 1 before a.
        let (near, far) = if am1 < 0.0 { (b, a) } else { (a, b) };
        let sigma = |st: &Station| (am1 * st.ln_rho).exp() / bl;
        let (sigma_near, sigma_far) = (sigma(near), sigma(far));
        let split = sigma_far.min(SERIES_RADIUS);
        if sigma_near * 2.0 < split && sigma_near > 0.0 {
            let toward_far = if am1 < 0.0 { -1.0 } else { 1.0 };
            let mid = form
                .advance_theta(near, toward_far * (split - sigma_near))
                .unwrap_or(*far);
            let series = series(form, near, &mid, sigma_near, split, derivative);
            if split >= sigma_far {
                return series;
            }
            let rest = if am1 < 0.0 {
                gauss_panels(form, a, &mid, derivative, None)
            } else {
                gauss_panels(form, &mid, b, derivative, None)
            };
            return Integral {
                value: series.value + rest.value,
                d_lambda: series.d_lambda + rest.d_lambda,
            };
        }
    }
    gauss_panels(form, a, b, derivative, cache)
}

/// The clothoid's closed form is used for arcs that turn by at least this much (radians):
/// it is a difference of two terms of size ρ, which loses the factor ρ/|P| ≈ 1/turning of
/// relative precision.
pub(crate) const CLOTHOID_MIN_TURN: f64 = 0.05;
/// … and with Λ × turning at least this: ∂P/∂Λ is formed with a cancellation of relative
/// size (Λ × turning)², which must leave the Newton steps their quadratic convergence.
pub(crate) const CLOTHOID_MIN_LAMBDA_TURN: f64 = 0.01;

/// ∫ₐᵇ ρ e^{iψ} dψ on the clothoid (α = −1, Λ > 0, both stations before the inflection at
/// ψ = 1/(2Λ)) in closed form, `ends` = [e^{ia}, e^{ib}].
///
/// With κ = √(1 − 2Λψ) and t the arc length left to the inflection (κ = Λt), ψ =
/// 1/(2Λ) − Λt²/2, so P = e^{i/(2Λ)} √(π/Λ) conj(F(x_a) − F(x_b)) with x = κ/√(πΛ) and F the
/// Fresnel integral (see `crate::foundation::fresnel`). Written with the auxiliary functions,
/// e^{i/(2Λ)} e^{−iπx²/2} = e^{iψ} and
///
/// ```text
/// P = √(π/Λ) [H(x_b) e^{ib} − H(x_a) e^{ia}],   H = g − i f,
/// ```
///
/// whose terms have the size of ρ at their end. From H′(x) = iπxH − 1 and
/// dx/dΛ = −1/(2πΛ²x): ∂P/∂Λ = (ρ_b e^{ib} − ρ_a e^{ia} − (i + Λ)P)/(2Λ²).
fn clothoid(
    lambda: f64,
    a: &Station,
    b: &Station,
    ends: [Complex; 2],
    derivative: bool,
) -> Integral {
    let end = |st: &Station| ClothoidEnd {
        kappa: (-st.ln_rho).exp(),
        rho: if derivative { st.ln_rho.exp() } else { 0.0 },
    };
    clothoid_arc(lambda, [end(a), end(b)], ends, derivative)
}

/// Curvature and radius of curvature at one end of a clothoid arc (the radius is needed
/// only for ∂/∂Λ).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ClothoidEnd {
    pub(crate) kappa: f64,
    pub(crate) rho: f64,
}

/// [`clothoid`] from the curvatures (and radii) at the ends, `ends` = [e^{ia}, e^{ib}];
/// used directly by the segment solver, which knows them in closed form. Requires
/// b − a ≥ [`CLOTHOID_MIN_TURN`] and Λ(b − a) ≥ [`CLOTHOID_MIN_LAMBDA_TURN`] for full
/// accuracy.
#[inline]
pub(crate) fn clothoid_arc(
    lambda: f64,
    [at_a, at_b]: [ClothoidEnd; 2],
    [ea, eb]: [Complex; 2],
    derivative: bool,
) -> Integral {
    let root = (std::f64::consts::PI * lambda).sqrt();
    let h = |kappa: f64| {
        let (f, g) = crate::foundation::fresnel::aux(kappa / root);
        Complex::new(g, -f)
    };
    let value = (eb * h(at_b.kappa) - ea * h(at_a.kappa)).scale(std::f64::consts::PI / root);
    let d_lambda = if derivative {
        let ends = eb.scale(at_b.rho) - ea.scale(at_a.rho);
        (ends - value.mul_i() - value.scale(lambda)).scale(0.5 / (lambda * lambda))
    } else {
        Complex::ZERO
    };
    Integral { value, d_lambda }
}

/// The power series about the singular point between distances `sigma_near < sigma_far`.
fn series(
    form: &StandardForm,
    near: &Station,
    far: &Station,
    sigma_near: f64,
    sigma_far: f64,
    derivative: bool,
) -> Integral {
    let am1 = form.alpha - 1.0;
    let gamma = 1.0 / am1;
    let psi_s = -1.0 / (am1 * form.lambda);
    // ψ = ψₛ + sign·σ: sign = −1 for α < 1 (singular point beyond the far end).
    let sign = if am1 < 0.0 { -1.0 } else { 1.0 };
    let ell = (sigma_far / sigma_near).ln();
    let (rho_near, rho_far) = (near.ln_rho.exp(), far.ln_rho.exp());
    // [ρ σ^j] / (j + γ) without cancellation when (j + γ)·ℓ is small.
    let bracket = |hi: f64, lo: f64, m: f64| {
        if (m * ell).abs() < 0.5 {
            lo * ell * expm1_ratio(m * ell)
        } else {
            (hi - lo) / m
        }
    };
    // Term k of the sum is (sign·i)^k/k! · bracket_k: a real coefficient c = sign^k/k!
    // added to the real or imaginary part, with the sign, as i^k cycles through 1, i, −1, −i.
    let add = |acc: &mut Complex, k: usize, x: f64| match k & 3 {
        0 => acc.re += x,
        1 => acc.im += x,
        2 => acc.re -= x,
        _ => acc.im -= x,
    };
    let (mut hi, mut lo) = (rho_far * sigma_far, rho_near * sigma_near);
    let mut sum = Complex::ZERO;
    // Q = ∫ ρ/σ e^{∓iσ} dσ, whose (k+1)-th term reuses the k-th bracket of the sum.
    let mut q = Complex::new(bracket(rho_far, rho_near, gamma), 0.0);
    let mut c = 1.0;
    for k in 0..MAX_TERMS {
        let d = bracket(hi, lo, k as f64 + 1.0 + gamma);
        let term = c * d;
        add(&mut sum, k, term);
        c *= sign * RECIPROCALS[k + 1];
        add(&mut q, k + 1, c * d);
        hi *= sigma_far;
        lo *= sigma_near;
        if k as f64 > sigma_far && term.abs() <= 1e-18 * sum.norm_max() {
            break;
        }
    }
    let e_s = Complex::cis(psi_s);
    let value = e_s * sum;
    let d_lambda = if derivative {
        // ∂ρ/∂Λ = ρψ/w with w = (|α−1|Λ)σ and ψ = ψₛ + sign·σ.
        (e_s * q).scale(psi_s) + value.scale(sign)
    } else {
        Complex::ZERO
    };
    Integral {
        value,
        d_lambda: d_lambda.scale(1.0 / (am1.abs() * form.lambda)),
    }
}

/// Gauss–Legendre panels from `b` back to `a`.
fn gauss_panels(
    form: &StandardForm,
    a: &Station,
    b: &Station,
    derivative: bool,
    cache: Option<&NodeCache>,
) -> Integral {
    let (alpha, lambda) = (form.alpha, form.lambda);
    let am1 = alpha - 1.0;
    let beta = am1.abs();
    // Panel width = (w/Λ)·width_factor, where w = ρ^(α−1) at the panel's right end: this
    // bounds the change of ln ρ (rate Λ/w) and keeps the singular point DISTANCE_RATIO
    // panel widths away (it lies at distance w/(βΛ)).
    let width_factor = if am1 <= 0.0 {
        RATE_LIMIT.min(DISTANCE_RATIO / beta)
    } else {
        (RATE_LIMIT / (1.0 + RATE_LIMIT * beta))
            .min(DISTANCE_RATIO / (beta * (1.0 + DISTANCE_RATIO)))
    };
    let mut out = Integral::default();
    let mut x = *b;
    loop {
        let remaining = x.theta - a.theta;
        let w_x = (am1 * x.ln_rho).exp();
        let h = (w_x / lambda * width_factor).min(MAX_PANEL).min(remaining);
        let half = 0.5 * h;
        let mid = x.theta - half;
        // Largest rate of ln ρ on the panel (at its right end for α ≤ 1, left for α > 1)
        // and the distance from the panel to the singular point.
        let w_far = if am1 > 0.0 {
            w_x - am1 * lambda * h
        } else {
            w_x
        };
        let rate = lambda / w_far;
        let distance = if beta * lambda > 0.0 {
            w_far / (beta * lambda)
        } else {
            f64::INFINITY
        };
        let easy = half * rate.hypot(1.0) <= EASY && distance >= 3.0 * h;
        let rule: &[(f64, f64)] = if easy { &GAUSS_8 } else { &GAUSS_16 };
        // Only a single panel spanning all of [a, b] has the cached nodes.
        let single = h >= remaining && x.theta == b.theta;
        let cached = cache
            .filter(|c| single && c.theta == (a.theta, b.theta))
            .map(|c| c.table(rule));
        let e_mid = if cached.is_some() {
            Complex::ZERO
        } else {
            Complex::cis(mid)
        };
        let mut acc = Complex::ZERO;
        let mut dacc = Complex::ZERO;
        for (i, &(xi, wgt)) in rule.iter().enumerate() {
            for (j, side) in [-1.0, 1.0].into_iter().enumerate() {
                let off = side * xi * half; // ψ − mid
                let delta = off - half; // ψ − x.theta
                let t = lambda * delta / w_x;
                let ln_rho = x.ln_rho + t * ln1p_ratio(am1 * t);
                let f = wgt * ln_rho.exp();
                let e = match cached {
                    Some(c) => c[2 * i + j],
                    None => e_mid * Complex::cis(off),
                };
                acc += e.scale(f);
                if derivative {
                    let psi = x.theta + delta;
                    let w = w_x + am1 * lambda * delta;
                    dacc += e.scale(f * psi / w);
                }
            }
        }
        out.value += acc.scale(half);
        out.d_lambda += dacc.scale(half);
        if h >= remaining {
            break;
        }
        x = match form.advance_theta(&x, -h) {
            Some(st) => st,
            None => break,
        };
        // What is left is bounded by ρ(x)·(x − a) since ρ grows with ψ.
        if x.ln_rho.exp() * (x.theta - a.theta) <= 1e-17 * out.value.norm() {
            break;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Composite Gauss on 4000 equal panels of the plain formula ρ(ψ) = exp(Λψ·L((α−1)Λψ)):
    /// slow but independent of the panel layout and the series.
    fn brute(form: &StandardForm, a: f64, b: f64) -> (Complex, Complex) {
        let (al, l) = (form.alpha, form.lambda);
        let n = 4000;
        let h = (b - a) / n as f64;
        let (mut v, mut d) = (Complex::ZERO, Complex::ZERO);
        for k in 0..n {
            let mid = a + (k as f64 + 0.5) * h;
            for &(xi, w) in GAUSS_16.iter() {
                for side in [-1.0, 1.0] {
                    let psi = mid + side * xi * 0.5 * h;
                    let x = (al - 1.0) * l * psi;
                    let rho = (l * psi * ln1p_ratio(x)).exp();
                    let e = Complex::cis(psi).scale(w * 0.5 * h * rho);
                    v += e;
                    d += e.scale(psi / (1.0 + x));
                }
            }
        }
        (v, d)
    }

    #[test]
    fn the_clothoid_closed_form_agrees_with_the_series_and_panels() {
        let mut worst: [f64; 2] = [0.0; 2];
        let mut count = 0;
        for &(a, b) in &[
            (0.0f64, 0.05f64),
            (0.0, 0.3),
            (0.0, 1.0),
            (0.0, 2.5),
            (0.0, 3.1),
            (-2.0, 0.0),
            (-0.7, -0.1),
        ] {
            for i in 0..80 {
                let mu = 0.005 * 1.15f64.powi(i);
                // Λ from near the circle to the inflection just past b (or 0 for b = 0).
                let reach = b.max(0.5);
                let lambda = mu * expm1_ratio(-2.0 * mu) / reach;
                let form = StandardForm {
                    alpha: -1.0,
                    lambda,
                };
                let (Some(sa), Some(sb)) = (
                    form.advance_theta(&Station::REFERENCE, a),
                    form.advance_theta(&Station::REFERENCE, b),
                ) else {
                    continue;
                };
                if lambda * (b - a) < CLOTHOID_MIN_LAMBDA_TURN {
                    continue;
                }
                let ends = [Complex::cis(a), Complex::cis(b)];
                let got = clothoid(lambda, &sa, &sb, ends, true);
                let want = general(&form, &sa, &sb, true, None);
                let err = (got.value - want.value).norm() / want.value.norm();
                let derr = (got.d_lambda - want.d_lambda).norm() / want.d_lambda.norm();
                worst = [worst[0].max(err), worst[1].max(derr)];
                count += 1;
                assert!(
                    err < 1e-14 * (0.3 / (b - a)).max(1.0),
                    "[{a}, {b}] Λ {lambda}: value {err:e}"
                );
                assert!(derr < 1e-9, "[{a}, {b}] Λ {lambda}: d/dΛ {derr:e}");
            }
        }
        assert!(count > 300);
        eprintln!("clothoid closed form against the series and panels ({count}): {worst:?}");
    }

    #[test]
    fn every_path_agrees_with_brute_force_composite_gauss() {
        let mut worst: f64 = 0.0;
        for &alpha in &[-3.0, -1.0, -0.2, 0.0, 0.5, 0.9, 1.0, 1.1, 2.0, 5.0] {
            for &theta_d in &[0.3, 1.04, 2.5] {
                // μ from the circle to close to the singular point, crossing every path switch.
                for i in 0..60 {
                    let mu = 0.02 * 1.12f64.powi(i);
                    let beta = (alpha - 1.0f64).abs();
                    let lambda = mu * expm1_ratio(-beta * mu) / theta_d;
                    let form = StandardForm { alpha, lambda };
                    let (a, b) = if alpha > 1.0 {
                        (-theta_d, 0.0)
                    } else {
                        (0.0, theta_d)
                    };
                    // The brute force needs its panels (θd/4000) well inside the distance to
                    // the singular point, w/(βΛ) with w = e^{−βμ} at the near end.
                    if beta * lambda > 0.0 && (-beta * mu).exp() / (beta * lambda) < 0.05 * theta_d
                    {
                        continue;
                    }
                    let sa = form.advance_theta(&Station::REFERENCE, a).unwrap();
                    let sb = form.advance_theta(&Station::REFERENCE, b).unwrap();
                    let got = integrate(&form, &sa, &sb, true);
                    let (v, d) = brute(&form, a, b);
                    let err = (got.value - v).norm() / v.norm();
                    let derr = (got.d_lambda - d).norm() / d.norm().max(v.norm());
                    worst = worst.max(err);
                    assert!(
                        err < 2e-13,
                        "alpha {alpha} theta_d {theta_d} mu {mu}: value error {err:e}"
                    );
                    assert!(
                        derr < 1e-10,
                        "alpha {alpha} theta_d {theta_d} mu {mu}: d/dΛ error {derr:e}"
                    );
                }
            }
        }
        eprintln!("worst relative error against brute force: {worst:e}");
    }
}
