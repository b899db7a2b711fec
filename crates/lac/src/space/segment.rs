//! A log-aesthetic space curve segment from four control points (seed 003 §4, docs/math.md
//! §6): the shape asked, the segment found (a placed piece of a standard form, or the planar
//! segment when the points are coplanar), its frames and its logarithmic graphs. The search
//! for the standard form is in `solver.rs`.

use kurbo::Point;

use super::family::{SpaceForm, TorsionType};
use super::shoot::end_angles;
use super::similarity::Similarity3;
use super::solver::{perpendicular, solve_space, Solution, WarmStart};
use super::taylor::{Expansion, State};
use super::{Frame, SpaceCurve};
use crate::curve::Curve;
use crate::foundation::error::{finite, Error, NotDrawable, Result};
use crate::foundation::turn::Turn;
use crate::foundation::vec3::Vec3;
use crate::segment::Segment;

/// Dihedral angles |θ2| below this (radians) count as coplanar: the planar segment is drawn.
pub const PLANAR_TOLERANCE: f64 = 1e-9;

/// The shape asked of a [`SpaceSegment`]: the slopes α, β of its logarithmic curvature and
/// torsion graphs, the torsion graph's parameter Ω and the torsion type (seed 003 §4). The
/// solver finds Λ and ν ([`SpaceFormParams`](super::SpaceFormParams)).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpaceShape {
    /// α, the slope of the logarithmic curvature graph (finite).
    pub alpha: f64,
    /// β, the slope of the logarithmic torsion graph (finite).
    pub beta: f64,
    /// Ω ≥ 0, the torsion graph's parameter (0: μ constant when β = 0).
    pub omega: f64,
    /// Whether the radius of torsion increases ([`TorsionType::One`]) or decreases along
    /// the standard form.
    pub torsion: TorsionType,
}

/// What the solver found: a piece of a standard form placed by a similarity, or, for
/// coplanar points, a planar segment in their plane.
#[derive(Clone, Debug)]
pub(super) enum Found {
    Space {
        form: SpaceForm,
        s_end: f64,
        transform: Similarity3,
        /// Integrator states at the starts of the steps from 0 to `s_end`.
        checkpoints: Vec<State>,
    },
    Planar {
        segment: Segment,
        /// The plane: origin P0 and orthonormal axes.
        origin: Vec3,
        e1: Vec3,
        e2: Vec3,
    },
}

/// A log-aesthetic space curve segment (seed 003 §4): it starts at `P0` tangent to
/// `P1 − P0`, ends at `P3` tangent to `P3 − P2`, and is a similar copy of a piece
/// `0 ≤ s ≤ s_end` of a [`SpaceForm`] with the given α, β, Ω and type, whose Λ and ν the
/// solver finds.
///
/// Arc length `s` runs from 0 at `P0` to [`SpaceSegment::arc_length`] at `P3`. When the four
/// points are coplanar (|θ2| < [`PLANAR_TOLERANCE`]) the space family has no member through
/// them (ν = ∞) and the segment is the planar log-aesthetic segment of slope α through P0,
/// the tangents' intersection and P3 ([`SpaceSegment::planar`]), with zero torsion.
///
/// ```
/// use lac::{SpaceCurve, SpaceSegment, SpaceShape, TorsionType, Vec3};
/// let p = [
///     Vec3::new(0.0, 0.0, 0.0),
///     Vec3::new(1.0, 0.0, 0.0),
///     Vec3::new(2.0, 1.0, 0.5),
///     Vec3::new(2.0, 2.0, 1.5),
/// ];
/// let shape = SpaceShape { alpha: 0.0, beta: 0.0, omega: 0.0, torsion: TorsionType::One };
/// let seg = SpaceSegment::from_control_points(p, shape)?;
/// let end = seg.frame_at_s(seg.arc_length())?;
/// assert!(end.point.distance(p[3]) < 1e-9);
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct SpaceSegment {
    points: [Vec3; 4],
    shape: SpaceShape,
    solved: Found,
    arc_length: f64,
}

