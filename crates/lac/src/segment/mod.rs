//! A log-aesthetic segment from three control points and α (docs/math.md §3, seed 000 §4).

use ::kurbo::{Point, Vec2};

use crate::family::chord_angle::{self, Solution};
use crate::family::lcg::LcgLine;
use crate::family::standard_form::integrate::integrate;
use crate::family::standard_form::{StandardForm, Station};
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::{clamp, Complex};
use crate::foundation::turn::Turn;

mod intrinsic;
mod kurbo;
pub(crate) mod sampling;
pub(crate) mod visible;

pub use kurbo::SegmentDerivative;
pub(crate) use kurbo::{central_difference, Travel};

/// The angles of a three-point control polygon (docs/math.md §3 steps 1 and 3).
#[derive(Clone)]
pub(crate) struct Triangle {
    /// Turning angle θd ∈ (0, π).
    pub(crate) turning: f64,
    /// The polygon's turning direction.
    pub(crate) turn: Turn,
    /// Direction of P1 − P0.
    pub(crate) theta_first: f64,
    /// Angle at P0 between P1 − P0 and P2 − P0, in (0, θd).
    pub(crate) theta_e: f64,
}

/// The vector scaled by a power of two (exactly) so that the cross and dot products of two
/// such vectors neither overflow nor lose digits to underflow: unchanged when its largest
/// component is within 2^±[`SAFE_EXPONENT`] already (the usual case), else scaled to a
/// largest component in [1, 2).
pub(crate) fn normalized(w: Vec2) -> Vec2 {
    let largest = w.x.abs().max(w.y.abs());
    if !(largest.is_finite() && largest > 0.0) {
        return w;
    }
    let k = if largest >= f64::MIN_POSITIVE {
        // The exponent of a normal number, from its bits.
        ((largest.to_bits() >> 52) as i32) - 1023
    } else {
        largest.log2().floor() as i32
    };
    if k.abs() <= SAFE_EXPONENT {
        return w;
    }
    // 2^(−k) applied in two halves, each a normal number even for k near ±1074.
    let power = |e: i32| f64::from_bits(((1023 + e) as u64) << 52);
    (w * power(-(k / 2))) * power(-(k - k / 2))
}

/// Vectors whose largest component lies within 2^±`SAFE_EXPONENT` multiply without
/// overflow, and the product of their largest components is at least 2^−800: a term that
/// underflows (below 2^−1022) is then under 2^−222 of it, far below rounding.
const SAFE_EXPONENT: i32 = 400;

/// Is the length of `w` finite? (Its components may be finite while it overflows.)
pub(crate) fn finite_length(w: Vec2) -> bool {
    let largest = w.x.abs().max(w.y.abs());
    // Below 1e300 the length is at most √2 × 1e300; std's hypot only beyond (kurbo's
    // squares the components, which overflows from 1e154 on).
    largest < 1e300 || (largest.is_finite() && w.x.hypot(w.y).is_finite())
}

/// Is `u` longer than `v`? (Both of finite length.)
fn longer(u: Vec2, v: Vec2) -> bool {
    let largest = u.x.abs().max(u.y.abs()).max(v.x.abs()).max(v.y.abs());
    if (1e-140..1e140).contains(&largest) {
        // No square underflows to nothing that matters, none overflows.
        u.hypot2() > v.hypot2()
    } else {
        u.x.hypot(u.y) > v.x.hypot(v.y)
    }
}

/// The slope α, checked: finite and |α| ≤ [`MAX_ABS_ALPHA`].
pub(crate) fn check_alpha(name: &'static str, alpha: f64) -> Result<f64> {
    finite(name, alpha)?;
    if alpha.abs() > MAX_ABS_ALPHA {
        return Err(Error::OutOfRange {
            name,
            value: alpha,
            expected: "a slope with |alpha| <= 1e6 (segments hardly change beyond it, and \
                       rho^alpha overflows)",
        });
    }
    Ok(alpha)
}

/// The largest |α| accepted. Segments converge as |α| grows (for one triangle the largest
/// chord angle a segment can make changes by 2.5e-5 rad from |α| = 1e4 to 1e6), and far
/// beyond it ρ^α overflows.
pub const MAX_ABS_ALPHA: f64 = 1e6;

