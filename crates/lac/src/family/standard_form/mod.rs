//! The planar log-aesthetic family in standard form (docs/math.md §2, seed 000 §3).

use kurbo::{Point, Vec2};

use crate::foundation::error::{finite, Error, Result};
pub(crate) mod integrate;

use crate::foundation::numeric::{expm1_ratio, ln1p_ratio, ln_1p_product, minus_one};
use integrate::integrate;

/// A planar log-aesthetic curve in standard form II (seed 000 §3.3, docs/math.md §2).
///
/// The reference point (s = θ = 0) is at the origin with tangent +x and radius of
/// curvature ρ = 1; the curve turns left and ρ grows with arc length s:
///
/// ```text
/// dρ/ds = Λ ρ^(1−α)          ρ(s) = (Λ α s + 1)^(1/α)        (ρ(s) = e^(Λ s) for α = 0)
/// θ(s)  = ∫₀ˢ du / ρ(u)       P(θ) = ∫₀^θ ρ(ψ) e^{iψ} dψ
/// ```
///
/// α is the slope of the logarithmic curvature graph (−1 clothoid, 0 Nielsen spiral,
/// 1 logarithmic spiral, 2 circle involute) and Λ ≥ 0 its parameter; Λ = 0 is the unit
/// circle for every α. Standard form I is the case Λ = 1 ([`StandardForm::form_one`]).
///
/// Every formula is evaluated so that it is continuous across α = 0, α = 1 and Λ = 0.
///
/// ```
/// use lac::StandardForm;
/// // The clothoid (α = −1, Λ = 1): κ = 1 − s, so θ(s) = s − s²/2.
/// let clothoid = StandardForm::new(-1.0, 1.0).unwrap();
/// assert!((clothoid.theta_at_s(0.5).unwrap() - 0.375).abs() < 1e-15);
/// // α = 1 is the logarithmic spiral: ρ(θ) = e^(Λθ).
/// let spiral = StandardForm::new(1.0, 0.2).unwrap();
/// assert!((spiral.rho_at_theta(1.0).unwrap() - 0.2f64.exp()).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StandardForm {
    /// Slope α of the logarithmic curvature graph.
    pub alpha: f64,
    /// The parameter Λ = dρ/ds at the reference point, Λ ≥ 0.
    pub lambda: f64,
}

/// A point of a standard-form curve, held as tangent angle, arc length and log radius.
///
/// Carrying ln ρ alongside θ and s keeps quantities near a bound (ρ → 0 or ∞) accurate:
/// they are derived from a nearby station rather than from the reference point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Station {
    pub(crate) theta: f64,
    pub(crate) s: f64,
    pub(crate) ln_rho: f64,
}

impl Station {
    /// The reference point of the standard form.
    pub(crate) const REFERENCE: Station = Station {
        theta: 0.0,
        s: 0.0,
        ln_rho: 0.0,
    };

    /// Curvature 1/ρ.
    #[inline]
    pub(crate) fn kappa(&self) -> f64 {
        (-self.ln_rho).exp()
    }
}

impl StandardForm {
    /// A standard form II curve with slope `alpha` and parameter `lambda` ≥ 0.
    pub fn new(alpha: f64, lambda: f64) -> Result<Self> {
        finite("alpha", alpha)?;
        finite("lambda", lambda)?;
        if lambda < 0.0 {
            return Err(Error::OutOfRange {
                name: "lambda",
                value: lambda,
                expected: "lambda >= 0",
            });
        }
        Ok(StandardForm { alpha, lambda })
    }

    /// Standard form I: Λ = 1 (seed 000 §3.2), the shape of the whole family for this α.
    pub fn form_one(alpha: f64) -> Result<Self> {
        Self::new(alpha, 1.0)
    }

    /// The interval of arc length s over which 0 < ρ < ∞ (docs/math.md §2 table; may be infinite).
    pub fn s_bounds(&self) -> (f64, f64) {
        let (a, l) = (self.alpha, self.lambda);
        if l == 0.0 || a == 0.0 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else if a < 0.0 {
            (f64::NEG_INFINITY, -1.0 / (l * a))
        } else {
            (-1.0 / (l * a), f64::INFINITY)
        }
    }

    /// The interval of tangent angle θ over which 0 < ρ < ∞ (docs/math.md §2 table; may be infinite).
    pub fn theta_bounds(&self) -> (f64, f64) {
        let (a, l) = (self.alpha, self.lambda);
        if l == 0.0 || a == 1.0 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else if a < 1.0 {
            (f64::NEG_INFINITY, 1.0 / (l * (1.0 - a)))
        } else {
            (-1.0 / (l * (a - 1.0)), f64::INFINITY)
        }
    }

