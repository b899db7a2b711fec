//! Compound-rhythm curves: two log-aesthetic pieces joined with G3 continuity (SPEC §4,
//! seeds 004 and 002).

use kurbo::{Point, Vec2};

use crate::error::{finite, Error, NotDrawable, Result};
use crate::lcg::LcgLine;
use crate::sampling::{check_count, Sample};
use crate::segment::{control_triangle, Segment};
use crate::solve::ChordAngle;
use crate::standard_form::Station;

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
/// use lac::CompoundCurve;
///
/// // A "valley": clothoid-like α0 = −1 into a circle-involute-like α1 = 2.
/// let curve = CompoundCurve::from_three_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.6, 0.9)],
///     -1.0, 2.0, 0.5,
/// )?;
/// let joint = curve.joint_s();
/// assert!(joint > 0.0 && joint < curve.arc_length());
/// // Curvature is continuous at the joint.
/// let (a, b) = (curve.pieces()[0].curvature_end(), curve.pieces()[1].curvature_start());
/// assert!((a - b).abs() < 1e-12 * a.abs());
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct CompoundCurve {
    pieces: [Segment; 2],
}

/// The caller's problem, in the caller's order.
struct Input {
    start: Point,
    end: Point,
    theta_first: f64,
    left: bool,
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
        finite("alpha0", alpha0)?;
        finite("alpha1", alpha1)?;
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
            left: tri.left,
            alpha: [alpha0, alpha1],
            theta: [theta0, tri.turning - theta0],
            theta_e: tri.theta_e,
        })
    }

    /// The compound curve for control points `[P0, P1, P2, P3]`: it starts at P0 tangent
    /// to P1 − P0, ends at P3 tangent to P3 − P2, and its joint's tangent is parallel to
    /// P2 − P1 (seed 002). The polygon must turn one way only.
    pub fn from_four_points(points: [Point; 4], alpha0: f64, alpha1: f64) -> Result<Self> {
        finite("alpha0", alpha0)?;
        finite("alpha1", alpha1)?;
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
        let turn = |a: Vec2, b: Vec2| a.cross(b).atan2(a.dot(b));
        let (t0, t1) = (turn(legs[0], legs[1]), turn(legs[1], legs[2]));
        let pi = std::f64::consts::PI;
        if [t0, t1]
            .iter()
            .any(|t| !(t.abs() > 1e-13 && t.abs() < pi - 1e-13))
        {
            return Err(Error::CollinearPoints);
        }
        let side = |t: f64| if t > 0.0 { "left" } else { "right" };
        if (t0 > 0.0) != (t1 > 0.0) {
            return Err(Error::InflectedPolygon {
                first: side(t0),
                second: side(t1),
            });
        }
        let left = t0 > 0.0;
        let sign = if left { 1.0 } else { -1.0 };
        let chord = points[3] - points[0];
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
            left,
            alpha: [alpha0, alpha1],
            theta: [t0.abs(), t1.abs()],
            theta_e,
        })
    }

    /// Solve in the joint-reference standard form, running from the end with the smaller
    /// radius of curvature (SPEC §4: if θe < Θ/2 the ends swap, α0 ↔ α1, θ0 ↔ θ1), and map
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
        let mirrored = input.left == reversed;
        let c = input.end - input.start;
        let c = crate::numeric::Complex::new(c.x, if mirrored { -c.y } else { c.y });
        let rot = c.div(chord);
        let mut origin = input.start;
        let mut theta_first = input.theta_first;
        let turn_sign = if input.left { 1.0 } else { -1.0 };
        let pieces = [0, 1].map(|i| {
            let (k, forward) = order[i];
            let p = parts[k];
            let (first, last, piece_chord): (Station, Station, _) = if forward {
                (p.start, p.end, p.chord)
            } else {
                (p.end, p.start, -p.chord)
            };
            let seg = Segment {
                alpha: input.alpha[i],
                form: p.form,
                first,
                last,
                chord: piece_chord,
                origin,
                rot,
                scale: rot.norm(),
                mirrored,
                left: input.left,
                theta_first,
                turning: input.theta[i],
            };
            origin = seg.caller_point(piece_chord);
            theta_first += turn_sign * input.theta[i];
            seg
        });
        Ok(CompoundCurve { pieces })
    }

    /// The two pieces in the caller's order: slope α0 from the first control point to the
    /// joint, slope α1 from the joint to the last control point.
    pub fn pieces(&self) -> &[Segment; 2] {
        &self.pieces
    }

    /// The slopes [α0, α1].
    pub fn alpha(&self) -> [f64; 2] {
        [self.pieces[0].alpha(), self.pieces[1].alpha()]
    }

    /// Λ of the joint-reference standard form (dρ/ds at the joint, with ρ = 1 there).
    pub fn lambda(&self) -> f64 {
        self.pieces[0].lambda()
    }

    /// Total arc length.
    pub fn arc_length(&self) -> f64 {
        self.pieces[0].arc_length() + self.pieces[1].arc_length()
    }

    /// Arc length from the first control point to the joint.
    pub fn joint_s(&self) -> f64 {
        self.pieces[0].arc_length()
    }

    /// The joint.
    pub fn joint(&self) -> Point {
        self.pieces[1].origin
    }

    /// Signed curvature at the first control point (positive for a left turn).
    pub fn curvature_start(&self) -> f64 {
        self.pieces[0].curvature_start()
    }

    /// Signed curvature at the joint.
    pub fn curvature_joint(&self) -> f64 {
        self.pieces[1].curvature_start()
    }

    /// Signed curvature at the last control point.
    pub fn curvature_end(&self) -> f64 {
        self.pieces[1].curvature_end()
    }

    /// The logarithmic curvature graph of each piece (`None` for a circular arc); the two
    /// lines meet at the joint's log ρ.
    pub fn lcg(&self) -> [Option<LcgLine>; 2] {
        [self.pieces[0].lcg(), self.pieces[1].lcg()]
    }

    /// The piece holding arc length `s` and the arc length within it.
    fn locate(&self, s: f64) -> Result<(&Segment, f64)> {
        finite("s", s)?;
        let len = self.arc_length();
        let slack = 1e-12 * len;
        if !(s >= -slack && s <= len + slack) {
            return Err(Error::OutOfRange {
                name: "s",
                value: s,
                expected: "an arc length between 0 and arc_length()",
            });
        }
        let joint = self.joint_s();
        if s <= joint {
            Ok((&self.pieces[0], s))
        } else {
            Ok((&self.pieces[1], self.second_piece_s(s)))
        }
    }

    /// Arc length within the second piece, measured from whichever of its ends is nearer:
    /// when that piece is much shorter than the first, `s − joint_s` would lose the digits
    /// of its position to the rounding of the whole length.
    fn second_piece_s(&self, s: f64) -> f64 {
        let (joint, total, len) = (
            self.joint_s(),
            self.arc_length(),
            self.pieces[1].arc_length(),
        );
        let from_end = total - s;
        if from_end < 0.5 * len {
            (len - from_end).clamp(0.0, len)
        } else {
            (s - joint).clamp(0.0, len)
        }
    }

    /// Point at arc length `s` from the first control point.
    pub fn point_at_s(&self, s: f64) -> Result<Point> {
        let (piece, s) = self.locate(s)?;
        piece.point_at_s(s)
    }

    /// Unit tangent at arc length `s`.
    pub fn tangent_at_s(&self, s: f64) -> Result<Vec2> {
        let (piece, s) = self.locate(s)?;
        piece.tangent_at_s(s)
    }

    /// Signed curvature at arc length `s`.
    pub fn curvature_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = self.locate(s)?;
        piece.curvature_at_s(s)
    }

    /// Tangent direction (radians, continuous from the first point) at arc length `s`.
    pub fn theta_at_s(&self, s: f64) -> Result<f64> {
        let (piece, s) = self.locate(s)?;
        piece.theta_at_s(s)
    }

    /// `n ≥ 2` samples equally spaced in arc length over the whole curve, ends included.
    pub fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        let (len, joint) = (self.arc_length(), self.joint_s());
        let step = len / (n - 1) as f64;
        let at = |i: usize| if i == n - 1 { len } else { i as f64 * step };
        let split = (0..n).take_while(|&i| at(i) <= joint).count();
        let first: Vec<f64> = (0..split).map(at).collect();
        let second: Vec<f64> = (split..n).map(|i| self.second_piece_s(at(i))).collect();
        let mut out = self.pieces[0].samples_at_arc_lengths(&first)?;
        out.extend(
            self.pieces[1]
                .samples_at_arc_lengths(&second)?
                .into_iter()
                .map(|s| Sample {
                    s: s.s + joint,
                    ..s
                }),
        );
        Ok(out)
    }

    /// Samples within `tolerance` of the curve (see [`Segment::sample_adaptive`]); the joint
    /// is always a sample.
    pub fn sample_adaptive(&self, tolerance: f64) -> Result<Vec<Sample>> {
        let joint = self.joint_s();
        let mut out = self.pieces[0].sample_adaptive(tolerance)?;
        let second = self.pieces[1].sample_adaptive(tolerance)?;
        out.extend(second.into_iter().skip(1).map(|s| Sample {
            s: s.s + joint,
            ..s
        }));
        Ok(out)
    }

    /// `n ≥ 2` points of the evolute at the arc-length samples.
    pub fn evolute(&self, n: usize) -> Result<Vec<Point>> {
        Ok(self
            .sample_by_arc_length(n)?
            .iter()
            .map(Sample::center_of_curvature)
            .collect())
    }
}
