//! `lac-fuzz [--count N] [--seed S] [ENTRY…]`: run the seeded random driver over the entry
//! points (all by default) and print each one's figures; exit code 1 if any input panicked,
//! broke an invariant or took over a second. `make fuzz` runs it with a million inputs per
//! entry point. `lac-fuzz --replay FILE` runs the inputs of a file (one JSON input a line,
//! as printed) and prints each outcome and time. `lac-fuzz --decode FILE…` prints, as a JSON
//! line, the input each byte file of the coverage-guided fuzzer stands for (`make afl`), to
//! keep in `regressions/inputs.jsonl`.

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
            "--decode" => {
                // The inputs a coverage-guided fuzzer's byte files stand for.
                for path in args.by_ref() {
                    match std::fs::read(&path) {
                        Ok(bytes) => println!(
                            "{}",
                            serde_json::to_string(&EntryPoint::input_from_bytes(&bytes))
                                .unwrap_or_default()
                        ),
                        Err(e) => {
                            eprintln!("cannot read {path}: {e}");
                            return ExitCode::from(2);
                        }
                    }
                }
                return ExitCode::SUCCESS;
            }
            "--replay" => {
                // Each kept input of a file, with its outcome and time.
                let path = args.next().unwrap_or_default();
                let text = std::fs::read_to_string(&path).unwrap_or_else(|e| {
                    eprintln!("cannot read {path}: {e}");
                    std::process::exit(2)
                });
                let mut clean = true;
                for line in text.lines().filter(|l| l.starts_with('{')) {
                    let input: lac_fuzz::Input = match serde_json::from_str(line) {
                        Ok(i) => i,
                        Err(e) => {
                            eprintln!("unreadable input ({e}): {line}");
                            return ExitCode::from(2);
                        }
                    };
                    let (outcome, elapsed) = lac_fuzz::run(&input);
                    println!("{:>10.3} ms  {outcome:?}", elapsed.as_secs_f64() * 1e3);
                    clean &= matches!(outcome, lac_fuzz::Outcome::Ok | lac_fuzz::Outcome::Refused);
                }
                return if clean {
                    ExitCode::SUCCESS
                } else {
                    ExitCode::from(1)
                };
            }
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
            eprint!("\r{:<10} {done:>9}/{}", entry.name(), entry.count(count));
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
