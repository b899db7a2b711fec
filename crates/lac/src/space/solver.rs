//! The search for a space segment's standard form (seed 003 §4): given the end geometry
//! and the shape, find Λ and ν (and the end s) so that the standard form's end meets the
//! chord's cone; near-helix starts first, then the free-end search, and when Ω itself is out
//! of reach the Ω continuation from the Ω = 0 segment, which finds Ω_max. Which segment is
//! returned when several fit is documented at
//! [`SpaceSegment::from_control_points`](crate::SpaceSegment::from_control_points).

use super::family::{SpaceForm, SpaceFormParams};
use super::mat3::Mat3;
use super::segment::{Found, SpaceShape};
use super::shoot::{
    end_angles, guard_end, integrate_to, integrate_tracked, shoot, shoot_each_and_touches, Budget,
    Checkpoints, Cone, Shot, Touches, Track, SOLVE_STEPS,
};
use super::similarity::{mirror, Similarity3};
use super::taylor::{Accuracy, State};
use crate::foundation::error::{Error, NotDrawable, Result};
use crate::foundation::vec3::Vec3;
use std::rc::Rc;

/// The Λ of the start scans: near-helix first, then a spiral.
const START_LAMBDAS: [f64; 2] = [0.0, 1.0];

/// The Λ of the scans that seed the free-end fallback ([`Problem::attempt_free_end`]).
const FREE_END_LAMBDAS: [f64; 4] = [0.0, 0.15, 0.4, 1.0];

/// How many points a ν scan has: four decades of [`SCAN_STEP`].
const SCAN_POINTS: u32 = 16;

/// The spacing of a ν scan in ln ν: a quarter decade.
const SCAN_STEP: f64 = 0.25 * std::f64::consts::LN_10;

/// How many of the fallback's starts (best first) are tried.
const FREE_END_STARTS: usize = 12;

/// How many of the scans' touches (best first) the fallback tries after its starts: where
/// the curve ends grazing the cone (|θ2| near π/2), or after it has come close to the cone
/// without crossing it, the crossing that ends the segment has no fixed number, so the
/// starts by crossing miss it; the end comes close to the cone on the scan's curves nearby.
const TOUCH_STARTS: usize = 8;

/// How many of the scans' ends cut off by the 2π guard near the cone
/// ([`Touches::cut_off`], best first) the fallback tries after the touches, with
/// [`PastGuard::PullBack`]: segments that end close to their guard where the torsion blows
/// up (see `shoot::guard_touch`). Tried last, so that every input solved without them gets
/// the same segment. Measured on the constructed inputs (`every_cell_solves_long_pieces`,
/// 2,000 per cell): 2 solve 27 of the 38 inputs missed without them (13 of 14 at α = 2,
/// β = 1, type 2) and raise the space benchmark's median refusal by 6–20% in integration
/// steps; 3 solve 3 more (α = 0, β = 0, type 2; 4 no more than 3) and raise it by 7–31%.
const CUT_OFF_STARTS: usize = 2;

/// A solution whose tangent and binormal turn by at most this much (3π/2) is accepted at
/// once; beyond it (nearly a loop) the other starts are tried for a gentler one.
const GENTLE_TURNING: f64 = 1.5 * std::f64::consts::PI;

/// Newton stops when both components of the end-tangent residual are below this (radians).
const RESIDUAL_TOLERANCE: f64 = 1e-13;

/// How often Newton's step is halved looking for a lower residual before the iteration gives
/// up: a step cut to 1/16 that still does not descend means the linear model is wrong there
/// (the edge of the region where the curve meets the cone, a fold), and more halvings, each
/// an integration, only delay the next start. Measured: 12 halvings solve the same
/// constructed inputs (5990/6000 and 5991/6000 on two sets of three seeds) and refuse 23%
/// slower.
const LINE_SEARCH_HALVINGS: u32 = 4;

/// The most Newton solves the continuation in Ω makes. Over two of the benchmark's random
/// sets (1,050 "Ω too large" refusals) it needs at most 19 (median 7); a branch that runs off
/// to Λ → ∞ (seen at α = 3, Λ past 10⁴) would otherwise creep on in steps of 0.1% of Ω,
/// 150 solves and 0.1 s. The Ω_max reported stays a verified lower bound.
const CONTINUATION_TRIES: u32 = 40;

/// Newton's iterations shoot at [`Accuracy::Search`] until the residual is below this
/// (radians), far above that accuracy's errors (about 1e-9), and at [`Accuracy::Full`] from
/// there on, so that every converged solve is exact to rounding.
const SEARCH_RESIDUAL: f64 = 1e-6;

/// The required end geometry, after the end swap.
#[derive(Clone, Copy, Debug)]
struct Target {
    theta0: f64,
    theta1: f64,
    theta2: f64,
}

impl Target {
    /// The end-tangent mismatch in polar coordinates about the chord, smooth where θ1 → 0.
    fn residual(&self, shot: &Shot) -> [f64; 2] {
        self.residual_of_angles(shot.theta1, shot.theta2)
    }

    /// [`Target::residual`] of an end at `x` with tangent `t`.
    fn residual_at(&self, x: Vec3, t: Vec3) -> [f64; 2] {
        let (_, theta1, theta2) = end_angles(x, Vec3::X, t);
        self.residual_of_angles(theta1, theta2)
    }

