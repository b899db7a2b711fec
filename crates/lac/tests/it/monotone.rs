//! "A monotone verdict is never contradicted by sampling": the curvature-monotonicity test
//! of rational cubics (docs/math.md §5) against dense sampling of dκ/ds on random curves.

use kurbo::Point;
use lac::{Monotonicity, RationalCubic};
use proptest::prelude::*;

const SAMPLES: usize = 2001;

fn dense(c: &RationalCubic) -> Vec<f64> {
    (0..SAMPLES)
        .map(|i| c.curvature_derivative(i as f64 / (SAMPLES - 1) as f64))
        .collect()
}

fn check(c: &RationalCubic) -> Result<(), TestCaseError> {
    let Ok(report) = c.curvature_monotonicity() else {
        return Ok(());
    };
    let dk = dense(c);
    let scale = dk.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    prop_assume!(scale.is_finite());
    // Pointwise evaluation of dκ/ds rounds; a contradiction must stand clear of that.
    let noise = 1e-9 * scale;
    match report.verdict {
        Monotonicity::Increasing => {
            let worst = dk.iter().cloned().fold(f64::INFINITY, f64::min);
            prop_assert!(
                worst >= -noise,
                "increasing, but dκ/ds = {worst} (scale {scale})"
            );
        }
        Monotonicity::Decreasing => {
            let worst = dk.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(
                worst <= noise,
                "decreasing, but dκ/ds = {worst} (scale {scale})"
            );
        }
        Monotonicity::Constant => {
            // Only for curves whose curvature is constant within rounding.
            let k = c.signed_curvature(0.5).abs();
            prop_assert!(
                scale <= 1e-10 * k * k.max(1.0),
                "constant, but |dκ/ds| reaches {scale}"
            );
        }
        Monotonicity::NotMonotone { t } => {
            prop_assert!((0.0..=1.0).contains(&t));
            if report.proven {
                let straddles = [1e-10, 1e-8, 1e-6, 1e-4].iter().any(|&h| {
                    let (a, b) = ((t - h).max(0.0), (t + h).min(1.0));
                    c.curvature_derivative(a) * c.curvature_derivative(b) <= 0.0
                });
                prop_assert!(straddles, "no sign change of dκ/ds next to t = {t}");
            }
        }
    }
    // And the other way: a clear sign change in the samples means "not monotone".
    let clear = 1e-6 * scale;
    if dk.iter().any(|&d| d > clear) && dk.iter().any(|&d| d < -clear) {
        prop_assert!(
            matches!(report.verdict, Monotonicity::NotMonotone { .. }),
            "{report:?}"
        );
        prop_assert!(report.proven);
    }
    Ok(())
}

fn point() -> impl Strategy<Value = Point> {
    (-1.0..1.0f64, -1.0..1.0f64).prop_map(|(x, y)| Point::new(x, y))
}

fn weight() -> impl Strategy<Value = f64> {
    (-1.0..1.0f64).prop_map(|e| 10f64.powf(e))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn random_rational_cubics(
        p in [point(), point(), point(), point()],
        w in [weight(), weight(), weight(), weight()],
    ) {
        check(&RationalCubic::new(p, w).unwrap())?;
    }

    #[test]
    fn random_polynomial_cubics_far_from_the_origin(
        p in [point(), point(), point(), point()],
        offset in (-1e6..1e6f64, -1e6..1e6f64),
        scale in -3.0..3.0f64,
    ) {
        let s = 10f64.powf(scale);
        let q = p.map(|p| Point::new(offset.0 + s * p.x, offset.1 + s * p.y));
        check(&RationalCubic::new(q, [1.0; 4]).unwrap())?;
    }

    /// Spiral-like arcs: the middle points pulled along the legs of a triangle, as the
    /// quasi-aesthetic fit makes them; these are monotone or nearly so, the delicate case.
    #[test]
    fn spiral_like_arcs(
        turn in 0.1..3.0f64,
        ratio in 0.3..1.0f64,
        u in 0.2..0.95f64,
        v in 0.2..0.95f64,
        w0 in weight(),
        w3 in weight(),
    ) {
        let b = Point::new(1.0, 0.0);
        let c = b + ratio * kurbo::Vec2::from_angle(turn);
        let q = [Point::ZERO, Point::new(u, 0.0), c + v * (b - c), c];
        let w = (2.0 * (0.5 * turn).cos() + 1.0) / 3.0;
        check(&RationalCubic::new(q, [w0, w, w, w3]).unwrap())?;
    }
}

#[test]
fn invalid_curves_are_errors_not_panics() {
    let p = [
        Point::ZERO,
        Point::new(1.0, 0.0),
        Point::new(1.0, 1.0),
        Point::new(0.0, 1.0),
    ];
    for w in [
        [0.0, 1.0, 1.0, 1.0],
        [1.0, -2.0, 1.0, 1.0],
        [1.0, f64::NAN, 1.0, 1.0],
    ] {
        assert!(RationalCubic::new(p, w).is_err());
    }
    let mut q = p;
    q[2].x = f64::INFINITY;
    assert!(RationalCubic::new(q, [1.0; 4]).is_err());
    let huge = [
        Point::new(-1e308, 0.0),
        Point::new(1e308, 1.0),
        Point::new(0.0, 1e308),
        Point::ZERO,
    ];
    assert!(RationalCubic::new(huge, [1.0; 4])
        .unwrap()
        .curvature_monotonicity()
        .is_err());
}

/// Found by the property test above: a near-cusp (the speed may vanish near t = 0.59) whose
/// dκ/ds is clearly positive before it and negative after: not monotone, and provably so.
#[test]
fn a_clear_sign_change_next_to_a_near_cusp_is_proven() {
    let p = [
        Point::new(0.7469810667823236, 0.8382768163037007),
        Point::new(-0.4534815946006516, -0.14561106351371728),
        Point::new(-0.2899710284880253, -0.11498395571284122),
        Point::new(0.052355777441696866, 0.3076966437793835),
    ];
    let c = RationalCubic::new(p, [1.0; 4]).unwrap();
    check(&c).unwrap();
    let report = c.curvature_monotonicity().unwrap();
    assert!(report.proven, "{report:?}");
    assert!(matches!(report.verdict, Monotonicity::NotMonotone { .. }));
}
