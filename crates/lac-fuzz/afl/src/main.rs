//! The coverage-guided fuzz target. AFL++ mutates byte strings; each one stands for an input
//! of one of `lac-fuzz`'s entry points ([`lac_fuzz::EntryPoint::input_from_bytes`]: the first
//! byte picks the entry point, the rest steer its generator), which is run and checked with the
//! same invariants as the seeded driver. A panic or a broken invariant aborts, which AFL keeps
//! as a crash; `lac-fuzz --decode` turns a crash file back into a JSON input for the
//! regression corpus.

use lac_fuzz::{EntryPoint, Outcome};

fn main() {
    afl::fuzz!(|bytes: &[u8]| {
        let input = EntryPoint::input_from_bytes(bytes);
        match lac_fuzz::run(&input).0 {
            Outcome::Ok | Outcome::Refused => {}
            Outcome::Violation(why) | Outcome::Panic(why) => panic!("{why}"),
        }
    });
}
