//! NumPy and sequences in, NumPy out.
//!
//! Input arrays of the wrong shape or of a dtype that is not real (complex, bool, strings,
//! objects) are refused with `lac.InvalidInput` (a `ValueError`) naming the argument, the
//! shape expected and the shape given; integers are taken as floats.

use kurbo::Point;
use numpy::ndarray::{Array2, Array3};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use crate::errors::invalid;

/// A real array read from Python: its numbers in C order, and its shape.
pub(crate) struct Real {
    pub(crate) data: Vec<f64>,
    pub(crate) shape: Vec<usize>,
}

/// The shape in NumPy's words, `(3, 2)`.
pub(crate) fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Any array-like of real numbers, as float64.
pub(crate) fn real_array(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Real> {
    let py = obj.py();
    let array = if let Ok(array) = obj.cast::<PyUntypedArray>() {
        let dtype = array.dtype();
        if !matches!(dtype.kind(), b'f' | b'i' | b'u') {
            return Err(invalid(
                py,
                format!(
                    "{what} must hold real numbers (a float or integer array), got dtype {}",
                    dtype.str()?
                ),
            ));
        }
        if dtype.is_equiv_to(&numpy::dtype::<f64>(py)) {
            array.clone().into_any()
        } else {
            obj.call_method1("astype", ("float64",))?
        }
    } else {
        // Sequences: NumPy decides the dtype first, so that complex numbers, strings and
        // other objects are refused by the check above rather than cast (a complex number
        // would lose its imaginary part with only a warning).
        let numpy = py.import("numpy")?;
        let array = numpy.call_method1("asarray", (obj,)).map_err(|e| {
            invalid(
                py,
                format!("{what} must be real numbers or sequences of them: {e}"),
            )
        })?;
        return real_array(&array, what);
    };
    // rust-numpy panics on arrays of more than 32 dimensions (NumPy 2 allows 64): no real
    // input has them, so they are refused before the view is taken.
    let ndim = array.cast::<PyUntypedArray>()?.ndim();
    if ndim > 8 {
        return Err(invalid(
            py,
            format!("{what} must be an array of at most 8 dimensions, got {ndim}"),
        ));
    }
    let array = array.cast_into::<PyArrayDyn<f64>>()?;
    let read = array.readonly();
    let view = read.as_array();
    Ok(Real {
        shape: view.shape().to_vec(),
        data: view.iter().copied().collect(),
    })
}

/// `N` points of dimension `D`: a sequence of `N` sequences of `D` numbers or an `N×D`
/// array.
pub(crate) fn fixed_points<const N: usize, const D: usize>(
    obj: &Bound<'_, PyAny>,
    what: &str,
) -> PyResult<[[f64; D]; N]> {
    // Tuples and lists of floats: no NumPy round trip (the single-call fast path).
    if obj.is_instance_of::<PyTuple>() || obj.is_instance_of::<PyList>() {
        if let Ok(points) = obj.extract::<[[f64; D]; N]>() {
            return Ok(points);
        }
    }
    let real = real_array(obj, what)?;
    if real.shape != [N, D] {
        return Err(invalid(
            obj.py(),
            format!(
                "{what} must be {N} points of {D} coordinates (shape ({N}, {D})), got shape {}",
                shape_text(&real.shape)
            ),
        ));
    }
    let mut out = [[0.0; D]; N];
    for (i, p) in out.iter_mut().enumerate() {
        p.copy_from_slice(&real.data[i * D..(i + 1) * D]);
    }
    Ok(out)
}

/// `N` planar points.
pub(crate) fn planar<const N: usize>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<[Point; N]> {
    Ok(fixed_points::<N, 2>(obj, what)?.map(|[x, y]| Point::new(x, y)))
}

/// An (n, 2) array or a sequence of (x, y) pairs as points.
pub(crate) fn point_list(
    py: Python<'_>,
    value: &Bound<'_, PyAny>,
    name: &str,
) -> PyResult<Vec<Point>> {
    let real = real_array(value, name)?;
    if real.shape.len() != 2 || real.shape[1] != 2 {
        return Err(invalid(
            py,
            format!("{name} must be an (n, 2) array or a sequence of (x, y) pairs"),
        ));
    }
    Ok(real
        .data
        .chunks(2)
        .map(|c| Point::new(c[0], c[1]))
        .collect())
}

/// A 1-D array of real numbers (a scalar is refused).
pub(crate) fn vector(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
    let real = real_array(obj, what)?;
    if real.shape.len() != 1 {
        return Err(invalid(
            obj.py(),
            format!(
                "{what} must be a 1-D array of numbers, got shape {}",
                shape_text(&real.shape)
            ),
        ));
    }
    Ok(real.data)
}

/// A scalar, or one number per item of `n`.
pub(crate) fn scalar_or_vector(obj: &Bound<'_, PyAny>, n: usize, what: &str) -> PyResult<Vec<f64>> {
    let real = real_array(obj, what)?;
    match real.shape.as_slice() {
        [] => Ok(vec![real.data[0]; n]),
        [m] if *m == n => Ok(real.data),
        _ => Err(invalid(
            obj.py(),
            format!(
                "{what} must be a number or an array of shape ({n},), got shape {}",
                shape_text(&real.shape)
            ),
        )),
    }
}

/// A 1-D float64 array.
pub(crate) fn array1<'py>(py: Python<'py>, v: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, v)
}

/// An `N×2` array of points.
pub(crate) fn points2<'py>(
    py: Python<'py>,
    points: impl ExactSizeIterator<Item = Point>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let n = points.len();
    let flat: Vec<f64> = points.flat_map(|p| [p.x, p.y]).collect();
    rows(py, flat, n, 2)
}

/// An `N×D` array from its numbers in C order.
pub(crate) fn rows(
    py: Python<'_>,
    flat: Vec<f64>,
    n: usize,
    d: usize,
) -> PyResult<Bound<'_, PyArray2<f64>>> {
    Ok(Array2::from_shape_vec((n, d), flat)
        .map_err(|e| PyRuntimeError::new_err(format!("lac-py defect, please report: {e}")))?
        .into_pyarray(py))
}

/// An `N×M×D` array from its numbers in C order.
pub(crate) fn blocks(
    py: Python<'_>,
    flat: Vec<f64>,
    shape: (usize, usize, usize),
) -> PyResult<Bound<'_, PyArray3<f64>>> {
    Ok(Array3::from_shape_vec(shape, flat)
        .map_err(|e| PyRuntimeError::new_err(format!("lac-py defect, please report: {e}")))?
        .into_pyarray(py))
}
