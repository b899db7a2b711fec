//! The span of a spline that passes through an inflection (α < 0): one log-aesthetic curve
//! continued through its point of zero curvature, drawn as two segments that meet there.
//!
//! For α < 0 every log-aesthetic curve is, up to similarity, a piece of one curve: with arc
//! length u from its inflection, κ(u) = sign(u)·|u|^p, p = −1/α (docs/math.md §2, the inflection end
//! at finite length; α = −1 is the clothoid, κ = u). Its tangent angle, measured from the
//! inflection tangent, is t(u) = |u|^(p+1)/(p+1) on both sides, so the piece from u = −U₁ to
//! U₂ starts at angle θ₁ = t(U₁), turns back to 0 at the inflection and on to θ₂ = t(U₂):
//! an S. Its chord is F(θ₁) + F(θ₂), with
//!
//! ```text
//! F(θ) = ∫₀^U e^{i t(u)} du = a^(1−a) ∫₀^θ τ^(a−1) e^{iτ} dτ
//!      = a^(1−a) Σₖ iᵏ θ^(k+a) / (k! (k+a)),        a = 1/(p+1) = −α/(1−α) ∈ (0, 1),
//! ```
//!
//! (at α = −1 a Fresnel integral), and its end curvatures are ∓(θ/a)^(1−a) per unit of
//! scale. Given the span's end tangents relative to its chord (ta, tb), the S is fixed up to
//! its size by the chord's direction A in the curve's own frame: θ₁ = σ·ta + A,
//! θ₂ = σ·tb + A, and A = arg(F(θ₁) + F(θ₂)), one equation in A (σ = ±1 picks the mirror
//! image). The spline's Newton iteration sees an S span like any other, through its two end
//! curvatures, which depend on the two end tangents only.
//!
//! The two halves are built as segments by [`Segment::from_curvatures`] from what the unit
//! curve says of the pieces from each end to a hair short of the inflection (their end
//! curvatures and lengths): a share [`HAIR`] of the half's length, so that the halves' ends
//! are within rounding of one another (a [`Segment`] has no station at zero curvature).
//! Their control triangles are what a caller sees of them. A half may turn by as little as
//! 1e-9 rad (the inflection almost at a point), so the smaller half's turning is solved as
//! its own unknown, not as a difference of larger angles.

use std::f64::consts::PI;

use kurbo::{Point, Vec2};

use crate::foundation::error::Result;
use crate::foundation::numeric::Complex;
use crate::segment::Segment;

/// Largest turning of one half, radians: the series for F loses about a digit per radian
/// beyond π, and a spline's span that turns by more is a loop, not an S.
const MAX_HALF_TURNING: f64 = PI;

/// The unit curve through its inflection for one α < 0.
#[derive(Clone, Copy, Debug)]
pub(super) struct Unit {
    /// a = −α/(1−α).
    a: f64,
    /// a^(1−a).
    k: f64,
}

impl Unit {
    /// The unit curve of slope `alpha`, or `None` for α ≥ 0 (no inflection at finite
    /// length).
    pub(super) fn new(alpha: f64) -> Option<Unit> {
        if !(alpha < 0.0 && alpha.is_finite()) {
            return None;
        }
        let a = -alpha / (1.0 - alpha);
        Some(Unit {
            a,
            k: a.powf(1.0 - a),
        })
    }

    /// F(θ): the chord from the inflection to the point of tangent angle θ ≥ 0.
    pub(super) fn chord(&self, theta: f64) -> Complex {
        if theta <= 0.0 {
            return Complex::ZERO;
        }
        // Σ (iθ)^k / k! / (k + a): terms fall below 1e-17 of the largest (about e^θ) by
        // k = 40 for θ ≤ π.
        let (mut re, mut im) = (0.0, 0.0);
        let mut term = 1.0; // θ^k / k!
        for k in 0..60 {
            let t = term / (k as f64 + self.a);
            match k % 4 {
                0 => re += t,
                1 => im += t,
                2 => re -= t,
                _ => im -= t,
            }
            if k as f64 > theta && term < 1e-18 {
                break;
            }
            term *= theta / (k + 1) as f64;
        }
        Complex::new(re, im).scale(self.k * theta.powf(self.a))
    }

    /// dF/dθ = a^(1−a) θ^(a−1) e^{iθ}.
    fn chord_derivative(&self, theta: f64) -> Complex {
        Complex::cis(theta).scale(self.k * theta.powf(self.a - 1.0))
    }

    /// |κ| at the point of tangent angle θ, on the unit curve: (θ/a)^(1−a).
    fn kappa(&self, theta: f64) -> f64 {
        (theta / self.a).powf(1.0 - self.a)
    }

