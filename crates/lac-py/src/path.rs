//! Log-aesthetic paths from a control polygon (`lac::Path`): G1 at given leg fractions, G2
//! solved (through inflections too), warm-started from an earlier solution.

use lac::{Alphas, Continuity, ControlPolygon};
use numpy::{PyArray1, PyArray2, PyArray3};
use pyo3::prelude::*;

use crate::convert::{array1, blocks, points2, real_array, vector};
use crate::curve::Samples;
use crate::errors::{invalid, OrRaise};

/// A straight piece as Python sees it: (leg, start point, end point).
type StraightRow = (usize, (f64, f64), (f64, f64));

/// A log-aesthetic path from a control polygon: one segment per interior vertex (per vertex
/// when `closed`), joined on the legs; `g2=True` solves the joints for continuous curvature
/// (where the turning changes direction, through a straight piece at zero curvature),
/// `g2=False` puts them at `fractions` (default the midpoints). `alpha` is one slope or one
/// per segment; `warm` the `joint_fractions` of an earlier G2 solution (e.g. before a drag).
///
/// Raises `LacError` when no G2 path is found (kind `no_g2_path`, naming the leg) or a
/// segment cannot be drawn.
#[pyclass(module = "lac", name = "Path", frozen)]
pub(crate) struct PyPath(lac::Path);

#[pymethods]
impl PyPath {
    #[new]
    #[pyo3(signature = (polygon, alpha, closed = false, g2 = true, fractions = None, warm = None))]
    fn new(
        py: Python<'_>,
        polygon: &Bound<'_, PyAny>,
        alpha: &Bound<'_, PyAny>,
        closed: bool,
        g2: bool,
        fractions: Option<&Bound<'_, PyAny>>,
        warm: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let real = real_array(polygon, "polygon")?;
        if real.shape.len() != 2 || real.shape[1] != 2 {
            return Err(invalid(
                py,
                "polygon must be an (n, 2) array or a sequence of (x, y) pairs",
            ));
        }
        let points: Vec<kurbo::Point> = real
            .data
            .chunks(2)
            .map(|c| kurbo::Point::new(c[0], c[1]))
            .collect();
        let poly = if closed {
            ControlPolygon::closed(&points)
        } else {
            ControlPolygon::open(&points)
        }
        .or_raise(py)?;
        let alphas = match alpha.extract::<f64>() {
            Ok(a) => Alphas::One(a),
            Err(_) => Alphas::PerSegment(vector(alpha, "alpha")?),
        };
        let fractions = fractions.map(|f| vector(f, "fractions")).transpose()?;
        let warm = warm.map(|w| vector(w, "warm")).transpose()?;
        let path = if g2 {
            if fractions.is_some() {
                return Err(invalid(
                    py,
                    "fractions place a G1 path's joints; use g2=False",
                ));
            }
            lac::Path::g2(&poly, &alphas, warm.as_deref())
        } else {
            lac::Path::g1(&poly, &alphas, fractions.as_deref())
        }
        .or_raise(py)?;
        Ok(PyPath(path))
    }

    /// "g1" or "g2".
    #[getter]
    fn continuity(&self) -> &'static str {
        match self.0.continuity() {
            Continuity::G1 => "g1",
            Continuity::G2 => "g2",
        }
    }

    /// Whether the polygon is closed.
    #[getter]
    fn closed(&self) -> bool {
        self.0.polygon().is_closed()
    }

    /// Arc length of the whole path (straight pieces included).
    #[getter]
    fn arc_length(&self) -> f64 {
        self.0.arc_length()
    }

    /// The largest relative curvature jump at a joint.
    #[getter]
    fn max_curvature_jump(&self) -> f64 {
        self.0.max_curvature_jump()
    }

    /// The fraction of each joint leg at which its joint lies: the `warm` start of a
    /// re-solve.
    #[getter]
    fn joint_fractions<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.joint_fractions())
    }

    /// Each segment's control triangle (start joint, vertex, end joint), shape (k, 3, 2).
    #[getter]
    fn control_triangles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let t = self.0.control_triangles();
        let flat: Vec<f64> = t.iter().flatten().flat_map(|p| [p.x, p.y]).collect();
        blocks(py, flat, (t.len(), 3, 2))
    }

    /// Each segment's signed curvature at its start and end, shape (k, 2).
    #[getter]
    fn end_curvatures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        use lac::Curve;
        let ends = self
            .0
            .segments()
            .iter()
            .map(|s| kurbo::Point::new(s.curvature_start(), s.curvature_end()));
        points2(py, ends.collect::<Vec<_>>().into_iter())
    }

    /// The straight pieces on inflection legs: (leg, start point, end point) each.
    #[getter]
    fn straight_pieces(&self) -> Vec<StraightRow> {
        self.0
            .straight_pieces()
            .iter()
            .map(|p| (p.leg, (p.from.x, p.from.y), (p.to.x, p.to.y)))
            .collect()
    }

    /// `n` samples equally spaced in arc length over the whole path.
    fn sample(&self, py: Python<'_>, n: i64) -> PyResult<Samples> {
        let n = usize::try_from(n)
            .map_err(|_| invalid(py, format!("n must be at least 2, got {n}")))?;
        Ok(Samples(self.0.sample_by_arc_length(n).or_raise(py)?))
    }
}
