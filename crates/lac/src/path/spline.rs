//! G2 splines through points (the interpolating mode, like Clothoids' G2 spline and Spiro):
//! every span between consecutive points is one log-aesthetic [`Segment`], whose control
//! triangle is the chord and the intersection of the tangent lines at its ends. The unknowns
//! are the tangent angles at the points; the equations, curvature continuity at the
//! interior points (every point of a closed spline). The curvature at the end of span i
//! depends on the angles at its two ends only, so the Jacobian is tridiagonal (cyclic when
//! closed) and Newton's method solves it like a path's joints.
//!
//! Not done: spans that must inflect (their end tangents on the same side of the chord: an
//! "inflection pair" of segments) and points where the turning changes direction; such
//! spans are refused, named, with [`G2Failure::SpanInflects`].

use std::f64::consts::{PI, TAU};

use kurbo::{Point, Vec2};

use super::{banded, G2Failure, G2_JUMP_LIMIT, G2_TOLERANCE, MAX_POLYGON_POINTS};
use crate::curve::Curve;
use crate::error::{finite, Error, Result};
use crate::segment::{check_alpha, end_curvatures_of, Segment};

/// The signed end curvatures of every span.
type Ends = Vec<(f64, f64)>;

/// Most Newton steps.
const MAX_STEPS: usize = 60;
/// Step of the forward differences in the tangent angles, radians.
const H: f64 = 1e-7;
/// Largest change of any tangent angle in one step, radians.
const MAX_STEP: f64 = 0.2;

/// A G2 spline of log-aesthetic segments through given points.
///
/// ```
/// use kurbo::Point;
/// use lac::{Curve, Spline};
///
/// let points = [
///     Point::new(0.0, 0.0), Point::new(2.0, 0.3), Point::new(3.5, 1.5), Point::new(4.0, 3.0),
/// ];
/// let spline = Spline::g2(&points, 0.5, false, None)?;
/// assert!(spline.max_curvature_jump() <= 1e-9);
/// assert!((spline.end_point() - points[3]).hypot() < 1e-12);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Spline {
    points: Vec<Point>,
    closed: bool,
    angles: Vec<f64>,
    triangles: Vec<[Point; 3]>,
    segments: Vec<Segment>,
    jumps: Vec<f64>,
}

/// The wrapped angle in (−π, π].
fn wrap(a: f64) -> f64 {
    a - TAU * ((a + PI) / TAU).floor()
}

fn dir(v: Vec2) -> f64 {
    v.y.atan2(v.x)
}

impl Spline {
    /// The G2 spline through `points` (at least 3; the first repeated last of a closed one
    /// is dropped) with slope `alpha`, open or `closed`; an open spline's end tangent
    /// directions are `ends` (radians) or those of the circles through its first and last
    /// three points.
    ///
    /// Errors: [`Error::NoG2Path`] naming the span (`leg` i is the span from point i) that
    /// must inflect ([`G2Failure::SpanInflects`]) or where the curvature could not be made
    /// continuous, or [`Error::PathSegment`] naming the span whose segment cannot be drawn;
    /// bad input.
    pub fn g2(
        points: &[Point],
        alpha: f64,
        closed: bool,
        ends: Option<[f64; 2]>,
    ) -> Result<Spline> {
        check_alpha("alpha", alpha)?;
        let mut points = points.to_vec();
        if closed && points.len() > 3 && points.first() == points.last() {
            points.pop();
        }
        let n = points.len();
        if !(3..=MAX_POLYGON_POINTS).contains(&n) {
            return Err(Error::OutOfRange {
                name: "number of points",
                value: n as f64,
                expected: "at least 3 points and at most 100000",
            });
        }
        for p in &points {
            finite("point x", p.x)?;
            finite("point y", p.y)?;
        }
        let spans = if closed { n } else { n - 1 };
        for i in 0..spans {
            let j = (i + 1) % n;
            if points[i] == points[j] {
                return Err(Error::CoincidentPoints {
                    first: i,
                    second: j,
                });
            }
            let d = points[j] - points[i];
            if !d.x.hypot(d.y).is_finite() {
                return Err(Error::OutOfRange {
                    name: "points",
                    value: f64::INFINITY,
                    expected: "coordinates whose differences do not overflow",
                });
            }
        }
        if let Some(e) = ends {
            finite("start angle", e[0])?;
            finite("end angle", e[1])?;
        }
        let mut s = Spline {
            points,
            closed,
            angles: Vec::new(),
            triangles: Vec::new(),
            segments: Vec::new(),
            jumps: Vec::new(),
        };
        s.solve(alpha, ends)?;
        Ok(s)
    }

