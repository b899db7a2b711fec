//! The slope of a single segment whose α is free: the surface of the distances over α is
//! flat and has several valleys for curves that bend little, so the segment is first fitted
//! with fixed slopes across the range, each started from its neighbour's answer, and the
//! best one starts the free fit.
//!
//! The sweep looks for the valley, not its floor: it looks at about a hundred of the points
//! with coarse tables (see [`Layout::coarse`]), fits each slope a few steps, and leaves a
//! direction of α once its cost has risen to [`HILL`] times the best. The free fit from the
//! best slope then runs on the same points; the fit of all the points starts from its
//! answer within a step or two of its own.

use crate::foundation::numeric::Complex;

use super::model::{every, AlphaMode, Layout};
use super::solve::{Problem, State};

/// The slopes tried, upwards from zero and then downwards (each direction continuing from
/// its neighbour's answer).
const SLOPES: [f64; 12] = [
    0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 8.0, -0.5, -1.0, -2.0, -3.5,
];

/// About how many points the sweep looks at.
const POINTS: usize = 100;

/// Most steps of each fixed slope's fit.
const STEPS: usize = 6;

/// Most steps of the free fit after the sweep.
const FREE_STEPS: usize = 30;

/// How many times the best cost a rising direction of the sweep leaves behind.
const HILL: f64 = 8.0;

/// A start of a fit: pose, the pieces' numbers and the feet.
type Start = ((Complex, f64), Vec<(f64, f64, f64, f64)>, Vec<f64>);

fn start_of(s: &State) -> Start {
    (
        (s.chain.start, s.chain.theta0),
        s.chain.numbers.clone(),
        s.feet.clone(),
    )
}

/// The single segment of `problem` (α free within `range`) from the first guess `state`:
/// a state of `problem`, or `None` when no slope gives a chain.
pub(super) fn sweep_alpha(problem: &Problem, state: State, range: (f64, f64)) -> Option<State> {
    let (lo, hi) = range;
    let k = problem.data.len().div_ceil(POINTS).max(1);
    let data = every(problem.data, k);
    let weights = every(problem.weights, k);
    let thin = |layout: Layout| Problem {
        layout: Layout {
            coarse: true,
            ..layout
        },
        data: &data,
        weights: &weights,
        ..*problem
    };
    let fixed = |alpha: f64| {
        thin(Layout {
            alpha: AlphaMode::Fixed(alpha),
            ..problem.layout
        })
    };
    let free = thin(problem.layout);
    let mut slopes: Vec<f64> = SLOPES
        .iter()
        .copied()
        .filter(|a| *a >= lo && *a <= hi)
        .collect();
    if slopes.is_empty() {
        slopes.push(0.5 * (lo + hi));
    }
    let first: Start = (
        (state.chain.start, state.chain.theta0),
        state.chain.numbers.clone(),
        every(&state.feet, k),
    );
    let mut best: Option<State> = None;
    let mut from: Option<Start> = None;
    let mut at_zero: Option<Start> = None;
    let (mut previous, mut negative, mut left) = (f64::INFINITY, false, false);
    for alpha in slopes {
        if alpha < 0.0 && !negative {
            // The negative slopes continue from the answer at zero, not from the largest.
            (negative, previous, left) = (true, f64::INFINITY, false);
            if at_zero.is_some() {
                from = at_zero.take();
            }
        }
        if left {
            continue;
        }
        let one = fixed(alpha);
        // From the neighbour's answer, the first slope from the first guess. (Starting
        // every slope from both, as the sweep once did, cost twice the steps and found the
        // same valleys in the tests and on the published data.)
        let (start, numbers, feet) = from.as_ref().unwrap_or(&first);
        let mut numbers = numbers.clone();
        numbers[0].3 = alpha;
        let Some(s) = one.state(one.layout.pack(*start, &numbers), feet) else {
            continue;
        };
        let s = one.minimize(s, STEPS);
        from = Some(start_of(&s));
        if alpha == 0.0 {
            at_zero = from.clone();
        }
        let rising = s.cost > previous;
        previous = s.cost;
        if best.as_ref().is_none_or(|b| s.cost < b.cost) {
            best = Some(s);
        }
        left = rising && best.as_ref().is_some_and(|b| previous > HILL * b.cost);
    }
    // Should no slope of the sweep give a chain from the first guess (a piece that winds
    // round more than twice at every slope but its own), the free fit starts from the first
    // guess itself.
    let best = match best {
        Some(best) => best,
        None => free.state(state.x.clone(), &first.2)?,
    };
    let x = free
        .layout
        .pack((best.chain.start, best.chain.theta0), &best.chain.numbers);
    let freed = free
        .state(x, &best.feet)
        .map(|s| free.minimize(s, FREE_STEPS))
        .filter(|s| s.cost < best.cost);
    // The free answer, or should the fine tables refuse it (a curl the coarse ones follow),
    // the best fixed one.
    [freed, Some(best)].into_iter().flatten().find_map(|s| {
        let start = (s.chain.start, s.chain.theta0);
        problem.state(problem.layout.pack(start, &s.chain.numbers), &state.feet)
    })
}
