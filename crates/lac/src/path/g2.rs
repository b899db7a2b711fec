//! Newton's method on the joint fractions for curvature continuity (see the module
//! documentation of [`crate::path`] for the equations).

use super::{banded, Continuity, ControlPolygon, Path};

use crate::foundation::error::{Error, G2Failure, Result};
use crate::foundation::numeric::length;
use crate::segment::{end_curvatures_of, normalized, Segment, SegmentSolution};

/// The solver stops once every joint's |ln(κ⁻/κ⁺)| is below this (about the rounding of
/// the segments' end curvatures); a result must in any case meet
/// [`G2_JUMP_LIMIT`](super::G2_JUMP_LIMIT).
pub const G2_TOLERANCE: f64 = 1e-12;

/// Most Newton steps.
const MAX_STEPS: usize = 60;
/// Step in ln r of the forward difference for dG/d ln r.
const H: f64 = 1e-6;
/// Largest change of any joint's logit fraction in one step.
const MAX_STEP: f64 = 2.0;
/// The solver stops once every segment's chord angle is within this (radians) of its
/// control triangle's, as well as its joints continuous: a segment taken at a μ predicted
/// on the way (see [`evaluate`]) is solved again on its own if it misses by more.
const MISS_TOLERANCE: f64 = 1e-14;

/// A G2 path, or the nearest G1 path and why G2 failed.
#[derive(Clone, Debug)]
pub struct G2Outcome {
    /// The path: G2 when `failure` is `None`, else the G1 path with the smallest curvature
    /// jumps the search reached.
    pub path: Path,
    /// Why there is no G2 path ([`Error::NoG2Path`]), if there is none.
    pub failure: Option<Error>,
}

impl G2Outcome {
    /// The G2 path, or the error that says why none was found.
    pub(crate) fn into_result(self) -> Result<Path> {
        match self.failure {
            None => Ok(self.path),
            Some(error) => Err(error),
        }
    }
}

/// One segment's end curvatures and the scale-free derivatives of ln|κ| at its ends in
/// ln r.
struct Eval {
    /// The segment, solved.
    solved: SegmentSolution,
    /// Signed curvature at the first and last point.
    kappa: (f64, f64),
    /// ln|κ| at the first and last point, corrected for the chord angle the segment misses.
    log_kappa: [f64; 2],
    /// d(ln|κ0| + ln a)/d ln r and d(ln|κ1| + ln b)/d ln r, r = a/b with the last point
    /// moved along its leg.
    slope: Option<[f64; 2]>,
}

/// The state at one set of fractions.
struct State {
    /// Logit of each joint's fraction.
    x: Vec<f64>,
    /// Fraction of every leg where a segment starts.
    t: Vec<f64>,
    /// Fraction of every leg where a segment ends (differs on inflection legs).
    t_end: Vec<f64>,
    evals: Vec<Eval>,
    /// ln|κ⁻| − ln|κ⁺| at each joint, with each segment's end curvatures corrected to
    /// first order for the chord angle it misses: what Newton's step brings to zero.
    residual: Vec<f64>,
    /// ln|κ⁻| − ln|κ⁺| at each joint of the segments as they are.
    raw: Vec<f64>,
}

impl State {
    /// The size of the joint residuals (as the segments are, uncorrected) and of the
    /// segments' chord-angle misses together.
    fn norm(&self) -> f64 {
        let misses = self
            .evals
            .iter()
            .map(|e| e.solved.chord_angle_miss().powi(2));
        self.raw
            .iter()
            .map(|r| r * r)
            .chain(misses)
            .sum::<f64>()
            .sqrt()
    }

    /// The largest chord-angle miss of a segment.
    fn miss(&self) -> f64 {
        self.evals
            .iter()
            .fold(0.0, |m, e| m.max(e.solved.chord_angle_miss().abs()))
    }

