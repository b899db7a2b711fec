//! The log-aesthetic space curve family in standard form (seed 003 §3, docs/math.md §6).

use super::taylor::{Accuracy, Expansion, State};
use super::Frame;
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::{expm1_ratio, ln1p_ratio};

/// `f(s) = c (1 + a e s)^(−1/e)`, and `c e^(−a s)` at `e = 0`.
///
/// Both curvature and torsion of a log-aesthetic space curve have this form: κ = 1/ρ with
/// `c = 1, a = Λ, e = α`, and τ = 1/μ with `c = 1/ν, a = ±Ω ν^(−β), e = β`. Every formula
/// below is written in `x = a e s` and `ln(1 + x) / e`, which tend to `a s` as `e → 0`, so
/// that α, β near 0 (and a near 0) need no case of their own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PowerLaw {
    pub(crate) c: f64,
    pub(crate) a: f64,
    pub(crate) e: f64,
}

impl PowerLaw {
    /// `ln(f(s) / c)` = `−a s ln(1 + x)/x` with x = a e s; NaN outside the valid range.
    /// (Written through `ln(1 + x)/x`, not `ln(1 + x)/e`: for e so small that x underflows,
    /// e = 5e-324, the quotient by e would be 0/e where the answer is −a s.)
    pub(crate) fn ln_ratio(&self, s: f64) -> f64 {
        let x = self.a * self.e * s;
        if x <= -1.0 {
            return f64::NAN;
        }
        if x.is_infinite() {
            return -x.ln_1p() / self.e;
        }
        -self.a * s * ln1p_ratio(x)
    }

    /// `f(s)`.
    pub(crate) fn value(&self, s: f64) -> f64 {
        self.c * self.ln_ratio(s).exp()
    }

    /// The open interval of s where `1 + a e s > 0`.
    pub(crate) fn range(&self) -> (f64, f64) {
        let ae = self.a * self.e;
        if ae > 0.0 {
            (-1.0 / ae, f64::INFINITY)
        } else if ae < 0.0 {
            (f64::NEG_INFINITY, -1.0 / ae)
        } else {
            (f64::NEG_INFINITY, f64::INFINITY)
        }
    }

    /// `∫₀ˢ f`, in the closed form `c s E₂(x) E((e − 1) a s E₂(x))` with
    /// `E(y) = (eʸ − 1)/y` and `E₂(x) = ln(1 + x)/x`, continuous in a and e (e = 1 gives
    /// `c ln(1 + a s)/a`, a = 0 gives `c s`).
    pub(crate) fn integral(&self, s: f64) -> f64 {
        let x = self.a * self.e * s;
        if x <= -1.0 {
            return f64::NAN;
        }
        let r = ln1p_ratio(x);
        self.c * s * r * expm1_ratio((self.e - 1.0) * self.a * s * r)
    }

    /// The s ≥ 0 where `∫₀ˢ f` reaches `value` (≥ 0), ∞ where it never does: inverting
    /// `∫₀ˢ f = c ((1 + y) − 1) / (a (e − 1))` with `1 + y = (1 + a e s)^((e − 1)/e)`,
    /// `s = (value/c) E₂(y) E(z)` with `y = a (e − 1) value / c`, `z = a e (value/c) E₂(y)`
    /// and E, E₂ as in [`PowerLaw::integral`], continuous in a and e as that is.
    pub(crate) fn s_of_integral(&self, value: f64) -> f64 {
        let v = value / self.c;
        let y = self.a * (self.e - 1.0) * v;
        if y <= -1.0 {
            return f64::INFINITY;
        }
        let r = ln1p_ratio(y);
        let s = v * r * expm1_ratio(self.a * self.e * v * r);
        if s.is_nan() {
            f64::INFINITY
        } else {
            s
        }
    }

    /// `∫₀^∞ f` (up to the upper bound of the range): `c / (a (1 − e))` where it converges
    /// (a > 0 with e < 1, or a < 0 with e > 1, where f blows up integrably), else ∞.
    pub(crate) fn integral_upper(&self) -> f64 {
        if (self.a > 0.0 && self.e < 1.0) || (self.a < 0.0 && self.e > 1.0) {
            self.c / (self.a * (1.0 - self.e))
        } else {
            f64::INFINITY
        }
    }

