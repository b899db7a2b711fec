//! The curvature comb: teeth along the normal with length proportional to |κ|.

use kurbo::Point;
use lac::Sample;

/// Teeth from the curve to their tips, drawn on the convex side (away from the centre of
/// curvature), as in CAD systems' curvature combs. The envelope is the polyline through the
/// tips.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Comb {
    /// (point on the curve, tip) for each sample.
    pub(crate) teeth: Vec<(Point, Point)>,
}

impl Comb {
    /// The comb of `samples`, scaled so that the longest tooth is `longest` long. Empty when
    /// no sample has a finite non-zero curvature.
    pub(crate) fn new(samples: &[Sample], longest: f64) -> Comb {
        let k_max = max_curvature(samples);
        if k_max <= 0.0 {
            return Comb { teeth: Vec::new() };
        }
        Comb::scaled(samples, longest / k_max)
    }

    /// The comb of `samples` with teeth |κ|·`scale` long, so that combs of several curves
    /// can be drawn to one scale.
    pub(crate) fn scaled(samples: &[Sample], scale: f64) -> Comb {
        let teeth = samples
            .iter()
            .filter(|s| s.kappa.is_finite())
            .map(|s| {
                // The left normal points to the centre of curvature when κ > 0.
                let normal = s.tangent().turn_90();
                (s.point, s.point - normal * (s.kappa * scale))
            })
            .collect();
        Comb { teeth }
    }

    /// The tips, in order: the comb's envelope.
    pub(crate) fn envelope(&self) -> Vec<Point> {
        self.teeth.iter().map(|&(_, tip)| tip).collect()
    }
}

/// The largest finite |κ| of `samples`, 0 when there is none.
pub(crate) fn max_curvature(samples: &[Sample]) -> f64 {
    samples
        .iter()
        .map(|s| s.kappa.abs())
        .filter(|k| k.is_finite())
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn teeth_of_a_left_turn_point_right_and_the_longest_has_the_requested_length() {
        let sample = |s: f64, kappa: f64| Sample {
            s,
            point: Point::new(s, 0.0),
            theta: 0.0,
            kappa,
        };
        let comb = Comb::new(&[sample(0.0, 1.0), sample(1.0, 4.0)], 2.0);
        assert_eq!(comb.teeth[1].1, Point::new(1.0, -2.0));
        assert_eq!(comb.teeth[0].1, Point::new(0.0, -0.5));
    }
}
