//! Claims about the family in standard form that need no reference file: closed forms,
//! bounds, seed 000 Table 2, and continuity across α = 0, 1, 2 and Λ = 0.

use lac::{Classification, InfiniteRadiusEnd, StandardForm, ZeroRadiusEnd};

#[test]
fn closed_forms_hold() {
    // Clothoid, Λ = 1: ρ = 1/(1 − s), θ = s − s²/2 ... with α = −1: ρ(s) = (1 − s)^(−1).
    let clothoid = StandardForm::new(-1.0, 1.0).unwrap();
    for s in [-3.0, -0.5, 0.0, 0.3, 0.9] {
        assert!((clothoid.rho_at_s(s).unwrap() - 1.0 / (1.0 - s)).abs() < 1e-14 / (1.0 - s));
        assert!((clothoid.theta_at_s(s).unwrap() - (s - s * s / 2.0)).abs() < 1e-14);
    }
    // Logarithmic spiral: P(θ) = (e^{(Λ+i)θ} − 1)/(Λ + i).
    let (l, t) = (0.3f64, 2.0f64);
    let spiral = StandardForm::new(1.0, l).unwrap();
    let p = spiral.point_at_theta(t).unwrap();
    let (er, ei) = ((l * t).exp() * t.cos() - 1.0, (l * t).exp() * t.sin());
    let d = l * l + 1.0;
    let (x, y) = ((er * l + ei) / d, (ei * l - er) / d);
    assert!(
        (p.x - x).abs() < 1e-14 && (p.y - y).abs() < 1e-14,
        "{p:?} vs ({x}, {y})"
    );
    // Λ = 0 is the unit circle for every α.
    for alpha in [-5.0, 0.0, 0.5, 1.0, 2.0, 40.0] {
        let circle = StandardForm::new(alpha, 0.0).unwrap();
        let p = circle.point_at_theta(1.2).unwrap();
        assert!((p.x - 1.2f64.sin()).abs() < 1e-15 && (p.y - (1.0 - 1.2f64.cos())).abs() < 1e-15);
        assert_eq!(circle.s_bounds(), (f64::NEG_INFINITY, f64::INFINITY));
    }
}

#[test]
fn bounds_follow_the_table_of_seed_000() {
    let f = |a| StandardForm::new(a, 2.0).unwrap();
    assert_eq!(f(-1.0).s_bounds(), (f64::NEG_INFINITY, 0.5));
    assert_eq!(f(0.0).s_bounds(), (f64::NEG_INFINITY, f64::INFINITY));
    assert_eq!(f(0.5).s_bounds(), (-1.0, f64::INFINITY));
    assert_eq!(f(-1.0).theta_bounds(), (f64::NEG_INFINITY, 0.25));
    assert_eq!(f(1.0).theta_bounds(), (f64::NEG_INFINITY, f64::INFINITY));
    assert_eq!(f(3.0).theta_bounds(), (-0.25, f64::INFINITY));
    // Outside the bounds: a typed error, not NaN.
    assert!(f(-1.0).rho_at_s(0.6).is_err());
    assert!(f(3.0).point_at_theta(-0.3).is_err());
    assert!(f(0.5).theta_at_s(f64::NAN).is_err());
    assert!(StandardForm::new(0.5, -1.0).is_err());
}