    /// `∫ₛ f` from s to the upper end of the range, where it is finite for every f of this
    /// kind (a > 0 with e < 1: f decays fast enough): `f(s) (1 + a e s) / (a (1 − e))`, in
    /// one product (no difference of two integrals); ∞ otherwise.
    pub(crate) fn integral_rest(&self, s: f64) -> f64 {
        if self.a > 0.0 && self.e < 1.0 {
            self.value(s) * (1.0 + self.a * self.e * s) / (self.a * (1.0 - self.e))
        } else {
            f64::INFINITY
        }
    }

    /// The Taylor coefficients of f about `s0`: `f(s0 + h) = Σ out[k] hᵏ`.
    ///
    /// `f_k = f_(k−1) · (−a)(1 + (k−1)e) / (k (1 + a e s0))`, the binomial series written so
    /// that `e = 0` gives the exponential's.
    pub(crate) fn taylor(&self, s0: f64, out: &mut [f64]) {
        let u = 1.0 + self.a * self.e * s0;
        let mut f = self.value(s0);
        for (k, slot) in out.iter_mut().enumerate() {
            if k > 0 {
                let k = k as f64;
                f *= -self.a * (1.0 + (k - 1.0) * self.e) / (k * u);
            }
            *slot = f;
        }
    }
}

/// Which way the radius of torsion runs (seed 003 eqs. 6–7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TorsionType {
    /// Type 1: μ = ν e^(Ωs) (β = 0), (Ωβs + ν^β)^(1/β) otherwise; μ increases with s.
    One,
    /// Type 2: μ = ν e^(−Ωs) (β = 0), (−Ωβs + ν^β)^(1/β) otherwise; μ decreases with s.
    Two,
}

impl TorsionType {
    /// 1 or 2, the seed's name.
    pub fn number(self) -> u8 {
        match self {
            TorsionType::One => 1,
            TorsionType::Two => 2,
        }
    }

    /// The type numbered 1 or 2.
    pub fn from_number(number: u8) -> Result<TorsionType> {
        match number {
            1 => Ok(TorsionType::One),
            2 => Ok(TorsionType::Two),
            _ => Err(Error::OutOfRange {
                name: "type",
                value: f64::from(number),
                expected: "1 (torsion radius increasing) or 2 (decreasing)",
            }),
        }
    }

    fn sign(self) -> f64 {
        match self {
            TorsionType::One => 1.0,
            TorsionType::Two => -1.0,
        }
    }
}

/// The parameters of a [`SpaceForm`] (seed 003 §3): the slopes α, β of its logarithmic
/// curvature and torsion graphs, their parameters Λ, Ω, the radius of torsion ν = μ(0) at
/// the start, and the torsion type.
///
/// Plain data; [`SpaceForm::new`] checks it (α, β finite, Λ ≥ 0, Ω ≥ 0, ν > 0).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpaceFormParams {
    /// α, the slope of the logarithmic curvature graph.
    pub alpha: f64,
    /// β, the slope of the logarithmic torsion graph.
    pub beta: f64,
    /// Λ ≥ 0, the curvature graph's parameter: ρ = e^(Λs) (α = 0), (Λαs + 1)^(1/α).
    pub lambda: f64,
    /// Ω ≥ 0, the torsion graph's parameter: μ = ν e^(±Ωs) (β = 0), (±Ωβs + ν^β)^(1/β).
    pub omega: f64,
    /// ν > 0, the radius of torsion μ(0) at the start.
    pub nu: f64,
    /// Whether μ increases ([`TorsionType::One`]) or decreases with s.
    pub torsion: TorsionType,
}

