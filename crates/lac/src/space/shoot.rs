//! The cone-intersection step of seed 003 §4: integrate a standard-form curve until it meets
//! the cone of half-angle θ0 about its start tangent.

use super::family::SpaceForm;
use super::taylor::{Accuracy, EndDerivatives, Expansion, Sensitivity, State};
use crate::foundation::numeric::{find_root, quadratic_roots, RootFailure};
use crate::foundation::vec3::Vec3;

/// Most Taylor steps one shot may take before the crossing is declared missing.
const MAX_STEPS: usize = 400;

/// The Taylor steps one solve may take over all its shots: the iteration cap that bounds
/// every call's time (about 0.1 s at most on this project's 2-core machine, about a
/// microsecond a step). Far above what solved inputs take: at most 1,859 over the 2,993
/// solved inputs of the constructed-input test (median 41, most of them at
/// [`Accuracy::Search`]).
pub(crate) const SOLVE_STEPS: u32 = 120_000;

/// What is left of a solve's [`SOLVE_STEPS`]: every shot draws on it, and finds nothing
/// once it is spent.
#[derive(Debug)]
pub(crate) struct Budget(std::cell::Cell<u32>);

impl Budget {
    pub(crate) fn new(steps: u32) -> Budget {
        Budget(std::cell::Cell::new(steps))
    }

    /// Take one step; false when none is left.
    fn take(&self) -> bool {
        let left = self.0.get();
        self.0.set(left.saturating_sub(1));
        left > 0
    }
}

/// Samples of the cone function inside each step, so that a crossing and recrossing
/// within one step are not missed (a step turns the frame by about a radian at most).
const PROBES: usize = 4;

/// The cone with apex at the origin, axis +x (the start tangent) and half-angle θ0, and
/// which crossing of it ends the segment.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Cone {
    cos: f64,
    half_angle: f64,
    /// Which crossing ends the segment, from 1: odd ones go outward (|θ2| ≤ π/2), even
    /// ones back inward (|θ2| > π/2, seed 003 Fig. 16). The seed uses the first two; the
    /// third and fourth serve curves that wind further about the cone's axis.
    crossing: u32,
}

impl Cone {
    pub(crate) fn new(theta0: f64, crossing: u32) -> Cone {
        Cone {
            cos: theta0.cos(),
            half_angle: theta0,
            crossing,
        }
    }

    /// `|x| cos θ0 − x·e1`: negative inside the cone, positive outside.
    fn g(&self, x: Vec3) -> f64 {
        x.length() * self.cos - x.x
    }

    /// g at `x` and its rate of change as x moves with velocity `v`,
    /// `cos θ0 (x·v)/|x| − v·e1` (NaN at the apex, where g has no derivative).
    fn g_and_slope(&self, x: Vec3, v: Vec3) -> (f64, f64) {
        let r = x.length();
        (r * self.cos - x.x, self.cos * x.dot(v) / r - v.x)
    }
}

/// Whether [`integrate_to`] keeps the integrator states at the starts of its steps (for
/// evaluating the solved segment) or only the end (for the solver's trial shots).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Checkpoints {
    /// Keep every step's start state in [`Shot::checkpoints`].
    Keep,
    /// Leave [`Shot::checkpoints`] empty.
    Discard,
}

/// Where a standard-form curve meets the cone, and the end angles it gives the segment.
#[derive(Clone, Debug)]
pub(crate) struct Shot {
    /// The state at the crossing.
    pub(crate) end: State,
    /// Angle between the end tangent and the chord, θ1 of the standard-form segment.
    pub(crate) theta1: f64,
    /// Dihedral angle about the chord from the start tangent's half-plane to the half-plane
    /// of the point behind the end (`x_e − t_e`), θ2 of the standard-form segment.
    pub(crate) theta2: f64,
    /// The states at the starts of the steps, for evaluation after the solve.
    pub(crate) checkpoints: Vec<State>,
    /// How the end moves with Λ, ln ν and Ω (at fixed s), when the shot tracked it.
    pub(crate) derivatives: Option<EndDerivatives>,
}

/// Whether a shot also finds how its end moves with the unknowns ([`Sensitivity`]): about a
/// third more work per step, two integrations fewer per Jacobian.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Track {
    /// Find [`Shot::derivatives`].
    Derivatives,
    /// Only the end.
    EndOnly,
}

