//! Rational cubic Bézier curves, their curvature-monotonicity verdict (seed 001 §5) and
//! quasi-aesthetic curves (seed 001 §4): the chains of cubics that replace a
//! log-aesthetic curve.

use kurbo::ParamCurve;
use lac::{Monotonicity, MonotonicityReport as Report, QuasiCurve, RationalCubic};
use numpy::{PyArray1, PyArray2, PyArray3};
use pyo3::prelude::*;

use crate::convert::{array1, blocks, planar, points2, rows, vector};
use crate::curve::{CurvaturePlot, LogCurvatureGraph};
use crate::errors::{invalid, OrRaise};

/// A rational cubic Bézier curve: P(t) = Σ wᵢ bᵢ Bᵢ(t) / Σ wᵢ Bᵢ(t), t ∈ [0, 1], with
/// positive weights (all 1 for a plain cubic).
///
/// `points` is a 4×2 array or four (x, y) pairs; `weights` four positive numbers
/// (default: all 1).
#[pyclass(module = "lac", name = "RationalCubic", frozen)]
#[derive(Clone)]
pub(crate) struct PyRationalCubic(pub(crate) RationalCubic);

#[pymethods]
impl PyRationalCubic {
    #[new]
    #[pyo3(signature = (points, weights = None))]
    fn new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        weights: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let points = planar::<4>(points, "points")?;
        let weights = match weights {
            Some(w) => {
                let w = vector(w, "weights")?;
                <[f64; 4]>::try_from(w.as_slice()).map_err(|_| {
                    invalid(py, format!("weights must be 4 numbers, got {}", w.len()))
                })?
            }
            None => [1.0; 4],
        };
        Ok(PyRationalCubic(
            RationalCubic::new(points, weights).or_raise(py)?,
        ))
    }

    /// The control points b0..b3, shape (4, 2).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.points().into_iter())
    }

    /// The weights w0..w3, shape (4,).
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.weights().to_vec())
    }

    /// Arc length of the whole curve.
    #[getter]
    fn arc_length(&self) -> f64 {
        self.0.arc_length()
    }

    /// Points at the parameters `t` (a 1-D array in [0, 1]), shape (n, 2).
    fn eval<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let t = vector(t, "t")?;
        points2(py, t.iter().map(|&t| self.0.eval(t)))
    }

    /// `n ≥ 2` points equally spaced in the parameter t, shape (n, 2).
    fn sample<'py>(&self, py: Python<'py>, n: usize) -> PyResult<Bound<'py, PyArray2<f64>>> {
        if n < 2 {
            return Err(invalid(py, format!("n must be at least 2, got {n}")));
        }
        let last = (n - 1) as f64;
        points2(py, (0..n).map(|i| self.0.eval(i as f64 / last)))
    }

    /// Signed curvature at parameter `t` (positive for a left turn).
    fn signed_curvature(&self, t: f64) -> f64 {
        self.0.signed_curvature(t)
    }

    /// dκ/ds at parameter `t`.
    fn curvature_derivative(&self, t: f64) -> f64 {
        self.0.curvature_derivative(t)
    }

    /// Whether the curvature is monotone along the curve: a verdict proven for the exact
    /// curve the input doubles describe (seed 001 §5).
    fn curvature_monotonicity(&self, py: Python<'_>) -> PyResult<MonotonicityReport> {
        Ok(MonotonicityReport(
            self.0.curvature_monotonicity().or_raise(py)?,
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "RationalCubic({:?}, weights={:?})",
            self.0.points().map(|p| (p.x, p.y)),
            self.0.weights()
        )
    }
}

/// The verdict of the curvature-monotonicity test: `verdict` ("increasing",
/// "decreasing", "constant" or "not_monotone"), whether it is `proven`, and for
/// "not_monotone" a parameter `t` where dκ/ds changes sign.
#[pyclass(module = "lac", name = "MonotonicityReport", frozen)]
pub(crate) struct MonotonicityReport(pub(crate) Report);

#[pymethods]
impl MonotonicityReport {
    /// "increasing", "decreasing", "constant" or "not_monotone".
    #[getter]
    fn verdict(&self) -> &'static str {
        self.0.verdict.name()
    }

    /// Whether the verdict is proven for the exact curve (false only where dκ/ds is within
    /// rounding of zero on part of [0, 1], always for "constant").
    #[getter]
    fn proven(&self) -> bool {
        self.0.proven
    }

    /// Whether the curvature is monotone (increasing, decreasing or constant).
    #[getter]
    fn is_monotone(&self) -> bool {
        self.0.verdict.is_monotone()
    }

    /// For "not_monotone", a parameter in [0, 1] where dκ/ds changes sign; else None.
    #[getter]
    fn t(&self) -> Option<f64> {
        match self.0.verdict {
            Monotonicity::NotMonotone { t } => Some(t),
            _ => None,
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "MonotonicityReport(verdict={:?}, proven={})",
            self.0.verdict.name(),
            if self.0.proven { "True" } else { "False" }
        )
    }
}

/// One piece of a quasi-aesthetic curve: the rational cubic `curve`, its `monotonicity`
/// verdict, its `turning` at both ends and its `max_deviation` from the exact curve.
#[pyclass(module = "lac", name = "QuasiPiece", frozen)]
pub(crate) struct QuasiPiece(lac::QuasiPiece);

