//! The classification of the ends of log-aesthetic space curves (seed 003 Figs. 5–6, rows
//! a1–a45 and b1–b37) against the fixture `space_classification.json`
//! (`tools/reference/space_fixtures.py`, corrected cells as in
//! `tools/reference/space_classification_notes.md`): every row, every parameter set, every
//! cell, the bound, and whether the tangent and the binormal settle.
//!
//! The library's cells are typed values; the seed's notation for them ("A", "Finite(-inf)",
//! "0*", "a24", …) is written out once here, in [`notation`], and every cell is compared in
//! it.

use std::collections::BTreeMap;

use lac::{SpaceClassification, SpaceEnd, SpaceForm, SpaceFormParams, TorsionType};
use serde::Deserialize;

use notation::{binds_name, radius_cell, ratio_name, row_label, seed_cells};

/// The seed's (and the fixture's) notation for the typed cells of the classification.
mod notation {
    use lac::{
        BoundBy, EndBehaviour, RadiusCell, RadiusLimit, RatioLimit, SeedRow, SpaceEnd, TorsionType,
        TurningCell,
    };

    /// "-inf" or "inf": an infinite value toward `end`.
    fn infinity(end: SpaceEnd) -> &'static str {
        match end {
            SpaceEnd::Lower => "-inf",
            SpaceEnd::Upper => "inf",
        }
    }

    /// The s column: "A" (= −1/(Λα), also when both bounds coincide), "B" (the μ bound),
    /// "-inf" or "inf".
    fn bound_cell(e: &EndBehaviour) -> String {
        match e.binds {
            BoundBy::Unbounded => infinity(e.end),
            BoundBy::Rho | BoundBy::Both => "A",
            BoundBy::Mu => "B",
        }
        .to_string()
    }

    /// A θ or φ cell at `end`: "-inf", "inf", "Finite", "Finite(-inf)", "Finite(inf)" or
    /// "Finite(F)".
    fn turning_cell(cell: TurningCell, end: SpaceEnd) -> String {
        match cell {
            TurningCell::Infinite => infinity(end).to_string(),
            TurningCell::Finite => "Finite".to_string(),
            TurningCell::CutShort {
                diverges_at_own_end: true,
            } => format!("Finite({})", infinity(end)),
            TurningCell::CutShort {
                diverges_at_own_end: false,
            } => "Finite(F)".to_string(),
        }
    }

    /// A ρ or μ cell: "0", "inf" or "-", with "*" when starred.
    pub(crate) fn radius_cell(cell: RadiusCell) -> String {
        let limit = match cell.limit {
            RadiusLimit::Zero => "0",
            RadiusLimit::Infinite => "inf",
            RadiusLimit::Positive => "-",
        };
        format!("{limit}{}", if cell.star { "*" } else { "" })
    }

    /// The five cells of a half row in the seed's order: s (bound), θ, φ, ρ, μ.
    pub(crate) fn seed_cells(e: &EndBehaviour) -> [String; 5] {
        [
            bound_cell(e),
            turning_cell(e.theta, e.end),
            turning_cell(e.phi, e.end),
            radius_cell(e.rho),
            radius_cell(e.mu),
        ]
    }

    /// The fixture's `binds`: "none", "rho", "mu" or "both".
    pub(crate) fn binds_name(binds: BoundBy) -> &'static str {
        match binds {
            BoundBy::Unbounded => "none",
            BoundBy::Rho => "rho",
            BoundBy::Mu => "mu",
            BoundBy::Both => "both",
        }
    }

    /// The fixture's `kappa_over_tau`: "0", "finite" or "inf".
    pub(crate) fn ratio_name(ratio: RatioLimit) -> &'static str {
        match ratio {
            RatioLimit::Zero => "0",
            RatioLimit::Finite => "finite",
            RatioLimit::Infinite => "inf",
        }
    }

    /// The seed's row label: "a1" … "a45" (Fig. 5, type 1), "b1" … "b37" (Fig. 6, type 2).
    pub(crate) fn row_label(row: SeedRow) -> String {
        let (table, rows) = match row.torsion {
            TorsionType::One => ('a', 45),
            TorsionType::Two => ('b', 37),
        };
        assert!(
            (1..=rows).contains(&row.number),
            "{row:?} is not a row of its table"
        );
        format!("{table}{}", row.number)
    }
}

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
    serde_json::from_str(include_str!("../fixtures/space_classification.json")).unwrap()
}

