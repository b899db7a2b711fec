//! Planar log-aesthetic curves: the `Curve` base class (everything `lac::Curve` offers,
//! written once), `Segment` (seed 000 §4) and `CompoundCurve` (seeds 004 and 002), the
//! standard form, and the results of sampling and analysis as NumPy arrays.

use crate::export::AnyCurveObject;
use lac_io::json::AnyCurve;
use std::sync::Arc;

use kurbo::Point;
use lac::{CurvaturePoint, Curve as _, Sample, ToBezier, Tolerance, Turn};
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;

use crate::convert::{array1, planar, point_list, points2, vector};
use crate::errors::{invalid, OrRaise};
use crate::quasi::PyQuasiCurve;

/// A curve the bindings hold: a segment or a compound curve, shared with the threads that
/// sample it while the GIL is released.
pub(crate) type Shared = Arc<dyn lac::SegmentChain + Send + Sync>;

/// A planar log-aesthetic curve: one or more log-aesthetic pieces joined end to end
/// (`Segment`, `CompoundCurve`). Arc length `s` runs from the first point; signed curvature
/// is positive for a left turn; angles are radians.
#[pyclass(module = "lac", name = "Curve", subclass, frozen)]
pub(crate) struct PyCurve {
    pub(crate) inner: Shared,
}

