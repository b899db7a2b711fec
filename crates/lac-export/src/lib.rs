//! CAD export: a log-aesthetic curve (segment, compound curve, path, spline, space segment) as rational
//! degree-3 B-splines within a tolerance, with the achieved deviation measured densely, in
//! DXF, STEP, IGES, SVG (plain cubics) or JSON.
//!
//! A curve comes as the parts it is fitted by ([`ExportCurve`], `parts.rs`). Planar
//! curves are replaced by the quasi-aesthetic rational cubics of
//! [`lac::ToBezier::to_rational_cubics`] (G2 joins, each piece's curvature proven monotone;
//! SVG takes the plain cubics of [`lac::ToBezier::to_cubics`]), space segments by the C1
//! cubic Hermite pieces of [`lac::SpaceSegment::to_cubics`] (no monotonicity proof). The pieces become
//! one clamped B-spline ([`Nurbs`]), or one single-span curve per piece. The deviation
//! reported is [`certify::deviation`] of the B-spline as written; when it exceeds the
//! tolerance (the fits measure their own deviation more coarsely) the fit is repeated with
//! a smaller target, and the export is refused when that does not help.
//!
//! A multi-segment path is fitted segment by segment (each segment's chain interpolates its
//! ends, end tangents and end curvatures), so every path joint is a knot of the B-spline
//! and the joins there are as the path is: G2 for a G2 path, G1 (curvature jumping as in
//! the path) for a G1 path. A closed path is written as a clamped curve whose ends meet. A
//! spline through points is fitted the same way, piece by piece (a span through an
//! inflection is two pieces meeting at zero curvature).
//!
//! A refused export is an [`Error`]: its [`Error::kind`] and message are what the front ends
//! (`lac export`, the editor's server, the Python bindings) show, through `lac-io`'s JSON
//! error body.

pub mod certify;
pub mod dxf;
mod error;
pub mod iges;
pub mod json;
mod number;
pub mod nurbs;
pub mod parts;
pub mod step;
pub mod svg;

use std::time::{SystemTime, UNIX_EPOCH};

use serde::{Deserialize, Serialize};

use lac::{Curve, QuasiCurve, Tolerance, MIN_RELATIVE_TOLERANCE};
use lac::{SegmentChain, ToBezier};

use certify::{deviation, Exact, Piece, PiecesExact, PlaneExact, SpaceExact};
pub use error::{Error, Result};
use json::{ExportDocument, NurbsRow};
pub use nurbs::Nurbs;
use nurbs::Span;
pub use parts::{path_pieces, segment_pieces, spline_pieces, ExportCurve, Parts};

/// The default tolerance: 1e-6 model units (millimetres in DXF, STEP and IGES).
pub const DEFAULT_TOLERANCE: f64 = 1e-6;

/// Samples per piece, in each direction, of the deviation measured.
pub const SAMPLES_PER_PIECE: usize = 64;

/// Fits tried with ever smaller targets before the export is refused.
const ATTEMPTS: usize = 4;

/// The file formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Format {
    /// DXF R2000, SPLINE entities.
    Dxf,
    /// STEP AP214, rational B-spline curves in a wireframe shape.
    Step,
    /// IGES 5.3, entity 126.
    Iges,
    /// SVG, plain cubic Béziers (planar curves).
    Svg,
    /// JSON: degree, control points, weights, knots.
    Json,
}

/// What the file says about itself.
#[derive(Clone, Debug, PartialEq)]
pub struct Meta {
    /// The product's (and file's) name.
    pub name: String,
    /// When it was written, ISO 8601 (`2026-11-23T14:00:00`).
    pub timestamp: String,
    /// The writing program's version.
    pub version: String,
}

impl Meta {
    /// The file named `name`, written now by this version of lac.
    pub fn now(name: impl Into<String>) -> Meta {
        Meta {
            name: name.into(),
            timestamp: timestamp(SystemTime::now()),
            version: env!("CARGO_PKG_VERSION").to_string(),
        }
    }
}

