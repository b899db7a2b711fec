//! Fitting log-aesthetic paths to points: the fairest curve through (or near) data, the
//! reverse of drawing from control points.
//!
//! Given ordered planar points, [`Fit::from_points`] finds the G2 (or G1) chain of
//! log-aesthetic segments that minimises the sum of squared orthogonal distances from the
//! points to the chain (docs/fit.md):
//!
//! * **One segment** (`max_segments = 1`, no tolerance): the least-squares segment, α fitted
//!   within a range or given; its ends move with the data unless pinned.
//! * **Paths** (a tolerance): the fewest segments such that every point lies within the
//!   tolerance. The fit starts from one segment (a closed set from two) and splits the
//!   segment nearest the worst point, exactly (both halves follow the same curve, so a
//!   split never loses ground), then fits all segments together again, their joints free to
//!   move and G2 at every joint by construction.
//!
//! The chain is described by its start, the curvature at every joint and each segment's
//! length and α (`model.rs`); a segment's curvature follows the log-aesthetic law between
//! its end curvatures (`law.rs`), and for α < 0 may pass through zero (an S): such a segment
//! becomes two [`Segment`]s meeting at the inflection. The solver is Levenberg–Marquardt
//! over those numbers with each point's foot found again at every step (`solve.rs`), from a
//! start read off the data's smoothed tangent and curvature (`guess.rs`; a single segment's
//! α by a sweep of fixed slopes, `sweep.rs`).
//!
//! The search for the segmentation looks at about [`SEARCH_POINTS`] of the points with
//! coarse tables (`Layout::coarse`); each chain it settles on is measured against every
//! point (the points it missed join it), and the answer is polished on every point with
//! fine tables. Every result is checked before it is returned (`build.rs`): finite, G2 (or
//! G1) at every joint, closed when asked, and each point within the tolerance when one was
//! asked.

mod build;
mod guess;
mod law;
mod model;
mod solve;
mod sweep;

use kurbo::Point;

use crate::curve::chain::SegmentChain;
use crate::foundation::error::{Error, Result};
use crate::foundation::numeric::Complex;
use crate::path::{Closure, Continuity};
use crate::segment::Segment;

use guess::Profile;
use model::every;
use model::{AlphaMode, Layout};
use solve::{Constraints, Problem, State};
use sweep::sweep_alpha;

/// The most segments a fit may use.
pub const MAX_FIT_SEGMENTS: usize = 64;

/// The default range of α a fitted segment may take.
pub const DEFAULT_ALPHA_RANGE: (f64, f64) = (-5.0, 10.0);

/// How α is chosen for the fitted segments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FitAlpha {
    /// Every segment has this α.
    Fixed(f64),
    /// Each segment's α is fitted within `[min, max]`; with `shared`, one α for all.
    Range {
        /// Smallest α.
        min: f64,
        /// Largest α.
        max: f64,
        /// One α for every segment.
        shared: bool,
    },
}

impl Default for FitAlpha {
    fn default() -> Self {
        FitAlpha::Range {
            min: DEFAULT_ALPHA_RANGE.0,
            max: DEFAULT_ALPHA_RANGE.1,
            shared: false,
        }
    }
}

/// The loss applied to each point's distance.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum FitLoss {
    /// Least squares: Σ d².
    #[default]
    Squares,
    /// Huber's robust loss: d² up to `delta`, 2·delta·d − delta² beyond (outliers pull
    /// linearly, not quadratically). `delta` in the points' units.
    Huber {
        /// Where the loss turns linear.
        delta: f64,
    },
}