/// Validate three control points and measure their triangle.
pub(crate) fn control_triangle(points: [Point; 3]) -> Result<Triangle> {
    const NAMES: [[&str; 2]; 3] = [["P0.x", "P0.y"], ["P1.x", "P1.y"], ["P2.x", "P2.y"]];
    for (p, names) in points.iter().zip(NAMES) {
        finite(names[0], p.x)?;
        finite(names[1], p.y)?;
    }
    for (i, j) in [(0, 1), (1, 2), (0, 2)] {
        if points[i] == points[j] {
            return Err(Error::CoincidentPoints {
                first: i,
                second: j,
            });
        }
    }
    let [p0, p1, p2] = points;
    let (u, v, c) = (p1 - p0, p2 - p1, p2 - p0);
    if ![u, v, c].into_iter().all(finite_length) {
        return Err(Error::OutOfRange {
            name: "control points",
            value: f64::INFINITY,
            expected: "coordinates whose differences do not overflow",
        });
    }
    // Angles only: scale each vector by its own power of two (exactly) to a magnitude near
    // 1, so that cross and dot products neither underflow nor overflow, whatever the
    // coordinates (~1e-160 or ~1e+160) and however unlike the legs (1 against 1e+160: one
    // scale for all would leave products of the short ones subnormal, a few digits).
    let [u, v, c] = [u, v, c].map(normalized);
    let cross = u.cross(v);
    let turning = cross.abs().atan2(u.dot(v));
    if !(turning > 1e-13 && turning < std::f64::consts::PI - 1e-13) {
        return Err(Error::CollinearPoints);
    }
    Ok(Triangle {
        turning,
        turn: if cross > 0.0 { Turn::Left } else { Turn::Right },
        theta_first: u.atan2(),
        theta_e: u.cross(c).abs().atan2(u.dot(c)),
    })
}

/// A segment solved from its control points but not yet built: its end curvatures and
/// their derivatives for a solver that iterates on control points (a path's G2 joints),
/// and the segment itself once that solver is done, without solving again.
#[derive(Clone)]
pub(crate) struct SegmentSolution {
    points: [Point; 3],
    alpha: f64,
    tri: Triangle,
    /// The standard-form piece, solved from the shorter leg (docs/math.md §3 step 2: there the
    /// chord angle is at least θd/2), with its μ; `reversed` when that is the last leg, so
    /// the piece runs from P2 to P0.
    solution: Solution,
    reversed: bool,
    /// The chord angle asked of the piece.
    theta_e: f64,
}

impl SegmentSolution {
    /// Solve the segment on `points` with slope `alpha` (not checked: see
    /// [`Segment::from_control_points`]).
    pub(crate) fn new(points: [Point; 3], alpha: f64) -> Result<SegmentSolution> {
        Self::near(points, alpha, (None, false))
    }

    /// [`SegmentSolution::new`], the chord-angle search started at μ = `hint.0` when given
    /// (the [`SegmentSolution::mu`] of a nearby triangle's solution), and with `hint.1`
    /// stopped loosely, for a difference quotient (see `chord_angle::solve_near`).
    pub(crate) fn near(
        points: [Point; 3],
        alpha: f64,
        hint: (Option<f64>, bool),
    ) -> Result<SegmentSolution> {
        let arranged = Self::arrange(points)?;
        let solution = chord_angle::solve_near(alpha, arranged.0.turning, arranged.2, hint)?;
        Ok(Self::with(points, alpha, arranged, solution))
    }

    /// The solution's μ, a hint for a nearby triangle's.
    pub(crate) fn mu(&self) -> f64 {
        self.solution.mu
    }

    /// The segment on `points`, arranged by [`SegmentSolution::arrange`], with its piece.
    fn with(
        points: [Point; 3],
        alpha: f64,
        (tri, reversed, theta_e): (Triangle, bool, f64),
        solution: Solution,
    ) -> SegmentSolution {
        SegmentSolution {
            points,
            alpha,
            tri,
            solution,
            reversed,
            theta_e,
        }
    }

    /// The triangle of `points`, whether the piece is solved from the last leg, and the
    /// chord angle asked of it there.
    fn arrange(points: [Point; 3]) -> Result<(Triangle, bool, f64)> {
        let tri = control_triangle(points)?;
        let (u, v) = (points[1] - points[0], points[2] - points[1]);
        let reversed = longer(u, v);
        let theta_e = if reversed {
            tri.turning - tri.theta_e
        } else {
            tri.theta_e
        };
        let theta_e = theta_e.max(0.5 * tri.turning);
        Ok((tri, reversed, theta_e))
    }

    /// The segment on `points` with slope `alpha`, not solved: its piece taken at the
    /// chord-angle search's first guess (see [`SegmentSolution::advanced`]).
    pub(crate) fn guessed(points: [Point; 3], alpha: f64) -> Option<SegmentSolution> {
        let arranged = Self::arrange(points).ok()?;
        let (turning, theta_e) = (arranged.0.turning, arranged.2);
        if theta_e - 0.5 * turning <= 1e-6 * turning {
            return None;
        }
        let solution = chord_angle::eval_at_guess(alpha, turning, theta_e)?;
        Some(Self::with(points, alpha, arranged, solution))
    }

