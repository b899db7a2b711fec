//! The control polygon of a path (open or closed, validated) and the slopes of its
//! segments.

use kurbo::Point;

use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::length;
use crate::foundation::turn::Turn;
use crate::segment::{check_alpha, normalized};

/// The most vertices a control polygon may have (the work is linear in it; this bounds a
/// request's memory and time).
pub const MAX_POLYGON_POINTS: usize = 100_000;

/// Whether a polygon, path or spline ends where it starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Closure {
    /// From the first point to the last.
    Open,
    /// Around, back to the first point.
    Closed,
}

/// A validated control polygon: at least three points, finite, consecutive points distinct;
/// open (the path runs from the first point to the last) or closed.
#[derive(Clone, Debug, PartialEq)]
pub struct ControlPolygon {
    points: Vec<Point>,
    closed: bool,
}

impl ControlPolygon {
    /// The polygon through `points`, open or closed.
    ///
    /// An open polygon P0 … Pn (n ≥ 2): the path starts at P0 tangent to P1 − P0 and ends at
    /// Pn tangent to Pn − Pn−1, with one segment per interior vertex. A closed polygon (at
    /// least three vertices; a last point equal to the first is dropped): one segment per
    /// vertex and a joint on every leg.
    pub fn from_points(points: &[Point], closure: Closure) -> Result<ControlPolygon> {
        match closure {
            Closure::Open => ControlPolygon::new(points, false),
            Closure::Closed => {
                let mut points = points.to_vec();
                if points.len() > 3 && points.first() == points.last() {
                    points.pop();
                }
                ControlPolygon::new(&points, true)
            }
        }
    }

    fn new(points: &[Point], closed: bool) -> Result<ControlPolygon> {
        if points.len() < 3 || points.len() > MAX_POLYGON_POINTS {
            return Err(Error::OutOfRange {
                name: "number of polygon points",
                value: points.len() as f64,
                expected: "at least 3 points (one interior vertex) and at most 100000",
            });
        }
        for p in points {
            finite("polygon point x", p.x)?;
            finite("polygon point y", p.y)?;
        }
        let n = points.len();
        let legs = if closed { n } else { n - 1 };
        for i in 0..legs {
            let j = (i + 1) % n;
            let d = points[j] - points[i];
            if points[i] == points[j] {
                return Err(Error::CoincidentPoints {
                    first: i,
                    second: j,
                });
            }
            if !d.x.hypot(d.y).is_finite() {
                return Err(Error::OutOfRange {
                    name: "polygon points",
                    value: f64::INFINITY,
                    expected: "coordinates whose differences do not overflow",
                });
            }
        }
        Ok(ControlPolygon {
            points: points.to_vec(),
            closed,
        })
    }

    /// The vertices.
    pub fn points(&self) -> &[Point] {
        &self.points
    }

