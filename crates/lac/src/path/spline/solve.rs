//! Newton's method on a spline's unknowns (tangent angles, knots' places): the shape and
//! end curvatures of every span, the residual of every condition, the Jacobian by forward
//! differences span by span (an unknown moves the spans at its node only), solved
//! tridiagonally when each unknown pairs with its node's equation and densely otherwise.
//! The relaxed problem first (with the continuation in α of the smooth spline), then the
//! full one from it.

use std::cell::{Cell, RefCell};
use std::f64::consts::PI;
use std::sync::OnceLock;

use kurbo::{Point, Vec2};

use super::super::s_span::{SSpan, Unit};
use super::super::{banded, G2_JUMP_LIMIT, G2_TOLERANCE};
use super::layout::{dir, wrap, At, Condition, Kind, Layout, Plan, Tangent};
use crate::curve::chain::Chain;
use crate::curve::Curve;
use crate::foundation::error::{Error, G2Failure, PointFailure, Result};
use crate::foundation::numeric::length;
use crate::segment::{Segment, SegmentSolution};

/// A kept Jacobian's steps must shrink the residual by this factor or it is made afresh, ...
const KEEP_WHILE: f64 = 0.0001;
/// ... unless the next step at the same rate would take the residual below this.
const NEXT: f64 = 1e-11;
/// A residual norm at rounding: below it a step that does not lower it ends the descent.
const RESIDUAL_FLOOR: f64 = 1e-12;
/// Most Newton steps.
const MAX_STEPS: usize = 60;
/// Most stages of the continuation in α.
const MAX_STAGES: f64 = 12.0;
/// Step of the forward differences in the unknowns (radians, or shares of a half chord).
const H: f64 = 1e-7;
/// Largest change of any unknown in one step.
const MAX_STEP: f64 = 0.2;
/// The homotopy's stages, when Newton's method does not reach the full problem at once.
const HOMOTOPY: [f64; 4] = [0.25, 0.5, 0.75, 1.0];
/// Where the knots' lines cross their chords, tried in turn (see [`Plan::knot_frame`]).
const KNOT_SHARES: [f64; 3] = [0.5, 0.3, 0.7];

/// A Jacobian's entries: (row, unknown, value).
pub(super) type Entries = Vec<(usize, usize, f64)>;

/// The shape of one span: one segment (its control triangle), an S (or half S), or a line.
#[derive(Clone, Copy, Debug)]
pub(super) enum Shape {
    Plain([Point; 3]),
    S(SSpan),
    Line,
}

/// A span's shape, its signed end curvatures and, for a half S, the direction of its
/// tangent at its other end.
#[derive(Clone, Copy, Debug)]
pub(super) struct Value {
    pub(super) shape: Shape,
    pub(super) kappa: (f64, f64),
    pub(super) other: f64,
}

/// Where each span's own search ended last time: a plain segment's μ, an S's mirror image
/// and A, a half S's turning. The next evaluation of the span, a Newton step or a
/// difference away, starts there (each search has one answer, or is checked, so the hint
/// only saves evaluations).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Memo {
    mu: Option<f64>,
    s: Option<(f64, f64)>,
    half: Option<f64>,
}

/// One problem: the points, the layout, the slope; the Jacobian Newton's method starts from
/// (an earlier answer's, for a warm re-solve) and the last one it made; each span's memo.
pub(super) struct Problem<'a> {
    pub(super) points: &'a [Point],
    pub(super) layout: &'a Layout,
    pub(super) alpha: f64,
    pub(super) unit: Option<Unit>,
    start: RefCell<Option<Entries>>,
    last: RefCell<Option<Entries>>,
    memo: RefCell<Vec<Memo>>,
    /// Each plain span's segment as the last evaluation solved it.
    made: RefCell<Vec<Option<SegmentSolution>>>,
    /// The spans at the last answer Newton's method reached, and their plain segments, so
    /// that the build need not solve them again.
    reached: RefCell<Vec<Reached>>,
    /// Each span's last full evaluation, so that a span whose ends did not move is not
    /// solved again (seeded with an earlier answer's spans for a warm re-solve).
    cache: RefCell<Vec<Option<Reached>>>,
    /// Whether span solves may stop loosely: while taking difference quotients, whose
    /// values are never kept.
    loose: Cell<bool>,
    /// The spans the last full evaluation solved (not taken from the cache).
    moved: RefCell<Vec<usize>>,
}

/// What a span's shape is a function of (with the slope): its kind, its ends' places and
/// tangents (its start's leaving, its end's arriving).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Key {
    kind: Kind,
    ends: [f64; 6],
}

/// What first-order moves of a span need from one evaluation of it: its chord's length and
/// its end tangents' angles from the chord, and its shape's exact slopes (made once per
/// evaluation, when first asked).
#[derive(Clone, Copy, Debug)]
pub(super) struct Slopes {
    chord: f64,
    psi: f64,
    ta: f64,
    tb: f64,
    of: Of,
}

/// A shape's exact slopes, with where it was.
#[derive(Clone, Copy, Debug)]
enum Of {
    /// A plain segment: d ln|κ| at its ends by its triangle's angles at its ends and ln
    /// chord, dμ by the angles, and μ.
    Plain {
        kappa: [[f64; 3]; 2],
        mu: [f64; 2],
        at: f64,
    },
    /// An S: d ln|κ| by (ta, tb, ln chord), dA by (ta, tb), and its mirror image and A.
    S {
        kappa: [[f64; 3]; 2],
        a: [f64; 2],
        at: (f64, f64),
    },
    /// A half S: its turning, ln|κ| at its curved end and its other tangent's angle by its
    /// size (see [`SSpan::half_slopes`]), and its turning.
    Half { slopes: [f64; 3], at: f64 },
    /// None to be had.
    Nothing,
}