/// The angles (θ0, θ1, θ2) of a chord and two tangents: θ0 between `t0` and the chord,
/// θ1 between `t1` and the chord, θ2 the dihedral angle about the chord from the half-plane
/// containing `t0` to the half-plane containing `−t1` (0 for a planar curve that turns one
/// way, ±π for a planar S).
pub(crate) fn end_angles(chord: Vec3, t0: Vec3, t1: Vec3) -> (f64, f64, f64) {
    let c = chord.normalize();
    let u0 = t0 - c * t0.dot(c);
    let minus_t1 = -t1;
    let u1 = minus_t1 - c * minus_t1.dot(c);
    let theta2 = c.dot(u0.cross(u1)).atan2(u0.dot(u1));
    (t0.angle_to(c), t1.angle_to(c), theta2)
}

/// Integrate `form` from s = 0 to its crossing with `cone`. `None` when the curve reaches a
/// bound of its valid range first, turns its tangent or binormal by more than 2π first (the
/// seed's guard against looping segments), or never gets there.
pub(crate) fn shoot(
    form: &SpaceForm,
    cone: &Cone,
    accuracy: Accuracy,
    track: Track,
    budget: &Budget,
) -> Option<Shot> {
    let mut found = None;
    crossings(form, cone, accuracy, track, budget, None, |shot, k| {
        if k == cone.crossing {
            found = Some(shot);
            false
        } else {
            true
        }
    });
    found
}

/// Every crossing of `cone` up to its own ([`Cone::crossing`]) in one integration, in
/// order: what [`shoot`] would give for each crossing number.
#[cfg(test)]
fn shoot_each(form: &SpaceForm, cone: &Cone, accuracy: Accuracy, budget: &Budget) -> Vec<Shot> {
    shoot_each_and_touches(form, cone, accuracy, budget, None)
}

/// Where a curve comes near the cone without crossing it ([`shoot_each_and_touches`]).
#[derive(Debug, Default)]
pub(crate) struct Touches {
    /// The points before its last crossing where the curve comes closest to the cone without
    /// crossing it, within [`TOUCH_ANGLE`] (at a probe, not refined): the ends where a nearby
    /// curve grazes the cone, crossing and recrossing between two probes, or misses it.
    pub(crate) approaches: Vec<Shot>,
    /// Its end just inside seed 003's 2π guard, where the guard cuts it off before its last
    /// crossing within [`TOUCH_ANGLE`] of the cone ([`guard_touch`]).
    pub(crate) cut_off: Option<Shot>,
}

/// [`shoot_each`], and with `touches` where the curve comes near the cone without crossing
/// it ([`Touches`]).
pub(crate) fn shoot_each_and_touches(
    form: &SpaceForm,
    cone: &Cone,
    accuracy: Accuracy,
    budget: &Budget,
    touches: Option<&mut Touches>,
) -> Vec<Shot> {
    let mut shots = Vec::new();
    crossings(
        form,
        cone,
        accuracy,
        Track::EndOnly,
        budget,
        touches,
        |shot, k| {
            shots.push(shot);
            k < cone.crossing
        },
    );
    shots
}

/// How close (radians, in the angle from the start tangent) a local approach to the cone
/// must come to count as a touch ([`shoot_each_and_touches`]).
pub(crate) const TOUCH_ANGLE: f64 = 0.1;