fn xy(py: Python<'_>, p: Point) -> Bound<'_, PyArray1<f64>> {
    array1(py, vec![p.x, p.y])
}

fn tolerance(py: Python<'_>, value: f64, absolute: bool) -> PyResult<Tolerance> {
    if value.is_nan() {
        return Err(invalid(py, "tolerance must be a number, got nan"));
    }
    Ok(if absolute {
        Tolerance::Absolute(value)
    } else {
        Tolerance::Relative(value)
    })
}

/// Check a sample count before the library sees it (a negative count is a Python error,
/// not an overflow).
fn count(py: Python<'_>, n: i64, what: &str) -> PyResult<usize> {
    usize::try_from(n).map_err(|_| invalid(py, format!("{what} must be at least 2, got {n}")))
}

#[pymethods]
impl PyCurve {
    /// Arc length from the first to the last point.
    #[getter]
    fn arc_length(&self) -> f64 {
        self.inner.arc_length()
    }

    /// The arc lengths of the joints between consecutive pieces (empty for one piece).
    #[getter]
    fn joints<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.inner.joint_arc_lengths())
    }

    /// The first point, shape (2,).
    #[getter]
    fn start_point<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        xy(py, self.inner.start_point())
    }

    /// The last point, shape (2,).
    #[getter]
    fn end_point<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        xy(py, self.inner.end_point())
    }

    /// Signed curvature at the first point (positive for a left turn).
    #[getter]
    fn curvature_start(&self) -> f64 {
        self.inner.signed_curvature_start()
    }

    /// Signed curvature at the last point.
    #[getter]
    fn curvature_end(&self) -> f64 {
        self.inner.signed_curvature_end()
    }

    /// Total turning of the tangent from the first to the last point, radians, signed
    /// (positive for a left turn).
    #[getter]
    fn turning(&self) -> f64 {
        self.inner.turning()
    }

    /// The log-aesthetic pieces in order from the first point, as `Segment`s.
    #[getter]
    fn pieces(&self, py: Python<'_>) -> PyResult<Vec<Py<PySegment>>> {
        self.inner
            .pieces()
            .iter()
            .map(|s| PySegment::wrap(py, s.clone()))
            .collect()
    }

    /// Point at arc length `s` (0 ≤ s ≤ arc_length), shape (2,).
    fn point_at_s<'py>(&self, py: Python<'py>, s: f64) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(xy(py, self.inner.point_at_s(s).or_raise(py)?))
    }

    /// Unit tangent at arc length `s`, in the direction of travel, shape (2,).
    fn tangent_at_s<'py>(&self, py: Python<'py>, s: f64) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let t = self.inner.tangent_at_s(s).or_raise(py)?;
        Ok(array1(py, vec![t.x, t.y]))
    }

    /// Tangent direction at arc length `s` (radians, continuous from the first point).
    fn theta_at_s(&self, py: Python<'_>, s: f64) -> PyResult<f64> {
        self.inner.theta_at_s(s).or_raise(py)
    }

    /// Signed curvature at arc length `s` (positive for a left turn).
    fn curvature_at_s(&self, py: Python<'_>, s: f64) -> PyResult<f64> {
        self.inner.signed_curvature_at_s(s).or_raise(py)
    }

    /// `n ≥ 2` samples equally spaced in arc length, the first at the first point and the
    /// last at the last.
    fn sample(&self, py: Python<'_>, n: i64) -> PyResult<Samples> {
        let n = count(py, n, "n")?;
        let curve = self.inner.clone();
        let samples = py.detach(move || curve.sample_by_arc_length(n));
        Ok(Samples(samples.or_raise(py)?))
    }

    /// Samples at the given arc lengths (a 1-D array), which must ascend within
    /// [0, arc_length].
    fn sample_at(&self, py: Python<'_>, s: &Bound<'_, PyAny>) -> PyResult<Samples> {
        let at = vector(s, "s")?;
        let curve = self.inner.clone();
        let samples = py.detach(move || curve.samples_at_arc_lengths(&at));
        Ok(Samples(samples.or_raise(py)?))
    }

    /// Samples such that the polyline through them stays within `accuracy` (a distance in
    /// the curve's units) of the curve; every joint is a sample.
    fn sample_adaptive(&self, py: Python<'_>, accuracy: f64) -> PyResult<Samples> {
        let curve = self.inner.clone();
        let samples = py.detach(move || curve.sample_adaptive(accuracy));
        Ok(Samples(samples.or_raise(py)?))
    }

    /// `n ≥ 2` points of the evolute (the centres of curvature P + N/κ) at the arc-length
    /// samples, shape (n, 2).
    fn evolute<'py>(&self, py: Python<'py>, n: i64) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let n = count(py, n, "n")?;
        let points = self.inner.evolute(n).or_raise(py)?;
        points2(py, points.into_iter())
    }

    /// `n ≥ 2` points of the curvature plot equally spaced in arc length, with the exact
    /// dκ/ds.
    fn curvature_plot(&self, py: Python<'_>, n: i64) -> PyResult<CurvaturePlot> {
        let n = count(py, n, "n")?;
        Ok(CurvaturePlot(self.inner.curvature_plot(n).or_raise(py)?))
    }

    /// The logarithmic curvature graph of `n ≥ 2` points of the curvature plot, with its
    /// least-squares line (the fitted α).
    fn log_curvature_graph(&self, py: Python<'_>, n: i64) -> PyResult<LogCurvatureGraph> {
        let n = count(py, n, "n")?;
        let plot = self.inner.curvature_plot(n).or_raise(py)?;
        Ok(LogCurvatureGraph(lac::log_curvature_graph(&plot)))
    }

    /// One rational cubic with the curve's ends, end tangents and end curvatures, closest
    /// to it in the least-squares sense of seed 001 §4.
    fn to_rational_cubic(&self, py: Python<'_>) -> PyResult<PyQuasiCurve> {
        let curve = self.inner.clone();
        let quasi = py.detach(move || curve.to_rational_cubic());
        Ok(PyQuasiCurve::new(
            quasi.or_raise(py)?,
            self.inner.arc_length(),
        ))
    }

    /// As few rational cubics as needed for a maximum deviation within `tolerance`
    /// (relative to the arc length, or in the curve's units when `absolute`), each with
    /// curvature proven monotone, joined G2.
    #[pyo3(signature = (tolerance, *, absolute = false))]
    fn to_rational_cubics(
        &self,
        py: Python<'_>,
        tolerance: f64,
        absolute: bool,
    ) -> PyResult<PyQuasiCurve> {
        let tol = self::tolerance(py, tolerance, absolute)?;
        let curve = self.inner.clone();
        let quasi = py.detach(move || curve.to_rational_cubics(tol));
        Ok(PyQuasiCurve::new(
            quasi.or_raise(py)?,
            self.inner.arc_length(),
        ))
    }

    /// As few plain (polynomial) cubics as needed for a maximum deviation within
    /// `tolerance` (relative, or absolute), each with curvature proven monotone, joined G2.
    #[pyo3(signature = (tolerance, *, absolute = false))]
    fn to_cubics(&self, py: Python<'_>, tolerance: f64, absolute: bool) -> PyResult<PyQuasiCurve> {
        let tol = self::tolerance(py, tolerance, absolute)?;
        let curve = self.inner.clone();
        let quasi = py.detach(move || curve.to_cubics(tol));
        Ok(PyQuasiCurve::new(
            quasi.or_raise(py)?,
            self.inner.arc_length(),
        ))
    }
}

