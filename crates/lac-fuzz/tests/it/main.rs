//! Integration tests of the fuzz driver: the seeded run and the regression corpus.
//!
//! One test binary for the crate (linked once); `cargo test -p lac-fuzz --test it MODULE`
//! runs one module's tests.

mod seeded;
