//! G2 splines through points: [`SplineInput`], what makes one, and [`SplineReport`], what
//! `lac spline` prints, with its point types (`"smooth"`, `"tangent"`, `"corner"`), straight
//! spans and end conditions, and what was measured at each point ([`SplinePointRow`]).

use kurbo::Point;
use lac::{Closure, Curve, PointType, Spline, SplineEnd, SplineOptions};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use lac_export::{spline_pieces, ExportCurve};

use super::kind::{fields, Kind};
use super::{all_finite, point, xy, ErrorBody, Report, SampleRow, Xy};

/// The point type of a name as `lac spline --types` spells it (`s`/`smooth`,
/// `t`/`tangent`, `c`/`corner`), a tangent point's direction still to be given (NaN).
pub fn point_type_named(name: &str) -> Option<PointType> {
    match name {
        "s" | "smooth" => Some(PointType::Smooth),
        "t" | "tangent" => Some(PointType::Tangent(f64::NAN)),
        "c" | "corner" => Some(PointType::CORNER),
        _ => None,
    }
}

/// A spline's points, slope, closure, point types, straight spans and end conditions, as
/// `lac spline` takes them.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineInput {
    /// The points it passes through.
    pub points: Vec<Point>,
    /// The slope of every segment.
    pub alpha: f64,
    /// Whether it is closed.
    pub closed: bool,
    /// Point types, straight spans and an open spline's end angles and curvatures (the
    /// default: every point smooth, the ends' directions from circles).
    pub options: SplineOptions,
}

impl SplineInput {
    /// The input of points given as JSON pairs.
    fn new(points: &[Xy], alpha: f64, closed: bool, options: SplineOptions) -> SplineInput {
        SplineInput {
            points: points.iter().map(|&p| point(p)).collect(),
            alpha,
            closed,
            options,
        }
    }

    /// Solve it.
    pub fn solve(&self) -> Result<Spline, ErrorBody> {
        let closure = if self.closed {
            Closure::Closed
        } else {
            Closure::Open
        };
        Ok(Spline::from_points_with(
            &self.points,
            self.alpha,
            closure,
            &self.options,
        )?)
    }
}

/// A spline as the editor asks for it: `{"points":[[x,y],…],"alpha":A,"closed":false,
/// "types":["s","t","c",…],"angles":[[in,out],…],"lines":[i,…],"start":{"angle","curvature"},
/// "end":{…}}`, every field but the points and α optional; a tangent point's direction is
/// the first of its `angles`, a corner's sides both (null: free).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplineRequest {
    /// The points it passes through.
    pub points: Vec<Xy>,
    /// The slope of every segment.
    pub alpha: f64,
    /// Whether it is closed.
    #[serde(default)]
    pub closed: bool,
    /// Each point's type, `s`, `t` or `c` (absent: every point smooth).
    #[serde(default)]
    pub types: Vec<String>,
    /// Each point's given directions (in, out).
    #[serde(default)]
    pub angles: Vec<[Option<f64>; 2]>,
    /// The straight spans.
    #[serde(default)]
    pub lines: Vec<usize>,
    /// An open spline's first point.
    #[serde(default)]
    pub start: SplineEndRow,
    /// An open spline's last point.
    #[serde(default)]
    pub end: SplineEndRow,
}

