//! Geometry verdicts: whether the curvature of a plot, or of a chain of Bézier pieces, is
//! monotone, and why not, for [`LcgReport`](super::LcgReport)'s note.
//!
//! These are geometry, not wire shapes.

// TODO(core): moves into lac. `plot_not_monotone`, `inflection` and `chain_not_monotone`
// (with `PLOT_ZERO`) belong to the core crate; they stay together here until the core
// restructuring has merged, then move as one piece.

use lac::{CurvaturePoint, Monotonicity, MonotonicityReport, RationalCubic};

use super::short;

/// The plot's dκ/ds (or κ) counts as zero where it is below this share of its scale: the
/// rounding of a circular arc's exact zero is far below it, a real change of sign far above.
const PLOT_ZERO: f64 = 1e-9;

/// Why the curvature of a sampled plot is not monotone, if it shows that: dκ/ds, made
/// dimensionless by the plot's length and largest curvature, takes both signs beyond
/// [`PLOT_ZERO`], or the curvature itself does.
pub(super) fn plot_not_monotone(plot: &[CurvaturePoint]) -> Option<String> {
    let (first, last) = (plot.first()?, plot.last()?);
    let length = (last.s - first.s).abs();
    let kmax = plot.iter().fold(0.0f64, |m, p| m.max(p.kappa.abs()));
    if !(length > 0.0 && length.is_finite() && kmax > 0.0 && kmax.is_finite()) {
        return None;
    }
    let scale = length / kmax;
    let mut sign = None;
    for p in plot {
        let d = p.dkappa_ds * scale;
        // NaN counts as zero: it shows no direction.
        if d.is_nan() || d.abs() <= PLOT_ZERO {
            continue;
        }
        match sign {
            None => sign = Some(d > 0.0),
            Some(up) if up != (d > 0.0) => {
                return Some(format!("dκ/ds changes sign near s = {}", short(p.s)))
            }
            _ => {}
        }
    }
    inflection(plot)
}

/// Where the curvature of a plot changes sign (beyond [`PLOT_ZERO`] of its largest value).
pub(super) fn inflection(plot: &[CurvaturePoint]) -> Option<String> {
    let kmax = plot.iter().fold(0.0f64, |m, p| m.max(p.kappa.abs()));
    let mut sign = None;
    for p in plot {
        if p.kappa.is_nan() || p.kappa.abs() <= PLOT_ZERO * kmax {
            continue;
        }
        match sign {
            None => sign = Some(p.kappa > 0.0),
            Some(left) if left != (p.kappa > 0.0) => {
                return Some(format!(
                    "the curvature changes sign near s = {}, an inflection",
                    short(p.s)
                ))
            }
            _ => {}
        }
    }
    None
}

/// Why the curvature of a chain of pieces with these verdicts is not monotone: a piece's is
/// proven not to be, two pieces' are proven to run in opposite directions, or it jumps the
/// wrong way at a joint.
pub(super) fn chain_not_monotone(
    pieces: &[RationalCubic],
    verdicts: &[MonotonicityReport],
) -> Option<String> {
    let n = pieces.len();
    let way = |up: bool| if up { "increases" } else { "decreases" };
    // The direction so far, and the piece that set it.
    let mut direction: Option<(bool, usize)> = None;
    let mut follow = |up: bool, k: usize, what: &str| match direction {
        None => {
            direction = Some((up, k));
            None
        }
        Some((was, j)) if was != up => Some(format!(
            "it {} along piece {} of {n} and {} {what}",
            way(was),
            j + 1,
            way(up)
        )),
        _ => None,
    };
    for (k, v) in verdicts.iter().enumerate() {
        if k > 0 {
            let (before, after) = (
                pieces[k - 1].signed_curvature(1.0),
                pieces[k].signed_curvature(0.0),
            );
            let jump = after - before;
            if jump.abs() > PLOT_ZERO * before.abs().max(after.abs()) {
                let at = format!("at the joint of pieces {k} and {}", k + 1);
                if let Some(why) = follow(jump > 0.0, k, &at) {
                    return Some(why);
                }
            }
        }
        // An unproven verdict is dκ/ds zero within rounding (a circular arc): no direction.
        if !v.proven {
            continue;
        }
        match v.verdict {
            Monotonicity::NotMonotone { t } => {
                return Some(format!(
                    "dκ/ds changes sign inside piece {} of {n}, at t = {}",
                    k + 1,
                    short(t)
                ))
            }
            Monotonicity::Constant => {}
            Monotonicity::Increasing | Monotonicity::Decreasing => {
                let up = v.verdict == Monotonicity::Increasing;
                let along = format!("along piece {}", k + 1);
                if let Some(why) = follow(up, k, &along) {
                    return Some(why);
                }
            }
        }
    }
    None
}
