//! Space curves (seed 003): [`SpaceInput`] and [`SpaceReport`], what `lac space` reads and
//! prints and the editor answers, its graphs ([`SpaceGraphsReport`]) and `lac lcg` of a space
//! curve ([`SpaceLcgReport`]: both graphs with their fitted lines).

use lac::SpaceCurve;
use lac::{Frame, GraphPoint, LcgFit, SpaceSegment, SpaceShape, TorsionType, Vec3};
use serde::{Deserialize, Serialize};

use lac_export::ExportCurve;

use super::kind::{fields, Kind};
use super::{all_finite, ErrorBody, Report, Xyz};
use serde_json::{Map, Value};

/// The `"note"` of a planar (coplanar-points) space result.
pub const PLANAR_NOTE: &str = "the four control points are coplanar, so the planar \
     log-aesthetic segment through the first point, the tangents' intersection and the last \
     point is drawn (torsion 0; beta and omega do not apply to a planar curve)";

/// A log-aesthetic space curve segment from four control points (seed 003 §4):
/// `{"points":[[x,y,z]×4],"alpha":A,"beta":B,"omega":W,"type":1}` (`omega` 0 and `type` 1
/// when absent).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpaceInput {
    /// P0 (start), P1 (on the start tangent), P2 (on the end tangent), P3 (end).
    pub points: [Xyz; 4],
    /// Slope of the logarithmic curvature graph.
    pub alpha: f64,
    /// Slope of the logarithmic torsion graph.
    pub beta: f64,
    /// Torsion parameter Ω ≥ 0 (0: constant torsion).
    #[serde(default)]
    pub omega: f64,
    /// Torsion type: 1 (the radius of torsion grows along the standard form) or 2.
    #[serde(rename = "type", default = "torsion_type_one")]
    pub torsion_type: u8,
}

fn torsion_type_one() -> u8 {
    1
}

impl SpaceInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"points":[[x,y,z],[x,y,z],[x,y,z],[x,y,z]],"alpha":A,"beta":B,"omega":W,"type":1}"#;

    /// Solve it.
    pub fn solve(&self) -> Result<SpaceSegment, ErrorBody> {
        let shape = SpaceShape {
            alpha: self.alpha,
            beta: self.beta,
            omega: self.omega,
            torsion: TorsionType::from_number(self.torsion_type)?,
        };
        Ok(SpaceSegment::from_control_points(
            self.points.map(Vec3::from_array),
            shape,
        )?)
    }
}

/// The standard form (seed 003 §3) with the Λ and ν the solver found, and the standard-form
/// arc length `s_end` of the segment.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpaceFormRow {
    /// Slope of the logarithmic curvature graph.
    pub alpha: f64,
    /// Slope of the logarithmic torsion graph.
    pub beta: f64,
    /// Λ.
    pub lambda: f64,
    /// Ω.
    pub omega: f64,
    /// ν.
    pub nu: f64,
    /// The torsion type, 1 or 2.
    #[serde(rename = "type")]
    pub torsion_type: u8,
    /// The standard-form arc length of the segment.
    pub s_end: f64,
}

/// `caller = translation + scale · rotation · M · standard`, M = diag(1, 1, −1) if
/// `mirror_z`; `reversed`: the standard form runs from the last point to the first.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TransformRow {
    /// Standard-form lengths to the caller's.
    pub scale: f64,
    /// A proper rotation, row-major.
    pub rotation: [[f64; 3]; 3],
    /// Where the standard form's origin lands.
    pub translation: Xyz,
    /// The standard form is mirrored in its xy plane first.
    pub mirror_z: bool,
    /// The standard form runs from the last control point to the first.
    pub reversed: bool,
}

/// One sample of a space curve; with frames also the unit tangent, normal and binormal.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpaceSampleRow {
    /// Arc length from the first control point.
    pub s: f64,
    /// Position, x.
    pub x: f64,
    /// Position, y.
    pub y: f64,
    /// Position, z.
    pub z: f64,
    /// Curvature, ≥ 0.
    pub kappa: f64,
    /// Torsion, negative for a left-handed (mirrored) segment.
    pub tau: f64,
    /// Unit tangent.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub t: Option<Xyz>,
    /// Unit principal normal.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub n: Option<Xyz>,
    /// Unit binormal.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub b: Option<Xyz>,
}