impl SplineRequest {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],…],"alpha":A,"closed":false,"types":["s","t","c",…],"angles":[[in,out],…],"lines":[i,…]}"#;

    /// The input it asks for, or what is wrong with its types.
    pub fn input(&self) -> Result<SplineInput, ErrorBody> {
        let types = self
            .types
            .iter()
            .enumerate()
            .map(|(i, name)| {
                let given = self.angles.get(i).copied().unwrap_or([None, None]);
                match point_type_named(name) {
                    Some(PointType::Tangent(_)) => {
                        given[0].map(PointType::Tangent).ok_or_else(|| {
                            ErrorBody::invalid_input(format!(
                            "point {i} is a tangent point: give its direction as angles[{i}][0]"
                        ))
                        })
                    }
                    Some(PointType::Corner { .. }) => Ok(PointType::Corner {
                        before: given[0],
                        after: given[1],
                    }),
                    Some(other) => Ok(other),
                    None => Err(ErrorBody::invalid_input(format!(
                        "types[{i}] = {name:?} is not a point type (s smooth, t tangent, c corner)"
                    ))),
                }
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(SplineInput::new(
            &self.points,
            self.alpha,
            self.closed,
            SplineOptions {
                types,
                lines: self.lines.clone(),
                start: self.start.end(),
                end: self.end.end(),
            },
        ))
    }
}

/// What a spline measured at one of its points, and its type as given: each side's tangent
/// direction (radians) and signed curvature (`null` outside an open spline's ends), whether
/// that side is a straight span, and the given directions (a tangent point's on both sides,
/// a corner's where given).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplinePointRow {
    /// `"smooth"`, `"tangent"` or `"corner"`.
    #[serde(rename = "type")]
    pub kind: String,
    /// The directions given, arriving and leaving, radians.
    pub given: [Option<f64>; 2],
    /// Whether the span arriving and the one leaving are straight.
    pub straight: [bool; 2],
    /// The tangent direction arriving and leaving, radians, measured on the pieces.
    pub angles: [Option<f64>; 2],
    /// The signed curvature arriving and leaving, measured on the pieces.
    pub curvatures: [Option<f64>; 2],
    /// Distance from the point to the pieces' ends there.
    pub gap: f64,
}

impl SplinePointRow {
    fn new(p: &lac::SplinePoint) -> Self {
        SplinePointRow {
            kind: p.kind.name().to_string(),
            given: match p.kind {
                PointType::Smooth => [None, None],
                PointType::Tangent(a) => [Some(a), Some(a)],
                PointType::Corner { before, after } => [before, after],
            },
            straight: p.straight,
            angles: p.angles,
            curvatures: p.curvatures,
            gap: p.gap,
        }
    }

    /// The point type it was given.
    fn point_type(&self) -> PointType {
        match (self.kind.as_str(), self.given) {
            ("tangent", [Some(a), _]) => PointType::Tangent(a),
            ("corner", [before, after]) => PointType::Corner { before, after },
            _ => PointType::Smooth,
        }
    }
}

/// An open spline's end as given: its direction and curvature, each `null` when free.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SplineEndRow {
    /// The tangent direction, radians.
    pub angle: Option<f64>,
    /// The signed curvature.
    pub curvature: Option<f64>,
}

impl SplineEndRow {
    /// The end as the library takes it.
    fn end(&self) -> SplineEnd {
        SplineEnd {
            angle: self.angle,
            curvature: self.curvature,
        }
    }
}

/// A knot: a joint inside a span that pays for a point's condition.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplineKnotRow {
    /// The span it lies in.
    pub span: usize,
    /// Where it is.
    pub point: Xy,
    /// The tangent direction there, radians.
    pub angle: f64,
    /// The relative curvature jump measured there.
    pub curvature_jump: f64,
}

/// One piece of a spline through points: the segment of a span, or one half of a span
/// through an inflection.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplinePieceRow {
    /// The span it belongs to (span i runs from point i to the next).
    pub span: usize,
    /// Its control triangle: the point it starts at, the tangents' intersection, the point
    /// it ends at (a hair short of the inflection, for a half).
    pub control_points: [Xy; 3],
    /// Λ of its standard-form piece.
    pub lambda: f64,
    /// Arc length.
    pub arc_length: f64,
    /// Signed curvature at its start and end.
    pub curvature: [f64; 2],
}

/// Where a span of a spline passes through an inflection.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplineInflectionRow {
    /// The span.
    pub span: usize,
    /// The inflection point.
    pub point: Xy,
    /// Signed curvature of the two halves where they meet (zero within 1e-9 of the
    /// spline's largest |κ| at a point).
    pub curvature: [f64; 2],
}