/// A point of a logarithmic curvature or torsion graph.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GraphPoint {
    /// Arc length from P0.
    pub s: f64,
    /// ln ρ (or ln μ).
    pub x: f64,
    /// ln(ρ |ds/dρ|) (or ln(μ |ds/dμ|)).
    pub y: f64,
}

impl SpaceSegment {
    /// Solve for the segment through `points = [P0, P1, P2, P3]` with the curvature slope α,
    /// torsion slope β, torsion parameter Ω ≥ 0 and torsion type of `shape`.
    ///
    /// Errors: non-finite input, coincident points (P0 = P1, P2 = P3 or P0 = P3), a tangent
    /// along the chord ([`Error::CollinearPoints`]), a coplanar S ([`Error::InflectedPolygon`]),
    /// and [`Error::NotDrawable`]: [`NotDrawable::TorsionTooLarge`] when no segment was found
    /// at Ω but one was at Ω = 0, with how far in Ω that one's branch reached,
    /// [`NotDrawable::NoSpaceSegment`] when none was found at Ω = 0 either.
    ///
    /// Which segment, when several fit the ends (they differ in Λ, ν and length): the
    /// search is deterministic, so the same input always gives the same segment, in this
    /// order, with the standard form starting at the end whose tangent makes the larger
    /// angle with the chord: (1) seed 003's cone search (the end is the first crossing of
    /// the cone about the start tangent, the second when |θ2| > π/2) from near-helix starts
    /// (Λ = 0, then Λ = 1, ν upward from about tan θ0); its first segment whose tangent and
    /// binormal turn by at most 3π/2 is returned; (2) otherwise the free-end search (the end
    /// s a third unknown, starts from ν scans on the first three crossings' cones at Λ = 0,
    /// 0.15, 0.4, 1, best residual first, then where those scans come closest to the cone
    /// without crossing it, then where seed 003's 2π guard cuts them off near it), and the
    /// segment that turns least among (1) and (2); (3) when Ω itself is out of reach, the
    /// segment at Ω = 0 followed continuously in Ω; (4) when none of these finds a segment,
    /// the free-end search (2) with the form starting at the other end (torsion can put the
    /// larger angle at the end where the curvature is smaller), and (3) in that order when
    /// the first has no segment at Ω = 0. The refusal reports how far in Ω the branch of (3)
    /// got. Segments found by (1) move continuously with the input while the near-helix
    /// start stays in their basin; for dragging, where the answer should follow the previous
    /// one, use [`SpaceSegment::from_control_points_near`].
    pub fn from_control_points(points: [Vec3; 4], shape: SpaceShape) -> Result<SpaceSegment> {
        Self::solve(points, shape, None)
    }

    /// [`SpaceSegment::from_control_points`] with a warm start: first Newton's method on
    /// (Λ, ln ν, s) from `previous`'s standard form and length (same α, β, type and end
    /// order), which follows the segment continuously as the points or Ω move a little (an
    /// editor's drag) and takes a few integrations instead of a search; the cold search
    /// when that does not converge or `previous` does not match (planar, other slopes or
    /// type). The warm start keeps `previous`'s order of the ends.
    pub fn from_control_points_near(
        points: [Vec3; 4],
        shape: SpaceShape,
        previous: &SpaceSegment,
    ) -> Result<SpaceSegment> {
        let start = match &previous.solved {
            Found::Space {
                form,
                s_end,
                transform,
                ..
            } if form.alpha() == shape.alpha
                && form.beta() == shape.beta
                && form.torsion_type() == shape.torsion =>
            {
                Some(WarmStart {
                    solution: Solution {
                        lambda: form.lambda(),
                        ln_nu: form.nu().ln(),
                    },
                    s_end: *s_end,
                    reversed: transform.reversed,
                })
            }
            _ => None,
        };
        Self::solve(points, shape, start)
    }

