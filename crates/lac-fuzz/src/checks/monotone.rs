//! `monotone`: [`lac::RationalCubic::curvature_monotonicity`]. Invariant: its verdict,
//! proven or not, is never contradicted by sampling the curvature (within its rounding).

use lac::{Monotonicity, RationalCubic};

use super::{pt, typed};

/// The checks of a `monotone` input.
pub(super) fn check(points: &[[f64; 2]; 4], weights: [f64; 4]) -> Result<bool, String> {
    let Some(curve) = typed(RationalCubic::new(points.map(pt), weights))? else {
        return Ok(false);
    };
    let Some(report) = typed(curve.curvature_monotonicity())? else {
        return Ok(false);
    };
    check_verdict(&curve, report.verdict, report.proven)?;
    Ok(true)
}

/// A verdict is never contradicted by sampling the curvature (within its rounding).
fn check_verdict(curve: &RationalCubic, verdict: Monotonicity, proven: bool) -> Result<(), String> {
    if let Monotonicity::NotMonotone { t } = verdict {
        if !(0.0..=1.0).contains(&t) {
            return Err(format!("sign change reported at t = {t}"));
        }
        return Ok(());
    }
    if !proven {
        return Ok(());
    }
    let ks: Vec<f64> = (0..=256)
        .map(|i| curve.signed_curvature(i as f64 / 256.0))
        .collect();
    if ks.iter().any(|k| !k.is_finite()) {
        return Ok(());
    }
    let big = ks.iter().fold(0.0f64, |m, k| m.max(k.abs()));
    let slack = 1e-9 * big;
    for w in ks.windows(2) {
        let bad = match verdict {
            Monotonicity::Increasing => w[1] < w[0] - slack,
            Monotonicity::Decreasing => w[1] > w[0] + slack,
            Monotonicity::Constant => (w[1] - w[0]).abs() > slack,
            Monotonicity::NotMonotone { .. } => false,
        };
        if bad {
            return Err(format!(
                "proven {verdict:?}, but sampled curvature goes {:e} → {:e}",
                w[0], w[1]
            ));
        }
    }
    Ok(())
}