    /// The largest jump ln|κ⁻/κ⁺| of the segments as they are.
    fn max(&self) -> f64 {
        self.raw.iter().fold(0.0, |m, r| m.max(r.abs()))
    }
}

fn logistic(x: f64) -> f64 {
    if x >= 0.0 {
        1.0 / (1.0 + (-x).exp())
    } else {
        let e = x.exp();
        e / (1.0 + e)
    }
}

/// The inflection legs of a polygon and the fixed leg ratios of the segments next to them.
pub(super) struct Inflections {
    /// The joint legs that are unknowns (not inflection legs).
    unknown: Vec<usize>,
    /// The inflection legs.
    legs: Vec<usize>,
    /// Per segment: the ratio (inflection leg / other leg) when its start leg is an
    /// inflection leg.
    at_start: Vec<Option<f64>>,
    /// Per segment: the same when its end leg is one.
    at_end: Vec<Option<f64>>,
}

impl Inflections {
    /// Whether segment `k`'s shape is fixed (it ends at an inflection).
    fn fixed(&self, k: usize) -> bool {
        self.at_start[k].is_some() || self.at_end[k].is_some()
    }
}

/// The inflections of `polygon`, or the leg and why no G2 path can pass through one.
fn inflections(
    polygon: &ControlPolygon,
    alphas: &[f64],
) -> std::result::Result<Inflections, (usize, G2Failure)> {
    let legs = polygon.inflection_legs();
    let m = polygon.segment_count();
    let (mut at_start, mut at_end) = (vec![None; m], vec![None; m]);
    for &leg in &legs {
        let (before, after) = polygon.segments_at_leg(leg);
        if alphas[before] >= 0.0 || alphas[after] >= 0.0 {
            return Err((
                leg,
                G2Failure::Inflection {
                    alphas: [alphas[before], alphas[after]],
                },
            ));
        }
        for (k, slot) in [(before, &mut at_end), (after, &mut at_start)] {
            let turning = {
                let [a, p, b] = polygon.control_points(
                    &vec![0.5; polygon.leg_count()],
                    &vec![0.5; polygon.leg_count()],
                    k,
                );
                let (u, v) = (normalized(p - a), normalized(b - p));
                u.cross(v).abs().atan2(u.dot(v))
            };
            match super::inflection::leg_ratio(alphas[k], turning) {
                Some((q, _)) => slot[k] = Some(q),
                None => {
                    return Err((leg, G2Failure::InflectionUnresolved { alpha: alphas[k] }));
                }
            }
        }
    }
    for k in 0..m {
        if at_start[k].is_some() && at_end[k].is_some() {
            let (sl, _) = polygon.legs_of_segment(k);
            return Err((
                sl,
                G2Failure::InflectionsAtOneVertex {
                    vertex: polygon.vertex_of_segment(k),
                },
            ));
        }
    }
    let unknown = polygon
        .joint_legs()
        .into_iter()
        .filter(|l| !legs.contains(l))
        .collect();
    Ok(Inflections {
        unknown,
        legs,
        at_start,
        at_end,
    })
}

/// The fractions where segments start and end on every leg for logit fractions `x` of the
/// unknown joints: on an inflection leg, each neighbouring segment's fixed leg ratio places
/// its end from its other leg.
fn fractions_of(
    polygon: &ControlPolygon,
    infl: &Inflections,
    x: &[f64],
) -> Result<(Vec<f64>, Vec<f64>)> {
    let mut joint = vec![0.5; polygon.joint_legs().len()];
    let legs = polygon.joint_legs();
    for (&leg, &x) in infl.unknown.iter().zip(x) {
        let i = legs.iter().position(|&l| l == leg).expect("a joint leg");
        joint[i] = logistic(x);
    }
    if joint.iter().any(|&t| !(t > 0.0 && t < 1.0)) {
        return Err(Error::NumericalFailure {
            what: "a joint fraction (it reached an end of its leg)",
        });
    }
    let mut t = polygon.leg_fractions(&joint);
    let mut t_end = t.clone();
    for &leg in &infl.legs {
        let (before, after) = polygon.segments_at_leg(leg);
        let length = polygon.leg_length(leg);
        let (sl, _) = polygon.legs_of_segment(before);
        let a = (1.0 - t[sl]) * polygon.leg_length(sl);
        t_end[leg] = infl.at_end[before].expect("fixed") * a / length;
        let (_, el) = polygon.legs_of_segment(after);
        let b = t_end[el] * polygon.leg_length(el);
        // (Beyond the leg's far end while iterating: the triangle stays valid on the leg's
        // line, and the overlap is checked on the answer.)
        t[leg] = 1.0 - infl.at_start[after].expect("fixed") * b / length;
    }
    Ok((t, t_end))
}