    /// The S span whose end tangents make the angles `ta` and `tb` (in (−π, π]) with its
    /// chord of length `chord`, or `None` when there is none that turns by at most
    /// [`MAX_HALF_TURNING`] each way. Of the two mirror images, the one that turns less.
    pub(super) fn s_span(&self, ta: f64, tb: f64, chord: f64) -> Option<SSpan> {
        self.s_span_near(ta, tb, chord, (None, false))
    }

    /// [`Unit::s_span`], started from `hint`, the [`SSpan::hint`] of the S of nearby
    /// tangents, when given: Newton's method from its A on its mirror image, and the other
    /// image searched only as far as it could turn less. Without a hint, or when Newton's
    /// method does not converge from it, the search from the smallest admissible A.
    /// With `loose` (for a difference quotient, a step of 1e-7 from the hint's tangents),
    /// Newton's method on the hint's mirror image alone when it converges.
    pub(super) fn s_span_near(
        &self,
        ta: f64,
        tb: f64,
        chord: f64,
        (hint, loose): (Option<(f64, f64)>, bool),
    ) -> Option<SSpan> {
        if let (true, Some((sigma, a0))) = (loose, hint) {
            if let Some(s) = self.s_span_from(sigma, ta, tb, chord, a0) {
                return Some(s);
            }
        }
        let (first, a0) = hint.map_or((1.0, None), |(sigma, a)| (sigma, Some(a)));
        let found = a0
            .and_then(|a0| self.s_span_from(first, ta, tb, chord, a0))
            .or_else(|| self.s_span_of(first, ta, tb, chord, f64::INFINITY));
        let bound = found.map_or(f64::INFINITY, |s| s.theta[0] + s.theta[1]);
        match self.s_span_of(-first, ta, tb, chord, bound) {
            Some(other) if other.theta[0] + other.theta[1] < bound => Some(other),
            _ => found,
        }
    }

