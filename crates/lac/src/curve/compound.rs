//! Compound-rhythm curves: two log-aesthetic pieces joined with G3 continuity (docs/math.md §4,
//! seeds 004 and 002).

use std::ops::Range;

use kurbo::{ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, Point, Vec2};

use crate::curve::chain::{locate, SegmentChain};
use crate::curve::{check_total_length, Curve};
use crate::family::chord_angle::ChordAngle;
use crate::family::lcg::LcgLine;
use crate::foundation::error::{finite, Error, NotDrawable, Result};
use crate::foundation::numeric::Complex;
use crate::foundation::turn::Turn;
use crate::segment::{
    check_alpha, control_triangle, finite_length, normalized, Placement, Segment, Travel,
};

/// A compound-rhythm log-aesthetic curve: a piece of slope α0 from the first control point
/// to the joint, then a piece of slope α1 to the last control point, with position,
/// tangent, curvature and dκ/ds continuous at the joint (G3), so that the logarithmic
/// curvature graph is one continuous two-piece polyline (Harada's "valley" and "mountain"
/// types; seed 004 eq. 3.5: Λ1 = Λ0 ρc^(α1−α0)).
///
/// Both pieces are drawn in one standard form with the reference point (ρ = 1) at the
/// joint, where both have dρ/ds = Λ: piece 0 is θ ∈ [−θ0, 0] of LAC(α0, Λ) and piece 1 is
/// θ ∈ [0, θ1] of LAC(α1, Λ). Curvature is monotone along the whole curve.
///
/// Two inputs: three control points with the share `ratio` = θ0/(θ0 + θ1) of the turning
/// made by the α0 piece (seed 004), or four control points whose middle leg gives the
/// joint's tangent direction (seed 002; the total turning may then reach π or more).
///
/// ```
/// use kurbo::Point;
/// use lac::{CompoundCurve, Curve, SegmentChain};
///
/// // A "valley": clothoid-like α0 = −1 into a circle-involute-like α1 = 2.
/// let curve = CompoundCurve::from_three_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.6, 0.9)],
///     -1.0, 2.0, 0.5,
/// )?;
/// let joint = curve.joint_s();
/// assert!(joint > 0.0 && joint < curve.arc_length());
/// // Curvature is continuous at the joint.
/// let (a, b) = (curve.pieces()[0].signed_curvature_end(), curve.pieces()[1].signed_curvature_start());
/// assert!((a - b).abs() < 1e-12 * a.abs());
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct CompoundCurve {
    pieces: [Segment; 2],
}

/// The shortest piece a compound curve may have, as a share of its arc length. Shorter
/// pieces (seen where α0 > 1 meets α1 < 0 and the control points demand a curvature ratio
/// of e^40 or more) turn by their share of the polygon's turning within less than a
/// trillionth of the curve (see [`HIDDEN_SHARE`](crate::HIDDEN_SHARE)): no sampled or
/// exported form of the curve could show it, and its end tangent would not be the one its
/// points suggest.
pub const MIN_PIECE_SHARE: f64 = crate::segment::visible::HIDDEN_SHARE;

/// The caller's problem, in the caller's order.
struct Input {
    start: Point,
    end: Point,
    theta_first: f64,
    turn: Turn,
    alpha: [f64; 2],
    theta: [f64; 2],
    theta_e: f64,
}

impl CompoundCurve {
    /// The compound curve for control points `[a0, a1, a2]` (ends and the intersection of
    /// the end tangents), slopes `alpha0` (from `a0`) and `alpha1`, and `ratio` ∈ (0, 1):
    /// the share of the total turning made by the α0 piece.
    pub fn from_three_points(
        points: [Point; 3],
        alpha0: f64,
        alpha1: f64,
        ratio: f64,
    ) -> Result<Self> {
        check_alpha("alpha0", alpha0)?;
        check_alpha("alpha1", alpha1)?;
        finite("ratio", ratio)?;
        if !(ratio > 0.0 && ratio < 1.0) {
            return Err(Error::OutOfRange {
                name: "ratio",
                value: ratio,
                expected: "a share of the turning strictly between 0 and 1",
            });
        }
        let tri = control_triangle(points)?;
        let theta0 = ratio * tri.turning;
        Self::assemble(Input {
            start: points[0],
            end: points[2],
            theta_first: tri.theta_first,
            turn: tri.turn,
            alpha: [alpha0, alpha1],
            theta: [theta0, tri.turning - theta0],
            theta_e: tri.theta_e,
        })
    }