/// The segments and joint residuals at logit fractions `x`, or the segment that fails.
///
/// From a `previous` state, each segment is not solved but taken once at the μ its
/// previous solution's derivatives predict (Newton's method on the joint fractions and the
/// segments' μ together: one evaluation a segment a step instead of a solve), and its end
/// curvatures corrected to first order for the chord angle it misses.
fn evaluate(
    polygon: &ControlPolygon,
    alphas: &[f64],
    infl: &Inflections,
    x: Vec<f64>,
    previous: Option<Previous<'_>>,
) -> Result<State> {
    let (t, t_end) = fractions_of(polygon, infl, &x)?;
    let evals = (0..polygon.segment_count())
        .map(|k| {
            let points = polygon.control_points(&t, &t_end, k);
            let advanced = match previous {
                Some(Previous::State(p, step)) => p.evals[k].solved.advanced(points, step),
                Some(Previous::Guess) => SegmentSolution::guessed(points, alphas[k]),
                None => None,
            };
            advanced
                .map_or_else(|| SegmentSolution::new(points, alphas[k]), Ok)
                .and_then(|solved| {
                    let (k0, k1) = solved.end_curvatures()?;
                    let [c0, c1] = solved.log_corrections().unwrap_or([0.0, 0.0]);
                    Ok(Eval {
                        kappa: (k0, k1),
                        log_kappa: [k0.abs().ln() + c0, k1.abs().ln() + c1],
                        solved,
                        slope: None,
                    })
                })
                .map_err(|e| Error::PathSegment {
                    vertex: polygon.vertex_of_segment(k),
                    source: Box::new(e),
                })
        })
        .collect::<Result<Vec<_>>>()?;
    let residual = infl
        .unknown
        .iter()
        .map(|&leg| {
            let (before, after) = polygon.segments_at_leg(leg);
            evals[before].log_kappa[1] - evals[after].log_kappa[0]
        })
        .collect();
    let raw = infl
        .unknown
        .iter()
        .map(|&leg| {
            let (before, after) = polygon.segments_at_leg(leg);
            (evals[before].kappa.1.abs() / evals[after].kappa.0.abs()).ln()
        })
        .collect();
    Ok(State {
        x,
        t,
        t_end,
        evals,
        residual,
        raw,
    })
}

/// Where [`evaluate`] takes each segment's μ from.
#[derive(Clone, Copy)]
enum Previous<'a> {
    /// Predicted from the segment's solution in this state, by this share of a Newton
    /// step.
    State(&'a State, f64),
    /// The chord-angle search's first guess.
    Guess,
}

/// `state` with every segment that misses its chord angle by more than
/// [`MISS_TOLERANCE`] solved on its own, and the residuals again.
fn settled(
    polygon: &ControlPolygon,
    alphas: &[f64],
    infl: &Inflections,
    state: State,
) -> Result<State> {
    if state.miss() <= MISS_TOLERANCE {
        return Ok(state);
    }
    evaluate(polygon, alphas, infl, state.x, None)
}