/// Integrate `form` from 0, calling `each(shot, k)` at the k-th crossing of `cone` (from 1)
/// until it returns false, `cone.crossing` is passed, or the curve ends (range, guard,
/// steps, budget).
fn crossings(
    form: &SpaceForm,
    cone: &Cone,
    accuracy: Accuracy,
    track: Track,
    budget: &Budget,
    mut touches: Option<&mut Touches>,
    mut each: impl FnMut(Shot, u32) -> bool,
) {
    let (_, s_max) = form.s_range();
    let mut state = State::start();
    let mut sensitivity = Sensitivity::default();
    // Inside the cone at the start (the curve leaves the apex along the axis).
    let mut crossings = 0;
    // g at the probe before the last one (across steps), for the touches.
    let mut g_before = f64::NAN;
    for _ in 0..MAX_STEPS {
        if !budget.take() {
            return;
        }
        // Where the tangent has less left to turn than the shot's tolerance the rest is a
        // ray (only shots without derivatives: those would need the rest's share too).
        if track == Track::EndOnly
            && form.kappa_law().integral_rest(state.s) <= accuracy.tolerance()
        {
            straight_rest(form, cone, &state, crossings, s_max, each);
            return;
        }
        let expansion = Expansion::stepping(form, &state);
        let mut h = expansion.step_size(accuracy);
        // Where κ or τ is entire (α = −1: κ linear) the series reaches the bound itself;
        // where it is singular there, steps shrink toward it and stop just short.
        let to_bound = expansion.offset_to(s_max);
        let last = h >= to_bound;
        if last {
            h = to_bound;
        }
        if h <= 1e-12 * expansion.start().abs().max(1.0) {
            return;
        }
        let mut prev = 0.0;
        let mut g_prev = if state.s == 0.0 {
            -1.0
        } else {
            cone.g(state.x)
        };
        let sigmas: [f64; PROBES] = std::array::from_fn(|i| h * (i + 1) as f64 / PROBES as f64);
        let points = expansion.points_at(sigmas);
        for (sigma, point) in sigmas.into_iter().zip(points) {
            let g = cone.g(point);
            let outside = crossings % 2 == 1;
            // The last probe came closest to the cone without crossing it.
            if let Some(touches) = touches.as_deref_mut() {
                let same_side = (g > 0.0) == outside && (g_before > 0.0) == outside;
                if same_side && g_prev.abs() < g_before.abs() && g_prev.abs() <= g.abs() {
                    let near = expansion.state_at(prev);
                    let off = (Vec3::X.angle_to(near.x) - cone.half_angle).abs();
                    if off < TOUCH_ANGLE {
                        touches.approaches.extend(shot_at(form, near, Vec::new()));
                    }
                }
            }
            g_before = g_prev;
            if (g > 0.0) != outside {
                crossings += 1;
                let at = refine(cone, &expansion, accuracy, (prev, g_prev), (sigma, g));
                let go_on = match finish(form, &expansion, at, Vec::new()) {
                    Some(mut shot) => {
                        if track == Track::Derivatives {
                            let d = sensitivity.along(form, &expansion, at).at(&shot.end);
                            shot.derivatives = Some(d);
                        }
                        each(shot, crossings) && crossings < cone.crossing
                    }
                    // Past the guard.
                    None => {
                        if let Some(touches) = touches.as_deref_mut() {
                            touches.cut_off = guard_touch(form, cone, &expansion);
                        }
                        false
                    }
                };
                if !go_on {
                    return;
                }
            }
            prev = sigma;
            g_prev = g;
        }
        if last {
            return;
        }
        if track == Track::Derivatives {
            sensitivity = sensitivity.along(form, &expansion, h);
        }
        state = expansion.state_at(h);
        if !within_guard(form, state.s) {
            if let Some(touches) = touches.as_deref_mut() {
                touches.cut_off = guard_touch(form, cone, &expansion);
            }
            return;
        }
        if crossings == 0 && never_leaves(form, cone, &state) {
            return;
        }
    }
}

/// The end of a curve that seed 003's 2π guard cuts off inside the step of `expansion`,
/// when it lies within [`TOUCH_ANGLE`] of the cone: the state just inside the guard
/// ([`Touches::cut_off`]), whichever way the curve is heading there.
///
/// Where the torsion grows without bound toward the end of the valid range (type 2 with
/// β > 0: μ falls to 0 at a finite s), the binormal's turning climbs steeply to the guard,
/// and a segment may end at 85–99.5% of its guard. The scan's curves at the neighbouring ν
/// (a quarter decade away) are cut off by their own guard short of the cone or just past
/// it, so they have neither a crossing nor a touch near that end; their end at the guard,
/// though, lies close to the segment's end (the tangent barely turns there while the frame
/// twists fast), and the free-end search converges from it.
fn guard_touch(form: &SpaceForm, cone: &Cone, expansion: &Expansion) -> Option<Shot> {
    let s = guard_end(form);
    let offset = expansion.offset_to(s);
    if !offset.is_finite() || offset < 0.0 {
        return None;
    }
    let end = expansion.state_at(offset);
    let off = (Vec3::X.angle_to(end.x) - cone.half_angle).abs();
    if off < TOUCH_ANGLE {
        shot_at(form, end, Vec::new())
    } else {
        None
    }
}

