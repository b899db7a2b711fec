//! Space segments from inputs built from known log-aesthetic space curves (so that a segment
//! exists, see `common/space_inputs.rs`): at least 99.5% are solved, and every solution
//! reproduces its ends and end tangents within 1e-9 by an integration independent of the
//! solver (classical Runge–Kutta with step doubling on κ(s), τ(s) written out).
//!
//! `LAC_SPACE_CASES` sets the number of cases per seed (default 600, three seeds), and the
//! test prints the shares solved per α, β, type, crossing and near-edge cases. A second test
//! holds every cell (α, β, type) with β ∈ {−1, 0, 1} to 99.5% on longer pieces
//! (`LAC_SPACE_CELL_CASES` per cell, default 400) and prints the share per cell.

use crate::common::space_inputs;

use std::collections::BTreeMap;

use lac::SpaceCurve;
use lac::{SpaceSegment, TorsionType};
use space_inputs::{check_ends, generate, Case};

/// Solved and total per key.
#[derive(Default)]
struct Tally(BTreeMap<String, (usize, usize)>);

impl Tally {
    fn add(&mut self, key: String, ok: bool) {
        let e = self.0.entry(key).or_default();
        e.0 += usize::from(ok);
        e.1 += 1;
    }
    fn print(&self, title: &str) {
        let rows: Vec<String> = self
            .0
            .iter()
            .map(|(k, (s, t))| format!("{k}: {s}/{t}"))
            .collect();
        eprintln!("{title}: {}", rows.join(", "));
    }
}

fn describe(c: &Case) -> String {
    let f = c.form;
    format!(
        "alpha {} beta {} omega {:?} type {} (lambda {:?} nu {:?} s_end {:?}, edge {}, \
         crossing {}, end angles {:?}) points {:?}",
        f.alpha(),
        f.beta(),
        f.omega(),
        f.torsion_type().number(),
        f.lambda(),
        f.nu(),
        c.s_end,
        c.edge,
        c.crossing,
        space_inputs::angles(&f, c.s_end).map(|(t0, t1, t2)| [t0, t1, t2]),
        c.points.map(|p| p.to_array())
    )
}

