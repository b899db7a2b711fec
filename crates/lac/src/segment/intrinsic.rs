//! A log-aesthetic segment from its start, its end curvatures and its arc length: the
//! intrinsic description a fit works in (docs/math.md §2), placed as a [`Segment`].
//!
//! Along a log-aesthetic segment ρ^α is linear in arc length (ln ρ for α = 0), so the start
//! point, the start tangent, the two end curvatures (one sign, neither zero), the length and
//! α fix it. In standard form II the end of smaller radius is the reference point (ρ = 1,
//! scale c = its radius) and the other end lies at s = L/c with ρ = R = ρ_max/ρ_min, which
//! fixes Λ = (R^α − 1)/(α L/c), written `expm1(α ln R)/α` so that α = 0 (Λ = c ln R / L) is
//! an ordinary value.

use kurbo::Point;

use super::{check_alpha, Placement, Segment};
use crate::family::standard_form::integrate::integrate;
use crate::family::standard_form::{StandardForm, Station};
use crate::foundation::error::{finite, Error, Result};
use crate::foundation::numeric::{expm1_ratio, Complex};
use crate::foundation::turn::Turn;

impl Segment {
    /// The segment that starts at `start` with tangent direction `theta` (radians), has the
    /// signed curvatures `curvatures = [κ_start, κ_end]` at its ends (one sign, neither
    /// zero: a log-aesthetic segment's curvature keeps its sign and only reaches zero at an
    /// infinite radius), arc length `length` and slope `alpha`.
    ///
    /// ```
    /// use kurbo::Point;
    /// use lac::{Curve, Segment};
    /// // A clothoid (α = −1): curvature linear in arc length, from 1 to 2 over length 0.5.
    /// let seg = Segment::from_curvatures(Point::ORIGIN, 0.0, [1.0, 2.0], 0.5, -1.0)?;
    /// assert!((seg.signed_curvature_at_s(0.25)? - 1.5).abs() < 1e-13);
    /// assert!((seg.arc_length() - 0.5).abs() < 1e-15);
    /// # Ok::<(), lac::Error>(())
    /// ```
    ///
    /// Errors: a non-finite input, a length that is not positive, curvatures of opposite
    /// signs or zero, a turning of π or more, or a segment whose numbers leave double range.
    pub fn from_curvatures(
        start: Point,
        theta: f64,
        curvatures: [f64; 2],
        length: f64,
        alpha: f64,
    ) -> Result<Segment> {
        check_alpha("alpha", alpha)?;
        finite("start.x", start.x)?;
        finite("start.y", start.y)?;
        finite("theta", theta)?;
        let [ka, kb] = curvatures;
        finite("start curvature", ka)?;
        finite("end curvature", kb)?;
        finite("length", length)?;
        if length <= 0.0 {
            return Err(Error::OutOfRange {
                name: "length",
                value: length,
                expected: "a positive arc length",
            });
        }
        if !(ka != 0.0 && kb != 0.0 && ka.signum() == kb.signum()) {
            return Err(Error::OutOfRange {
                name: "curvatures",
                value: if ka == 0.0 { ka } else { kb },
                expected: "end curvatures of one sign, neither zero (a log-aesthetic segment \
                           turns one way and reaches zero curvature only at an infinite radius)",
            });
        }
        let (rho_a, rho_b) = (1.0 / ka.abs(), 1.0 / kb.abs());
        // Which end is the reference (the smaller radius): the caller runs forward in the
        // standard form when it starts there.
        let forward = rho_a <= rho_b;
        let (c, ln_ratio) = if forward {
            (rho_a, (ka / kb).abs().ln())
        } else {
            (rho_b, (kb / ka).abs().ln())
        };
        let s_other = length / c;
        let lambda = ln_ratio * expm1_ratio(alpha * ln_ratio) / s_other;
        let form = StandardForm::new(alpha, lambda)?;
        let other = if lambda == 0.0 {
            Station {
                theta: s_other,
                s: s_other,
                ln_rho: 0.0,
            }
        } else {
            form.station_at_s(s_other)?
        };
        // A segment turns by less than π (as one drawn from control points does): longer
        // turns are several segments, and every use of a segment (its control triangle, its
        // Bézier replacement) assumes it.
        let turning = other.theta.abs();
        if turning.is_nan() || turning >= std::f64::consts::PI {
            return Err(Error::OutOfRange {
                name: "turning",
                value: turning,
                expected: "a segment that turns by less than pi (split longer turns into \
                           several segments)",
            });
        }
        let (first, last) = if forward {
            (Station::REFERENCE, other)
        } else {
            (other, Station::REFERENCE)
        };
        let along = integrate(&form, &Station::REFERENCE, &other, false).value;
        let chord = if forward { along } else { -along };
        // The direction the caller travels in the standard form at its first point, and
        // whether that travel turns the standard form's way (left) or is mirrored.
        let (phi, d) = if forward {
            (0.0, 1.0)
        } else {
            (other.theta + std::f64::consts::PI, -1.0)
        };
        let sigma = ka.signum();
        let mirrored = sigma != d;
        let rot = if mirrored {
            Complex::cis(-(theta + phi)).scale(c)
        } else {
            Complex::cis(theta - phi).scale(c)
        };
        let placement = Placement {
            origin: start,
            rot,
            mirrored,
            turn: if sigma > 0.0 { Turn::Left } else { Turn::Right },
            theta_first: theta,
        };
        let segment = Segment::new(alpha, form, [first, last], chord, placement);
        segment.check()?;
        Ok(segment)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::Curve;

    /// Every combination of turning direction, growing or shrinking curvature and α gives a
    /// segment with the asked start, tangent, end curvatures and length, and the control
    /// triangle of that segment solves back to the same curve.
    #[test]
    fn asked_ends_and_length_and_the_same_curve_from_its_control_points() {
        for alpha in [-2.0, -1.0, -0.3, 0.0, 1e-9, 0.5, 1.0, 2.0, 4.0] {
            for (ka, kb) in [
                (1.0, 2.5),
                (2.5, 1.0),
                (-1.0, -2.5),
                (-2.5, -1.0),
                (0.7, 0.7),
            ] {
                let start = Point::new(0.3, -0.2);
                let seg = Segment::from_curvatures(start, 0.4, [ka, kb], 0.8, alpha).unwrap();
                let (k0, k1) = seg.end_curvatures();
                assert!(
                    (k0 - ka).abs() < 1e-13 && (k1 - kb).abs() < 1e-12,
                    "{alpha}: {k0} {k1}"
                );
                assert!((seg.arc_length() - 0.8).abs() < 1e-14);
                assert!((seg.start_point() - start).hypot() < 1e-15);
                assert!((seg.theta_at_s(0.0).unwrap() - 0.4).abs() < 1e-14);
                // Tangent angle: the integral of curvature; the middle against a Simpson sum.
                let n = 2000;
                let h = 0.8 / n as f64;
                let mut turned = 0.0;
                for i in 0..n {
                    let s = i as f64 * h;
                    let k = |s: f64| seg.signed_curvature_at_s(s).unwrap();
                    turned += h / 6.0 * (k(s) + 4.0 * k(s + 0.5 * h) + k(s + h));
                }
                let theta_end = seg.theta_at_s(0.8).unwrap();
                assert!(
                    (theta_end - 0.4 - turned).abs() < 1e-11,
                    "{alpha} {ka} {kb}"
                );
                if ka != kb {
                    let again = Segment::from_control_points(seg.control_points(), alpha).unwrap();
                    let p = seg.point_at_s(0.5).unwrap();
                    let q = again.point_at_s(0.5).unwrap();
                    assert!((p - q).hypot() < 1e-11, "{alpha} {ka} {kb}: {p:?} {q:?}");
                }
            }
        }
    }

    #[test]
    fn opposite_signs_zero_and_bad_lengths_are_refused() {
        let p = Point::ORIGIN;
        assert!(Segment::from_curvatures(p, 0.0, [1.0, -1.0], 1.0, -1.0).is_err());
        assert!(Segment::from_curvatures(p, 0.0, [0.0, 1.0], 1.0, -1.0).is_err());
        assert!(Segment::from_curvatures(p, 0.0, [1.0, 2.0], 0.0, -1.0).is_err());
        assert!(Segment::from_curvatures(p, 0.0, [1.0, 2.0], f64::NAN, -1.0).is_err());
        assert!(Segment::from_curvatures(p, f64::INFINITY, [1.0, 2.0], 1.0, -1.0).is_err());
        // Turning by π or more: a spiral of several segments, not one.
        assert!(Segment::from_curvatures(p, 0.0, [1.0, 2.0], 2.2, -1.0).is_err());
        assert!(Segment::from_curvatures(p, 0.0, [1.0, 1.0], 3.2, 0.0).is_err());
    }
}