/// What a fit is asked for. `FitOptions::default()` is the least-squares single segment, α
/// fitted in [`DEFAULT_ALPHA_RANGE`].
#[derive(Clone, Debug, PartialEq)]
pub struct FitOptions {
    /// The largest distance allowed between a point and the fit (the points' units); `None`
    /// fits exactly `max_segments` segments by least squares.
    pub tolerance: Option<f64>,
    /// The most segments (with a tolerance), or the number of segments (without).
    pub max_segments: usize,
    /// How α is chosen.
    pub alpha: FitAlpha,
    /// G2 (curvature continuous at the joints, the default) or G1.
    pub continuity: Continuity,
    /// Open, or closed (the points go round once, the last not repeating the first).
    pub closure: Closure,
    /// Pin the ends of an open fit on the first and last points.
    pub pin_ends: bool,
    /// The loss on each distance.
    pub loss: FitLoss,
    /// A weight per point (non-negative, not all zero), or equal weights.
    pub weights: Option<Vec<f64>>,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            tolerance: None,
            max_segments: 1,
            alpha: FitAlpha::default(),
            continuity: Continuity::G2,
            closure: Closure::Open,
            pin_ends: false,
            loss: FitLoss::Squares,
            weights: None,
        }
    }
}

/// One fitted log-aesthetic segment (one or, through an inflection, two [`Segment`]s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitPiece {
    /// Its α.
    pub alpha: f64,
    /// Signed curvature at its start and end.
    pub curvatures: [f64; 2],
    /// Its arc length.
    pub length: f64,
    /// Arc length from the fit's start to its start.
    pub s: f64,
    /// Arc length (from the fit's start) of its point of zero curvature, for an S.
    pub inflection: Option<f64>,
    /// The first and the last of the [`Segment`]s it is made of (more than one for an S,
    /// and for a piece that turns by π or more: a segment turns by less).
    pub segments: [usize; 2],
}

/// A joint of a fit between two pieces, as the check measured it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitJoint {
    /// Arc length from the fit's start (a closed fit's closing joint is at its length).
    pub s: f64,
    /// The joint.
    pub point: Point,
    /// Signed curvature at the end of the piece before it.
    pub curvature_before: f64,
    /// Signed curvature at the start of the piece after it.
    pub curvature_after: f64,
    /// Distance between the pieces' ends.
    pub gap: f64,
    /// Angle between their tangents, radians.
    pub tangent_jump: f64,
    /// |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|) (0 when both are 0).
    pub curvature_jump: f64,
}

/// A log-aesthetic path fitted to points: its segments, joints and how far each point lies
/// from it. A [`Curve`](crate::Curve) through its segments ([`SegmentChain`]).
///
/// ```
/// use kurbo::Point;
/// use lac::{Curve, Fit, FitOptions, Segment};
///
/// // Points on a known clothoid segment (curvature from 1 to 3): the fit finds it again.
/// let truth = Segment::from_curvatures(Point::ORIGIN, 0.0, [1.0, 3.0], 1.0, -1.0)?;
/// let points: Vec<Point> = truth.sample_by_arc_length(200)?.iter().map(|s| s.point).collect();
/// let fit = Fit::from_points(&points, &FitOptions::default())?;
/// assert!(fit.max_distance() < 1e-9);
/// assert!((fit.pieces()[0].alpha + 1.0).abs() < 1e-5);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Fit {
    segments: Vec<Segment>,
    pieces: Vec<FitPiece>,
    joints: Vec<FitJoint>,
    continuity: Continuity,
    closure: Closure,
    distances: Vec<f64>,
    feet: Vec<f64>,
    rms: f64,
    worst: usize,
}

impl SegmentChain for Fit {
    fn pieces(&self) -> &[Segment] {
        &self.segments
    }
}