#[test]
fn constructed_inputs_are_solved_and_verified() {
    let per_seed: usize = std::env::var("LAC_SPACE_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(600);
    let (mut by_pair, mut by_type, mut by_crossing, mut by_edge) = (
        Tally::default(),
        Tally::default(),
        Tally::default(),
        Tally::default(),
    );
    let (mut solved, mut total) = (0, 0);
    let mut worst = (0.0f64, 0.0f64);
    let mut failures = Vec::new();
    for seed in [1u64, 2, 3] {
        let clock = std::time::Instant::now();
        let cases = generate(seed, per_seed);
        eprintln!(
            "seed {seed}: {} cases made in {:?}",
            cases.len(),
            clock.elapsed()
        );
        for case in cases {
            total += 1;
            if std::env::var_os("LAC_SPACE_TRACE").is_some() {
                eprintln!("case {total}: {}", describe(&case));
            }
            let clock = std::time::Instant::now();
            let result = SpaceSegment::from_control_points(case.points, case.shape);
            let took = clock.elapsed();
            if took.as_secs_f64() > 0.05 {
                eprintln!(
                    "slow ({took:?}, ok {}): {}",
                    result.is_ok(),
                    describe(&case)
                );
            }
            let ok = match &result {
                Ok(seg) if seg.is_planar() => panic!("planar answer for {}", describe(&case)),
                Ok(seg) => {
                    let clock = std::time::Instant::now();
                    let (pos, tan) = check_ends(seg, case.points);
                    if clock.elapsed().as_secs_f64() > 0.05 {
                        eprintln!("slow check ({:?}): {}", clock.elapsed(), describe(&case));
                    }
                    assert!(
                        pos < 1e-9 && tan < 1e-9,
                        "position {pos:e}, tangent {tan:e}: {}",
                        describe(&case)
                    );
                    worst = (worst.0.max(pos), worst.1.max(tan));
                    true
                }
                Err(e) => {
                    failures.push(format!("{e}: {}", describe(&case)));
                    false
                }
            };
            solved += usize::from(ok);
            let s = case.shape;
            by_pair.add(format!("({:>4},{:>4})", s.alpha, s.beta), ok);
            by_type.add(
                match s.torsion {
                    TorsionType::One => "type 1".into(),
                    TorsionType::Two => "type 2".into(),
                },
                ok,
            );
            by_crossing.add(format!("crossing {}", case.crossing), ok);
            by_edge.add(if case.edge { "edge" } else { "plain" }.into(), ok);
        }
    }
    by_pair.print("per (alpha, beta)");
    by_type.print("per type");
    by_crossing.print("per crossing of the end");
    by_edge.print("near the cone's edge");
    for f in failures.iter().take(30) {
        eprintln!("unsolved: {f}");
    }
    eprintln!(
        "solved {solved}/{total} ({:.2}%); worst position {:e} of the chord, tangent {:e} rad",
        100.0 * solved as f64 / total as f64,
        worst.0,
        worst.1
    );
    assert!(
        solved as f64 >= 0.995 * total as f64,
        "solved {solved}/{total}"
    );
}

/// Dragging: P3 moved in 20 small steps (1/500 of the chord each), each solve warm-started
/// from the last, gives a segment at every step that reproduces its ends, and the drawn curve
/// moves only a little between steps (the warm start follows one branch).
#[test]
fn warm_start_follows_a_drag_continuously() {
    let (mut followed, mut steps) = (0, 0);
    for case in generate(7, 40) {
        let Ok(mut seg) = SpaceSegment::from_control_points(case.points, case.shape) else {
            continue;
        };
        let mut p = case.points;
        let chord = p[3].distance(p[0]);
        let dir = (p[1] - p[0]).cross(p[3] - p[2]).normalize();
        for _ in 0..20 {
            p[3] += dir * (chord / 500.0);
            // A drag may leave the drawable region; the drag ends there.
            let Ok(next) = SpaceSegment::from_control_points_near(p, case.shape, &seg) else {
                break;
            };
            steps += 1;
            let (pos, tan) = check_ends(&next, p);
            assert!(pos < 1e-9 && tan < 1e-9, "{pos:e} {tan:e}");
            // The drawn curve moves about as much as the point did (no jump to another
            // branch): samples at equal fractions of the length stay within 1/50 of the chord.
            let (a, b) = (
                seg.sample_by_arc_length(17).unwrap(),
                next.sample_by_arc_length(17).unwrap(),
            );
            let jump = a
                .iter()
                .zip(&b)
                .fold(0.0f64, |m, (f, g)| m.max(f.point.distance(g.point)))
                / chord;
            assert!(jump < 0.02, "jump {jump}: {}", describe(&case));
            seg = next;
        }
        followed += 1;
    }
    eprintln!("{followed} drags, {steps} warm-started steps");
    assert!(
        followed >= 35 && steps >= 600,
        "followed {followed}, {steps} steps"
    );
}

/// Every (α, β) of {−1, −0.5, 0, 0.5, 1, 2} × {−1, 0, 1} with both types, on longer pieces
/// (s 0.6–6 of the standard form, ν up to 4, |θ2| at least 0.05 rad off 0 and π): at least
/// 99.5% solved in every cell, each solution verified as above; the shares per cell are
/// printed. `LAC_SPACE_CELL_CASES` sets the cases per cell (default 400),
/// `LAC_SPACE_CELL_SEED` the seed (default 33), and with `LAC_SPACE_TRACE` every miss is
/// printed (else the first ten). At the default count no cell misses more than one input
/// (99.75%) with seeds 1, 2, 3, 33, 34 and 35; at 2,000 per cell the least cell solves
/// 99.85%.
#[test]
fn every_cell_solves_long_pieces() {
    let per_cell: usize = std::env::var("LAC_SPACE_CELL_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(400);
    let mut cells = Vec::new();
    for torsion in [TorsionType::One, TorsionType::Two] {
        for beta in [-1.0, 0.0, 1.0] {
            for alpha in space_inputs::SLOPES {
                cells.push((alpha, beta, torsion));
            }
        }
    }
    let recipe = space_inputs::Recipe {
        cells: cells.clone(),
        s_end: (0.6, 6.0),
        min_s_end: 0.6,
        min_dihedral: 0.05,
    };
    let mut by_cell: BTreeMap<(i32, i32, u8), (usize, usize)> = BTreeMap::new();
    let mut by_end = Tally::default();
    let mut failures = Vec::new();
    let seed: u64 = std::env::var("LAC_SPACE_CELL_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(33);
    for case in space_inputs::generate_with(seed, per_cell * cells.len(), &recipe) {
        let ok = match SpaceSegment::from_control_points(case.points, case.shape) {
            Ok(seg) => {
                let (pos, tan) = check_ends(&seg, case.points);
                assert!(
                    pos < 1e-9 && tan < 1e-9,
                    "position {pos:e}, tangent {tan:e}: {}",
                    describe(&case)
                );
                true
            }
            Err(e) => {
                failures.push(format!("{e}: {}", describe(&case)));
                false
            }
        };
        let s = case.shape;
        let key = ((2.0 * s.alpha) as i32, s.beta as i32, s.torsion.number());
        let cell = by_cell.entry(key).or_default();
        cell.0 += usize::from(ok);
        cell.1 += 1;
        by_end.add(
            format!(
                "type {}, larger angle at the {}",
                s.torsion.number(),
                if case.larger_angle_at_end {
                    "end"
                } else {
                    "start"
                }
            ),
            ok,
        );
    }
    eprintln!("solved per cell (alpha, beta, type):");
    for ((alpha2, beta, torsion), (solved, total)) in &by_cell {
        eprintln!(
            "  ({:>4}, {beta:>2}, {torsion}): {solved}/{total} ({:.2}%)",
            f64::from(*alpha2) / 2.0,
            100.0 * *solved as f64 / *total as f64
        );
    }
    by_end.print("where the standard form has the larger chord angle");
    // `LAC_SPACE_TRACE` prints every miss, not only the first ten.
    let shown = if std::env::var_os("LAC_SPACE_TRACE").is_some() {
        failures.len()
    } else {
        10
    };
    for f in failures.iter().take(shown) {
        eprintln!("unsolved: {f}");
    }
    let low: Vec<_> = by_cell
        .iter()
        .filter(|(_, (solved, total))| (*solved as f64) < 0.995 * *total as f64)
        .collect();
    assert!(low.is_empty(), "cells below 99.5%: {low:?}");
}