/// `YYYY-MM-DDTHH:MM:SS` (UTC) of `time`.
pub fn timestamp(time: SystemTime) -> String {
    let secs = time
        .duration_since(UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0);
    let (days, rest) = ((secs / 86_400) as i64, secs % 86_400);
    // Days to civil date (proleptic Gregorian), after H. Hinnant's `civil_from_days`.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}

/// How an export went: `lac export`'s report.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ExportReport {
    /// The format written.
    pub format: Format,
    /// `"segment"`, `"compound"`, `"path"`, `"spline"` or `"space"`.
    pub kind: String,
    /// Bézier pieces (knot spans).
    pub pieces: usize,
    /// Each piece written as a curve of its own (`--pieces`)?
    pub single_spans: bool,
    /// The tolerance asked, model units.
    pub tolerance: f64,
    /// The largest deviation from the exact curve, model units, measured densely on what
    /// was written (a sampled two-sided distance, [`certify::deviation`]).
    pub max_deviation: f64,
    /// The fit's own measure of its largest deviation, model units.
    pub fit_deviation: f64,
    /// Samples per piece of `max_deviation`, in each direction.
    pub samples_per_piece: usize,
    /// Arc length of the exact curve.
    pub arc_length: f64,
    /// Continuity at the joins: `"G2"` (planar; a G2 path), `"G1"` (a G1 path: G2 within
    /// its segments, G1 at its joints) or `"C1"` (space).
    pub continuity: String,
    /// Every piece's curvature proven monotone (planar rational pieces); null for space
    /// curves, for which nothing is proven about curvature.
    pub monotone_proven: Option<bool>,
    /// Weights all 1 (plain cubics)?
    pub polynomial: bool,
    /// The length unit the CAD formats declare.
    pub units: String,
}

/// The written document and its report.
#[derive(Clone, Debug, PartialEq)]
pub struct Exported {
    /// The file's text.
    pub document: String,
    /// How it went.
    pub report: ExportReport,
}

/// An approximation before writing.
struct Fitted {
    nurbs: Nurbs,
    fit_deviation: f64,
    monotone_proven: Option<bool>,
}

/// Export `curve` as `format` within `tolerance`, one curve or (`single_spans`) one per
/// piece.
pub fn export(
    curve: &ExportCurve,
    format: Format,
    tolerance: Tolerance,
    single_spans: bool,
    meta: &Meta,
) -> Result<Exported> {
    let (length, kind, continuity) = (curve.length, curve.kind, curve.continuity);
    let parts = &curve.parts;
    if format == Format::Svg && matches!(parts, Parts::Space(_)) {
        return Err(Error::SvgOfSpaceCurve);
    }
    let tol = checked_tolerance(tolerance, length)? * length;
    let plain = format == Format::Svg;
    let mut target = tol;
    let mut reached = f64::INFINITY;
    for _ in 0..ATTEMPTS {
        let fitted = fit(parts, target, plain)?;
        let measured = match parts {
            Parts::Whole(chain) => measure(&PlaneExact(*chain), &fitted.nurbs)?,
            Parts::Pieces(pieces) => measure(&PiecesExact(pieces), &fitted.nurbs)?,
            Parts::Space(s) => measure(&SpaceExact(s), &fitted.nurbs)?,
        };
        if measured <= tol {
            let curves = if single_spans {
                fitted.nurbs.single_spans()
            } else {
                vec![fitted.nurbs.clone()]
            };
            let report = ExportReport {
                format,
                kind: kind.to_string(),
                pieces: fitted.nurbs.span_count(),
                single_spans,
                tolerance: tol,
                max_deviation: measured,
                fit_deviation: fitted.fit_deviation,
                samples_per_piece: SAMPLES_PER_PIECE,
                arc_length: length,
                continuity: continuity.to_string(),
                monotone_proven: fitted.monotone_proven,
                polynomial: fitted.nurbs.is_polynomial(),
                units: "mm".to_string(),
            };
            let document = write(format, &curves, &fitted.nurbs, meta, &report);
            return Ok(Exported { document, report });
        }
        reached = reached.min(measured);
        target *= (0.8 * tol / measured).min(0.5);
    }
    Err(lac::Error::ToleranceNotMet {
        tolerance: tol / length,
        reached: reached / length,
    }
    .into())
}