impl Fit {
    /// Fit a log-aesthetic path to ordered `points`; see the module documentation.
    ///
    /// Errors: a non-finite point or option, fewer than 3 distinct points (4 closed),
    /// points all on one line, [`Error::FitToleranceNotMet`] naming the worst stretch of
    /// the points and the best distance reached, or a fit that does not pass its own check.
    pub fn from_points(points: &[Point], options: &FitOptions) -> Result<Fit> {
        let input = build::Input::new(points, options)?;
        let closed = options.closure == Closure::Closed;
        let profile = Profile::new(&input.data, closed);
        let layout_of = |n: usize| Layout {
            n,
            continuity: options.continuity,
            alpha: input.alpha_mode,
            closed,
            coarse: false,
        };
        // Pinned ends are held from the free fit's answer: a first guess read off noisy data
        // can miss the last point by a tenth of the length, which the KKT steps then fight.
        let constraints = Constraints {
            start: None,
            end: None,
            closed_turn: profile.closed_turn,
        };
        let pins = Constraints {
            start: Some(input.data[0]),
            end: Some(*input.data.last().unwrap()),
            closed_turn: None,
        };
        let tolerance = input.tolerance;
        let target = if tolerance.is_some() {
            options.max_segments
        } else {
            options.max_segments.max(1)
        };
        // The first chain: one segment when it may be enough (a tolerance, an open set);
        // failing that, a piece for every run of monotone curvature in the data (at least
        // two round a closed set); without a tolerance, the asked number.
        let mut extrema = if tolerance.is_some() {
            let mut cuts = profile.curvature_extrema();
            cuts.truncate(target.saturating_sub(1));
            if closed && cuts.len() < 2 {
                cuts = (1..3.min(target))
                    .map(|i| profile.total * i as f64 / 3.0)
                    .collect();
            }
            Some(cuts)
        } else {
            None
        };
        let cuts: Vec<f64> = if extrema.is_none() {
            (1..target)
                .map(|i| profile.total * i as f64 / target as f64)
                .collect()
        } else if closed {
            extrema.take().unwrap_or_default()
        } else {
            Vec::new()
        };
        let problem = |layout: Layout| Problem {
            layout,
            data: &input.data,
            weights: &input.weights,
            loss: input.loss,
            alpha_range: input.alpha_range,
            longest: LONGEST * profile.total,
            constraints,
        };
        // The search (the first chains, splits, merges) looks at about [`SEARCH_POINTS`]
        // of the points, with coarse tables; each chain it settles on is measured against
        // all the points, and the answer polished on all of them with fine tables.
        let mut sample = Sample::new(&input.data, &input.weights, SEARCH_POINTS);
        let failed = |what: &'static str| Error::NumericalFailure { what };
        // A searched chain against all the points, the feet found from the searched ones.
        let measure = |sample: &Sample, s: &State, n: usize| -> Result<State> {
            problem(layout_of(n))
                .state(s.x.clone(), &sample.spread(&s.feet))
                .ok_or(failed("the fit measured against every point"))
        };
        // The polish looks at every point, or of more than [`POLISH_POINTS`] at that many
        // (evenly spread: their least-squares answer is the same to a fraction of the noise),
        // and is measured against every point.
        let dense = Sample::new(&input.data, &input.weights, POLISH_POINTS);
        let pin = options.pin_ends && !closed;
        let polish_every = |full: State, n: usize, steps: usize| -> State {
            if dense.indices.len() == input.data.len() {
                return polish(&problem(layout_of(n)), pin, pins, full, steps);
            }
            let fine = dense.fine(problem(layout_of(n)));
            fine.state(full.x.clone(), &dense.pick(&full.feet))
                .map(|s| polish(&fine, pin, pins, s, steps))
                .and_then(|s| measure(&dense, &s, n).ok())
                .unwrap_or(full)
        };
        let first_state = |sample: &Sample, cuts: &[f64]| -> Result<State> {
            let n = cuts.len() + 1;
            let pieces = guess::pieces(&profile, cuts, input.alpha_mode, input.alpha_range);
            let start = (input.data[0], profile.theta_at(0.0));
            let x = layout_of(n).pack(start, &pieces);
            // Should the profile's pieces describe no chain (a law the range of α does not
            // have, a piece winding round), start from circles of each piece's mean
            // curvature, and failing that from a nearly straight line.
            let circles = |straight: bool| {
                let alpha = input.alpha_range.0.max(0.0).min(input.alpha_range.1);
                pieces
                    .iter()
                    .map(|&(ka, kb, len, _)| {
                        let k = if straight { 1e-6 } else { 0.5 * (ka + kb) };
                        let k = if k == 0.0 { 1e-6 } else { k };
                        (k, k, len, alpha)
                    })
                    .collect::<Vec<_>>()
            };
            let one = sample.problem(problem(layout_of(n)));
            let feet = sample.pick(&profile.s);
            let starts = [
                one.state(x, &feet),
                one.state(layout_of(n).pack(start, &circles(false)), &feet),
                one.state(layout_of(n).pack(start, &circles(true)), &feet),
            ];
            let failed = failed("the first guess of the fit");
            if n == 1 && matches!(input.alpha_mode, AlphaMode::Fixed(_)) {
                // One segment of a given α: the best of the three starts, each fitted a
                // little (the profile's start can lie in another valley than the circle's).
                return starts
                    .into_iter()
                    .flatten()
                    .map(|s| one.minimize(s, 30))
                    .min_by(|a, b| a.cost.total_cmp(&b.cost))
                    .ok_or(failed);
            }
            let state = starts.into_iter().flatten().next().ok_or(failed.clone())?;
            if n == 1 {
                sweep_alpha(&one, state, input.alpha_range).ok_or(failed)
            } else {
                Ok(state)
            }
        };
        let mut n = cuts.len() + 1;
        let mut state = first_state(&sample, &cuts)?;
        // Each round splits a piece; a piece the descent then shrinks to nothing goes again,
        // so that the rounds are counted: a split that keeps collapsing (a curl at the data's
        // end that no piece reaches) would otherwise go round for ever.
        let mut rounds = 0;
        let measured = loop {
            rounds += 1;
            let search = |layout: Layout| sample.problem(problem(layout));
            // With a slope per segment, one slope for all first: from a rough start, free
            // slopes fall into minima where a segment bends hard at the range's end.
            if input.alpha_mode == AlphaMode::Each && n > 1 {
                state = shared_slope_first(&search, layout_of(n), state, input.alpha_range);
            }
            state = search(layout_of(n)).minimize(state, 100);
            // A piece the descent shrank to nothing holds its neighbours (its length's
            // derivatives vanish with it): it goes, and the rest are fitted again.
            if let Some((fewer, m)) = without_collapsed(&search, layout_of(n), &state) {
                state = search(layout_of(m)).minimize(fewer, 100);
                n = m;
            }
            // An open chain that runs on before the first point or after the last is cut
            // there and fitted again: its ends then pull on the data's ends (a split of a
            // piece that lies beyond them would gain nothing).
            if !closed && !options.pin_ends {
                let before = state.chain.length();
                let (cut, m) = trim(&search(layout_of(n)), state);
                state = if cut.chain.length() < before * (1.0 - 1e-9) {
                    search(layout_of(m)).minimize(cut, 100)
                } else {
                    cut
                };
                n = m;
            }
            if options.pin_ends && !closed {
                let pinned = Problem {
                    constraints: pins,
                    ..search(layout_of(n))
                };
                let mut x = state.x.clone();
                (x[0], x[1]) = (input.data[0].re, input.data[0].im);
                state = pinned
                    .state(x, &state.feet)
                    .ok_or(failed("the fit with pinned ends"))?;
                state = pinned.minimize(state, 100);
            }
            let mut full = measure(&sample, &state, n)?;
            let mut worst = worst_index(&full.distances);
            if let Some(tol) = tolerance {
                // Just beyond the tolerance: the polish on every point may bring it within
                // (a few steps: within, the answer's polish goes on from there).
                if full.distances[worst] > tol && full.distances[worst] <= POLISH_NEAR * tol {
                    full = polish_every(full, n, POLISH_PEEK);
                    worst = worst_index(&full.distances);
                }
            }
            let reached = full.distances[worst];
            let Some(tol) = tolerance.filter(|tol| reached > *tol) else {
                break full;
            };
            let (from, to) = stretch(&full.distances, worst, tol);
            let not_met = |segments: usize| Error::FitToleranceNotMet {
                tolerance: tol * input.scale,
                reached: reached * input.scale,
                segments,
                from,
                to,
            };
            if n >= target {
                return Err(not_met(target));
            }
            // (Refused as at the most segments asked: the pieces it would split further
            // are the ones that keep collapsing.)
            if rounds > MOST_ROUNDS_PER_SEGMENT * target {
                return Err(not_met(target));
            }
            if let Some(cuts) = extrema.take().filter(|c| !c.is_empty()) {
                // One segment is not enough: start again from the runs of the data.
                n = cuts.len() + 1;
                state = first_state(&sample, &cuts)?;
                continue;
            }
            // The points beyond the tolerance join the search, which would not see them
            // otherwise (at most [`JOINING`] of them a round, evenly spread, and the
            // worst), and the piece at the worst is split.
            let beyond: Vec<usize> = (0..input.data.len())
                .filter(|&i| full.distances[i] > tol)
                .collect();
            let step = beyond.len().div_ceil(JOINING).max(1);
            let joining = beyond.iter().step_by(step).copied().chain([worst]);
            if sample.add(joining, &input.data, &input.weights) {
                state = sample
                    .problem(problem(layout_of(n)))
                    .state(full.x.clone(), &sample.pick(&full.feet))
                    .ok_or(failed("the fit measured against every point"))?;
            }
            // A piece that cannot be split (no share gives halves the tables can follow)
            // ends the search with what it reached.
            state = split(
                &sample.problem(problem(layout_of(n + 1))),
                state,
                full.feet[worst],
            )
            .ok_or(not_met(n))?;
            n += 1;
        };
        // The polish on every point; kept when it stays within the tolerance.
        let polished = |full: State, n: usize| -> State {
            let fine = polish_every(full.clone(), n, POLISH_STEPS);
            match tolerance {
                Some(tol) if fine.distances.iter().any(|d| *d > tol) => full,
                _ => fine,
            }
        };
        let finish = |state: State, n: usize| -> Result<Fit> {
            let (state, n) = if !closed && !options.pin_ends {
                trim(&problem(layout_of(n)), state)
            } else {
                (state, n)
            };
            build::build(&input, &layout_of(n), state, options)
        };
        // The fewest segments: joints whose two pieces can become one within the tolerance
        // are taken out (a start from the data's noisy curvature runs may have too many).
        // Should the merged chain not pass the final check, the chain before merging is
        // the answer.
        if let (Some(tol), false) = (tolerance, options.pin_ends) {
            let within = |s: &State, m: usize| {
                measure(&sample, s, m)
                    .ok()
                    .filter(|full| full.distances.iter().all(|d| *d <= tol))
            };
            let search = |n: usize| sample.problem(problem(layout_of(n)));
            if let Some((merged, m)) = merge(&search, &within, tol, state, n) {
                if let Ok(fit) = finish(polished(merged, m), m) {
                    return Ok(fit);
                }
            }
        }
        finish(polished(measured, n), n)
    }