/// A solved G2 spline through points: `lac spline`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SplineReport {
    /// Whether it is closed.
    pub closed: bool,
    /// The slope of every segment.
    pub alpha: f64,
    /// Arc length of the whole spline.
    pub arc_length: f64,
    /// The largest relative curvature jump at a joint.
    pub max_curvature_jump: f64,
    /// The points it passes through.
    pub points: Vec<Xy>,
    /// The tangent direction at each point, radians.
    pub angles: Vec<f64>,
    /// The pieces in order: one per span, two for a span through an inflection.
    pub pieces: Vec<SplinePieceRow>,
    /// The inflections (only for alpha < 0), in order.
    pub inflections: Vec<SplineInflectionRow>,
    /// The relative curvature jump measured at each joint with continuous curvature.
    pub curvature_jumps: Vec<f64>,
    /// What was measured at each point, with its type.
    #[serde(default)]
    pub at_points: Vec<SplinePointRow>,
    /// The straight spans (i: from point i to the next).
    #[serde(default)]
    pub lines: Vec<usize>,
    /// An open spline's first point as given (absent: its direction is `angles`' first).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start: Option<SplineEndRow>,
    /// An open spline's last point as given (absent: its direction is `angles`' last).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end: Option<SplineEndRow>,
    /// The knots.
    #[serde(default)]
    pub knots: Vec<SplineKnotRow>,
    /// Samples equally spaced in arc length over the whole spline.
    pub samples: Vec<SampleRow>,
}

impl SplineReport {
    /// The report of `spline` with `n` samples.
    pub fn new(spline: &lac::Spline, alpha: f64, n: usize) -> Result<Self, ErrorBody> {
        let samples = spline.sample_by_arc_length(n)?;
        SplineReport {
            closed: spline.is_closed(),
            alpha,
            arc_length: spline.arc_length(),
            max_curvature_jump: spline.max_curvature_jump(),
            points: spline.points().iter().map(|&p| xy(p)).collect(),
            angles: spline.angles().to_vec(),
            pieces: spline
                .pieces()
                .iter()
                .zip(spline.control_triangles())
                .zip(spline.spans_of_pieces())
                .map(|((seg, tri), &span)| SplinePieceRow {
                    span,
                    control_points: tri.map(xy),
                    lambda: seg.lambda(),
                    arc_length: seg.arc_length(),
                    curvature: [seg.signed_curvature_start(), seg.signed_curvature_end()],
                })
                .collect(),
            inflections: spline
                .inflections()
                .iter()
                .map(|f| SplineInflectionRow {
                    span: f.span,
                    point: xy(f.point),
                    curvature: f.curvatures,
                })
                .collect(),
            curvature_jumps: spline.curvature_jumps().to_vec(),
            at_points: spline
                .point_reports()
                .iter()
                .map(SplinePointRow::new)
                .collect(),
            lines: spline.options().lines.clone(),
            start: end_row(spline, spline.options().start),
            end: end_row(spline, spline.options().end),
            knots: spline
                .knots()
                .iter()
                .map(|k| SplineKnotRow {
                    span: k.span,
                    point: xy(k.point),
                    angle: k.angle,
                    curvature_jump: k.curvature_jump,
                })
                .collect(),
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }
}

/// An open spline's end as given, when it is more than a direction (a curvature, or a
/// free direction): a report without it gives the end's direction solved.
fn end_row(spline: &Spline, end: SplineEnd) -> Option<SplineEndRow> {
    (!spline.is_closed() && end.curvature.is_some()).then_some(SplineEndRow {
        angle: end.angle,
        curvature: end.curvature,
    })
}

impl SplineReport {
    /// The spline it reports, as an input: its points, slope and closure, point types,
    /// straight spans, and an open one's ends (their directions as solved, unless given
    /// with a curvature).
    pub fn input(&self) -> SplineInput {
        let solved = |i: Option<&f64>| if self.closed { None } else { i.copied() };
        let end = |row: Option<SplineEndRow>, solved: Option<f64>| match row {
            Some(r) => r.end(),
            None => SplineEnd {
                angle: solved,
                curvature: None,
            },
        };
        let mut types: Vec<PointType> = self.at_points.iter().map(|r| r.point_type()).collect();
        // An open spline's end that is a tangent point has its direction from its type.
        let mut start = end(self.start, solved(self.angles.first()));
        let mut last = end(self.end, solved(self.angles.last()));
        if !self.closed {
            if matches!(
                types.first(),
                Some(PointType::Tangent(_) | PointType::Corner { .. })
            ) {
                start.angle = None;
            }
            if matches!(
                types.last(),
                Some(PointType::Tangent(_) | PointType::Corner { .. })
            ) {
                last.angle = None;
            }
            // An end on a straight span takes the span's direction.
            if self.lines.contains(&0) {
                start.angle = None;
            }
            if self.lines.contains(&(self.points.len().saturating_sub(2))) {
                last.angle = None;
            }
        }
        if types.iter().all(|t| *t == PointType::Smooth) {
            types.clear();
        }
        SplineInput::new(
            &self.points,
            self.alpha,
            self.closed,
            SplineOptions {
                types,
                lines: self.lines.clone(),
                start,
                end: last,
            },
        )
    }
}

/// A spline through points: `lac spline`'s result, told by its `"pieces"` and `"angles"`,
/// solved again through its points with its end tangents; or a spline as the editor asks
/// for it ([`SplineRequest`]), told by its `"types"`.
pub struct SplineKind;

impl Kind for SplineKind {
    const NAME: &'static str = "spline";
    type Curve = Spline;