    /// The half S from a point to its inflection, or from its inflection to a point: the
    /// span of chord length `chord` that meets a straight span with zero curvature
    /// (docs/math.md, splines with point types). `t_inflection` is the angle of the tangent
    /// at the inflection end from the chord (in (−π, π], not 0); `at_end` puts the inflection
    /// at the span's end. Returns the half and the angle from the chord of the tangent at
    /// its other end, or `None` when no half turning by at most [`MAX_HALF_TURNING`] fits.
    ///
    /// With one half of the S of zero turning, A = |t_inflection| and σ = −sign(t_inflection):
    /// the turning θ of the other half solves arg F(θ) = A, which grows from 0 with θ.
    ///
    /// `hint`, the turning of a nearby half's, starts the search when given (arg F grows
    /// with θ, so the answer is the same).
    pub(super) fn half(
        &self,
        t_inflection: f64,
        chord: f64,
        at_end: bool,
        hint: Option<f64>,
    ) -> Option<(SSpan, f64)> {
        if !(t_inflection != 0.0 && t_inflection.is_finite() && chord > 0.0) {
            return None;
        }
        let sigma = -t_inflection.signum();
        let target = t_inflection.abs();
        let g = |theta: f64| self.chord(theta).arg() - target;
        let (mut lo, mut hi) = (0.0, MAX_HALF_TURNING);
        if g(hi).is_nan() || g(hi) < 0.0 {
            return None;
        }
        // arg F(θ) = θ a/(1 + a) + O(θ³): the first guess.
        let mut x = hint
            .filter(|h| *h > 0.0 && *h < hi)
            .unwrap_or_else(|| (target * (1.0 + self.a) / self.a).clamp(0.05 * hi, 0.95 * hi));
        for _ in 0..100 {
            let c = self.chord(x);
            let gx = c.arg() - target;
            if gx < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            // d arg F/dθ = Im(F′/F).
            let slope = self.chord_derivative(x).div(c).im;
            let newton = x - gx / slope;
            let next = if slope > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - x).abs() <= 4.0 * f64::EPSILON * x.abs().max(1e-300) || hi - lo <= 1e-16 {
                x = next;
                break;
            }
            x = next;
        }
        let c = self.chord(x);
        let scale = chord / c.norm();
        if !(x > 0.0 && scale.is_finite() && scale > 0.0) {
            return None;
        }
        let other = sigma * (x - target);
        let theta = if at_end { [x, 0.0] } else { [0.0, x] };
        Some((
            SSpan {
                unit: *self,
                sigma,
                theta,
                angle: target,
                scale,
            },
            other,
        ))
    }

    /// The S of orientation `sigma` (+1: it turns right first): the root A of
    /// g(A) = arg(F(σ·ta + A) + F(σ·tb + A)) − A nearest to its smallest admissible value,
    /// or `None` when there is none, or none that turns by less than `within` in all.
    fn s_span_of(&self, sigma: f64, ta: f64, tb: f64, chord: f64, within: f64) -> Option<SSpan> {
        let (d, e) = (sigma * ta, sigma * tb);
        let g = |a: f64| -> (f64, Complex) {
            let c = self.chord(d + a) + self.chord(e + a);
            (c.arg() - a, c)
        };
        // The S turns by d + e + 2A in all.
        let admissible =
            |a: f64| (d + a).max(e + a) <= MAX_HALF_TURNING && d + e + 2.0 * a < within;
        // At the smallest A one half has zero turning: g > 0 there, or no root follows.
        let mut lo = 0.0f64.max(-d).max(-e);
        if !admissible(lo) || g(lo).0 <= 0.0 {
            return None;
        }
        let mut step = 0.05;
        let mut hi = lo;
        loop {
            let next = hi + step;
            if !admissible(next) {
                return None;
            }
            if g(next).0 <= 0.0 {
                hi = next;
                break;
            }
            lo = next;
            hi = next;
            step *= 1.6;
        }
        // Newton's method on g, kept inside the bracket [lo, hi] (bisection when it leaves).
        let mut x = 0.5 * (lo + hi);
        for _ in 0..100 {
            let (gx, c) = g(x);
            if gx > 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let dc = self.chord_derivative(d + x) + self.chord_derivative(e + x);
            let slope = dc.div(c).im - 1.0;
            let newton = x - gx / slope;
            let next = if slope < 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - x).abs() <= 4.0 * f64::EPSILON * x.abs().max(1.0) || hi - lo <= 1e-15 {
                x = next;
                break;
            }
            x = next;
        }
        self.finish(sigma, d, e, x, chord)
    }

    /// The S of orientation `sigma` by Newton's method from A = `a0` (a nearby S's), or
    /// `None` when it leaves the admissible range or does not settle in a few steps.
    fn s_span_from(&self, sigma: f64, ta: f64, tb: f64, chord: f64, a0: f64) -> Option<SSpan> {
        let (d, e) = (sigma * ta, sigma * tb);
        let lo = 0.0f64.max(-d).max(-e);
        let mut x = a0;
        for _ in 0..8 {
            let c = self.chord(d + x) + self.chord(e + x);
            let gx = c.arg() - x;
            let dc = self.chord_derivative(d + x) + self.chord_derivative(e + x);
            let slope = dc.div(c).im - 1.0;
            let next = x - gx / slope;
            if !(slope < 0.0 && next > lo && (d + next).max(e + next) <= MAX_HALF_TURNING) {
                return None;
            }
            let done = (next - x).abs() <= 4.0 * f64::EPSILON * x.abs().max(1.0);
            x = next;
            if done {
                return self.finish(sigma, d, e, x, chord);
            }
        }
        None
    }

    /// The S of orientation `sigma` whose chord makes the angle A ≈ `x` with its inflection
    /// tangent, its halves turning by d + A and e + A, scaled to a chord of length `chord`.
    fn finish(&self, sigma: f64, d: f64, e: f64, x: f64, chord: f64) -> Option<SSpan> {
        // The smaller half's turning d + A (or e + A) carries A's rounding, 1e-16, which is
        // most of it when it turns by 1e-9, and F's slope there (θ^(a−1)) turns that into
        // 1e-11 rad of the chord's direction: polish with the smaller turning itself as the
        // unknown, to its own rounding, so that the S closes on its chord. (Where it turns by
        // more than 0.01 rad, A's rounding is below its own.)
        let (small, other) = if d <= e { (d, e) } else { (e, d) };
        let mut t = small + x;
        for _ in 0..8 {
            if t > 1e-2 {
                break;
            }
            let (tb, a) = (t + (other - small), t - small);
            let c = self.chord(t) + self.chord(tb);
            let g = c.arg() - a;
            let slope = (self.chord_derivative(t) + self.chord_derivative(tb))
                .div(c)
                .im
                - 1.0;
            let next = t - g / slope;
            if !(next > 0.0 && slope < 0.0 && next.is_finite()) {
                break;
            }
            let done = (next - t).abs() <= 4.0 * f64::EPSILON * t;
            t = next;
            if done {
                break;
            }
        }
        let x = t - small;
        let theta = if d <= e {
            [t, t + (other - small)]
        } else {
            [t + (other - small), t]
        };
        let c = self.chord(theta[0]) + self.chord(theta[1]);
        let scale = chord / c.norm();
        (theta.iter().all(|t| *t >= 0.0) && scale.is_finite() && scale > 0.0).then_some(SSpan {
            unit: *self,
            sigma,
            theta,
            angle: x,
            scale,
        })
    }
}

/// An S span in its own frame: which mirror image, how far each half turns, and its size.
#[derive(Clone, Copy, Debug)]
pub(super) struct SSpan {
    unit: Unit,
    /// +1 when it turns right first (negative curvature at its start), −1 when left.
    sigma: f64,
    /// The turning of the half from the start to the inflection and of the half after it.
    pub(super) theta: [f64; 2],
    /// The chord's direction from the inflection tangent, in the curve's frame (A).
    angle: f64,
    /// Caller's lengths per unit-curve length.
    scale: f64,
}

