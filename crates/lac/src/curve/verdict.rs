//! Whether a curve's curvature is monotone, read from its curvature plot or, with a proof
//! per piece, from a chain of rational cubic pieces; and why not ([`NotMonotone`]). A
//! logarithmic curvature graph is one line only where the curvature is monotone, so these
//! decide whether a slope α can be fitted at all.

use std::fmt;

use crate::curve::analysis::CurvaturePoint;
use crate::family::bezier::RationalCubic;
use crate::family::monotone::{Monotonicity, MonotonicityReport};
use crate::foundation::numeric::short_number;

/// A plot's dκ/ds (or κ) counts as zero where it is below this share of its scale: the
/// rounding of a circular arc's exact zero is far below it, a real change of sign far above.
pub const PLOT_ZERO: f64 = 1e-9;

/// Where a curve's curvature shows that it is not monotone. Its `Display` is the sentence
/// the front ends print (`lac lcg`'s note).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum NotMonotone {
    /// The plot's dκ/ds changes sign near arc length `s`.
    SlopeChangesSign {
        /// Arc length of the first sample of the other sign.
        s: f64,
    },
    /// The plot's curvature changes sign near arc length `s`: an inflection.
    Inflection {
        /// Arc length of the first sample of the other sign.
        s: f64,
    },
    /// dκ/ds changes sign inside a piece of a chain (proven by its verdict).
    InsidePiece {
        /// The piece, from 0.
        piece: usize,
        /// How many pieces the chain has.
        pieces: usize,
        /// A parameter of the piece where dκ/ds changes sign.
        t: f64,
    },
    /// The curvature runs one way along a piece (or jumps one way at a joint) and the
    /// other way later.
    Opposite {
        /// Whether it increases first.
        increasing_first: bool,
        /// The piece that set the first direction, from 0.
        first: usize,
        /// Where it runs the other way.
        then: Place,
        /// How many pieces the chain has.
        pieces: usize,
    },
}

/// Where along a chain of pieces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Place {
    /// Along piece `k` (from 0).
    Along(usize),
    /// At the joint between pieces `k − 1` and `k` (from 0).
    Joint(usize),
}

impl NotMonotone {
    /// Why the curvature of a sampled plot is not monotone, if it shows that: dκ/ds, made
    /// dimensionless by the plot's length and largest curvature, takes both signs beyond
    /// [`PLOT_ZERO`], or the curvature itself does ([`NotMonotone::inflection_of_plot`]).
    pub fn of_plot(plot: &[CurvaturePoint]) -> Option<NotMonotone> {
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
                    return Some(NotMonotone::SlopeChangesSign { s: p.s })
                }
                _ => {}
            }
        }
        NotMonotone::inflection_of_plot(plot)
    }

    /// Where the curvature of a plot changes sign (beyond [`PLOT_ZERO`] of its largest
    /// value).
    pub fn inflection_of_plot(plot: &[CurvaturePoint]) -> Option<NotMonotone> {
        let kmax = plot.iter().fold(0.0f64, |m, p| m.max(p.kappa.abs()));
        let mut sign = None;
        for p in plot {
            if p.kappa.is_nan() || p.kappa.abs() <= PLOT_ZERO * kmax {
                continue;
            }
            match sign {
                None => sign = Some(p.kappa > 0.0),
                Some(left) if left != (p.kappa > 0.0) => {
                    return Some(NotMonotone::Inflection { s: p.s })
                }
                _ => {}
            }
        }
        None
    }

    /// Why the curvature of a chain of pieces with these (proven) verdicts is not monotone:
    /// a piece's is proven not to be, two pieces' are proven to run in opposite directions,
    /// or it jumps the wrong way at a joint.
    pub fn of_chain(
        pieces: &[RationalCubic],
        verdicts: &[MonotonicityReport],
    ) -> Option<NotMonotone> {
        let n = pieces.len();
        // The direction so far, and the piece that set it.
        let mut direction: Option<(bool, usize)> = None;
        let mut follow = |up: bool, k: usize, then: Place| match direction {
            None => {
                direction = Some((up, k));
                None
            }
            Some((was, j)) if was != up => Some(NotMonotone::Opposite {
                increasing_first: was,
                first: j,
                then,
                pieces: n,
            }),
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
                    if let Some(why) = follow(jump > 0.0, k, Place::Joint(k)) {
                        return Some(why);
                    }
                }
            }
            // An unproven verdict is dκ/ds zero within rounding (a circular arc): no
            // direction.
            if !v.proven {
                continue;
            }
            match v.verdict {
                Monotonicity::NotMonotone { t } => {
                    return Some(NotMonotone::InsidePiece {
                        piece: k,
                        pieces: n,
                        t,
                    })
                }
                Monotonicity::Constant => {}
                Monotonicity::Increasing | Monotonicity::Decreasing => {
                    let up = v.verdict == Monotonicity::Increasing;
                    if let Some(why) = follow(up, k, Place::Along(k)) {
                        return Some(why);
                    }
                }
            }
        }
        None
    }
}