    /// Whether the polygon is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// Number of legs: n for an open polygon of n + 1 points, n for a closed one of n.
    pub fn leg_count(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 1
        }
    }

    /// Number of segments: one per interior vertex (every vertex when closed).
    pub fn segment_count(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 2
        }
    }

    /// The vertex that carries segment `k`.
    pub fn vertex_of_segment(&self, k: usize) -> usize {
        if self.closed {
            k
        } else {
            k + 1
        }
    }

    /// The legs on which segment `k` starts and ends.
    pub(super) fn legs_of_segment(&self, k: usize) -> (usize, usize) {
        let n = self.points.len();
        if self.closed {
            ((k + n - 1) % n, k)
        } else {
            (k, k + 1)
        }
    }

    /// The legs that carry a joint between two segments (all but the end legs when open).
    pub fn joint_legs(&self) -> Vec<usize> {
        if self.closed {
            (0..self.points.len()).collect()
        } else {
            (1..self.points.len() - 2).collect()
        }
    }

    /// The segments that end and start on joint leg `leg`.
    pub(super) fn segments_at_leg(&self, leg: usize) -> (usize, usize) {
        if self.closed {
            (leg, (leg + 1) % self.points.len())
        } else {
            (leg - 1, leg)
        }
    }

    /// Leg `i` from `P_i` to `P_{i+1}` (cyclically).
    pub(super) fn leg(&self, i: usize) -> (Point, Point) {
        let n = self.points.len();
        (self.points[i], self.points[(i + 1) % n])
    }

    /// The point at fraction `t` along leg `i` (exactly the vertex at t = 0 and t = 1).
    pub(super) fn at(&self, i: usize, t: f64) -> Point {
        let (a, b) = self.leg(i);
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            a.lerp(b, t)
        }
    }

    /// The control triangle of segment `k` when the segments starting on each leg start at
    /// fraction `start[leg]` and those ending on it end at `end[leg]` (the same but on an
    /// inflection leg, where a straight piece runs between them).
    pub(super) fn control_points(&self, start: &[f64], end: &[f64], k: usize) -> [Point; 3] {
        let (sl, el) = self.legs_of_segment(k);
        let v = self.vertex_of_segment(k);
        [self.at(sl, start[sl]), self.points[v], self.at(el, end[el])]
    }

    /// Length of leg `i`.
    pub(super) fn leg_length(&self, i: usize) -> f64 {
        let (a, b) = self.leg(i);
        length(b - a)
    }

    /// The joint legs where the turning direction changes (the curvature must pass through
    /// zero there).
    pub(super) fn inflection_legs(&self) -> Vec<usize> {
        self.joint_legs()
            .into_iter()
            .filter(|&leg| {
                let (before, after) = self.segments_at_leg(leg);
                self.turn_at(self.vertex_of_segment(before))
                    != self.turn_at(self.vertex_of_segment(after))
            })
            .collect()
    }

    /// The turning direction at vertex `v` (`None` when the legs are collinear).
    pub(super) fn turn_at(&self, v: usize) -> Option<Turn> {
        let n = self.points.len();
        let (p, q, r) = (
            self.points[(v + n - 1) % n],
            self.points[v],
            self.points[(v + 1) % n],
        );
        // (Each leg at its own scale: a product of legs near 1e308 overflows.)
        Turn::of(normalized(q - p).cross(normalized(r - q)))
    }

    /// Largest coordinate extent, the scale of position checks.
    pub(super) fn size(&self) -> f64 {
        let (mut lo, mut hi) = (self.points[0], self.points[0]);
        for p in &self.points {
            lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        (hi.x - lo.x).max(hi.y - lo.y)
    }

    /// The fractions of every leg for joints `fractions` on the joint legs (in the order of
    /// [`ControlPolygon::joint_legs`]); an open polygon's end legs get 0 (start at P0) and
    /// 1 (end at Pn).
    pub(super) fn leg_fractions(&self, joint_fractions: &[f64]) -> Vec<f64> {
        let mut t = vec![0.0; self.leg_count()];
        if !self.closed {
            let last = t.len() - 1;
            t[last] = 1.0;
        }
        for (leg, f) in self.joint_legs().into_iter().zip(joint_fractions) {
            t[leg] = *f;
        }
        t
    }
}

/// The slopes of a path's segments: one α for all, or one per segment (in the order of the
/// vertices that carry them).
#[derive(Clone, Debug, PartialEq)]
pub enum Alphas {
    /// The same α for every segment.
    One(f64),
    /// α of each segment.
    PerSegment(Vec<f64>),
}

impl Alphas {
    /// One α per segment of `polygon`, checked.
    pub(super) fn resolve(&self, polygon: &ControlPolygon) -> Result<Vec<f64>> {
        let n = polygon.segment_count();
        let out = match self {
            Alphas::One(a) => vec![check_alpha("alpha", *a)?; n],
            Alphas::PerSegment(list) => {
                if list.len() != n {
                    return Err(Error::OutOfRange {
                        name: "number of alphas",
                        value: list.len() as f64,
                        expected: "one alpha per segment (per interior vertex of an open \
                                   polygon, per vertex of a closed one), or a single alpha",
                    });
                }
                for a in list {
                    check_alpha("alpha", *a)?;
                }
                list.clone()
            }
        };
        Ok(out)
    }
}
