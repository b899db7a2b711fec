//! The ends of a log-aesthetic space curve (seed 003 §3, Figs. 5–6, with the errata of
//! `tools/reference/space_classification_notes.md`).
//!
//! Toward each end of its s range, κ = 1/ρ and τ = 1/μ are each one of
//!
//! * a finite positive value, when the end is the *other* function's bound ("cut");
//! * `u^(−1/e)` with `u → 0⁺` the function's own radicand (`e` = α for κ, β for τ), at its own
//!   finite bound;
//! * `|s|^(−1/e)` as s → ±∞ (e ≠ 0);
//! * `e^(g|s|)` as s → ±∞ (e = 0, or Λ = 0 / Ω = 0, which make the function constant: g = 0).
//!
//! Everything in the seed's tables follows from these: whether θ = ∫κ ds and φ = ∫τ ds
//! converge, the limits of ρ and μ, and the limit of κ/τ. The tangent and binormal are
//! decided by the Darboux axis d = (τt + κb)/|ω|: with χ = atan(τ/κ), `|d′| = |χ′|`, so d
//! has a limit, `t·d = sin χ` and `b·d = cos χ`. Hence **the tangent settles iff ∫κ ds < ∞
//! or τ/κ → ∞, and the binormal settles iff ∫τ ds < ∞ or κ/τ → ∞** toward that end; if both
//! integrals diverge and κ/τ tends to a finite positive limit, both precess about d forever.
//! The seed reads an infinite θ (φ) as a tangent (binormal) that keeps turning, which is
//! wrong in 42 cells of Figs. 5–6 (the notes list them).

use std::cmp::Ordering;

use super::family::{PowerLaw, SpaceForm, TorsionType};

/// Which end of the valid s range ([`SpaceForm::s_range`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SpaceEnd {
    /// The lower end, s decreasing from 0.
    Lower,
    /// The upper end, s increasing from 0.
    Upper,
}

impl SpaceEnd {
    /// −1 for the lower end, +1 for the upper one.
    pub fn direction(self) -> f64 {
        match self {
            SpaceEnd::Lower => -1.0,
            SpaceEnd::Upper => 1.0,
        }
    }
}

/// Which function's bound ends the s range (seed 003 Fig. 2): the s column of Figs. 5–6.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BoundBy {
    /// No bound: the end is at s = ±∞ (infinite length); the seed's "-inf" / "inf".
    Unbounded,
    /// The radius of curvature's bound −1/(Λα) (ρ → 0 or ∞ there); the seed's "A".
    Rho,
    /// The radius of torsion's bound, −ν^β/(Ωβ) for type 1 and ν^β/(Ωβ) for type 2 (μ → 0
    /// or ∞ there); the seed's "B".
    Mu,
    /// Both bounds are the same number (the seed's rows with "="); the seed writes "A".
    Both,
}

/// A θ or φ cell of seed 003 Figs. 5–6: how θ = ∫₀ˢ κ or φ = ∫₀ˢ τ behaves toward an end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TurningCell {
    /// The integral diverges toward the end: −∞ at the lower end, +∞ at the upper one
    /// ("-inf" / "inf"). This alone does not mean the vector keeps turning (see
    /// [`EndBehaviour::tangent_settles`]).
    Infinite,
    /// The function defines the end (or none does, at ±∞) and the integral converges there
    /// ("Finite").
    Finite,
    /// The other function's bound comes first, so the integral stops at a finite value;
    /// `diverges_at_own_end` tells what it would do at the function's own end:
    /// "Finite(-inf)" / "Finite(inf)" if it would diverge, "Finite(F)" if not.
    CutShort {
        /// Would the integral diverge at the function's own end?
        diverges_at_own_end: bool,
    },
}

/// The limit of a radius (ρ or μ) toward an end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum RadiusLimit {
    /// The radius tends to 0 (the curvature or torsion blows up); the seed's "0".
    Zero,
    /// The radius tends to ∞ (the curvature or torsion vanishes); the seed's "inf".
    Infinite,
    /// A finite positive value: the end is the other function's bound, or the radius is
    /// constant (Λ = 0 for ρ, Ω = 0 for μ). The seed writes "-".
    Positive,
}