impl Slopes {
    /// The slopes of span `value` (and `made`, a plain segment's solution), evaluated for
    /// `key`.
    fn of(key: &Key, value: &Value, made: Option<&SegmentSolution>) -> Slopes {
        let [ax, ay, bx, by, phi_a, phi_b] = key.ends;
        let d = Point::new(bx, by) - Point::new(ax, ay);
        let (chord, psi) = (length(d), dir(d));
        let of = match (&value.shape, made) {
            (Shape::Plain(_), Some(m)) => match (m.angle_slopes(), m.mu_slopes()) {
                (Some(kappa), Some(mu)) => Of::Plain {
                    kappa,
                    mu,
                    at: m.mu(),
                },
                _ => Of::Nothing,
            },
            (Shape::S(s), _) if s.is_half() => match s.half_slopes(chord) {
                Some(slopes) => Of::Half {
                    slopes,
                    at: s.theta[0].max(s.theta[1]),
                },
                None => Of::Nothing,
            },
            (Shape::S(s), _) => match s.slopes(chord) {
                Some((kappa, a)) => Of::S {
                    kappa,
                    a,
                    at: s.hint(),
                },
                None => Of::Nothing,
            },
            _ => Of::Nothing,
        };
        Slopes {
            chord,
            psi,
            ta: wrap(phi_a - psi),
            tb: wrap(phi_b - psi),
            of,
        }
    }

    /// The change of a plain segment's triangle (its angles at its ends between leg and
    /// chord, and ln of its chord) from this span's to one with chord `c` and end tangents
    /// `ta`, `tb` from it, or `None` unless both are plain segments turning the same way.
    fn plain_step(&self, c: f64, ta: f64, tb: f64) -> Option<[f64; 3]> {
        let (ta0, tb0) = (self.ta, self.tb);
        (ta * ta0 > 0.0 && tb * tb0 > 0.0 && ta * tb < 0.0).then(|| {
            [
                ta.abs() - ta0.abs(),
                tb.abs() - tb0.abs(),
                (c / self.chord).ln(),
            ]
        })
    }

    /// The change of an S span's end tangents' angles from its chord, and of ln of its
    /// chord, to one with chord `c` and end tangents `ta`, `tb`, or `None` where one would
    /// be tried as a plain segment and the other not.
    fn s_step(&self, c: f64, ta: f64, tb: f64) -> Option<[f64; 3]> {
        let plain = |ta: f64, tb: f64| ta * tb < 0.0 && ta.abs() + tb.abs() < PI;
        (plain(ta, tb) == plain(self.ta, self.tb))
            .then(|| [ta - self.ta, tb - self.tb, (c / self.chord).ln()])
    }

    /// The change of a half S's size (the angle from the chord of its tangent at the
    /// inflection, at its end when `at_end`), and of ln of its chord, to one with chord `c`
    /// and that angle `t`, or `None` unless the angle keeps its side.
    fn half_step(&self, c: f64, t: f64, at_end: bool) -> Option<[f64; 2]> {
        let t0 = if at_end { self.tb } else { self.ta };
        (t * t0 > 0.0).then(|| [t.abs() - t0.abs(), (c / self.chord).ln()])
    }
}

/// A span at an answer, or as last evaluated: what it was evaluated for, its value and, for
/// a plain segment, its solution.
#[derive(Clone)]
pub(super) struct Reached {
    key: Key,
    pub(super) value: Value,
    pub(super) made: Option<SegmentSolution>,
    slopes: OnceLock<Slopes>,
}

impl Reached {
    fn new(key: Key, value: Value, made: Option<SegmentSolution>) -> Reached {
        Reached {
            key,
            value,
            made,
            slopes: OnceLock::new(),
        }
    }

    /// Its slopes, made when first asked.
    fn slopes(&self) -> &Slopes {
        self.slopes
            .get_or_init(|| Slopes::of(&self.key, &self.value, self.made.as_ref()))
    }
}

impl std::fmt::Debug for Reached {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Reached")
            .field("key", &self.key)
            .field("value", &self.value)
            .field("made", &self.made.as_ref().map(|m| m.mu()))
            .finish()
    }
}