    fn residual_of_angles(&self, theta1: f64, theta2: f64) -> [f64; 2] {
        let (a, b) = (theta1, theta2.abs());
        let (c, d) = (self.theta1, self.theta2.abs());
        [a * b.cos() - c * d.cos(), a * b.sin() - c * d.sin()]
    }
}

/// One converged standard form.
#[derive(Clone, Copy, Debug)]
pub(super) struct Solution {
    pub(super) lambda: f64,
    pub(super) ln_nu: f64,
}

/// A previous segment's standard form and end, to start from.
#[derive(Clone, Copy, Debug)]
pub(super) struct WarmStart {
    pub(super) solution: Solution,
    pub(super) s_end: f64,
    pub(super) reversed: bool,
}

/// A converged solution and the larger of the total turnings θ, φ of its tangent and
/// binormal.
#[derive(Clone, Debug)]
struct Converged {
    solution: Solution,
    turning: f64,
    /// The standard-form end.
    s_end: f64,
    /// Where the solution goes as Ω grows: d(Λ, ln ν, s)/dΩ, when known.
    tangent: Option<[f64; 3]>,
}

/// Solve the space problem: find (Λ, ν) with the standard form starting at the end whose
/// tangent makes the larger angle with the chord, else at the other end; build the
/// similarity.
///
/// Seed 003 starts at the end with the larger angle: a planar spiral's chord makes the
/// larger angle with the tangent where its curvature is larger, and the standard form's
/// curvature falls from its start (Λ ≥ 0). Torsion can turn that round: a long piece
/// whose torsion radius grows (type 1) may end with the larger angle, and then only the
/// other order has a segment with Λ ≥ 0. So the other order is searched too when the first
/// finds nothing; it comes second, so that what the first finds is what was found before.
/// The Ω_max of a refusal is the first order's, or the other's where the first has no
/// segment at Ω = 0.
pub(super) fn solve_space(
    points: [Vec3; 4],
    shape: SpaceShape,
    angles: [f64; 3],
    warm: Option<WarmStart>,
) -> Result<Found> {
    let [theta0, theta1, _] = angles;
    let first = theta0 < theta1;
    let budget = Budget::new(SOLVE_STEPS);
    let scans = [ScanShots::default(), ScanShots::default()];
    let orders = [first, !first].map(|reversed| Order::new(points, reversed));
    let problems = [0, 1].map(|k| orders[k].problem(shape, &budget, &scans[k]));
    let omega = shape.omega;
    // A warm start in the order it was found in (a drag that makes θ0 and θ1 change places
    // keeps following its segment).
    if let Some(w) = warm {
        let k = usize::from(w.reversed != first);
        if let Some(found) =
            problems[k].newton3(w.solution, w.s_end, omega, Accuracy::Full, PastGuard::Halve)
        {
            return orders[k].place(&problems[k], &found, omega);
        }
    }
    if let Some(found) = problems[0].solve_directly(omega) {
        return orders[0].place(&problems[0], &found, omega);
    }
    let refusal = match problems[0].continue_from_zero(omega) {
        Ok(found) => return orders[0].place(&problems[0], &found, omega),
        Err(e) => e,
    };
    // The other order: its free-end search alone (it finds every constructed input that
    // needs this order, the cone search only three in four of them), and its continuation
    // only where the first order has no segment at Ω = 0 to report: together they add about
    // half to a refusal's integration steps, where the whole search would add a time.
    if let Some(found) = problems[1].attempt_free_end(omega) {
        return orders[1].place(&problems[1], &found, omega);
    }
    let other = match refusal {
        Refusal::None => match problems[1].continue_from_zero(omega) {
            Ok(found) => return orders[1].place(&problems[1], &found, omega),
            Err(other) => other,
        },
        Refusal::BranchEnds { .. } => Refusal::None,
    };
    Err(Error::NotDrawable(match refusal.max(other) {
        Refusal::None => NotDrawable::NoSpaceSegment { omega },
        Refusal::BranchEnds { omega_max } => NotDrawable::TorsionTooLarge { omega, omega_max },
    }))
}

/// The refusal of the search in one order of the ends.
#[derive(Clone, Copy, Debug)]
enum Refusal {
    /// No segment at Ω = 0 either.
    None,
    /// The branch of the Ω = 0 segment, followed in Ω, ends at `omega_max`.
    BranchEnds { omega_max: f64 },
}

impl Refusal {
    /// What the two orders together say: the branch that reaches further.
    fn max(self, other: Refusal) -> Refusal {
        match (self, other) {
            (Refusal::None, r) | (r, Refusal::None) => r,
            (Refusal::BranchEnds { omega_max: a }, Refusal::BranchEnds { omega_max: b }) => {
                Refusal::BranchEnds {
                    omega_max: a.max(b),
                }
            }
        }
    }
}

/// One order of the ends: the control points with the standard form's start first.
#[derive(Clone, Copy, Debug)]
struct Order {
    reversed: bool,
    p0: Vec3,
    t0: Vec3,
    chord: Vec3,
    target: Target,
    /// The seed's crossing: the first outward, or the way back in when |θ2| > π/2.
    crossing: u32,
}

impl Order {
    fn new(points: [Vec3; 4], reversed: bool) -> Order {
        let [p0, p1, p2, p3] = if reversed {
            [points[3], points[2], points[1], points[0]]
        } else {
            points
        };
        let t0 = (p1 - p0).normalize();
        let t1 = (p3 - p2).normalize();
        let chord = p3 - p0;
        let (theta0, theta1, theta2) = end_angles(chord, t0, t1);
        let crossing = if theta2.abs() > std::f64::consts::FRAC_PI_2 {
            2
        } else {
            1
        };
        Order {
            reversed,
            p0,
            t0,
            chord,
            target: Target {
                theta0,
                theta1,
                theta2,
            },
            crossing,
        }
    }

