//! The classification of the ends of log-aesthetic space curves (seed 003 Figs. 5–6, rows
//! a1–a45 and b1–b37) against the fixture `space_classification.json`
//! (`tools/reference/space_fixtures.py`, corrected cells as in
//! `tools/reference/space_classification_notes.md`): every row, every parameter set, every
//! cell, the bound, and whether the tangent and the binormal settle.

use std::collections::BTreeMap;

use lac::{SpaceClassification, SpaceEnd, SpaceForm, TorsionType};
use serde::Deserialize;

#[derive(Deserialize)]
struct Fixture {
    rows: Vec<Row>,
}

#[derive(Deserialize)]
struct Row {
    row: String,
    #[serde(rename = "type")]
    kind: u8,
    expected: BTreeMap<String, Cells>,
    behaviour: BTreeMap<String, Behaviour>,
    checks: Vec<Check>,
}

#[derive(Deserialize, Debug, PartialEq)]
struct Cells {
    bound: String,
    theta: String,
    phi: String,
    rho: String,
    mu: String,
}

#[derive(Deserialize)]
struct Behaviour {
    length_finite: bool,
    tangent: String,
    binormal: String,
    #[serde(default)]
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    when: String,
    tangent: String,
    binormal: String,
}

#[derive(Deserialize)]
struct Check {
    alpha: f64,
    beta: f64,
    lambda: f64,
    omega: f64,
    nu: f64,
    #[serde(rename = "type")]
    kind: u8,
    lower: CheckEnd,
    upper: CheckEnd,
    subcase: Option<String>,
}

#[derive(Deserialize)]
struct CheckEnd {
    bound_value: Option<f64>,
    binds: String,
    length_finite: bool,
    cells: Cells,
    kappa_over_tau: String,
    radius_cells_by_behaviour: RadiusCells,
    tangent_settles: bool,
    binormal_settles: bool,
}

#[derive(Deserialize)]
struct RadiusCells {
    rho: String,
    mu: String,
}

fn fixture() -> Fixture {
    serde_json::from_str(include_str!("fixtures/space_classification.json")).unwrap()
}

fn classify(c: &Check) -> SpaceClassification {
    let kind = TorsionType::from_number(c.kind).unwrap();
    SpaceForm::new(c.alpha, c.beta, c.lambda, c.omega, c.nu, kind)
        .unwrap()
        .classify()
}

fn settles(word: &str) -> bool {
    match word {
        "settles" => true,
        "turns" => false,
        other => panic!("unexpected behaviour {other:?}"),
    }
}

/// Every disagreement with the fixture at one end, as readable lines.
fn compare_end(got: &lac::EndBehaviour, want: &CheckEnd) -> Vec<String> {
    let mut bad = Vec::new();
    let mut expect = |what: &str, got: String, want: &str| {
        if got != want {
            bad.push(format!("{what}: got {got}, want {want}"));
        }
    };
    let [bound, theta, phi, rho, mu] = got.seed_cells();
    expect("bound", bound, &want.cells.bound);
    expect("theta", theta, &want.cells.theta);
    expect("phi", phi, &want.cells.phi);
    expect("rho", rho, &want.cells.rho);
    expect("mu", mu, &want.cells.mu);
    expect("binds", got.binds.name().into(), &want.binds);
    expect(
        "kappa_over_tau",
        got.kappa_over_tau.name().into(),
        &want.kappa_over_tau,
    );
    expect(
        "rho by behaviour",
        got.rho_by_behaviour().to_string(),
        &want.radius_cells_by_behaviour.rho,
    );
    expect(
        "mu by behaviour",
        got.mu_by_behaviour().to_string(),
        &want.radius_cells_by_behaviour.mu,
    );
    expect(
        "length_finite",
        got.length_finite.to_string(),
        &want.length_finite.to_string(),
    );
    expect(
        "tangent_settles",
        got.tangent_settles.to_string(),
        &want.tangent_settles.to_string(),
    );
    expect(
        "binormal_settles",
        got.binormal_settles.to_string(),
        &want.binormal_settles.to_string(),
    );
    match want.bound_value {
        Some(v) => {
            let close = (got.s - v).abs() <= 1e-12 * v.abs();
            if !close {
                bad.push(format!("bound value: got {}, want {v}", got.s));
            }
        }
        None => {
            let inf = got.end.direction() * f64::INFINITY;
            if got.s != inf {
                bad.push(format!("bound value: got {}, want {inf}", got.s));
            }
        }
    }
    if got.length_finite != got.s.is_finite() {
        bad.push("length_finite disagrees with the bound".into());
    }
    bad
}