impl Problem<'_> {
    pub(super) fn new<'a>(points: &'a [Point], layout: &'a Layout, alpha: f64) -> Problem<'a> {
        Problem {
            points,
            layout,
            alpha,
            unit: Unit::new(alpha),
            start: RefCell::new(None),
            last: RefCell::new(None),
            memo: RefCell::new(vec![Memo::default(); layout.spans.len()]),
            made: RefCell::new(vec![None; layout.spans.len()]),
            reached: RefCell::new(Vec::new()),
            cache: RefCell::new(vec![None; layout.spans.len()]),
            loose: Cell::new(false),
            moved: RefCell::new(Vec::new()),
        }
    }

    /// The spans at the last answer [`Problem::newton`] reached, with their plain segments.
    pub(super) fn reached(&self) -> Vec<Reached> {
        self.reached.take()
    }

    /// Keep `values`, the spans at `x`, as reached, with the plain segments solved for them
    /// where the cache still holds them.
    fn reach(&self, x: &[f64], values: &[Value]) {
        let cache = self.cache.borrow();
        *self.reached.borrow_mut() = values
            .iter()
            .zip(cache.iter())
            .enumerate()
            .map(|(k, (v, c))| {
                let key = self.key(x, k);
                Reached::new(
                    key,
                    *v,
                    c.as_ref()
                        .filter(|c| c.key == key)
                        .and_then(|c| c.made.clone()),
                )
            })
            .collect();
    }

    /// Start from an earlier answer's spans (of the same layout and slope): those whose
    /// ends have not moved are not solved again.
    pub(super) fn seed_spans(&self, reached: &[Reached]) {
        let mut cache = self.cache.borrow_mut();
        if reached.len() == cache.len() {
            for (c, r) in cache.iter_mut().zip(reached) {
                *c = Some(r.clone());
            }
        }
    }

    /// What span `k` is a function of, for unknowns `x`.
    pub(super) fn key(&self, x: &[f64], k: usize) -> Key {
        let l = self.layout;
        let (ka, kb) = (k, l.end_of(k));
        let (a, b) = (
            l.position(self.points, x, ka),
            l.position(self.points, x, kb),
        );
        Key {
            kind: l.spans[k].kind,
            ends: [
                a.x,
                a.y,
                b.x,
                b.y,
                l.tangent(x, ka, true),
                l.tangent(x, kb, false),
            ],
        }
    }

    /// Every span's memo.
    pub(super) fn memos(&self) -> Vec<Memo> {
        self.memo.borrow().clone()
    }

    /// Start each span's search from `memo` (another problem's on the same layout).
    pub(super) fn seed(&self, memo: &[Memo]) {
        let mut mine = self.memo.borrow_mut();
        if memo.len() == mine.len() {
            mine.copy_from_slice(memo);
        }
    }

    /// The μ span `k`'s plain segment was last solved with, if it was.
    pub(super) fn mu_of(&self, k: usize) -> Option<f64> {
        self.memo.borrow().get(k).and_then(|m| m.mu)
    }

    /// Span `k` (from node k to the next) for unknowns `x`.
    pub(super) fn span(&self, x: &[f64], k: usize) -> Result<Value> {
        let l = self.layout;
        let (ka, kb) = (k, l.end_of(k));
        let (a, b) = (
            l.position(self.points, x, ka),
            l.position(self.points, x, kb),
        );
        let span = l.spans[k].span;
        let psi = dir(b - a);
        let c = length(b - a);
        let (ta, tb) = (
            wrap(l.tangent(x, ka, true) - psi),
            wrap(l.tangent(x, kb, false) - psi),
        );
        let memo = self.memo.borrow().get(k).copied().unwrap_or_default();
        let remember = |m: Memo| {
            if let Some(slot) = self.memo.borrow_mut().get_mut(k) {
                *slot = m;
            }
        };
        // For a difference quotient: the span's last solution moved to first order, where
        // it can be.
        if self.loose.get() && l.spans[k].kind != Kind::Line {
            if let Some(v) = self.linear(k, c, (ta, tb), psi) {
                return Ok(v);
            }
        }
        let half = |t: f64, at_end: bool| -> Result<Value> {
            let fail = || Error::SplinePoint {
                point: point_of(l, if at_end { kb } else { ka }),
                reason: PointFailure::Unmet {
                    what: Condition::Inflection { after: !at_end }.what(),
                    miss: f64::NAN,
                },
            };
            let hint = self.predicted(k, memo, c, ta, tb).half;
            let (s, other) = self
                .unit
                .and_then(|u| u.half(t, c, at_end, hint))
                .ok_or_else(fail)?;
            remember(Memo {
                half: Some(s.theta[0].max(s.theta[1])),
                ..memo
            });
            Ok(Value {
                shape: Shape::S(s),
                kappa: s.end_curvatures(),
                other: psi + other,
            })
        };
        match l.spans[k].kind {
            Kind::Line => Ok(Value {
                shape: Shape::Line,
                kappa: (0.0, 0.0),
                other: f64::NAN,
            }),
            Kind::HalfToEnd => half(tb, true),
            Kind::HalfFromStart => half(ta, false),
            Kind::Curve => {
                let phi_a = l.tangent(x, ka, true);
                // The search starts where the last evaluation's slopes put it, if they can.
                let mut m = self.predicted(k, memo, c, ta, tb);
                let mut made = None;
                let (shape, kappa) = curve(
                    self.alpha,
                    self.unit.as_ref(),
                    a,
                    b,
                    [phi_a, ta, tb],
                    span,
                    (&mut m, &mut made, self.loose.get()),
                )?;
                if let Some(slot) = self.made.borrow_mut().get_mut(k) {
                    *slot = made;
                }
                remember(m);
                Ok(Value {
                    shape,
                    kappa,
                    other: f64::NAN,
                })
            }
        }
    }

    /// Span `k` for a chord `c` of direction `psi` and end tangents `ta`, `tb` a difference
    /// quotient's step from those of its last full evaluation: its end curvatures (and a
    /// half S's other tangent) moved to first order by the exact slopes of that evaluation's
    /// segment, S or half S (none solved), or `None` where it has none or the step leaves
    /// its kind of shape.
    fn linear(&self, k: usize, c: f64, (ta, tb): (f64, f64), psi: f64) -> Option<Value> {
        let cache = self.cache.borrow();
        let last = cache.get(k)?.as_ref()?;
        let slopes = last.slopes();
        let kind = self.layout.spans[k].kind;
        let (k0, k1) = last.value.kappa;
        let (kappa, other) = match slopes.of {
            Of::Half {
                slopes: [_, dln_kappa, d_other],
                ..
            } => {
                let at_end = kind == Kind::HalfToEnd;
                let t = if at_end { tb } else { ta };
                let [d_angle, dlnc] = slopes.half_step(c, t, at_end)?;
                let f = (dln_kappa * d_angle - dlnc).exp();
                // Its other tangent: from the chord as it was, moved, on the chord as it is.
                let other = psi + (last.value.other - slopes.psi) + d_other * d_angle;
                ((k0 * f, k1 * f), other)
            }
            Of::Plain { kappa, .. } | Of::S { kappa, .. } => {
                let d = match slopes.of {
                    Of::Plain { .. } => slopes.plain_step(c, ta, tb)?,
                    _ => slopes.s_step(c, ta, tb)?,
                };
                let moved = |s: [f64; 3]| (s[0] * d[0] + s[1] * d[1] + s[2] * d[2]).exp();
                // (A difference quotient reads the curvatures only.)
                ((k0 * moved(kappa[0]), k1 * moved(kappa[1])), f64::NAN)
            }
            Of::Nothing => return None,
        };
        (kappa.0.is_finite() && kappa.1.is_finite() && (other.is_finite() || other.is_nan()))
            .then_some(Value {
                shape: last.value.shape,
                kappa,
                other,
            })
    }

    /// Span `k`'s memo for chord `c` and end tangents `ta`, `tb`: a plain segment's μ, an
    /// S's A, a half S's turning, moved to first order from its last full evaluation where
    /// it can be.
    fn predicted(&self, k: usize, memo: Memo, c: f64, ta: f64, tb: f64) -> Memo {
        let cache = self.cache.borrow();
        let Some(last) = cache.get(k).and_then(|c| c.as_ref()) else {
            return memo;
        };
        let slopes = last.slopes();
        match slopes.of {
            Of::Plain { mu, at, .. } => {
                let next = slopes
                    .plain_step(c, ta, tb)
                    .map(|d| at + mu[0] * d[0] + mu[1] * d[1])
                    .filter(|mu| *mu > 0.0 && mu.is_finite());
                Memo {
                    mu: next.or(memo.mu),
                    ..memo
                }
            }
            Of::S { a, at, .. } => {
                let next = slopes
                    .s_step(c, ta, tb)
                    .map(|d| (at.0, at.1 + a[0] * d[0] + a[1] * d[1]))
                    .filter(|s| s.1.is_finite());
                Memo {
                    s: next.or(memo.s),
                    ..memo
                }
            }
            Of::Half { slopes: h, at } => {
                let at_end = self.layout.spans[k].kind == Kind::HalfToEnd;
                let t = if at_end { tb } else { ta };
                let next = slopes
                    .half_step(c, t, at_end)
                    .map(|[d, _]| at + h[0] * d)
                    .filter(|t| *t > 0.0 && t.is_finite());
                Memo {
                    half: next.or(memo.half),
                    ..memo
                }
            }
            Of::Nothing => memo,
        }
    }

    /// Every span: solved again where its ends moved since its last full evaluation.
    pub(super) fn spans(&self, x: &[f64]) -> Result<Vec<Value>> {
        self.moved.borrow_mut().clear();
        (0..self.layout.spans.len())
            .map(|k| {
                let key = self.key(x, k);
                if let Some(r) = self.cache.borrow()[k].as_ref().filter(|r| r.key == key) {
                    return Ok(r.value);
                }
                self.moved.borrow_mut().push(k);
                self.made.borrow_mut()[k] = None;
                let value = self.span(x, k)?;
                let made = self.made.borrow_mut()[k].take();
                self.cache.borrow_mut()[k] = Some(Reached::new(key, value, made));
                Ok(value)
            })
            .collect()
    }

    /// The residual of node `k`'s condition, with `value(span)` each span's value: scale
    /// free (curvatures times the node's length, directions in radians).
    fn row(&self, x: &[f64], k: usize, value: &dyn Fn(usize) -> Value) -> f64 {
        let l = self.layout;
        let node = &l.nodes[k];
        let (before, after) = l.spans_at(k);
        let w = node.weight;
        match node.condition.expect("a row") {
            Condition::G2 => {
                let (b, a) = (before.expect("a span"), after.expect("a span"));
                (value(b).kappa.1 - value(a).kappa.0) * w
            }
            Condition::Curvature {
                after: true,
                value: v,
            } => (value(after.expect("a span")).kappa.0 - v) * w,
            Condition::Curvature {
                after: false,
                value: v,
            } => (value(before.expect("a span")).kappa.1 - v) * w,
            Condition::Inflection { after: true } => {
                let s = after.expect("a span");
                wrap(value(s).other - l.tangent(x, l.end_of(s), false))
            }
            Condition::Inflection { after: false } => {
                let s = before.expect("a span");
                wrap(value(s).other - l.tangent(x, s, true))
            }
        }
    }

    /// The residual of every row.
    pub(super) fn residual(&self, x: &[f64], values: &[Value]) -> Vec<f64> {
        self.layout
            .rows
            .iter()
            .map(|&k| self.row(x, k, &|s| values[s]))
            .collect()
    }

    /// How far each row is from its condition: the relative curvature jump or miss, or the
    /// direction's miss in radians.
    pub(super) fn misses(&self, x: &[f64], values: &[Value]) -> Vec<f64> {
        let l = self.layout;
        l.rows
            .iter()
            .map(|&k| {
                let (before, after) = l.spans_at(k);
                let relative = |a: f64, b: f64| {
                    let big = a.abs().max(b.abs());
                    if big > 0.0 {
                        (a - b).abs() / big
                    } else {
                        (a - b).abs()
                    }
                };
                match l.nodes[k].condition.expect("a row") {
                    Condition::G2 => relative(
                        values[before.expect("a span")].kappa.1,
                        values[after.expect("a span")].kappa.0,
                    ),
                    Condition::Curvature { after: true, value } => {
                        relative(values[after.expect("a span")].kappa.0, value)
                    }
                    Condition::Curvature {
                        after: false,
                        value,
                    } => relative(values[before.expect("a span")].kappa.1, value),
                    Condition::Inflection { .. } => self.row(x, k, &|s| values[s]).abs(),
                }
            })
            .collect()
    }

    /// The Jacobian's entries (row, unknown, value) by forward differences: each unknown
    /// moves the spans at its node, which move the rows at that node and its neighbours.
    /// Only the columns of the unknowns `on`.
    fn jacobian(&self, x: &mut [f64], values: &[Value], on: &[bool]) -> Option<Entries> {
        let l = self.layout;
        let m = l.owner.len();
        if l.rows.len() != m {
            return None;
        }
        let mut row_of = vec![usize::MAX; l.nodes.len()];
        for (r, &k) in l.rows.iter().enumerate() {
            row_of[k] = r;
        }
        let nodes = l.nodes.len();
        let base = self.residual(x, values);
        let mut entries: Vec<(usize, usize, f64)> = Vec::with_capacity(3 * m);
        self.loose.set(true);
        for v in (0..m).filter(|&v| on[v]) {
            let node = l.owner[v];
            let (before, after) = l.spans_at(node);
            let saved = x[v];
            x[v] += H;
            let moved: Vec<(usize, Option<Value>)> = [before, after]
                .into_iter()
                .flatten()
                .map(|s| (s, self.span(x, s).ok()))
                .collect();
            let value = |s: usize| {
                moved
                    .iter()
                    .find(|(m, _)| *m == s)
                    .map_or(values[s], |(_, v)| v.unwrap_or(values[s]))
            };
            let near = [(node + nodes - 1) % nodes, node, (node + 1) % nodes];
            for (i, &k) in near.iter().enumerate() {
                if near[..i].contains(&k) || row_of[k] == usize::MAX {
                    continue;
                }
                if !l.closed && ((i == 0 && node == 0) || (i == 2 && node + 1 == nodes)) {
                    continue;
                }
                // The curvature rows by each span's end-curvature differences (their own
                // rounding, not that of the residual's), the others by the residual's.
                let dk = |s: usize, end: usize| {
                    let (now, moved) = (values[s].kappa, value(s).kappa);
                    if end == 0 {
                        (moved.0 - now.0) / H
                    } else {
                        (moved.1 - now.1) / H
                    }
                };
                let (b, a) = l.spans_at(k);
                let w = l.nodes[k].weight;
                let d = match l.nodes[k].condition.expect("a row") {
                    Condition::G2 => (dk(b.expect("a span"), 1) - dk(a.expect("a span"), 0)) * w,
                    Condition::Curvature { after: true, .. } => dk(a.expect("a span"), 0) * w,
                    Condition::Curvature { after: false, .. } => dk(b.expect("a span"), 1) * w,
                    Condition::Inflection { .. } => (self.row(x, k, &value) - base[row_of[k]]) / H,
                };
                if d != 0.0 && d.is_finite() {
                    entries.push((row_of[k], v, d));
                }
            }
            x[v] = saved;
        }
        self.loose.set(false);
        Some(entries)
    }

    /// The Newton step of Jacobian `entries` for the right-hand side `rhs`, in the rows and
    /// unknowns `on` (the others' steps zero; they must be a whole number of parts), solved
    /// tridiagonally when it is, densely otherwise.
    fn step(
        &self,
        entries: &Entries,
        rhs: &[f64],
        (rows_on, on): (&[bool], &[bool]),
    ) -> Option<Vec<f64>> {
        let l = self.layout;
        let m = l.owner.len();
        if on.iter().any(|o| !o) {
            // Each row's or unknown's place among those on.
            let index = |on: &[bool]| {
                let mut next = 0;
                on.iter()
                    .map(|&o| {
                        let place = o.then_some(next);
                        next += usize::from(o);
                        place
                    })
                    .collect::<Vec<_>>()
            };
            let (rows, cols) = (index(rows_on), index(on));
            let n = cols.iter().flatten().count();
            if rows.iter().flatten().count() != n {
                return None;
            }
            let mut a = vec![0.0; n * n];
            for &(r, c, d) in entries {
                if let (Some(r), Some(c)) = (rows[r], cols[c]) {
                    a[r * n + c] += d;
                }
            }
            let b = rhs
                .iter()
                .zip(rows_on)
                .filter(|(_, o)| **o)
                .map(|(b, _)| *b)
                .collect();
            let dx = banded::dense(a, b)?;
            return Some(cols.iter().map(|c| c.map_or(0.0, |c| dx[c])).collect());
        }
        if l.is_tridiagonal() {
            let (mut sub, mut diag, mut sup) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
            let mut banded_ok = true;
            for &(r, c, d) in entries {
                if c == r {
                    diag[r] += d;
                } else if c + 1 == r || (r == 0 && c + 1 == m) {
                    sub[r] += d;
                } else if c == r + 1 || (r + 1 == m && c == 0) {
                    sup[r] += d;
                } else {
                    banded_ok = false;
                }
            }
            if banded_ok {
                return banded::solve(&sub, &diag, &sup, rhs, l.closed);
            }
        }
        let mut a = vec![0.0; m * m];
        for &(r, c, d) in entries {
            a[r * m + c] += d;
        }
        banded::dense(a, rhs.to_vec())
    }

    /// Newton's method (damped) from `x` on the residual minus `offset`: the unknowns and
    /// the rows' misses reached (with `offset` zero), or the span that fails at the start.
    pub(super) fn newton(&self, mut x: Vec<f64>, offset: &[f64]) -> Result<(Vec<f64>, Vec<f64>)> {
        let exact = offset.iter().all(|o| *o == 0.0);
        let eval = |x: &[f64]| -> Result<(Vec<Value>, Vec<f64>)> {
            let values = self.spans(x)?;
            let r = self
                .residual(x, &values)
                .iter()
                .zip(offset)
                .map(|(r, o)| r - o)
                .collect();
            Ok((values, r))
        };
        let norm = |r: &[f64]| r.iter().map(|x| x * x).sum::<f64>().sqrt();
        let (mut values, mut r) = eval(&x)?;
        // A Jacobian is kept while the steps it gives shrink the residual a hundredfold (the
        // point conditions' dense systems: each Jacobian costs two span solves an unknown,
        // a step one; a Jacobian kept through slower steps costs more steps than it saves);
        // the smooth spline's is made afresh at every step, as it always was.
        let keep = !self.layout.is_tridiagonal();
        let mut jacobian: Option<Entries> = self.start.take();
        // An earlier answer's Jacobian: its columns at the spans that moved made afresh.
        if let Some(j) = &mut jacobian {
            let moved = self.moved.borrow();
            let l = self.layout;
            let mut on = vec![false; l.owner.len()];
            for &s in moved.iter() {
                for (v, &node) in l.owner.iter().enumerate() {
                    on[v] |= node == s || node == l.end_of(s);
                }
            }
            drop(moved);
            if on.contains(&true) && on.contains(&false) {
                if let Some(fresh) = self.jacobian(&mut x, &values, &on) {
                    j.retain(|e| !on[e.1]);
                    j.extend(fresh);
                }
            }
        }
        // The latest Jacobian with every column: a fresh one need only make the columns of
        // the parts that move.
        let mut whole = jacobian.clone();
        let (row_part, unknown_part) = self.layout.parts();
        for _ in 0..MAX_STEPS {
            // With the exact conditions, a part whose rows all hold is done: its unknowns
            // stay, so its spans are not solved again (a warm re-solve moves a part or two).
            let misses = exact.then(|| self.misses(&x, &values));
            let (rows_on, on) = match &misses {
                Some(misses) => {
                    let mut part_on = vec![false; row_part.len() + unknown_part.len()];
                    for (m, &p) in misses.iter().zip(&row_part) {
                        part_on[p] |= *m > G2_TOLERANCE || m.is_nan();
                    }
                    let on = |parts: &[usize]| parts.iter().map(|&p| part_on[p]).collect();
                    (on(&row_part), on(&unknown_part))
                }
                None => (vec![true; row_part.len()], vec![true; unknown_part.len()]),
            };
            let done = match &misses {
                Some(_) => !rows_on.contains(&true),
                None => norm(&r) <= 1e-9,
            };
            if done {
                break;
            }
            let fresh = jacobian.is_none();
            let entries = match jacobian.take() {
                Some(j) => j,
                None => {
                    let partial = whole.is_some() && on.contains(&false);
                    let columns = if partial {
                        on.clone()
                    } else {
                        vec![true; on.len()]
                    };
                    let Some(mut j) = self.jacobian(&mut x, &values, &columns) else {
                        break;
                    };
                    if let (true, Some(w)) = (partial, &whole) {
                        j.extend(w.iter().filter(|e| !on[e.1]));
                    }
                    whole = Some(j.clone());
                    j
                }
            };
            let rhs: Vec<f64> = r.iter().map(|x| -x).collect();
            let Some(dx) = self.step(&entries, &rhs, (&rows_on, &on)) else {
                if fresh {
                    break;
                }
                continue;
            };
            let big = dx.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let mut lambda = if big > MAX_STEP { MAX_STEP / big } else { 1.0 };
            let now = norm(&r);
            let mut next = None;
            // At the residual's rounding (1e-14 here), a step that does not lower it is
            // rounding too: two halvings, not thirty full evaluations.
            let tries = if now <= RESIDUAL_FLOOR { 2 } else { 30 };
            for _ in 0..tries {
                let trial: Vec<f64> = x.iter().zip(&dx).map(|(x, d)| x + lambda * d).collect();
                if let Ok((v2, r2)) = eval(&trial) {
                    if norm(&r2) < now * (1.0 - 1e-4 * lambda) {
                        next = Some((trial, v2, r2));
                        break;
                    }
                }
                lambda *= 0.5;
            }
            let Some((x2, v2, r2)) = next else {
                if fresh {
                    break;
                }
                // A kept Jacobian that no longer leads: make it afresh.
                continue;
            };
            if keep {
                *self.last.borrow_mut() = Some(entries.clone());
            }
            let (n2, rate) = (norm(&r2), norm(&r2) / now);
            if keep && lambda == 1.0 && (rate < KEEP_WHILE || n2 * rate < NEXT) {
                jacobian = Some(entries);
            }
            (x, values, r) = (x2, v2, r2);
        }
        self.reach(&x, &values);
        let misses = self.misses(&x, &values);
        Ok((x, misses))
    }
}