/// A log-aesthetic space curve in standard form (seed 003 §3): straight logarithmic curvature
/// graph of slope α and torsion graph of slope β,
///
/// ```text
/// ρ(s) = e^(Λs)                      (α = 0),   (Λαs + 1)^(1/α)      otherwise,
/// μ(s) = ν e^(±Ωs)                   (β = 0),   (±Ωβs + ν^β)^(1/β)   otherwise,
/// ```
///
/// (+ for [`TorsionType::One`]), starting at the origin with tangent +x, principal normal +y
/// and binormal +z, ρ(0) = 1, μ(0) = ν; the curve solves the Frenet–Serret system
/// `x′ = t, t′ = κn, n′ = −κt + τb, b′ = −τn` with κ = 1/ρ, τ = 1/μ > 0 (right-handed: it
/// leaves the osculating plane toward +b). Λ = Ω = 0 is a helix.
///
/// ```
/// use lac::{SpaceForm, SpaceFormParams, TorsionType};
/// let helix = SpaceForm::new(SpaceFormParams {
///     alpha: 0.5,
///     beta: -1.0,
///     lambda: 0.0,
///     omega: 0.0,
///     nu: 2.0,
///     torsion: TorsionType::One,
/// })
/// .unwrap();
/// let f = helix.frame_at_s(1.0).unwrap();
/// assert!((f.curvature - 1.0).abs() < 1e-15 && (f.torsion - 0.5).abs() < 1e-15);
/// ```
///
/// With the `serde` feature it is (de)serialised as its [`SpaceFormParams`], and
/// deserialisation checks them as [`SpaceForm::new`] does.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(into = "SpaceFormParams", try_from = "SpaceFormParams")
)]
pub struct SpaceForm {
    params: SpaceFormParams,
    kappa: PowerLaw,
    tau: PowerLaw,
}

impl SpaceForm {
    /// The standard form with these parameters: α, β any finite numbers, Λ ≥ 0, Ω ≥ 0,
    /// ν > 0.
    pub fn new(params: SpaceFormParams) -> Result<SpaceForm> {
        let SpaceFormParams {
            alpha,
            beta,
            lambda,
            omega,
            nu,
            torsion: _,
        } = params;
        finite("alpha", alpha)?;
        finite("beta", beta)?;
        for (name, value) in [("lambda", lambda), ("omega", omega)] {
            finite(name, value)?;
            if value < 0.0 {
                return Err(Error::OutOfRange {
                    name,
                    value,
                    expected: ">= 0",
                });
            }
        }
        finite("nu", nu)?;
        if nu <= 0.0 {
            return Err(Error::OutOfRange {
                name: "nu",
                value: nu,
                expected: "> 0",
            });
        }
        Ok(Self::new_unchecked(params))
    }

    /// [`SpaceForm::new`] without the checks, for the solver (which also visits Λ < 0).
    pub(crate) fn new_unchecked(params: SpaceFormParams) -> SpaceForm {
        let SpaceFormParams {
            alpha,
            beta,
            lambda,
            omega,
            nu,
            torsion,
        } = params;
        // τ = 1/μ = ν⁻¹ (1 ± Ωβν^(−β) s)^(−1/β); ν^(−β) = e^(−β ln ν) is 1 at β = 0.
        let rate = torsion.sign() * omega * (-beta * nu.ln()).exp();
        SpaceForm {
            params,
            kappa: PowerLaw {
                c: 1.0,
                a: lambda,
                e: alpha,
            },
            tau: PowerLaw {
                c: 1.0 / nu,
                a: rate,
                e: beta,
            },
        }
    }

    /// `∂a/∂Ω` of the torsion law's rate `a = ±Ω ν^(−β)`.
    pub(crate) fn tau_rate_per_omega(&self) -> f64 {
        let p = &self.params;
        p.torsion.sign() * (-p.beta * p.nu.ln()).exp()
    }