    fn claims(document: &Map<String, Value>) -> bool {
        let has = |key: &str| document.contains_key(key);
        (has("pieces") && has("angles")) || has("types")
    }

    fn solve(document: Map<String, Value>) -> Result<Spline, ErrorBody> {
        if !document.contains_key("pieces") {
            let request: SplineRequest = fields(document, "a spline", SplineRequest::SHAPE)?;
            return request.input()?.solve();
        }
        let report: SplineReport =
            fields(document, "a lac spline result", "what lac spline prints")?;
        report.input().solve()
    }

    /// Piece by piece, like a path: every point, and the two halves of a span through an
    /// inflection (with the straight piece where they are flat), is a knot. The joins are G2
    /// but at corners, where the tangent may break (G0); an open spline's end points have one
    /// side only.
    fn export(spline: &Spline) -> Result<ExportCurve<'_>, ErrorBody> {
        let n = spline.points().len();
        let ends = |i: usize| !spline.is_closed() && (i == 0 || i + 1 == n);
        let corner = spline
            .options()
            .types
            .iter()
            .enumerate()
            .any(|(i, t)| matches!(t, PointType::Corner { .. }) && !ends(i));
        Ok(ExportCurve::pieces(
            Self::NAME,
            spline.arc_length(),
            if corner { "G0" } else { "G2" },
            spline_pieces(spline)?,
        ))
    }
}

impl Report for SplineReport {
    fn is_finite(&self) -> bool {
        all_finite([self.arc_length, self.max_curvature_jump, self.alpha])
            && all_finite(self.points.iter().flatten().copied())
            && all_finite(self.angles.iter().copied())
            && all_finite(self.curvature_jumps.iter().copied())
            && self.at_points.iter().all(|r| {
                all_finite(
                    r.given
                        .iter()
                        .chain(&r.angles)
                        .chain(&r.curvatures)
                        .flatten()
                        .copied(),
                ) && r.gap.is_finite()
            })
            && self
                .knots
                .iter()
                .all(|k| all_finite(k.point.iter().copied().chain([k.angle, k.curvature_jump])))
            && self.pieces.iter().all(|g| {
                all_finite([g.lambda, g.arc_length, g.curvature[0], g.curvature[1]])
                    && all_finite(g.control_points.iter().flatten().copied())
            })
            && self
                .inflections
                .iter()
                .all(|f| all_finite(f.point.iter().copied().chain(f.curvature.iter().copied())))
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}
