//! The vectorised entry point: many segments in one call, solved on all cores with the GIL
//! released, one result or one error per curve (never an exception for a bad curve).

use kurbo::Point;
use lac::{Curve as _, Sample, Segment};
use lac_io::json::ErrorBody;
use numpy::{PyArray1, PyArray2, PyArray3};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::convert::{array1, blocks, real_array, rows, scalar_or_vector, shape_text};
use crate::errors::invalid;

/// Most samples per curve times curves in one call (80 MB of float64 per array).
const MAX_SAMPLE_VALUES: usize = 10_000_000;

/// One curve's answer.
struct Answer {
    lambda: f64,
    arc_length: f64,
    curvature_start: f64,
    curvature_end: f64,
    turning: f64,
    samples: Vec<Sample>,
}

fn solve_one(points: [Point; 3], alpha: f64, samples: usize) -> Result<Answer, ErrorBody> {
    let segment = Segment::from_control_points(points, alpha)?;
    let samples = if samples >= 2 {
        segment.sample_by_arc_length(samples)?
    } else {
        Vec::new()
    };
    Ok(Answer {
        lambda: segment.lambda(),
        arc_length: segment.arc_length(),
        curvature_start: segment.signed_curvature_start(),
        curvature_end: segment.signed_curvature_end(),
        turning: segment.turning(),
        samples,
    })
}

/// The answers of `solve_segments`: one row per curve. `ok[i]` says whether curve i was
/// solved; where it was not, its numbers are NaN, and `error_kind[i]` and `error[i]` say
/// why (the library's snake_case kind and message; None where solved).
#[pyclass(module = "lac", name = "SegmentBatch", frozen)]
pub(crate) struct SegmentBatch {
    /// Which curves were solved, shape (n,), bool.
    #[pyo3(get)]
    ok: Py<PyArray1<bool>>,
    /// Each curve's error kind ("not_drawable", "collinear_points", ...) or None.
    #[pyo3(get)]
    error_kind: Vec<Option<String>>,
    /// Each curve's error message, or None.
    #[pyo3(get)]
    error: Vec<Option<String>>,
    /// α, shape (n,).
    #[pyo3(get)]
    alpha: Py<PyArray1<f64>>,
    /// Λ of each solved standard form, shape (n,).
    #[pyo3(get, name = "lambda_")]
    lambda: Py<PyArray1<f64>>,
    /// Arc lengths, shape (n,).
    #[pyo3(get)]
    arc_length: Py<PyArray1<f64>>,
    /// Signed curvature at the first point, shape (n,).
    #[pyo3(get)]
    curvature_start: Py<PyArray1<f64>>,
    /// Signed curvature at the last point, shape (n,).
    #[pyo3(get)]
    curvature_end: Py<PyArray1<f64>>,
    /// Signed total turning, radians, shape (n,).
    #[pyo3(get)]
    turning: Py<PyArray1<f64>>,
    /// With `samples = m`: arc lengths of the samples, shape (n, m); else None.
    #[pyo3(get)]
    s: Option<Py<PyArray2<f64>>>,
    /// With `samples = m`: positions, shape (n, m, 2); else None.
    #[pyo3(get)]
    points: Option<Py<PyArray3<f64>>>,
    /// With `samples = m`: tangent directions, shape (n, m); else None.
    #[pyo3(get)]
    theta: Option<Py<PyArray2<f64>>>,
    /// With `samples = m`: signed curvatures, shape (n, m); else None.
    #[pyo3(get)]
    kappa: Option<Py<PyArray2<f64>>>,
}

#[pymethods]
impl SegmentBatch {
    fn __len__(&self) -> usize {
        self.error.len()
    }

    fn __repr__(&self) -> String {
        let failed = self.error.iter().filter(|e| e.is_some()).count();
        format!(
            "<SegmentBatch n={} solved={} failed={failed}>",
            self.error.len(),
            self.error.len() - failed
        )
    }
}