    fn solve(
        points: [Vec3; 4],
        shape: SpaceShape,
        warm: Option<WarmStart>,
    ) -> Result<SpaceSegment> {
        for p in &points {
            for c in p.to_array() {
                finite("control point coordinate", c)?;
            }
        }
        let SpaceShape {
            alpha, beta, omega, ..
        } = shape;
        finite("alpha", alpha)?;
        finite("beta", beta)?;
        finite("omega", omega)?;
        if omega < 0.0 {
            return Err(Error::OutOfRange {
                name: "omega",
                value: omega,
                expected: ">= 0 (the type sets the direction of the torsion radius)",
            });
        }
        for (first, second) in [(0, 1), (2, 3), (0, 3)] {
            if points[first] == points[second] {
                return Err(Error::CoincidentPoints { first, second });
            }
        }
        let [p0, p1, p2, p3] = points;
        if ![p1 - p0, p2 - p1, p3 - p2, p3 - p0]
            .iter()
            .all(|d| d.is_finite() && d.length().is_finite())
        {
            return Err(Error::OutOfRange {
                name: "control points",
                value: f64::INFINITY,
                expected: "coordinates whose differences do not overflow",
            });
        }
        let t0 = (p1 - p0).normalize();
        let t1 = (p3 - p2).normalize();
        let chord = p3 - p0;
        let (theta0, theta1, theta2) = end_angles(chord, t0, t1);
        // A tangent along the chord line: no cone (seed 003 needs 0 < θ0, θ1 < π).
        for th in [theta0, theta1] {
            if !(1e-12..=std::f64::consts::PI - 1e-12).contains(&th) {
                return Err(Error::CollinearPoints);
            }
        }
        let off_plane = theta2.abs().min(std::f64::consts::PI - theta2.abs());
        let solved = if off_plane < PLANAR_TOLERANCE {
            planar(points, alpha, theta2)?
        } else {
            solve_space(points, shape, [theta0, theta1, theta2], warm)?
        };
        let arc_length = match &solved {
            Found::Space {
                s_end, transform, ..
            } => s_end * transform.scale,
            Found::Planar { segment, .. } => segment.arc_length(),
        };
        // The solver's last look: a length and end frames that double precision holds.
        let segment = SpaceSegment {
            points,
            shape,
            solved,
            arc_length,
        };
        let ends_finite = [0.0, arc_length].iter().all(|&s| {
            segment.frame_at_s(s).is_ok_and(|f| {
                [f.point, f.tangent, f.normal, f.binormal]
                    .iter()
                    .all(|v| v.is_finite())
                    && f.curvature.is_finite()
                    && f.torsion.is_finite()
            })
        });
        if !(arc_length.is_finite() && arc_length > 0.0 && ends_finite) {
            return Err(Error::Unrepresentable {
                what: "arc length or end frames",
            });
        }
        Ok(segment)
    }

    /// The control points `[P0, P1, P2, P3]`.
    pub fn control_points(&self) -> [Vec3; 4] {
        self.points
    }
    /// The shape asked for: α, β, Ω and type.
    pub fn shape(&self) -> SpaceShape {
        self.shape
    }
    /// Slope of the logarithmic curvature graph.
    pub fn alpha(&self) -> f64 {
        self.shape.alpha
    }
    /// Slope of the logarithmic torsion graph.
    pub fn beta(&self) -> f64 {
        self.shape.beta
    }
    /// The torsion parameter Ω asked for.
    pub fn omega(&self) -> f64 {
        self.shape.omega
    }
    /// Type 1 or 2.
    pub fn torsion_type(&self) -> TorsionType {
        self.shape.torsion
    }

    /// The solved standard form (with Λ and ν), `None` for a coplanar (planar) segment.
    pub fn standard_form(&self) -> Option<&SpaceForm> {
        match &self.solved {
            Found::Space { form, .. } => Some(form),
            Found::Planar { .. } => None,
        }
    }

    /// The standard-form arc length of the segment, `None` when planar.
    pub fn s_end(&self) -> Option<f64> {
        match &self.solved {
            Found::Space { s_end, .. } => Some(*s_end),
            Found::Planar { .. } => None,
        }
    }

