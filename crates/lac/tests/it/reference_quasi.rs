//! The quasi-aesthetic fit and the monotonicity test against the independent reference of
//! `tools/reference/quasi_fixtures.py`: exact verdicts (rational arithmetic and Sturm
//! sequences on the degree-12 numerator), 40-digit curvature samples, and the seed's fit
//! optimised at 40 digits.

use kurbo::Point;
use lac::Curve;
use lac::ToBezier;
use lac::{Monotonicity, RationalCubic, Segment};
use serde::Deserialize;

use crate::common::fixture_text;

#[derive(Deserialize)]
struct Fixture<T> {
    cases: Vec<T>,
}

#[derive(Deserialize)]
struct MonotoneCase {
    name: String,
    kind: String,
    points: [[f64; 2]; 4],
    weights: [f64; 4],
    verdict: String,
    sign_changes: Vec<f64>,
    samples: Vec<CurvatureSample>,
}

#[derive(Deserialize)]
struct CurvatureSample {
    t: f64,
    kappa: f64,
    dkappa_ds: f64,
}

fn load<T: for<'de> Deserialize<'de>>(name: &str) -> Vec<T> {
    serde_json::from_str::<Fixture<T>>(&fixture_text(name))
        .unwrap()
        .cases
}

fn pt(p: [f64; 2]) -> Point {
    Point::new(p[0], p[1])
}

#[test]
fn proven_verdicts_equal_the_exact_ones() {
    let cases: Vec<MonotoneCase> = load("monotone.json");
    let mut proven = 0;
    let mut unproven_kinds = std::collections::BTreeMap::<String, usize>::new();
    for c in &cases {
        let curve = RationalCubic::new(c.points.map(pt), c.weights).unwrap();
        let report = curve.curvature_monotonicity().unwrap();
        let scale_k = c.samples.iter().fold(0.0f64, |m, s| m.max(s.kappa.abs()));
        let scale_dk = c
            .samples
            .iter()
            .fold(0.0f64, |m, s| m.max(s.dkappa_ds.abs()));
        if !report.proven {
            *unproven_kinds.entry(c.kind.clone()).or_insert(0) += 1;
        }
        if report.proven {
            proven += 1;
            assert_eq!(report.verdict.name(), c.verdict, "{}", c.name);
            if let Monotonicity::NotMonotone { t } = report.verdict {
                let near = c.sign_changes.iter().any(|&r| (r - t).abs() <= 1e-9);
                assert!(
                    near,
                    "{}: t = {t}, sign changes {:?}",
                    c.name, c.sign_changes
                );
            }
        } else {
            // Not proven: dκ/ds is zero within rounding somewhere, so the curve is (nearly)
            // a circle or a line, or dκ/ds touches zero; the exact verdict may be anything,
            // but only by amounts far below the curvature's scale.
            match report.verdict {
                Monotonicity::Constant => assert!(
                    scale_dk <= 1e-10 * scale_k.powi(2).max(f64::MIN_POSITIVE)
                        || c.kind == "collinear",
                    "{}: constant, but |dκ/ds| reaches {scale_dk} (κ {scale_k})",
                    c.name
                ),
                v if v.name() == c.verdict => {}
                v => {
                    // The exact curve changes sign, but only by amounts within rounding: the
                    // excursion between its sign changes is negligible on the curve's scale.
                    let excursion = c
                        .sign_changes
                        .windows(2)
                        .map(|w| curve.curvature_derivative(0.5 * (w[0] + w[1])).abs())
                        .fold(0.0f64, f64::max);
                    assert!(
                        excursion <= 1e-9 * scale_dk,
                        "{}: unproven {v:?} vs exact {}, excursion {excursion} of {scale_dk}",
                        c.name,
                        c.verdict
                    );
                }
            }
        }
        // Pointwise curvature and dκ/ds against 40 digits.
        for s in &c.samples {
            let (k, dk) = (curve.signed_curvature(s.t), curve.curvature_derivative(s.t));
            assert!(
                (k - s.kappa).abs() <= 1e-11 * scale_k.max(1e-300),
                "{} κ({})",
                c.name,
                s.t
            );
            assert!(
                // Pointwise rounding is relative to κ², which matters for near-circles.
                (dk - s.dkappa_ds).abs() <= 1e-9 * scale_dk + 1e-13 * scale_k * scale_k,
                "{} dκ/ds({}): {dk} vs {}",
                c.name,
                s.t,
                s.dkappa_ds
            );
        }
    }
    // Every generic curve gets a proof; only the adversarial kinds (circles, lines, curves
    // whose dκ/ds touches zero or dips by less than the rounding) may not.
    for generic in ["random", "polynomial", "scaled"] {
        assert!(!unproven_kinds.contains_key(generic), "{unproven_kinds:?}");
    }
    assert!(
        proven * 4 >= cases.len() * 3,
        "{proven} of {}: {unproven_kinds:?}",
        cases.len()
    );
}

