//! Integration tests of the `lac` command: each module runs the built binary on one subcommand or concern.
//!
//! One test binary for the crate (linked once); `cargo test -p lac-cli --test it MODULE`
//! runs one module's tests.

mod batch;
mod common;
mod compound;
mod drawings;
mod export;
mod fit;
mod formats;
mod lcg;
mod monotone;
mod path;
mod quasi;
mod readme_figures;
mod region;
mod robustness;
mod segment;
mod serve;
mod space;
mod spline;
mod svg;