/// A ρ or μ cell of seed 003 Figs. 5–6: the limit and the seed's star ("0*", "inf", "-", …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RadiusCell {
    /// The limit of the radius.
    pub limit: RadiusLimit,
    /// The seed's "*": in [`EndBehaviour::rho`] / [`EndBehaviour::mu`], set on a 0 or ∞
    /// limit when the length to the end is infinite or the turning integral (θ for ρ, φ for
    /// μ) diverges, as the seed's cells do; in [`EndBehaviour::rho_by_behaviour`] /
    /// [`EndBehaviour::mu_by_behaviour`], when the length is infinite or the vector (tangent
    /// for ρ, binormal for μ) keeps turning. Never set on [`RadiusLimit::Positive`].
    pub star: bool,
}

/// The limit of κ/τ toward an end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum RatioLimit {
    /// κ/τ → 0 (the torsion dominates).
    Zero,
    /// κ/τ tends to a finite positive value (κ and τ of the same order: helix-like).
    Finite,
    /// κ/τ → ∞ (the curvature dominates).
    Infinite,
}

/// How a log-aesthetic space curve behaves toward one end of its s range: one half of a row
/// of seed 003 Figs. 5–6, corrected (see [`SpaceForm::classify`]).
///
/// The seed's five cells of the half row are `binds` (its s column), `theta`, `phi`, `rho`
/// and `mu`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EndBehaviour {
    /// Which end this is.
    pub end: SpaceEnd,
    /// The end's value of s: the bound, or ±∞.
    pub s: f64,
    /// Which function's bound it is: the seed's s cell.
    pub binds: BoundBy,
    /// Is the arc length from s = 0 to this end finite? (Exactly when `s` is finite.)
    pub length_finite: bool,
    /// The θ = ∫₀ˢ κ cell.
    pub theta: TurningCell,
    /// The φ = ∫₀ˢ τ cell.
    pub phi: TurningCell,
    /// The ρ cell, starred as in the seed (infinite length or θ diverges).
    pub rho: RadiusCell,
    /// The μ cell, starred as in the seed (infinite length or φ diverges).
    pub mu: RadiusCell,
    /// The limit of κ/τ.
    pub kappa_over_tau: RatioLimit,
    /// Does the unit tangent have a limit toward this end? True iff ∫κ ds < ∞ or
    /// τ/κ → ∞.
    pub tangent_settles: bool,
    /// Does the unit binormal have a limit toward this end? True iff ∫τ ds < ∞ or
    /// κ/τ → ∞.
    pub binormal_settles: bool,
}

impl EndBehaviour {
    /// The ρ cell with the star set by the actual behaviour (infinite length, or the tangent
    /// keeps turning): the seed's definition of "*" ("direction not determined") applied to
    /// the corrected rule. Differs from [`EndBehaviour::rho`] at finite-length ends where θ
    /// diverges but τ/κ → ∞ (rows a16, a27).
    pub fn rho_by_behaviour(&self) -> RadiusCell {
        RadiusCell {
            star: star(self.rho.limit, !self.length_finite || !self.tangent_settles),
            ..self.rho
        }
    }

    /// The μ cell with the star set by the actual behaviour (infinite length, or the
    /// binormal keeps turning). Differs from [`EndBehaviour::mu`] at finite-length ends where
    /// φ diverges but κ/τ → ∞ (rows a16, a19).
    pub fn mu_by_behaviour(&self) -> RadiusCell {
        RadiusCell {
            star: star(self.mu.limit, !self.length_finite || !self.binormal_settles),
            ..self.mu
        }
    }
}

/// A row of seed 003's classification tables: Fig. 5 for [`TorsionType::One`] (rows 1–45,
/// which the seed names a1–a45), Fig. 6 for [`TorsionType::Two`] (rows 1–37, b1–b37).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SeedRow {
    /// The table: Fig. 5 for type 1, Fig. 6 for type 2.
    pub torsion: TorsionType,
    /// The row's number in its table, from 1.
    pub number: u8,
}

