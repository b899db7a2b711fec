//! Paths from a control polygon (issue 15): [`PathInput`] and [`PathReport`], what `lac
//! path` reads and prints.

use kurbo::Point;
use lac::Closure;
use lac::{Alphas, Continuity, ControlPolygon, Curve, Path};
use serde::{Deserialize, Serialize};

use lac_export::{path_pieces, ExportCurve};

use super::kind::{fields, Kind};
use super::{all_finite, point, xy, ErrorBody, Report, SampleRow, Xy};
use serde_json::{Map, Value};

/// A path from a control polygon: `{"points":[[x,y],…],"closed":false,"alpha":A,"g2":true}`,
/// with `"alphas":[…]` (one per segment) instead of `"alpha"`, and for a G1 path optionally
/// `"fractions":[…]` (one per joint leg; default the midpoints).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathInput {
    /// The control polygon's vertices.
    pub points: Vec<Xy>,
    /// A closed polygon (the last vertex joins the first).
    #[serde(default)]
    pub closed: bool,
    /// One slope for every segment.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha: Option<f64>,
    /// One slope per segment (per interior vertex; per vertex when closed).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alphas: Option<Vec<f64>>,
    /// Solve the joints for continuous curvature.
    #[serde(default)]
    pub g2: bool,
    /// G1 only: the fraction of each joint leg at which its joint lies.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub fractions: Option<Vec<f64>>,
}

impl PathInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"points":[[x,y],[x,y],[x,y],…],"closed":false,"alpha":A,"g2":true}"#;

    /// Solve it. A failed G2 solve's message names the joint, says why, and gives the
    /// fractions of the nearest G1 path (to pass back as `fractions` without `g2`).
    pub fn solve(&self) -> Result<Path, ErrorBody> {
        let points: Vec<Point> = self.points.iter().map(|&p| point(p)).collect();
        let polygon = if self.closed {
            ControlPolygon::from_points(&points, Closure::Closed)?
        } else {
            ControlPolygon::from_points(&points, Closure::Open)?
        };
        let alphas = match (self.alpha, &self.alphas) {
            (Some(a), None) => Alphas::One(a),
            (None, Some(list)) => Alphas::PerSegment(list.clone()),
            _ => {
                return Err(ErrorBody::invalid_input(
                    "give either one alpha for every segment or alphas, one per segment",
                ))
            }
        };
        if !self.g2 {
            return Ok(Path::from_polygon_g1(
                &polygon,
                &alphas,
                self.fractions.as_deref(),
            )?);
        }
        if self.fractions.is_some() {
            return Err(ErrorBody::invalid_input(
                "fractions place the joints of a G1 path; a G2 path solves them: drop one",
            ));
        }
        let outcome = Path::from_polygon_g2_or_nearest_g1(&polygon, &alphas)?;
        match outcome.failure {
            None => Ok(outcome.path),
            Some(err) => {
                let fractions = outcome.path.joint_fractions();
                let shown: Vec<String> = fractions.iter().map(|f| format!("{f:.6}")).collect();
                let mut body = ErrorBody::from(err);
                body.message = format!(
                    "{}; the nearest G1 path has its joints at the leg fractions [{}]",
                    body.message,
                    shown.join(", ")
                );
                body.g1_fractions = Some(fractions);
                Err(body)
            }
        }
    }
}

/// One segment of a path.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathSegmentRow {
    /// The polygon vertex that carries it.
    pub vertex: usize,
    /// Its slope.
    pub alpha: f64,
    /// Λ of its standard-form piece.
    pub lambda: f64,
    /// Its control triangle: start joint, vertex, end joint.
    pub control_points: [Xy; 3],
    /// Arc length.
    pub arc_length: f64,
    /// Signed curvature at its start and end.
    pub curvature: [f64; 2],
}

/// One joint of a path, as the solver checked it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathJointRow {
    /// The leg it lies on (leg i from P_i to P_i+1).
    pub leg: usize,
    /// Its fraction of the leg from P_i.
    pub fraction: f64,
    /// The joint.
    pub point: Xy,
    /// Arc length from the path's start.
    pub s: f64,
    /// Signed curvature before and after it.
    pub curvature: [f64; 2],
    /// |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|).
    pub curvature_jump: f64,
    /// Distance between the two segments' ends.
    pub gap: f64,
    /// Angle between their tangents, radians.
    pub tangent_jump: f64,
}

/// The straight piece of a G2 path on a leg where its turning changes direction (an
/// inflection: the segments on either side reach zero curvature at its ends).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathStraightRow {
    /// The leg it lies on.
    pub leg: usize,
    /// Fractions of the leg from P_leg where it starts and ends.
    pub fractions: [f64; 2],
    /// Where it starts and ends.
    pub points: [Xy; 2],
    /// Arc length from the path's start to its start.
    pub s: f64,
    /// Its length (0 when the segments meet).
    pub length: f64,
    /// Signed curvature of the segments at its ends (zero within 1e-9 of the path's
    /// largest |κ|).
    pub curvature: [f64; 2],
}

/// A solved path: `lac path`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathReport {
    /// `"g1"` or `"g2"`.
    pub continuity: String,
    /// Whether the polygon is closed.
    pub closed: bool,
    /// Arc length of the whole path.
    pub arc_length: f64,
    /// The largest relative curvature jump at a joint.
    pub max_curvature_jump: f64,
    /// The control polygon as given.
    pub points: Vec<Xy>,
    /// The segments in order.
    pub segments: Vec<PathSegmentRow>,
    /// The joints in order.
    pub joints: Vec<PathJointRow>,
    /// The straight pieces on inflection legs, in order (G2 paths only).
    #[serde(default)]
    pub straight_pieces: Vec<PathStraightRow>,
    /// Samples equally spaced in arc length over the whole path.
    pub samples: Vec<SampleRow>,
}