/// The crossings of `cone` after `state` (crossings so far: `crossings`) where the rest of the
/// curve is straight to the shot's accuracy: the ray from `state.x` along `state.t`, about
/// which n and b only twist, by the torsion's turning φ (κ = 0: n′ = τ b, b′ = −τ n), and
/// `each` called as [`crossings`] does. Every later crossing is a sign change of g along the
/// ray, at a root of `|x|² cos² θ0 = (x·e1)²`, a quadratic in the distance.
fn straight_rest(
    form: &SpaceForm,
    cone: &Cone,
    state: &State,
    mut crossings: u32,
    s_max: f64,
    mut each: impl FnMut(Shot, u32) -> bool,
) {
    let (x0, t) = (state.x, state.t);
    let c2 = cone.cos * cone.cos;
    let a = c2 - t.x * t.x;
    let b = 2.0 * (c2 * x0.dot(t) - x0.x * t.x);
    let c = c2 * x0.length_squared() - x0.x * x0.x;
    let mut roots = Vec::with_capacity(2);
    if a == 0.0 {
        roots.push(-c / b);
    } else if let Some((r1, r2)) = quadratic_roots(a, b, c, 1e-12) {
        // A double root (a ray crossing a flat cone, θ0 = π/2) may round to a slightly
        // negative discriminant: it counts as 0, and the sign test below decides.
        roots.extend([r1, r2]);
    }
    roots.retain(|r| r.is_finite() && *r > 0.0);
    roots.sort_by(f64::total_cmp);
    roots.dedup();
    // A root is a crossing where g's sign differs on its two sides (not at a tangency, nor
    // on the cone's other nappe, which squaring brought in).
    let outside = |d: f64| cone.g(x0 + t * d) > 0.0;
    let mut left = 0.0;
    for (i, &r) in roots.iter().enumerate() {
        let right = roots
            .get(i + 1)
            .map_or(2.0 * r + 1.0, |&next| 0.5 * (r + next));
        if outside(0.5 * (left + r)) == outside(right) {
            left = r;
            continue;
        }
        left = r;
        // Two Newton steps on g itself: the quadratic's coefficients cancel where the ray
        // runs nearly along the cone.
        let mut r = r;
        for _ in 0..2 {
            let (g, slope) = cone.g_and_slope(x0 + t * r, t);
            let step = g / slope;
            if step.is_finite() && step.abs() < 0.5 * r {
                r -= step;
            }
        }
        let s = state.s + r;
        if s >= s_max {
            return;
        }
        let phi = form.tau_law().integral(s) - form.tau_law().integral(state.s);
        let (sin, cos) = phi.sin_cos();
        let end = State {
            s,
            x: x0 + t * r,
            t,
            n: state.n * cos + state.b * sin,
            b: state.b * cos - state.n * sin,
        };
        let Some(shot) = shot_at(form, end, Vec::new()) else {
            return;
        };
        crossings += 1;
        if !each(shot, crossings) || crossings >= cone.crossing {
            return;
        }
    }
}

/// Integrate `form` from s = 0 to `s_end` at `accuracy`: the state there and, with
/// [`Checkpoints::Keep`], the states at the starts of the steps. `None` when `s_end` is not
/// inside the valid range, beyond seed 003's 2π guard, further than [`MAX_STEPS`] steps, or
/// beyond the budget.
pub(crate) fn integrate_to(
    form: &SpaceForm,
    s_end: f64,
    keep: Checkpoints,
    accuracy: Accuracy,
    budget: &Budget,
) -> Option<Shot> {
    integrate(
        form,
        s_end,
        keep,
        accuracy,
        Track::EndOnly,
        budget,
        |f, e, sigma, c, _| finish(f, e, sigma, c),
    )
}

/// [`integrate_to`] `s_end` without checkpoints, with the end's [`Shot::derivatives`].
pub(crate) fn integrate_tracked(
    form: &SpaceForm,
    s_end: f64,
    accuracy: Accuracy,
    budget: &Budget,
) -> Option<Shot> {
    let (keep, track) = (Checkpoints::Discard, Track::Derivatives);
    integrate(
        form,
        s_end,
        keep,
        accuracy,
        track,
        budget,
        |form, expansion, sigma, _, sensitivity| {
            let mut shot = finish(form, expansion, sigma, Vec::new())?;
            shot.derivatives = Some(sensitivity.along(form, expansion, sigma).at(&shot.end));
            Some(shot)
        },
    )
}

/// The steps of [`integrate_to`]; `end(form, last step's series, offset into it, checkpoints,
/// sensitivity at the last step's start)` makes the answer.
fn integrate<T>(
    form: &SpaceForm,
    s_end: f64,
    keep: Checkpoints,
    accuracy: Accuracy,
    track: Track,
    budget: &Budget,
    end: impl FnOnce(&SpaceForm, &Expansion, f64, Vec<State>, &Sensitivity) -> Option<T>,
) -> Option<T> {
    let (_, s_max) = form.s_range();
    if !(s_end > 0.0 && s_end < s_max && within_guard(form, s_end)) {
        return None;
    }
    let mut state = State::start();
    let mut sensitivity = Sensitivity::default();
    let mut checkpoints = Vec::new();
    for _ in 0..MAX_STEPS {
        if !budget.take() {
            return None;
        }
        // Checkpoints are replayed by series in s (`SpaceSegment::frames`).
        let expansion = match keep {
            Checkpoints::Keep => Expansion::new(form, &state),
            Checkpoints::Discard => Expansion::stepping(form, &state),
        };
        let h = expansion.step_size(accuracy);
        if h <= 1e-12 * expansion.start().abs().max(1.0) {
            return None;
        }
        if keep == Checkpoints::Keep {
            checkpoints.push(state);
        }
        let to_end = expansion.offset_to(s_end);
        if h >= to_end {
            return end(form, &expansion, to_end, checkpoints, &sensitivity);
        }
        if track == Track::Derivatives {
            sensitivity = sensitivity.along(form, &expansion, h);
        }
        state = expansion.state_at(h);
    }
    None
}