/// The given point a node stands for, or for a knot the point of its span whose condition
/// it pays for (its start when both).
pub(super) fn point_of(layout: &Layout, k: usize) -> usize {
    match layout.nodes[k].at {
        At::Point(i) => i,
        At::Knot(span, _) => {
            let next = layout.end_of(k);
            match layout.nodes[next].at {
                At::Point(j)
                    if matches!(
                        layout.nodes[next].condition,
                        Some(Condition::Inflection { .. } | Condition::Curvature { .. })
                    ) =>
                {
                    j
                }
                _ => span,
            }
        }
    }
}

/// The shape of a curve span from `a` to `b` whose start tangent has direction `phi_a` and
/// whose end tangents make the angles `ta`, `tb` with its chord, at slope `alpha` (`unit`
/// the unit curve through the inflection, for α < 0), and its signed end curvatures, or why
/// it has none (`span` names it). Its searches start from `memo`, which it updates; a plain
/// segment's solution goes to `made`.
pub(super) fn curve(
    alpha: f64,
    unit: Option<&Unit>,
    a: Point,
    b: Point,
    [phi_a, ta, tb]: [f64; 3],
    span: usize,
    (memo, made, loose): (&mut Memo, &mut Option<SegmentSolution>, bool),
) -> Result<(Shape, (f64, f64))> {
    let c = length(b - a);
    let hint = memo.s;
    let s_span = || unit.and_then(|u| u.s_span_near(ta, tb, c, (hint, loose)));
    let s_found = |memo: &mut Memo, s: SSpan| {
        memo.s = Some(s.hint());
        Ok((Shape::S(s), s.end_curvatures()))
    };
    // One segment turns one way: its tangents leave and reach the chord from opposite
    // sides, and turn by less than π.
    if ta * tb < 0.0 && ta.abs() + tb.abs() < PI {
        let u = c * tb.abs().sin() / (ta.abs() + tb.abs()).sin();
        let t = [a, a + Vec2::from_angle(phi_a) * u, b];
        let solved = SegmentSolution::near(t, alpha, (memo.mu, loose))
            .and_then(|s| Ok((s.end_curvatures()?, s)));
        return match solved {
            Ok((k, s)) => {
                memo.mu = Some(s.mu());
                *made = Some(s);
                Ok((Shape::Plain(t), k))
            }
            Err(e) => match s_span() {
                Some(s) => s_found(memo, s),
                None => Err(Error::SplineSpan {
                    span,
                    // Points near 1e308 can put the tangents' meeting point beyond double
                    // range: say so, not that an input was infinite.
                    source: Box::new(if t[1].x.is_finite() && t[1].y.is_finite() {
                        e
                    } else {
                        Error::Unrepresentable {
                            what: "control triangle of a span (where its end tangents meet)",
                        }
                    }),
                }),
            },
        };
    }
    match s_span() {
        Some(s) => s_found(memo, s),
        None => Err(Error::NoG2Spline {
            span,
            reason: G2Failure::SpanInflects,
        }),
    }
}

