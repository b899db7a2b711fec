//! The logarithmic curvature graph (LCG) of a log-aesthetic piece.

/// The logarithmic curvature graph of a log-aesthetic piece, in the caller's units: the
/// straight line `log(ρ ds/dρ) = α log ρ + intercept` over `log ρ ∈ log_rho` (natural
/// logarithms; seed 000 eq. 1, docs/math.md §1).
///
/// For a piece of the standard form scaled by σ, `intercept = (1 − α) ln σ − ln Λ`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LcgLine {
    /// The slope α.
    pub alpha: f64,
    /// The value of log(ρ ds/dρ) at log ρ = 0.
    pub intercept: f64,
    /// The range of log ρ covered by the piece, in the order of travel.
    pub log_rho: (f64, f64),
}

impl LcgLine {
    /// log(ρ ds/dρ) at `log_rho`.
    pub fn at(&self, log_rho: f64) -> f64 {
        self.alpha * log_rho + self.intercept
    }
}