impl PathReport {
    /// The report of `path` with `n` samples.
    pub fn new(path: &Path, n: usize) -> Result<Self, ErrorBody> {
        let samples = path.sample_by_arc_length(n)?;
        let polygon = path.polygon();
        let triangles = path.control_triangles();
        let segments = path
            .segments()
            .iter()
            .enumerate()
            .map(|(k, seg)| PathSegmentRow {
                vertex: polygon.vertex_of_segment(k),
                alpha: seg.alpha(),
                lambda: seg.lambda(),
                control_points: triangles[k].map(xy),
                arc_length: seg.arc_length(),
                curvature: [seg.signed_curvature_start(), seg.signed_curvature_end()],
            })
            .collect();
        let s = path.joints().iter().map(|j| j.s).collect::<Vec<_>>();
        let joints = path
            .joints()
            .iter()
            .zip(s)
            .map(|(j, s)| PathJointRow {
                leg: j.leg,
                fraction: j.fraction,
                point: xy(j.point),
                s,
                curvature: [j.curvature_before, j.curvature_after],
                curvature_jump: j.curvature_jump,
                gap: j.gap,
                tangent_jump: j.tangent_jump,
            })
            .collect();
        PathReport {
            continuity: match path.continuity() {
                Continuity::G1 => "g1",
                Continuity::G2 => "g2",
            }
            .to_string(),
            closed: polygon.is_closed(),
            arc_length: path.arc_length(),
            max_curvature_jump: path.max_curvature_jump(),
            points: polygon.points().iter().map(|&p| xy(p)).collect(),
            segments,
            joints,
            straight_pieces: path
                .straight_pieces()
                .iter()
                .zip(
                    path.straight_pieces()
                        .iter()
                        .map(|p| p.s)
                        .collect::<Vec<_>>(),
                )
                .map(|(p, s)| PathStraightRow {
                    leg: p.leg,
                    fractions: p.fractions,
                    points: [xy(p.from), xy(p.to)],
                    s,
                    length: p.length(),
                    curvature: [p.curvature_before, p.curvature_after],
                })
                .collect(),
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }

    /// What solves this path again: its polygon, closure, the segments' slopes, and a G2
    /// solve or (G1) the joints' leg fractions. (Numbers are printed to round trip, so the
    /// path solved again is the one reported.)
    pub fn input(&self) -> PathInput {
        let g2 = self.continuity == "g2";
        PathInput {
            points: self.points.clone(),
            closed: self.closed,
            alpha: None,
            alphas: Some(self.segments.iter().map(|g| g.alpha).collect()),
            g2,
            fractions: (!g2).then(|| self.joints.iter().map(|j| j.fraction).collect()),
        }
    }
}

impl Report for PathReport {
    fn is_finite(&self) -> bool {
        all_finite([self.arc_length, self.max_curvature_jump])
            && all_finite(self.points.iter().flatten().copied())
            && self.segments.iter().all(|g| {
                all_finite([
                    g.alpha,
                    g.lambda,
                    g.arc_length,
                    g.curvature[0],
                    g.curvature[1],
                ]) && all_finite(g.control_points.iter().flatten().copied())
            })
            && self.joints.iter().all(|j| {
                all_finite([
                    j.fraction,
                    j.point[0],
                    j.point[1],
                    j.s,
                    j.curvature[0],
                    j.curvature[1],
                    j.curvature_jump,
                    j.gap,
                    j.tangent_jump,
                ])
            })
            && self.straight_pieces.iter().all(|p| {
                all_finite([p.s, p.length, p.curvature[0], p.curvature[1]])
                    && all_finite(p.fractions)
                    && all_finite(p.points.iter().flatten().copied())
            })
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}

/// A path from a control polygon: `lac path`'s result (told by its `"segments"` and
/// `"joints"`, solved again from its input) or its input (told by `"alphas"`, `"closed"`,
/// `"g2"` or `"fractions"`).
pub struct PathKind;

impl Kind for PathKind {
    const NAME: &'static str = "path";
    type Curve = Path;

    fn claims(document: &Map<String, Value>) -> bool {
        let has = |key: &str| document.contains_key(key);
        (has("segments") && has("joints"))
            || ["alphas", "closed", "g2", "fractions"]
                .iter()
                .any(|key| has(key))
    }

    fn solve(document: Map<String, Value>) -> Result<Path, ErrorBody> {
        let input = if document.contains_key("segments") && document.contains_key("joints") {
            fields::<PathReport>(document, "a lac path result", PathInput::SHAPE)?.input()
        } else {
            fields::<PathInput>(document, "a path", PathInput::SHAPE)?
        };
        input.solve()
    }

    /// Segment by segment: each segment's chain keeps its end points, tangents and
    /// curvatures, so the path's joints stay knots with the path's own continuity; a straight
    /// piece (an inflection leg) is one cubic span with collinear points.
    fn export(path: &Path) -> Result<ExportCurve<'_>, ErrorBody> {
        let continuity = match path.continuity() {
            Continuity::G1 => "G1",
            Continuity::G2 => "G2",
        };
        Ok(ExportCurve::pieces(
            Self::NAME,
            path.arc_length(),
            continuity,
            path_pieces(path),
        ))
    }
}
