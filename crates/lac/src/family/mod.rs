//! Layer 1, the families: curves given by their mathematics, before any control point.
//! The planar log-aesthetic family in standard form ([`standard_form`]) and the
//! one-dimensional search that fits it to a chord and its end angles ([`chord_angle`]); the
//! straight line of its logarithmic curvature graph ([`lcg`]); rational cubic Bézier curves
//! ([`bezier`]) and the proof that their curvature is monotone ([`monotone`]); and the sample
//! of a planar curve that every curve returns ([`sample`]). Uses only the foundations.

pub(crate) mod bezier;
pub(crate) mod chord_angle;
pub(crate) mod lcg;
pub(crate) mod monotone;
pub(crate) mod sample;
pub(crate) mod standard_form;