#[test]
fn every_row_and_check_matches_the_fixture() {
    let fixture = fixture();
    assert_eq!(fixture.rows.len(), 82, "rows a1–a45 and b1–b37");
    let mut failures = Vec::new();
    let mut checks = 0;
    for row in &fixture.rows {
        for check in &row.checks {
            checks += 1;
            assert_eq!(check.kind, row.kind, "{}: type of a check", row.row);
            let got = classify(check);
            let label = format!(
                "{} (alpha {}, beta {}, lambda {}, omega {}, nu {}, type {})",
                row.row, check.alpha, check.beta, check.lambda, check.omega, check.nu, check.kind
            );
            if got.row() != Some(row.row.as_str()) {
                failures.push(format!("{label}: row {:?}", got.row()));
            }
            for (end, want) in [
                (SpaceEnd::Lower, &check.lower),
                (SpaceEnd::Upper, &check.upper),
            ] {
                let e = got.end(end);
                assert_eq!(e.end, end);
                for line in compare_end(e, want) {
                    failures.push(format!("{label} {end:?}: {line}"));
                }
            }
        }
    }
    assert_eq!(checks, 98);
    assert!(
        failures.is_empty(),
        "{} disagreements:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The row-level cells and behaviour agree with each check's (the checks are what the
/// classifier is tested on; this keeps the two halves of the fixture honest).
#[test]
fn row_cells_and_behaviour_agree_with_the_checks() {
    for row in fixture().rows {
        for check in &row.checks {
            for (name, end) in [("lower", &check.lower), ("upper", &check.upper)] {
                assert_eq!(&end.cells, &row.expected[name], "{} {name}", row.row);
                let b = &row.behaviour[name];
                assert_eq!(b.length_finite, end.length_finite, "{} {name}", row.row);
                let (tangent, binormal) = if b.tangent == "depends" || b.binormal == "depends" {
                    let when = check.subcase.as_deref().expect("dependent row has subcase");
                    let case = b.cases.iter().find(|c| c.when == when).unwrap_or_else(|| {
                        panic!("{} {name}: subcase {when:?} not among the cases", row.row)
                    });
                    (case.tangent.as_str(), case.binormal.as_str())
                } else {
                    (b.tangent.as_str(), b.binormal.as_str())
                };
                assert_eq!(settles(tangent), end.tangent_settles, "{} {name}", row.row);
                assert_eq!(
                    settles(binormal),
                    end.binormal_settles,
                    "{} {name}",
                    row.row
                );
            }
        }
    }
}

#[test]
fn every_row_name_is_reached() {
    let mut seen: Vec<String> = fixture()
        .rows
        .iter()
        .flat_map(|r| {
            r.checks
                .iter()
                .map(|c| classify(c).row().unwrap().to_string())
        })
        .collect();
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 82);
}

#[test]
fn helix_and_degenerate_parameters() {
    // Λ = Ω = 0: a helix, infinite at both ends, both vectors keep turning.
    for kind in [TorsionType::One, TorsionType::Two] {
        for (alpha, beta) in [(0.0, 0.0), (-1.0, 2.0), (0.5, 1.0)] {
            let c = SpaceForm::new(alpha, beta, 0.0, 0.0, 2.0, kind)
                .unwrap()
                .classify();
            assert_eq!(c.row(), None);
            for e in [c.lower, c.upper] {
                assert!(!e.length_finite && e.s.is_infinite());
                assert!(!e.tangent_settles && !e.binormal_settles);
                assert_eq!(e.kappa_over_tau, lac::RatioLimit::Finite);
                assert_eq!(e.theta, lac::TurningCell::Infinite);
                assert_eq!(e.phi, lac::TurningCell::Infinite);
                assert_eq!(e.rho.to_string(), "-");
                assert_eq!(e.mu.to_string(), "-");
            }
        }
    }
    // Λ = 0, β = 0, type 1: τ = e^(−Ωs)/ν → 0 as s → ∞ (a circle in the limit: the binormal
    // settles, the tangent keeps turning) and → ∞ as s → −∞ (the tangent settles).
    let c = SpaceForm::new(0.5, 0.0, 0.0, 1.0, 1.0, TorsionType::One)
        .unwrap()
        .classify();
    assert_eq!(c.row(), None);
    assert!(!c.upper.tangent_settles && c.upper.binormal_settles);
    assert!(c.lower.tangent_settles && !c.lower.binormal_settles);
    assert_eq!(c.upper.seed_cells(), ["inf", "inf", "Finite", "-", "inf*"]);
    assert_eq!(c.lower.seed_cells(), ["-inf", "-inf", "-inf", "-", "0*"]);
    // Ω = 0, α > 1: the ρ bound at −1/(Λα) is the only one.
    let c = SpaceForm::new(2.0, -1.0, 1.0, 0.0, 1.0, TorsionType::Two)
        .unwrap()
        .classify();
    assert_eq!(c.row(), None);
    assert_eq!(c.lower.s, -0.5);
    assert_eq!(c.lower.binds, lac::BoundBy::Rho);
    assert!(c.lower.tangent_settles && c.lower.binormal_settles);
    // s → ∞: κ ~ s^(−1/2) → 0 while τ = 1, so τ/κ → ∞: the tangent settles although θ
    // diverges, and the binormal keeps turning.
    assert_eq!(c.upper.seed_cells(), ["inf", "inf", "inf", "inf*", "-"]);
    assert!(c.upper.tangent_settles && !c.upper.binormal_settles);
}
