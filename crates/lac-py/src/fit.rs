//! Log-aesthetic paths fitted to points (`lac::Fit`): `lac.fit(points, …)` and the `Fit`
//! class it returns.
//!
//! A fit is a `Curve` (sampling, curvature plot, evolute, logarithmic curvature graph, CAD
//! export) with the fit's own figures. It is not a `Path`: `lac.Path` is a path solved from
//! a control polygon (its joint fractions, control triangles and straight pieces), which a
//! fit does not have.

use std::sync::Arc;

use lac::{Closure, Continuity};
use lac_io::json::{AnyCurve, FitInput, FittedPath};
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;

use crate::convert::{array1, points2, real_array, vector};
use crate::curve::PyCurve;
use crate::errors::{from_body, invalid};
use crate::export::AnyCurveObject;

/// A log-aesthetic path fitted to points (`lac.fit`): a `Curve` made of its segments, with
/// the fitted pieces (an S through an inflection is one piece of two segments), the joints
/// between them and each point's distance to the fit.
#[pyclass(module = "lac", name = "Fit", extends = PyCurve, frozen)]
pub(crate) struct PyFit {
    inner: Arc<lac::Fit>,
}

/// Fit a log-aesthetic path to `points` (an (n, 2) array or a sequence of (x, y) pairs, in
/// order along the curve), by orthogonal-distance least squares, as `lac fit` does.
///
/// Without `tolerance`, `max_segments` segments (default 1); with it, the fewest segments up
/// to `max_segments` (default 16) that keep every point within it, or `NotDrawable` (kind
/// `fit_tolerance_not_met`) naming the stretch of points it could not reach. `alpha` fixes
/// every segment's α; else it is fitted per segment within `alpha_range` (default (-5, 10)),
/// one for all with `shared_alpha`. `g1` joins with continuous tangent only, `closed` fits
/// points that go round once, `pin_ends` holds an open fit's ends on the first and last
/// points, `huber` is δ of Huber's robust loss, `weights` one per point.
///
/// The GIL is released while fitting.
#[pyfunction]
#[pyo3(signature = (points, tolerance = None, max_segments = None, alpha = None, alpha_range = None, shared_alpha = false, g1 = false, closed = false, pin_ends = false, huber = None, weights = None))]
#[allow(clippy::too_many_arguments)] // the keyword arguments of a Python function
pub(crate) fn fit(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    tolerance: Option<f64>,
    max_segments: Option<i64>,
    alpha: Option<f64>,
    alpha_range: Option<&Bound<'_, PyAny>>,
    shared_alpha: bool,
    g1: bool,
    closed: bool,
    pin_ends: bool,
    huber: Option<f64>,
    weights: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyFit>> {
    let real = real_array(points, "points")?;
    if real.shape.len() != 2 || real.shape[1] != 2 {
        return Err(invalid(
            py,
            "points must be an (n, 2) array or a sequence of (x, y) pairs",
        ));
    }
    let points: Vec<[f64; 2]> = real.data.chunks(2).map(|c| [c[0], c[1]]).collect();
    let max_segments = match max_segments {
        Some(n) => Some(usize::try_from(n).map_err(|_| {
            invalid(
                py,
                format!("max_segments must be between 1 and 64, got {n}"),
            )
        })?),
        None => None,
    };
    let alpha_range = match alpha_range.map(|r| vector(r, "alpha_range")).transpose()? {
        Some(v) => match v[..] {
            [a, b] => Some([a, b]),
            _ => {
                return Err(invalid(
                    py,
                    format!(
                        "alpha_range must be two numbers (min, max), got {}",
                        v.len()
                    ),
                ))
            }
        },
        None => None,
    };
    let input = FitInput {
        points,
        tolerance,
        max_segments,
        alpha,
        alpha_range,
        shared_alpha,
        g1,
        closed,
        pin_ends,
        huber,
        weights: weights.map(|w| vector(w, "weights")).transpose()?,
    };
    let fitted = py.detach(|| input.solve()).map_err(|e| from_body(py, e))?;
    let inner = Arc::new(fitted);
    Py::new(
        py,
        PyClassInitializer::from(PyCurve {
            inner: inner.clone(),
        })
        .add_subclass(PyFit { inner }),
    )
}

#[pymethods]
impl PyFit {
    /// The curve for `lac.export` (not public: `export` calls it).
    fn _any_curve(&self) -> AnyCurveObject {
        AnyCurveObject(AnyCurve::Fit(FittedPath::from(&*self.inner)))
    }

    /// "g1" or "g2".
    #[getter]
    fn continuity(&self) -> &'static str {
        match self.inner.continuity() {
            Continuity::G1 => "g1",
            Continuity::G2 => "g2",
        }
    }

    /// Whether the fit is closed.
    #[getter]
    fn closed(&self) -> bool {
        self.inner.closure() == Closure::Closed
    }

    /// The number of fitted log-aesthetic segments (an S through an inflection counts once;
    /// `pieces` lists the segments themselves, an S's two halves apart).
    #[getter]
    fn fitted_segments(&self) -> usize {
        self.inner.pieces().len()
    }

    /// Each fitted segment's α, shape (k,).
    #[getter]
    fn alphas<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.pieces().iter().map(|p| p.alpha).collect())
    }

    /// Each fitted segment's signed curvature at its start and end, shape (k, 2).
    #[getter]
    fn piece_curvatures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let ends = self
            .inner
            .pieces()
            .iter()
            .map(|p| kurbo::Point::new(p.curvatures[0], p.curvatures[1]));
        points2(py, ends.collect::<Vec<_>>().into_iter())
    }

    /// Each fitted segment's arc length, shape (k,).
    #[getter]
    fn piece_lengths<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.pieces().iter().map(|p| p.length).collect())
    }

    /// The arc length at which each fitted segment starts, shape (k,).
    #[getter]
    fn piece_starts<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.pieces().iter().map(|p| p.s).collect())
    }

    /// The arc lengths of the inflections (zero curvature inside an S), shape (m,).
    #[getter]
    fn inflections<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(
            py,
            self.inner
                .pieces()
                .iter()
                .filter_map(|p| p.inflection)
                .collect(),
        )
    }

    /// The arc length of each joint between fitted segments (a closed fit's last closes
    /// it), shape (j,).
    #[getter]
    fn joint_s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.joints().iter().map(|j| j.s).collect())
    }

    /// The joints, shape (j, 2).
    #[getter]
    fn joint_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(
            py,
            self.inner
                .joints()
                .iter()
                .map(|j| j.point)
                .collect::<Vec<_>>()
                .into_iter(),
        )
    }

    /// The signed curvature before and after each joint, shape (j, 2).
    #[getter]
    fn joint_curvatures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let k = self
            .inner
            .joints()
            .iter()
            .map(|j| kurbo::Point::new(j.curvature_before, j.curvature_after));
        points2(py, k.collect::<Vec<_>>().into_iter())
    }

    /// Each joint's relative curvature jump |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|), shape (j,).
    #[getter]
    fn curvature_jumps<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(
            py,
            self.inner
                .joints()
                .iter()
                .map(|j| j.curvature_jump)
                .collect(),
        )
    }

    /// Each joint's gap and tangent jump (radians) as the fit's check measured them, shape
    /// (j, 2).
    #[getter]
    fn joint_gaps<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let g = self
            .inner
            .joints()
            .iter()
            .map(|j| kurbo::Point::new(j.gap, j.tangent_jump));
        points2(py, g.collect::<Vec<_>>().into_iter())
    }

    /// Each point's distance to the fit, in the points' order, shape (n,).
    #[getter]
    fn distances<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.distances().to_vec())
    }

    /// Each point's foot on the fit, as arc length, shape (n,).
    #[getter]
    fn feet<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.feet().to_vec())
    }

    /// Root mean square of the distances.
    #[getter]
    fn rms(&self) -> f64 {
        self.inner.rms()
    }

    /// The largest distance.
    #[getter]
    fn max_distance(&self) -> f64 {
        self.inner.max_distance()
    }

    /// The index of the point farthest from the fit.
    #[getter]
    fn worst_point(&self) -> usize {
        self.inner.worst_point()
    }

    /// The indices of the `n` points farthest from the fit, farthest first.
    fn farthest_points<'py>(&self, py: Python<'py>, n: i64) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let n = usize::try_from(n)
            .map_err(|_| invalid(py, format!("n must be at least 0, got {n}")))?;
        Ok(PyArray1::from_iter(
            py,
            self.inner.farthest_points(n).into_iter().map(|k| k as i64),
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "<Fit continuity={} closed={} fitted_segments={} points={} rms={} max_distance={}>",
            self.continuity(),
            if self.closed() { "True" } else { "False" },
            self.inner.pieces().len(),
            self.inner.distances().len(),
            self.inner.rms(),
            self.inner.max_distance()
        )
    }
}
