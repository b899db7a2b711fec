//! The two ends of a fit: the caller's points and options checked and brought to a unit
//! box (so that points near 1e-150 or 1e150 fit as well as points near 1), and the fitted
//! chain placed back as [`Segment`]s, measured and checked.
//!
//! A piece through zero curvature (an S, α < 0) becomes two segments, each stopping a hair
//! short of the inflection (`Segment` has no station at ρ = ∞): a share η of the piece's
//! length on either side, where the curvature is [`HAIR_CURVATURE`] of the piece's largest
//! (as the paths' segments that end at an inflection do), at least 1e-15 and at most 1e-12
//! of the length (so that the segments meet to rounding; for α near 0 the curvature there
//! is then far below); the two halves are joined across the 2η gap along their common
//! tangent.

use kurbo::{Point, Vec2};

use crate::curve::Curve;
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::Complex;
use crate::path::{Closure, Continuity, G2_JUMP_LIMIT, INFLECTION_LIMIT};
use crate::segment::{check_alpha, Segment};

use super::model::{AlphaMode, Layout};
use super::solve::{Loss, State};
use super::{Fit, FitAlpha, FitJoint, FitLoss, FitOptions, FitPiece, MAX_FIT_SEGMENTS};

/// Largest gap (relative to the size of the points) and tangent jump (radians) at a joint.
const JOINT_LIMIT: f64 = 1e-10;

/// Largest difference between the solver's tabulated chain and the placed segments,
/// relative to the size of the points (or to the chain's length, where that is larger):
/// the distances the fit reports are the solver's.
const MODEL_LIMIT: f64 = 1e-9;

/// The rounding of a joint's curvature, relative to the fit's largest: a segment evaluates
/// its end curvature to about 1e-9 of itself at curvature ratios of 1e4 (seen: a joint at
/// 5e-4 of the largest, 3e-9 of itself apart), far below the fit's curvature scale.
const CURVATURE_ROUNDING: f64 = 1e-10;

/// The largest extent and distance from the origin of the points a fit takes.
const LARGEST_COORDINATE: f64 = 1e150;

/// The caller's points and options in the unit box.
pub(super) struct Input {
    pub(super) data: Vec<Complex>,
    pub(super) weights: Vec<f64>,
    /// Caller = center + scale × unit.
    pub(super) center: Point,
    pub(super) scale: f64,
    pub(super) tolerance: Option<f64>,
    pub(super) loss: Loss,
    pub(super) alpha_mode: AlphaMode,
    pub(super) alpha_range: (f64, f64),
}

