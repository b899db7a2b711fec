//! Integration tests of CAD export.
//!
//! One test binary for the crate (linked once); `cargo test -p lac-export --test it MODULE`
//! runs one module's tests.

mod export;
