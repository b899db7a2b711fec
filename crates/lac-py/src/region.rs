//! Drawable regions (seed 000 §4.2, Fig. 9): with the first control point at (−1, 0) and
//! the last at (1, 0), where may the middle one lie? Rows are computed in parallel with
//! the GIL released.

use kurbo::Point;
use lac_io::json::RegionInput;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::errors::{from_body, invalid, OrRaise};

/// The largest map side the bindings draw (a 4096² map is 16 M solves, about a minute).
const MAX_SIZE: usize = 4096;

fn map<'py>(
    py: Python<'py>,
    input: RegionInput,
    size: usize,
) -> PyResult<Bound<'py, PyArray2<bool>>> {
    input.check().map_err(|e| from_body(py, e))?;
    if !(1..=MAX_SIZE).contains(&size) {
        return Err(invalid(
            py,
            format!("size must be between 1 and {MAX_SIZE} pixels per side, got {size}"),
        ));
    }
    let flat: Vec<bool> = py.detach(|| {
        input
            .rows(size, |top| {
                (0..top)
                    .into_par_iter()
                    .map(|row| input.row(size, row))
                    .collect()
            })
            .concat()
    });
    let array = Array2::from_shape_vec((size, size), flat)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    Ok(array.into_pyarray(py))
}

/// The drawable region of segments of slope `alpha`: a `size`×`size` boolean map of the
/// middle control point over [−1, 1]², row 0 at y = +1, column 0 at x = −1 (pixel
/// centres: `pixel_center`). Matplotlib: `imshow(m, extent=(-1, 1, -1, 1))`.
#[pyfunction]
#[pyo3(signature = (alpha, size = 256))]
pub(crate) fn drawable_region<'py>(
    py: Python<'py>,
    alpha: f64,
    size: usize,
) -> PyResult<Bound<'py, PyArray2<bool>>> {
    let input = RegionInput {
        alpha,
        alpha1: None,
        ratio: None,
        size: Some(size),
    };
    map(py, input, size)
}

/// The drawable region of compound curves of slopes `alpha0`, `alpha1` and turning ratio
/// `ratio`, as `drawable_region`.
#[pyfunction]
#[pyo3(signature = (alpha0, alpha1, ratio, size = 256))]
pub(crate) fn drawable_region_compound<'py>(
    py: Python<'py>,
    alpha0: f64,
    alpha1: f64,
    ratio: f64,
    size: usize,
) -> PyResult<Bound<'py, PyArray2<bool>>> {
    let input = RegionInput {
        alpha: alpha0,
        alpha1: Some(alpha1),
        ratio: Some(ratio),
        size: Some(size),
    };
    map(py, input, size)
}

/// Is there a segment of slope `alpha` from (−1, 0) to (1, 0) with this middle point?
#[pyfunction]
pub(crate) fn is_drawable(alpha: f64, middle: [f64; 2]) -> bool {
    lac::region::is_drawable(alpha, Point::new(middle[0], middle[1]))
}

/// `None` when a segment of slope `alpha` from (−1, 0) to (1, 0) with this middle point
/// exists; otherwise raise the library's reason.
#[pyfunction]
pub(crate) fn classify(py: Python<'_>, alpha: f64, middle: [f64; 2]) -> PyResult<()> {
    lac::region::classify(alpha, Point::new(middle[0], middle[1])).or_raise(py)
}

/// The centre of pixel (`row`, `col`) of a `size`×`size` map, as (x, y).
#[pyfunction]
pub(crate) fn pixel_center(size: usize, row: usize, col: usize) -> (f64, f64) {
    let p = lac::region::pixel_center(size, row, col);
    (p.x, p.y)
}