impl Input {
    pub(super) fn new(points: &[Point], options: &FitOptions) -> Result<Input> {
        for p in points {
            finite("point x", p.x)?;
            finite("point y", p.y)?;
        }
        let closed = options.closure == Closure::Closed;
        let needed = if closed { 4 } else { 3 };
        let mut distinct: Vec<(f64, f64)> = points.iter().map(|p| (p.x, p.y)).collect();
        distinct.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        distinct.dedup();
        if distinct.len() < needed {
            return Err(Error::TooFewPoints {
                needed,
                got: distinct.len(),
            });
        }
        if !(1..=MAX_FIT_SEGMENTS).contains(&options.max_segments) {
            return Err(Error::OutOfRange {
                name: "max_segments",
                value: options.max_segments as f64,
                expected: "between 1 and 64 segments",
            });
        }
        let (alpha_mode, alpha_range) = match options.alpha {
            FitAlpha::Fixed(a) => (AlphaMode::Fixed(check_alpha("alpha", a)?), (a, a)),
            FitAlpha::Range { min, max, shared } => {
                check_alpha("alpha range minimum", min)?;
                check_alpha("alpha range maximum", max)?;
                if !(min <= max && max - min <= 100.0) {
                    return Err(Error::OutOfRange {
                        name: "alpha range",
                        value: max - min,
                        expected: "a range min <= max no wider than 100",
                    });
                }
                let mode = if min == max {
                    AlphaMode::Fixed(min)
                } else if shared {
                    AlphaMode::Shared
                } else {
                    AlphaMode::Each
                };
                (mode, (min, max))
            }
        };
        // The unit box: halves first, so that neither the centre nor the extent overflows.
        let (mut lo, mut hi) = (points[0], points[0]);
        for p in points {
            lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        let center = Point::new(0.5 * lo.x + 0.5 * hi.x, 0.5 * lo.y + 0.5 * hi.y);
        let half = (0.5 * hi.x - 0.5 * lo.x).max(0.5 * hi.y - 0.5 * lo.y);
        if !(half > 0.0 && half.is_finite()) {
            return Err(Error::Unrepresentable {
                what: "extent of the points",
            });
        }
        // A segment's own arithmetic squares lengths: points more than 1e150 apart or from
        // the origin would overflow it.
        if half > LARGEST_COORDINATE || center.x.abs().max(center.y.abs()) > LARGEST_COORDINATE {
            return Err(Error::Unrepresentable {
                what: "extent of the points",
            });
        }
        let data: Vec<Complex> = points
            .iter()
            .map(|p| {
                Complex::new(
                    (0.5 * p.x - 0.5 * center.x) / half,
                    (0.5 * p.y - 0.5 * center.y) / half,
                )
            })
            .collect();
        let scale = 2.0 * half;
        if collinear(&data) {
            return Err(Error::CollinearPoints);
        }
        let tolerance = match options.tolerance {
            Some(t) => {
                finite("tolerance", t)?;
                if t.is_nan() || t <= 0.0 {
                    return Err(Error::OutOfRange {
                        name: "tolerance",
                        value: t,
                        expected: "a positive distance",
                    });
                }
                Some(t / scale)
            }
            None => None,
        };
        let loss = match options.loss {
            FitLoss::Squares => Loss::Squares,
            FitLoss::Huber { delta } => {
                finite("huber delta", delta)?;
                if delta.is_nan() || delta <= 0.0 {
                    return Err(Error::OutOfRange {
                        name: "huber delta",
                        value: delta,
                        expected: "a positive distance",
                    });
                }
                Loss::Huber(delta / scale)
            }
        };
        let weights = match &options.weights {
            Some(w) => {
                if w.len() != points.len() {
                    return Err(Error::OutOfRange {
                        name: "weights",
                        value: w.len() as f64,
                        expected: "one weight per point",
                    });
                }
                for &v in w {
                    finite("weight", v)?;
                    if v < 0.0 {
                        return Err(Error::OutOfRange {
                            name: "weight",
                            value: v,
                            expected: "non-negative weights",
                        });
                    }
                }
                let sum: f64 = w.iter().sum();
                if !(sum > 0.0 && sum.is_finite()) {
                    return Err(Error::OutOfRange {
                        name: "weights",
                        value: sum,
                        expected: "weights that are not all zero",
                    });
                }
                let mean = sum / w.len() as f64;
                w.iter().map(|v| v / mean).collect()
            }
            None => vec![1.0; points.len()],
        };
        Ok(Input {
            data,
            weights,
            center,
            scale,
            tolerance,
            loss,
            alpha_mode,
            alpha_range,
        })
    }

    fn caller(&self, z: Complex) -> Point {
        Point::new(
            self.center.x + self.scale * z.re,
            self.center.y + self.scale * z.im,
        )
    }
}

/// Do the points lie on one line (to 1e-12 of their size)?
fn collinear(data: &[Complex]) -> bool {
    let n = data.len() as f64;
    let (mx, my) = data
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p.re / n, y + p.im / n));
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for p in data {
        let (x, y) = (p.re - mx, p.im - my);
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
    }
    // The smaller eigenvalue of the scatter: the mean squared distance to the best line.
    let tr = sxx + syy;
    let det = sxx * syy - sxy * sxy;
    let small = 0.5 * (tr - (tr * tr - 4.0 * det).max(0.0).sqrt());
    (small.max(0.0) / n).sqrt() <= 1e-12
}

/// The curvature at the ends of the segments on either side of an inflection, relative to
/// the piece's largest.
const HAIR_CURVATURE: f64 = 1e-12;

/// The share of a piece's length left out on either side of a point of zero curvature.
fn hair(law: &super::law::Law, largest: f64) -> f64 {
    law.within(HAIR_CURVATURE * largest)
        .unwrap_or(0.0)
        .clamp(1e-15, 1e-12)
}