/// The tolerance relative to the arc length. A positive tolerance below
/// [`MIN_RELATIVE_TOLERANCE`] of the arc length cannot be met (double precision cannot
/// measure the deviation that finely): `tolerance_not_met`, not an invalid request.
fn checked_tolerance(tolerance: Tolerance, length: f64) -> Result<f64> {
    let (Tolerance::Absolute(t) | Tolerance::Relative(t)) = tolerance;
    let relative = match tolerance {
        Tolerance::Absolute(t) => t / length,
        Tolerance::Relative(t) => t,
    };
    if t.is_finite() && relative > 0.0 && relative < MIN_RELATIVE_TOLERANCE {
        return Err(Error::ToleranceBelowPrecision {
            tolerance: t,
            relative,
            length,
        });
    }
    Ok(tolerance.relative_to(length)?)
}

fn measure(exact: &dyn Exact, nurbs: &Nurbs) -> Result<f64> {
    let d = deviation(exact, nurbs, SAMPLES_PER_PIECE)?;
    if d.is_finite() {
        Ok(d)
    } else {
        Err(bad("the deviation of an export"))
    }
}

/// A numerical failure in computing `what` (a defect).
fn bad(what: &'static str) -> Error {
    lac::Error::NumericalFailure { what }.into()
}

/// The length of the polyline through 513 points of `curve` at equal parameter steps: its
/// arc length to a relative (Δθ)²/24, Δθ the turning per step, however unevenly it moves.
fn polyline_length(curve: &lac::RationalCubic) -> f64 {
    use kurbo::ParamCurve;
    const STEPS: usize = 512;
    let points: Vec<kurbo::Point> = (0..=STEPS)
        .map(|j| curve.eval(j as f64 / STEPS as f64))
        .collect();
    points
        .windows(2)
        .map(|w| certify::norm([w[1].x - w[0].x, w[1].y - w[0].y, 0.0]))
        .sum()
}

/// The largest control-point coordinate whose B-spline can be evaluated and measured: the
/// power basis of a span multiplies coordinates by up to 6 and sums four of them, so one of
/// 2^1018 (about 2.8e306) stays within double range; larger ones are the caller's to scale.
const LARGEST_COORDINATE: f64 = 2.8e306;

/// An error unless every control point of `spans` is within [`LARGEST_COORDINATE`].
fn representable(spans: &[Span]) -> Result<()> {
    let largest = spans
        .iter()
        .flat_map(|s| s.points.iter().flatten())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    if largest <= LARGEST_COORDINATE {
        Ok(())
    } else {
        Err(lac::Error::Unrepresentable {
            what: "B-spline (control points too near the largest double to evaluate)",
        }
        .into())
    }
}

/// The B-spline of the pieces fitted to `curve` within `target` (model units).
fn fit(parts: &Parts, target: f64, plain: bool) -> Result<Fitted> {
    let bad = || bad("the B-spline of an export");
    let fit = |c: &dyn SegmentChain, target: f64| -> Result<QuasiCurve> {
        Ok(if plain {
            c.to_cubics(Tolerance::Absolute(target))?
        } else {
            c.to_rational_cubics(Tolerance::Absolute(target))?
        })
    };
    let quasi_of = |c: &dyn SegmentChain| fit(c, target);
    // A piece of a chain (a path's segment, a spline's half) shorter than the tolerance is
    // fitted within its own length: the curve's tolerance, not the piece's, was asked for.
    let piece_of = |c: &dyn SegmentChain| fit(c, target.min(c.arc_length()));
    let planar = |chains: &[(QuasiCurve, f64)]| -> Result<Fitted> {
        let pieces = || chains.iter().flat_map(|(q, _)| &q.pieces);
        let spans: Vec<Span> = pieces()
            .map(|p| Span::from_rational_cubic(&p.curve))
            .collect();
        // The knots at the pieces' arc lengths (by a fine polyline: a piece next to a flat
        // end has weights far from 1 and a speed that varies by orders of magnitude, where
        // the fixed quadrature of `RationalCubic::arc_length` can be off by a third and an
        // adaptive one takes seconds), each chain's scaled to the exact length of its curve,
        // so that a knot's parameter is the curve's arc length there.
        let mut breaks = vec![0.0];
        for (q, length) in chains {
            let lengths: Vec<f64> = q.pieces.iter().map(|p| polyline_length(&p.curve)).collect();
            let total: f64 = lengths.iter().sum();
            let scale = if total > 0.0 && total.is_finite() && *length > 0.0 {
                length / total
            } else {
                1.0
            };
            for l in lengths {
                breaks.push(breaks[breaks.len() - 1] + l * scale);
            }
        }
        representable(&spans)?;
        // Pieces fitted one by one within `target` meet within it (what is written is
        // certified below).
        let nurbs = Nurbs::from_spans(&spans, &breaks, true, target).map_err(|_| bad())?;
        Ok(Fitted {
            nurbs,
            fit_deviation: chains
                .iter()
                .fold(0.0f64, |m, (q, length)| m.max(q.max * length)),
            monotone_proven: Some(pieces().all(|p| p.monotonicity.proven)),
        })
    };
    match parts {
        Parts::Whole(chain) => planar(&[(quasi_of(*chain)?, chain.arc_length())]),
        Parts::Pieces(pieces) => {
            let chains = pieces
                .iter()
                .map(|piece| match piece {
                    Piece::Segment(seg) => {
                        Ok((piece_of(seg.as_ref())?, Curve::arc_length(seg.as_ref())))
                    }
                    Piece::Line(a, b) => Ok((straight(*a, *b)?, piece.length())),
                })
                .collect::<Result<Vec<_>>>()?;
            planar(&chains)
        }
        Parts::Space(seg) => {
            let cubics = seg.to_cubics(Tolerance::Absolute(target))?;
            let spans: Vec<Span> = cubics
                .pieces
                .iter()
                .map(|p| Span {
                    points: p.points.map(|q| q.to_array()),
                    weights: [1.0; 4],
                })
                .collect();
            let mut breaks = vec![0.0];
            breaks.extend(cubics.pieces.iter().map(|p| p.s.1));
            representable(&spans)?;
            let nurbs = Nurbs::from_spans(&spans, &breaks, false, target).map_err(|_| bad())?;
            Ok(Fitted {
                nurbs,
                fit_deviation: cubics.max_deviation,
                monotone_proven: None,
            })
        }
    }
}