    /// The fitted pieces in order.
    pub fn pieces(&self) -> &[FitPiece] {
        &self.pieces
    }

    /// The joints between pieces (a closed fit's last joint closes it).
    pub fn joints(&self) -> &[FitJoint] {
        &self.joints
    }

    /// G2 or G1.
    pub fn continuity(&self) -> Continuity {
        self.continuity
    }

    /// Open or closed.
    pub fn closure(&self) -> Closure {
        self.closure
    }

    /// Each point's distance to the fit, in the points' order.
    pub fn distances(&self) -> &[f64] {
        &self.distances
    }

    /// Each point's foot on the fit, as arc length from its start.
    pub fn feet(&self) -> &[f64] {
        &self.feet
    }

    /// Root mean square of the distances (unweighted).
    pub fn rms(&self) -> f64 {
        self.rms
    }

    /// The largest distance.
    pub fn max_distance(&self) -> f64 {
        self.distances[self.worst]
    }

    /// The point farthest from the fit (0-based).
    pub fn worst_point(&self) -> usize {
        self.worst
    }

    /// The points farthest from the fit, farthest first (at most `count`).
    pub fn farthest_points(&self, count: usize) -> Vec<usize> {
        let mut order: Vec<usize> = (0..self.distances.len()).collect();
        order.sort_by(|&a, &b| self.distances[b].total_cmp(&self.distances[a]));
        order.truncate(count);
        order
    }
}