/// The segments of a span's shape from `a` to `b` (none for a line), each half of an S
/// stopping a share `hair` of its length short of the inflection.
pub(super) fn segments_of(
    shape: &Shape,
    a: Point,
    b: Point,
    alpha: f64,
    hair: f64,
) -> Result<Vec<Segment>> {
    match shape {
        Shape::Plain(t) => Ok(vec![Segment::from_control_points(*t, alpha)?]),
        Shape::S(s) => s.turning_segments(a, b, hair, alpha),
        Shape::Line => Ok(Vec::new()),
    }
}

/// An earlier answer to start from: its unknowns, where its knots were (their share, and
/// whether the tangent points' knots were in the spans before them) and its last Jacobian.
pub(super) struct Warm<'a> {
    pub(super) unknowns: &'a [f64],
    pub(super) share: f64,
    pub(super) before: bool,
    pub(super) jacobian: &'a Entries,
    pub(super) memo: &'a [Memo],
    pub(super) points: &'a [Point],
    /// Its spans (empty unless at the same slope).
    pub(super) reached: &'a [Reached],
}

/// An earlier answer's unknowns `x` (for the points `old`) made a start for `points`: a free
/// tangent at a point turns by the mean of the turns of the chords on either side of it, so
/// that the spans next to a moved point keep their shapes to first order. (The knots'
/// unknowns are placed in their spans' own frames, which move with the points already.)
fn turn_with_chords(layout: &Layout, points: &[Point], old: &[Point], x: &mut [f64]) {
    let n = points.len();
    if old.len() != n {
        return;
    }
    let turn = |s: usize| {
        let (a, b) = (s % n, (s + 1) % n);
        wrap(dir(points[b] - points[a]) - dir(old[b] - old[a]))
    };
    let spans = if layout.closed { n } else { n - 1 };
    for (v, &node) in layout.owner.iter().enumerate() {
        let At::Point(i) = layout.nodes[node].at else {
            continue;
        };
        if !layout.nodes[node].tangent.contains(&Tangent::Free(v)) {
            continue;
        }
        let before = (i > 0 || layout.closed).then(|| turn(i + n - 1));
        let after = (i < spans).then(|| turn(i));
        let sides: Vec<f64> = [before, after].into_iter().flatten().collect();
        if !sides.is_empty() {
            x[v] += sides.iter().sum::<f64>() / sides.len() as f64;
        }
    }
}