    /// The compound curve for control points `[P0, P1, P2, P3]`: it starts at P0 tangent
    /// to P1 − P0, ends at P3 tangent to P3 − P2, and its joint's tangent is parallel to
    /// P2 − P1 (seed 002). The polygon must turn one way only.
    pub fn from_four_points(points: [Point; 4], alpha0: f64, alpha1: f64) -> Result<Self> {
        check_alpha("alpha0", alpha0)?;
        check_alpha("alpha1", alpha1)?;
        const NAMES: [[&str; 2]; 4] = [
            ["P0.x", "P0.y"],
            ["P1.x", "P1.y"],
            ["P2.x", "P2.y"],
            ["P3.x", "P3.y"],
        ];
        for (p, names) in points.iter().zip(NAMES) {
            finite(names[0], p.x)?;
            finite(names[1], p.y)?;
        }
        for (i, j) in [(0, 1), (1, 2), (2, 3), (0, 3)] {
            if points[i] == points[j] {
                return Err(Error::CoincidentPoints {
                    first: i,
                    second: j,
                });
            }
        }
        let legs = [
            points[1] - points[0],
            points[2] - points[1],
            points[3] - points[2],
        ];
        let chord = points[3] - points[0];
        if !legs.into_iter().chain([chord]).all(finite_length) {
            return Err(Error::OutOfRange {
                name: "control points",
                value: f64::INFINITY,
                expected: "coordinates whose differences do not overflow",
            });
        }
        // Angles only: legs and chord each scaled (exactly) to a magnitude near 1 (one scale
        // for all would leave the products of legs 1e-160 of the chord subnormal).
        let [l0, l1, l2, chord] = [legs[0], legs[1], legs[2], chord].map(normalized);
        let legs = [l0, l1, l2];
        let turn = |a: Vec2, b: Vec2| a.cross(b).atan2(a.dot(b));
        let (t0, t1) = (turn(legs[0], legs[1]), turn(legs[1], legs[2]));
        let pi = std::f64::consts::PI;
        if [t0, t1]
            .iter()
            .any(|t| !(t.abs() > 1e-13 && t.abs() < pi - 1e-13))
        {
            return Err(Error::CollinearPoints);
        }
        let side = |t: f64| if t > 0.0 { Turn::Left } else { Turn::Right };
        let direction = side(t0);
        if direction != side(t1) {
            return Err(Error::InflectedPolygon {
                first: direction,
                second: side(t1),
            });
        }
        let sign = direction.sign();
        let theta_e = (sign * turn(legs[0], chord)).rem_euclid(std::f64::consts::TAU);
        let turning = t0.abs() + t1.abs();
        if !(theta_e > 0.0 && theta_e < turning) {
            return Err(Error::NotDrawable(NotDrawable::ChordOutsideTangents {
                theta_e,
                turning,
            }));
        }
        Self::assemble(Input {
            start: points[0],
            end: points[3],
            theta_first: legs[0].atan2(),
            turn: direction,
            alpha: [alpha0, alpha1],
            theta: [t0.abs(), t1.abs()],
            theta_e,
        })
    }