/// The crossing inside a step, between probes `a` (g = `ga`) and `b` (g = `gb`) of opposite
/// signs, as an offset in the step's variable: the crate's safeguarded Newton
/// ([`find_root`]) on the step's series, from the probes' secant, with
/// g′ = cos θ0 (x·x′)/|x| − x′·e1 from the series' velocity, to the accuracy's
/// [`Accuracy::crossing_tolerance`] (1e-16 in full) of the variable's value (a Newton step or
/// the bracket below that).
///
/// Near the crossing g is at the level of its rounding, so where a Newton step rounds to
/// nothing the bracket is narrowed to that width instead.
fn refine(
    cone: &Cone,
    e: &Expansion,
    accuracy: Accuracy,
    (a, ga): (f64, f64),
    (b, gb): (f64, f64),
) -> f64 {
    let g = |sigma: f64| {
        let (p, v) = e.point_and_velocity_at(sigma);
        // At the apex g′ is NaN: find_root then takes a secant step.
        let (g, slope) = cone.g_and_slope(p, v);
        (g, Some(slope))
    };
    let secant = a - ga * (b - a) / (gb - ga);
    let x_tol = accuracy.crossing_tolerance() * (e.start().abs() + secant.abs());
    match find_root(g, (a, ga), (b, gb), Some(secant), x_tol, 60) {
        Ok(sigma) => sigma,
        // Still bracketed after 60 steps (g flat at rounding level): its middle is as good.
        Err(RootFailure::NotConverged { lo, hi }) => 0.5 * (lo + hi),
        // The probes' signs differ by construction; should they not, the secant is the
        // best estimate there is.
        Err(RootFailure::NotBracketed) => secant,
    }
}

fn finish(form: &SpaceForm, e: &Expansion, sigma: f64, checkpoints: Vec<State>) -> Option<Shot> {
    shot_at(form, e.state_at(sigma), checkpoints)
}

/// The shot ending at `end`, with its end angles; `None` past the 2π guard.
fn shot_at(form: &SpaceForm, end: State, checkpoints: Vec<State>) -> Option<Shot> {
    if !within_guard(form, end.s) {
        return None;
    }
    let (_, theta1, theta2) = end_angles(end.x, Vec3::X, end.t);
    Some(Shot {
        end,
        theta1,
        theta2,
        checkpoints,
        derivatives: None,
    })
}

/// The s just inside where seed 003's 2π guard ends `form` ([`within_guard`]; the guard's
/// own s may round either way, so a billionth short of it): where its tangent or binormal
/// has turned by 2π, ∞ where neither ever does.
pub(crate) fn guard_end(form: &SpaceForm) -> f64 {
    let tau = std::f64::consts::TAU;
    let guard = form
        .kappa_law()
        .s_of_integral(tau)
        .min(form.tau_law().s_of_integral(tau));
    guard * (1.0 - 1e-9)
}

/// The seed's 2π guard: neither tangent nor binormal has turned by more than 2π from 0 to
/// s (closed-form θ and φ).
fn within_guard(form: &SpaceForm, s: f64) -> bool {
    let two_pi = std::f64::consts::TAU;
    form.kappa_law().integral(s) <= two_pi && form.tau_law().integral(s) <= two_pi
}