/// The answer of one problem: the unknowns and the rows' misses.
type Answer = (Vec<f64>, Vec<f64>);

/// A solved problem: its layout, its unknowns, the last Jacobian of the point conditions'
/// Newton's method (the warm start of a re-solve), if it made one, and its spans' memos.
pub(super) type Solved = (Layout, Vec<f64>, Option<Entries>, Vec<Memo>, Vec<Reached>);

/// Solve the relaxed problem, then (when the plan asks more) the full one from it, or from
/// `warm` (an earlier answer's unknowns for the same plan, and its knots' share). `accept` builds and checks a
/// smooth spline's answer found at α directly (α < 0), which the continuation in α replaces
/// when it does not pass.
pub(super) fn solve(
    points: &[Point],
    closed: bool,
    alpha: f64,
    plan: &Plan,
    warm: Option<Warm<'_>>,
    accept: &mut dyn FnMut(&Layout, &[f64]) -> bool,
) -> Result<Solved> {
    let relaxed = Layout::relaxed(points, closed, plan);
    if let Some(Warm {
        unknowns: w,
        share,
        before,
        jacobian,
        memo,
        points: old,
        reached,
    }) = warm
    {
        let placed = if before {
            plan.tangent_knots_before()
        } else {
            None
        };
        let warm_plan = Plan {
            knot_share: share,
            ..placed.unwrap_or_else(|| plan.clone())
        };
        let start = if plan.is_relaxed() {
            (w.len() == relaxed.owner.len()).then(|| (relaxed.clone(), w.to_vec()))
        } else {
            Layout::full(points, closed, &warm_plan, |_| 0.0, |_| Ok((0.0, 0.0, 0.0)))
                .ok()
                .filter(|(l, _)| l.owner.len() == w.len())
                .map(|(l, _)| (l, w.to_vec()))
        };
        if let Some((layout, mut x)) = start {
            turn_with_chords(&layout, points, old, &mut x);
            let p = Problem::new(points, &layout, alpha);
            *p.start.borrow_mut() = (!jacobian.is_empty()).then(|| jacobian.clone());
            p.seed(memo);
            p.seed_spans(reached);
            if let Ok((x, misses)) = p.newton(x, &vec![0.0; layout.rows.len()]) {
                if converged(&misses) {
                    let (jacobian, memo) = (p.last.take(), p.memos());
                    let reached = p.reached();
                    return Ok((layout, x, jacobian, memo, reached));
                }
            }
        }
    }
    let x = if plan.is_relaxed() {
        solve_relaxed(points, &relaxed, alpha, &mut |x| accept(&relaxed, x))?
    } else {
        solve_relaxed(points, &relaxed, alpha, &mut |x| {
            super::build::builds(points, &relaxed, alpha, x)
        })?
    };
    if plan.is_relaxed() {
        return Ok((relaxed, x, None, Vec::new(), Vec::new()));
    }
    // The full problem from the relaxed answer, its knots' lines across their chords at
    // each of KNOT_SHARES in turn until one converges (the spline depends on where they
    // are: a knot is a freedom the conditions do not fix).
    let mut first = None;
    let before = plan.tangent_knots_before();
    // Each share with the tangent points' knots after them, then before them.
    let plans = KNOT_SHARES
        .iter()
        .flat_map(|&share| [Some((share, plan)), before.as_ref().map(|b| (share, b))])
        .flatten();
    for (share, plan) in plans {
        let plan = Plan {
            knot_share: share,
            ..plan.clone()
        };
        // (The homotopy at the first share only: a refusal costs each placement's Newton.)
        let homotopy = share == KNOT_SHARES[0];
        match full(points, closed, alpha, &plan, &relaxed, &x, homotopy) {
            Ok(answer) => return Ok(answer),
            Err(e) => {
                first.get_or_insert(e);
            }
        }
    }
    Err(first.expect("a share was tried"))
}