/// The index of the largest distance.
fn worst_index(distances: &[f64]) -> usize {
    let mut worst = 0;
    for (k, d) in distances.iter().enumerate() {
        if *d > distances[worst] {
            worst = k;
        }
    }
    worst
}

/// The run of points around `worst` farther than `tolerance`.
fn stretch(distances: &[f64], worst: usize, tolerance: f64) -> (usize, usize) {
    let mut from = worst;
    while from > 0 && distances[from - 1] > tolerance {
        from -= 1;
    }
    let mut to = worst;
    while to + 1 < distances.len() && distances[to + 1] > tolerance {
        to += 1;
    }
    (from, to)
}

/// The chain with the piece at the arc length `foot` (the worst point's) split in two
/// there (within its middle half), both halves on the same curve.
fn split(problem: &Problem, state: State, foot: f64) -> Option<State> {
    let chain = &state.chain;
    let (i, t) = chain.locate(foot, 0);
    let start = (Complex::new(state.x[0], state.x[1]), state.x[2]);
    // Where the halves describe no chain the tables can follow (a half whose curvature
    // changes too fast), other shares of the piece.
    [t.clamp(0.4, 0.6), 0.5, 0.3, 0.7]
        .into_iter()
        .find_map(|t| {
            let mut pieces = chain.numbers.clone();
            let (ka, kb, len, alpha) = pieces[i];
            let kt = chain.pieces[i].law.at(t).1;
            pieces[i] = (ka, kt, t * len, alpha);
            pieces.insert(i + 1, (kt, kb, (1.0 - t) * len, alpha));
            problem.state(problem.layout.pack(start, &pieces), &state.feet)
        })
}

