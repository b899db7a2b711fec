//! `export`: [`lac_export::export`] of a solved segment, compound curve, path or space
//! segment, in every file format. Invariants: a report of finite figures whose measured
//! deviation is within the tolerance asked; a document without a non-finite number; for
//! JSON, well-formed clamped B-splines (knots ascending, weights positive) that start and
//! end at the exact curve's ends, the pieces of `--pieces` meeting end to start, evaluated
//! here by de Boor's algorithm.

use lac::Tolerance;
use lac_export::json::{ExportDocument, NurbsRow};
use lac_export::{Exported, Format, Meta};

use super::{build, distance, finite, typed, Built};
use crate::Input;

/// The checks of an `export` input.
pub(super) fn check(
    curve: &Input,
    format: Format,
    tolerance: f64,
    relative: bool,
    single_spans: bool,
) -> Result<bool, String> {
    let Some(built) = build(curve)? else {
        return Ok(false);
    };
    let tolerance = if relative {
        Tolerance::Relative(tolerance)
    } else {
        Tolerance::Absolute(tolerance)
    };
    let Some(curve) = typed(built.as_export())? else {
        return Ok(false);
    };
    let Some(exported) = typed(lac_export::export(
        &curve,
        format,
        tolerance,
        single_spans,
        &Meta {
            name: "fuzz".to_string(),
            timestamp: "2026-11-23T00:00:00".to_string(),
            version: "0".to_string(),
        },
    ))?
    else {
        return Ok(false);
    };
    check_export(&built, tolerance, &exported)?;
    Ok(true)
}

/// An export: a report of finite figures whose measured deviation is within the tolerance
/// asked; a document without a non-finite number; for JSON, well-formed clamped B-splines
/// (knots ascending, weights positive) that start and end at the exact curve's ends, the
/// pieces of `--pieces` meeting end to start, evaluated here by de Boor's algorithm.
fn check_export(built: &Built, tolerance: Tolerance, exported: &Exported) -> Result<(), String> {
    let report = &exported.report;
    let (start, end, len) = built.ends()?;
    finite(
        "export report",
        &[
            report.tolerance,
            report.max_deviation,
            report.fit_deviation,
            report.arc_length,
        ],
    )?;
    let asked = match tolerance {
        Tolerance::Absolute(t) => t,
        Tolerance::Relative(t) => t * len,
    };
    if (report.tolerance - asked).abs() > 1e-12 * asked {
        return Err(format!(
            "export tolerance {:e} reported for {asked:e} asked",
            report.tolerance
        ));
    }
    // Both finite (checked above).
    if report.max_deviation > report.tolerance || report.pieces == 0 {
        return Err(format!(
            "export deviation {:e} over its tolerance {:e} ({} pieces)",
            report.max_deviation, report.tolerance, report.pieces
        ));
    }
    let doc = &exported.document;
    if doc.is_empty() || doc.contains("NaN") || doc.contains("inf") {
        return Err(format!("{:?} document empty or not finite", report.format));
    }
    if report.format != Format::Json {
        return Ok(());
    }
    let parsed: ExportDocument =
        serde_json::from_str(doc).map_err(|e| format!("export JSON does not parse: {e}"))?;
    let magnitude = start.iter().chain(&end).fold(0.0f64, |m, x| m.max(x.abs()));
    let near = report.tolerance + 64.0 * f64::EPSILON * magnitude;
    let mut previous_end: Option<Vec<f64>> = None;
    for row in &parsed.curves {
        let n = row.control_points.len();
        let well_formed = row.degree == 3
            && n >= 4
            && row.weights.len() == n
            && row.knots.len() == n + 4
            && row.knots.windows(2).all(|w| w[0] <= w[1])
            && row.knots[3] < row.knots[n]
            && row.weights.iter().all(|w| w.is_finite() && *w > 0.0)
            && row
                .control_points
                .iter()
                .all(|p| p.len() == row.dimension && p.iter().all(|x| x.is_finite()));
        if !well_formed {
            return Err("exported B-spline malformed".to_string());
        }
        let a = nurbs_point(row, row.knots[3]);
        if let Some(b) = &previous_end {
            if distance(&a, b) > near {
                return Err(format!("exported pieces apart by {:e}", distance(&a, b)));
            }
        }
        previous_end = Some(nurbs_point(row, row.knots[n]));
    }
    let first = parsed.curves.first().map(|r| nurbs_point(r, r.knots[3]));
    let last = previous_end;
    for (what, got, want) in [("start", first, start), ("end", last, end)] {
        let got = got.ok_or("an export without curves")?;
        if distance(&got, &want) > near {
            return Err(format!(
                "exported curve's {what} {:e} from the exact one's (tolerance {:e})",
                distance(&got, &want),
                report.tolerance
            ));
        }
    }
    Ok(())
}

/// The point at `u` of a clamped rational cubic B-spline, by de Boor's algorithm in
/// homogeneous coordinates.
fn nurbs_point(row: &NurbsRow, u: f64) -> Vec<f64> {
    const P: usize = 3;
    let (k, n, dim) = (&row.knots, row.control_points.len(), row.dimension);
    let mut i = P;
    while i + 1 < n && k[i + 1] <= u {
        i += 1;
    }
    let mut d: Vec<Vec<f64>> = (0..=P)
        .map(|j| {
            let w = row.weights[i - P + j];
            let mut h: Vec<f64> = row.control_points[i - P + j]
                .iter()
                .map(|x| x * w)
                .collect();
            h.push(w);
            h
        })
        .collect();
    for r in 1..=P {
        for j in (r..=P).rev() {
            let a = (u - k[i - P + j]) / (k[i + 1 + j - r] - k[i - P + j]);
            let prev = d[j - 1].clone();
            for (x, y) in d[j].iter_mut().zip(prev) {
                *x = (1.0 - a) * y + a * *x;
            }
        }
    }
    let w = d[P][dim];
    let mut p: Vec<f64> = d[P][..dim].iter().map(|x| x / w).collect();
    p.resize(3, 0.0);
    p
}
