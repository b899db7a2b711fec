//! `lac-fuzz [--count N] [--seed S] [ENTRY…]`: run the seeded random driver over the entry
//! points (all by default) and print each one's figures; exit code 1 if any input panicked,
//! broke an invariant or took over a second. `make fuzz` runs it with a million inputs per
//! entry point.

use std::io::Write;
use std::process::ExitCode;

use lac_fuzz::{campaign, EntryPoint};

fn main() -> ExitCode {
    let mut count = 100_000u64;
    let mut seed = 1u64;
    let mut entries = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let value = |args: &mut dyn Iterator<Item = String>| {
            args.next()
                .and_then(|v| v.parse::<u64>().ok())
                .unwrap_or_else(|| {
                    eprintln!("{arg} needs a whole number");
                    std::process::exit(2)
                })
        };
        match arg.as_str() {
            "--count" => count = value(&mut args),
            "--seed" => seed = value(&mut args),
            name => match EntryPoint::from_name(name) {
                Some(e) => entries.push(e),
                None => {
                    let names: Vec<_> = EntryPoint::ALL.iter().map(|e| e.name()).collect();
                    eprintln!("unknown entry point {name:?}; one of {}", names.join(", "));
                    return ExitCode::from(2);
                }
            },
        }
    }
    if entries.is_empty() {
        entries = EntryPoint::ALL.to_vec();
    }
    let mut clean = true;
    for entry in entries {
        let progress = |done: u64| {
            eprint!("\r{:<10} {done:>9}/{count}", entry.name());
            let _ = std::io::stderr().flush();
        };
        let stats = campaign(entry, seed, count, &progress);
        eprint!("\r");
        println!("{}", stats.summary(entry));
        for (input, why) in stats.violations.iter().chain(&stats.panics).take(5) {
            println!(
                "  {why}\n    {}",
                serde_json::to_string(input).unwrap_or_default()
            );
        }
        if let Some((d, input)) = &stats.slowest {
            if d.as_secs_f64() > 0.1 {
                println!(
                    "  slowest input: {}",
                    serde_json::to_string(input).unwrap_or_default()
                );
            }
        }
        clean &= stats.clean();
    }
    if clean {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