    /// The parameters α, β, Λ, Ω, ν and type.
    pub fn params(&self) -> SpaceFormParams {
        self.params
    }
    /// Slope of the logarithmic curvature graph.
    pub fn alpha(&self) -> f64 {
        self.params.alpha
    }
    /// Slope of the logarithmic torsion graph.
    pub fn beta(&self) -> f64 {
        self.params.beta
    }
    /// Λ, the curvature graph's parameter.
    pub fn lambda(&self) -> f64 {
        self.params.lambda
    }
    /// Ω, the torsion graph's parameter.
    pub fn omega(&self) -> f64 {
        self.params.omega
    }
    /// ν = μ(0), the radius of torsion at the start.
    pub fn nu(&self) -> f64 {
        self.params.nu
    }
    /// Type 1 or 2.
    pub fn torsion_type(&self) -> TorsionType {
        self.params.torsion
    }

    pub(crate) fn kappa_law(&self) -> &PowerLaw {
        &self.kappa
    }
    pub(crate) fn tau_law(&self) -> &PowerLaw {
        &self.tau
    }

    /// The valid interval of s (seed 003 Fig. 2): where both ρ and μ are defined, an open
    /// interval whose ends may be infinite.
    pub fn s_range(&self) -> (f64, f64) {
        let (k0, k1) = self.kappa.range();
        let (t0, t1) = self.tau.range();
        (k0.max(t0), k1.min(t1))
    }

    fn check_s(&self, s: f64) -> Result<f64> {
        finite("s", s)?;
        let (lo, hi) = self.s_range();
        if s <= lo || s >= hi {
            return Err(Error::OutOfRange {
                name: "s",
                value: s,
                expected: "inside the curve's valid range (SpaceForm::s_range)",
            });
        }
        Ok(s)
    }

    /// Curvature κ(s) = 1/ρ(s).
    pub fn curvature(&self, s: f64) -> Result<f64> {
        Ok(self.kappa.value(self.check_s(s)?))
    }
    /// Torsion τ(s) = 1/μ(s) (positive).
    pub fn torsion(&self, s: f64) -> Result<f64> {
        Ok(self.tau.value(self.check_s(s)?))
    }
    /// Radius of curvature ρ(s).
    pub fn rho(&self, s: f64) -> Result<f64> {
        Ok(1.0 / self.curvature(s)?)
    }
    /// Radius of torsion μ(s).
    pub fn mu(&self, s: f64) -> Result<f64> {
        Ok(1.0 / self.torsion(s)?)
    }
    /// θ(s) = ∫₀ˢ κ, the total turning of the tangent from s = 0 (negative for s < 0).
    pub fn theta(&self, s: f64) -> Result<f64> {
        Ok(self.kappa.integral(self.check_s(s)?))
    }
    /// φ(s) = ∫₀ˢ τ, the total turning of the binormal from s = 0.
    pub fn phi(&self, s: f64) -> Result<f64> {
        Ok(self.tau.integral(self.check_s(s)?))
    }

    /// The point and Frenet frame at s, by the Taylor integrator of
    /// [`SpaceForm::frames`].
    pub fn frame_at_s(&self, s: f64) -> Result<Frame> {
        Ok(self.frames(&[s])?.remove(0))
    }

    /// Points and Frenet frames at every s in `s_values` (any order, each inside
    /// [`SpaceForm::s_range`]).
    ///
    /// The Frenet–Serret system is integrated by Taylor series of order 20 whose
    /// coefficients follow from recurrences (the binomial series of κ and τ and Cauchy
    /// products); each step is as long as the last two terms allow at 2e-16, so positions
    /// and frames are accurate to about 1e-14 of the curve's size over a few turns. After
    /// every step the frame is made orthonormal again. Values between steps come from the
    /// step's series.
    pub fn frames(&self, s_values: &[f64]) -> Result<Vec<Frame>> {
        for &s in s_values {
            self.check_s(s)?;
        }
        let mut order: Vec<usize> = (0..s_values.len()).collect();
        order.sort_by(|&i, &j| s_values[i].total_cmp(&s_values[j]));
        let mut out = vec![None; s_values.len()];
        // Walk up from 0 through the positive values, then down through the negative ones.
        let split = order.partition_point(|&i| s_values[i] < 0.0);
        self.walk_to(order[split..].iter().map(|&i| (i, s_values[i])), &mut out);
        self.walk_to(
            order[..split].iter().rev().map(|&i| (i, s_values[i])),
            &mut out,
        );
        Ok(out
            .into_iter()
            .map(|f| f.expect("every s visited"))
            .collect())
    }