    /// Solve in the joint-reference standard form, running from the end with the smaller
    /// radius of curvature (docs/math.md §4: if θe < Θ/2 the ends swap, α0 ↔ α1, θ0 ↔ θ1), and map
    /// the pieces back in the caller's order.
    fn assemble(input: Input) -> Result<Self> {
        let total = input.theta[0] + input.theta[1];
        let reversed = input.theta_e < 0.5 * total;
        let (alpha, theta, theta_e) = if reversed {
            (
                [input.alpha[1], input.alpha[0]],
                [input.theta[1], input.theta[0]],
                total - input.theta_e,
            )
        } else {
            (input.alpha, input.theta, input.theta_e)
        };
        let parts = ChordAngle::new(alpha, theta, theta_e)
            .solve()
            .map_err(|e| match e {
                // Say it in the caller's terms: both slopes, and at which end the angle is.
                Error::NotDrawable(NotDrawable::ChordAngleTooLarge { theta_e, max, .. }) => {
                    Error::NotDrawable(NotDrawable::CompoundChordAngleTooLarge {
                        alpha0: input.alpha[0],
                        alpha1: input.alpha[1],
                        at_first: !reversed,
                        theta_e,
                        max,
                    })
                }
                other => other,
            })?
            .parts;
        // Caller-order pieces as (standard-form piece, traversed forward?).
        let order = if reversed {
            [(1, false), (0, false)]
        } else {
            [(0, true), (1, true)]
        };
        let chord = parts[0].chord + parts[1].chord;
        let chord = if reversed { -chord } else { chord };
        // The standard form turns left along increasing θ; traversed backwards it turns right.
        let mirrored = (input.turn == Turn::Left) == reversed;
        let c = input.end - input.start;
        let c = Complex::new(c.x, if mirrored { -c.y } else { c.y });
        let mut placement = Placement {
            origin: input.start,
            rot: c.div(chord),
            mirrored,
            turn: input.turn,
            theta_first: input.theta_first,
        };
        let pieces = [0, 1].map(|i| {
            let (k, forward) = order[i];
            let p = parts[k];
            let (ends, piece_chord) = if forward {
                ([p.start, p.end], p.chord)
            } else {
                ([p.end, p.start], -p.chord)
            };
            let seg = Segment::new(input.alpha[i], p.form, ends, piece_chord, placement);
            placement.origin = seg.caller_point(piece_chord);
            placement.theta_first += input.turn.sign() * input.theta[i];
            seg
        });
        for piece in &pieces {
            piece.check()?;
        }
        // A piece too short to draw in floating point is a hook that no sample shows: its
        // turning would happen below the rounding of the curve's own coordinates.
        let total = pieces[0].length() + pieces[1].length();
        for (i, piece) in pieces.iter().enumerate() {
            let share = piece.length() / total;
            if share < MIN_PIECE_SHARE {
                return Err(Error::NotDrawable(NotDrawable::PieceTooShort {
                    piece: i,
                    alpha: piece.alpha(),
                    share,
                    turning: piece.turning_angle(),
                }));
            }
        }
        crate::segment::visible::check_visible_ends(&pieces)?;
        let curve = CompoundCurve { pieces };
        check_total_length(&curve)?;
        Ok(curve)
    }

    /// The slopes [α0, α1].
    pub fn alpha(&self) -> [f64; 2] {
        [self.pieces[0].alpha(), self.pieces[1].alpha()]
    }

    /// Λ of the joint-reference standard form (dρ/ds at the joint, with ρ = 1 there).
    pub fn lambda(&self) -> f64 {
        self.pieces[0].lambda()
    }

    /// Arc length from the first control point to the joint.
    pub fn joint_s(&self) -> f64 {
        self.pieces[0].length()
    }

    /// The joint.
    pub fn joint(&self) -> Point {
        self.pieces[1].first_point()
    }

    /// Signed curvature at the joint.
    pub fn signed_curvature_joint(&self) -> f64 {
        self.pieces[1].end_curvatures().0
    }

    /// The logarithmic curvature graph of each piece (`None` for a circular arc); the two
    /// lines meet at the joint's log ρ.
    pub fn lcg(&self) -> [Option<LcgLine>; 2] {
        [self.pieces[0].lcg(), self.pieces[1].lcg()]
    }
}

impl SegmentChain for CompoundCurve {
    /// The two pieces in the caller's order: slope α0 from the first control point to the
    /// joint, slope α1 from the joint to the last control point.
    fn pieces(&self) -> &[Segment] {
        &self.pieces
    }
}

// kurbo's traits, with t ∈ [0, 1] proportional to arc length over the whole curve, t
// clamped to [0, 1] and NaN giving NaN, and kurbo's curvature sign (see `segment/kurbo.rs`).

impl CompoundCurve {
    /// The piece and its local arc length at parameter t, or `None` for a NaN t.
    fn at_t(&self, t: f64) -> Option<(&Segment, f64)> {
        if t.is_nan() {
            return None;
        }
        locate(&self.pieces, t.clamp(0.0, 1.0) * self.arc_length()).ok()
    }
}

impl ParamCurve for CompoundCurve {
    fn eval(&self, t: f64) -> Point {
        self.at_t(t)
            .and_then(|(piece, s)| piece.station_at_s(s).ok().map(|st| piece.point_of(&st)))
            .unwrap_or(Point::new(f64::NAN, f64::NAN))
    }

