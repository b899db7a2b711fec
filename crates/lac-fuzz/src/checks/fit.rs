//! `fit`: [`lac::Fit::from_points`]. Invariants: everything finite; a distance and a foot
//! per point; the figures agree with the distances (the largest is the worst point's, the
//! RMS below it); each point's reported distance is its distance to the fit at its foot,
//! measured on the placed segments; with a tolerance, every point within it at its foot
//! (so truly within it); no more segments than asked, with the α asked; consecutive
//! segments meet (position and tangent) and, G2, their curvatures agree where they are not
//! flat; a closed fit ends where it starts.

use kurbo::Point;
use lac::{Closure, Continuity, Curve, Fit, FitAlpha, FitLoss, FitOptions, SegmentChain};

use super::{bounds, finite, largest_end_curvature, meet, pt, rounding, typed};

/// The options of an input, as the library takes them.
pub(super) struct Asked<'a> {
    pub(super) points: &'a [[f64; 2]],
    pub(super) tolerance: Option<f64>,
    pub(super) max_segments: usize,
    pub(super) alpha: Option<f64>,
    pub(super) closed: bool,
    pub(super) g1: bool,
    pub(super) pin_ends: bool,
    pub(super) huber: Option<f64>,
    pub(super) weights: Option<&'a [f64]>,
}

/// The checks of a `fit` input.
pub(super) fn check(asked: &Asked) -> Result<bool, String> {
    let points: Vec<Point> = asked.points.iter().map(|&p| pt(p)).collect();
    let options = FitOptions {
        tolerance: asked.tolerance,
        max_segments: asked.max_segments,
        alpha: match asked.alpha {
            Some(a) => FitAlpha::Fixed(a),
            None => FitAlpha::default(),
        },
        continuity: if asked.g1 {
            Continuity::G1
        } else {
            Continuity::G2
        },
        closure: if asked.closed {
            Closure::Closed
        } else {
            Closure::Open
        },
        pin_ends: asked.pin_ends,
        loss: match asked.huber {
            Some(delta) => FitLoss::Huber { delta },
            None => FitLoss::Squares,
        },
        weights: asked.weights.map(<[f64]>::to_vec),
    };
    let Some(fit) = typed(Fit::from_points(&points, &options))? else {
        return Ok(false);
    };
    check_fit(&fit, &points, asked)?;
    Ok(true)
}

fn check_fit(fit: &Fit, points: &[Point], asked: &Asked) -> Result<(), String> {
    let n = points.len();
    let (distances, feet) = (fit.distances(), fit.feet());
    if distances.len() != n || feet.len() != n {
        return Err(format!(
            "{} distances and {} feet for {n} points",
            distances.len(),
            feet.len()
        ));
    }
    finite("distances", distances)?;
    finite("feet", feet)?;
    finite(
        "figures",
        &[fit.rms(), fit.max_distance(), fit.arc_length()],
    )?;
    let largest = distances.iter().copied().fold(0.0, f64::max);
    if fit.worst_point() >= n
        || fit.max_distance() != largest
        || distances[fit.worst_point()] != largest
        || fit.rms() > largest * (1.0 + 1e-12)
        || distances.iter().any(|d| *d < 0.0)
    {
        return Err(format!(
            "figures disagree: worst point {} of {n}, max {:e}, rms {:e}, largest {largest:e}",
            fit.worst_point(),
            fit.max_distance(),
            fit.rms()
        ));
    }
    let pieces = fit.pieces();
    if pieces.is_empty() || pieces.len() > asked.max_segments {
        return Err(format!(
            "{} pieces for at most {}",
            pieces.len(),
            asked.max_segments
        ));
    }
    for p in pieces {
        finite(
            "a piece",
            &[p.alpha, p.curvatures[0], p.curvatures[1], p.length, p.s],
        )?;
        if let Some(a) = asked.alpha {
            if p.alpha != a {
                return Err(format!("α {} where {a} was asked", p.alpha));
            }
        } else if !(lac::DEFAULT_ALPHA_RANGE.0..=lac::DEFAULT_ALPHA_RANGE.1).contains(&p.alpha) {
            return Err(format!("α {} outside the default range", p.alpha));
        }
    }
    let segments = SegmentChain::pieces(fit);
    let size = points.iter().fold(
        (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ),
        |b, p| (b.0.min(p.x), b.1.max(p.x), b.2.min(p.y), b.3.max(p.y)),
    );
    let size = (size.1 - size.0).max(size.3 - size.2);
    let tol = bounds::POSITION * size + rounding(points);
    // The whole fit sampled: finite everywhere.
    for q in fit
        .sample_by_arc_length(65)
        .map_err(|e| format!("sampling a fit failed: {e}"))?
    {
        finite("fit sample", &[q.s, q.point.x, q.point.y, q.theta, q.kappa])?;
    }
    // Consecutive segments meet; G2, their curvatures agree unless both are flat (an S's
    // inflection, a hair apart).
    let kmax = largest_end_curvature(segments);
    let pairs = segments.len() - usize::from(!asked.closed);
    for i in 0..pairs {
        let (a, b) = (&segments[i], &segments[(i + 1) % segments.len()]);
        meet(a, b, i, tol, size)?;
        let (ka, kb) = (a.signed_curvature_end(), b.signed_curvature_start());
        let flat = ka.abs().max(kb.abs()) <= 10.0 * lac::INFLECTION_LIMIT * kmax;
        if !asked.g1 && !flat && (ka - kb).abs() > bounds::JOINT_CURVATURE * kmax {
            return Err(format!(
                "curvature jumps after segment {i}: {ka:e} to {kb:e}"
            ));
        }
    }
    // Each distance is the point's distance to the fit at its foot, on the placed segments;
    // with a tolerance that is within it. (At most 64 points, evenly spread, and the worst.)
    let step = n.div_ceil(64).max(1);
    let length = fit.arc_length();
    for k in (0..n).step_by(step).chain([fit.worst_point()]) {
        // (A closed fit's feet run on round its closing joint.)
        let s = if asked.closed {
            feet[k].rem_euclid(length)
        } else {
            feet[k].clamp(0.0, length)
        };
        let foot = fit
            .point_at_s(s)
            .map_err(|e| format!("the foot of point {k} at s = {s:e}: {e}"))?;
        let d = (points[k].x - foot.x).hypot(points[k].y - foot.y);
        if (d - distances[k]).abs() > 1e-6 * size + rounding(points) {
            return Err(format!(
                "point {k}: reported distance {:e}, {d:e} from its foot",
                distances[k]
            ));
        }
        if let Some(t) = asked.tolerance {
            if d > t + 1e-9 * size + rounding(points) {
                return Err(format!("point {k} is {d:e} from the fit, tolerance {t:e}"));
            }
        }
    }
    Ok(())
}