/// Solve many segments at once: `points` of shape (n, 3, 2) (n control-point triples),
/// `alpha` a number or shape (n,). With `samples = m ≥ 2`, each curve is also sampled at
/// m points equally spaced in arc length. The work runs on all cores with the GIL
/// released; a curve that cannot be solved gives NaNs and its error in the result instead
/// of an exception. `threads`: None for all cores (rayon's pool), 1 for the calling thread
/// alone (no hand-off to the pool: best for small batches or a busy machine), k for a pool
/// of k threads made for the call.
#[pyfunction]
#[pyo3(signature = (points, alpha, *, samples = 0, threads = None))]
pub(crate) fn solve_segments(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    alpha: &Bound<'_, PyAny>,
    samples: usize,
    threads: Option<usize>,
) -> PyResult<SegmentBatch> {
    let real = real_array(points, "points")?;
    let n = match real.shape.as_slice() {
        [n, 3, 2] => *n,
        _ => {
            return Err(invalid(
                py,
                format!(
                    "points must have shape (n, 3, 2): n triples of (x, y) control points, got \
                     shape {}",
                    shape_text(&real.shape)
                ),
            ))
        }
    };
    let alpha = scalar_or_vector(alpha, n, "alpha")?;
    if samples == 1 {
        return Err(invalid(py, "samples must be 0 (none) or at least 2, got 1"));
    }
    if n.saturating_mul(samples) > MAX_SAMPLE_VALUES {
        return Err(invalid(
            py,
            format!(
                "n · samples must be at most {MAX_SAMPLE_VALUES}, got {n} · {samples}; solve \
                 in chunks"
            ),
        ));
    }
    let data = real.data;
    let solve = |(c, &a): (&[f64], &f64)| {
        let p = [
            Point::new(c[0], c[1]),
            Point::new(c[2], c[3]),
            Point::new(c[4], c[5]),
        ];
        solve_one(p, a, samples)
    };
    let pool = match threads {
        None | Some(1) => None,
        Some(0) => {
            return Err(invalid(
                py,
                "threads must be at least 1, or None for all cores",
            ))
        }
        Some(k) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .map_err(|e| PyRuntimeError::new_err(format!("cannot start {k} threads: {e}")))?,
        ),
    };
    let results: Vec<Result<Answer, ErrorBody>> = py.detach(|| {
        let parallel = || {
            data.par_chunks_exact(6)
                .zip(alpha.par_iter())
                .map(solve)
                .collect()
        };
        match (threads, &pool) {
            (Some(1), _) => data.chunks_exact(6).zip(alpha.iter()).map(solve).collect(),
            (_, Some(pool)) => pool.install(parallel),
            _ => parallel(),
        }
    });

    let column = |f: &dyn Fn(&Answer) -> f64| -> Vec<f64> {
        results
            .iter()
            .map(|r| r.as_ref().map_or(f64::NAN, f))
            .collect()
    };
    let per_sample = |f: &dyn Fn(&Sample) -> f64| -> Vec<f64> {
        results
            .iter()
            .flat_map(|r| match r {
                Ok(solved) => solved.samples.iter().map(f).collect::<Vec<_>>(),
                Err(_) => vec![f64::NAN; samples],
            })
            .collect()
    };
    let (s, points, theta, kappa) = if samples >= 2 {
        let xy: Vec<f64> = results
            .iter()
            .flat_map(|r| match r {
                Ok(solved) => solved
                    .samples
                    .iter()
                    .flat_map(|s| [s.point.x, s.point.y])
                    .collect::<Vec<_>>(),
                Err(_) => vec![f64::NAN; 2 * samples],
            })
            .collect();
        (
            Some(rows(py, per_sample(&|s| s.s), n, samples)?.unbind()),
            Some(blocks(py, xy, (n, samples, 2))?.unbind()),
            Some(rows(py, per_sample(&|s| s.theta), n, samples)?.unbind()),
            Some(rows(py, per_sample(&|s| s.kappa), n, samples)?.unbind()),
        )
    } else {
        (None, None, None, None)
    };
    let ok: Vec<bool> = results.iter().map(Result::is_ok).collect();
    Ok(SegmentBatch {
        ok: PyArray1::from_vec(py, ok).unbind(),
        error_kind: results
            .iter()
            .map(|r| r.as_ref().err().map(|e| e.kind.clone()))
            .collect(),
        error: results
            .iter()
            .map(|r| r.as_ref().err().map(|e| e.message.clone()))
            .collect(),
        alpha: array1(py, alpha).unbind(),
        lambda: array1(py, column(&|s| s.lambda)).unbind(),
        arc_length: array1(py, column(&|s| s.arc_length)).unbind(),
        curvature_start: array1(py, column(&|s| s.curvature_start)).unbind(),
        curvature_end: array1(py, column(&|s| s.curvature_end)).unbind(),
        turning: array1(py, column(&|s| s.turning)).unbind(),
        s,
        points,
        theta,
        kappa,
    })
}