impl SSpan {
    /// What [`Unit::s_span_near`] starts from for nearby tangents: its mirror image and A.
    pub(super) fn hint(&self) -> (f64, f64) {
        (self.sigma, self.angle)
    }

    /// For a whole S on a chord of length `chord`: d ln|κ| at its start and at its end with
    /// respect to its end tangents' angles from the chord (ta, tb) and to ln `chord`, and
    /// dA with respect to ta and tb, exactly; `None` for a half, or where they are not
    /// numbers.
    ///
    /// With S = F(θ₁) + F(θ₂) = (chord/scale) e^{iA}, θ₁ = σ ta + A, θ₂ = σ tb + A and
    /// fᵢ = F′(θᵢ)/S, the equation arg S = A moves A by −σ Im fᵢ/(Im f₁ + Im f₂ − 1) per
    /// unit of its angle, ln|S| by Re f₁ dθ₁ + Re f₂ dθ₂, and ln|κᵢ| = (1 − a) ln(θᵢ/a) +
    /// ln|S| − ln chord.
    pub(super) fn slopes(&self, chord: f64) -> Option<([[f64; 3]; 2], [f64; 2])> {
        if self.is_half() {
            return None;
        }
        let [t1, t2] = self.theta;
        let s = Complex::cis(self.angle).scale(chord / self.scale);
        let f1 = self.unit.chord_derivative(t1).div(s);
        let f2 = self.unit.chord_derivative(t2).div(s);
        let g_a = f1.im + f2.im - 1.0;
        let da = [-self.sigma * f1.im / g_a, -self.sigma * f2.im / g_a];
        let (dt1, dt2) = ([self.sigma + da[0], da[1]], [da[0], self.sigma + da[1]]);
        let dln_s = [
            f1.re * dt1[0] + f2.re * dt2[0],
            f1.re * dt1[1] + f2.re * dt2[1],
        ];
        let k = 1.0 - self.unit.a;
        let row = |dt: [f64; 2], t: f64| [k * dt[0] / t + dln_s[0], k * dt[1] / t + dln_s[1], -1.0];
        let out = [row(dt1, t1), row(dt2, t2)];
        out.iter()
            .flatten()
            .chain(&da)
            .all(|d| d.is_finite())
            .then_some((out, da))
    }

    /// For a half S (see [`Unit::half`]) on a chord of length `chord`: with respect to the
    /// angle from the chord of its tangent at the inflection (its size), the turning of its
    /// curved end's half, ln|κ| there (which falls by 1 per unit of ln `chord` besides), and
    /// the angle from the chord of its tangent there; `None` for a whole S.
    ///
    /// The turning θ solves arg F(θ) = that angle, so moves by 1/Im(F′/F); ln|κ| =
    /// (1 − a) ln(θ/a) + ln|F(θ)| − ln chord, and the other angle is σ(θ − the angle).
    pub(super) fn half_slopes(&self, chord: f64) -> Option<[f64; 3]> {
        if !self.is_half() {
            return None;
        }
        let x = self.theta[0].max(self.theta[1]);
        let f = Complex::cis(self.angle).scale(chord / self.scale);
        let r = self.unit.chord_derivative(x).div(f);
        let dx = 1.0 / r.im;
        let out = [
            dx,
            ((1.0 - self.unit.a) / x + r.re) * dx,
            self.sigma * (dx - 1.0),
        ];
        out.iter().all(|d| d.is_finite()).then_some(out)
    }

    /// The signed curvature at its start and end.
    pub(super) fn end_curvatures(&self) -> (f64, f64) {
        let [t1, t2] = self.theta;
        (
            -self.sigma * self.unit.kappa(t1) / self.scale,
            self.sigma * self.unit.kappa(t2) / self.scale,
        )
    }

    /// Placement of the curve's frame for the chord from `start` to `end`: the point of the
    /// caller's plane at unit-frame point z (measured from the inflection).
    fn place(&self, start: Point, end: Point) -> impl Fn(Complex) -> Point {
        let chord = end - start;
        let psi = chord.y.atan2(chord.x) - self.sigma * self.angle;
        let rot = Complex::cis(psi).scale(self.scale);
        let z0 = -self.unit.chord(self.theta[0]);
        let sigma = self.sigma;
        move |z: Complex| {
            let local = z - z0;
            let local = if sigma < 0.0 { local.conj() } else { local };
            let w = rot * local;
            start + Vec2::new(w.re, w.im)
        }
    }

    /// The inflection point, for the chord from `start` to `end`.
    pub(super) fn inflection(&self, start: Point, end: Point) -> Point {
        self.place(start, end)(Complex::ZERO)
    }