/// A log-aesthetic segment from three control points and α (seed 000 §4): it starts at
/// P0 tangent to P1 − P0 and ends at P2 tangent to P2 − P1, and its curvature follows
/// dρ/ds = Λ ρ^(1−α).
///
/// `points` is a 3×2 array or a sequence of three (x, y) pairs.
#[pyclass(module = "lac", name = "Segment", extends = PyCurve, frozen)]
pub(crate) struct PySegment {
    pub(crate) inner: Arc<lac::Segment>,
}

impl PySegment {
    /// A Python `Segment` for a solved segment.
    pub(crate) fn wrap(py: Python<'_>, segment: lac::Segment) -> PyResult<Py<PySegment>> {
        Py::new(py, Self::init(segment))
    }

    /// The base class and the subclass share the one solved segment.
    fn init(segment: lac::Segment) -> PyClassInitializer<PySegment> {
        let inner = Arc::new(segment);
        PyClassInitializer::from(PyCurve {
            inner: inner.clone(),
        })
        .add_subclass(PySegment { inner })
    }
}

fn turn_name(turn: Turn) -> &'static str {
    match turn {
        Turn::Left => "left",
        Turn::Right => "right",
    }
}

#[pymethods]
impl PySegment {
    /// The curve for `lac.export` (not public: `export` calls it).
    fn _any_curve(&self) -> AnyCurveObject {
        AnyCurveObject(AnyCurve::Segment((*self.inner).clone()))
    }

    #[new]
    fn new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        alpha: f64,
    ) -> PyResult<PyClassInitializer<PySegment>> {
        let points = planar::<3>(points, "points")?;
        let segment = lac::Segment::from_control_points(points, alpha).or_raise(py)?;
        Ok(Self::init(segment))
    }

    /// The slope α of the logarithmic curvature graph.
    #[getter]
    fn alpha(&self) -> f64 {
        self.inner.alpha()
    }

    /// Λ of the solved standard-form piece (0 for a circular arc).
    #[getter]
    fn lambda_(&self) -> f64 {
        self.inner.lambda()
    }

    /// Turning angle of the control polygon, radians, in (0, π).
    #[getter]
    fn turning_angle(&self) -> f64 {
        self.inner.turning_angle()
    }

    /// "left" or "right": which way the segment turns.
    #[getter]
    fn turn(&self) -> &'static str {
        turn_name(self.inner.turn())
    }

    /// Whether the segment is a circular arc (Λ = 0).
    #[getter]
    fn is_circle(&self) -> bool {
        self.inner.is_circle()
    }

    /// The control points, shape (3, 2).
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.inner.control_points().into_iter())
    }

    /// The standard form the segment is a similar copy of.
    #[getter]
    fn standard_form(&self) -> StandardForm {
        StandardForm(self.inner.standard_form())
    }

    /// Arc length at tangent angle `theta` (radians, measured from the start tangent in
    /// the turning direction).
    fn s_at_theta(&self, py: Python<'_>, theta: f64) -> PyResult<f64> {
        self.inner.s_at_theta(theta).or_raise(py)
    }

    /// Point at tangent angle `theta`, shape (2,).
    fn point_at_theta<'py>(
        &self,
        py: Python<'py>,
        theta: f64,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(xy(py, self.inner.point_at_theta(theta).or_raise(py)?))
    }

    /// Signed curvature at tangent angle `theta`.
    fn curvature_at_theta(&self, py: Python<'_>, theta: f64) -> PyResult<f64> {
        self.inner.signed_curvature_at_theta(theta).or_raise(py)
    }

    /// `n ≥ 2` samples equally spaced in tangent angle.
    fn sample_by_tangent_angle(&self, py: Python<'_>, n: i64) -> PyResult<Samples> {
        let n = count(py, n, "n")?;
        Ok(Samples(self.inner.sample_by_tangent_angle(n).or_raise(py)?))
    }

    /// The segment's logarithmic curvature graph, a straight line; None for a circular arc.
    fn lcg(&self) -> Option<LcgLine> {
        self.inner.lcg().map(LcgLine)
    }

    fn __repr__(&self) -> String {
        let [a, b, c] = self.inner.control_points();
        format!(
            "Segment([({}, {}), ({}, {}), ({}, {})], alpha={})",
            a.x,
            a.y,
            b.x,
            b.y,
            c.x,
            c.y,
            self.inner.alpha()
        )
    }
}

