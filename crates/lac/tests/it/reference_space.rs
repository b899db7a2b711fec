//! The space family against the 50-digit reference (`tools/reference/space_fixtures.py`,
//! fixture `space_family.json`): valid ranges, curvature, torsion, positions and Frenet
//! frames of 152 curves, α, β ∈ {−1, −0.5, 0, 0.5, 1, 2} and next to 0 and 1, Λ, Ω ∈ {0, …}.

use lac::{SpaceForm, SpaceFormParams, TorsionType, Vec3};
use serde::Deserialize;

#[derive(Deserialize)]
struct Fixture {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    alpha: f64,
    beta: f64,
    lambda: f64,
    omega: f64,
    nu: f64,
    #[serde(rename = "type")]
    kind: u8,
    s_range: [Option<f64>; 2],
    points: Vec<RefFrame>,
}

#[derive(Deserialize)]
struct RefFrame {
    s: f64,
    x: [f64; 3],
    t: [f64; 3],
    n: [f64; 3],
    b: [f64; 3],
    kappa: f64,
    tau: f64,
}

fn fixture() -> Fixture {
    serde_json::from_str(include_str!("../fixtures/space_family.json")).unwrap()
}

fn form(c: &Case) -> SpaceForm {
    SpaceForm::new(SpaceFormParams {
        alpha: c.alpha,
        beta: c.beta,
        lambda: c.lambda,
        omega: c.omega,
        nu: c.nu,
        torsion: TorsionType::from_number(c.kind).unwrap(),
    })
    .unwrap()
}

fn dist(a: Vec3, b: [f64; 3]) -> f64 {
    a.distance(Vec3::from(b))
}

#[test]
fn valid_ranges_match_the_reference() {
    for c in fixture().cases {
        let (lo, hi) = form(&c).s_range();
        let want_lo = c.s_range[0].unwrap_or(f64::NEG_INFINITY);
        let want_hi = c.s_range[1].unwrap_or(f64::INFINITY);
        for (got, want) in [(lo, want_lo), (hi, want_hi)] {
            assert!(
                got == want || (got - want).abs() <= 1e-14 * want.abs(),
                "alpha {} beta {} lambda {} omega {} nu {} type {}: {got} vs {want}",
                c.alpha,
                c.beta,
                c.lambda,
                c.omega,
                c.nu,
                c.kind
            );
        }
    }
}

#[test]
fn frames_match_the_reference_to_1e_12_of_the_size() {
    let mut worst = (0.0f64, 0.0f64, 0.0f64);
    for c in fixture().cases {
        let f = form(&c);
        let s: Vec<f64> = c.points.iter().map(|p| p.s).collect();
        let frames = f.frames(&s).unwrap();
        for (got, want) in frames.iter().zip(&c.points) {
            // Size: the distance travelled, at least 1 (ρ(0) = 1).
            let size = want.s.abs().max(1.0);
            let dx = dist(got.point, want.x) / size;
            let df = dist(got.tangent, want.t)
                .max(dist(got.normal, want.n))
                .max(dist(got.binormal, want.b));
            let dk = ((got.curvature - want.kappa) / want.kappa)
                .abs()
                .max(((got.torsion - want.tau) / want.tau).abs());
            worst = (worst.0.max(dx), worst.1.max(df), worst.2.max(dk));
            assert!(
                dx < 1e-12 && df < 1e-12 && dk < 1e-13,
                "alpha {} beta {} lambda {} omega {} nu {} type {} s {}: position {dx:e}, \
                 frame {df:e}, curvature/torsion {dk:e}",
                c.alpha,
                c.beta,
                c.lambda,
                c.omega,
                c.nu,
                c.kind,
                want.s
            );
        }
    }
    eprintln!(
        "worst: position {:e}, frame {:e}, kappa/tau {:e}",
        worst.0, worst.1, worst.2
    );
}