/// The full problem of `plan` from the relaxed answer `x`: Newton's method from it, and where
/// that does not converge (and `homotopy`) a homotopy that takes the relaxed answer's
/// residuals away step by step.
fn full(
    points: &[Point],
    closed: bool,
    alpha: f64,
    plan: &Plan,
    relaxed: &Layout,
    x: &[f64],
    homotopy: bool,
) -> Result<Solved> {
    // The knots where the relaxed spline's spans cross the lines of their frames; every
    // unknown point tangent from the relaxed answer.
    let p = Problem::new(points, relaxed, alpha);
    let values = p.spans(x)?;
    let n = points.len();
    let tangent = |i: usize| relaxed.tangent(x, i, true);
    let knot_at = |s: usize| -> Result<(f64, f64, f64)> {
        let (a, b) = (points[s], points[(s + 1) % n]);
        let segments = segments_of(&values[s].shape, a, b, alpha, super::super::s_span::HAIR)
            .map_err(|e| Error::SplineSpan {
                span: s,
                source: Box::new(e),
            })?;
        let chain = Chain(&segments);
        let (mid, along, across) = plan.knot_frame(points, s);
        let side = |s: f64| chain.point_at_s(s).map(|p| (p - mid).dot(along));
        let (mut lo, mut hi) = (0.0, chain.arc_length());
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if side(m)? < 0.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        let s = 0.5 * (lo + hi);
        let k = chain.point_at_s(s)?;
        let q = along.hypot2();
        Ok((
            (k - mid).dot(along) / q,
            (k - mid).dot(across) / q,
            chain.theta_at_s(s)?,
        ))
    };
    let (layout, x0) = Layout::full(points, closed, plan, tangent, knot_at)?;
    let p = Problem::new(points, &layout, alpha);
    let zero = vec![0.0; layout.rows.len()];
    let mut best: Option<Answer> = None;
    if let Ok(answer) = p.newton(x0.clone(), &zero) {
        if converged(&answer.1) {
            let (jacobian, memo, reached) = (p.last.take(), p.memos(), p.reached());
            return Ok((layout, answer.0, jacobian, memo, reached));
        }
        best = Some(answer);
    }
    // The homotopy: the relaxed answer's residuals taken away step by step.
    let r0 = p.residual(&x0, &p.spans(&x0)?);
    let mut x = x0;
    for t in HOMOTOPY.into_iter().filter(|_| homotopy) {
        let offset: Vec<f64> = r0.iter().map(|r| (1.0 - t) * r).collect();
        match p.newton(x.clone(), if t == 1.0 { &zero } else { &offset }) {
            Ok((x2, misses)) => {
                x = x2;
                if t == 1.0 {
                    if converged(&misses) {
                        let (jacobian, memo, reached) = (p.last.take(), p.memos(), p.reached());
                        return Ok((layout, x, jacobian, memo, reached));
                    }
                    if best
                        .as_ref()
                        .is_none_or(|b| worst(&misses).1 < worst(&b.1).1)
                    {
                        best = Some((x.clone(), misses));
                    }
                }
            }
            Err(_) => break,
        }
    }
    let (worst_row, miss) = best.as_ref().map_or((0, f64::NAN), |b| worst(&b.1));
    let k = layout.rows[worst_row];
    Err(Error::SplinePoint {
        point: point_of(&layout, k),
        reason: PointFailure::Unmet {
            what: layout.nodes[k].condition.expect("a row").what(),
            miss,
        },
    })
}

