//! Log-aesthetic paths from a control polygon (`lac::Path`): G1 at given leg fractions, G2
//! solved (through inflections too), warm-started from an earlier solution; G2 splines
//! through points (`lac::Spline`).

use crate::export::AnyCurveObject;
use lac::{Alphas, Continuity, ControlPolygon};
use lac::{Closure, Curve};
use lac_io::json::AnyCurve;
use numpy::{PyArray1, PyArray2, PyArray3};
use pyo3::prelude::*;

use crate::convert::{array1, blocks, point_list, points2, vector};
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
pub(crate) struct PyPath(pub(crate) lac::Path);

#[pymethods]
impl PyPath {
    /// The curve for `lac.export` (not public: `export` calls it).
    fn _any_curve(&self) -> AnyCurveObject {
        AnyCurveObject(AnyCurve::Path(self.0.clone()))
    }

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
        let points = point_list(py, polygon, "polygon")?;
        let poly = if closed {
            ControlPolygon::from_points(&points, Closure::Closed)
        } else {
            ControlPolygon::from_points(&points, Closure::Open)
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
            match warm.as_deref() {
                Some(near) => lac::Path::from_polygon_g2_near(&poly, &alphas, near),
                None => lac::Path::from_polygon_g2(&poly, &alphas),
            }
        } else {
            lac::Path::from_polygon_g1(&poly, &alphas, fractions.as_deref())
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

    fn __repr__(&self) -> String {
        format!(
            "<Path continuity={} closed={} segments={} arc_length={}>",
            self.continuity(),
            if self.closed() { "True" } else { "False" },
            self.0.segments().len(),
            self.0.arc_length()
        )
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
        triangles(py, &self.0.control_triangles())
    }

    /// Each segment's signed curvature at its start and end, shape (k, 2).
    #[getter]
    fn end_curvatures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        end_curvatures(py, self.0.segments())
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

/// A G2 spline of log-aesthetic segments through `points` (at least three): one segment per
/// span, the tangent angles at the points solved for continuous curvature. An open spline's
/// end tangent directions are `ends` = (start, end) in radians (either may be None), or those
/// of the circles through its first and last three points.
///
/// Point types, as `lac spline` takes them: `types` one per point, "s"/"smooth", "t"/"tangent"
/// (G2 with the direction given in `angles`), "c"/"corner" (the tangent may break), as a
/// sequence or one string "s t c …"; `angles` maps a tangent point to its direction and a
/// corner to its two sides (in, out), either None for free; `lines` lists the straight spans
/// (i: from point i to the next), which the curve meets with zero curvature (alpha < 0);
/// `start_curvature` and `end_curvature` an open spline's end curvatures (with the end's
/// angle, a G2 Hermite end).
///
/// For `alpha < 0`, a span that must inflect is an S: two segments meeting at zero
/// curvature (`inflections`, `spans_of_pieces`).
///
/// Raises `LacError` (kind `no_g2_path`, naming the span or the point and what to change)
/// where a span would have to inflect with `alpha >= 0`, a point's type cannot be met, or no
/// continuous curvature is reached.
#[pyclass(module = "lac", name = "Spline", frozen)]
pub(crate) struct PySpline(pub(crate) lac::Spline);

/// One point's measurements as Python sees them: (type, given, straight, angles,
/// curvatures).
type PointRow = (
    &'static str,
    Pair<Option<f64>>,
    Pair<bool>,
    Pair<Option<f64>>,
    Pair<Option<f64>>,
);

/// Two values, arriving and leaving (a Python tuple).
type Pair<T> = (T, T);

fn pair<T: Copy>(v: [T; 2]) -> Pair<T> {
    (v[0], v[1])
}

/// The point types of `types` (a string of letters or a sequence of names) for `n` points.
fn point_types(
    py: Python<'_>,
    types: &Bound<'_, PyAny>,
    n: usize,
) -> PyResult<Vec<lac::PointType>> {
    let names: Vec<String> = match types.extract::<String>() {
        Ok(text) => text
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
            .map(str::to_string)
            .collect(),
        Err(_) => types.extract::<Vec<String>>().map_err(|_| {
            invalid(
                py,
                "types must be a string \"s t c …\" or a sequence of type names",
            )
        })?,
    };
    if names.len() != n {
        return Err(invalid(
            py,
            format!(
                "types has {} entries for {n} points: one per point",
                names.len()
            ),
        ));
    }
    names
        .iter()
        .map(|name| {
            lac_io::json::point_type_named(name).ok_or_else(|| {
                invalid(
                    py,
                    format!("{name:?} is not a point type (s smooth, t tangent, c corner)"),
                )
            })
        })
        .collect()
}

#[pymethods]
impl PySpline {
    /// The curve for `lac.export` (not public: `export` calls it).
    fn _any_curve(&self) -> AnyCurveObject {
        AnyCurveObject(AnyCurve::Spline(self.0.clone()))
    }

    #[new]
    #[pyo3(signature = (
        points, alpha, closed = false, ends = None, types = None, angles = None, lines = None,
        start_curvature = None, end_curvature = None, warm = None
    ))]
    #[allow(clippy::too_many_arguments)] // Python keyword arguments
    fn new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        alpha: f64,
        closed: bool,
        ends: Option<&Bound<'_, PyAny>>,
        types: Option<&Bound<'_, PyAny>>,
        angles: Option<std::collections::HashMap<usize, Bound<'_, PyAny>>>,
        lines: Option<Vec<usize>>,
        start_curvature: Option<f64>,
        end_curvature: Option<f64>,
        warm: Option<Bound<'_, PySpline>>,
    ) -> PyResult<Self> {
        let points = point_list(py, points, "points")?;
        if closed && (ends.is_some() || start_curvature.is_some() || end_curvature.is_some()) {
            return Err(invalid(
                py,
                "ends are an open spline's (and end curvatures); closed=True",
            ));
        }
        // Two angles, or a pair whose entries may be None.
        let ends: Option<(Option<f64>, Option<f64>)> = match ends {
            None => None,
            Some(e) => match e.extract::<(Option<f64>, Option<f64>)>() {
                Ok(pair) => Some(pair),
                Err(_) => match vector(e, "ends")?.as_slice() {
                    [a, b] => Some((Some(*a), Some(*b))),
                    v => {
                        return Err(invalid(
                            py,
                            format!("ends must be two angles (start, end), got {}", v.len()),
                        ))
                    }
                },
            },
        };
        let mut types = match types {
            Some(t) => point_types(py, t, points.len())?,
            None => Vec::new(),
        };
        for (i, value) in angles.unwrap_or_default() {
            let slot = types.get_mut(i).ok_or_else(|| {
                invalid(py, format!("angles: point {i} has no type t or c in types"))
            })?;
            *slot = match *slot {
                lac::PointType::Tangent(_) => {
                    lac::PointType::Tangent(value.extract().map_err(|_| {
                        invalid(
                            py,
                            format!("angles: point {i} is a tangent point: one angle"),
                        )
                    })?)
                }
                lac::PointType::Corner { .. } => {
                    let (before, after): (Option<f64>, Option<f64>) =
                        value.extract().map_err(|_| {
                            invalid(py, format!("angles: point {i} is a corner: (in, out)"))
                        })?;
                    lac::PointType::Corner { before, after }
                }
                lac::PointType::Smooth => {
                    return Err(invalid(
                        py,
                        format!("angles: point {i} is smooth: give it type t or c"),
                    ))
                }
            };
        }
        if let Some(i) = types
            .iter()
            .position(|t| matches!(t, lac::PointType::Tangent(a) if a.is_nan()))
        {
            return Err(invalid(
                py,
                format!("point {i} is a tangent point: give its direction in angles"),
            ));
        }
        let (start, end) = ends.unwrap_or((None, None));
        let options = lac::SplineOptions {
            types,
            lines: lines.unwrap_or_default(),
            start: lac::SplineEnd {
                angle: start,
                curvature: start_curvature,
            },
            end: lac::SplineEnd {
                angle: end,
                curvature: end_curvature,
            },
        };
        let closure = if closed {
            Closure::Closed
        } else {
            Closure::Open
        };
        let near = warm.as_ref().map(|w| &w.get().0);
        let spline = py
            .detach(|| match near {
                Some(near) => {
                    lac::Spline::from_points_near(&points, alpha, closure, &options, near)
                }
                None => lac::Spline::from_points_with(&points, alpha, closure, &options),
            })
            .or_raise(py)?;
        Ok(PySpline(spline))
    }

    /// What was measured at each point: a list of (type, given directions (in, out),
    /// straight (in, out), angles (in, out), curvatures (in, out)), None outside an open
    /// spline's ends.
    #[getter]
    fn point_reports(&self) -> Vec<PointRow> {
        self.0
            .point_reports()
            .iter()
            .map(|p| {
                let given = match p.kind {
                    lac::PointType::Smooth => [None, None],
                    lac::PointType::Tangent(a) => [Some(a), Some(a)],
                    lac::PointType::Corner { before, after } => [before, after],
                };
                (
                    p.kind.name(),
                    pair(given),
                    pair(p.straight),
                    pair(p.angles),
                    pair(p.curvatures),
                )
            })
            .collect()
    }

    /// The knots (joints inside spans that pay for the points' conditions), shape (m, 2).
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.knots().iter().map(|k| k.point))
    }

    /// Whether it is closed.
    #[getter]
    fn closed(&self) -> bool {
        self.0.is_closed()
    }

    fn __repr__(&self) -> String {
        format!(
            "<Spline closed={} points={} pieces={} arc_length={}>",
            if self.0.is_closed() { "True" } else { "False" },
            self.0.points().len(),
            self.0.pieces().len(),
            self.0.arc_length()
        )
    }

    /// Arc length of the whole spline.
    #[getter]
    fn arc_length(&self) -> f64 {
        use lac::Curve;
        self.0.arc_length()
    }

    /// The points it passes through, shape (n, 2).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.points().iter().copied())
    }

    /// The tangent direction at each point, radians.
    #[getter]
    fn angles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.angles().to_vec())
    }

    /// Each piece's control triangle (its first point, the intersection of its end
    /// tangents, its last point), shape (k, 3, 2): one piece per span, two (halves ending a
    /// hair short of the inflection) for a span through an inflection.
    #[getter]
    fn control_triangles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f64>>> {
        triangles(py, self.0.control_triangles())
    }

    /// The span of each piece (span i runs from point i to the next), shape (k,).
    #[getter]
    fn spans_of_pieces<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let spans = self.0.spans_of_pieces().iter().map(|&i| i as i64);
        PyArray1::from_iter(py, spans)
    }

    /// The inflection points (only for alpha < 0), shape (m, 2); `inflection_spans` says
    /// which span each lies on.
    #[getter]
    fn inflections<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points2(py, self.0.inflections().iter().map(|f| f.point))
    }

    /// The span of each inflection, shape (m,).
    #[getter]
    fn inflection_spans<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        PyArray1::from_iter(py, self.0.inflections().iter().map(|f| f.span as i64))
    }

    /// Each piece's signed curvature at its start and end, shape (k, 2).
    #[getter]
    fn end_curvatures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        end_curvatures(py, self.0.pieces())
    }

    /// The relative curvature jump at each joint (the interior points; every point when
    /// closed).
    #[getter]
    fn curvature_jumps<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array1(py, self.0.curvature_jumps().to_vec())
    }

    /// The largest relative curvature jump at a joint.
    #[getter]
    fn max_curvature_jump(&self) -> f64 {
        self.0.max_curvature_jump()
    }

    /// `n` samples equally spaced in arc length over the whole spline.
    fn sample(&self, py: Python<'_>, n: i64) -> PyResult<Samples> {
        use lac::Curve;
        let n = usize::try_from(n)
            .map_err(|_| invalid(py, format!("n must be at least 2, got {n}")))?;
        Ok(Samples(self.0.sample_by_arc_length(n).or_raise(py)?))
    }
}

/// Control triangles as a (k, 3, 2) array.
fn triangles<'py>(py: Python<'py>, t: &[[kurbo::Point; 3]]) -> PyResult<Bound<'py, PyArray3<f64>>> {
    let flat: Vec<f64> = t.iter().flatten().flat_map(|p| [p.x, p.y]).collect();
    blocks(py, flat, (t.len(), 3, 2))
}

/// Each segment's signed curvature at its start and end, as a (k, 2) array.
fn end_curvatures<'py>(
    py: Python<'py>,
    segments: &[lac::Segment],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    use lac::Curve;
    let ends = segments
        .iter()
        .map(|s| kurbo::Point::new(s.signed_curvature_start(), s.signed_curvature_end()));
    points2(py, ends.collect::<Vec<_>>().into_iter())
}
