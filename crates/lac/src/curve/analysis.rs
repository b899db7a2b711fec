//! Curvature analysis of any planar curve given as (rational) cubic Bézier pieces, or of a
//! log-aesthetic curve: the curvature plot, the logarithmic curvature graph (LCG) and a
//! least-squares estimate of its slope α (Harada's measurement; seed 001 §6, docs/math.md §1).
//!
//! The LCG of a curve plots x = ln ρ against y = ln(ρ |ds/dρ|). With κ = ±1/ρ,
//! dρ/ds = −(1/κ²) dκ/ds·sign κ (seed 001 eq. 6.1), so y = ln(|κ| / |dκ/ds|): no numerical
//! differentiation is needed, since dκ/ds of a rational cubic is a closed form. The line
//! y = αx + c is fitted by least squares with the trapezoid weights of x, i.e. minimising
//! ∫ (y − αx − c)² |dx| along the graph, so the answer does not depend on how densely the
//! curve was sampled where; a log-aesthetic curve gives its α back exactly.

use kurbo::{ParamCurve, Point};

use crate::family::bezier::RationalCubic;
use crate::family::sample::{check_count, Sample};
use crate::foundation::error::{Error, Result};
use crate::foundation::gauss::GAUSS_8;
use crate::foundation::numeric::length;
use crate::segment::Segment;

/// One point of a curvature plot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvaturePoint {
    /// Arc length from the start of the curve.
    pub s: f64,
    /// Position.
    pub point: Point,
    /// Signed curvature (positive for a left turn).
    pub kappa: f64,
    /// dκ/ds.
    pub dkappa_ds: f64,
}

impl CurvaturePoint {
    /// The point of the logarithmic curvature graph, (ln ρ, ln(ρ |ds/dρ|)), when κ ≠ 0 and
    /// dκ/ds ≠ 0.
    pub fn lcg(&self) -> Option<(f64, f64)> {
        let (k, dk) = (self.kappa.abs(), self.dkappa_ds.abs());
        let p = (-k.ln(), k.ln() - dk.ln());
        (p.0.is_finite() && p.1.is_finite()).then_some(p)
    }
}

/// The straight line fitted to a logarithmic curvature graph: y = α x + intercept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LcgFit {
    /// The slope: the α of the log-aesthetic curve that best matches.
    pub alpha: f64,
    /// The value at ln ρ = 0 (for a log-aesthetic curve, −ln Λ in its own units).
    pub intercept: f64,
    /// Root mean square of y − (αx + intercept), weighted by |dx|.
    pub rms_residual: f64,
    /// Largest |y − (αx + intercept)| over the points.
    pub max_residual: f64,
    /// The range of ln ρ covered.
    pub log_rho: (f64, f64),
}

/// The logarithmic curvature graph of a curve and its fitted line.
#[derive(Clone, Debug, PartialEq)]
pub struct LogCurvatureGraph {
    /// (ln ρ, ln(ρ |ds/dρ|)) in the order of the curvature plot; points where κ = 0 or
    /// dκ/ds = 0 have no graph point and are left out.
    pub points: Vec<(f64, f64)>,
    /// The fitted line; `None` when ln ρ does not vary (a circle) or fewer than two points
    /// have a graph point.
    pub fit: Option<LcgFit>,
}