/// dG0/d ln r and dG1/d ln r of segment `k`: exact, from its solution's derivatives, or
/// where those are not numbers by a forward difference (its end point moved toward its
/// vertex by the factor e^{−h}, backwards when that is not drawable).
fn slopes(alphas: &[f64], infl: &Inflections, state: &State, k: usize) -> Option<[f64; 2]> {
    if infl.fixed(k) {
        // Its leg ratio is fixed: its G0, G1 do not change.
        return Some([0.0, 0.0]);
    }
    let eval = &state.evals[k];
    if let Some(exact) = eval.solved.log_slopes() {
        return Some(exact);
    }
    let [q0, p, q1] = eval.solved.points();
    let (k0, k1) = eval.kappa;
    for h in [H, -H] {
        let moved = p + (q1 - p) * (-h).exp();
        let Ok((m0, m1)) = end_curvatures_of([q0, p, moved], alphas[k]) else {
            continue;
        };
        let g0 = (m0.abs() / k0.abs()).ln() / h;
        let g1 = (m1.abs() / k1.abs()).ln() / h - 1.0;
        if g0.is_finite() && g1.is_finite() {
            return Some([g0, g1]);
        }
    }
    None
}

/// Logit fractions that give each segment legs of similar length: a vertex may use at
/// most half of a leg it shares with another vertex (all of an open polygon's end leg), and
/// each joint splits its leg in proportion to what its two vertices can use on their other
/// sides.
fn balanced_start(polygon: &ControlPolygon) -> Vec<f64> {
    let n = polygon.points().len();
    let leg_length = |i: usize| {
        let (a, b) = polygon.leg(i);
        length(b - a)
    };
    let joints = polygon.joint_legs();
    let is_joint = |i: usize| polygon.is_closed() || (i > 0 && i + 2 < n);
    let usable = |i: usize| {
        if is_joint(i) {
            0.5 * leg_length(i)
        } else {
            leg_length(i)
        }
    };
    joints
        .iter()
        .map(|&leg| {
            let (before, after) = polygon.segments_at_leg(leg);
            let (sl, _) = polygon.legs_of_segment(before);
            let (_, el) = polygon.legs_of_segment(after);
            let (wb, wa) = (usable(sl), usable(el));
            let t = (wb / (wb + wa)).clamp(0.05, 0.95);
            (t / (1.0 - t)).ln()
        })
        .collect()
}

/// Logit fractions `x` of the unknown joints moved so that each segment that ends at an
/// inflection takes at most 45% of its inflection leg: its other leg is short enough (a
/// segment from an inflection point is long and flat there, its inflection-side leg several
/// times its other leg), so that Newton's method starts where every segment fits.
fn room_for_inflections(polygon: &ControlPolygon, infl: &Inflections, mut x: Vec<f64>) -> Vec<f64> {
    const SHARE: f64 = 0.45;
    let logit = |t: f64| (t / (1.0 - t)).ln();
    for &leg in &infl.legs {
        let length = polygon.leg_length(leg);
        let (before, after) = polygon.segments_at_leg(leg);
        let (sl, _) = polygon.legs_of_segment(before);
        if let Some(u) = infl.unknown.iter().position(|&l| l == sl) {
            let q = infl.at_end[before].expect("fixed");
            let lowest = 1.0 - SHARE * length / (q * polygon.leg_length(sl));
            if lowest > 0.0 {
                x[u] = x[u].max(logit(lowest.min(0.95)));
            }
        }
        let (_, el) = polygon.legs_of_segment(after);
        if let Some(u) = infl.unknown.iter().position(|&l| l == el) {
            let q = infl.at_start[after].expect("fixed");
            let highest = SHARE * length / (q * polygon.leg_length(el));
            if highest < 1.0 {
                x[u] = x[u].min(logit(highest.max(0.05)));
            }
        }
    }
    x
}