/// The behaviour of a log-aesthetic space curve at both ends of its s range (seed 003
/// Figs. 5–6, corrected); see [`SpaceForm::classify`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpaceClassification {
    /// Toward the lower end of s.
    pub lower: EndBehaviour,
    /// Toward the upper end of s.
    pub upper: EndBehaviour,
    row: Option<SeedRow>,
}

impl SpaceClassification {
    /// The row of seed 003 Fig. 5 (type 1) or Fig. 6 (type 2) this curve falls in, or `None`
    /// unless Λ > 0 and Ω > 0 (the tables assume both; with either 0 the curve is a
    /// different case, see [`SpaceForm::classify`]).
    ///
    /// The row follows from the type, the classes of α and of β (negative, 0, in (0, 1), 1,
    /// above 1) and, where both bounds lie on the same side, from comparing them (exactly, as
    /// the classification does).
    pub fn row(&self) -> Option<SeedRow> {
        self.row
    }

    /// The behaviour toward `end`.
    pub fn end(&self, end: SpaceEnd) -> &EndBehaviour {
        match end {
            SpaceEnd::Lower => &self.lower,
            SpaceEnd::Upper => &self.upper,
        }
    }
}

impl SpaceForm {
    /// How the curve behaves toward each end of its s range: seed 003 Figs. 5–6 (rows a1–a45
    /// for type 1, b1–b37 for type 2), worked out from the asymptotics of κ and τ, with the
    /// table's errors corrected (`tools/reference/space_classification_notes.md`).
    ///
    /// The cells (bound, θ, φ, ρ, μ) are the seed's, as typed values. The vectors follow
    /// the corrected rule: **the tangent settles iff ∫κ ds < ∞ or τ/κ → ∞, and the binormal
    /// settles iff ∫τ ds < ∞ or κ/τ → ∞** (the Darboux axis argument, module docs), so an
    /// infinite θ or φ does not by itself mean that the vector keeps turning.
    ///
    /// Bounds are the values [`SpaceForm::s_range`] returns, and two bounds are "the same"
    /// (the seed's rows with "=") only when they are the same double; the classification
    /// thus always agrees with the range the curve is evaluated on.
    ///
    /// Λ = 0 or Ω = 0 (outside the seed's tables, [`SpaceClassification::row`] is `None`):
    /// a constant κ or τ is treated as `e^(0·s)`, and the same rule applies. With both 0 the
    /// curve is a helix: both ends at infinite length, κ/τ finite, both vectors keep turning.
    /// With one of them 0 an infinite end is helix-like only if the other function also
    /// tends to a positive constant (it never does); otherwise whichever of κ, τ dominates
    /// decides, e.g. Λ = 0, β = 0, type 1 at s → +∞: τ → 0, the binormal settles and the
    /// tangent keeps turning (the curve approaches a circle).
    ///
    /// ```
    /// use lac::{
    ///     BoundBy, RadiusCell, RadiusLimit, SeedRow, SpaceForm, SpaceFormParams, TorsionType,
    ///     TurningCell,
    /// };
    /// // Row a24 (α = 1, β < 0, type 1).
    /// let params = SpaceFormParams {
    ///     alpha: 1.0,
    ///     beta: -1.0,
    ///     lambda: 1.0,
    ///     omega: 1.0,
    ///     nu: 1.0,
    ///     torsion: TorsionType::One,
    /// };
    /// let c = SpaceForm::new(params).unwrap().classify();
    /// assert_eq!(c.row(), Some(SeedRow { torsion: TorsionType::One, number: 24 }));
    /// assert_eq!(c.upper.s, 1.0); // −ν^β/(Ωβ)
    /// assert_eq!(c.upper.theta, TurningCell::CutShort { diverges_at_own_end: true });
    /// assert_eq!(c.upper.mu.limit, RadiusLimit::Infinite);
    /// assert!(c.upper.tangent_settles && c.upper.binormal_settles);
    /// // The seed's "A", "-inf", "Finite(-inf)", "0*", "-".
    /// let lower = c.lower;
    /// assert_eq!(lower.binds, BoundBy::Rho);
    /// assert_eq!(lower.theta, TurningCell::Infinite);
    /// assert_eq!(lower.phi, TurningCell::CutShort { diverges_at_own_end: true });
    /// assert_eq!(lower.rho, RadiusCell { limit: RadiusLimit::Zero, star: true });
    /// assert_eq!(lower.mu.limit, RadiusLimit::Positive);
    /// assert!(!lower.tangent_settles && lower.binormal_settles);
    /// ```
    pub fn classify(&self) -> SpaceClassification {
        let (lo, hi) = self.s_range();
        SpaceClassification {
            lower: self.end_behaviour(SpaceEnd::Lower, lo),
            upper: self.end_behaviour(SpaceEnd::Upper, hi),
            row: self.seed_row(),
        }
    }