/// `per_piece ≥ 2` curvature points per piece, equally spaced in t, with the arc length
/// accumulated over the chain (consecutive pieces share their end points, which appear
/// once).
///
/// ```
/// use kurbo::Point;
/// use lac::{curvature_plot, log_curvature_graph, Segment, ToBezier, Tolerance};
///
/// let seg = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.0, 0.8)], 0.5)?;
/// let quasi = seg.to_rational_cubics(Tolerance::Relative(1e-6))?;
/// let pieces: Vec<_> = quasi.pieces.iter().map(|p| p.curve).collect();
/// let graph = log_curvature_graph(&curvature_plot(&pieces, 64)?);
/// let fit = graph.fit.unwrap();
/// assert!((fit.alpha - 0.5).abs() < 0.05);
/// # Ok::<(), lac::Error>(())
/// ```
pub fn curvature_plot(pieces: &[RationalCubic], per_piece: usize) -> Result<Vec<CurvaturePoint>> {
    check_count(per_piece)?;
    if pieces.is_empty() {
        return Err(Error::OutOfRange {
            name: "pieces",
            value: 0.0,
            expected: "at least one Bézier piece",
        });
    }
    let mut out = Vec::with_capacity(pieces.len() * per_piece);
    let mut s = 0.0;
    for (k, piece) in pieces.iter().enumerate() {
        let mut prev_t = 0.0;
        for i in 0..per_piece {
            if k > 0 && i == 0 {
                continue;
            }
            let t = i as f64 / (per_piece - 1) as f64;
            s += arc_length_gauss8(piece, prev_t, t);
            prev_t = t;
            let point = CurvaturePoint {
                s,
                point: piece.eval(t),
                kappa: piece.signed_curvature(t),
                dkappa_ds: piece.curvature_derivative(t),
            };
            let values = [
                s,
                point.point.x,
                point.point.y,
                point.kappa,
                point.dkappa_ds,
            ];
            if !values.iter().all(|v| v.is_finite()) {
                // A cusp (zero speed: a repeated control point, or a loop's tip) has no
                // curvature; an overflow is beyond double range. Either way, no plot.
                return Err(Error::CurvatureUndefined { piece: k, t });
            }
            out.push(point);
        }
    }
    Ok(out)
}

fn arc_length_gauss8(c: &RationalCubic, t0: f64, t1: f64) -> f64 {
    if t1 == t0 {
        return 0.0;
    }
    let (mid, half) = (0.5 * (t0 + t1), 0.5 * (t1 - t0));
    half * GAUSS_8
        .iter()
        .map(|&(x, w)| {
            w * (length(c.derivative(mid - half * x)) + length(c.derivative(mid + half * x)))
        })
        .sum::<f64>()
}

/// Fit the logarithmic curvature graph of a curvature plot.
pub fn log_curvature_graph(plot: &[CurvaturePoint]) -> LogCurvatureGraph {
    let points: Vec<(f64, f64)> = plot.iter().filter_map(CurvaturePoint::lcg).collect();
    LogCurvatureGraph::from_points(points)
}

impl LogCurvatureGraph {
    /// Any logarithmic graph given by its points `(x, y)` in the order of travel, with the
    /// line fitted as for [`log_curvature_graph`]: the curvature graph `(ln ρ, ln(ρ |ds/dρ|))`
    /// of a space curve ([`SpaceCurve::log_curvature_graph`]) or its torsion graph
    /// `(ln μ, ln(μ |ds/dμ|))`, whose slope is β.
    ///
    /// [`SpaceCurve::log_curvature_graph`]: crate::SpaceCurve::log_curvature_graph
    pub fn from_points(points: Vec<(f64, f64)>) -> LogCurvatureGraph {
        let fit = fit_line(&points);
        LogCurvatureGraph { points, fit }
    }
}

/// Least squares with trapezoid weights in x.
fn fit_line(points: &[(f64, f64)]) -> Option<LcgFit> {
    if points.len() < 2 {
        return None;
    }
    let n = points.len();
    let weight = |i: usize| {
        let left = if i > 0 {
            (points[i].0 - points[i - 1].0).abs()
        } else {
            0.0
        };
        let right = if i + 1 < n {
            (points[i + 1].0 - points[i].0).abs()
        } else {
            0.0
        };
        0.5 * (left + right)
    };
    let (mut sw, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for (i, &(x, y)) in points.iter().enumerate() {
        let w = weight(i);
        sw += w;
        sx += w * x;
        sy += w * y;
    }
    if !sw.is_finite() || sw <= 0.0 {
        return None;
    }
    let (mx, my) = (sx / sw, sy / sw);
    let (mut sxx, mut sxy) = (0.0, 0.0);
    for (i, &(x, y)) in points.iter().enumerate() {
        let w = weight(i);
        sxx += w * (x - mx) * (x - mx);
        sxy += w * (x - mx) * (y - my);
    }
    let range = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.0), hi.max(p.0))
        });
    // ln ρ must vary by more than its rounding for a slope to mean anything.
    if !sxx.is_finite()
        || sxx <= 0.0
        || range.1 - range.0 <= 1e-12 * range.0.abs().max(range.1.abs()).max(1.0)
    {
        return None;
    }
    let alpha = sxy / sxx;
    let intercept = my - alpha * mx;
    let (mut ss, mut max) = (0.0, 0.0f64);
    for (i, &(x, y)) in points.iter().enumerate() {
        let r = y - (alpha * x + intercept);
        ss += weight(i) * r * r;
        max = max.max(r.abs());
    }
    let first = points[0].0;
    let last = points[n - 1].0;
    Some(LcgFit {
        alpha,
        intercept,
        rms_residual: (ss / sw).sqrt(),
        max_residual: max,
        log_rho: (first, last),
    })
}