    fn problem<'a>(
        &self,
        shape: SpaceShape,
        budget: &'a Budget,
        scans: &'a ScanShots,
    ) -> Problem<'a> {
        Problem {
            shape,
            target: self.target,
            crossing: self.crossing,
            budget,
            scans,
        }
    }

    /// The segment of `found`: checked once more, mirrored and placed on the points.
    fn place(&self, problem: &Problem<'_>, found: &Converged, omega: f64) -> Result<Found> {
        let form = problem.form(&found.solution, omega);
        // The solver's own check: the end it found, integrated once more with its
        // checkpoints, meets the end angles.
        let shot = integrate_to(
            &form,
            found.s_end,
            Checkpoints::Keep,
            Accuracy::Full,
            &Budget::new(SOLVE_STEPS),
        )
        .filter(|shot| problem.residual3(shot).iter().all(|r| r.abs() < 1e-10))
        .ok_or(Error::NotDrawable(NotDrawable::NoSpaceSegment { omega }))?;
        // Mirror when the standard form's dihedral has the other sign (seed 003 §4).
        let mirror_z = (shot.theta2 < 0.0) != (self.target.theta2 < 0.0);
        // Rotation taking e1 to t0 and the standard-form chord to the caller's.
        let frame_of = |axis: Vec3, towards: Vec3| {
            let w = perpendicular(towards, axis);
            Mat3::from_columns(axis, w, axis.cross(w))
        };
        let standard = frame_of(Vec3::X, mirror(shot.end.x, mirror_z));
        let caller = frame_of(self.t0, self.chord);
        let rotation = caller * standard.transpose();
        let transform = Similarity3 {
            scale: self.chord.length() / shot.end.x.length(),
            rotation: rotation.0,
            translation: self.p0,
            mirror_z,
            reversed: self.reversed,
        };
        Ok(Found::Space {
            form,
            s_end: shot.end.s,
            transform,
            checkpoints: shot.checkpoints,
        })
    }
}

/// The unit vector along the part of `v` perpendicular to the unit vector `axis`, by
/// Gram–Schmidt twice: when `v` lies within ~1e-11 rad of `axis` (a start tangent nearly
/// along the chord) one pass leaves it off-perpendicular by ε/angle, ~1e-6, and the frame
/// built on it skewed; the second pass makes it perpendicular to rounding.
pub(super) fn perpendicular(v: Vec3, axis: Vec3) -> Vec3 {
    let w = v - v.dot(axis) * axis;
    (w - w.dot(axis) * axis).normalize()
}

/// `x` with `m x = b` (Cramer's rule); `None` when `m` is singular.
fn solve3(m: [[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(m);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let mut x = [0.0; 3];
    for (k, xk) in x.iter_mut().enumerate() {
        let mut mk = m;
        for i in 0..3 {
            mk[i][k] = b[i];
        }
        *xk = det(mk) / d;
    }
    Some(x)
}

/// The change of `residual` (a function of an end's point and tangent) per unit move of the
/// end (x, t) along (dx, dt), by a central difference.
fn end_slope<const N: usize>(
    residual: impl Fn(Vec3, Vec3) -> [f64; N],
    (x, t): (Vec3, Vec3),
    (dx, dt): (Vec3, Vec3),
) -> [f64; N] {
    let h = 1e-6 / (dx.length() / x.length() + dt.length()).max(1e-300);
    let plus = residual(x + dx * h, t + dt * h);
    let minus = residual(x - dx * h, t - dt * h);
    std::array::from_fn(|i| (plus[i] - minus[i]) / (2.0 * h))
}

/// The branch's point at `omega`, guessed along the tangent at its last point, else on the
/// line through its last two points, else the last point.
fn predict(path: &[(f64, Converged)], omega: f64) -> (Solution, f64) {
    let (om1, c1) = path.last().expect("a branch starts with a point");
    let step = omega - om1;
    let (lambda, ln_nu, s) = if let Some([dl, dn, ds]) = c1.tangent {
        let p = c1.solution;
        (
            p.lambda + step * dl,
            p.ln_nu + step * dn,
            c1.s_end + step * ds,
        )
    } else if let Some((om0, c0)) = path.len().checked_sub(2).map(|i| &path[i]) {
        let t = step / (om1 - om0);
        let lerp = |a: f64, b: f64| b + t * (b - a);
        (
            lerp(c0.solution.lambda, c1.solution.lambda),
            lerp(c0.solution.ln_nu, c1.solution.ln_nu),
            lerp(c0.s_end, c1.s_end),
        )
    } else {
        return (c1.solution, c1.s_end);
    };
    let guess = Solution {
        lambda: if lambda >= 0.0 {
            lambda
        } else {
            0.1 * c1.solution.lambda
        },
        ln_nu,
    };
    (guess, if s > 0.0 { s } else { c1.s_end })
}

/// A point of a ν scan: its grid index, its residual and the start it gives.
type ScanPoint<T> = (u32, f64, T);

/// The points of a scan that lie lowest in their valley:
/// no higher than the points at the neighbouring grid indices (a missing one counts as
/// infinitely high). Starting a search from each, rather than from the lowest few, tries
/// different basins.
fn valley_floors<T: Copy>(points: &[ScanPoint<T>]) -> impl Iterator<Item = (f64, T)> + '_ {
    let at = |k: Option<u32>| {
        k.and_then(|k| points.iter().find(|p| p.0 == k))
            .map_or(f64::INFINITY, |p| p.1)
    };
    points
        .iter()
        .filter(move |p| p.1 <= at(p.0.checked_sub(1)) && p.1 <= at(Some(p.0 + 1)))
        .map(|p| (p.1, p.2))
}

/// The state of a ν scan: the next grid index, the last defined point's dihedral mismatch
/// and every defined point with its grid index and residual.
#[derive(Default)]
struct Scan {
    next: u32,
    prev: Option<(f64, f64)>,
    defined: Vec<ScanPoint<Solution>>,
}

/// The two-parameter search of seed 003 §4 for fixed α, β, type, end geometry and crossing
/// (the Ω of `shape` is the goal; continuation visits smaller ones).
#[derive(Clone, Copy, Debug)]
struct Problem<'a> {
    shape: SpaceShape,
    target: Target,
    crossing: u32,
    /// What is left of the solve's Taylor steps.
    budget: &'a Budget,
    /// The ν scans' shots made so far.
    scans: &'a ScanShots,
}