/// The span [a, b] of a piece cut into parts that each turn by less than 0.9π.
fn cut_by_turning(law: &super::law::Law, a: f64, b: f64) -> Vec<(f64, f64)> {
    let (ta, tb) = (law.at(a).0, law.at(b).0);
    let turn = (tb - ta).abs();
    let parts = (turn / (0.9 * std::f64::consts::PI)).floor() as usize + 1;
    let mut cuts = vec![a];
    for j in 1..parts {
        let target = ta + (tb - ta) * j as f64 / parts as f64;
        let rising = tb > ta;
        let (mut lo, mut hi) = (a, b);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if (law.at(mid).0 < target) == rising {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        cuts.push(0.5 * (lo + hi));
    }
    cuts.push(b);
    cuts.windows(2).map(|w| (w[0], w[1])).collect()
}

/// Place the fitted chain of `state` as segments, measure it and check it.
pub(super) fn build(
    input: &Input,
    layout: &Layout,
    state: State,
    options: &FitOptions,
) -> Result<Fit> {
    let scale = input.scale;
    let chain = &state.chain;
    let mut segments: Vec<Segment> = Vec::new();
    let mut segment_s: Vec<f64> = Vec::new();
    // The segments that start just after an inflection.
    let mut inflections: Vec<usize> = Vec::new();
    let mut pieces = Vec::with_capacity(layout.n);
    let mut start = input.caller(chain.start);
    let mut theta = chain.theta0;
    let mut s = 0.0;
    let mut largest_kappa: f64 = 0.0;
    for (i, table) in chain.pieces.iter().enumerate() {
        let (_, _, len, alpha) = chain.numbers[i];
        let law = table.law;
        let (k0, k1) = (law.at(0.0).1, law.at(1.0).1);
        largest_kappa = largest_kappa.max(k0.abs()).max(k1.abs());
        let eta = hair(&law, k0.abs().max(k1.abs()));
        // The shares [a, b] of each segment of the piece.
        let mut spans: Vec<(f64, f64)> = Vec::new();
        let lo = if k0 == 0.0 { eta } else { 0.0 };
        let hi = if k1 == 0.0 { 1.0 - eta } else { 1.0 };
        match law.inflection() {
            Some(t) => {
                spans.push((lo, t - eta));
                spans.push((t + eta, hi));
            }
            None => spans.push((lo, hi)),
        }
        // A segment turns by less than π: a piece that turns more is several segments, cut
        // where equal shares of its turning are reached (on one side of an inflection the
        // turning is monotone).
        let spans: Vec<(f64, f64)> = spans
            .into_iter()
            .flat_map(|(a, b)| cut_by_turning(&law, a, b))
            .collect();
        let first = segments.len();
        let piece_s = s;
        let mut inflection = None;
        let mut after_inflection = None;
        let mut pos = 0.0;
        for (a, b) in spans {
            if b.is_nan() || a.is_nan() || b <= a {
                return Err(Error::NumericalFailure {
                    what: "a fitted segment through zero curvature",
                });
            }
            if a > pos {
                // Straight across the hair.
                let gap = (a - pos) * len * scale;
                if pos > 0.0 {
                    inflection = Some(s + 0.5 * gap);
                    after_inflection = Some(segments.len());
                }
                start += gap * Vec2::from_angle(theta);
                s += gap;
            }
            let (ka, kb) = (law.at(a).1 / scale, law.at(b).1 / scale);
            let seg_len = (b - a) * len * scale;
            let seg = Segment::from_curvatures(start, theta, [ka, kb], seg_len, alpha)?;
            segment_s.push(s);
            start = seg.end_point();
            theta = seg.theta_at_s(seg.arc_length())?;
            s += seg.arc_length();
            pos = b;
            segments.push(seg);
        }
        if pos < 1.0 {
            let gap = (1.0 - pos) * len * scale;
            start += gap * Vec2::from_angle(theta);
            s += gap;
        }
        let last = segments.len() - 1;
        inflections.extend(after_inflection);
        pieces.push(FitPiece {
            alpha,
            curvatures: [
                segments[first].signed_curvature_start(),
                segments[last].signed_curvature_end(),
            ],
            length: s - piece_s,
            s: piece_s,
            inflection,
            segments: [first, last],
        });
    }
    let fit_size = scale;
    // The placed segments against the solver's tabulated chain.
    let mut model_error: f64 = 0.0;
    for (i, piece) in pieces.iter().enumerate() {
        for k in piece.segments[0]..=piece.segments[1] {
            let seg = &segments[k];
            let seg_s = segment_s[k];
            for j in 0..=4 {
                let u = j as f64 / 4.0 * seg.arc_length();
                let p = seg.point_at_s(u)?;
                let t = ((seg_s + u - piece.s) / piece.length).clamp(0.0, 1.0);
                let (q, _, _) = chain.pieces[i].at(t);
                model_error = model_error.max((p - input.caller(q)).hypot());
            }
        }
    }
    // Far from the origin the caller's coordinates themselves round: their last bits are
    // allowed on top (a fit of points 1e7 from the origin and 1e-4 apart).
    let magnitude = input.center.x.abs().max(input.center.y.abs()) + fit_size;
    // The tables place a piece's points to a share of its own length (1e-11 of it through
    // an inflection): a chain far longer than the points' extent (a wandering fit of
    // scattered points, 900 times as long) is held to that share of its length.
    let reach = fit_size * chain.length().max(1.0);
    if model_error.is_nan() || model_error > MODEL_LIMIT * reach + 64.0 * f64::EPSILON * magnitude {
        return Err(Error::NumericalFailure {
            what: "the placed segments of the fit (they differ from the solver's chain)",
        });
    }
    // Joints.
    let closed = options.closure == Closure::Closed;
    let mut joints = Vec::new();
    let n = pieces.len();
    let joint_count = if closed { n } else { n - 1 };
    for i in 0..joint_count {
        let before = &segments[pieces[i].segments[1]];
        let after = &segments[pieces[(i + 1) % n].segments[0]];
        let (kb, ka) = (
            before.signed_curvature_end(),
            after.signed_curvature_start(),
        );
        let theta_b = before.theta_at_s(before.arc_length())?;
        let theta_a = after.theta_at_s(0.0)?;
        let jump = (theta_b - theta_a).rem_euclid(std::f64::consts::TAU);
        let largest = kb.abs().max(ka.abs());
        joints.push(FitJoint {
            s: pieces[i].s + pieces[i].length,
            point: before.end_point(),
            curvature_before: kb,
            curvature_after: ka,
            gap: (before.end_point() - after.start_point()).hypot(),
            tangent_jump: jump.min(std::f64::consts::TAU - jump),
            curvature_jump: if largest > 0.0 {
                (kb - ka).abs() / largest
            } else {
                0.0
            },
        });
    }
    for (k, j) in joints.iter().enumerate() {
        let closing = closed && k + 1 == joints.len();
        let flat = j.curvature_before.abs().max(j.curvature_after.abs())
            <= INFLECTION_LIMIT * largest_kappa / scale;
        // Relative to the joint's own curvature, or where that is far below the fit's
        // largest, to the rounding of the largest (a joint far below it carries the
        // rounding of its segments' curvature ratios on both sides).
        let rounding = CURVATURE_ROUNDING * largest_kappa / scale;
        let g2_ok = options.continuity == Continuity::G1
            || j.curvature_jump <= G2_JUMP_LIMIT
            || (j.curvature_before - j.curvature_after).abs() <= rounding
            || flat;
        if !(j.gap <= JOINT_LIMIT * fit_size && j.tangent_jump <= JOINT_LIMIT && g2_ok) {
            // The closing joint is where the solver's closure constraints were not met.
            if closing {
                return Err(Error::FitNotClosed { segments: n });
            }
            return Err(Error::NumericalFailure {
                what: "a joint of the fit (it is not continuous)",
            });
        }
    }
    for &k in &inflections {
        let a = segments[k - 1].signed_curvature_end().abs();
        let b = segments[k].signed_curvature_start().abs();
        if a.max(b) > INFLECTION_LIMIT * 10.0 * largest_kappa / scale {
            return Err(Error::NumericalFailure {
                what: "an inflection of the fit (its curvature does not reach zero)",
            });
        }
    }
    let distances: Vec<f64> = state.distances.iter().map(|d| d * scale).collect();
    if !distances.iter().all(|d| d.is_finite()) {
        return Err(Error::NumericalFailure {
            what: "the distances of the points to the fit",
        });
    }
    let worst = super::worst_index(&distances);
    if let Some(tol) = options.tolerance {
        if distances[worst] > tol {
            return Err(Error::NumericalFailure {
                what: "the fit's distances (a point beyond the tolerance)",
            });
        }
    }
    let rms = (distances.iter().map(|d| d * d).sum::<f64>() / distances.len() as f64).sqrt();
    let feet = state.feet.iter().map(|f| f * scale).collect();
    Ok(Fit {
        segments,
        pieces,
        joints,
        continuity: options.continuity,
        closure: options.closure,
        distances,
        feet,
        rms,
        worst,
    })
}