impl SpaceSampleRow {
    /// The row of `frame`, with its Frenet frame when `frames`.
    pub fn new(frame: &Frame, frames: bool) -> Self {
        let Vec3 { x, y, z } = frame.point;
        SpaceSampleRow {
            s: frame.s,
            x,
            y,
            z,
            kappa: frame.curvature,
            tau: frame.torsion,
            t: frames.then_some(frame.tangent.to_array()),
            n: frames.then_some(frame.normal.to_array()),
            b: frames.then_some(frame.binormal.to_array()),
        }
    }

    fn is_finite(&self) -> bool {
        all_finite([self.s, self.x, self.y, self.z, self.kappa, self.tau])
            && [self.t, self.n, self.b]
                .iter()
                .flatten()
                .all(|v| all_finite(*v))
    }
}

/// The planar segment drawn for coplanar points, its control points in the caller's
/// coordinates.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanarRow {
    /// α of the planar segment.
    pub alpha: f64,
    /// Λ of the planar segment.
    pub lambda: f64,
    /// The first point, the tangents' intersection and the last point.
    pub control_points: [Xyz; 3],
}

/// A solved space curve segment: `lac space --format json`. `planar_segment` and `note` only
/// for coplanar points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpaceReport {
    /// The solved standard form; `null` when planar.
    pub standard_form: Option<SpaceFormRow>,
    /// Standard form to the caller's coordinates; `null` when planar.
    pub transform: Option<TransformRow>,
    /// Arc length from the first to the last control point.
    pub arc_length: f64,
    /// Were the points coplanar (the planar segment drawn instead)?
    pub planar: bool,
    /// Samples equally spaced in arc length, first and last at the end points.
    pub samples: Vec<SpaceSampleRow>,
    /// The planar segment drawn for coplanar points.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub planar_segment: Option<PlanarRow>,
    /// Why the result is planar.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub note: Option<String>,
    /// What was solved, as given: `"points"`, `"alpha"`, `"beta"`, `"omega"`, `"type"`, so
    /// that a report reads back as its input (`lac lcg` reads `lac space` output).
    #[serde(flatten)]
    pub input: SpaceInput,
}

impl SpaceReport {
    /// The report of `segment` with `n` samples, with their Frenet frames when `frames`.
    pub fn new(segment: &SpaceSegment, n: usize, frames: bool) -> Result<Self, ErrorBody> {
        SpaceReport {
            standard_form: segment
                .standard_form()
                .zip(segment.s_end())
                .map(|(form, s_end)| SpaceFormRow {
                    alpha: form.alpha(),
                    beta: form.beta(),
                    lambda: form.lambda(),
                    omega: form.omega(),
                    nu: form.nu(),
                    torsion_type: form.torsion_type().number(),
                    s_end,
                }),
            transform: segment.transform().map(|t| TransformRow {
                scale: t.scale,
                rotation: t.rotation,
                translation: t.translation.to_array(),
                mirror_z: t.mirror_z,
                reversed: t.reversed,
            }),
            arc_length: segment.arc_length(),
            planar: segment.is_planar(),
            samples: segment
                .sample_by_arc_length(n)?
                .iter()
                .map(|f| SpaceSampleRow::new(f, frames))
                .collect(),
            planar_segment: segment.planar().zip(planar_control_points(segment)).map(
                |(planar, points)| PlanarRow {
                    alpha: planar.alpha(),
                    lambda: planar.lambda(),
                    control_points: points.map(Vec3::to_array),
                },
            ),
            note: segment.is_planar().then(|| PLANAR_NOTE.to_string()),
            input: SpaceInput::of(segment),
        }
        .checked()
    }
}

impl Report for SpaceReport {
    fn is_finite(&self) -> bool {
        self.standard_form
            .as_ref()
            .is_none_or(|f| all_finite([f.alpha, f.beta, f.lambda, f.omega, f.nu, f.s_end]))
            && self.transform.as_ref().is_none_or(|t| {
                t.scale.is_finite()
                    && all_finite(t.rotation.iter().flatten().copied())
                    && all_finite(t.translation)
            })
            && self.arc_length.is_finite()
            && self.samples.iter().all(SpaceSampleRow::is_finite)
            && self.planar_segment.as_ref().is_none_or(|p| {
                all_finite([p.alpha, p.lambda])
                    && all_finite(p.control_points.iter().flatten().copied())
            })
            && all_finite(self.input.points.iter().flatten().copied())
            && all_finite([self.input.alpha, self.input.beta, self.input.omega])
    }
}

