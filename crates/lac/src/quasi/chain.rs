//! The tolerance-driven chain: pieces are taken greedily from the first point, each as
//! long as possible (guided by the error model d ∝ Θ⁶ of a G2 cubic) with max ≤ tolerance
//! and curvature proven monotone in the curve's direction. Neighbouring pieces share the
//! curve's point, tangent and curvature at their join, so the chain is G2.

use super::deviation::has_flat_end;
use super::fit::{fit_span, Fitted};
use super::{Kind, QuasiPiece, TurningCurve};
use crate::family::monotone::Monotonicity;
use crate::foundation::error::{Error, Result};

/// Most pieces a tolerance may ask for: about a second of work at most, and far beyond
/// what a CAD system wants of one curve.
pub const MAX_PIECES: usize = 1000;

/// Pieces fitted before their average turning projects the chain's length.
const PROJECT_AFTER: usize = 8;

/// Is this piece's monotonicity the curve's, proven (or constant within rounding where the
/// curve's curvature hardly changes over the piece)?
fn faithful(piece: &QuasiPiece, expected: Monotonicity, k0: f64, k1: f64) -> bool {
    let m = piece.monotonicity;
    match m.verdict {
        Monotonicity::Constant => {
            expected == Monotonicity::Constant || (k1 - k0).abs() <= 1e-9 * k0.abs().max(k1.abs())
        }
        v => m.proven && v == expected,
    }
}

/// The pieces from the curve's start to its end, each as long as a maximum deviation of
/// `tol` (caller's units) and a faithful monotonicity allow.
pub(super) fn greedy(
    curve: &(impl TurningCurve + ?Sized),
    tol: f64,
    kind: Kind,
    expected: Monotonicity,
) -> Result<Vec<Fitted>> {
    let total = curve.total_turning();
    // Accept a little below the tolerance: the maximum found is a value attained, within
    // about 1e-6 (relative) of the true maximum.
    let accept = tol * (1.0 - 1e-4);
    let mut out: Vec<Fitted> = Vec::new();
    let mut start = 0.0;
    let mut width = total;
    // Next to a flat end (an inflection, κ ∝ s^p with p = −1/α) a piece of length ℓ turns
    // by ∝ ℓ^(p+1) and deviates by about ∝ ℓ^(p+2): nearly linear in its turning, far from
    // the error model's Θ⁶. Such a curve's widths are searched longer, and down to 1e-15
    // of the whole turning.
    let flat = has_flat_end(curve);
    let narrowest = if flat { 1e-15 } else { 1e-9 };
    while start < total {
        // Stop as soon as the pieces so far say the chain would be too long: the turning
        // left, at the average turning per piece so far. (Not on the first few: next to a
        // flat start, an inflection, each piece turns ten times as much as the last.)
        let projected = if out.len() >= PROJECT_AFTER {
            out.len() as f64 * total / start
        } else {
            0.0
        };
        if out.len() >= MAX_PIECES || projected > 2.0 * MAX_PIECES as f64 {
            return Err(Error::TooManyPieces {
                tolerance: tol / curve.length(),
                max_pieces: MAX_PIECES,
            });
        }
        let remaining = total - start;
        width = width.min(remaining);
        let mut best: Option<(f64, Fitted)> = None;
        let mut worst_seen = f64::INFINITY;
        for _ in 0..if flat { 48 } else { 16 } {
            // Never leave a sliver: a remainder shorter than half a piece is shared out.
            // (Not next to a flat end, where a remainder that turns by little is long.)
            if !flat && width < remaining && remaining - width < 0.5 * width {
                width = 0.5 * remaining;
            }
            let end = if width >= remaining {
                total
            } else {
                start + width
            };
            let (error, accepted) = match fit_span(curve, start, end, kind) {
                Ok(trial) => {
                    let error = trial.piece.max_deviation;
                    let [ka, kb] = trial.end_kappa;
                    // A plain cubic cannot have constant curvature: for a circular arc
                    // only the deviation is asked of it.
                    let ok = error <= accept
                        && ((kind == Kind::Polynomial && expected == Monotonicity::Constant)
                            || faithful(&trial.piece, expected, ka, kb));
                    (error, ok.then_some(trial.fitted))
                }
                Err(_) => (f64::INFINITY, None),
            };
            if let Some(fitted) = accepted {
                let done = width >= remaining;
                best = Some((width, fitted));
                // Grow when the error model promises a clearly longer piece.
                let grow = (accept / error.max(f64::MIN_POSITIVE)).powf(1.0 / 6.0) * 0.97;
                if done || grow < 1.05 {
                    break;
                }
                width = (width * grow.min(2.0)).min(remaining);
            } else {
                worst_seen = worst_seen.min(error);
                let shrink = if error.is_finite() {
                    ((accept / error).powf(1.0 / 6.0) * 0.9).clamp(0.2, 0.9)
                } else {
                    0.5
                };
                let smaller = width * shrink;
                if let Some((w, _)) = &best {
                    if smaller <= *w {
                        break;
                    }
                }
                width = smaller;
                if width < narrowest * total {
                    break;
                }
            }
        }
        let Some((w, fitted)) = best else {
            return Err(Error::ToleranceNotMet {
                tolerance: tol / curve.length(),
                reached: worst_seen / curve.length(),
            });
        };
        start = fitted.piece.turning.1;
        out.push(fitted);
        width = w;
    }
    Ok(out)
}