    /// The segment on `points` (this one's control points moved, with the same vertex
    /// angle), not solved: its piece taken once at the μ that this one's derivatives
    /// predict, for a solver that iterates on μ and on the control points together (its
    /// chord angle misses by [`SegmentSolution::chord_angle_miss`]). `None` where that prediction
    /// is not to be trusted (the piece would be solved from the other leg, or next to the
    /// circular arc of equal legs); then solve it with [`SegmentSolution::new`]. The share `step` of
    /// this one's own miss is corrected (1 for a whole Newton step, less for a damped one).
    pub(crate) fn advanced(&self, points: [Point; 3], step: f64) -> Option<SegmentSolution> {
        let arranged = Self::arrange(points).ok()?;
        let (turning, reversed, theta_e) = (arranged.0.turning, arranged.1, arranged.2);
        let sens = self.solution.sensitivity?;
        let clear = theta_e - 0.5 * turning > 1e-6 * turning
            && self.theta_e - 0.5 * self.tri.turning > 1e-6 * self.tri.turning;
        if reversed != self.reversed || !clear {
            return None;
        }
        let miss = step * self.solution.g;
        let mu = self.solution.mu + sens.dmu_dtheta_e * (theta_e - self.theta_e - miss);
        let solution = chord_angle::eval_at(self.alpha, turning, theta_e, mu)?;
        Some(Self::with(points, self.alpha, arranged, solution))
    }

    /// How far the piece's chord angle is from the one asked for (radians; rounding when
    /// solved by [`SegmentSolution::new`]).
    pub(crate) fn chord_angle_miss(&self) -> f64 {
        self.solution.g
    }

    /// d ln|κ|/dμ at the first and the other end of the piece (in the order it was
    /// solved), at fixed control points: ln κ_std by 0 and −1 per μ (+1 and 0 for α > 1),
    /// and the scale by d ln|P_std|/dμ.
    fn per_mu(&self) -> Option<[f64; 2]> {
        let q = self.solution.sensitivity?.dln_chord_dmu;
        let (at_start, at_end) = if self.alpha > 1.0 {
            (1.0, 0.0)
        } else {
            (0.0, -1.0)
        };
        Some([at_start + q, at_end + q])
    }

    /// The first-order change of ln|κ0| and ln|κ1| when μ is brought to the solution of
    /// the chord-angle equation at these control points (zero for a solved segment, to
    /// rounding).
    pub(crate) fn log_corrections(&self) -> Option<[f64; 2]> {
        let sens = self.solution.sensitivity?;
        let [first, other] = self.per_mu()?;
        let dmu = -self.solution.g * sens.dmu_dtheta_e;
        let out = if self.reversed {
            [other * dmu, first * dmu]
        } else {
            [first * dmu, other * dmu]
        };
        out.iter().all(|d| d.is_finite()).then_some(out)
    }

    /// The control points.
    pub(crate) fn points(&self) -> [Point; 3] {
        self.points
    }

    /// The signed curvature at the first and last control point.
    pub(crate) fn end_curvatures(&self) -> Result<(f64, f64)> {
        let piece = &self.solution.piece;
        let (first, last) = if self.reversed {
            (piece.end, piece.start)
        } else {
            (piece.start, piece.end)
        };
        let c = self.points[2] - self.points[0];
        let scale = c.x.hypot(c.y) / piece.chord.norm();
        let k = |st: &Station| self.tri.turn.sign() * st.kappa() / scale;
        let out = (k(&first), k(&last));
        if out.0.is_finite() && out.1.is_finite() && out.0 != 0.0 && out.1 != 0.0 {
            Ok(out)
        } else {
            Err(Error::Unrepresentable {
                what: "curvature (it scales as 1/length)",
            })
        }
    }

    /// With a = |P1 − P0|, b = |P2 − P1| and the last point moved along its leg:
    /// d(ln|κ0| + ln a)/d ln(a/b) and d(ln|κ1| + ln b)/d ln(a/b), exactly (from the
    /// chord-angle solution's own derivatives), or `None` where they are not numbers.
    ///
    /// With the leg the piece was solved from of length f, the other o, ρ = o/f and
    /// C = |P2 − P0|/f = √(1 + 2ρ cos θd + ρ²): the chord angle at the first point is
    /// θe = atan2(ρ sin θd, 1 + ρ cos θd), so dθe/d ln ρ = ρ sin θd/C²; the end curvatures
    /// are κ = κ_std |P_std|/|P2 − P0|, so ln|κ| + ln f = ln κ_std + ln|P_std| − ln C (plus
    /// ln ρ at the other end), with d ln C/d ln ρ = ρ(cos θd + ρ)/C². Of the piece, μ moves
    /// with θe by 1/(dφ/dμ), ln κ_std at its ends by 0 and −1 per μ (+1 and 0 for α > 1),
    /// and ln|P_std| by Re(P′/P) dΛ/dμ.
    pub(crate) fn log_slopes(&self) -> Option<[f64; 2]> {
        let sens = self.solution.sensitivity?;
        let [p0, p1, p2] = self.points;
        let (u, v) = (p1 - p0, p2 - p1);
        let (first, other) = if self.reversed { (v, u) } else { (u, v) };
        let rho = other.x.hypot(other.y) / first.x.hypot(first.y);
        let (sin, cos) = self.tri.turning.sin_cos();
        let c2 = 1.0 + 2.0 * rho * cos + rho * rho;
        let dtheta_e = rho * sin / c2;
        let dln_c = rho * (cos + rho) / c2;
        let [first_mu, other_mu] = self.per_mu()?;
        let mu_per_rho = sens.dmu_dtheta_e * dtheta_e;
        // d/d ln ρ of the first and the other end's ln|κ| + ln(leg).
        let d_first = first_mu * mu_per_rho - dln_c;
        let d_other = other_mu * mu_per_rho - dln_c + 1.0;
        // ln(a/b) is −ln ρ when the piece was solved from P0's leg, +ln ρ from P2's.
        let out = if self.reversed {
            [d_other, d_first]
        } else {
            [-d_first, -d_other]
        };
        out.iter().all(|d| d.is_finite()).then_some(out)
    }