    fn end_behaviour(&self, end: SpaceEnd, s: f64) -> EndBehaviour {
        let d = end.direction();
        let (kappa, tau) = (self.kappa_law(), self.tau_law());
        let length_finite = s.is_finite();
        // Exact comparisons, no tolerance. `s` is one of the two laws' own ends (or ±∞) bit
        // for bit, since s_range() takes the max / min of the same two numbers from
        // PowerLaw::range(); comparing those exactly keeps the classification consistent with
        // the range the curve is evaluated on. Two bounds one ulp apart really are a "cut"
        // case for the curve these doubles define, and a relative tolerance would call them
        // "both" while s_range() still ends at one of them. The fixture's "=" rows do not
        // need one: they use ν = 1, Λ = |β|, Ω = |α|, so −1/(Λα) and −ν^β/(±Ωβ) are the same
        // double (ν^(−β) = e^(−β ln 1) = 1 exactly).
        let k_own = own_end(kappa, d);
        let t_own = own_end(tau, d);
        let binds = match (length_finite, s == k_own, s == t_own) {
            (false, _, _) => BoundBy::Unbounded,
            (true, true, true) => BoundBy::Both,
            (true, true, false) => BoundBy::Rho,
            (true, false, _) => BoundBy::Mu,
        };
        let k_at_own = Asymptote::at_own_end(kappa, d);
        let t_at_own = Asymptote::at_own_end(tau, d);
        let k = if s == k_own { k_at_own } else { Asymptote::Cut };
        let t = if s == t_own { t_at_own } else { Asymptote::Cut };

        let theta = turning_cell(k, k_at_own);
        let phi = turning_cell(t, t_at_own);
        let kappa_over_tau = ratio_limit(k, t, length_finite);
        let tangent_settles = !k.integral_diverges() || kappa_over_tau == RatioLimit::Zero;
        let binormal_settles = !t.integral_diverges() || kappa_over_tau == RatioLimit::Infinite;
        let rho_limit = k.radius_limit();
        let mu_limit = t.radius_limit();
        EndBehaviour {
            end,
            s,
            binds,
            length_finite,
            theta,
            phi,
            rho: RadiusCell {
                limit: rho_limit,
                star: star(rho_limit, !length_finite || k.integral_diverges()),
            },
            mu: RadiusCell {
                limit: mu_limit,
                star: star(mu_limit, !length_finite || t.integral_diverges()),
            },
            kappa_over_tau,
            tangent_settles,
            binormal_settles,
        }
    }