    /// The similarity from the standard form to the caller's coordinates, `None` when
    /// planar.
    pub fn transform(&self) -> Option<&Similarity3> {
        match &self.solved {
            Found::Space { transform, .. } => Some(transform),
            Found::Planar { .. } => None,
        }
    }

    /// The planar segment drawn instead when the four points are coplanar, in the plane's
    /// coordinates: origin P0, x along `P1 − P0`, y toward the chord.
    pub fn planar(&self) -> Option<&Segment> {
        match &self.solved {
            Found::Planar { segment, .. } => Some(segment),
            Found::Space { .. } => None,
        }
    }

    /// Is this the planar fallback for coplanar points?
    pub fn is_planar(&self) -> bool {
        matches!(self.solved, Found::Planar { .. })
    }

    fn graph(
        &self,
        n: usize,
        rate: f64,
        point: impl Fn(&Frame) -> (f64, f64),
    ) -> Result<Vec<GraphPoint>> {
        let frames = self.sample_by_arc_length(n)?;
        if rate == 0.0 {
            return Ok(Vec::new());
        }
        Ok(frames
            .iter()
            .map(|f| {
                let (x, y) = point(f);
                GraphPoint { s: f.s, x, y }
            })
            .collect())
    }

    /// The frame at `s` in [0, arc length]; `series` keeps the last step's Taylor series.
    fn frame_unchecked(&self, s: f64, series: &mut Option<(usize, Expansion)>) -> Frame {
        match &self.solved {
            Found::Space {
                form,
                s_end,
                transform,
                checkpoints,
            } => {
                let st = if transform.reversed {
                    s_end - s / transform.scale
                } else {
                    s / transform.scale
                };
                let st = st.clamp(0.0, *s_end);
                let i = checkpoints.partition_point(|c| c.s <= st).saturating_sub(1);
                if series.as_ref().is_none_or(|(j, _)| *j != i) {
                    *series = Some((i, Expansion::new(form, &checkpoints[i])));
                }
                let (_, expansion) = series.as_ref().expect("just set");
                let state = expansion.state_at(st - checkpoints[i].s);
                let f = form.frame_from(&state);
                let sign = if transform.reversed { -1.0 } else { 1.0 };
                let tangent = transform.apply_vector(f.tangent) * sign;
                let normal = transform.apply_vector(f.normal);
                Frame {
                    s,
                    point: transform.apply(f.point),
                    tangent,
                    normal,
                    binormal: tangent.cross(normal),
                    curvature: f.curvature / transform.scale,
                    torsion: if transform.mirror_z { -1.0 } else { 1.0 } * f.torsion
                        / transform.scale,
                }
            }
            Found::Planar {
                segment,
                origin,
                e1,
                e2,
            } => {
                let station = segment.station_at_s(s).expect("s within the segment");
                let p = segment.point_of(&station);
                let theta = segment.theta_of(&station);
                let kappa = segment.kappa_of(&station);
                let tangent = *e1 * theta.cos() + *e2 * theta.sin();
                let left = *e1 * -theta.sin() + *e2 * theta.cos();
                let normal = left * kappa.signum();
                Frame {
                    s,
                    point: *origin + *e1 * p.x + *e2 * p.y,
                    tangent,
                    normal,
                    binormal: tangent.cross(normal),
                    curvature: kappa.abs(),
                    torsion: 0.0,
                }
            }
        }
    }
}