/// The shots of the ν scans, each to the first [`SCAN_CROSSINGS`] crossings of the cone, by
/// (Ω, Λ, grid index): the cone search and the free-end search scan some of the same points.
#[derive(Debug, Default)]
struct ScanShots(std::cell::RefCell<std::collections::HashMap<(u64, u64, u32), Rc<ScanShot>>>);

/// One shot of a ν scan: its crossings of the cone, in order, and where it comes near the
/// cone without crossing it ([`shoot_each_and_touches`]).
#[derive(Debug)]
struct ScanShot {
    crossings: Vec<Shot>,
    touches: Touches,
}

/// How many crossings of the cone a scan's shot looks for.
const SCAN_CROSSINGS: u32 = 3;

/// What [`Problem::newton3`] does with a trial step whose end lies past the 2π guard of the
/// trial's curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PastGuard {
    /// The trial fails, and the step is halved (the shot cannot end there).
    Halve,
    /// The trial's end is pulled back to just inside its guard, and the trial goes on: for
    /// the starts on the guard ([`Touches::cut_off`]), where a step that lengthens the piece
    /// faster than it moves the guard fails however often it is halved. Measured on the
    /// constructed inputs (2,000 per cell): with it, the cut-offs solve 27 of the 38 missed
    /// without them, against 16 when they halve; pulling back on every start as well loses
    /// one input that halving solves (α = 1, β = 1, type 2), so the other starts keep
    /// halving.
    PullBack,
}

/// How far [`Problem::scan`] goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ScanUntil {
    /// Stop at the first sign change of the dihedral mismatch and return it, interpolated.
    SignChange,
    /// Scan the whole grid, collecting every defined point.
    End,
}