    /// Radius of curvature at arc length `s`: ρ(s) = (Λαs + 1)^(1/α), e^(Λs) for α = 0.
    pub fn rho_at_s(&self, s: f64) -> Result<f64> {
        Ok(self.station_at_s(s)?.ln_rho.exp())
    }

    /// Tangent angle at arc length `s` (θ(0) = 0).
    pub fn theta_at_s(&self, s: f64) -> Result<f64> {
        Ok(self.station_at_s(s)?.theta)
    }

    /// Radius of curvature at tangent angle `theta`: ((α−1)Λθ + 1)^(1/(α−1)), e^(Λθ) for α = 1.
    pub fn rho_at_theta(&self, theta: f64) -> Result<f64> {
        Ok(self.station_at_theta(theta)?.ln_rho.exp())
    }

    /// Arc length from the reference point to tangent angle `theta` (the inverse of θ(s)).
    pub fn s_at_theta(&self, theta: f64) -> Result<f64> {
        Ok(self.station_at_theta(theta)?.s)
    }

    /// The point with tangent angle `theta`: P(θ) = ∫₀^θ ρ(ψ) e^{iψ} dψ.
    pub fn point_at_theta(&self, theta: f64) -> Result<Point> {
        let station = self.station_at_theta(theta)?;
        Ok(self.point_at_station(&station))
    }

    /// The point at arc length `s`: C(s) = ∫₀ˢ e^{iθ(u)} du.
    pub fn point_at_s(&self, s: f64) -> Result<Point> {
        let station = self.station_at_s(s)?;
        Ok(self.point_at_station(&station))
    }

    /// Unit tangent at tangent angle `theta` (it is (cos θ, sin θ) by definition).
    pub fn tangent_at_theta(&self, theta: f64) -> Vec2 {
        Vec2::new(theta.cos(), theta.sin())
    }

    /// The qualitative shape of the family for this α (seed 000 Table 2).
    pub fn classification(&self) -> Classification {
        Classification::of(self.alpha)
    }

    fn point_at_station(&self, station: &Station) -> Point {
        let z = if station.theta >= 0.0 {
            integrate(self, &Station::REFERENCE, station, false).value
        } else {
            -integrate(self, station, &Station::REFERENCE, false).value
        };
        Point::new(z.re, z.im)
    }

    pub(crate) fn station_at_theta(&self, theta: f64) -> Result<Station> {
        finite("theta", theta)?;
        self.advance_theta(&Station::REFERENCE, theta)
            .ok_or(Error::OutOfRange {
                name: "theta",
                value: theta,
                expected: "a tangent angle inside theta_bounds()",
            })
    }

    pub(crate) fn station_at_s(&self, s: f64) -> Result<Station> {
        finite("s", s)?;
        self.advance_s(&Station::REFERENCE, s)
            .ok_or(Error::OutOfRange {
                name: "s",
                value: s,
                expected: "an arc length inside s_bounds()",
            })
    }

    /// The station `d_theta` further along in tangent angle, or `None` past a bound.
    ///
    /// With w = ρ^(α−1) at `from`, ln ρ grows by ln(1 + (α−1)Λ dθ/w)/(α−1) and s by
    /// (ρ^α − ρ_from^α)/(Λα); both are written through `ln1p_ratio`/`expm1_ratio` so that
    /// α → 1, α → 0 and Λ → 0 are ordinary values rather than 0/0.
    pub(crate) fn advance_theta(&self, from: &Station, d_theta: f64) -> Option<Station> {
        let (a, l) = (self.alpha, self.lambda);
        let w = ((a - 1.0) * from.ln_rho).exp();
        let t = l * d_theta / w;
        let x = (a - 1.0) * t;
        if x <= -1.0 || x.is_nan() {
            return None;
        }
        let lr = if from.ln_rho == 0.0 && x < -0.5 {
            // From the reference point (w = 1) near the bound: form 1 + (α−1)Λθ exactly.
            let (am1, am1_lo) = minus_one(a);
            ln_1p_product(am1, am1_lo, l, d_theta) / x
        } else {
            ln1p_ratio(x)
        };
        let d_ln_rho = t * lr;
        let d_s = from.ln_rho.exp() * d_theta * lr * expm1_ratio(a * d_ln_rho);
        let out = Station {
            theta: from.theta + d_theta,
            s: from.s + d_s,
            ln_rho: from.ln_rho + d_ln_rho,
        };
        (out.s.is_finite() && out.ln_rho.is_finite()).then_some(out)
    }

