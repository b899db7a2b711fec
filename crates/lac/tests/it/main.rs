//! Integration tests of the core crate, one module per subject (see each module's own comment).
//!
//! One test binary for the crate (linked once); `cargo test -p lac --test it MODULE`
//! runs one module's tests.

mod architecture;
mod bezier_kurbo;
mod common;
mod compound;
mod curve_trait;
mod fit;
mod fit_prius;
mod kurbo_traits;
mod monotone;
mod path;
mod properties;
mod quasi;
mod reference;
mod reference_compound;
mod reference_quasi;
mod reference_space;
mod region;
mod segment_api;
mod space_classification;
mod space_constructed;
mod space_cubics;
mod space_segment;
mod space_serde;
mod spline;
mod spline_types;
mod standard_form;