/// Newton's method (damped) on the joint equations from `state`, returning the last
/// iterate: on the joint fractions and the segments' μ together when `joint` (see
/// [`evaluate`]), else on the fractions with every segment solved at every iterate.
fn newton(
    polygon: &ControlPolygon,
    alphas: &[f64],
    infl: &Inflections,
    mut state: State,
    joint: bool,
) -> State {
    let legs = &infl.unknown;
    let n = legs.len();
    let cyclic = polygon.is_closed();
    for _ in 0..MAX_STEPS {
        if state.max() <= G2_TOLERANCE && state.miss() <= MISS_TOLERANCE {
            break;
        }
        // The tridiagonal Jacobian of the residuals in the logit fractions: dG/d ln r of
        // each segment (exact, from its solution) by the chain rule.
        for k in 0..state.evals.len() {
            state.evals[k].slope = slopes(alphas, infl, &state, k);
        }
        let (mut sub, mut diag, mut sup) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut ok = true;
        for (u, &leg) in legs.iter().enumerate() {
            let (before, after) = polygon.segments_at_leg(leg);
            let (Some(gb), Some(ga)) = (state.evals[before].slope, state.evals[after].slope) else {
                ok = false;
                break;
            };
            let t = state.t[leg];
            let (sl, _) = polygon.legs_of_segment(before);
            let (_, el) = polygon.legs_of_segment(after);
            // R = G1(before) − G0(after) − x, ln r(before) = ln(1 − t_sl) − ln t_leg + …,
            // ln r(after) = ln(1 − t_leg) − ln t_el + ….
            diag[u] = gb[1] * -(1.0 - t) - ga[0] * -t - 1.0;
            sub[u] = gb[1] * -state.t[sl];
            sup[u] = -ga[0] * -(1.0 - state.t[el]);
            // A neighbour that is an end leg of an open polygon is not an unknown.
            if !cyclic && u == 0 {
                sub[u] = 0.0;
            }
            if !cyclic && u + 1 == n {
                sup[u] = 0.0;
            }
        }
        if !ok {
            break;
        }
        let rhs: Vec<f64> = state.residual.iter().map(|r| -r).collect();
        let Some(dx) = banded::solve(&sub, &diag, &sup, &rhs, cyclic) else {
            break;
        };
        let biggest = dx.iter().fold(0.0f64, |m, d| m.max(d.abs()));
        let mut lambda = if biggest > MAX_STEP {
            MAX_STEP / biggest
        } else {
            1.0
        };
        let norm = state.norm();
        let mut next = None;
        for _ in 0..30 {
            let x: Vec<f64> = state
                .x
                .iter()
                .zip(&dx)
                .map(|(x, d)| x + lambda * d)
                .collect();
            let previous = joint.then_some(Previous::State(&state, lambda));
            if let Ok(s) = evaluate(polygon, alphas, infl, x, previous) {
                if s.norm() < norm * (1.0 - 1e-4 * lambda) {
                    next = Some(s);
                    break;
                }
            }
            lambda *= 0.5;
        }
        match next {
            Some(s) => state = s,
            None => break,
        }
    }
    state
}