    /// The station `d_s` further along in arc length, or `None` past a bound.
    ///
    /// With v = ρ^α at `from`, ln ρ grows by ln(1 + ΛαΔs/v)/α and θ by
    /// (ρ^(α−1) − ρ_from^(α−1))/(Λ(α−1)), written as for [`Self::advance_theta`].
    pub(crate) fn advance_s(&self, from: &Station, d_s: f64) -> Option<Station> {
        let (a, l) = (self.alpha, self.lambda);
        let v = (a * from.ln_rho).exp();
        let t = l * d_s / v;
        let x = a * t;
        if x <= -1.0 || x.is_nan() {
            return None;
        }
        let lr = if from.ln_rho == 0.0 && x < -0.5 {
            ln_1p_product(a, 0.0, l, d_s) / x
        } else {
            ln1p_ratio(x)
        };
        let d_ln_rho = t * lr;
        let d_theta = from.kappa() * d_s * lr * expm1_ratio((a - 1.0) * d_ln_rho);
        let out = Station {
            theta: from.theta + d_theta,
            s: from.s + d_s,
            ln_rho: from.ln_rho + d_ln_rho,
        };
        (out.theta.is_finite() && out.ln_rho.is_finite()).then_some(out)
    }
}

/// What happens at the end of the curve where ρ → 0 (seed 000 Table 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ZeroRadiusEnd {
    /// α ≤ 0: the curve spirals into the point ρ = 0 and the arc length to it is infinite.
    SpiralsInInfiniteLength,
    /// 0 < α ≤ 1: the curve spirals into the point ρ = 0 and the arc length to it is finite.
    SpiralsInFiniteLength,
    /// α > 1: the curve reaches ρ = 0 at finite length with a definite tangent direction.
    EndsWithTangent,
}

/// What happens at the end of the curve where ρ → ∞ (seed 000 Table 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InfiniteRadiusEnd {
    /// α < 0: the point of inflection is reached at finite arc length.
    InflectionAtFiniteDistance,
    /// 0 ≤ α < 1: the point of inflection is at infinity; the direction of divergence is
    /// determined (the tangent angle tends to a finite limit).
    InflectionAtInfinity,
    /// α ≥ 1: the curve spirals outward forever (θ → ∞ as ρ → ∞).
    SpiralsOut,
}

/// The qualitative behaviour of the family at both ends of the ρ range (seed 000 Table 2),
/// valid for Λ > 0 (Λ = 0 is a circle).
///
/// ```
/// use lac::{Classification, InfiniteRadiusEnd};
/// let clothoid = Classification::of(-1.0);
/// assert_eq!(clothoid.infinite_radius, InfiniteRadiusEnd::InflectionAtFiniteDistance);
/// assert!(!clothoid.arc_length_finite_at_zero_radius());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Classification {
    /// Behaviour toward ρ = 0.
    pub zero_radius: ZeroRadiusEnd,
    /// Behaviour toward ρ = ∞.
    pub infinite_radius: InfiniteRadiusEnd,
}

impl Classification {
    /// Classify the family of slope `alpha` (NaN is treated as a circle-free generic α > 1).
    pub fn of(alpha: f64) -> Self {
        let zero_radius = if alpha <= 0.0 {
            ZeroRadiusEnd::SpiralsInInfiniteLength
        } else if alpha <= 1.0 {
            ZeroRadiusEnd::SpiralsInFiniteLength
        } else {
            ZeroRadiusEnd::EndsWithTangent
        };
        let infinite_radius = if alpha < 0.0 {
            InfiniteRadiusEnd::InflectionAtFiniteDistance
        } else if alpha < 1.0 {
            InfiniteRadiusEnd::InflectionAtInfinity
        } else {
            InfiniteRadiusEnd::SpiralsOut
        };
        Classification {
            zero_radius,
            infinite_radius,
        }
    }

    /// Is the arc length from any point to ρ = 0 finite? (α > 0)
    pub fn arc_length_finite_at_zero_radius(&self) -> bool {
        self.zero_radius != ZeroRadiusEnd::SpiralsInInfiniteLength
    }

    /// Is the tangent angle bounded toward ρ = 0? (α > 1)
    pub fn tangent_angle_finite_at_zero_radius(&self) -> bool {
        self.zero_radius == ZeroRadiusEnd::EndsWithTangent
    }

    /// Is the arc length from any point to ρ = ∞ finite? (α < 0)
    pub fn arc_length_finite_at_infinite_radius(&self) -> bool {
        self.infinite_radius == InfiniteRadiusEnd::InflectionAtFiniteDistance
    }

    /// Is the tangent angle bounded toward ρ = ∞? (α < 1)
    pub fn tangent_angle_finite_at_infinite_radius(&self) -> bool {
        self.infinite_radius != InfiniteRadiusEnd::SpiralsOut
    }
}