    /// The control triangles of its halves that turn (both of an S, one of a half S), each
    /// stopping a share `hair` of its length short of the inflection.
    pub(super) fn turning_halves(&self, start: Point, end: Point, hair: f64) -> Vec<[Point; 3]> {
        let [first, second] = self.halves(start, end, hair);
        let mut out = Vec::with_capacity(2);
        if self.theta[0] > 0.0 {
            out.push(first);
        }
        if self.theta[1] > 0.0 {
            out.push(second);
        }
        out
    }

    /// The segments of its halves that turn (both of an S, one of a half S), slope `alpha`,
    /// each stopping a share `hair` of its length short of the inflection, for the chord
    /// from `start` to `end`. Built from what the unit curve says of each half (its end
    /// curvatures, its length, its tangent at its far end), not from its control triangle:
    /// a half that turns by 1e-5 rad has a triangle whose apex lies 1e-8 of its length off
    /// its chord, where the coordinates' rounding costs the curvature 1e-7 of itself.
    /// The first half starts at `start`; the second ends within rounding of `end`.
    pub(super) fn turning_segments(
        &self,
        start: Point,
        end: Point,
        hair: f64,
        alpha: f64,
    ) -> Result<Vec<Segment>> {
        let unit = self.unit;
        let chord = end - start;
        // The caller's direction of a unit-frame direction t (the frame is mirrored for
        // σ < 0): ψ + σ t.
        let psi = chord.y.atan2(chord.x) - self.sigma * self.angle;
        // Arc length from the inflection to the point of angle θ: (θ/a)^a, and the curvature
        // a share `hair` of it from the inflection: a share hair^(1/a − 1) of the far end's.
        let length = |theta: f64| self.scale * (theta / unit.a).powf(unit.a) * (1.0 - hair);
        let thin = hair.powf(1.0 / unit.a - 1.0);
        let [t1, t2] = self.theta;
        let mut out = Vec::with_capacity(2);
        if t1 > 0.0 {
            let k = -self.sigma * unit.kappa(t1) / self.scale;
            out.push(Segment::from_curvatures(
                start,
                psi + self.sigma * t1,
                [k, k * thin],
                length(t1),
                alpha,
            )?);
        }
        if t2 > 0.0 {
            let k = self.sigma * unit.kappa(t2) / self.scale;
            let near = t2 * hair.powf(1.0 / unit.a);
            out.push(Segment::from_curvatures(
                self.place(start, end)(unit.chord(near)),
                psi + self.sigma * near,
                [k * thin, k],
                length(t2),
                alpha,
            )?);
        }
        Ok(out)
    }

    /// Whether one of its halves has zero turning: it starts or ends at its inflection.
    pub(super) fn is_half(&self) -> bool {
        self.theta[0] == 0.0 || self.theta[1] == 0.0
    }

    /// The control triangles of the two halves from `start` and to `end`, each stopping a
    /// share `hair` of its length short of the inflection.
    pub(super) fn halves(&self, start: Point, end: Point, hair: f64) -> [[Point; 3]; 2] {
        let place = self.place(start, end);
        let unit = self.unit;
        // The tangent angle a share `hair` of the half's length from the inflection:
        // t ∝ u^(1/a).
        let near = |theta: f64| theta * hair.powf(1.0 / unit.a);
        let [t1, t2] = self.theta;
        // Half 1 runs from −F(θ₁) (angle θ₁) to −F(near) (angle near); half 2 from
        // F(near) to F(θ₂). The travel tangent at a point of angle t is e^{it} on both.
        let first = triangle(-unit.chord(t1), t1, -unit.chord(near(t1)), near(t1));
        let second = triangle(unit.chord(near(t2)), near(t2), unit.chord(t2), t2);
        let mut out = [first.map(&place), second.map(&place)];
        out[0][0] = start;
        out[1][2] = end;
        out
    }
}

/// The control triangle (in the unit frame) of the piece from `p` (tangent angle `tp`) to
/// `q` (tangent angle `tq`): its ends and the intersection of their tangents.
fn triangle(p: Complex, tp: f64, q: Complex, tq: f64) -> [Complex; 3] {
    let (dp, dq) = (Complex::cis(tp), Complex::cis(tq));
    let w = q - p;
    let cross = |u: Complex, v: Complex| u.re * v.im - u.im * v.re;
    // p + s·dp = q − r·dq: s = (w × dq) / (dp × dq).
    let s = cross(w, dq) / cross(dp, dq);
    [p, p + dp.scale(s), q]
}

/// The share of a half's length left out next to the inflection. The curvature there is
/// a share HAIR^(1/|α|) of the half's other end: 1e-12 for α = −1, below
/// [`INFLECTION_LIMIT`](super::INFLECTION_LIMIT) down to α ≈ −1.3 (a spline checks it).
/// Shorter hairs would put the halves' triangles, which a caller sees, closer to the edge
/// of the drawable region than the segment solver resolves.
pub(super) const HAIR: f64 = 1e-12;

