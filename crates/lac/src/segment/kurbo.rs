//! kurbo's curve traits for [`Segment`], with the parameter t ∈ [0, 1] proportional to arc
//! length (t = s / arc_length).
//!
//! The traits cannot return errors, so their domain is stated instead: t is clamped to
//! [0, 1] (kurbo's curves extrapolate; a log-aesthetic segment may end at a singular point,
//! so it does not), and a NaN t gives NaN. Curvature follows kurbo's sign
//! (`d″ × d′ / |d′|³`, negative for a left turn); [`Curve::signed_curvature_at_s`](crate::Curve)
//! is docs/math.md's signed curvature, positive for a left turn.

use std::ops::Range;

use kurbo::{ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, Point, Vec2};

use super::Segment;
use crate::family::standard_form::Station;

/// A point whose every coordinate is NaN: what a trait method that cannot fail returns
/// when it has no answer.
const NAN_POINT: Point = Point::new(f64::NAN, f64::NAN);

impl Segment {
    /// The arc length at parameter `t` (clamped to [0, 1]; NaN stays NaN).
    fn s_of_t(&self, t: f64) -> f64 {
        t.clamp(0.0, 1.0) * self.length()
    }

    /// The station at parameter `t`, or `None` when t is NaN or the station cannot be
    /// computed.
    fn station_of_t(&self, t: f64) -> Option<Station> {
        if t.is_nan() {
            return None;
        }
        self.station_at_s(self.s_of_t(t)).ok()
    }

    /// The `order`-th derivative (1 to 6) of the position with respect to a parameter u
    /// with ds/du = `speed`, at arc length `s` of this segment.
    pub(crate) fn derivative_at_s(&self, s: f64, order: u32, speed: f64) -> Option<Vec2> {
        if !(1..=6).contains(&order) || s.is_nan() {
            return None;
        }
        let st = self.station_at_s(s).ok()?;
        let jet = self.jet(&st);
        // d/du = (speed · dir / scale) d/ds_std on the standard form, then the similarity.
        let k = (speed * self.dir() / self.scale()).powi(order as i32);
        let z = (self.rot * jet[order as usize - 1]).scale(k);
        let z = if self.mirrored { z.conj() } else { z };
        Some(Vec2::new(z.re, z.im))
    }

    /// The piece between arc lengths `a` and `b` of this segment, traversed from `a` to `b`
    /// (`travel` says which way when a = b, for an empty piece).
    pub(crate) fn between(&self, a: f64, b: f64, travel: Travel) -> Segment {
        // A station that cannot be computed makes the piece NaN: the trait cannot say so
        // otherwise, and a NaN curve cannot be mistaken for a good one.
        let nan = Station {
            theta: f64::NAN,
            s: f64::NAN,
            ln_rho: f64::NAN,
        };
        let station = |s: f64| self.station_at_s(s).unwrap_or(nan);
        let (sa, sb) = (station(a), station(b));
        let offset_a = self.offset_of(&sa);
        let chord = self.offset_of(&sb) - offset_a;
        let forward = match travel {
            Travel::Forward => true,
            Travel::Backward => false,
        };
        let mut placement = self.placement();
        placement.origin = self.caller_point(offset_a);
        placement.theta_first = self.theta_of(&sa);
        if !forward {
            placement.theta_first += std::f64::consts::PI;
            placement.turn = placement.turn.reversed();
        }
        Segment::new(self.alpha, self.form, [sa, sb], chord, placement)
    }
}

/// The direction in which a piece cut from a segment is traversed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Travel {
    /// In the segment's own direction.
    Forward,
    /// From its last point toward its first.
    Backward,
}

impl Travel {
    /// The direction from arc length `a` to `b` (forward when they are equal).
    pub(crate) fn of(a: f64, b: f64) -> Travel {
        if b >= a {
            Travel::Forward
        } else {
            Travel::Backward
        }
    }
}

impl ParamCurve for Segment {
    /// The point at arc length t · arc_length (t clamped to [0, 1]; NaN for a NaN t).
    fn eval(&self, t: f64) -> Point {
        match self.station_of_t(t) {
            Some(st) => self.point_of(&st),
            None => NAN_POINT,
        }
    }

    /// The piece between parameters `range.start` and `range.end` (reversed if
    /// `range.start > range.end`), itself a log-aesthetic segment.
    fn subsegment(&self, range: Range<f64>) -> Segment {
        let (a, b) = (self.s_of_t(range.start), self.s_of_t(range.end));
        self.between(a, b, Travel::of(a, b))
    }

    fn start(&self) -> Point {
        self.first_point()
    }

    fn end(&self) -> Point {
        self.last_point()
    }
}

impl ParamCurveArclen for Segment {
    /// Exact: the arc length is known in closed form.
    fn arclen(&self, _accuracy: f64) -> f64 {
        self.length()
    }

    /// Exact: t = arclen / arc_length, clamped to [0, 1].
    fn inv_arclen(&self, arclen: f64, _accuracy: f64) -> f64 {
        let len = self.length();
        if len > 0.0 {
            (arclen / len).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

/// The `order`-th derivative of a [`Segment`] with respect to t = s / arc_length, as a
/// curve (kurbo's convention: the vector is returned as a `Point`).
///
/// Orders 1 to 6 are exact (algebraic in κ and its derivatives); higher orders, which
/// nothing in kurbo uses, are central differences of the order below. t is clamped to
/// [0, 1]; NaN in gives NaN out.
#[derive(Clone, Debug)]
pub struct SegmentDerivative {
    segment: Segment,
    order: u32,
}

impl ParamCurveDeriv for Segment {
    type DerivResult = SegmentDerivative;

    fn deriv(&self) -> SegmentDerivative {
        SegmentDerivative {
            segment: self.clone(),
            order: 1,
        }
    }
}

impl ParamCurveDeriv for SegmentDerivative {
    type DerivResult = SegmentDerivative;

    fn deriv(&self) -> SegmentDerivative {
        SegmentDerivative {
            segment: self.segment.clone(),
            order: self.order.saturating_add(1),
        }
    }
}

impl ParamCurve for SegmentDerivative {
    fn eval(&self, t: f64) -> Point {
        let seg = &self.segment;
        if self.order > 6 {
            let lower = SegmentDerivative {
                segment: seg.clone(),
                order: self.order - 1,
            };
            return central_difference(t, |t| lower.eval(t));
        }
        seg.derivative_at_s(seg.s_of_t(t), self.order, seg.length())
            .map_or(NAN_POINT, Vec2::to_point)
    }

    fn subsegment(&self, range: Range<f64>) -> SegmentDerivative {
        // d/dt' = (t1 − t0) d/dt on the sub-range.
        SegmentDerivative {
            segment: self.segment.subsegment(range),
            order: self.order,
        }
    }
}

/// The derivative of `f` at `t` ∈ [0, 1] by a central difference (one-sided at the ends).
pub(crate) fn central_difference(t: f64, f: impl Fn(f64) -> Point) -> Point {
    let h = 1e-4;
    let (t0, t1) = ((t - h).max(0.0), (t + h).min(1.0));
    ((f(t1) - f(t0)) / (t1 - t0)).to_point()
}

impl ParamCurveCurvature for Segment {
    /// Exact curvature with kurbo's sign: negative for a left turn (the opposite of
    /// [`Curve::signed_curvature_at_s`](crate::Curve::signed_curvature_at_s)). NaN for a NaN t.
    fn curvature(&self, t: f64) -> f64 {
        match self.station_of_t(t) {
            Some(st) => -self.kappa_of(&st),
            None => f64::NAN,
        }
    }
}