/// Can the curve, inside a cone narrower than a half-space, still leave it? Not if it is
/// inside and its tangent stays inside by more than all the turning left to it: every later
/// point is then the current one plus a path inside the (convex) cone.
fn never_leaves(form: &SpaceForm, cone: &Cone, state: &State) -> bool {
    if cone.half_angle >= std::f64::consts::FRAC_PI_2 {
        return false;
    }
    let remaining = form.kappa_law().integral_upper() - form.kappa_law().integral(state.s);
    let tangent_angle = state.t.x.clamp(-1.0, 1.0).acos();
    remaining.is_finite() && tangent_angle + remaining < cone.half_angle
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::space::family::{SpaceFormParams, TorsionType};

    fn form(
        alpha: f64,
        beta: f64,
        lambda: f64,
        ln_nu: f64,
        omega: f64,
        torsion: TorsionType,
    ) -> SpaceForm {
        SpaceForm::new_unchecked(SpaceFormParams {
            alpha,
            beta,
            lambda,
            omega,
            nu: ln_nu.exp(),
            torsion,
        })
    }

    /// The tracked derivatives of the end (Λ, ln ν, Ω at fixed s) against central differences
    /// of full-accuracy integrations, over slopes, types and lengths.
    #[test]
    fn tracked_derivatives_match_differences() {
        let budget = Budget::new(SOLVE_STEPS);
        let mut worst: f64 = 0.0;
        for (alpha, beta) in [
            (-1.0, -1.0),
            (0.0, 0.0),
            (1.0, 0.5),
            (2.0, -0.5),
            (-0.5, 2.0),
        ] {
            for torsion in [TorsionType::One, TorsionType::Two] {
                // The last runs far out in σ (1 + Λαs up to 160).
                for (lambda, ln_nu, omega, s) in [
                    (0.3, 0.2, 0.1, 2.0),
                    (1.5, -0.4, 0.3, 0.8),
                    (0.05, 1.1, 0.0, 5.0),
                    (4.0, 1.5, 0.05, 20.0),
                ] {
                    let shot = |dl: f64, dn: f64, dom: f64| {
                        let f = form(alpha, beta, lambda + dl, ln_nu + dn, omega + dom, torsion);
                        integrate_to(&f, s, Checkpoints::Discard, Accuracy::Full, &budget)
                    };
                    let f = form(alpha, beta, lambda, ln_nu, omega, torsion);
                    let Some(tracked) = integrate_tracked(&f, s, Accuracy::Full, &budget) else {
                        continue;
                    };
                    let d = tracked.derivatives.expect("tracked");
                    let h = 1e-5;
                    for (k, (dl, dn, dom)) in [(h, 0.0, 0.0), (0.0, h, 0.0), (0.0, 0.0, h)]
                        .into_iter()
                        .enumerate()
                    {
                        let (Some(plus), Some(minus)) = (shot(dl, dn, dom), shot(-dl, -dn, -dom))
                        else {
                            continue;
                        };
                        let dx = (plus.end.x - minus.end.x) / (2.0 * h);
                        let dt = (plus.end.t - minus.end.t) / (2.0 * h);
                        let scale = 1.0 + dx.length() + dt.length();
                        let err = (d[k].0 - dx).length().max((d[k].1 - dt).length()) / scale;
                        assert!(
                            err < 1e-8,
                            "alpha {alpha} beta {beta} {torsion:?} lambda {lambda} ln nu {ln_nu} omega {omega} s {s} unknown {k}: {err:e}"
                        );
                        worst = worst.max(err);
                    }
                }
            }
        }
        assert!(worst > 0.0, "no case was checked");
    }

    /// The crossings [`straight_rest`] finds along a ray against the sign changes of the cone
    /// function sampled densely along it, for rays from inside and outside cones narrower
    /// and wider than a half-space (roots of the squared equation on the other nappe, and
    /// tangencies, are not crossings).
    #[test]
    fn ray_crossings_match_sampling() {
        // Turning and twisting that stay far inside the 2π guard from s = 10 on.
        let f = form(0.0, 0.0, 2.0, 0.0, 1.0, TorsionType::One);
        let mut seed = 7u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut found = 0;
        for i in 0..400 {
            let theta0 = [0.3, 1.0, std::f64::consts::FRAC_PI_2, 2.0, 2.8][i % 5];
            let x0 = Vec3::new(next(), next(), next()) * 2.0;
            let t = Vec3::new(next(), next(), next()).normalize();
            let cone = Cone::new(theta0, 3);
            let n = t.cross(Vec3::Z).normalize();
            let start = State {
                s: 10.0,
                x: x0,
                t,
                n,
                b: t.cross(n),
            };
            let already = u32::from(cone.g(x0) > 0.0);
            let mut by_ray = Vec::new();
            straight_rest(&f, &cone, &start, already, f64::INFINITY, |shot, _| {
                by_ray.push(shot.end.s - 10.0);
                true
            });
            // Sign changes on a fine geometric grid to 10⁶, each bisected.
            let g = |d: f64| cone.g(x0 + t * d);
            let mut sampled = Vec::new();
            let mut prev = 0.0;
            for k in 0..=60_000 {
                let d = 1e-6 * 1e12f64.powf(f64::from(k) / 60_000.0);
                if (g(prev) > 0.0) != (g(d) > 0.0) {
                    let (mut lo, mut hi) = (prev, d);
                    for _ in 0..100 {
                        let mid = 0.5 * (lo + hi);
                        if (g(mid) > 0.0) == (g(lo) > 0.0) {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                    sampled.push(lo);
                }
                prev = d;
            }
            sampled.truncate(3 - already as usize);
            assert_eq!(
                by_ray.len(),
                sampled.len(),
                "ray {i}: {by_ray:?} against {sampled:?}"
            );
            for (a, b) in by_ray.iter().zip(&sampled) {
                assert!(
                    (a - b).abs() <= 1e-9 * b.max(1.0),
                    "ray {i}: {a} against {b}"
                );
                found += 1;
            }
        }
        assert!(found > 100, "only {found} crossings");
    }

    /// Shots that finish along a straight rest ([`straight_rest`]) against the same shots
    /// integrated to their crossings (those that track derivatives never take that path).
    #[test]
    fn straight_rest_matches_integration() {
        let (mut checked, mut shortened) = (0, 0);
        for alpha in [0.0, 0.5, -0.5] {
            for beta in [-1.0, 0.0, 1.0] {
                for torsion in [TorsionType::One, TorsionType::Two] {
                    for (lambda, ln_nu, theta0) in [
                        (2.0, 0.5, 0.3),
                        (4.0, 1.5, 0.8),
                        (1.0, -0.5, 1.2),
                        (0.5, 1.0, 0.5),
                        (0.8, 2.0, 1.0),
                    ] {
                        let f = form(alpha, beta, lambda, ln_nu, 0.1, torsion);
                        let cone = Cone::new(theta0, 3);
                        let ray_budget = Budget::new(SOLVE_STEPS);
                        let by_ray = shoot_each(&f, &cone, Accuracy::Scan, &ray_budget);
                        let budget = Budget::new(SOLVE_STEPS);
                        let integrated: Vec<Shot> = (1..=3)
                            .map_while(|k| {
                                let cone = Cone::new(theta0, k);
                                shoot(&f, &cone, Accuracy::Scan, Track::Derivatives, &budget)
                            })
                            .collect();
                        assert_eq!(
                            by_ray.len(),
                            integrated.len(),
                            "alpha {alpha} beta {beta} {torsion:?} lambda {lambda} theta0 {theta0}"
                        );
                        for (a, b) in by_ray.iter().zip(&integrated) {
                            let err = (a.end.x - b.end.x).length() / b.end.x.length()
                                + (a.end.t - b.end.t).length()
                                + (a.end.b - b.end.b).length()
                                + (a.theta2 - b.theta2).abs();
                            assert!(
                                err < 1e-5,
                                "alpha {alpha} beta {beta} {torsion:?} lambda {lambda} theta0 {theta0}: {err:e}"
                            );
                            checked += 1;
                        }
                        // The integrated shots walk on where the ray shows no crossing is left.
                        if ray_budget.0.get() > budget.0.get() + 100 {
                            shortened += 1;
                        }
                    }
                }
            }
        }
        assert!(
            checked >= 30 && shortened >= 3,
            "{checked} crossings, {shortened} shortened"
        );
        // Crossings on the ray itself: a cone a hair narrower than the direction the curve
        // ends up going (α = 0 turns by 1/Λ in all), which the curve leaves far out.
        let mut on_ray = 0;
        for beta in [-1.0, 0.0, 1.0] {
            for torsion in [TorsionType::One, TorsionType::Two] {
                for (lambda, ln_nu) in [
                    (2.0, 0.5),
                    (1.0, 1.5),
                    (4.0, -0.5),
                    (1.5, 2.5),
                    (3.0, 1.0),
                    (5.0, 1.0),
                    (2.5, 2.0),
                ] {
                    let f = form(0.0, beta, lambda, ln_nu, 0.1, torsion);
                    let budget = Budget::new(SOLVE_STEPS);
                    let far = 40.0 / lambda;
                    let Some(end) =
                        integrate_to(&f, far, Checkpoints::Discard, Accuracy::Full, &budget)
                    else {
                        continue;
                    };
                    let cone = Cone::new(0.98 * end.end.t.x.acos(), 1);
                    let by_ray = shoot_each(&f, &cone, Accuracy::Scan, &budget);
                    let integrated = shoot(&f, &cone, Accuracy::Full, Track::Derivatives, &budget);
                    // Both or neither (the 2π guard may come first).
                    assert_eq!(by_ray.len(), usize::from(integrated.is_some()));
                    let (Some(ray), Some(steps)) = (by_ray.first(), integrated) else {
                        continue;
                    };
                    let (a, b) = (&ray.end, &steps.end);
                    let err = (a.x - b.x).length() / b.x.length()
                        + (a.t - b.t).length()
                        + (a.b - b.b).length();
                    // The ray meets the cone at a few percent of its angle: the scan's 1e-6
                    // moves the crossing along it up to some 50 times as much.
                    assert!(
                        err < 1e-4,
                        "beta {beta} {torsion:?} lambda {lambda}: {err:e}"
                    );
                    let ray_from = (1.0 / (lambda * Accuracy::Scan.tolerance())).ln() / lambda;
                    if b.s > ray_from {
                        on_ray += 1;
                    }
                }
            }
        }
        assert!(on_ray >= 8, "only {on_ray} crossings on the ray");
    }

    /// The solver's shots, stepping in σ where Λα > 0, against the same integration in s
    /// (as segments are evaluated), at full accuracy, out to curvature ratios of 10⁴.
    #[test]
    fn log_radius_steps_match_arc_length() {
        let budget = Budget::new(SOLVE_STEPS);
        let mut checked = 0;
        for (alpha, beta) in [(1.0, 0.0), (0.5, -1.0), (2.0, 1.0), (1.0, 1.0), (3.0, -0.5)] {
            for torsion in [TorsionType::One, TorsionType::Two] {
                for (lambda, ln_nu, omega, s) in [(0.4, 0.3, 0.1, 3.0), (4.5, 1.2, 0.05, 2000.0)] {
                    let f = form(alpha, beta, lambda, ln_nu, omega, torsion);
                    let in_sigma =
                        integrate_to(&f, s, Checkpoints::Discard, Accuracy::Full, &budget);
                    let in_s = integrate_to(&f, s, Checkpoints::Keep, Accuracy::Full, &budget);
                    let (Some(a), Some(b)) = (in_sigma, in_s) else {
                        continue;
                    };
                    let scale = b.end.x.length().max(1.0);
                    let err = ((a.end.x - b.end.x).length() / scale)
                        .max((a.end.t - b.end.t).length())
                        .max((a.end.b - b.end.b).length());
                    assert!(
                        err < 1e-12,
                        "alpha {alpha} beta {beta} {torsion:?} lambda {lambda} s {s}: {err:e}"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked >= 10, "only {checked} cases reached their end");
    }

    /// A scan's curve that the 2π guard cuts off near the cone (α = 2, β = 1, type 2, Ω 0.39:
    /// the torsion blows up at s = ν/Ω, 5.0 here, and the binormal turns by 2π at 4.6)
    /// reports its end just inside the guard as [`Touches::cut_off`], the same state as an
    /// integration to there; one whose end at the guard is far from the cone reports none,
    /// and so does one that makes the crossings asked for before its guard.
    #[test]
    fn guard_cut_off_is_the_end_just_inside_the_guard() {
        let theta0 = 1.1018;
        let cone = Cone::new(theta0, 3);
        let budget = Budget::new(SOLVE_STEPS);
        let tau = std::f64::consts::TAU;
        let mut cut = 0;
        for (lambda, near) in [(0.4, true), (0.15, true), (1.0, false)] {
            let f = form(2.0, 1.0, lambda, 0.6797, 0.3925, TorsionType::Two);
            let mut touches = Touches::default();
            let shots =
                shoot_each_and_touches(&f, &cone, Accuracy::Scan, &budget, Some(&mut touches));
            assert!(
                shots.len() < 3,
                "lambda {lambda}: cut off before its third crossing"
            );
            let Some(end) = touches.cut_off else {
                assert!(!near, "lambda {lambda}: no cut-off");
                continue;
            };
            assert!(near, "lambda {lambda}: a cut-off far from the cone");
            let phi = f.tau_law().integral(end.end.s);
            assert!(
                phi <= tau && phi > tau * (1.0 - 1e-8),
                "lambda {lambda}: phi {phi} at the cut-off"
            );
            let off = (Vec3::X.angle_to(end.end.x) - theta0).abs();
            assert!(off < TOUCH_ANGLE, "lambda {lambda}: {off} off the cone");
            let full = integrate_to(&f, end.end.s, Checkpoints::Discard, Accuracy::Full, &budget)
                .expect("inside the guard");
            let err = (full.end.x - end.end.x).length() / full.end.x.length()
                + (full.end.t - end.end.t).length();
            assert!(err < 1e-5, "lambda {lambda}: {err:e} from the integration");
            cut += 1;
        }
        assert_eq!(cut, 2);
        // Ω = 0: constant torsion, two crossings before the guard, all that is asked.
        let f = form(2.0, 1.0, 0.4, 0.6797, 0.0, TorsionType::Two);
        let mut touches = Touches::default();
        let two = Cone::new(theta0, 2);
        let shots = shoot_each_and_touches(&f, &two, Accuracy::Scan, &budget, Some(&mut touches));
        assert_eq!(shots.len(), 2);
        assert!(touches.cut_off.is_none());
    }
}