    /// d ln|κ0| and d ln|κ1| with respect to the triangle's angles at P0 and at P2 (between
    /// each leg and the chord) and to ln|P2 − P0|, exactly, from the solution's own
    /// derivatives: `None` for α ≥ 1, next to the circular arc of equal legs, or where they
    /// are not numbers.
    ///
    /// The piece runs from its reference point (ρ = 1) at the end it was solved from, whose
    /// angle is θe, over θd = θe + θo. At fixed μ, Λ = μ·(1 − e^{−(1−α)μ})/((1−α)μ θd) falls as
    /// 1/θd and the far end keeps ln ρ = μ, so ∂ln P/∂θd = ρ_far e^{iθd}/P − (Λ/θd) P′/P
    /// =: R, with P′/P = (d ln|P|/dμ + i dφ/dμ)/(dΛ/dμ). The chord-angle equation φ = θe
    /// then moves μ by (dθe − Im R dθd)/(dφ/dμ), and ln|κ| = ln κ_std + ln|P| − ln|P2 − P0|
    /// with ln κ_std 0 at the reference end and −μ at the far one, ln|P| by
    /// (d ln|P|/dμ) dμ + Re R dθd.
    pub(crate) fn angle_slopes(&self) -> Option<[[f64; 3]; 2]> {
        Some(self.slopes()?.0)
    }

    /// dμ with respect to the triangle's angles at P0 and at P2 (see
    /// [`SegmentSolution::angle_slopes`]): a first guess of μ for a nearby triangle.
    pub(crate) fn mu_slopes(&self) -> Option<[f64; 2]> {
        Some(self.slopes()?.1)
    }

    /// [`SegmentSolution::angle_slopes`] and [`SegmentSolution::mu_slopes`].
    fn slopes(&self) -> Option<([[f64; 3]; 2], [f64; 2])> {
        let sens = self.solution.sensitivity?;
        let turning = self.tri.turning;
        if self.alpha >= 1.0 || self.theta_e - 0.5 * turning <= 1e-6 * turning {
            return None;
        }
        let piece = &self.solution.piece;
        let (mu, lambda) = (self.solution.mu, piece.form.lambda);
        let slope = 1.0 / sens.dmu_dtheta_e;
        let q = sens.dln_chord_dmu;
        // dΛ/dμ = e^{−(1−α)μ}/θd.
        let dlambda_dmu = (-(1.0 - self.alpha) * mu).exp() / turning;
        let p_ratio = Complex::new(q, slope).scale(1.0 / dlambda_dmu);
        let far = Complex::cis(piece.end.theta).scale(piece.end.ln_rho.exp());
        let r = far.div(piece.chord) - p_ratio.scale(lambda / turning);
        // d/dθs (the end solved from) and d/dθo (the other), θd = θs + θo.
        let dmu = [(1.0 - r.im) / slope, -r.im / slope];
        let dln_p = [q * dmu[0] + r.re, q * dmu[1] + r.re];
        let solved = [dln_p[0], dln_p[1], -1.0];
        let other = [dln_p[0] - dmu[0], dln_p[1] - dmu[1], -1.0];
        // In the triangle's order: angles at (P0, P2), then ln|P2 − P0|.
        let by_ends = |d: [f64; 3]| if self.reversed { [d[1], d[0], d[2]] } else { d };
        let (solved, other) = (by_ends(solved), by_ends(other));
        let out = if self.reversed {
            [other, solved]
        } else {
            [solved, other]
        };
        let dmu = by_ends([dmu[0], dmu[1], 0.0]);
        let dmu = [dmu[0], dmu[1]];
        (out.iter().flatten().chain(&dmu).all(|d| d.is_finite())).then_some((out, dmu))
    }