/// The chain with one slope for all its pieces fitted first (their mean, within −1 and 2),
/// then each its own from there: from a rough start, free slopes fall into minima where a
/// segment bends hard at the range's end. The better of that and the chain fitted as it is.
fn shared_slope_first<'a>(
    problem: &dyn Fn(Layout) -> Problem<'a>,
    layout: Layout,
    state: State,
    range: (f64, f64),
) -> State {
    let shared = Layout {
        alpha: AlphaMode::Shared,
        ..layout
    };
    let mut numbers = state.chain.numbers.clone();
    let mean = numbers.iter().map(|p| p.3).sum::<f64>() / numbers.len() as f64;
    let mean = mean
        .clamp(range.0.max(-1.0), range.1.min(2.0))
        .clamp(range.0, range.1);
    for p in numbers.iter_mut() {
        p.3 = mean;
    }
    let one = problem(shared);
    let start = (state.chain.start, state.chain.theta0);
    let Some(s1) = one.state(shared.pack(start, &numbers), &state.feet) else {
        return state;
    };
    let s1 = one.minimize(s1, SHARED_STEPS);
    let each = problem(layout);
    let x = layout.pack((s1.chain.start, s1.chain.theta0), &s1.chain.numbers);
    let Some(s2) = each.state(x, &s1.feet) else {
        return state;
    };
    if s2.cost < state.cost || state.cost.is_nan() {
        return s2;
    }
    let state = each.minimize(state, SHARED_STEPS);
    let alternative = each.minimize(s2, SHARED_STEPS);
    if alternative.cost < state.cost {
        alternative
    } else {
        state
    }
}

/// The chain without its pieces shorter than [`COLLAPSED`] of it, and their number;
/// `None` when there are none (or only such pieces).
fn without_collapsed<'a>(
    problem: &dyn Fn(Layout) -> Problem<'a>,
    layout: Layout,
    state: &State,
) -> Option<(State, usize)> {
    let chain = &state.chain;
    let least = if layout.closed { 2 } else { 1 };
    let total = chain.length();
    let kept: Vec<_> = chain
        .numbers
        .iter()
        .copied()
        .filter(|p| p.2 > COLLAPSED * total)
        .collect();
    if kept.len() == chain.numbers.len() || kept.len() < least {
        return None;
    }
    // The chain starts where its first kept piece does.
    let first = chain.numbers.iter().position(|p| p.2 > COLLAPSED * total)?;
    let start = (chain.pieces[first].points[0], chain.pieces[first].thetas[0]);
    let fewer = Layout {
        n: kept.len(),
        ..layout
    };
    let s = problem(fewer).state(fewer.pack(start, &kept), &state.feet)?;
    Some((s, fewer.n))
}

