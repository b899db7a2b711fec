//! The logarithmic curvature graph (LCG) of a log-aesthetic piece.

use crate::segment::Segment;

/// The logarithmic curvature graph of a log-aesthetic piece, in the caller's units: the
/// straight line `log(ρ ds/dρ) = α log ρ + intercept` over `log ρ ∈ log_rho` (natural
/// logarithms; seed 000 eq. 1, SPEC §1).
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

impl Segment {
    /// The segment's logarithmic curvature graph, or `None` for a circular arc (Λ = 0,
    /// where ρ is constant and the graph degenerates to a point at infinity).
    ///
    /// ```
    /// use kurbo::Point;
    /// use lac::Segment;
    /// let seg = Segment::from_control_points(
    ///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.5, 1.0)], -1.0)?;
    /// let lcg = seg.lcg().unwrap();
    /// assert_eq!(lcg.alpha, -1.0);
    /// # Ok::<(), lac::Error>(())
    /// ```
    pub fn lcg(&self) -> Option<LcgLine> {
        let lambda = self.form.lambda;
        if lambda <= 0.0 {
            return None;
        }
        let ln_scale = self.scale().ln();
        Some(LcgLine {
            alpha: self.alpha,
            intercept: (1.0 - self.alpha) * ln_scale - lambda.ln(),
            log_rho: (ln_scale + self.first.ln_rho, ln_scale + self.last.ln_rho),
        })
    }
}
