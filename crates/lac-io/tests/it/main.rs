//! Integration tests of the file formats.
//!
//! One test binary for the crate (linked once); `cargo test -p lac-io --test it MODULE`
//! runs one module's tests.

mod export;