/// A compound-rhythm curve: two log-aesthetic pieces of slopes α0 (from the first point)
/// and α1 joined with G3 continuity.
///
/// From three control points (the ends and the end tangents' intersection) and `ratio`,
/// the share of the turning made by the α0 piece (seed 004); or from four control points
/// without `ratio`: it starts at P0 tangent to P1 − P0, ends at P3 tangent to P3 − P2, and
/// its joint's tangent is parallel to P2 − P1 (seed 002).
#[pyclass(module = "lac", name = "CompoundCurve", extends = PyCurve, frozen)]
pub(crate) struct PyCompoundCurve {
    pub(crate) inner: Arc<lac::CompoundCurve>,
}

impl PyCompoundCurve {
    /// The base class and the subclass share the one solved curve.
    fn init(curve: lac::CompoundCurve) -> PyClassInitializer<PyCompoundCurve> {
        let inner = Arc::new(curve);
        PyClassInitializer::from(PyCurve {
            inner: inner.clone(),
        })
        .add_subclass(PyCompoundCurve { inner })
    }
}

#[pymethods]
impl PyCompoundCurve {
    /// The curve for `lac.export` (not public: `export` calls it).
    fn _any_curve(&self) -> AnyCurveObject {
        AnyCurveObject(AnyCurve::Compound((*self.inner).clone()))
    }

