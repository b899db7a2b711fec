//! CAD export (`lac export`): a segment, compound curve, path or space segment as rational
//! cubic B-splines within a tolerance, written as DXF, STEP, IGES, SVG or JSON.

use lac::Tolerance;
use lac_export::{Format, Meta};
use lac_io::json::{AnyCurve, ErrorBody};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{from_body, invalid};

/// Write `curve` (a `Segment`, `CompoundCurve`, `Path`, `Spline`, `SpaceSegment` or `Fit`) as a
/// CAD file:
/// returns the file's text and its report (a dict: `pieces`, `tolerance`, `max_deviation`
/// measured densely on what was written, `fit_deviation`, `continuity`, `monotone_proven`,
/// …, as `lac export` prints it).
///
/// `format` is "step", "iges", "dxf", "svg" (planar curves, plain cubics) or "json";
/// `tolerance` is in model units (millimetres in the CAD formats), or a share of the arc
/// length with `relative=True`; `pieces=True` writes one curve per Bézier piece; `name`
/// names the product. Raises `LacError` when the tolerance cannot be met (kind
/// `tolerance_not_met`) and `InvalidInput` for a bad format, tolerance or curve.
#[pyfunction]
#[pyo3(signature = (curve, format = "step", tolerance = 1e-6, relative = false, pieces = false, name = "lac"))]
pub(crate) fn export<'py>(
    py: Python<'py>,
    curve: &Bound<'py, PyAny>,
    format: &str,
    tolerance: f64,
    relative: bool,
    pieces: bool,
    name: &str,
) -> PyResult<(String, Bound<'py, PyDict>)> {
    let format: Format = serde_json::from_value(serde_json::Value::from(format)).map_err(|_| {
        invalid(
            py,
            format!("format must be one of step, iges, dxf, svg, json; got {format:?}"),
        )
    })?;
    if tolerance.is_nan() {
        return Err(invalid(py, "tolerance must be a number, got nan"));
    }
    let tolerance = if relative {
        Tolerance::Relative(tolerance)
    } else {
        Tolerance::Absolute(tolerance)
    };
    // A copy of the curve, so that the GIL can be released: every curve class gives one.
    let any = curve.call_method0("_any_curve").ok();
    let owned = match any.as_ref().map(|c| c.cast::<AnyCurveObject>()) {
        Some(Ok(c)) => c.get().0.clone(),
        _ => {
            return Err(invalid(
                py,
                "curve must be a Segment, CompoundCurve, Path, Spline, SpaceSegment or Fit",
            ))
        }
    };
    let meta = Meta::now(name);
    let written = py.detach(|| {
        let curve = owned.export_curve()?;
        Ok(lac_export::export(
            &curve, format, tolerance, pieces, &meta,
        )?)
    });
    let written = written.map_err(|e: ErrorBody| from_body(py, e))?;
    let report = serde_json::to_value(&written.report)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    let dict = PyDict::new(py);
    if let serde_json::Value::Object(fields) = report {
        for (key, value) in fields {
            dict.set_item(key, json_to_py(py, value)?)?;
        }
    }
    Ok((written.document, dict))
}

/// A report's JSON value as a Python object (its values are numbers, strings, booleans
/// and null).
fn json_to_py(py: Python<'_>, value: serde_json::Value) -> PyResult<Py<PyAny>> {
    use pyo3::IntoPyObjectExt;
    match value {
        serde_json::Value::Null => Ok(py.None()),
        serde_json::Value::Bool(b) => b.into_py_any(py),
        serde_json::Value::Number(n) => match n.as_u64() {
            Some(u) => u.into_py_any(py),
            None => n.as_f64().unwrap_or(f64::NAN).into_py_any(py),
        },
        serde_json::Value::String(s) => s.into_py_any(py),
        other => other.to_string().into_py_any(py),
    }
}

/// A curve of any kind, as a curve class hands it to [`export`] (`_any_curve`).
#[pyclass(module = "lac", name = "_AnyCurve", frozen)]
pub(crate) struct AnyCurveObject(pub(crate) AnyCurve);
