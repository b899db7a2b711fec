//! `analysis`: [`lac::curvature_plot`] and [`lac::log_curvature_graph`] of a chain of
//! rational cubics. Invariants: every point of the plot and of the graph, and the fitted
//! line, finite.

use lac::{curvature_plot, log_curvature_graph, RationalCubic};

use super::{finite, pt, typed};

/// The checks of an `analysis` input.
pub(super) fn check(
    pieces: &[([[f64; 2]; 4], [f64; 4])],
    per_piece: usize,
) -> Result<bool, String> {
    let Some(curves) = typed(
        pieces
            .iter()
            .map(|(p, w)| RationalCubic::new(p.map(pt), *w))
            .collect::<lac::Result<Vec<_>>>(),
    )?
    else {
        return Ok(false);
    };
    let Some(plot) = typed(curvature_plot(&curves, per_piece))? else {
        return Ok(false);
    };
    for p in &plot {
        finite(
            "curvature plot",
            &[p.s, p.point.x, p.point.y, p.kappa, p.dkappa_ds],
        )?;
    }
    let graph = log_curvature_graph(&plot);
    for (x, y) in &graph.points {
        finite("logarithmic curvature graph", &[*x, *y])?;
    }
    if let Some(fit) = graph.fit {
        finite(
            "LCG fit",
            &[
                fit.alpha,
                fit.intercept,
                fit.rms_residual,
                fit.max_residual,
                fit.log_rho.0,
                fit.log_rho.1,
            ],
        )?;
    }
    Ok(true)
}
