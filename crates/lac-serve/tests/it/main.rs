//! Integration tests of the editor's server: its API, concurrency and mutated requests.
//!
//! One test binary for the crate (linked once); `cargo test -p lac-serve --test it MODULE`
//! runs one module's tests.

mod api;
mod common;
mod concurrency;
mod fit;
mod fuzz;