    /// The seed's row, for Λ > 0 and Ω > 0.
    ///
    /// Both tables list α-classes in the order < 0, = 0, (0, 1), = 1, > 1, and within each
    /// the same β-classes; a pair takes three rows when both bounds exist on the same side
    /// (type 1: α, β both < 0 or both > 0; type 2: opposite signs), one row otherwise. The
    /// three rows compare A = −1/(Λα) with the μ bound B in the order >, =, < (type 1) or
    /// <, =, > (type 2). This reproduces a1–a45 and b1–b37.
    fn seed_row(&self) -> Option<SeedRow> {
        if !(self.lambda() > 0.0 && self.omega() > 0.0) {
            return None;
        }
        let (ca, cb) = (slope_class(self.alpha())?, slope_class(self.beta())?);
        let type_one = self.torsion_type() == TorsionType::One;
        let split = |a: usize, b: usize| {
            // class 0 is "< 0", class 1 "= 0", classes 2–4 are > 0
            let (neg_a, pos_a) = (a == 0, a >= 2);
            let (neg_b, pos_b) = (b == 0, b >= 2);
            if type_one {
                (neg_a && neg_b) || (pos_a && pos_b)
            } else {
                (neg_a && pos_b) || (pos_a && neg_b)
            }
        };
        let mut index = 0;
        for a in 0..5 {
            for b in 0..5 {
                if (a, b) == (ca, cb) {
                    if split(a, b) {
                        // the same numbers as s_range(), compared exactly (end_behaviour)
                        let bound_a = finite_bound(self.kappa_law());
                        let bound_b = finite_bound(self.tau_law());
                        let order = bound_a.partial_cmp(&bound_b)?;
                        let offset = match (type_one, order) {
                            (true, Ordering::Greater) | (false, Ordering::Less) => 0,
                            (_, Ordering::Equal) => 1,
                            _ => 2,
                        };
                        index += offset;
                    }
                    let rows = if type_one { ROWS_1 } else { ROWS_2 };
                    return (index < rows).then(|| SeedRow {
                        torsion: self.torsion_type(),
                        number: index as u8 + 1,
                    });
                }
                index += if split(a, b) { 3 } else { 1 };
            }
        }
        None
    }
}

/// Rows of seed 003 Fig. 5 (type 1).
const ROWS_1: usize = 45;

/// Rows of seed 003 Fig. 6 (type 2).
const ROWS_2: usize = 37;

/// The seed's classes of a slope: 0 for < 0, 1 for = 0, 2 for (0, 1), 3 for = 1, 4 for > 1.
fn slope_class(x: f64) -> Option<usize> {
    match x.partial_cmp(&0.0)? {
        Ordering::Less => Some(0),
        Ordering::Equal => Some(1),
        Ordering::Greater => match x.partial_cmp(&1.0)? {
            Ordering::Less => Some(2),
            Ordering::Equal => Some(3),
            Ordering::Greater => Some(4),
        },
    }
}

/// `law`'s finite bound (its radicand's zero), or NaN if it has none.
fn finite_bound(law: &PowerLaw) -> f64 {
    let (lo, hi) = law.range();
    if lo.is_finite() {
        lo
    } else if hi.is_finite() {
        hi
    } else {
        f64::NAN
    }
}

/// The star applies only to a limit 0 or ∞.
fn star(limit: RadiusLimit, condition: bool) -> bool {
    condition && limit != RadiusLimit::Positive
}

/// Where `law`'s own range ends in direction `d`: its radicand's zero, or ±∞.
fn own_end(law: &PowerLaw, d: f64) -> f64 {
    let (lo, hi) = law.range();
    if d < 0.0 {
        lo
    } else {
        hi
    }
}

/// The asymptotic form of κ or τ (`c (1 + a e s)^(−1/e)`, `c e^(−a s)` at a e = 0) toward
/// an end.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Asymptote {
    /// A finite positive value: the end is the other function's bound.
    Cut,
    /// `~ u^(−1/e)`, u → 0⁺ the radicand, at the function's own finite bound (e ≠ 0).
    AtZero { e: f64 },
    /// `~ |s|^(−1/e)` as s → ±∞ (e ≠ 0).
    Power { e: f64 },
    /// `~ e^(g|s|)` as s → ±∞; g = 0 is a constant (Λ = 0 or Ω = 0).
    Exp { g: f64 },
}

impl Asymptote {
    /// The form at the law's own end in direction `d` (which the law alone would reach).
    fn at_own_end(law: &PowerLaw, d: f64) -> Asymptote {
        // The same test as PowerLaw::range(): a radicand of slope 0 means no bound.
        if law.a * law.e == 0.0 {
            // e = 0: e^(−a s); a = 0: constant, e^(0 s).
            Asymptote::Exp { g: -law.a * d }
        } else if own_end(law, d).is_finite() {
            Asymptote::AtZero { e: law.e }
        } else {
            Asymptote::Power { e: law.e }
        }
    }

