//! kurbo's curve traits for [`Segment`], with the parameter t ∈ [0, 1] proportional to arc
//! length (t = s / arc_length).

use std::ops::Range;

use kurbo::{ParamCurve, ParamCurveArclen, ParamCurveCurvature, ParamCurveDeriv, Point};

use crate::segment::Segment;

impl ParamCurve for Segment {
    fn eval(&self, t: f64) -> Point {
        let s = t.clamp(0.0, 1.0) * self.arc_length();
        match self.station_at_s(s) {
            Ok(st) => self.point_of(&st),
            Err(_) => self.origin,
        }
    }

    /// The piece between parameters `range.start` and `range.end` (reversed if
    /// `range.start > range.end`), itself a log-aesthetic segment.
    fn subsegment(&self, range: Range<f64>) -> Segment {
        let len = self.arc_length();
        let at = |t: f64| {
            self.station_at_s(t.clamp(0.0, 1.0) * len)
                .unwrap_or(self.first)
        };
        let (a, b) = (at(range.start), at(range.end));
        let offset_a = self.offset_of(&a);
        let chord = self.offset_of(&b) - offset_a;
        let forward = range.end >= range.start;
        Segment {
            first: a,
            last: b,
            chord,
            origin: self.caller_point(offset_a),
            theta_first: if forward {
                self.theta_of(&a)
            } else {
                self.theta_of(&a) + std::f64::consts::PI
            },
            left: self.left == forward,
            turning: (b.theta - a.theta).abs(),
            ..self.clone()
        }
    }

    fn start(&self) -> Point {
        self.origin
    }

    fn end(&self) -> Point {
        self.caller_point(self.chord)
    }
}

impl ParamCurveArclen for Segment {
    /// Exact: the arc length is known in closed form.
    fn arclen(&self, _accuracy: f64) -> f64 {
        self.arc_length()
    }

    fn inv_arclen(&self, arclen: f64, _accuracy: f64) -> f64 {
        let len = self.arc_length();
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
/// Orders 1 to 6 are exact (algebraic in κ and its derivatives); higher orders, which nothing in kurbo
/// uses, are central differences of the order below.
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
            let h = 1e-4;
            let lower = SegmentDerivative {
                segment: seg.clone(),
                order: self.order - 1,
            };
            let (t0, t1) = ((t - h).max(0.0), (t + h).min(1.0));
            return ((lower.eval(t1) - lower.eval(t0)) / (t1 - t0)).to_point();
        }
        let len = seg.arc_length();
        let st = seg
            .station_at_s(t.clamp(0.0, 1.0) * len)
            .unwrap_or(seg.first);
        let jet = seg.jet(&st);
        // d/dt = (len · dir / scale) d/ds_std on the standard form, then the similarity.
        let k = (len * seg.dir() / seg.scale()).powi(self.order as i32);
        let z = (seg.rot * jet[self.order as usize - 1]).scale(k);
        let z = if seg.mirrored { z.conj() } else { z };
        Point::new(z.re, z.im)
    }

    fn subsegment(&self, range: Range<f64>) -> SegmentDerivative {
        // d/dt' = (t1 − t0) d/dt on the sub-range.
        let sub = self.segment.subsegment(range);
        SegmentDerivative {
            segment: sub,
            order: self.order,
        }
    }
}

impl ParamCurveCurvature for Segment {
    /// Exact signed curvature, positive for a left turn (SPEC §1). Note that kurbo's
    /// default formula returns the opposite sign.
    fn curvature(&self, t: f64) -> f64 {
        let s = t.clamp(0.0, 1.0) * self.arc_length();
        self.curvature_at_s(s).unwrap_or(0.0)
    }
}
