//! A curve made of segments and straight lines in order, whose tangent may break where two
//! meet (a spline's corners): the [`Curve`] of a spline with point types. Each sample is
//! taken from the item that holds its arc length, θ continuous from the first point across
//! every join (a corner's break counted by its angle in (−π, π]).

use kurbo::Point;

use crate::curve::{check_arc_length, check_ascending, Curve};
use crate::family::sample::Sample;
use crate::foundation::error::Result;
use crate::foundation::numeric::length;
use crate::segment::Segment;

/// One item of a run: a segment (by its index) or a straight line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Item {
    /// The segment of this index.
    Segment(usize),
    /// A straight line from the first point to the second.
    Line(Point, Point),
}

/// Segments and lines in order, as a curve.
pub(crate) struct Run<'a> {
    pub(crate) segments: &'a [Segment],
    pub(crate) items: &'a [Item],
}

/// The wrapped angle in (−π, π].
fn wrap(a: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    a - TAU * ((a + PI) / TAU).floor()
}

impl Run<'_> {
    fn length_of(&self, item: &Item) -> f64 {
        match item {
            Item::Segment(k) => self.segments[*k].arc_length(),
            Item::Line(a, b) => length(*b - *a),
        }
    }

    /// The direction of an item at its start and end, in its own continuous measure.
    fn ends_of(&self, item: &Item) -> Result<(f64, f64)> {
        Ok(match item {
            Item::Segment(k) => {
                let seg = &self.segments[*k];
                (seg.theta_at_s(0.0)?, seg.theta_at_s(seg.arc_length())?)
            }
            Item::Line(a, b) => {
                let d = (*b - *a).atan2();
                (d, d)
            }
        })
    }

    /// θ at the start of every item, continuous from the first item's start direction.
    fn start_thetas(&self) -> Result<Vec<f64>> {
        let mut out = Vec::with_capacity(self.items.len());
        let mut previous_end: Option<f64> = None;
        let mut at = 0.0;
        for item in self.items {
            let (start, end) = self.ends_of(item)?;
            at = match previous_end {
                None => start,
                Some(e) => at + wrap(start - e),
            };
            out.push(at);
            at += end - start;
            previous_end = Some(end);
        }
        Ok(out)
    }

    /// The item holding `s` (a join belongs to the item after it), its start θ and `s`
    /// within it, clamped to its length.
    fn locate(&self, s: f64) -> Result<(usize, f64, f64)> {
        check_arc_length(s, self.arc_length())?;
        let thetas = self.start_thetas()?;
        let mut start = 0.0;
        for (i, item) in self.items.iter().enumerate() {
            let l = self.length_of(item);
            if s < start + l || i + 1 == self.items.len() {
                return Ok((i, thetas[i], (s - start).clamp(0.0, l)));
            }
            start += l;
        }
        unreachable!("a run has at least one item")
    }

    fn theta_in(&self, i: usize, at_start: f64, local: f64) -> Result<f64> {
        Ok(match self.items[i] {
            Item::Segment(k) => {
                let seg = &self.segments[k];
                at_start + (seg.theta_at_s(local)? - seg.theta_at_s(0.0)?)
            }
            Item::Line(..) => at_start,
        })
    }
}

impl Curve for Run<'_> {
    fn arc_length(&self) -> f64 {
        self.items.iter().map(|i| self.length_of(i)).sum()
    }

    fn start_point(&self) -> Point {
        match self.items[0] {
            Item::Segment(k) => self.segments[k].start_point(),
            Item::Line(a, _) => a,
        }
    }

    fn end_point(&self) -> Point {
        match self.items[self.items.len() - 1] {
            Item::Segment(k) => self.segments[k].end_point(),
            Item::Line(_, b) => b,
        }
    }

    fn signed_curvature_start(&self) -> f64 {
        match self.items[0] {
            Item::Segment(k) => self.segments[k].signed_curvature_start(),
            Item::Line(..) => 0.0,
        }
    }

    fn signed_curvature_end(&self) -> f64 {
        match self.items[self.items.len() - 1] {
            Item::Segment(k) => self.segments[k].signed_curvature_end(),
            Item::Line(..) => 0.0,
        }
    }

    /// The change of θ from the first point to the last, corners' breaks included.
    fn turning(&self) -> f64 {
        let Ok(thetas) = self.start_thetas() else {
            return f64::NAN;
        };
        let last = self.items.len() - 1;
        match self.ends_of(&self.items[last]) {
            Ok((start, end)) => thetas[last] + (end - start) - thetas[0],
            Err(_) => f64::NAN,
        }
    }

    fn point_at_s(&self, s: f64) -> Result<Point> {
        let (i, _, local) = self.locate(s)?;
        match self.items[i] {
            Item::Segment(k) => self.segments[k].point_at_s(local),
            Item::Line(a, b) => Ok(line_point(a, b, local)),
        }
    }

    fn theta_at_s(&self, s: f64) -> Result<f64> {
        let (i, at_start, local) = self.locate(s)?;
        self.theta_in(i, at_start, local)
    }

    fn signed_curvature_at_s(&self, s: f64) -> Result<f64> {
        let (i, _, local) = self.locate(s)?;
        match self.items[i] {
            Item::Segment(k) => self.segments[k].signed_curvature_at_s(local),
            Item::Line(..) => Ok(0.0),
        }
    }

    fn curvature_derivative_at_s(&self, s: f64) -> Result<f64> {
        let (i, _, local) = self.locate(s)?;
        match self.items[i] {
            Item::Segment(k) => self.segments[k].curvature_derivative_at_s(local),
            Item::Line(..) => Ok(0.0),
        }
    }

    /// Where consecutive items meet.
    fn joint_arc_lengths(&self) -> Vec<f64> {
        let mut s = 0.0;
        self.items[..self.items.len() - 1]
            .iter()
            .map(|item| {
                s += self.length_of(item);
                s
            })
            .collect()
    }

    /// The samples over the whole run (κ = 0 on the lines); θ continuous from the first
    /// point.
    fn samples_at_arc_lengths(&self, at: &[f64]) -> Result<Vec<Sample>> {
        let lengths: Vec<f64> = self.items.iter().map(|i| self.length_of(i)).collect();
        check_ascending(at, lengths.iter().sum())?;
        let thetas = self.start_thetas()?;
        let mut out = Vec::with_capacity(at.len());
        let (mut i, mut start) = (0, 0.0);
        for &s in at {
            while i + 1 < self.items.len() && s > start + lengths[i] {
                start += lengths[i];
                i += 1;
            }
            let local = (s - start).clamp(0.0, lengths[i]);
            let sample = match self.items[i] {
                Item::Segment(k) => {
                    let seg = &self.segments[k];
                    let mut smp = seg.samples_at_arc_lengths(&[local])?[0];
                    smp.s = s;
                    smp.theta = thetas[i] + (smp.theta - seg.theta_at_s(0.0)?);
                    smp
                }
                Item::Line(a, b) => Sample {
                    s,
                    point: line_point(a, b, local),
                    theta: thetas[i],
                    kappa: 0.0,
                },
            };
            out.push(sample);
        }
        Ok(out)
    }
}

/// The point at arc length `local` from `a` toward `b`.
fn line_point(a: Point, b: Point, local: f64) -> Point {
    let l = length(b - a);
    a.lerp(b, if l > 0.0 { local / l } else { 0.0 })
}
