//! Python bindings of lac: `import lac`.
//!
//! A thin front end (STYLE: parse, call the library, answer): every class wraps one type
//! of the `lac` crate and every error is the library's, classified as `lac_io` classifies
//! it for the command line and the server. Arrays go in and out as NumPy float64 arrays;
//! sampling, fitting and the vectorised `solve_segments` release the GIL.
//!
//! The extension module is `lac._lac`; the package `lac` (python/lac/__init__.py)
//! re-exports it with type stubs.

mod batch;
mod convert;
mod curve;
mod errors;
mod export;
mod fit;
mod path;
mod quasi;
mod region;
mod space;

use pyo3::prelude::*;

/// The extension module.
#[pymodule]
fn _lac(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    m.add_class::<curve::PyCurve>()?;
    m.add_class::<curve::PySegment>()?;
    m.add_class::<curve::PyCompoundCurve>()?;
    m.add_class::<curve::StandardForm>()?;
    m.add_class::<curve::Samples>()?;
    m.add_class::<curve::CurvaturePlot>()?;
    m.add_class::<curve::LogCurvatureGraph>()?;
    m.add_class::<curve::LcgFit>()?;
    m.add_class::<curve::LcgLine>()?;
    m.add_class::<quasi::PyRationalCubic>()?;
    m.add_class::<quasi::MonotonicityReport>()?;
    m.add_class::<quasi::QuasiPiece>()?;
    m.add_class::<quasi::PyQuasiCurve>()?;
    m.add_class::<path::PyPath>()?;
    m.add_class::<path::PySpline>()?;
    m.add_class::<fit::PyFit>()?;
    m.add_class::<space::PySpaceSegment>()?;
    m.add_class::<space::Frames>()?;
    m.add_class::<space::Graph>()?;
    m.add_class::<batch::SegmentBatch>()?;
    m.add_function(wrap_pyfunction!(quasi::curvature_plot, m)?)?;
    m.add_function(wrap_pyfunction!(quasi::log_curvature_graph, m)?)?;
    m.add_function(wrap_pyfunction!(region::drawable_region, m)?)?;
    m.add_function(wrap_pyfunction!(region::drawable_region_compound, m)?)?;
    m.add_function(wrap_pyfunction!(region::is_drawable, m)?)?;
    m.add_function(wrap_pyfunction!(region::classify, m)?)?;
    m.add_function(wrap_pyfunction!(region::pixel_center, m)?)?;
    m.add_function(wrap_pyfunction!(batch::solve_segments, m)?)?;
    m.add_function(wrap_pyfunction!(export::export, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add("MAX_ABS_ALPHA", lac::MAX_ABS_ALPHA)?;
    Ok(())
}