#[cfg(test)]
mod tests {
    use super::*;

    /// F by Gauss–Legendre on the smooth form ∫₀^U e^{i t(u)} du.
    fn chord_by_quadrature(alpha: f64, theta: f64) -> Complex {
        let p = -1.0 / alpha;
        let big_u = ((p + 1.0) * theta).powf(1.0 / (p + 1.0));
        let n = 20_000;
        let h = big_u / n as f64;
        // Simpson's rule.
        let f = |u: f64| Complex::cis(u.powf(p + 1.0) / (p + 1.0));
        let mut sum = f(0.0) + f(big_u);
        for i in 1..n {
            let w = if i % 2 == 1 { 4.0 } else { 2.0 };
            sum += f(i as f64 * h).scale(w);
        }
        sum.scale(h / 3.0)
    }

    #[test]
    fn the_series_is_the_integral() {
        for alpha in [-0.25, -0.5, -1.0, -1.5] {
            let unit = Unit::new(alpha).unwrap();
            for theta in [0.01, 0.5, 1.5, 3.0] {
                let (s, q) = (unit.chord(theta), chord_by_quadrature(alpha, theta));
                assert!((s - q).norm() < 1e-10, "{alpha} {theta}: {s:?} {q:?}");
            }
        }
        // α = −1: the clothoid, F(θ) = ∫₀^√(2θ) e^{iu²/2} du; at θ = π/2, √π·(C, S)(1).
        let f = Unit::new(-1.0).unwrap().chord(PI / 2.0);
        let (c1, s1) = (0.779_893_400_376_822_8, 0.438_259_147_390_354_8);
        let k = PI.sqrt();
        assert!((f.re - k * c1).abs() < 1e-14 && (f.im - k * s1).abs() < 1e-14);
    }

    #[test]
    fn an_s_span_meets_its_tangents() {
        let unit = Unit::new(-0.5).unwrap();
        for (ta, tb) in [(0.4, 0.3), (-0.2, -0.7), (0.05, 0.9), (0.3, -0.05)] {
            let s = unit.s_span(ta, tb, 2.0).expect("an S");
            let [t1, t2] = s.theta;
            let c = unit.chord(t1) + unit.chord(t2);
            assert!((c.arg() - s.angle).abs() < 1e-14);
            assert!((s.sigma * (t1 - s.angle) - ta).abs() < 1e-14);
            assert!((s.sigma * (t2 - s.angle) - tb).abs() < 1e-14);
            assert!((c.norm() * s.scale - 2.0).abs() < 1e-14);
        }
    }

    /// A half S: zero curvature at its inflection end, whose tangent makes the given angle
    /// with the chord, and the other end's angle as returned; built as one segment, the same.
    #[test]
    fn a_half_s_meets_its_tangents_with_zero_curvature_at_its_inflection() {
        use crate::segment::Segment;
        for alpha in [-0.25, -0.5, -1.0] {
            let unit = Unit::new(alpha).unwrap();
            for t in [0.05, 0.3, -0.25] {
                for at_end in [true, false] {
                    let (s, other) = unit
                        .half(t, 2.0, at_end, None)
                        .unwrap_or_else(|| panic!("a half: {alpha} {t} {at_end}"));
                    let theta = s.theta[0].max(s.theta[1]);
                    let c = unit.chord(theta);
                    assert!((c.arg() - s.angle).abs() < 1e-14, "{alpha} {t}");
                    assert!((c.norm() * s.scale - 2.0).abs() < 1e-14);
                    // The tangents from the chord: the inflection's t, the other end's.
                    assert!((s.sigma * (theta - s.angle) - other).abs() < 1e-14);
                    assert!((-s.sigma * s.angle - t).abs() < 1e-15, "{alpha} {t}");
                    let (k0, k1) = s.end_curvatures();
                    assert_eq!(if at_end { k1 } else { k0 }, 0.0);
                    let (a, b) = (Point::new(0.5, -1.0), Point::new(0.5, 1.0));
                    let [tri] = s.turning_halves(a, b, HAIR)[..] else {
                        panic!("one half")
                    };
                    let seg = Segment::from_control_points(tri, alpha).unwrap();
                    let (f0, f1) = seg.end_curvatures();
                    let (far, near) = if at_end { (f0, f1) } else { (f1, f0) };
                    let want = if at_end { k0 } else { k1 };
                    assert!(
                        (far - want).abs() <= 1e-12 * want.abs(),
                        "{alpha} {t} {at_end}"
                    );
                    assert!(near.abs() <= 1e-11 * want.abs(), "{alpha} {t} {at_end}");
                }
            }
        }
        assert!(Unit::new(-1.0)
            .unwrap()
            .half(0.0, 1.0, true, None)
            .is_none());
    }

