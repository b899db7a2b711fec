//! Claim: on a hundred thousand seeded random and adversarial inputs per entry point, the
//! library never panics, never returns NaN or ∞ in an Ok result, never returns an Ok result
//! that breaks its constraints, and every input that ever failed still passes.
//!
//! `LAC_FUZZ_COUNT` changes the count (about 5 minutes for the default on this 2-core
//! machine); `make fuzz` runs a million per entry point with the optimised `lac-fuzz`
//! binary.

use lac_fuzz::{campaign, replay, EntryPoint, Outcome};

fn count() -> u64 {
    std::env::var("LAC_FUZZ_COUNT")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100_000)
}

#[test]
fn every_entry_point_survives_the_seeded_driver() {
    let failures = survive(EntryPoint::ALL.into_iter(), count());
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// Run `n` seeded inputs of each entry point; what went wrong.
fn survive(entries: impl Iterator<Item = EntryPoint>, n: u64) -> Vec<String> {
    let mut failures = Vec::new();
    for entry in entries {
        let stats = campaign(entry, 20261123, n, &|_| {});
        eprintln!("{}", stats.summary(entry));
        // A hang detector, not a timing claim: the iteration caps keep every call far below.
        let hung = stats
            .slowest
            .as_ref()
            .is_some_and(|(d, _)| d.as_secs_f64() > 10.0);
        if stats.panic_count > 0 || stats.violation_count > 0 || hung {
            for (input, why) in stats.panics.iter().chain(&stats.violations).take(3) {
                failures.push(format!(
                    "{}: {why}\n  {}",
                    entry.name(),
                    serde_json::to_string(input).unwrap()
                ));
            }
            if hung {
                failures.push(format!("{}: a call took over 10 s", entry.name()));
            }
        }
    }
    failures
}

#[test]
fn every_input_that_ever_failed_passes() {
    let corpus = include_str!("../../regressions/inputs.jsonl");
    let results = replay(corpus);
    assert!(
        results.len() >= 10,
        "the corpus holds {} inputs",
        results.len()
    );
    let bad: Vec<String> = results
        .iter()
        .filter(|(_, o)| matches!(o, Outcome::Violation(_) | Outcome::Panic(_)))
        .map(|(i, o)| format!("{o:?}\n  {}", serde_json::to_string(i).unwrap()))
        .collect();
    assert!(bad.is_empty(), "\n{}", bad.join("\n"));
}

#[test]
fn byte_strings_steer_the_generators_for_the_coverage_guided_fuzzer() {
    // The first byte picks the entry point; the same bytes give the same input; the empty
    // string and long strings are inputs too.
    for (i, entry) in EntryPoint::ALL.into_iter().enumerate() {
        let bytes: Vec<u8> = std::iter::once(i as u8)
            .chain((0..64u8).map(|b| b.wrapping_mul(37)))
            .collect();
        let input = EntryPoint::input_from_bytes(&bytes);
        assert_eq!(input, EntryPoint::input_from_bytes(&bytes));
        let name = serde_json::to_value(&input).unwrap()["entry"].clone();
        assert_eq!(name, entry.name(), "{input:?}");
        assert!(!matches!(
            lac_fuzz::run(&input).0,
            Outcome::Violation(_) | Outcome::Panic(_)
        ));
    }
    for bytes in [&[][..], &[255; 4096][..]] {
        let input = EntryPoint::input_from_bytes(bytes);
        assert!(!matches!(
            lac_fuzz::run(&input).0,
            Outcome::Violation(_) | Outcome::Panic(_)
        ));
    }
}