impl fmt::Display for NotMonotone {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let way = |up: bool| if up { "increases" } else { "decreases" };
        match *self {
            NotMonotone::SlopeChangesSign { s } => {
                write!(f, "dκ/ds changes sign near s = {}", short_number(s))
            }
            NotMonotone::Inflection { s } => write!(
                f,
                "the curvature changes sign near s = {}, an inflection",
                short_number(s)
            ),
            NotMonotone::InsidePiece { piece, pieces, t } => write!(
                f,
                "dκ/ds changes sign inside piece {} of {pieces}, at t = {}",
                piece + 1,
                short_number(t)
            ),
            NotMonotone::Opposite {
                increasing_first,
                first,
                then,
                pieces,
            } => {
                write!(
                    f,
                    "it {} along piece {} of {pieces} and {} ",
                    way(increasing_first),
                    first + 1,
                    way(!increasing_first)
                )?;
                match then {
                    Place::Along(k) => write!(f, "along piece {}", k + 1),
                    Place::Joint(k) => write!(f, "at the joint of pieces {k} and {}", k + 1),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use kurbo::Point;

    use super::*;

    fn plot(points: &[(f64, f64, f64)]) -> Vec<CurvaturePoint> {
        points
            .iter()
            .map(|&(s, kappa, dkappa_ds)| CurvaturePoint {
                s,
                point: Point::ZERO,
                kappa,
                dkappa_ds,
            })
            .collect()
    }

    #[test]
    fn a_plot_whose_slope_or_curvature_turns_back_is_caught_where_it_does() {
        let monotone = plot(&[(0.0, 1.0, 1.0), (0.5, 1.5, 1.0), (1.0, 2.0, 1.0)]);
        assert_eq!(NotMonotone::of_plot(&monotone), None);
        let back = plot(&[(0.0, 1.0, 1.0), (0.5, 1.5, 0.0), (1.0, 1.2, -1.0)]);
        let why = NotMonotone::of_plot(&back).unwrap();
        assert_eq!(why, NotMonotone::SlopeChangesSign { s: 1.0 });
        assert_eq!(why.to_string(), "dκ/ds changes sign near s = 1");
        let inflection = plot(&[(0.0, -1.0, 2.0), (1.0 / 3.0, 0.0, 2.0), (1.0, 1.0, 2.0)]);
        let why = NotMonotone::of_plot(&inflection).unwrap();
        assert_eq!(why, NotMonotone::Inflection { s: 1.0 });
        assert_eq!(
            why.to_string(),
            "the curvature changes sign near s = 1, an inflection"
        );
    }

    #[test]
    fn a_chain_whose_proven_pieces_run_opposite_ways_is_named_piece_by_piece() {
        // Straight pieces (κ = 0 everywhere, so no jump at the joint) with given verdicts.
        let line = RationalCubic::new(
            [
                Point::new(0.0, 0.0),
                Point::new(1.0, 0.0),
                Point::new(2.0, 0.0),
                Point::new(3.0, 0.0),
            ],
            [1.0; 4],
        )
        .unwrap();
        let proven = |verdict| MonotonicityReport {
            verdict,
            proven: true,
        };
        let up_down = [
            proven(Monotonicity::Increasing),
            proven(Monotonicity::Decreasing),
        ];
        let why = NotMonotone::of_chain(&[line, line], &up_down).unwrap();
        assert_eq!(
            why.to_string(),
            "it increases along piece 1 of 2 and decreases along piece 2"
        );
        let wavy = [proven(Monotonicity::NotMonotone { t: 0.25 })];
        let why = NotMonotone::of_chain(&[line], &wavy).unwrap();
        assert_eq!(
            why.to_string(),
            "dκ/ds changes sign inside piece 1 of 1, at t = 0.25"
        );
        let unproven = [MonotonicityReport {
            verdict: Monotonicity::Decreasing,
            proven: false,
        }];
        assert_eq!(NotMonotone::of_chain(&[line], &unproven), None);
    }
}