    /// The segment, checked.
    pub(crate) fn into_segment(self) -> Result<Segment> {
        let SegmentSolution {
            points,
            alpha,
            tri,
            solution,
            reversed,
            ..
        } = self;
        let piece = solution.piece;
        let (first, last, chord) = if reversed {
            (piece.end, piece.start, -piece.chord)
        } else {
            (piece.start, piece.end, piece.chord)
        };
        // The standard form turns left along increasing θ; traversed backwards it turns right.
        let mirrored = (tri.turn == Turn::Left) == reversed;
        let c = points[2] - points[0];
        let c = Complex::new(c.x, if mirrored { -c.y } else { c.y });
        let placement = Placement {
            origin: points[0],
            rot: c.div(chord),
            mirrored,
            turn: tri.turn,
            theta_first: tri.theta_first,
        };
        let segment = Segment::new(alpha, piece.form, [first, last], chord, placement);
        segment.check()?;
        crate::segment::visible::check_visible_ends(std::slice::from_ref(&segment))?;
        Ok(segment)
    }
}

/// The signed end curvatures of the segment on `points` with slope `alpha`, without
/// building or checking it: for solvers that iterate on them (a path's G2 joints), whose
/// final answer is built by [`Segment::from_control_points`] and checked there.
pub(crate) fn end_curvatures_of(points: [Point; 3], alpha: f64) -> Result<(f64, f64)> {
    SegmentSolution::new(points, alpha)?.end_curvatures()
}

/// A planar log-aesthetic curve segment defined like a quadratic Bézier curve: it starts
/// at `P0` tangent to `P1 − P0` and ends at `P2` tangent to `P2 − P1` (seed 000 §4.1).
///
/// It is a piece of a [`StandardForm`] curve with the tangent-angle range [0, θd]
/// (α ≤ 1) or [−θd, 0] (α > 1), θd the turning angle of the control polygon, mapped by a
/// similarity (and a reflection for right turns) onto the control points. Λ is found so that
/// the piece's chord makes the same angle with its start tangent as `P2 − P0` makes with
/// `P1 − P0` at the end with the shorter leg.
///
/// Arc length `s` runs from 0 at `P0` to [`Curve::arc_length`](crate::Curve::arc_length) at `P2`; `theta` is the
/// tangent direction in the caller's frame, starting at the direction of `P1 − P0` and
/// continuous along the curve; curvature is signed, positive for a left turn.
///
/// ```
/// use kurbo::Point;
/// use lac::{Curve, Segment};
///
/// // A clothoid (α = −1) segment.
/// let seg = Segment::from_control_points(
///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.6, 0.9)],
///     -1.0,
/// )?;
/// let samples = seg.sample_by_arc_length(65)?;
/// assert_eq!(samples.len(), 65);
/// assert!((samples[64].point - Point::new(1.6, 0.9)).hypot() < 1e-12);
/// // Curvature varies monotonically along a log-aesthetic segment.
/// assert!(samples.windows(2).all(|w| w[1].kappa >= w[0].kappa)
///     || samples.windows(2).all(|w| w[1].kappa <= w[0].kappa));
/// # Ok::<(), lac::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Segment {
    alpha: f64,
    form: StandardForm,
    /// Standard-form stations at the caller's first and last point.
    first: Station,
    last: Station,
    /// P(last) − P(first) in the standard form.
    chord: Complex,
    /// The caller's first point.
    origin: Point,
    /// caller = origin + M(rot · (P − P(first))), M = conjugation when `mirrored`.
    rot: Complex,
    /// |rot|: standard-form lengths to the caller's.
    scale: f64,
    mirrored: bool,
    /// The caller's curve turns left (positive curvature) or right.
    turn: Turn,
    /// Tangent direction at the first point, radians.
    theta_first: f64,
    /// Turning angle θd = |θ(last) − θ(first)|.
    turning: f64,
}

/// Where a standard-form piece lies in the caller's plane: the similarity (and reflection)
/// `caller = origin + M(rot · (P − P(first)))`, and the caller's turning direction and start
/// tangent.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Placement {
    /// The caller's first point.
    pub(crate) origin: Point,
    /// Rotation and scale, as a complex factor.
    pub(crate) rot: Complex,
    /// Whether M is the conjugation (the caller's curve is the mirror image).
    pub(crate) mirrored: bool,
    /// The caller's turning direction.
    pub(crate) turn: Turn,
    /// Tangent direction at the first point, radians.
    pub(crate) theta_first: f64,
}

impl Segment {
    /// Solve for the segment with control points `points = [P0, P1, P2]` and slope `alpha`.
    ///
    /// Errors: non-finite input ([`Error::NonFinite`]), coincident or collinear control
    /// points, or [`Error::NotDrawable`] when no segment of this α fits the triangle.
    pub fn from_control_points(points: [Point; 3], alpha: f64) -> Result<Segment> {
        check_alpha("alpha", alpha)?;
        SegmentSolution::new(points, alpha)?.into_segment()
    }