/// Solve the G2 joint equations (see the module documentation of [`crate::path`]).
pub(super) fn solve(
    polygon: &ControlPolygon,
    alphas: &[f64],
    warm: Option<&[f64]>,
) -> Result<G2Outcome> {
    let legs = polygon.joint_legs();
    let n = legs.len();
    // Inflection legs: the curvature passes through zero on a straight piece there, between
    // two segments of fixed shape.
    let infl = match inflections(polygon, alphas) {
        Ok(infl) => infl,
        Err((leg, reason)) => {
            return nearest_g1(polygon, alphas, None, Error::NoG2Path { leg, reason });
        }
    };
    // Only the joints on other legs are unknowns.
    let unknowns = |x: Vec<f64>| -> Vec<f64> {
        legs.iter()
            .zip(x)
            .filter(|(l, _)| infl.unknown.contains(l))
            .map(|(_, x)| x)
            .collect()
    };
    let warm: Option<Vec<f64>> = match warm {
        Some(w) if w.len() == n && w.iter().all(|t| *t > 0.0 && *t < 1.0) => {
            Some(unknowns(w.iter().map(|t| (t / (1.0 - t)).ln()).collect()))
        }
        _ => None,
    };
    // Starts in order: the warm start, fractions that make each segment's legs alike (the
    // isosceles triangle is a circular arc, drawable for every α), the midpoints.
    // With inflections, the same moved to give the segments there room first.
    let plain = [
        unknowns(balanced_start(polygon)),
        vec![0.0; infl.unknown.len()],
    ];
    let roomy: Vec<Vec<f64>> = if infl.legs.is_empty() {
        Vec::new()
    } else {
        plain
            .iter()
            .map(|x| room_for_inflections(polygon, &infl, x.clone()))
            .collect()
    };
    let starts = warm.into_iter().chain(roomy).chain(plain);
    // Newton from each start that can be evaluated, until one converges; otherwise the
    // best iterate reached (smallest residual) is the nearest G1 path.
    let mut first_error = None;
    let mut best: Option<State> = None;
    let converged = |s: &State| s.max() <= 0.5 * super::G2_JUMP_LIMIT;
    for start in starts {
        // Newton on fractions and μ together first (fast); where that does not end at a
        // G2 path (it may stray where a segment cannot be drawn), on the fractions alone.
        let attempt = |joint: bool| {
            let first = joint.then_some(Previous::Guess);
            evaluate(polygon, alphas, &infl, start.clone(), first).and_then(|s| {
                let last = newton(polygon, alphas, &infl, s, joint);
                settled(polygon, alphas, &infl, last)
            })
        };
        let state = match attempt(true) {
            Ok(s) if converged(&s) => Ok(s),
            _ => attempt(false),
        };
        let state = match state {
            Ok(s) => s,
            Err(e) => {
                first_error.get_or_insert(e);
                continue;
            }
        };
        let done = converged(&state);
        if best.as_ref().is_none_or(|b| state.norm() < b.norm()) {
            best = Some(state);
        }
        if done {
            break;
        }
    }
    let Some(state) = best else {
        return Err(first_error.expect("at least one start was tried"));
    };
    let fractions: Vec<f64> = legs
        .iter()
        .map(|&leg| (0.5 * (state.t[leg] + state.t_end[leg])).clamp(0.05, 0.95))
        .collect();
    // The segments as solved at the answer, built and checked.
    let State {
        t,
        t_end,
        evals,
        raw: residual,
        ..
    } = state;
    let segments = evals
        .into_iter()
        .enumerate()
        .map(|(k, e)| {
            e.solved.into_segment().map_err(|e| Error::PathSegment {
                vertex: polygon.vertex_of_segment(k),
                source: Box::new(e),
            })
        })
        .collect::<Result<Vec<Segment>>>()?;
    let jump_ok = residual
        .iter()
        .all(|r| r.abs() <= 0.5 * super::G2_JUMP_LIMIT);
    // Each straight piece must fit on its leg.
    let overlap = infl
        .legs
        .iter()
        .map(|&leg| (leg, t_end[leg] - t[leg]))
        .find(|(_, o)| *o > 0.0);
    if let (true, Some((leg, overlap))) = (jump_ok, overlap) {
        let failure = Error::NoG2Path {
            leg,
            reason: G2Failure::InflectionLegTooShort { overlap },
        };
        return nearest_g1(polygon, alphas, Some(&fractions), failure);
    }
    if jump_ok {
        let failure = match Path::assemble(
            polygon.clone(),
            alphas.to_vec(),
            [t, t_end],
            segments,
            Continuity::G2,
        ) {
            Ok(path) => {
                return Ok(G2Outcome {
                    path,
                    failure: None,
                })
            }
            // An inflection whose segments could not reach zero curvature.
            Err(failure @ Error::NoG2Path { .. }) => failure,
            Err(e) => return Err(e),
        };
        return nearest_g1(polygon, alphas, Some(&fractions), failure);
    }
    let (worst, jump) = residual
        .iter()
        .enumerate()
        .fold(
            (0, 0.0f64),
            |(i, m), (j, r)| if r.abs() > m { (j, r.abs()) } else { (i, m) },
        );
    let failure = Error::NoG2Path {
        leg: infl.unknown[worst],
        reason: G2Failure::NoConvergence { jump },
    };
    nearest_g1(polygon, alphas, Some(&fractions), failure)
}