/// The control points of the planar segment drawn for coplanar points, in the caller's
/// coordinates: the planar segment lives in the plane with origin P0, x along P1 − P0 and y
/// toward the chord ([`SpaceSegment::planar`]). `None` when the segment is not planar.
pub fn planar_control_points(segment: &SpaceSegment) -> Option<[Vec3; 3]> {
    let planar = segment.planar()?;
    let [p0, p1, _, p3] = segment.control_points();
    // Divided by the length rather than `Vec3::normalize`d (a product with its reciprocal),
    // so that the printed digits stay those `lac space` has always printed.
    let unit = |v: Vec3| v / v.length();
    let e1 = unit(p1 - p0);
    let chord = p3 - p0;
    let e2 = unit(chord - chord.dot(e1) * e1);
    Some(planar.control_points().map(|q| p0 + q.x * e1 + q.y * e2))
}

/// One point of a space curve's logarithmic curvature graph `(ln ρ, ln(ρ |ds/dρ|))` or
/// torsion graph `(ln μ, ln(μ |ds/dμ|))`, at arc length `s`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GraphRow {
    /// Arc length from P0.
    pub s: f64,
    /// ln ρ (or ln μ).
    pub x: f64,
    /// ln(ρ |ds/dρ|) (or ln(μ |ds/dμ|)).
    pub y: f64,
}

impl From<&GraphPoint> for GraphRow {
    fn from(p: &GraphPoint) -> Self {
        GraphRow {
            s: p.s,
            x: p.x,
            y: p.y,
        }
    }
}

/// A space curve's two graphs: `{"curvature":[…],"torsion":[…]}`, straight lines of slopes α
/// and β (empty when ρ, or μ, is constant, or the segment is planar for the torsion).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpaceGraphsReport {
    /// The logarithmic curvature graph.
    pub curvature: Vec<GraphRow>,
    /// The logarithmic torsion graph.
    pub torsion: Vec<GraphRow>,
}

impl SpaceGraphsReport {
    /// Both graphs of `segment` at `n` points equally spaced in arc length.
    pub fn new(segment: &SpaceSegment, n: usize) -> Result<Self, ErrorBody> {
        SpaceGraphsReport {
            curvature: segment
                .log_curvature_graph(n)?
                .iter()
                .map(GraphRow::from)
                .collect(),
            torsion: segment
                .log_torsion_graph(n)?
                .iter()
                .map(GraphRow::from)
                .collect(),
        }
        .checked()
    }
}

impl Report for SpaceGraphsReport {
    fn is_finite(&self) -> bool {
        self.curvature
            .iter()
            .chain(&self.torsion)
            .all(|p| all_finite([p.s, p.x, p.y]))
    }
}

impl SpaceInput {
    /// The input `segment` was solved from, as given.
    pub fn of(segment: &SpaceSegment) -> SpaceInput {
        let shape = segment.shape();
        SpaceInput {
            points: segment.control_points().map(Vec3::to_array),
            alpha: shape.alpha,
            beta: shape.beta,
            omega: shape.omega,
            torsion_type: shape.torsion.number(),
        }
    }
}

/// A line fitted to a logarithmic graph, `y = slope x + intercept` over x ∈ `x` (natural
/// logarithms): α for the curvature graph, β for the torsion graph.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LineFitRow {
    /// The slope: α (curvature graph) or β (torsion graph).
    pub slope: f64,
    /// The value at x = 0.
    pub intercept: f64,
    /// Root mean square residual, weighted along x.
    pub rms_residual: f64,
    /// Largest residual.
    pub max_residual: f64,
    /// The range of x covered, [from, to] in the order of travel.
    pub x: [f64; 2],
}

impl From<&LcgFit> for LineFitRow {
    fn from(f: &LcgFit) -> Self {
        LineFitRow {
            slope: f.alpha,
            intercept: f.intercept,
            rms_residual: f.rms_residual,
            max_residual: f.max_residual,
            x: [f.log_rho.0, f.log_rho.1],
        }
    }
}

/// One logarithmic graph of a space curve, its points and its fitted line.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GraphFitRow {
    /// The graph's points in the order of travel (empty when the radius is constant).
    pub points: Vec<GraphRow>,
    /// The line fitted to them; `null` when there are none.
    pub fit: Option<LineFitRow>,
}