/// The share of a chain's length below which a piece has collapsed.
const COLLAPSED: f64 = 1e-6;

/// The longest a fitted piece may grow, times the length of the points' polyline.
const LONGEST: f64 = 4.0;

/// Most steps of a polish on every point: it starts a step or two from its answer, and a
/// chain of several pieces can crawl along a flat valley for a hundred steps to gain a
/// thousandth of its cost.
const POLISH_STEPS: usize = 25;

/// Most steps of each descent in [`shared_slope_first`] (the search's own descent follows).
const SHARED_STEPS: usize = 30;

/// Most steps of the polish that looks whether a searched chain just beyond the tolerance
/// comes within it.
const POLISH_PEEK: usize = 8;

/// A chain fitted to every point with fine tables from `state`, at most `steps` steps (its
/// ends held on the first and last points when `pin`).
fn polish(problem: &Problem, pin: bool, pins: Constraints, state: State, steps: usize) -> State {
    if pin {
        let pinned = Problem {
            constraints: pins,
            ..*problem
        };
        pinned.polish(state, steps)
    } else {
        problem.polish(state, steps)
    }
}

/// The most points a polish looks at.
const POLISH_POINTS: usize = 20_000;

/// About how many points the search for a path's segments looks at.
const SEARCH_POINTS: usize = 200;

/// The most rounds of the search (each splits a piece), times the most segments: twice
/// as many as splitting up to the most would take, for pieces that collapse and go.
const MOST_ROUNDS_PER_SEGMENT: usize = 2;

/// The most points beyond the tolerance that join the search in one round: one piece is
/// split a round, and what the rest miss is seen again in the next.
const JOINING: usize = 50;

/// Steps of a merge's descent after which a chain farther than [`MERGE_HOPELESS`] times the
/// tolerance from a searched point is given up.
const MERGE_GLANCE: usize = 12;

/// See [`MERGE_GLANCE`].
const MERGE_HOPELESS: f64 = 2.0;

/// A searched chain this close to the tolerance (times it) is polished on every point
/// before it is split.
const POLISH_NEAR: f64 = 1.5;

/// The points a search looks at: every k-th and the last, and those it was found to miss.
struct Sample {
    /// Their indices, increasing.
    indices: Vec<usize>,
    data: Vec<Complex>,
    weights: Vec<f64>,
}

impl Sample {
    /// About `count` of the points, evenly spread.
    fn new(data: &[Complex], weights: &[f64], count: usize) -> Sample {
        let k = data.len().div_ceil(count).max(1);
        let indices = every(&(0..data.len()).collect::<Vec<_>>(), k);
        Sample {
            data: indices.iter().map(|&i| data[i]).collect(),
            weights: indices.iter().map(|&i| weights[i]).collect(),
            indices,
        }
    }

    /// Add the points `extra`; whether any was new.
    fn add(
        &mut self,
        extra: impl Iterator<Item = usize>,
        data: &[Complex],
        weights: &[f64],
    ) -> bool {
        let before = self.indices.len();
        self.indices.extend(extra);
        self.indices.sort_unstable();
        self.indices.dedup();
        if self.indices.len() == before {
            return false;
        }
        self.data = self.indices.iter().map(|&i| data[i]).collect();
        self.weights = self.indices.iter().map(|&i| weights[i]).collect();
        true
    }

    /// The problem over these points with coarse tables.
    fn problem<'a>(&'a self, base: Problem<'a>) -> Problem<'a> {
        Problem {
            layout: Layout {
                coarse: true,
                ..base.layout
            },
            data: &self.data,
            weights: &self.weights,
            ..base
        }
    }

    /// The problem over these points with the base's (fine) tables.
    fn fine<'a>(&'a self, base: Problem<'a>) -> Problem<'a> {
        Problem {
            data: &self.data,
            weights: &self.weights,
            ..base
        }
    }

    /// These points' entries of a value for every point.
    fn pick(&self, every: &[f64]) -> Vec<f64> {
        self.indices.iter().map(|&i| every[i]).collect()
    }

    /// Feet for every point from these points' feet, by linear interpolation in the
    /// points' order.
    fn spread(&self, feet: &[f64]) -> Vec<f64> {
        model::spread(&self.indices, feet)
    }
}

