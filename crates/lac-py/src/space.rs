//! Log-aesthetic space curves (seed 003 §4): a segment from four control points whose
//! logarithmic curvature and torsion graphs are both straight.

use crate::export::AnyCurveObject;
use lac::SpaceCurve;
use lac::{Frame, GraphPoint, Vec3};
use lac_io::json::AnyCurve;
use lac_io::json::SpaceInput;
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;

use crate::convert::{array1, fixed_points, rows, vector};
use crate::errors::{from_body, invalid, OrRaise};

/// A log-aesthetic space segment from four control points: it starts at P0 tangent to
/// P1 − P0 and ends at P3 tangent to P3 − P2, with log(ρ ds/dρ) = α log ρ + c and
/// log(μ ds/dμ) = β log μ + d (μ the radius of torsion), torsion parameter Ω ≥ 0 and
/// torsion type 1 (μ grows along the standard form) or 2.
///
/// `points` is a 4×3 array or four (x, y, z) triples. Coplanar points give the planar
/// segment (`is_planar`).
#[pyclass(module = "lac", name = "SpaceSegment", frozen)]
pub(crate) struct PySpaceSegment(pub(crate) lac::SpaceSegment);

fn vec3_rows<'py>(
    py: Python<'py>,
    frames: &[Frame],
    f: impl Fn(&Frame) -> Vec3,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = frames
        .iter()
        .flat_map(|fr| <[f64; 3]>::from(f(fr)))
        .collect();
    rows(py, flat, frames.len(), 3)
}

#[pymethods]
impl PySpaceSegment {
    /// The curve for `lac.export` (not public: `export` calls it).
    fn _any_curve(&self) -> AnyCurveObject {
        AnyCurveObject(AnyCurve::Space(self.0.clone()))
    }

    #[new]
    #[pyo3(signature = (points, alpha, beta, omega = 0.0, torsion_type = 1))]
    fn new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        alpha: f64,
        beta: f64,
        omega: f64,
        torsion_type: u8,
    ) -> PyResult<Self> {
        let input = SpaceInput {
            points: fixed_points::<4, 3>(points, "points")?,
            alpha,
            beta,
            omega,
            torsion_type,
        };
        Ok(PySpaceSegment(input.solve().map_err(|e| from_body(py, e))?))
    }

    /// The control points, shape (4, 3).
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let flat: Vec<f64> = self
            .0
            .control_points()
            .into_iter()
            .flat_map(<[f64; 3]>::from)
            .collect();
        rows(py, flat, 4, 3)
    }

    /// α, the slope of the logarithmic curvature graph.
    #[getter]
    fn alpha(&self) -> f64 {
        self.0.alpha()
    }

    /// β, the slope of the logarithmic torsion graph.
    #[getter]
    fn beta(&self) -> f64 {
        self.0.beta()
    }

    /// Ω, the torsion graph's parameter.
    #[getter]
    fn omega(&self) -> f64 {
        self.0.omega()
    }

    /// The torsion type, 1 or 2.
    #[getter]
    fn torsion_type(&self) -> u8 {
        self.0.torsion_type().number()
    }

    /// Whether the control points are coplanar and the segment is the planar one.
    #[getter]
    fn is_planar(&self) -> bool {
        self.0.is_planar()
    }

    /// Arc length from the first to the last point.
    #[getter]
    fn arc_length(&self) -> f64 {
        self.0.arc_length()
    }

    /// The Frenet frame, curvature and torsion at arc length `s`.
    fn frame_at(&self, py: Python<'_>, s: f64) -> PyResult<Frames> {
        Ok(Frames(vec![self.0.frame_at_s(s).or_raise(py)?]))
    }

    /// Frames at the given ascending arc lengths (a 1-D array within [0, arc_length]).
    fn frames(&self, py: Python<'_>, s: &Bound<'_, PyAny>) -> PyResult<Frames> {
        let at = vector(s, "s")?;
        Ok(Frames(self.0.frames(&at).or_raise(py)?))
    }

    /// `n ≥ 2` frames equally spaced in arc length.
    fn sample(&self, py: Python<'_>, n: i64) -> PyResult<Frames> {
        let n = usize::try_from(n)
            .map_err(|_| invalid(py, format!("n must be at least 2, got {n}")))?;
        Ok(Frames(self.0.sample_by_arc_length(n).or_raise(py)?))
    }

    /// The logarithmic curvature graph at `n` points: (log ρ, log(ρ ds/dρ)).
    fn log_curvature_graph(&self, py: Python<'_>, n: usize) -> PyResult<Graph> {
        Ok(Graph(self.0.log_curvature_graph(n).or_raise(py)?))
    }

    /// The logarithmic torsion graph at `n` points: (log μ, log(μ ds/dμ)).
    fn log_torsion_graph(&self, py: Python<'_>, n: usize) -> PyResult<Graph> {
        Ok(Graph(self.0.log_torsion_graph(n).or_raise(py)?))
    }

    fn __repr__(&self) -> String {
        format!(
            "<SpaceSegment alpha={} beta={} omega={} type={} arc_length={}>",
            self.0.alpha(),
            self.0.beta(),
            self.0.omega(),
            self.0.torsion_type().number(),
            self.0.arc_length()
        )
    }
}

/// Frames of a space curve: arc length `s` (n,), `points`, unit `tangents`, `normals` and
/// `binormals` (n, 3), `curvature` (n,, ≥ 0) and `torsion` (n,).
#[pyclass(module = "lac", name = "Frames", frozen)]
pub(crate) struct Frames(Vec<Frame>);

#[pymethods]
impl Frames {
    /// Arc length, shape (n,).
    #[getter]
    fn s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|f| f.s).collect())
    }

    /// Positions, shape (n, 3).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_rows(py, &self.0, |f| f.point)
    }

    /// Unit tangents, shape (n, 3).
    #[getter]
    fn tangents<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_rows(py, &self.0, |f| f.tangent)
    }

    /// Unit principal normals, shape (n, 3).
    #[getter]
    fn normals<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_rows(py, &self.0, |f| f.normal)
    }

    /// Unit binormals, shape (n, 3).
    #[getter]
    fn binormals<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_rows(py, &self.0, |f| f.binormal)
    }

    /// Curvature κ ≥ 0, shape (n,).
    #[getter]
    fn curvature<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|f| f.curvature).collect())
    }

    /// Torsion τ, shape (n,).
    #[getter]
    fn torsion<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|f| f.torsion).collect())
    }

    fn __len__(&self) -> usize {
        self.0.len()
    }

    fn __repr__(&self) -> String {
        format!("<Frames n={}>", self.0.len())
    }
}

/// A logarithmic graph of a space curve: arc length `s` and the graph's points `x`, `y`,
/// each shape (n,).
#[pyclass(module = "lac", name = "Graph", frozen)]
pub(crate) struct Graph(Vec<GraphPoint>);

#[pymethods]
impl Graph {
    /// Arc length, shape (n,).
    #[getter]
    fn s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|g| g.s).collect())
    }

    /// log ρ (or log μ), shape (n,).
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|g| g.x).collect())
    }

    /// log(ρ ds/dρ) (or log(μ ds/dμ)), shape (n,).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|g| g.y).collect())
    }

    fn __len__(&self) -> usize {
        self.0.len()
    }
}