    /// The one constructor: the piece of `form` from station `ends[0]` to `ends[1]` (in the
    /// caller's order; `chord` = P(ends[1]) − P(ends[0]) in the standard form), placed by
    /// `placement`.
    pub(crate) fn new(
        alpha: f64,
        form: StandardForm,
        [first, last]: [Station; 2],
        chord: Complex,
        placement: Placement,
    ) -> Segment {
        Segment {
            alpha,
            form,
            first,
            last,
            chord,
            origin: placement.origin,
            rot: placement.rot,
            scale: placement.rot.norm(),
            mirrored: placement.mirrored,
            turn: placement.turn,
            theta_first: placement.theta_first,
            turning: (last.theta - first.theta).abs(),
        }
    }

    /// A solver's last look at its answer before returning it: every number finite, a
    /// positive scale and length, and finite non-zero end curvatures.
    pub(crate) fn check(&self) -> Result<()> {
        let stations = [self.first, self.last];
        let numbers = stations
            .iter()
            .flat_map(|st| [st.theta, st.s, st.ln_rho])
            .chain([
                self.alpha,
                self.form.lambda,
                self.chord.re,
                self.chord.im,
                self.theta_first,
            ]);
        let (k0, k1) = self.end_curvatures();
        if !numbers.into_iter().all(f64::is_finite) {
            return Err(Error::NumericalFailure {
                what: "the solved segment (a number overflowed or is not finite)",
            });
        }
        // The standard-form piece is fine; its similarity to the caller's points (and so
        // its length) can still leave double range for points near 1e308.
        let placed = [self.rot.re, self.rot.im, self.scale, self.length()];
        if !(placed.iter().all(|x| x.is_finite()) && self.scale > 0.0 && self.length() > 0.0) {
            return Err(Error::Unrepresentable { what: "arc length" });
        }
        // Curvature is 1/length: for curves near 1e308 (or 1e-308) in size it leaves the
        // range of double precision.
        if ![k0, k1].iter().all(|k| k.is_finite() && *k != 0.0) {
            return Err(Error::Unrepresentable {
                what: "curvature (it scales as 1/length)",
            });
        }
        // Where the curvature varies by more than a million, points are placed by integrals
        // over tangent-angle steps that can fall below the resolution of θ: check that the
        // two ends agree on the points between them.
        let ratio = (k1 / k0).abs();
        if !(1e-6..=1e6).contains(&ratio) {
            let chord = self.chord.norm();
            for u in [0.1, 0.5, 0.9] {
                let st = self.station_at_s(u * self.length())?;
                let from_first = self.span(&self.first, &st);
                let from_last = self.chord - self.span(&st, &self.last);
                let disagree = (from_first - from_last).norm_max();
                if disagree.is_nan() || disagree > 1e-9 * chord {
                    return Err(Error::Unrepresentable {
                        what: "points (the curvature varies too much for the tangent angle \
                               to place them)",
                    });
                }
            }
        }
        Ok(())
    }

    /// The placement of this segment (to place a neighbour built on the same standard form).
    pub(crate) fn placement(&self) -> Placement {
        Placement {
            origin: self.origin,
            rot: self.rot,
            mirrored: self.mirrored,
            turn: self.turn,
            theta_first: self.theta_first,
        }
    }

    /// The slope α of the logarithmic curvature graph.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The Λ of the solved standard-form piece (ρ = 1 at the end that stays regular).
    pub fn lambda(&self) -> f64 {
        self.form.lambda
    }

    /// The standard-form curve this segment is a similar copy of.
    pub fn standard_form(&self) -> StandardForm {
        self.form
    }

    /// The turning angle θd of the control polygon, in (0, π) (for a piece of a compound
    /// curve, the piece's own turning).
    pub fn turning_angle(&self) -> f64 {
        self.turning
    }

    /// Which way the segment turns.
    pub fn turn(&self) -> Turn {
        self.turn
    }

    /// Is this an exact circular arc (isosceles control triangle, Λ = 0)?
    pub fn is_circle(&self) -> bool {
        self.form.lambda == 0.0
    }

    /// The control points `[P0, P1, P2]`: the ends and the intersection of the end tangents.
    pub fn control_points(&self) -> [Point; 3] {
        let p0 = self.origin;
        let p2 = self.caller_point(self.chord);
        let t0 = Vec2::from_angle(self.theta_first);
        let t1 = Vec2::from_angle(self.theta_of(&self.last));
        // P1 = P0 + a t0 with (P2 − P0 − a t0) × t1 = 0.
        let a = (p2 - p0).cross(t1) / t0.cross(t1);
        [p0, p0 + a * t0, p2]
    }