    #[new]
    #[pyo3(signature = (points, alpha0, alpha1, ratio = None))]
    fn new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        alpha0: f64,
        alpha1: f64,
        ratio: Option<f64>,
    ) -> PyResult<PyClassInitializer<PyCompoundCurve>> {
        let curve = match ratio {
            Some(ratio) => lac::CompoundCurve::from_three_points(
                planar::<3>(points, "points (three points with ratio)")?,
                alpha0,
                alpha1,
                ratio,
            ),
            None => lac::CompoundCurve::from_four_points(
                planar::<4>(points, "points (four points without ratio)")?,
                alpha0,
                alpha1,
            ),
        };
        Ok(Self::init(curve.or_raise(py)?))
    }

    /// The compound curve of three control points and a turning ratio (seed 004).
    #[staticmethod]
    fn from_three_points(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        alpha0: f64,
        alpha1: f64,
        ratio: f64,
    ) -> PyResult<Py<PyCompoundCurve>> {
        let points = planar::<3>(points, "points")?;
        let curve =
            lac::CompoundCurve::from_three_points(points, alpha0, alpha1, ratio).or_raise(py)?;
        Py::new(py, Self::init(curve))
    }

    /// The compound curve of four control points (seed 002).
    #[staticmethod]
    fn from_four_points(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        alpha0: f64,
        alpha1: f64,
    ) -> PyResult<Py<PyCompoundCurve>> {
        let points = planar::<4>(points, "points")?;
        let curve = lac::CompoundCurve::from_four_points(points, alpha0, alpha1).or_raise(py)?;
        Py::new(py, Self::init(curve))
    }

    /// The slope of the piece from the first point to the joint.
    #[getter]
    fn alpha0(&self) -> f64 {
        self.inner.alpha()[0]
    }

    /// The slope of the piece from the joint to the last point.
    #[getter]
    fn alpha1(&self) -> f64 {
        self.inner.alpha()[1]
    }

    /// Λ of the joint-reference standard form (ρ = 1 at the joint).
    #[getter]
    fn lambda_(&self) -> f64 {
        self.inner.lambda()
    }

    /// Arc length from the first point to the joint.
    #[getter]
    fn joint_s(&self) -> f64 {
        self.inner.joint_s()
    }

    /// The joint, shape (2,).
    #[getter]
    fn joint<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        xy(py, self.inner.joint())
    }

    /// Signed curvature at the joint (the same from both pieces).
    #[getter]
    fn curvature_joint(&self) -> f64 {
        self.inner.signed_curvature_joint()
    }

    /// The logarithmic curvature graph of each piece (None for a circular arc).
    fn lcg(&self) -> (Option<LcgLine>, Option<LcgLine>) {
        let [a, b] = self.inner.lcg();
        (a.map(LcgLine), b.map(LcgLine))
    }

    fn __repr__(&self) -> String {
        let [a0, a1] = self.inner.alpha();
        format!(
            "<CompoundCurve alpha0={a0} alpha1={a1} arc_length={}>",
            self.inner.arc_length()
        )
    }
}

/// The standard form of a log-aesthetic curve: ρ = 1 and θ = 0 at s = 0, dρ/ds =
/// Λ ρ^(1−α) (seed 000 §3). `StandardForm(alpha, lambda_)`.
#[pyclass(module = "lac", name = "StandardForm", frozen)]
pub(crate) struct StandardForm(lac::StandardForm);

#[pymethods]
impl StandardForm {
    #[new]
    fn new(py: Python<'_>, alpha: f64, lambda_: f64) -> PyResult<StandardForm> {
        Ok(StandardForm(
            lac::StandardForm::new(alpha, lambda_).or_raise(py)?,
        ))
    }

    /// α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.0.alpha
    }

    /// Λ.
    #[getter]
    fn lambda_(&self) -> f64 {
        self.0.lambda
    }

    /// The range of s over which the form is defined.
    #[getter]
    fn s_bounds(&self) -> (f64, f64) {
        self.0.s_bounds()
    }

    /// The range of θ over which the form is defined.
    #[getter]
    fn theta_bounds(&self) -> (f64, f64) {
        self.0.theta_bounds()
    }

    /// Radius of curvature at arc length `s`.
    fn rho_at_s(&self, py: Python<'_>, s: f64) -> PyResult<f64> {
        self.0.rho_at_s(s).or_raise(py)
    }

    /// Tangent angle at arc length `s`.
    fn theta_at_s(&self, py: Python<'_>, s: f64) -> PyResult<f64> {
        self.0.theta_at_s(s).or_raise(py)
    }

    /// Radius of curvature at tangent angle `theta`.
    fn rho_at_theta(&self, py: Python<'_>, theta: f64) -> PyResult<f64> {
        self.0.rho_at_theta(theta).or_raise(py)
    }

    /// Arc length at tangent angle `theta`.
    fn s_at_theta(&self, py: Python<'_>, theta: f64) -> PyResult<f64> {
        self.0.s_at_theta(theta).or_raise(py)
    }

    /// Point at arc length `s`, shape (2,).
    fn point_at_s<'py>(&self, py: Python<'py>, s: f64) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(xy(py, self.0.point_at_s(s).or_raise(py)?))
    }

    /// Point at tangent angle `theta`, shape (2,).
    fn point_at_theta<'py>(
        &self,
        py: Python<'py>,
        theta: f64,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(xy(py, self.0.point_at_theta(theta).or_raise(py)?))
    }

    fn __repr__(&self) -> String {
        format!("StandardForm({}, {})", self.0.alpha, self.0.lambda)
    }
}