    fn spans(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 1
        }
    }

    /// The control triangle of span `i` for tangent angles `phi`, or the reason it has none.
    fn triangle(&self, phi: &[f64], i: usize) -> std::result::Result<[Point; 3], G2Failure> {
        let n = self.points.len();
        let (a, b) = (self.points[i], self.points[(i + 1) % n]);
        let chord = b - a;
        let psi = dir(chord);
        let (ta, tb) = (wrap(phi[i] - psi), wrap(phi[(i + 1) % n] - psi));
        // One segment turns one way: its tangents leave and reach the chord from opposite
        // sides, and turn by less than π.
        if !(ta * tb < 0.0 && ta.abs() + tb.abs() < PI) {
            return Err(G2Failure::SpanInflects);
        }
        let c = chord.hypot();
        let u = c * tb.abs().sin() / (ta.abs() + tb.abs()).sin();
        Ok([a, a + Vec2::from_angle(phi[i]) * u, b])
    }

    /// End curvatures of every span.
    fn curvatures(&self, alpha: f64, phi: &[f64]) -> Result<Ends> {
        (0..self.spans())
            .map(|i| {
                let t = self
                    .triangle(phi, i)
                    .map_err(|reason| Error::NoG2Path { leg: i, reason })?;
                end_curvatures_of(t, alpha).map_err(|e| Error::PathSegment {
                    vertex: i,
                    source: Box::new(e),
                })
            })
            .collect()
    }

    /// ln|κ⁻/κ⁺| at each unknown point (a sign change counts as a failure of the span
    /// after it).
    fn residual(&self, k: &[(f64, f64)]) -> std::result::Result<Vec<f64>, usize> {
        let n = self.points.len();
        let unknowns: Vec<usize> = if self.closed {
            (0..n).collect()
        } else {
            (1..n - 1).collect()
        };
        unknowns
            .iter()
            .map(|&j| {
                let before = k[(j + n - 1) % n].1;
                let after = k[j % k.len()].0;
                if before * after <= 0.0 {
                    Err(j % k.len())
                } else {
                    Ok((before / after).abs().ln())
                }
            })
            .collect()
    }

    fn solve(&mut self, alpha: f64, ends: Option<[f64; 2]>) -> Result<()> {
        let n = self.points.len();
        let p = &self.points;
        let at = |i: usize| p[i % n];
        // Start: the tangents of the circles through each point and its neighbours.
        // (The tangent at B of the circle through A, B, C is dir AB + dir BC − dir AC.)
        let circle = |a: Point, b: Point, c: Point| {
            dir(b - a) + wrap(dir(c - b) - dir(b - a)) - wrap(dir(c - a) - dir(b - a))
        };
        let mut phi: Vec<f64> = (0..n)
            .map(|i| {
                if self.closed || (i > 0 && i + 1 < n) {
                    circle(at(i + n - 1), at(i), at(i + 1))
                } else {
                    0.0
                }
            })
            .collect();
        if !self.closed {
            let delta0 = wrap(dir(p[2] - p[1]) - dir(p[1] - p[0]));
            let delta1 = wrap(dir(p[n - 1] - p[n - 2]) - dir(p[n - 2] - p[n - 3]));
            let [s, e] =
                ends.unwrap_or([dir(p[2] - p[0]) - delta0, dir(p[n - 1] - p[n - 3]) + delta1]);
            phi[0] = s;
            phi[n - 1] = e;
        }
        // Continuation in α from the nearest of [0, 1] (where the circles' tangents are
        // drawable for any sensible points), each stage warm-started from the last.
        let start = alpha.clamp(0.0, 1.0);
        let stages = ((alpha - start).abs() / 0.25).ceil().max(0.0) as usize;
        let mut last = Err(Error::NumericalFailure {
            what: "the spline's continuation in alpha",
        });
        for stage in 0..=stages {
            let a = if stage == stages {
                alpha
            } else {
                start + (alpha - start) * stage as f64 / stages.max(1) as f64
            };
            last = self.newton(a, phi.clone());
            match &last {
                Ok((p2, _)) => phi = p2.clone(),
                Err(_) if stage == 0 && stages > 0 => {
                    // The circles' tangents do not solve at α in [0, 1]: try α directly.
                    last = self.newton(alpha, phi.clone());
                    break;
                }
                Err(_) => break,
            }
        }
        let (phi, r) = last?;
        self.finish(alpha, phi, r)
    }

    /// Newton's method on the unknown angles of `phi` at slope `alpha`: the angles and
    /// residuals reached, or the span that fails at the start.
    fn newton(&self, alpha: f64, mut phi: Vec<f64>) -> Result<(Vec<f64>, Vec<f64>)> {
        let n = self.points.len();
        let unknowns: Vec<usize> = if self.closed {
            (0..n).collect()
        } else {
            (1..n - 1).collect()
        };
        let eval = |phi: &[f64]| -> Result<(Ends, Vec<f64>)> {
            let k = self.curvatures(alpha, phi)?;
            let r = self.residual(&k).map_err(|span| Error::NoG2Path {
                leg: span,
                reason: G2Failure::SpanInflects,
            })?;
            Ok((k, r))
        };
        let norm = |r: &[f64]| r.iter().map(|x| x * x).sum::<f64>().sqrt();
        let (mut k, mut r) = eval(&phi)?;
        for _ in 0..MAX_STEPS {
            if r.iter().all(|x| x.abs() <= G2_TOLERANCE) {
                break;
            }
            // ∂ ln|κ_start|, ∂ ln|κ_end| of each span in the angles at its two ends.
            let spans = self.spans();
            let mut d = vec![[[0.0; 2]; 2]; spans];
            for (i, di) in d.iter_mut().enumerate() {
                for (e, end) in [i, (i + 1) % n].into_iter().enumerate() {
                    let mut moved = phi.clone();
                    moved[end] += H;
                    let t = self.triangle(&moved, i).ok();
                    let Some(Ok((a, b))) = t.map(|t| end_curvatures_of(t, alpha)) else {
                        continue;
                    };
                    di[e] = [(a / k[i].0).abs().ln() / H, (b / k[i].1).abs().ln() / H];
                }
            }
            let m = unknowns.len();
            let (mut sub, mut diag, mut sup) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
            for (u, &j) in unknowns.iter().enumerate() {
                let (before, after) = ((j + n - 1) % n, j % spans);
                // R_j = ln|κ_end(before)| − ln|κ_start(after)|
                diag[u] = d[before][1][1] - d[after][0][0];
                sub[u] = d[before][0][1];
                sup[u] = -d[after][1][0];
            }
            let rhs: Vec<f64> = r.iter().map(|x| -x).collect();
            let Some(dx) = banded::solve(&sub, &diag, &sup, &rhs, self.closed) else {
                break;
            };
            let big = dx.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let mut lambda = if big > MAX_STEP { MAX_STEP / big } else { 1.0 };
            let now = norm(&r);
            let mut next = None;
            for _ in 0..30 {
                let mut trial = phi.clone();
                for (u, &j) in unknowns.iter().enumerate() {
                    trial[j] += lambda * dx[u];
                }
                if let Ok((k2, r2)) = eval(&trial) {
                    if norm(&r2) < now * (1.0 - 1e-4 * lambda) {
                        next = Some((trial, k2, r2));
                        break;
                    }
                }
                lambda *= 0.5;
            }
            let Some((p2, k2, r2)) = next else { break };
            (phi, k, r) = (p2, k2, r2);
        }
        Ok((phi, r))
    }

    /// Check the answer of the last stage and build the segments.
    fn finish(&mut self, alpha: f64, phi: Vec<f64>, r: Vec<f64>) -> Result<()> {
        let n = self.points.len();
        let unknowns: Vec<usize> = if self.closed {
            (0..n).collect()
        } else {
            (1..n - 1).collect()
        };
        let (worst, jump) =
            r.iter().enumerate().fold(
                (0, 0.0f64),
                |(i, m), (j, x)| {
                    if x.abs() > m {
                        (j, x.abs())
                    } else {
                        (i, m)
                    }
                },
            );
        if jump > 0.5 * G2_JUMP_LIMIT {
            return Err(Error::NoG2Path {
                leg: unknowns[worst],
                reason: G2Failure::NoConvergence { jump },
            });
        }
        // The checked segments, and the joints measured on them.
        let triangles = (0..self.spans())
            .map(|i| {
                self.triangle(&phi, i)
                    .map_err(|reason| Error::NoG2Path { leg: i, reason })
            })
            .collect::<Result<Vec<_>>>()?;
        let segments = triangles
            .iter()
            .enumerate()
            .map(|(i, &t)| {
                Segment::from_control_points(t, alpha).map_err(|e| Error::PathSegment {
                    vertex: i,
                    source: Box::new(e),
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let size = self
            .points
            .iter()
            .map(|q| (*q - self.points[0]).hypot())
            .fold(0.0, f64::max);
        let pairs = if self.closed {
            segments.len()
        } else {
            segments.len() - 1
        };
        let mut jumps = Vec::new();
        for i in 0..pairs {
            let (a, b) = (&segments[i], &segments[(i + 1) % segments.len()]);
            let gap = (a.end_point() - b.start_point()).hypot();
            let dt = wrap(
                a.theta_of(&a.station_at_turning(a.turning_angle())?)
                    - b.theta_of(&b.station_at_turning(0.0)?),
            );
            let (k0, k1) = (a.end_curvatures().1, b.end_curvatures().0);
            let jump = (k0 - k1).abs() / k0.abs().max(k1.abs());
            if !(gap <= 1e-10 * size && dt.abs() <= 1e-10 && jump <= G2_JUMP_LIMIT) {
                return Err(Error::NumericalFailure {
                    what: "the spline's joint check (a point's position, tangent or \
                           curvature does not match)",
                });
            }
            jumps.push(jump);
        }
        self.angles = phi;
        self.triangles = triangles;
        self.segments = segments;
        self.jumps = jumps;
        Ok(())
    }

    /// The points it passes through.
    pub fn points(&self) -> &[Point] {
        &self.points
    }

    /// Whether it is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The tangent direction at each point, radians.
    pub fn angles(&self) -> &[f64] {
        &self.angles
    }

    /// The control triangle of each span as solved: (its first point, the intersection of
    /// its end tangents, its last point), the points exactly as given.
    pub fn control_triangles(&self) -> &[[Point; 3]] {
        &self.triangles
    }

    /// The relative curvature jump measured at each joint (the interior points; every
    /// point when closed, the last at the first point).
    pub fn curvature_jumps(&self) -> &[f64] {
        &self.jumps
    }

    /// The largest relative curvature jump over the joints.
    pub fn max_curvature_jump(&self) -> f64 {
        self.jumps.iter().fold(0.0, |m, j| m.max(*j))
    }
}

impl Curve for Spline {
    fn pieces(&self) -> &[Segment] {
        &self.segments
    }
}