    /// Arc length at which the tangent direction is `theta` (caller's frame, between
    /// the start direction and the start direction ± θd).
    pub fn s_at_theta(&self, theta: f64) -> Result<f64> {
        Ok(self.s_of(&self.station_at_theta(theta)?))
    }

    /// Point where the tangent direction is `theta`.
    pub fn point_at_theta(&self, theta: f64) -> Result<Point> {
        Ok(self.point_of(&self.station_at_theta(theta)?))
    }

    /// Signed curvature where the tangent direction is `theta`.
    pub fn signed_curvature_at_theta(&self, theta: f64) -> Result<f64> {
        Ok(self.kappa_of(&self.station_at_theta(theta)?))
    }

    /// The segment's logarithmic curvature graph, or `None` for a circular arc (Λ = 0,
    /// where ρ is constant and the graph degenerates to a point at infinity).
    ///
    /// ```
    /// use kurbo::Point;
    /// use lac::Segment;
    /// let seg = Segment::from_control_points(
    ///     [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.5, 1.0)], -1.0)?;
    /// let lcg = seg.lcg().unwrap();
    /// assert_eq!(lcg.alpha, -1.0);
    /// # Ok::<(), lac::Error>(())
    /// ```
    pub fn lcg(&self) -> Option<LcgLine> {
        let lambda = self.form.lambda;
        if lambda <= 0.0 {
            return None;
        }
        let ln_scale = self.scale.ln();
        Some(LcgLine {
            alpha: self.alpha,
            intercept: (1.0 - self.alpha) * ln_scale - lambda.ln(),
            log_rho: (ln_scale + self.first.ln_rho, ln_scale + self.last.ln_rho),
        })
    }

    // The primitives the `Curve` trait, the sampling and the Bézier fits are built on.

    /// Scale factor from standard-form lengths to the caller's.
    #[inline]
    pub(crate) fn scale(&self) -> f64 {
        self.scale
    }

    /// Arc length from the first to the last point.
    pub(crate) fn length(&self) -> f64 {
        (self.last.s - self.first.s).abs() * self.scale
    }

    /// Signed curvature at the first (`Which::First`) or last point.
    pub(crate) fn end_curvatures(&self) -> (f64, f64) {
        (self.kappa_of(&self.first), self.kappa_of(&self.last))
    }

    /// The first point.
    pub(crate) fn first_point(&self) -> Point {
        self.origin
    }

    /// The last point.
    pub(crate) fn last_point(&self) -> Point {
        self.caller_point(self.chord)
    }

    /// +1 along increasing standard-form θ, −1 when the caller's direction is reversed.
    #[inline]
    pub(crate) fn dir(&self) -> f64 {
        if self.last.theta >= self.first.theta {
            1.0
        } else {
            -1.0
        }
    }

    /// The station at arc length `s` ∈ [0, length] (checked by the caller, see
    /// `curve::locate`), anchored at the nearer end: near a singular end its ρ is known
    /// exactly.
    pub(crate) fn station_at_s(&self, s: f64) -> Result<Station> {
        let len = self.length();
        let s = clamp(s, 0.0, len);
        let k = self.dir() / self.scale;
        let st = if s <= 0.5 * len {
            self.form.advance_s(&self.first, k * s)
        } else {
            self.form.advance_s(&self.last, -k * (len - s))
        };
        st.ok_or(Error::NumericalFailure {
            what: "the station at an arc length of the segment",
        })
    }

    pub(crate) fn station_at_theta(&self, theta: f64) -> Result<Station> {
        finite("theta", theta)?;
        let turn = self.turn.sign() * (theta - self.theta_first);
        let slack = 1e-12 * self.turning;
        if !(turn >= -slack && turn <= self.turning + slack) {
            return Err(Error::OutOfRange {
                name: "theta",
                value: theta,
                expected: "a tangent direction between those at the two ends of the segment",
            });
        }
        self.station_at_turning(turn)
    }

    /// The station where the tangent has turned by `turn` ∈ [0, θd] from the first point.
    pub(crate) fn station_at_turning(&self, turn: f64) -> Result<Station> {
        let turn = clamp(turn, 0.0, self.turning);
        let st = if turn <= 0.5 * self.turning {
            self.form.advance_theta(&self.first, self.dir() * turn)
        } else {
            self.form
                .advance_theta(&self.last, -self.dir() * (self.turning - turn))
        };
        st.ok_or(Error::NumericalFailure {
            what: "the station at a tangent angle of the segment",
        })
    }

    /// P(b) − P(a) in the standard form.
    fn span(&self, a: &Station, b: &Station) -> Complex {
        if a.theta <= b.theta {
            integrate(&self.form, a, b, false).value
        } else {
            -integrate(&self.form, b, a, false).value
        }
    }