#[pymethods]
impl QuasiPiece {
    /// The rational (or plain) cubic.
    #[getter]
    fn curve(&self) -> PyRationalCubic {
        PyRationalCubic(self.0.curve)
    }

    /// The curvature-monotonicity verdict of the piece.
    #[getter]
    fn monotonicity(&self) -> MonotonicityReport {
        MonotonicityReport(self.0.monotonicity)
    }

    /// The tangent turning from the exact curve's, at the piece's start and end
    /// (radians).
    #[getter]
    fn turning(&self) -> (f64, f64) {
        self.0.turning
    }

    /// The largest distance from the exact curve, in the curve's units.
    #[getter]
    fn max_deviation(&self) -> f64 {
        self.0.max_deviation
    }
}

/// A quasi-aesthetic replacement of a log-aesthetic curve (seed 001 §4): `pieces` of
/// rational (or plain) cubics joined G2, with their deviation from the curve relative to
/// its arc length (`rms`, `max`).
#[pyclass(module = "lac", name = "QuasiCurve", frozen)]
pub(crate) struct PyQuasiCurve {
    inner: QuasiCurve,
    arc_length: f64,
}

impl PyQuasiCurve {
    pub(crate) fn new(inner: QuasiCurve, arc_length: f64) -> Self {
        PyQuasiCurve { inner, arc_length }
    }

    fn cubics(&self) -> Vec<RationalCubic> {
        self.inner.pieces.iter().map(|p| p.curve).collect()
    }
}

#[pymethods]
impl PyQuasiCurve {
    /// The pieces, in order from the first point.
    #[getter]
    fn pieces(&self) -> Vec<QuasiPiece> {
        self.inner.pieces.iter().map(|p| QuasiPiece(*p)).collect()
    }

    /// Root-mean-square deviation from the exact curve, relative to its arc length.
    #[getter]
    fn rms(&self) -> f64 {
        self.inner.rms
    }

    /// Largest deviation from the exact curve, relative to its arc length.
    #[getter]
    fn max(&self) -> f64 {
        self.inner.max
    }

    /// Largest deviation in the curve's units.
    #[getter]
    fn max_deviation(&self) -> f64 {
        self.inner.max * self.arc_length
    }

    /// Whether every piece's curvature is monotone (the verdict of each piece).
    #[getter]
    fn is_monotone(&self) -> bool {
        self.inner
            .pieces
            .iter()
            .all(|p| p.monotonicity.verdict.is_monotone())
    }

    /// The control points of every piece, shape (pieces, 4, 2).
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let flat: Vec<f64> = self
            .inner
            .pieces
            .iter()
            .flat_map(|p| p.curve.points())
            .flat_map(|p| [p.x, p.y])
            .collect();
        blocks(py, flat, (self.inner.pieces.len(), 4, 2))
    }

    /// The weights of every piece, shape (pieces, 4).
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let flat: Vec<f64> = self
            .inner
            .pieces
            .iter()
            .flat_map(|p| p.curve.weights())
            .collect();
        rows(py, flat, self.inner.pieces.len(), 4)
    }

    /// `per_piece ≥ 2` points of each piece, equally spaced in its parameter, the shared
    /// ends once: shape (pieces · (per_piece − 1) + 1, 2).
    fn sample<'py>(
        &self,
        py: Python<'py>,
        per_piece: usize,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        if per_piece < 2 {
            return Err(invalid(
                py,
                format!("per_piece must be at least 2, got {per_piece}"),
            ));
        }
        let last = (per_piece - 1) as f64;
        let mut points = Vec::new();
        for (k, piece) in self.inner.pieces.iter().enumerate() {
            let skip = usize::from(k > 0);
            points.extend((skip..per_piece).map(|i| piece.curve.eval(i as f64 / last)));
        }
        points2(py, points.into_iter())
    }

    /// The curvature plot of the chain, `per_piece ≥ 2` points per piece.
    fn curvature_plot(&self, py: Python<'_>, per_piece: usize) -> PyResult<CurvaturePlot> {
        Ok(CurvaturePlot(
            lac::curvature_plot(&self.cubics(), per_piece).or_raise(py)?,
        ))
    }

    fn __len__(&self) -> usize {
        self.inner.pieces.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "<QuasiCurve pieces={} max={:e} monotone={}>",
            self.inner.pieces.len(),
            self.inner.max,
            if self.is_monotone() { "True" } else { "False" }
        )
    }
}

/// The curvature plot of a chain of Bézier pieces (RationalCubic), `per_piece ≥ 2`
/// points each, with the exact dκ/ds.
#[pyfunction]
pub(crate) fn curvature_plot(
    py: Python<'_>,
    pieces: Vec<PyRef<'_, PyRationalCubic>>,
    per_piece: usize,
) -> PyResult<CurvaturePlot> {
    let cubics: Vec<RationalCubic> = pieces.iter().map(|p| p.0).collect();
    Ok(CurvaturePlot(
        lac::curvature_plot(&cubics, per_piece).or_raise(py)?,
    ))
}

/// The logarithmic curvature graph of a curvature plot, with its least-squares line.
#[pyfunction]
pub(crate) fn log_curvature_graph(plot: &CurvaturePlot) -> LogCurvatureGraph {
    LogCurvatureGraph(lac::log_curvature_graph(&plot.0))
}
