//! File formats and shared JSON shapes for log-aesthetic curves.
//!
//! The core crate `lac` does no I/O and knows no format vocabulary. This crate holds what
//! the front ends share: the JSON that the `lac` command prints and reads (one curve, or one
//! line of a `--batch`), which the editor's server speaks and the Python bindings mirror, in
//! [`json`], the CSV forms of the reports in [`csv`], and the point files that a fit reads
//! in [`points`]. CAD export is the crate
//! `lac-export`; its errors become this crate's JSON error body
//! ([`json::ErrorBody`]).

pub mod csv;
pub mod json;
pub mod points;