/// The planar fallback: the planar segment through P0, the tangents' intersection and P3.
fn planar(points: [Vec3; 4], alpha: f64, theta2: f64) -> Result<Found> {
    if theta2.abs() > std::f64::consts::FRAC_PI_2 {
        return Err(Error::InflectedPolygon {
            first: Turn::Left,
            second: Turn::Right,
        });
    }
    let [p0, p1, p2, p3] = points;
    let e1 = (p1 - p0).normalize();
    let chord = p3 - p0;
    let e2 = perpendicular(chord, e1);
    let to2 = |p: Vec3| Point::new((p - p0).dot(e1), (p - p0).dot(e2));
    // The last leg projected as a difference (exact for nearby points), not as the
    // difference of two projections: those cancel, and a leg 1e-12 of the coordinates long
    // would lose its direction to 1e-4 rad.
    let leg = p3 - p2;
    let (q3, d) = (to2(p3), kurbo::Vec2::new(leg.dot(e1), leg.dot(e2)));
    // P0 + a e1 = P3 − b d/|d|: the tangents' intersection, ahead of both ends.
    let d = d / d.x.hypot(d.y);
    let cross_d = d.y; // (1, 0) × d
    let a = (q3.x * d.y - q3.y * d.x) / cross_d;
    let b = q3.y / d.y;
    if !(a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite()) {
        return Err(Error::NotDrawable(NotDrawable::PlanarTangentsApart {
            turning: (p1 - p0).angle_to(p3 - p2),
            chord_angle: chord.angle_to(e1),
        }));
    }
    let segment = Segment::from_control_points([Point::ZERO, Point::new(a, 0.0), q3], alpha)?;
    Ok(Found::Planar {
        segment,
        origin: p0,
        e1,
        e2,
    })
}

/// Arc length from P0 to P3.
impl SpaceCurve for SpaceSegment {
    /// Arc length from P0 to P3.
    fn arc_length(&self) -> f64 {
        self.arc_length
    }

    /// Frames at many arc lengths at once, from P0 (the Taylor series of one integrator step
    /// serve all the arc lengths within it).
    fn frames(&self, s_values: &[f64]) -> Result<Vec<Frame>> {
        let len = self.arc_length;
        for &s in s_values {
            finite("s", s)?;
            if !(s >= -1e-12 * len && s <= len * (1.0 + 1e-12)) {
                return Err(Error::OutOfRange {
                    name: "s",
                    value: s,
                    expected: "an arc length between 0 and arc_length()",
                });
            }
        }
        // Consecutive arc lengths in one integrator step share its series.
        let mut series = None;
        Ok(s_values
            .iter()
            .map(|&s| self.frame_unchecked(s.clamp(0.0, len), &mut series))
            .collect())
    }

    /// The logarithmic curvature graph at `n ≥ 2` points equally spaced in arc length:
    /// `(ln ρ, ln(ρ |ds/dρ|))` in the caller's units, a straight line of slope α. Empty when
    /// ρ is constant (Λ = 0).
    fn log_curvature_graph(&self, n: usize) -> Result<Vec<GraphPoint>> {
        let (alpha, lambda, scale) = match &self.solved {
            Found::Space {
                form, transform, ..
            } => (form.alpha(), form.lambda(), transform.scale),
            Found::Planar { segment, .. } => (segment.alpha(), segment.lambda(), 1.0),
        };
        // dρ/ds = Λ ρ^(1−α) in standard units, so ρ ds/dρ = ρ^α / Λ; scaling by k
        // multiplies ρ and s by k (and ρ ds/dρ by k).
        self.graph(n, lambda, |f| {
            let rho = 1.0 / f.curvature;
            let rho_std = rho / scale;
            (rho.ln(), alpha * rho_std.ln() - lambda.ln() + scale.ln())
        })
    }

    /// The logarithmic torsion graph: `(ln μ, ln(μ |ds/dμ|))`, μ = 1/|τ|, a straight line of
    /// slope β. Empty when μ is constant (Ω = 0) or the segment is planar.
    fn log_torsion_graph(&self, n: usize) -> Result<Vec<GraphPoint>> {
        let scale = match &self.solved {
            Found::Space { transform, .. } => transform.scale,
            Found::Planar { .. } => return Ok(Vec::new()),
        };
        let (beta, omega) = (self.shape.beta, self.shape.omega);
        // |dμ/ds| = Ω μ^(1−β) in standard units.
        self.graph(n, omega, |f| {
            let mu = 1.0 / f.torsion.abs();
            let mu_std = mu / scale;
            (mu.ln(), beta * mu_std.ln() - omega.ln() + scale.ln())
        })
    }
}