/// The outcome of a G2 search that failed with `failure`: the G1 path at the joint
/// `fractions` it reached (if any), or at the leg midpoints where that one cannot be drawn;
/// `failure` itself as the error when neither can (why G2 failed is then the more useful
/// error).
fn nearest_g1(
    polygon: &ControlPolygon,
    alphas: &[f64],
    fractions: Option<&[f64]>,
    failure: Error,
) -> Result<G2Outcome> {
    let alphas = super::Alphas::PerSegment(alphas.to_vec());
    let reached = fractions.map(|f| Path::from_polygon_g1(polygon, &alphas, Some(f)));
    match reached
        .filter(Result::is_ok)
        .unwrap_or_else(|| Path::from_polygon_g1(polygon, &alphas, None))
    {
        Ok(path) => Ok(G2Outcome {
            path,
            failure: Some(failure),
        }),
        Err(_) => Err(failure),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kurbo::{Point, Vec2};

    /// The exact dG/d ln(a/b) of a solved segment agree with extrapolated central
    /// differences of its
    /// end curvatures, for every kind of α (the clothoid's closed form, pieces that head
    /// toward an inflection or toward ρ = 0), either leg the longer (the piece solved from
    /// either end), turnings from 0.1 to 3 rad, left and right.
    #[test]
    fn exact_slopes_match_differences() {
        const H: f64 = 1e-4;
        let mut worst: f64 = 0.0;
        let mut checked = 0;
        for alpha in [-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0] {
            for turning in [0.1, 0.6, 1.2, 2.0, 3.0] {
                for ratio in [0.35, 0.6, 0.9, 1.0, 1.2, 1.9, 3.0] {
                    for side in [1.0, -1.0] {
                        let q0 = Point::new(-1.0, 0.0);
                        let p = Point::ZERO;
                        let q1 = p + Vec2::from_angle(side * turning) * ratio;
                        let Ok(solved) = SegmentSolution::new([q0, p, q1], alpha) else {
                            continue;
                        };
                        let exact = solved.log_slopes().expect("exact slopes");
                        // G as a function of ln(a/b) = −ln b: the last point moved along its
                        // leg.
                        let g = |h: f64| {
                            let moved = p + (q1 - p) * (-h).exp();
                            let (k0, k1) = end_curvatures_of([q0, p, moved], alpha).ok()?;
                            let b = (moved - p).hypot();
                            Some([k0.abs().ln() + 1.0, k1.abs().ln() + b.ln()])
                        };
                        // Central differences at h and h/2, extrapolated (error O(h⁴)).
                        let steps = [H, -H, 0.5 * H, -0.5 * H].map(g);
                        let [Some(up), Some(down), Some(up2), Some(down2)] = steps else {
                            continue;
                        };
                        for i in 0..2 {
                            let coarse = (up[i] - down[i]) / (2.0 * H);
                            let fine = (up2[i] - down2[i]) / H;
                            let diff = (4.0 * fine - coarse) / 3.0;
                            let err = (exact[i] - diff).abs() / diff.abs().max(1.0);
                            assert!(
                                err < 1e-8,
                                "alpha {alpha}, turning {turning}, ratio {ratio}, side {side}, \
                                 end {i}: exact {} against {diff}",
                                exact[i]
                            );
                            worst = worst.max(err);
                        }
                        checked += 1;
                    }
                }
            }
        }
        eprintln!("{checked} segments, worst relative difference {worst:e}");
        assert!(checked > 400, "{checked}");
    }
}