/// A straight piece from `a` to `b` as a one-piece chain: the cubic with its inner control
/// points at the thirds (weights 1), of constant (zero) curvature.
fn straight(a: kurbo::Point, b: kurbo::Point) -> Result<QuasiCurve> {
    let at = |t: f64| a + t * (b - a);
    let curve = lac::RationalCubic::new([a, at(1.0 / 3.0), at(2.0 / 3.0), b], [1.0; 4])?;
    Ok(QuasiCurve {
        pieces: vec![lac::QuasiPiece {
            curve,
            monotonicity: lac::MonotonicityReport {
                verdict: lac::Monotonicity::Constant,
                proven: true,
            },
            turning: (0.0, 0.0),
            max_deviation: 0.0,
        }],
        rms: 0.0,
        max: 0.0,
    })
}

/// The document of `curves` in `format`.
fn write(
    format: Format,
    curves: &[Nurbs],
    whole: &Nurbs,
    meta: &Meta,
    report: &ExportReport,
) -> String {
    let uncertainty = (0.1 * report.tolerance).min(1e-7);
    match format {
        Format::Dxf => dxf::write(curves),
        Format::Step => step::write(curves, meta, uncertainty),
        Format::Iges => iges::write(curves, meta, uncertainty),
        Format::Svg => {
            let mut path = kurbo::BezPath::new();
            for i in 0..whole.span_count() {
                let p = whole.span(i).points.map(|q| kurbo::Point::new(q[0], q[1]));
                if i == 0 {
                    path.move_to(p[0]);
                }
                path.curve_to(p[1], p[2], p[3]);
            }
            svg::write(&path)
        }
        Format::Json => {
            let document = ExportDocument {
                curves: curves.iter().map(NurbsRow::from).collect(),
                report: report.clone(),
            };
            to_line(&document) + "\n"
        }
    }
}

/// The document as one line of JSON, as the front ends write their reports: serialising it
/// cannot fail (plain numbers, strings and arrays), and would write the JSON error line.
fn to_line(document: &ExportDocument) -> String {
    serde_json::to_string(document).unwrap_or_else(|e| {
        serde_json::json!({"error": {
            "kind": "internal",
            "message": format!("a report did not serialise: {e}"),
        }})
        .to_string()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn timestamps_are_utc_calendar_dates() {
        let at = |s| timestamp(UNIX_EPOCH + Duration::from_secs(s));
        assert_eq!(at(0), "1970-01-01T00:00:00");
        assert_eq!(at(951_782_400), "2000-02-29T00:00:00");
        assert_eq!(at(1_795_000_000), "2026-11-18T11:06:40");
    }
}