impl Segment {
    /// The curvature point of a sample of this segment, with the exact dκ/ds.
    pub(crate) fn curvature_point(&self, s: &Sample) -> CurvaturePoint {
        CurvaturePoint {
            s: s.s,
            point: s.point,
            kappa: s.kappa,
            dkappa_ds: self.dkappa_ds_at(s.kappa),
        }
    }

    /// The exact dκ/ds where the signed curvature is `kappa`.
    pub(crate) fn dkappa_ds_at(&self, kappa: f64) -> f64 {
        self.dkappa_ds_of(-(kappa.abs() * self.scale()).ln())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Curve;

    #[test]
    fn any_straight_graph_gives_its_slope_back_and_a_constant_x_gives_none() {
        let line: Vec<(f64, f64)> = (0..9)
            .map(|i| {
                let x = -1.0 + 0.3 * f64::from(i);
                (x, 1.5 * x - 0.25)
            })
            .collect();
        let fit = LogCurvatureGraph::from_points(line).fit.unwrap();
        assert!((fit.alpha - 1.5).abs() < 1e-14 && (fit.intercept + 0.25).abs() < 1e-14);
        assert!(fit.rms_residual < 1e-14);
        let flat = LogCurvatureGraph::from_points(vec![(0.5, 1.0), (0.5, 2.0)]);
        assert!(flat.fit.is_none());
    }

    #[test]
    fn a_log_aesthetic_segment_has_its_own_alpha() {
        for &alpha in &[-1.0, 0.0, 0.5, 1.0, 2.0] {
            let seg = Segment::from_control_points(
                [
                    Point::new(0.0, 0.0),
                    Point::new(2.0, 0.5),
                    Point::new(3.0, 2.0),
                ],
                alpha,
            )
            .unwrap();
            let graph = log_curvature_graph(&seg.curvature_plot(50).unwrap());
            let fit = graph.fit.unwrap();
            assert!((fit.alpha - alpha).abs() < 1e-10, "{alpha}: {fit:?}");
            assert!(fit.rms_residual < 1e-10);
            let line = seg.lcg().unwrap();
            assert!((fit.intercept - line.intercept).abs() < 1e-9);
        }
    }

    #[test]
    fn exact_dkappa_matches_differences() {
        let seg = Segment::from_control_points(
            [
                Point::new(0.0, 0.0),
                Point::new(-1.0, 1.0),
                Point::new(-1.0, 3.0),
            ],
            -0.4,
        )
        .unwrap();
        let plot = seg.curvature_plot(9).unwrap();
        let h = 1e-6;
        for p in &plot[1..8] {
            let fd = (seg.signed_curvature_at_s(p.s + h).unwrap()
                - seg.signed_curvature_at_s(p.s - h).unwrap())
                / (2.0 * h);
            assert!(
                (fd - p.dkappa_ds).abs() < 1e-6 * fd.abs(),
                "{fd} {}",
                p.dkappa_ds
            );
        }
    }

    #[test]
    fn a_circle_has_no_fit() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let w = (2.0 * c + 1.0) / 3.0;
        let k = 2.0 * c / (1.0 + 2.0 * c);
        let arc = RationalCubic::new(
            [
                Point::new(1.0, 0.0),
                Point::new(1.0, k),
                Point::new(k, 1.0),
                Point::new(0.0, 1.0),
            ],
            [1.0, w, w, 1.0],
        )
        .unwrap();
        let plot = curvature_plot(&[arc], 20).unwrap();
        assert!((plot.last().unwrap().s - std::f64::consts::FRAC_PI_2).abs() < 1e-13);
        assert!(log_curvature_graph(&plot).fit.is_none());
    }
}