/// The chain with pieces merged pairwise while the fit stays within the tolerance: each
/// joint in turn (the shortest pair first) is taken out, the two pieces becoming one with
/// their outer curvatures and α the mean, and the chain refitted; kept when `within` (the
/// chain measured against every point, when every point lies within the tolerance) says
/// so. The last chain kept, measured, and its number of pieces; `None` when no joint goes.
fn merge<'a>(
    problem: &dyn Fn(usize) -> Problem<'a>,
    within: &dyn Fn(&State, usize) -> Option<State>,
    tolerance: f64,
    mut state: State,
    mut n: usize,
) -> Option<(State, usize)> {
    let closed = problem(n).layout.closed;
    let least = if closed { 2 } else { 1 };
    let mut measured = None;
    'again: while n > least {
        let numbers = state.chain.numbers.clone();
        let mut order: Vec<usize> = (0..n - 1).collect();
        order.sort_by(|&a, &b| {
            let la = numbers[a].2 + numbers[a + 1].2;
            let lb = numbers[b].2 + numbers[b + 1].2;
            la.total_cmp(&lb)
        });
        for j in order {
            let mut pieces = numbers.clone();
            let (ka, _, la, aa) = pieces[j];
            let (_, kb, lb, ab) = pieces[j + 1];
            pieces[j] = (ka, kb, la + lb, 0.5 * (aa + ab));
            pieces.remove(j + 1);
            let fewer = problem(n - 1);
            let start = (state.chain.start, state.chain.theta0);
            let Some(trial) = fewer.state(fewer.layout.pack(start, &pieces), &state.feet) else {
                continue;
            };
            // A few steps first: a merge whose chain is still far beyond the tolerance
            // then is given up without the whole descent.
            let trial = fewer.minimize(trial, MERGE_GLANCE);
            if trial
                .distances
                .iter()
                .any(|d| *d > MERGE_HOPELESS * tolerance)
            {
                continue;
            }
            let trial = fewer.minimize(trial, 100);
            if let Some(full) = within(&trial, n - 1) {
                state = trial;
                measured = Some(full);
                n -= 1;
                continue 'again;
            }
        }
        break;
    }
    measured.map(|m| (m, n))
}

/// The open chain cut to the stretch between the first and the last foot of a point: the
/// data say nothing of the curve beyond, where it would otherwise run on at no cost. The
/// state and its number of pieces (the chain as it is when it cannot be cut).
fn trim(problem: &Problem, state: State) -> (State, usize) {
    let chain = &state.chain;
    let n = chain.pieces.len();
    let lo = state.feet.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = state.feet.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (i0, t0) = chain.locate(lo, 0);
    let (i1, t1) = chain.locate(hi, n - 1);
    let mut pieces = Vec::with_capacity(i1 + 1 - i0);
    for i in i0..=i1 {
        let (_, _, len, alpha) = chain.numbers[i];
        let a = if i == i0 { t0 } else { 0.0 };
        let b = if i == i1 { t1 } else { 1.0 };
        if (b - a).is_nan() || b - a <= 1e-9 {
            // A piece that would be cut to (almost) nothing: keep the chain as it is.
            return (state, n);
        }
        let law = chain.pieces[i].law;
        pieces.push((law.at(a).1, law.at(b).1, (b - a) * len, alpha));
    }
    let (p, _, _) = chain.pieces[i0].at(t0);
    let theta = chain.pieces[i0].thetas[0] + chain.pieces[i0].law.at(t0).0;
    let layout = Layout {
        n: pieces.len(),
        ..problem.layout
    };
    let trimmed = Problem { layout, ..*problem };
    let x = layout.pack((p, theta), &pieces);
    let feet: Vec<f64> = state.feet.iter().map(|f| f - lo).collect();
    // Should the trimmed chain describe no chain the tables can follow (a piece cut where
    // its curvature changes too fast), the chain is kept as it is.
    match trimmed.state(x, &feet) {
        Some(t) => (t, layout.n),
        None => (state, n),
    }
}

#[cfg(test)]
mod tests;