    /// P(st) − P(first) in the standard form, integrating from the nearer end.
    pub(crate) fn offset_of(&self, st: &Station) -> Complex {
        if *st == self.first {
            return Complex::ZERO;
        }
        if (st.theta - self.first.theta).abs() <= (self.last.theta - st.theta).abs() {
            self.span(&self.first, st)
        } else {
            self.chord - self.span(st, &self.last)
        }
    }

    pub(crate) fn caller_point(&self, offset: Complex) -> Point {
        let z = self.rot * offset;
        let z = if self.mirrored { z.conj() } else { z };
        Point::new(self.origin.x + z.re, self.origin.y + z.im)
    }

    pub(crate) fn point_of(&self, st: &Station) -> Point {
        self.caller_point(self.offset_of(st))
    }

    pub(crate) fn kappa_of(&self, st: &Station) -> f64 {
        self.turn.sign() * st.kappa() / self.scale
    }

    pub(crate) fn theta_of(&self, st: &Station) -> f64 {
        self.theta_first + self.turn.sign() * (st.theta - self.first.theta).abs()
    }

    pub(crate) fn s_of(&self, st: &Station) -> f64 {
        (st.s - self.first.s).abs() * self.scale
    }

    /// dκ/ds at a station: with ρ the standard-form radius and σ the scale,
    /// dκ/ds = −sign(κ)·dir·Λ ρ^(−1−α) / σ².
    pub(crate) fn dkappa_ds_of(&self, ln_rho: f64) -> f64 {
        let scale = self.scale;
        -self.turn.sign() * self.dir() * self.form.lambda * (-(1.0 + self.alpha) * ln_rho).exp()
            / (scale * scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The control points of the triangle on a chord of length `c` whose legs make the
    /// angles `t0` at P0 and `t2` at P2 with it.
    fn triangle(t0: f64, t2: f64, c: f64) -> [Point; 3] {
        let u = c * t2.sin() / (t0 + t2).sin();
        [
            Point::ORIGIN,
            Point::new(u * t0.cos(), u * t0.sin()),
            Point::new(c, 0.0),
        ]
    }

    /// ln|κ0| and ln|κ1| of the solved segment.
    fn ln_kappa(p: [Point; 3], alpha: f64) -> [f64; 2] {
        let (k0, k1) = SegmentSolution::new(p, alpha)
            .unwrap()
            .end_curvatures()
            .unwrap();
        [k0.abs().ln(), k1.abs().ln()]
    }

    /// The exact slopes (of ln|κ| and μ) by the triangle's angles and chord agree with
    /// central differences of solved segments (h = 1e-5: their error about 1e-10), either leg solved from.
    #[test]
    fn angle_slopes_agree_with_differences() {
        let h = 1e-5;
        let mut checked = 0;
        for alpha in [-1.0, -0.5, 0.0, 0.5] {
            for (t0, t2, c) in [
                (0.3, 0.5, 1.0),
                (0.5, 0.3, 2.0),
                (0.25, 0.8, 0.7),
                (1.1, 0.4, 1.3),
                (0.2, 0.21, 1.0),
            ] {
                // (Not every triangle is drawable at every α.)
                let Ok(s) = SegmentSolution::new(triangle(t0, t2, c), alpha) else {
                    continue;
                };
                let exact = s.angle_slopes().expect("slopes");
                checked += 1;
                let moved = [
                    (triangle(t0 + h, t2, c), triangle(t0 - h, t2, c), h),
                    (triangle(t0, t2 + h, c), triangle(t0, t2 - h, c), h),
                    (
                        triangle(t0, t2, c * h.exp()),
                        triangle(t0, t2, c * (-h).exp()),
                        h,
                    ),
                ];
                let dmu = s.mu_slopes().expect("slopes");
                for (var, (plus, minus, step)) in moved.into_iter().enumerate() {
                    let mu = |p| SegmentSolution::new(p, alpha).unwrap().mu();
                    let diff = (mu(plus) - mu(minus)) / (2.0 * step);
                    let want = dmu.get(var).copied().unwrap_or(0.0);
                    assert!(
                        (diff - want).abs() <= 1e-7 * diff.abs().max(1.0),
                        "α {alpha} ({t0}, {t2}, {c}) dμ var {var}: {diff} {want}"
                    );
                    let (up, down) = (ln_kappa(plus, alpha), ln_kappa(minus, alpha));
                    for end in 0..2 {
                        let diff = (up[end] - down[end]) / (2.0 * step);
                        assert!(
                            (diff - exact[end][var]).abs() <= 1e-7 * diff.abs().max(1.0),
                            "α {alpha} ({t0}, {t2}, {c}) end {end} var {var}: {diff} {}",
                            exact[end][var]
                        );
                    }
                }
            }
        }
        assert!(checked >= 16, "{checked} of 20 triangles drawable");
    }
}
