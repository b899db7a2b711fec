//! JSON: the B-spline data for anything else, `{"degree":3,"dimension":2|3,
//! "control_points":[[x,y(,z)]…],"weights":[…],"knots":[…]}` per curve, in the report's
//! `"curves"` (one curve, or one per span with `--pieces`).

use serde::{Deserialize, Serialize};

use super::nurbs::{Nurbs, DEGREE};
use super::ExportReport;

/// One rational B-spline curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NurbsRow {
    /// Always 3.
    pub degree: usize,
    /// 2 for a planar result (points `[x, y]`), 3 for a space curve (`[x, y, z]`).
    pub dimension: usize,
    /// The control points.
    pub control_points: Vec<Vec<f64>>,
    /// One weight per control point.
    pub weights: Vec<f64>,
    /// The full (clamped) knot vector: control points + 4 values.
    pub knots: Vec<f64>,
}

impl From<&Nurbs> for NurbsRow {
    fn from(n: &Nurbs) -> Self {
        let dimension = if n.planar { 2 } else { 3 };
        NurbsRow {
            degree: DEGREE,
            dimension,
            control_points: n
                .control_points
                .iter()
                .map(|p| p[..dimension].to_vec())
                .collect(),
            weights: n.weights.clone(),
            knots: n.knots.clone(),
        }
    }
}

/// `lac export --format json`: the curves and the report.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ExportDocument {
    /// The B-spline curves.
    pub curves: Vec<NurbsRow>,
    /// How well they follow the exact curve.
    #[serde(flatten)]
    pub report: ExportReport,
}