fn classify(c: &Check) -> SpaceClassification {
    SpaceForm::new(SpaceFormParams {
        alpha: c.alpha,
        beta: c.beta,
        lambda: c.lambda,
        omega: c.omega,
        nu: c.nu,
        torsion: TorsionType::from_number(c.kind).unwrap(),
    })
    .unwrap()
    .classify()
}

fn form(
    alpha: f64,
    beta: f64,
    lambda: f64,
    omega: f64,
    nu: f64,
    torsion: TorsionType,
) -> SpaceForm {
    SpaceForm::new(SpaceFormParams {
        alpha,
        beta,
        lambda,
        omega,
        nu,
        torsion,
    })
    .unwrap()
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
    let [bound, theta, phi, rho, mu] = seed_cells(got);
    expect("bound", bound, &want.cells.bound);
    expect("theta", theta, &want.cells.theta);
    expect("phi", phi, &want.cells.phi);
    expect("rho", rho, &want.cells.rho);
    expect("mu", mu, &want.cells.mu);
    expect("binds", binds_name(got.binds).into(), &want.binds);
    expect(
        "kappa_over_tau",
        ratio_name(got.kappa_over_tau).into(),
        &want.kappa_over_tau,
    );
    expect(
        "rho by behaviour",
        radius_cell(got.rho_by_behaviour()),
        &want.radius_cells_by_behaviour.rho,
    );
    expect(
        "mu by behaviour",
        radius_cell(got.mu_by_behaviour()),
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
            if got.row().map(row_label).as_deref() != Some(row.row.as_str()) {
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
                .map(|c| row_label(classify(c).row().unwrap()))
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
            let c = form(alpha, beta, 0.0, 0.0, 2.0, kind).classify();
            assert_eq!(c.row(), None);
            for e in [c.lower, c.upper] {
                assert!(!e.length_finite && e.s.is_infinite());
                assert!(!e.tangent_settles && !e.binormal_settles);
                assert_eq!(e.kappa_over_tau, lac::RatioLimit::Finite);
                assert_eq!(e.theta, lac::TurningCell::Infinite);
                assert_eq!(e.phi, lac::TurningCell::Infinite);
                assert_eq!(radius_cell(e.rho), "-");
                assert_eq!(radius_cell(e.mu), "-");
            }
        }
    }
    // Λ = 0, β = 0, type 1: τ = e^(−Ωs)/ν → 0 as s → ∞ (a circle in the limit: the binormal
    // settles, the tangent keeps turning) and → ∞ as s → −∞ (the tangent settles).
    let c = form(0.5, 0.0, 0.0, 1.0, 1.0, TorsionType::One).classify();
    assert_eq!(c.row(), None);
    assert!(!c.upper.tangent_settles && c.upper.binormal_settles);
    assert!(c.lower.tangent_settles && !c.lower.binormal_settles);
    assert_eq!(seed_cells(&c.upper), ["inf", "inf", "Finite", "-", "inf*"]);
    assert_eq!(seed_cells(&c.lower), ["-inf", "-inf", "-inf", "-", "0*"]);
    // Ω = 0, α > 1: the ρ bound at −1/(Λα) is the only one.
    let c = form(2.0, -1.0, 1.0, 0.0, 1.0, TorsionType::Two).classify();
    assert_eq!(c.row(), None);
    assert_eq!(c.lower.s, -0.5);
    assert_eq!(c.lower.binds, lac::BoundBy::Rho);
    assert!(c.lower.tangent_settles && c.lower.binormal_settles);
    // s → ∞: κ ~ s^(−1/2) → 0 while τ = 1, so τ/κ → ∞: the tangent settles although θ
    // diverges, and the binormal keeps turning.
    assert_eq!(seed_cells(&c.upper), ["inf", "inf", "inf", "inf*", "-"]);
    assert!(c.upper.tangent_settles && !c.upper.binormal_settles);
}