    /// An S whose inflection lies almost at one of its ends (a half turning by 1e-9 rad
    /// down to 1e-3) closes on its chord to rounding, and its halves, built from their
    /// curvatures, reach its end there with the end curvatures of the formula (built on their
    /// triangles, the flat half's curvature was off by up to 1e-6 of itself).
    #[test]
    fn an_s_with_its_inflection_almost_at_an_end_closes_and_builds() {
        for alpha in [-0.5, -1.0] {
            let unit = Unit::new(alpha).unwrap();
            for small in [1e-9, 1e-7, 1e-5, 1e-3] {
                for (big, sigma, flip) in [(0.6, 1.0, false), (0.6, -1.0, true), (1.9, 1.0, true)] {
                    // The tangents of the S whose halves turn by `big` and `small` (the small
                    // one second, or first when flipped): θᵢ = σ·tᵢ + A.
                    let theta = if flip { [small, big] } else { [big, small] };
                    let a = (unit.chord(theta[0]) + unit.chord(theta[1])).arg();
                    let (ta, tb) = (sigma * (theta[0] - a), sigma * (theta[1] - a));
                    let s = unit.s_span(ta, tb, 2.0).expect("an S");
                    let [p, q] = [Point::new(0.5, -1.0), Point::new(0.5, 1.0)];
                    let turned = s.theta[0].min(s.theta[1]);
                    assert!(
                        (turned - small).abs() <= 1e-6 * small,
                        "{alpha} {small} {flip}: {:?}",
                        s.theta
                    );
                    let end = s.place(p, q)(unit.chord(s.theta[1]));
                    assert!((end - q).hypot() <= 1e-15, "{alpha} {small}: {end:?}");
                    let segs = s.turning_segments(p, q, HAIR, alpha).unwrap();
                    let (k0, k1) = s.end_curvatures();
                    let (first, last) = (&segs[0], &segs[1]);
                    assert!((first.end_curvatures().0 - k0).abs() <= 1e-14 * k0.abs());
                    assert!((last.end_curvatures().1 - k1).abs() <= 1e-14 * k1.abs());
                    assert!((first.first_point() - p).hypot() == 0.0);
                    // (The second half is integrated from its flat end: a few ulps of the
                    // chord per radian it turns.)
                    let miss = (last.last_point() - q).hypot();
                    assert!(miss <= 1e-14 * 2.0, "{alpha} {small} {flip}: {miss:e}");
                    let gap = (first.last_point() - last.first_point()).hypot();
                    assert!(gap <= 1e-11, "{gap}");
                }
            }
        }
    }

    /// The exact slopes of an S (of ln|κ| at its ends and of A) agree with central
    /// differences of S spans solved afresh.
    #[test]
    fn s_slopes_agree_with_differences() {
        let h = 1e-6;
        for alpha in [-0.5, -1.0, -2.0] {
            let unit = Unit::new(alpha).unwrap();
            for (ta, tb) in [(0.4, 0.3), (-0.2, -0.7), (0.05, 0.9), (1.2, 0.2)] {
                let c = 1.7;
                let s = unit.s_span(ta, tb, c).expect("an S");
                let (exact, da) = s.slopes(c).expect("slopes");
                let at = |ta: f64, tb: f64, c: f64| {
                    let s = unit.s_span(ta, tb, c).expect("an S");
                    let (k0, k1) = s.end_curvatures();
                    [k0.abs().ln(), k1.abs().ln(), s.angle]
                };
                let moved = [
                    (at(ta + h, tb, c), at(ta - h, tb, c)),
                    (at(ta, tb + h, c), at(ta, tb - h, c)),
                    (at(ta, tb, c * h.exp()), at(ta, tb, c * (-h).exp())),
                ];
                for (var, (up, down)) in moved.iter().enumerate() {
                    let want = [
                        exact[0][var],
                        exact[1][var],
                        da.get(var).copied().unwrap_or(0.0),
                    ];
                    for i in 0..3 {
                        let diff = (up[i] - down[i]) / (2.0 * h);
                        assert!(
                            (diff - want[i]).abs() <= 1e-6 * diff.abs().max(1.0),
                            "α {alpha} ({ta}, {tb}) var {var} {i}: {diff} {}",
                            want[i]
                        );
                    }
                }
            }
        }
    }