    /// The part between parameters `range.start` and `range.end` (reversed when
    /// `range.start > range.end`), as a compound curve whose pieces are the parts of the two
    /// pieces in the range. When the range lies within one piece, the other is an empty
    /// (zero-length) cut of that same piece at the range's end next to the joint, so the
    /// chain stays connected.
    fn subsegment(&self, range: Range<f64>) -> CompoundCurve {
        let len = self.arc_length();
        let joint = self.joint_s();
        let l1 = self.pieces[1].length();
        let s = |t: f64| t.clamp(0.0, 1.0) * len;
        let (a, b) = (s(range.start), s(range.end));
        let (lo, hi) = (a.min(b), a.max(b));
        // Forward parts as (piece, from, to) in the piece's own arc length.
        let in0 = |x: f64| x.min(joint);
        let in1 = |x: f64| crate::foundation::numeric::clamp(x - joint, 0.0, l1);
        let parts = if hi <= joint {
            [(0, lo, hi), (0, hi, hi)]
        } else if lo >= joint {
            [(1, in1(lo), in1(lo)), (1, in1(lo), in1(hi))]
        } else {
            [(0, in0(lo), joint), (1, 0.0, in1(hi))]
        };
        let cut = |(i, p, q): (usize, f64, f64), travel: Travel| {
            let piece: &Segment = &self.pieces[i];
            match travel {
                Travel::Forward => piece.between(p, q, travel),
                Travel::Backward => piece.between(q, p, travel),
            }
        };
        let pieces = match Travel::of(a, b) {
            Travel::Forward => [
                cut(parts[0], Travel::Forward),
                cut(parts[1], Travel::Forward),
            ],
            Travel::Backward => [
                cut(parts[1], Travel::Backward),
                cut(parts[0], Travel::Backward),
            ],
        };
        CompoundCurve { pieces }
    }

    fn start(&self) -> Point {
        self.start_point()
    }

    fn end(&self) -> Point {
        self.end_point()
    }
}

impl ParamCurveArclen for CompoundCurve {
    /// Exact: the arc length is known in closed form.
    fn arclen(&self, _accuracy: f64) -> f64 {
        self.arc_length()
    }

    /// Exact: t = arclen / arc_length, clamped to [0, 1].
    fn inv_arclen(&self, arclen: f64, _accuracy: f64) -> f64 {
        let len = self.arc_length();
        if len > 0.0 {
            (arclen / len).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

/// The `order`-th derivative of a [`CompoundCurve`] with respect to t = s / arc_length
/// (exact for orders 1 to 6, central differences above; see [`SegmentDerivative`]).
///
/// [`SegmentDerivative`]: crate::SegmentDerivative
#[derive(Clone, Debug)]
pub struct CompoundDerivative {
    curve: CompoundCurve,
    order: u32,
}

impl ParamCurveDeriv for CompoundCurve {
    type DerivResult = CompoundDerivative;

    fn deriv(&self) -> CompoundDerivative {
        CompoundDerivative {
            curve: self.clone(),
            order: 1,
        }
    }
}

impl ParamCurveDeriv for CompoundDerivative {
    type DerivResult = CompoundDerivative;

    fn deriv(&self) -> CompoundDerivative {
        CompoundDerivative {
            curve: self.curve.clone(),
            order: self.order.saturating_add(1),
        }
    }
}

impl ParamCurve for CompoundDerivative {
    fn eval(&self, t: f64) -> Point {
        if self.order > 6 {
            let lower = CompoundDerivative {
                curve: self.curve.clone(),
                order: self.order - 1,
            };
            return crate::segment::central_difference(t, |t| lower.eval(t));
        }
        let speed = self.curve.arc_length();
        self.curve
            .at_t(t)
            .and_then(|(piece, s)| piece.derivative_at_s(s, self.order, speed))
            .map_or(Point::new(f64::NAN, f64::NAN), Vec2::to_point)
    }

    fn subsegment(&self, range: Range<f64>) -> CompoundDerivative {
        CompoundDerivative {
            curve: self.curve.subsegment(range),
            order: self.order,
        }
    }
}

impl ParamCurveCurvature for CompoundCurve {
    /// Exact curvature with kurbo's sign: negative for a left turn (the opposite of
    /// [`Curve::signed_curvature_at_s`]). NaN for a NaN t.
    fn curvature(&self, t: f64) -> f64 {
        self.at_t(t)
            .and_then(|(piece, s)| piece.station_at_s(s).ok().map(|st| -piece.kappa_of(&st)))
            .unwrap_or(f64::NAN)
    }
}