/// Whether every row's miss is within half the G2 limit.
fn converged(misses: &[f64]) -> bool {
    misses.iter().all(|m| *m <= 0.5 * G2_JUMP_LIMIT)
}

/// The row with the largest miss (NaN the largest), and its miss.
fn worst(misses: &[f64]) -> (usize, f64) {
    misses
        .iter()
        .enumerate()
        .fold((0, 0.0f64), |(i, m), (j, x)| {
            if x.abs() > m || x.is_nan() {
                (j, x.abs())
            } else {
                (i, m)
            }
        })
}

/// The smooth spline between the given tangents: Newton's method from the circles'
/// tangents at α itself (α < 0, where every pair of end tangents has a segment or an S), or
/// by continuation in α from the nearest of [0, 1].
fn solve_relaxed(
    points: &[Point],
    layout: &Layout,
    alpha: f64,
    accept: &mut dyn FnMut(&[f64]) -> bool,
) -> Result<Vec<f64>> {
    let n = points.len();
    let at = |i: usize| points[i % n];
    // The tangent at B of the circle through A, B, C is dir AB + dir BC − dir AC.
    let circle = |a: Point, b: Point, c: Point| {
        dir(b - a) + wrap(dir(c - b) - dir(b - a)) - wrap(dir(c - a) - dir(b - a))
    };
    let phi: Vec<f64> = layout
        .owner
        .iter()
        .map(|&k| match layout.nodes[k].at {
            At::Point(i) => circle(at(i + n - 1), at(i), at(i + 1)),
            At::Knot(..) => 0.0,
        })
        .collect();
    let zero = vec![0.0; layout.rows.len()];
    let p = |a: f64| Problem::new(points, layout, a);
    let fail = |misses: &[f64]| {
        let (w, jump) = worst(misses);
        let k = layout.rows.get(w).copied().unwrap_or(0);
        Error::NoG2Spline {
            span: point_of(layout, k),
            reason: G2Failure::NoConvergence { jump },
        }
    };
    if alpha < 0.0 {
        if let Ok((p2, r)) = p(alpha).newton(phi.clone(), &zero) {
            if converged(&r) && accept(&p2) {
                return Ok(p2);
            }
        }
    }
    // Continuation in α from the nearest of [0, 1] (where the circles' tangents are
    // drawable for any sensible points), each stage warm-started from the last; steps of
    // 0.25 in α, at most MAX_STAGES of them.
    let start = alpha.clamp(0.0, 1.0);
    let stages = ((alpha - start).abs() / 0.25).ceil().clamp(0.0, MAX_STAGES) as usize;
    let mut last: Result<Answer> = Err(Error::NumericalFailure {
        what: "the spline's continuation in alpha",
    });
    let mut phi = phi;
    for stage in 0..=stages {
        let a = if stage == stages {
            alpha
        } else {
            start + (alpha - start) * stage as f64 / stages.max(1) as f64
        };
        last = p(a).newton(phi.clone(), &zero);
        match &last {
            Ok((p2, _)) => phi = p2.clone(),
            Err(_) if stage == 0 && stages > 0 => {
                // The circles' tangents do not solve at α in [0, 1]: try α directly.
                last = p(alpha).newton(phi.clone(), &zero);
                break;
            }
            Err(_) => break,
        }
    }
    let (phi, misses) = last?;
    if !converged(&misses) {
        return Err(fail(&misses));
    }
    Ok(phi)
}