#[derive(Deserialize)]
struct QuasiCase {
    name: String,
    points: [[f64; 2]; 3],
    alpha: f64,
    u: f64,
    v: f64,
    rms: f64,
    max: f64,
    arc_length: f64,
    kappa_start: f64,
    kappa_end: f64,
}

#[test]
fn the_seed_fit_finds_the_reference_optimum() {
    let cases: Vec<QuasiCase> = load("quasi.json");
    let mut missed = Vec::new();
    for c in &cases {
        let seg = Segment::from_control_points(c.points.map(pt), c.alpha).unwrap();
        assert!(
            (seg.arc_length() - c.arc_length).abs() <= 1e-13 * c.arc_length,
            "{}",
            c.name
        );
        assert!(
            (seg.signed_curvature_start() - c.kappa_start).abs() <= 1e-12 * c.kappa_start.abs()
        );
        assert!((seg.signed_curvature_end() - c.kappa_end).abs() <= 1e-12 * c.kappa_end.abs());
        let q = seg.to_rational_cubic().unwrap();
        let b = q.pieces[0].curve.points();
        let [pa, pb, pc] = c.points.map(pt);
        let u = (b[1] - b[0]).hypot() / (pb - pa).hypot();
        let v = (b[2] - b[3]).hypot() / (pb - pc).hypot();
        // Our F is 16-point Gauss–Legendre in φ. Toward an end of small curvature (an
        // inflection nearby: end curvatures in a ratio below 1/4) d(φ) is steep in φ and
        // that rule is ~1e-3 off the continuous integral the reference minimises, which moves
        // the optimum by ~1e-6 (worst: α = −1, r = 0.6, ratio 0.05). Elsewhere the optimum
        // agrees to 1e-9.
        let ratio =
            c.kappa_start.abs().min(c.kappa_end.abs()) / c.kappa_start.abs().max(c.kappa_end.abs());
        let (tol_uv, tol_dev) = if ratio < 0.25 {
            (1e-5, 3e-3)
        } else {
            (1e-8, 1e-5)
        };
        let same_optimum = (u - c.u).abs() <= tol_uv && (v - c.v).abs() <= tol_uv;
        let close = |ours: f64, theirs: f64| (ours - theirs).abs() <= tol_dev * theirs + 1e-15;
        if same_optimum {
            assert!(
                close(q.rms, c.rms) && close(q.max, c.max),
                "{}: rms {} vs {}, max {} vs {}",
                c.name,
                q.rms,
                c.rms,
                q.max,
                c.max
            );
        } else {
            // F has several local minima; where the search ends in another one, it must not
            // be much worse than the reference's global optimum.
            missed.push(c.name.clone());
            assert!(
                q.rms <= 1.1 * c.rms,
                "{}: rms {} vs optimum {}",
                c.name,
                q.rms,
                c.rms
            );
        }
    }
    // Today one case of 30 (turning 30°, r = 0.6, α = 0) ends in a local minimum 7% above
    // the optimum.
    assert!(missed.len() <= 1, "local minima: {missed:?}");
}