    /// The exact slopes of a half S agree with central differences of halves solved afresh.
    #[test]
    fn half_slopes_agree_with_differences() {
        let h = 1e-6;
        let mut checked = 0;
        for alpha in [-0.5, -1.0, -2.0] {
            let unit = Unit::new(alpha).unwrap();
            for (t, at_end) in [(0.3, true), (-0.5, false), (0.05, true), (-0.9, true)] {
                let c = 1.3;
                let at = |t: f64| {
                    let (s, other) = unit.half(t, c, at_end, None).expect("a half");
                    let (k0, k1) = s.end_curvatures();
                    [
                        s.theta[0].max(s.theta[1]),
                        k0.abs().max(k1.abs()).ln(),
                        other,
                    ]
                };
                // (Not every angle has a half that turns by at most π.)
                let Some((s, _)) = unit.half(t, c, at_end, None) else {
                    continue;
                };
                let exact = s.half_slopes(c).expect("slopes");
                checked += 1;
                // The size of the angle grows with t for t > 0, falls for t < 0.
                let (up, down) = (at(t + h), at(t - h));
                for i in 0..3 {
                    let diff = t.signum() * (up[i] - down[i]) / (2.0 * h);
                    assert!(
                        (diff - exact[i]).abs() <= 1e-6 * diff.abs().max(1.0),
                        "α {alpha} {t} {i}: {diff} {}",
                        exact[i]
                    );
                }
            }
        }
        assert!(checked >= 9, "{checked} of 12 halves");
    }

    /// Started from a nearby S (as a spline's Newton iteration does), the search finds the
    /// S it finds from scratch, mirror image and all; a half S likewise.
    #[test]
    fn a_hint_finds_the_same_s() {
        for alpha in [-0.5, -1.0] {
            let unit = Unit::new(alpha).unwrap();
            for (ta, tb) in [
                (0.4, 0.3),
                (-0.2, -0.7),
                (0.05, 0.9),
                (0.3, 0.001),
                (1.2, 0.2),
            ] {
                let near = unit.s_span(ta, tb, 2.0).expect("an S");
                for d in [1e-7, 1e-3, -2e-2] {
                    let cold = unit.s_span(ta + d, tb - d, 2.0);
                    let warm = unit.s_span_near(ta + d, tb - d, 2.0, (Some(near.hint()), false));
                    // Loosely (the hint's mirror image only), a difference quotient's step.
                    let loose = (d == 1e-7)
                        .then(|| unit.s_span_near(ta + d, tb - d, 2.0, (Some(near.hint()), true)));
                    let cold = cold.expect("an S");
                    for warm in [warm].into_iter().chain(loose).map(|w| w.expect("an S")) {
                        assert_eq!(cold.sigma, warm.sigma, "{alpha} {ta} {tb} {d}");
                        for i in 0..2 {
                            let gap = (cold.theta[i] - warm.theta[i]).abs();
                            assert!(
                                gap <= 1e-14 * cold.theta[i].max(1.0),
                                "{alpha} {ta} {tb} {d}"
                            );
                        }
                    }
                }
            }
            let (half, _) = unit.half(0.3, 2.0, true, None).unwrap();
            let hinted = unit.half(0.31, 2.0, true, Some(half.theta[0])).unwrap().0;
            let cold = unit.half(0.31, 2.0, true, None).unwrap().0;
            assert!((hinted.theta[0] - cold.theta[0]).abs() <= 1e-14);
        }
    }

    /// The halves built as segments (by the chord-angle solver, on their triangles) have
    /// the end curvatures of the formula, and meet at zero curvature.
    #[test]
    fn the_halves_as_segments() {
        use crate::segment::Segment;
        for alpha in [-0.25, -0.5, -1.0, -1.3] {
            let unit = Unit::new(alpha).unwrap();
            for (ta, tb) in [
                (0.4, 0.3),
                (0.05, 0.9),
                (0.9, 0.05),
                (0.2, 0.02),
                (-0.6, -0.1),
            ] {
                let s = unit.s_span(ta, tb, 2.0).expect("an S");
                let (a, b) = (Point::new(0.5, -1.0), Point::new(1.7, 0.6));
                let [h0, h1] = s.halves(a, b, HAIR);
                let (k0, k1) = s.end_curvatures();
                let first = Segment::from_control_points(h0, alpha).unwrap();
                let second = Segment::from_control_points(h1, alpha).unwrap();
                let (f0, f1) = first.end_curvatures();
                let (g0, g1) = second.end_curvatures();
                assert!((f0 - k0).abs() <= 1e-13 * k0.abs(), "{alpha} {ta} {tb}");
                assert!((g1 - k1).abs() <= 1e-13 * k1.abs(), "{alpha} {ta} {tb}");
                assert!(f1.abs().max(g0.abs()) <= 1e-9 * k0.abs().max(k1.abs()));
                assert!(f1 * g0 <= 0.0 && k0 * k1 < 0.0);
                let gap = (first.last_point() - second.first_point()).hypot();
                assert!(gap <= 1e-11, "{gap}");
                let m = s.inflection(a, b);
                assert!((m - first.last_point()).hypot() <= 1e-11);
            }
        }
    }
}
