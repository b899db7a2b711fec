//! The exception hierarchy: `lac.LacError`, `lac.InvalidInput` (also a `ValueError`) and
//! `lac.NotDrawable`, chosen by the class `lac_io` gives each [`lac::ErrorKind`], so that
//! Python's exceptions, the command line's exit codes and the server's statuses agree.

use lac_io::json::{ErrorBody, ErrorClass};
use pyo3::exceptions::{PyException, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyTuple, PyType};

/// The three exception classes, made once per interpreter.
struct Classes {
    base: Py<PyType>,
    invalid: Py<PyType>,
    not_drawable: Py<PyType>,
}

static CLASSES: PyOnceLock<Classes> = PyOnceLock::new();

const BASE_DOC: &str = "Everything lac refuses or cannot do. `kind` is the library's snake_case \
    error kind (\"not_drawable\", \"collinear_points\", ...); `message` says what was wrong \
    and what would fix it.";
const INVALID_DOC: &str = "The input itself is wrong: a NaN, coincident or collinear points, \
    a parameter out of range, an array of the wrong shape. Also a ValueError.";
const NOT_DRAWABLE_DOC: &str = "The input is valid but no curve (or fit) exists for it: the \
    control points and slopes admit no log-aesthetic curve, or no chain of cubics meets the \
    tolerance.";

/// `type(name, bases, {"__doc__": doc, "__module__": "lac"})`.
fn make_class<'py>(
    py: Python<'py>,
    name: &str,
    bases: Bound<'py, PyTuple>,
    doc: &str,
) -> PyResult<Py<PyType>> {
    let dict = PyDict::new(py);
    dict.set_item("__doc__", doc)?;
    dict.set_item("__module__", "lac")?;
    let class = py.get_type::<PyType>().call1((name, bases, dict))?;
    Ok(class.cast_into::<PyType>()?.unbind())
}

fn classes(py: Python<'_>) -> PyResult<&Classes> {
    CLASSES.get_or_try_init(py, || {
        let base = make_class(
            py,
            "LacError",
            PyTuple::new(py, [py.get_type::<PyException>()])?,
            BASE_DOC,
        )?;
        let invalid = make_class(
            py,
            "InvalidInput",
            PyTuple::new(py, [base.bind(py).clone(), py.get_type::<PyValueError>()])?,
            INVALID_DOC,
        )?;
        let not_drawable = make_class(
            py,
            "NotDrawable",
            PyTuple::new(py, [base.bind(py).clone()])?,
            NOT_DRAWABLE_DOC,
        )?;
        Ok(Classes {
            base,
            invalid,
            not_drawable,
        })
    })
}

/// Add the classes to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let c = classes(m.py())?;
    m.add("LacError", c.base.bind(m.py()))?;
    m.add("InvalidInput", c.invalid.bind(m.py()))?;
    m.add("NotDrawable", c.not_drawable.bind(m.py()))?;
    Ok(())
}

/// The exception for a failure described as `lac_io` describes it, with `kind`, `message`
/// and (for space segments found at Ω = 0 but not at the Ω asked) `omega_max` attributes.
pub(crate) fn from_body(py: Python<'_>, body: ErrorBody) -> PyErr {
    let c = match classes(py) {
        Ok(c) => c,
        Err(e) => return e,
    };
    let class = match body.class() {
        ErrorClass::Invalid => &c.invalid,
        ErrorClass::Undrawable => &c.not_drawable,
        ErrorClass::Io | ErrorClass::Internal => &c.base,
    };
    let err = PyErr::from_type(class.bind(py).clone(), (body.message.clone(),));
    let value = err.value(py);
    let set = value
        .setattr("kind", &body.kind)
        .and_then(|()| value.setattr("message", &body.message))
        .and_then(|()| value.setattr("omega_max", body.omega_max));
    match set {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// The exception for a library error.
pub(crate) fn lac_err(py: Python<'_>, err: lac::Error) -> PyErr {
    from_body(py, ErrorBody::from(err))
}

/// `lac.InvalidInput` for input the bindings refuse themselves (shapes, dtypes, counts).
pub(crate) fn invalid(py: Python<'_>, message: impl Into<String>) -> PyErr {
    from_body(py, ErrorBody::invalid_input(message))
}

/// `Result<T, lac::Error>` to `PyResult<T>`.
pub(crate) trait OrRaise<T> {
    /// Raise the matching `lac` exception.
    fn or_raise(self, py: Python<'_>) -> PyResult<T>;
}

impl<T> OrRaise<T> for lac::Result<T> {
    fn or_raise(self, py: Python<'_>) -> PyResult<T> {
        self.map_err(|e| lac_err(py, e))
    }
}