/// Samples of a curve: arc length `s` (n,), `points` (n, 2), tangent direction `theta`
/// (n,, radians) and signed curvature `kappa` (n,). Each attribute access builds a new
/// array.
#[pyclass(module = "lac", name = "Samples", frozen)]
pub(crate) struct Samples(pub(crate) Vec<Sample>);

#[pymethods]
impl Samples {
    /// Arc length from the first point, shape (n,).
    #[getter]
    fn s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|s| s.s).collect())
    }

    /// Positions, shape (n, 2).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.iter().map(|s| s.point))
    }

    /// Tangent directions, radians, continuous from the first point, shape (n,).
    #[getter]
    fn theta<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|s| s.theta).collect())
    }

    /// Signed curvatures (positive for a left turn), shape (n,).
    #[getter]
    fn kappa<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|s| s.kappa).collect())
    }

    /// Unit tangents (cos θ, sin θ), shape (n, 2).
    #[getter]
    fn tangents<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.iter().map(|s| s.tangent().to_point()))
    }

    fn __len__(&self) -> usize {
        self.0.len()
    }

    fn __repr__(&self) -> String {
        format!("<Samples n={}>", self.0.len())
    }
}

/// The curvature plot: arc length `s`, `points`, signed curvature `kappa` and its exact
/// derivative `dkappa_ds`.
#[pyclass(module = "lac", name = "CurvaturePlot", frozen)]
pub(crate) struct CurvaturePlot(pub(crate) Vec<CurvaturePoint>);

#[pymethods]
impl CurvaturePlot {
    /// A curvature plot from samples measured elsewhere (a CAD kernel's or a drawing
    /// program's evaluation of its own curve), for `log_curvature_graph` and
    /// `not_monotone`: arc length `s`, signed curvature `kappa` (unsigned for a space curve)
    /// and `dkappa_ds`, each of shape (n,), and `points` (n, 2) when known (zeros otherwise).
    #[staticmethod]
    #[pyo3(signature = (s, kappa, dkappa_ds, points = None))]
    fn from_samples(
        py: Python<'_>,
        s: &Bound<'_, PyAny>,
        kappa: &Bound<'_, PyAny>,
        dkappa_ds: &Bound<'_, PyAny>,
        points: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<CurvaturePlot> {
        let (s, kappa) = (vector(s, "s")?, vector(kappa, "kappa")?);
        let dkappa_ds = vector(dkappa_ds, "dkappa_ds")?;
        let n = s.len();
        let xy = match points {
            Some(p) => point_list(py, p, "points")?,
            None => vec![Point::ZERO; n],
        };
        if kappa.len() != n || dkappa_ds.len() != n || xy.len() != n {
            return Err(invalid(
                py,
                format!(
                    "s, kappa, dkappa_ds and points must have one length, got {n}, {}, {} and {}",
                    kappa.len(),
                    dkappa_ds.len(),
                    xy.len()
                ),
            ));
        }
        if s.iter()
            .chain(&kappa)
            .chain(&dkappa_ds)
            .any(|v| !v.is_finite())
        {
            return Err(invalid(py, "s, kappa and dkappa_ds must be finite numbers"));
        }
        Ok(CurvaturePlot(
            (0..n)
                .map(|i| CurvaturePoint {
                    s: s[i],
                    point: xy[i],
                    kappa: kappa[i],
                    dkappa_ds: dkappa_ds[i],
                })
                .collect(),
        ))
    }

    /// Why the plot shows the curvature is not monotone (dκ/ds or κ takes both signs beyond
    /// `PLOT_ZERO` of their scale: the sentence `lac lcg` prints), or None when it is.
    fn not_monotone(&self) -> Option<String> {
        lac::NotMonotone::of_plot(&self.0).map(|why| why.to_string())
    }

    /// Arc length, shape (n,).
    #[getter]
    fn s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|p| p.s).collect())
    }

    /// Positions, shape (n, 2).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.iter().map(|p| p.point))
    }

    /// Signed curvature, shape (n,).
    #[getter]
    fn kappa<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|p| p.kappa).collect())
    }

    /// dκ/ds, shape (n,).
    #[getter]
    fn dkappa_ds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.iter().map(|p| p.dkappa_ds).collect())
    }

    /// The logarithmic curvature graph of these points, with its least-squares line.
    fn log_curvature_graph(&self) -> LogCurvatureGraph {
        LogCurvatureGraph(lac::log_curvature_graph(&self.0))
    }

    fn __len__(&self) -> usize {
        self.0.len()
    }

    fn __repr__(&self) -> String {
        format!("<CurvaturePlot n={}>", self.0.len())
    }
}