impl GraphFitRow {
    fn new(points: &[GraphPoint]) -> Self {
        let graph =
            lac::LogCurvatureGraph::from_points(points.iter().map(|p| (p.x, p.y)).collect());
        GraphFitRow {
            points: points.iter().map(GraphRow::from).collect(),
            fit: graph.fit.as_ref().map(LineFitRow::from),
        }
    }

    fn is_finite(&self) -> bool {
        self.points.iter().all(|p| all_finite([p.s, p.x, p.y]))
            && self.fit.as_ref().is_none_or(|f| {
                all_finite([f.slope, f.intercept, f.rms_residual, f.max_residual])
                    && all_finite(f.x)
            })
    }
}

/// `lac lcg` of a space curve (seed 003): its logarithmic curvature graph
/// `(ln ρ, ln(ρ |ds/dρ|))` and torsion graph `(ln μ, ln(μ |ds/dμ|))`, μ = 1/|τ|, each with
/// its fitted line, whose slopes are α and β:
/// `{"curvature":{"points":[{s,x,y}…],"fit":{"slope":α,…}},"torsion":{…"slope":β…}}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpaceLcgReport {
    /// The logarithmic curvature graph; its slope is α.
    pub curvature: GraphFitRow,
    /// The logarithmic torsion graph; its slope is β.
    pub torsion: GraphFitRow,
    /// Why a graph is empty: a planar segment, a constant radius of torsion (Ω = 0) or of
    /// curvature (a circle or helix).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub note: Option<String>,
}

impl SpaceLcgReport {
    /// Both graphs of `segment` at `n` points equally spaced in arc length.
    pub fn new(segment: &SpaceSegment, n: usize) -> Result<Self, ErrorBody> {
        let curvature = GraphFitRow::new(&segment.log_curvature_graph(n)?);
        let torsion = GraphFitRow::new(&segment.log_torsion_graph(n)?);
        let mut notes = Vec::new();
        if curvature.points.is_empty() {
            notes.push("the radius of curvature is constant (Λ = 0): no curvature graph");
        }
        if segment.is_planar() {
            notes.push("the control points are coplanar, so the planar segment is drawn (torsion 0): no torsion graph");
        } else if torsion.points.is_empty() {
            notes.push("the radius of torsion is constant (Ω = 0): no torsion graph");
        }
        SpaceLcgReport {
            curvature,
            torsion,
            note: (!notes.is_empty()).then(|| notes.join("; ")),
        }
        .checked()
    }
}

impl Report for SpaceLcgReport {
    fn is_finite(&self) -> bool {
        self.curvature.is_finite() && self.torsion.is_finite()
    }
}

/// A space segment: a document with `"beta"`.
pub struct SpaceKind;

impl Kind for SpaceKind {
    const NAME: &'static str = "space";
    type Curve = SpaceSegment;

    fn claims(document: &Map<String, Value>) -> bool {
        document.contains_key("beta")
    }

    fn solve(document: Map<String, Value>) -> Result<SpaceSegment, ErrorBody> {
        fields::<SpaceInput>(document, "a space curve", SpaceInput::SHAPE)?.solve()
    }

    fn export(segment: &SpaceSegment) -> Result<ExportCurve<'_>, ErrorBody> {
        Ok(ExportCurve::space(Self::NAME, segment))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::{parse, to_line};

    #[test]
    fn a_space_report_reads_back_as_its_input_and_its_graphs_give_alpha_and_beta() {
        let input = SpaceInput {
            points: [
                [0.0, 0.0, 0.0],
                [3.0, 0.0, 0.0],
                [3.0, 3.0, 1.5],
                [0.0, 3.0, 3.0],
            ],
            alpha: 0.5,
            beta: -0.5,
            omega: 0.3,
            torsion_type: 1,
        };
        let segment = input.solve().unwrap();
        let line = to_line(&SpaceReport::new(&segment, 3, false).unwrap());
        let back: SpaceInput = parse(&line, SpaceInput::SHAPE).unwrap();
        assert_eq!(back, input);
        let graphs = SpaceLcgReport::new(&segment, 33).unwrap();
        let slope = |g: &GraphFitRow| g.fit.as_ref().unwrap().slope;
        assert!((slope(&graphs.curvature) - 0.5).abs() < 1e-9);
        assert!((slope(&graphs.torsion) + 0.5).abs() < 1e-9);
        assert_eq!(graphs.note, None);
    }
}