    /// Does ∫ f ds diverge toward the end?
    fn integral_diverges(self) -> bool {
        match self {
            Asymptote::Cut => false,
            // ∫ u^p du diverges at 0 iff p = −1/e ≤ −1, i.e. 0 < e ≤ 1
            Asymptote::AtZero { e } => e > 0.0 && e <= 1.0,
            // ∫ |s|^p ds diverges at ∞ iff p = −1/e ≥ −1, i.e. e < 0 or e ≥ 1
            Asymptote::Power { e } => !(0.0..1.0).contains(&e),
            Asymptote::Exp { g } => g >= 0.0,
        }
    }

    /// Does f blow up (+1), vanish (−1) or stay finite and positive (0) toward the end?
    fn growth(self) -> i8 {
        let sign = |v: f64| (v > 0.0) as i8 - (v < 0.0) as i8;
        match self {
            Asymptote::Cut => 0,
            // u^(−1/e) with u → 0 blows up iff e > 0
            Asymptote::AtZero { e } => sign(e),
            // |s|^(−1/e) with |s| → ∞ blows up iff e < 0
            Asymptote::Power { e } => -sign(e),
            Asymptote::Exp { g } => sign(g),
        }
    }

    /// The limit of the radius 1/f.
    fn radius_limit(self) -> RadiusLimit {
        match self.growth() {
            1 => RadiusLimit::Zero,
            -1 => RadiusLimit::Infinite,
            _ => RadiusLimit::Positive,
        }
    }

    /// The exponent's slope as a key whose reciprocal gives the power: `Power {e}` and
    /// `AtZero {e}` go like (·)^(−1/e); `Cut` and `Exp` have power 0, i.e. e = ∞.
    fn slope(self) -> f64 {
        match self {
            Asymptote::AtZero { e } | Asymptote::Power { e } => e,
            Asymptote::Cut | Asymptote::Exp { .. } => f64::INFINITY,
        }
    }

    /// The exponential rate (0 for powers and finite values).
    fn rate(self) -> f64 {
        match self {
            Asymptote::Exp { g } => g,
            _ => 0.0,
        }
    }
}

/// The θ or φ cell from the form at the end (`at_end`) and at the function's own end.
fn turning_cell(at_end: Asymptote, at_own: Asymptote) -> TurningCell {
    match at_end {
        Asymptote::Cut => TurningCell::CutShort {
            diverges_at_own_end: at_own.integral_diverges(),
        },
        _ if at_end.integral_diverges() => TurningCell::Infinite,
        _ => TurningCell::Finite,
    }
}

/// Compares 1/x with 1/y exactly (x, y nonzero, possibly ±∞, where 1/±∞ = 0), without
/// rounding the reciprocals: distinct slopes one ulp apart stay distinct.
fn reciprocal_cmp(x: f64, y: f64) -> Ordering {
    // sign class of 1/x: negative, zero, positive
    let class = |v: f64| {
        if v.is_infinite() {
            1
        } else if v < 0.0 {
            0
        } else {
            2
        }
    };
    // within a sign class 1/v decreases as v increases
    class(x)
        .cmp(&class(y))
        .then_with(|| y.partial_cmp(&x).unwrap_or(Ordering::Equal))
}

/// The limit of κ/τ from their forms at the same end.
///
/// At a finite end both are powers of the distance u → 0 to it (exponent p = −1/e, 0 when
/// cut): κ/τ ~ u^(p_κ − p_τ) → ∞ iff p_κ < p_τ. At an infinite end the exponential rate
/// decides first, then the power of |s|: κ/τ → ∞ iff (g_κ, p_κ) > (g_τ, p_τ)
/// (Python reference: `_ratio_limit`).
fn ratio_limit(k: Asymptote, t: Asymptote, finite_end: bool) -> RatioLimit {
    // p = −1/e, so p_κ ⋛ p_τ ⟺ 1/e_τ ⋛ 1/e_κ
    let by_power = reciprocal_cmp(t.slope(), k.slope());
    let order = if finite_end {
        by_power.reverse()
    } else {
        k.rate()
            .partial_cmp(&t.rate())
            .unwrap_or(Ordering::Equal)
            .then(by_power)
    };
    match order {
        Ordering::Greater => RatioLimit::Infinite,
        Ordering::Less => RatioLimit::Zero,
        Ordering::Equal => RatioLimit::Finite,
    }
}