/// A logarithmic curvature graph: `points` (n, 2) of (log ρ, log(ρ ds/dρ)) (natural
/// logarithms; the points where dκ/ds = 0 or κ = 0 are left out), and `fit`, the
/// least-squares line (None with fewer than two points).
#[pyclass(module = "lac", name = "LogCurvatureGraph", frozen)]
pub(crate) struct LogCurvatureGraph(pub(crate) lac::LogCurvatureGraph);

#[pymethods]
impl LogCurvatureGraph {
    /// (log ρ, log(ρ ds/dρ)) pairs, shape (n, 2).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.points.iter().map(|&(x, y)| Point::new(x, y)))
    }

    /// The least-squares line, or None.
    #[getter]
    fn fit(&self) -> Option<LcgFit> {
        self.0.fit.map(LcgFit)
    }

    fn __repr__(&self) -> String {
        format!("<LogCurvatureGraph n={}>", self.0.points.len())
    }
}

/// The least-squares line through a logarithmic curvature graph: its slope `alpha`,
/// `intercept`, the residuals (`rms_residual`, `max_residual`) and the range of log ρ.
#[pyclass(module = "lac", name = "LcgFit", frozen)]
pub(crate) struct LcgFit(lac::LcgFit);

#[pymethods]
impl LcgFit {
    /// The fitted slope α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.0.alpha
    }

    /// The fitted value at log ρ = 0.
    #[getter]
    fn intercept(&self) -> f64 {
        self.0.intercept
    }

    /// Root-mean-square residual.
    #[getter]
    fn rms_residual(&self) -> f64 {
        self.0.rms_residual
    }

    /// Largest absolute residual.
    #[getter]
    fn max_residual(&self) -> f64 {
        self.0.max_residual
    }

    /// The range of log ρ covered.
    #[getter]
    fn log_rho(&self) -> (f64, f64) {
        self.0.log_rho
    }

    fn __repr__(&self) -> String {
        format!(
            "LcgFit(alpha={}, intercept={}, rms_residual={:e})",
            self.0.alpha, self.0.intercept, self.0.rms_residual
        )
    }
}

/// The logarithmic curvature graph of a log-aesthetic piece: the straight line
/// log(ρ ds/dρ) = alpha · log ρ + intercept over `log_rho` (natural logarithms).
#[pyclass(module = "lac", name = "LcgLine", frozen)]
pub(crate) struct LcgLine(lac::LcgLine);

#[pymethods]
impl LcgLine {
    /// The slope α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.0.alpha
    }

    /// The value of log(ρ ds/dρ) at log ρ = 0.
    #[getter]
    fn intercept(&self) -> f64 {
        self.0.intercept
    }

    /// The range of log ρ covered by the piece, in the order of travel.
    #[getter]
    fn log_rho(&self) -> (f64, f64) {
        self.0.log_rho
    }

    /// log(ρ ds/dρ) at `log_rho`.
    fn at(&self, log_rho: f64) -> f64 {
        self.0.at(log_rho)
    }

    fn __repr__(&self) -> String {
        format!(
            "LcgLine(alpha={}, intercept={}, log_rho={:?})",
            self.0.alpha, self.0.intercept, self.0.log_rho
        )
    }
}