    fn walk_to(&self, targets: impl Iterator<Item = (usize, f64)>, out: &mut [Option<Frame>]) {
        let mut state = State::start();
        let mut expansion = Expansion::new(self, &state);
        let mut h_max = expansion.step_size(Accuracy::Full);
        for (index, s) in targets {
            while (s - state.s).abs() > h_max {
                let h = h_max.copysign(s - state.s);
                state = expansion.state_at(h);
                expansion = Expansion::new(self, &state);
                h_max = expansion.step_size(Accuracy::Full);
            }
            out[index] = Some(self.frame_from(&expansion.state_at(s - state.s)));
        }
    }

    /// The public frame for an integrator state.
    pub(crate) fn frame_from(&self, state: &State) -> Frame {
        Frame {
            s: state.s,
            point: state.x,
            tangent: state.t,
            normal: state.n,
            binormal: state.b,
            curvature: self.kappa.value(state.s),
            torsion: self.tau.value(state.s),
        }
    }
}

impl TryFrom<SpaceFormParams> for SpaceForm {
    type Error = Error;

    /// [`SpaceForm::new`].
    fn try_from(params: SpaceFormParams) -> Result<SpaceForm> {
        SpaceForm::new(params)
    }
}

impl From<SpaceForm> for SpaceFormParams {
    fn from(form: SpaceForm) -> SpaceFormParams {
        form.params
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`PowerLaw::s_of_integral`] inverts [`PowerLaw::integral`] to 1e-13 (times the
    /// inverse's condition number) over slopes
    /// either side of 0 and 1 (and at them), rising and falling laws, lengths from 1e-3 to
    /// 50 inside the valid range; beyond what the integral reaches it is ∞.
    #[test]
    fn s_of_integral_inverts_the_integral() {
        let mut checked = 0;
        for e in [
            -2.0,
            -1.0,
            -0.5,
            -1e-9,
            0.0,
            1e-9,
            0.5,
            1.0 - 1e-9,
            1.0,
            1.0 + 1e-9,
            2.0,
        ] {
            for a in [-0.7, -1e-8, 0.0, 0.3, 2.5] {
                let law = PowerLaw { c: 1.7, a, e };
                for s in [1e-3, 0.4, 3.0, 50.0] {
                    if s >= law.range().1 {
                        continue;
                    }
                    let value = law.integral(s);
                    let back = law.s_of_integral(value);
                    // The inverse's own condition: a rounding of the value moves s by
                    // that over f(s), large where f has decayed (e^(−15) at a s = 15).
                    let condition = 1.0 + value / (s * law.value(s));
                    if condition > 1e12 {
                        continue; // the value has rounded to its limit: no s to find
                    }
                    let err = (back - s).abs() / s / condition;
                    assert!(err < 1e-13, "e {e} a {a} s {s}: {back} ({err:e})");
                    checked += 1;
                }
                let upper = law.integral_upper();
                if upper.is_finite() {
                    assert_eq!(
                        law.s_of_integral(1.01 * upper),
                        f64::INFINITY,
                        "e {e} a {a}"
                    );
                }
            }
        }
        assert!(checked > 150, "only {checked}");
    }

    /// Slopes so small that a e s underflows (subnormal e) give the exponential of e = 0,
    /// as the formulas' limit says: the fuzzer's α, β = 5e-324 once gave c (1 + tiny)/e.
    #[test]
    fn tiny_slopes_are_the_exponential() {
        for e in [5e-324, 1e-310, 1e-300, 1e-20, -1e-300] {
            for s in [0.5f64, 3.0, 40.0] {
                let law = PowerLaw { c: 2.0, a: 0.7, e };
                let exact = 2.0 * (-0.7 * s).exp();
                let err = (law.value(s) - exact).abs() / exact;
                assert!(err < 1e-14, "e {e:e} s {s}: {err:e}");
            }
        }
    }
}