impl Problem<'_> {
    fn cone(&self) -> Cone {
        Cone::new(self.target.theta0, self.crossing)
    }

    /// ln ν at index `k` of the ν scans ([`SCAN_POINTS`] of them): quarter decades upward
    /// from half a decade below tan θ0 ([`Problem::scan`] says why).
    fn scan_ln_nu(&self, k: u32) -> f64 {
        let base = self.target.theta0.min(1.4).tan().ln() - 0.5 * std::f64::consts::LN_10;
        base + f64::from(k) * SCAN_STEP
    }

    /// The crossings of the θ0 cone (up to [`SCAN_CROSSINGS`]) of the form at Λ = `lambda`
    /// and index `k` of the ν scan, and its touches, made once per solve.
    fn scan_shots(&self, omega: f64, lambda: f64, k: u32) -> Rc<ScanShot> {
        let key = (omega.to_bits(), lambda.to_bits(), k);
        if let Some(shots) = self.scans.0.borrow().get(&key) {
            return Rc::clone(shots);
        }
        let p = Solution {
            lambda,
            ln_nu: self.scan_ln_nu(k),
        };
        let cone = Cone::new(self.target.theta0, SCAN_CROSSINGS);
        let mut touches = Touches::default();
        let crossings = shoot_each_and_touches(
            &self.form(&p, omega),
            &cone,
            Accuracy::Scan,
            self.budget,
            Some(&mut touches),
        );
        let shots = Rc::new(ScanShot { crossings, touches });
        self.scans.0.borrow_mut().insert(key, Rc::clone(&shots));
        shots
    }

    fn form(&self, p: &Solution, omega: f64) -> SpaceForm {
        SpaceForm::new_unchecked(SpaceFormParams {
            alpha: self.shape.alpha,
            beta: self.shape.beta,
            lambda: p.lambda,
            omega,
            nu: p.ln_nu.exp(),
            torsion: self.shape.torsion,
        })
    }

    /// The mismatch of a piece ending anywhere: its chord angle at the start less θ0, and
    /// the end-tangent mismatch of [`Target::residual`].
    fn residual3(&self, shot: &Shot) -> [f64; 3] {
        self.residual3_at(shot.end.x, shot.end.t)
    }

    /// [`Problem::residual3`] of an end at `x` with tangent `t`.
    fn residual3_at(&self, x: Vec3, t: Vec3) -> [f64; 3] {
        let r = self.target.residual_at(x, t);
        [Vec3::X.angle_to(x) - self.target.theta0, r[0], r[1]]
    }

    /// The fallback where the cone search found nothing: the end s becomes a third unknown
    /// beside Λ and ln ν, and the three angles θ0, θ1, θ2 of the piece from 0 to s are
    /// matched by [`Problem::newton3`]. Eliminating s by the cone crossing has a fold where
    /// the curve grazes the cone (|θ2| near π/2, where the first and second crossings meet)
    /// and misses ends beyond the second crossing; the angles are smooth in all three
    /// unknowns there. Starts: from ν scans at a few Λ on the cones of the first three
    /// crossings, the lowest point of each valley of the 2-D residual along ν, best first;
    /// then the scans' touches ([`TOUCH_STARTS`]), then their ends where the 2π guard cuts
    /// them off near the cone ([`CUT_OFF_STARTS`]).
    fn attempt_free_end(&self, omega: f64) -> Option<Converged> {
        const CROSSINGS: usize = SCAN_CROSSINGS as usize;
        let mut starts = Vec::new();
        let (mut touches, mut cut_offs) = (Vec::new(), Vec::new());
        for lambda in FREE_END_LAMBDAS {
            // Each crossing's residuals along the ν scan, with the start they give.
            let mut by_crossing: [Vec<ScanPoint<(Solution, f64)>>; CROSSINGS] = Default::default();
            for k in 0..SCAN_POINTS {
                let p = Solution {
                    lambda,
                    ln_nu: self.scan_ln_nu(k),
                };
                let shots = self.scan_shots(omega, lambda, k);
                for (points, shot) in by_crossing.iter_mut().zip(&shots.crossings) {
                    let r = self.target.residual(shot);
                    points.push((k, r[0].hypot(r[1]), (p, shot.end.s)));
                }
                let start = |shot: &Shot| {
                    let r = self.residual3(shot);
                    (r[0].hypot(r[1]).hypot(r[2]), p, shot.end.s)
                };
                touches.extend(shots.touches.approaches.iter().map(start));
                cut_offs.extend(shots.touches.cut_off.iter().map(start));
            }
            // One start per valley, so that the starts tried lie in different basins.
            for points in &by_crossing {
                starts.extend(valley_floors(points).map(|(r, (p, s_end))| (r, p, s_end)));
            }
        }
        starts.sort_by(|a, b| a.0.total_cmp(&b.0));
        touches.sort_by(|a, b| a.0.total_cmp(&b.0));
        cut_offs.sort_by(|a, b| a.0.total_cmp(&b.0));
        starts
            .into_iter()
            .take(FREE_END_STARTS)
            .chain(touches.into_iter().take(TOUCH_STARTS))
            .map(|start| (start, PastGuard::Halve))
            .chain(
                cut_offs
                    .into_iter()
                    .take(CUT_OFF_STARTS)
                    .map(|start| (start, PastGuard::PullBack)),
            )
            .find_map(|((_, p, s_end), past_guard)| {
                self.newton3(p, s_end, omega, Accuracy::Full, past_guard)
            })
    }

    /// Damped Newton on the three residuals of [`Problem::residual3`] in (Λ, ln ν, s), with
    /// the Jacobian of [`Problem::free_end_jacobian`] and the safeguards and accuracies of
    /// [`Problem::newton`]; converged in full, or only to [`SEARCH_RESIDUAL`] at the search
    /// accuracy when `finish` is [`Accuracy::Search`] (the continuation's inner points). A
    /// trial end past its curve's 2π guard is halved, or pulled back, as `past_guard` says.
    fn newton3(
        &self,
        mut p: Solution,
        mut s_end: f64,
        omega: f64,
        finish: Accuracy,
        past_guard: PastGuard,
    ) -> Option<Converged> {
        let mut accuracy = Accuracy::Search;
        let eval = |p: &Solution, s: f64, accuracy: Accuracy| {
            integrate_tracked(&self.form(p, omega), s, accuracy, self.budget)
        };
        let size_of = |r: &[f64; 3]| r.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut shot = eval(&p, s_end, accuracy)?;
        let mut r = self.residual3(&shot);
        let (mut slow, mut last) = (0, f64::INFINITY);
        for _ in 0..40 {
            if accuracy == Accuracy::Search && size_of(&r) < SEARCH_RESIDUAL {
                if finish == Accuracy::Search {
                    return self.converged(p, s_end, omega, &shot);
                }
                accuracy = Accuracy::Full;
                shot = eval(&p, s_end, accuracy)?;
                r = self.residual3(&shot);
                last = f64::INFINITY;
            }
            let size = size_of(&r);
            if size < RESIDUAL_TOLERANCE {
                return self.converged(p, s_end, omega, &shot);
            }
            slow = if size > 0.7 * last { slow + 1 } else { 0 };
            if slow >= 4 {
                return None;
            }
            last = size;
            let (jac, _) = self.free_end_jacobian(&shot, &self.form(&p, omega))?;
            let mut d = solve3(jac, [-r[0], -r[1], -r[2]])?;
            // Keep steps local: ν by at most a factor e, Λ by its size plus 1, s by half.
            let limit = (d[1].abs())
                .max(d[0].abs() / (p.lambda + 1.0))
                .max(d[2].abs() / (0.5 * s_end))
                .max(1.0);
            d = d.map(|x| x / limit);
            let mut accepted = false;
            for _ in 0..LINE_SEARCH_HALVINGS {
                let mut lambda = p.lambda + d[0];
                if lambda < 0.0 {
                    lambda = 0.1 * p.lambda;
                }
                let q = Solution {
                    lambda,
                    ln_nu: p.ln_nu + d[1],
                };
                let mut s_trial = s_end + d[2];
                if past_guard == PastGuard::PullBack {
                    s_trial = s_trial.min(guard_end(&self.form(&q, omega)));
                }
                if let Some(sq) = eval(&q, s_trial, accuracy) {
                    let rq = self.residual3(&sq);
                    if size_of(&rq) < size {
                        p = q;
                        s_end = s_trial;
                        (r, shot) = (rq, sq);
                        accepted = true;
                        break;
                    }
                }
                d = d.map(|x| 0.5 * x);
            }
            if !accepted {
                return None;
            }
        }
        None
    }

    /// Where the branch through `path` is expected to end: the nearest Ω at which a
    /// quantity that must stay positive reaches 0 (Λ; the room left before the end of the
    /// valid range; the turning left before the 2π guard), each a Newton step along the
    /// tangent at the last point, or a fold (where the tangent grows like (Ω_fold − Ω)^(−1/2),
    /// so 1/|tangent|² falls linearly to 0 across the last two points). Infinite when nothing
    /// ends it.
    fn predicted_end(&self, path: &[(f64, Converged)]) -> f64 {
        let (omega, c) = path.last().expect("a branch starts with a point");
        let Some(tangent) = c.tangent else {
            return f64::INFINITY;
        };
        let margins = |d: f64| {
            let p = Solution {
                lambda: c.solution.lambda + d * tangent[0],
                ln_nu: c.solution.ln_nu + d * tangent[1],
            };
            let s = c.s_end + d * tangent[2];
            let form = self.form(&p, omega + d);
            let turning = form.kappa_law().integral(s).max(form.tau_law().integral(s));
            [
                p.lambda,
                form.s_range().1 - s,
                std::f64::consts::TAU - turning,
            ]
        };
        let h = 1e-6 * omega.max(1e-3);
        let (here, ahead) = (margins(0.0), margins(h));
        let mut end = f64::INFINITY;
        for (m, m_ahead) in here.into_iter().zip(ahead) {
            let slope = (m_ahead - m) / h;
            if m > 0.0 && slope < 0.0 && slope.is_finite() {
                end = end.min(omega + m / -slope);
            }
        }
        let steepness = |c: &Converged| {
            c.tangent.map(|[dl, dn, ds]| {
                1.0 / ((dl / (1.0 + c.solution.lambda)).powi(2)
                    + dn.powi(2)
                    + (ds / c.s_end).powi(2))
            })
        };
        if let Some((omega0, c0)) = path.len().checked_sub(2).map(|i| &path[i]) {
            if let (Some(g0), Some(g1)) = (steepness(c0), steepness(c)) {
                if g1 < g0 {
                    end = end.min(omega + g1 * (omega - omega0) / (g0 - g1));
                }
            }
        }
        end
    }

    /// The free-end solution `p`, `s_end` (tracked `shot` at its end), with its turning and
    /// its branch's direction in Ω; `None` when Λ < 0.
    fn converged(&self, p: Solution, s_end: f64, omega: f64, shot: &Shot) -> Option<Converged> {
        let form = self.form(&p, omega);
        let turning = form
            .kappa_law()
            .integral(s_end)
            .max(form.tau_law().integral(s_end));
        (p.lambda >= 0.0).then(|| Converged {
            solution: p,
            turning,
            s_end,
            tangent: self.tangent(shot, &form),
        })
    }

    /// The Jacobian of [`Problem::residual3`] in (Λ, ln ν, s) at a tracked shot, and its
    /// column in Ω: the end moves by [`Shot::derivatives`] and, with s, along the curve
    /// (x′ = t, t′ = κ n); each column is a central difference in the end, no integration.
    fn free_end_jacobian(
        &self,
        shot: &Shot,
        form: &SpaceForm,
    ) -> Option<([[f64; 3]; 3], [f64; 3])> {
        let [d_lambda, d_nu, d_omega] = shot.derivatives?;
        let State { s, x, t, n, .. } = shot.end;
        let d_s = (t, n * form.kappa_law().value(s));
        let residual = |x, t| self.residual3_at(x, t);
        let [c_lambda, c_nu, c_s, c_omega] =
            [d_lambda, d_nu, d_s, d_omega].map(|d| end_slope(residual, (x, t), d));
        let jac = [0, 1, 2].map(|i| [c_lambda[i], c_nu[i], c_s[i]]);
        (jac.iter().flatten().chain(&c_omega).all(|c| c.is_finite())).then_some((jac, c_omega))
    }

    /// The branch's direction at a solution (tracked `shot` at its end): d(Λ, ln ν, s)/dΩ
    /// from the implicit function theorem on [`Problem::residual3`].
    fn tangent(&self, shot: &Shot, form: &SpaceForm) -> Option<[f64; 3]> {
        let (jac, per_omega) = self.free_end_jacobian(shot, form)?;
        solve3(jac, per_omega.map(|x| -x))
    }

    /// A shot with its [`Shot::derivatives`].
    fn tracked_shot(&self, p: &Solution, omega: f64, accuracy: Accuracy) -> Option<Shot> {
        let track = Track::Derivatives;
        shoot(
            &self.form(p, omega),
            &self.cone(),
            accuracy,
            track,
            self.budget,
        )
    }

    /// The columns (Λ, ln ν) of the Jacobian of [`Target::residual`] at a tracked shot: the
    /// end moves with the unknowns at fixed s ([`Shot::derivatives`]) and along the curve as
    /// the crossing s moves (by −∇g·δx / ∇g·t, g the cone function); the residual's change is
    /// a central difference in that end, no integration.
    fn cone_jacobian(&self, shot: &Shot, form: &SpaceForm) -> Option<[[f64; 2]; 2]> {
        let d = shot.derivatives?;
        let State { s, x, t, n, .. } = shot.end;
        let grad = x.normalize() * self.target.theta0.cos() - Vec3::X;
        let along = grad.dot(t);
        let kappa = form.kappa_law().value(s);
        let columns = [d[0], d[1]].map(|(dx, dt)| {
            let ds = -grad.dot(dx) / along;
            let residual = |x, t| self.target.residual_at(x, t);
            end_slope(residual, (x, t), (dx + t * ds, dt + n * (kappa * ds)))
        });
        columns
            .iter()
            .flatten()
            .all(|c| c.is_finite())
            .then_some(columns)
    }

    /// Solve at `omega` directly: the cone search first; where it finds nothing, or only a
    /// segment that turns by more than [`GENTLE_TURNING`], the free-end search, and the
    /// gentler of the two.
    fn solve_directly(&self, omega: f64) -> Option<Converged> {
        let cone = self.attempt(omega);
        if let Some(c) = cone.clone().filter(|c| c.turning <= GENTLE_TURNING) {
            return Some(c);
        }
        let free = self.attempt_free_end(omega);
        [cone, free]
            .into_iter()
            .flatten()
            .min_by(|a, b| a.turning.total_cmp(&b.turning))
    }

    /// Solve at `omega` by continuation in Ω from the segment at Ω = 0; report the largest
    /// Ω reached when `omega` is out of reach.
    fn continue_from_zero(&self, omega: f64) -> std::result::Result<Converged, Refusal> {
        if omega == 0.0 {
            return Err(Refusal::None);
        }
        let ok = self
            .attempt(0.0)
            .or_else(|| self.attempt_free_end(0.0))
            .ok_or(Refusal::None)?;
        // Follow that segment's branch in Ω with the end s free (smooth through the cone's
        // fold), to Ω or as far as it goes (to 0.1% of Ω: the Ω_max reported is a lower bound),
        // each step started along the branch's tangent at its last point and converged at the
        // search accuracy (only Ω itself, and the Ω_max reported, are converged in full).
        // Where the branch is expected to end before Ω ([`Problem::predicted_end`]) the steps
        // aim just inside that end, then just past it: an end where Λ reaches 0 is found in a
        // few Newton steps on Λ(Ω) rather than by halving the step ten times.
        let mut ok = ok;
        if ok.tangent.is_none() {
            ok.tangent = integrate_tracked(
                &self.form(&ok.solution, 0.0),
                ok.s_end,
                Accuracy::Search,
                self.budget,
            )
            .and_then(|shot| self.tangent(&shot, &self.form(&ok.solution, 0.0)));
        }
        let mut path = vec![(0.0, ok)];
        // `failed`: the smallest Ω where a step from the current point failed, not tried again
        // from there.
        let (mut reached, mut failed, mut step) = (0.0, f64::INFINITY, 0.25 * omega);
        let tolerance = 1e-3 * omega;
        let mut tries = 0;
        while step > tolerance && failed - reached > tolerance && tries < CONTINUATION_TRIES {
            tries += 1;
            let mut next = (reached + step).min(omega);
            // Aim just inside where the branch is expected to end, and once there, just past.
            let end = self.predicted_end(&path);
            if end < next {
                next = (end - 0.5 * tolerance).max(reached + tolerance).min(next);
            }
            if next >= failed {
                next = 0.5 * (reached + failed);
            }
            let (guess, s_guess) = predict(&path, next);
            match self.newton3(guess, s_guess, next, Accuracy::Search, PastGuard::Halve) {
                Some(c) if next == omega => {
                    if let Some(c) =
                        self.newton3(c.solution, c.s_end, omega, Accuracy::Full, PastGuard::Halve)
                    {
                        return Ok(c);
                    }
                    failed = next;
                    step = 0.5 * (next - reached);
                }
                Some(c) => {
                    path.push((next, c));
                    step = 2.0 * (next - reached).max(step);
                    reached = next;
                    failed = f64::INFINITY;
                }
                None => {
                    failed = next;
                    step = 0.5 * (next - reached);
                }
            }
        }
        // The Ω_max reported has a segment to rounding: the branch's last point converged in
        // full, else the one before it.
        let omega_max = path
            .iter()
            .rev()
            .find(|(o, c)| {
                *o == 0.0
                    || self
                        .newton3(c.solution, c.s_end, *o, Accuracy::Full, PastGuard::Halve)
                        .is_some()
            })
            .map_or(0.0, |(o, _)| *o);
        Err(Refusal::BranchEnds { omega_max })
    }

    /// Newton from the near-helix start (Λ = 0: a helix when Ω = 0, which always meets the
    /// cone, with the ν whose dihedral angle matches the end's). Where the region in which
    /// the curve meets the cone is narrow, the solution may lie next to its edge and a
    /// descent stalls against it: the rest of the scan is then made and its best points
    /// tried, then the same from Λ = 1. The ends may admit several segments; one whose
    /// tangent or binormal turns by more than [`GENTLE_TURNING`] (near the 2π guard: a
    /// loop) is kept only if no gentler one turns up among the starts.
    fn attempt(&self, omega: f64) -> Option<Converged> {
        let mut best: Option<Converged> = None;
        for lambda in START_LAMBDAS {
            let mut scan = Scan::default();
            let first = self.scan(omega, lambda, &mut scan, ScanUntil::SignChange);
            let mut starts = first.into_iter().collect::<Vec<_>>();
            for pass in 0..2 {
                for start in starts.drain(..) {
                    if let Some(c) = self.newton(start, omega) {
                        if best.as_ref().is_none_or(|b| c.turning < b.turning) {
                            best = Some(c);
                        }
                        if best.as_ref().is_some_and(|b| b.turning <= GENTLE_TURNING) {
                            return best;
                        }
                    }
                }
                if pass == 0 {
                    self.scan(omega, lambda, &mut scan, ScanUntil::End);
                    let mut floors: Vec<_> = valley_floors(&scan.defined).collect();
                    floors.sort_by(|a, b| a.0.total_cmp(&b.0));
                    starts = floors.into_iter().map(|(_, p)| p).take(3).collect();
                }
            }
        }
        best
    }

    /// The ν scan at fixed Λ. The helix's axis makes the angle atan ν with the start
    /// tangent, so it leaves the cone only for ν beyond about tan θ0, and its dihedral
    /// angle falls toward 0 as ν grows: scan upward from there in quarter decades, `until`
    /// the first sign change of the dihedral mismatch (returned, interpolated) or the end.
    fn scan(&self, omega: f64, lambda: f64, scan: &mut Scan, until: ScanUntil) -> Option<Solution> {
        let want = self.target.theta2.abs();
        while scan.next < SCAN_POINTS {
            let k = scan.next;
            let ln_nu = self.scan_ln_nu(k);
            scan.next += 1;
            let p = Solution { lambda, ln_nu };
            let shots = self.scan_shots(omega, lambda, k);
            let Some(shot) = shots.crossings.get(self.crossing as usize - 1) else {
                scan.prev = None;
                continue;
            };
            let r = self.target.residual(shot);
            scan.defined.push((k, r[0].hypot(r[1]), p));
            let d = shot.theta2.abs() - want;
            let prev = scan.prev.replace((ln_nu, d));
            if let Some((ln_prev, d_prev)) = prev {
                if until == ScanUntil::SignChange && d_prev > 0.0 && d <= 0.0 {
                    return Some(Solution {
                        lambda,
                        ln_nu: ln_prev + SCAN_STEP * d_prev / (d_prev - d),
                    });
                }
            }
        }
        None
    }

    /// Damped Newton on the two residuals in (Λ, ln ν) with a forward-difference Jacobian;
    /// a trial point where the curve misses the cone is pulled back toward the current one
    /// (seed 003's rule for its simplex), and a negative Λ is replaced by a tenth of the
    /// current one. Its shots are at [`Accuracy::Search`] until the residual is below
    /// [`SEARCH_RESIDUAL`], at [`Accuracy::Full`] after.
    fn newton(&self, mut p: Solution, omega: f64) -> Option<Converged> {
        let mut accuracy = Accuracy::Search;
        let mut shot = self.tracked_shot(&p, omega, accuracy)?;
        let mut r = self.target.residual(&shot);
        let mut slow = 0;
        let mut last = f64::INFINITY;
        for _ in 0..60 {
            if accuracy == Accuracy::Search && r[0].abs().max(r[1].abs()) < SEARCH_RESIDUAL {
                accuracy = Accuracy::Full;
                shot = self.tracked_shot(&p, omega, accuracy)?;
                r = self.target.residual(&shot);
                last = f64::INFINITY;
            }
            let size = r[0].abs().max(r[1].abs());
            if size < RESIDUAL_TOLERANCE {
                let form = self.form(&p, omega);
                let turning = form
                    .kappa_law()
                    .integral(shot.end.s)
                    .max(form.tau_law().integral(shot.end.s));
                return (p.lambda >= 0.0).then_some(Converged {
                    solution: p,
                    turning,
                    s_end: shot.end.s,
                    tangent: None,
                });
            }
            // Newton converges fast near a root; steady crawling means a dead end (the
            // edge of the region where the curve meets the cone).
            slow = if size > 0.7 * last { slow + 1 } else { 0 };
            if slow >= 4 {
                return None;
            }
            last = size;
            let [jl, jn] = self.cone_jacobian(&shot, &self.form(&p, omega))?;
            let det = jl[0] * jn[1] - jl[1] * jn[0];
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let mut dl = -(r[0] * jn[1] - r[1] * jn[0]) / det;
            let mut dn = -(jl[0] * r[1] - jl[1] * r[0]) / det;
            // Keep steps local: ν by at most a factor e, Λ by at most its size plus 1.
            let limit = (dn.abs() / 1.0).max(dl.abs() / (p.lambda + 1.0)).max(1.0);
            dl /= limit;
            dn /= limit;
            let mut accepted = false;
            for _ in 0..LINE_SEARCH_HALVINGS {
                let mut lambda = p.lambda + dl;
                if lambda < 0.0 {
                    lambda = 0.1 * p.lambda;
                }
                let q = Solution {
                    lambda,
                    ln_nu: p.ln_nu + dn,
                };
                if let Some(sq) = self.tracked_shot(&q, omega, accuracy) {
                    let rq = self.target.residual(&sq);
                    if rq[0].abs().max(rq[1].abs()) < size {
                        p = q;
                        r = rq;
                        shot = sq;
                        accepted = true;
                        break;
                    }
                }
                dl *= 0.5;
                dn *= 0.5;
            }
            if !accepted {
                return None;
            }
        }
        None
    }
}