#[test]
fn table_2_of_seed_000() {
    let rows = [
        (
            -1.0,
            ZeroRadiusEnd::SpiralsInInfiniteLength,
            InfiniteRadiusEnd::InflectionAtFiniteDistance,
        ),
        (
            0.0,
            ZeroRadiusEnd::SpiralsInInfiniteLength,
            InfiniteRadiusEnd::InflectionAtInfinity,
        ),
        (
            0.5,
            ZeroRadiusEnd::SpiralsInFiniteLength,
            InfiniteRadiusEnd::InflectionAtInfinity,
        ),
        (
            1.0,
            ZeroRadiusEnd::SpiralsInFiniteLength,
            InfiniteRadiusEnd::SpiralsOut,
        ),
        (
            2.0,
            ZeroRadiusEnd::EndsWithTangent,
            InfiniteRadiusEnd::SpiralsOut,
        ),
    ];
    for (alpha, zero, infinite) in rows {
        let c = Classification::of(alpha);
        assert_eq!(
            (c.zero_radius, c.infinite_radius),
            (zero, infinite),
            "alpha {alpha}"
        );
    }
    // The table's finite/infinite columns, row by row (s and θ at ρ = 0, then at ρ = ∞).
    let columns = |a: f64| {
        let c = Classification::of(a);
        (
            c.arc_length_finite_at_zero_radius(),
            c.tangent_angle_finite_at_zero_radius(),
            c.arc_length_finite_at_infinite_radius(),
            c.tangent_angle_finite_at_infinite_radius(),
        )
    };
    assert_eq!(columns(-2.0), (false, false, true, true));
    assert_eq!(columns(0.0), (false, false, false, true));
    assert_eq!(columns(0.7), (true, false, false, true));
    assert_eq!(columns(1.0), (true, false, false, false));
    assert_eq!(columns(1.5), (true, true, false, false));
    // And the bounds agree with the classification.
    for a in [-2.0, 0.0, 0.7, 1.0, 1.5] {
        let (s_lo, s_hi) = StandardForm::new(a, 1.0).unwrap().s_bounds();
        let (t_lo, t_hi) = StandardForm::new(a, 1.0).unwrap().theta_bounds();
        let (s0, t0, s_inf, t_inf) = columns(a);
        assert_eq!(
            (
                s_lo.is_finite(),
                t_lo.is_finite(),
                s_hi.is_finite(),
                t_hi.is_finite()
            ),
            (s0, t0, s_inf, t_inf)
        );
    }
}

/// Values at α and at α ± 1e-9 (and Λ vs Λ = 1e-12) differ by O(1e-9), not O(1).
#[test]
fn continuous_across_alpha_0_1_2_and_lambda_0() {
    for alpha in [0.0, 1.0, 2.0] {
        for lambda in [1e-12, 0.4, 1.0] {
            let at = StandardForm::new(alpha, lambda).unwrap();
            for eps in [1e-9, -1e-9, 1e-15, -1e-15] {
                let near = StandardForm::new(alpha + eps, lambda).unwrap();
                for theta in [-0.45, 0.3, 0.9] {
                    let (p, q) = (
                        at.point_at_theta(theta).unwrap(),
                        near.point_at_theta(theta).unwrap(),
                    );
                    assert!(
                        (p - q).hypot() < 1e3 * eps.abs() + 1e-15,
                        "alpha {alpha} eps {eps} theta {theta}"
                    );
                    let (r, r2) = (
                        at.rho_at_theta(theta).unwrap(),
                        near.rho_at_theta(theta).unwrap(),
                    );
                    assert!((r - r2).abs() < 1e3 * eps.abs() * r + 1e-15 * r);
                    let (s, s2) = (
                        at.theta_at_s(theta).unwrap(),
                        near.theta_at_s(theta).unwrap(),
                    );
                    assert!((s - s2).abs() < 1e3 * eps.abs() + 1e-15);
                }
            }
        }
    }
    for alpha in [-1.0, 0.0, 0.5, 1.0, 3.0] {
        let circle = StandardForm::new(alpha, 0.0).unwrap();
        let tiny = StandardForm::new(alpha, 1e-12).unwrap();
        let (p, q) = (
            circle.point_at_theta(1.0).unwrap(),
            tiny.point_at_theta(1.0).unwrap(),
        );
        assert!((p - q).hypot() < 1e-11, "alpha {alpha}");
    }
}

#[test]
fn s_and_theta_are_inverse_and_points_agree() {
    for alpha in [-3.0, -1.0, 0.0, 0.4, 1.0, 2.0, 7.0] {
        let form = StandardForm::new(alpha, 0.7).unwrap();
        for theta in [-0.2, 0.1, 0.25] {
            let s = form.s_at_theta(theta).unwrap();
            assert!((form.theta_at_s(s).unwrap() - theta).abs() < 1e-14);
            let (a, b) = (
                form.point_at_theta(theta).unwrap(),
                form.point_at_s(s).unwrap(),
            );
            assert!(
                (a - b).hypot() < 1e-14 * (1.0 + s.abs()),
                "alpha {alpha}: {a:?} vs {b:?}"
            );
            // dρ/ds = Λ ρ^(1−α) by central differences.
            let h = 1e-5;
            let d = (form.rho_at_s(s + h).unwrap() - form.rho_at_s(s - h).unwrap()) / (2.0 * h);
            let rho = form.rho_at_s(s).unwrap();
            assert!((d - 0.7 * rho.powf(1.0 - alpha)).abs() < 1e-7 * d.abs());
        }
    }
}
