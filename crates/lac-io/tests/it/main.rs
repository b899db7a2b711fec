//! Integration tests of lac-io: one test binary for the crate (linked once);
//! `cargo test -p lac-io --test it MODULE` runs one module's tests.

mod fit;
mod points;
