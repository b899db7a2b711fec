//! Log-aesthetic paths fitted to points (issue 30): [`FitInput`] and [`FitReport`], what
//! `lac fit` reads and prints, and [`FittedPath`], a fit's segments as a curve of their
//! own (what a fit's result solves back to for `lac export`).

use kurbo::Point;
use lac::{Closure, Continuity, Curve, Fit, FitAlpha, FitLoss, FitOptions, Segment, SegmentChain};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use lac_export::{segment_pieces, ExportCurve};

use super::kind::{fields, Kind};
use super::{all_finite, point, xy, ErrorBody, Report, SampleRow, Xy};

/// The most segments a fit with a tolerance may use when `max_segments` is not given.
pub const DEFAULT_MAX_SEGMENTS: usize = 16;

/// How many of the farthest points a report lists.
pub const FARTHEST_LISTED: usize = 10;

/// A fit asked for: `{"points":[[x,y],…]}` with any of `"tolerance"`, `"max_segments"`,
/// `"alpha"` (fixed) or `"alpha_range":[a,b]`, `"shared_alpha"`, `"g1"`, `"closed"`,
/// `"pin_ends"`, `"huber"` (δ of the robust loss) and `"weights"` (one per point).
///
/// Without a tolerance it fits `max_segments` segments (default 1) by least squares; with
/// one, the fewest segments up to `max_segments` (default [`DEFAULT_MAX_SEGMENTS`]) that
/// keep every point within it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FitInput {
    /// The points, in order along the curve.
    pub points: Vec<Xy>,
    /// The largest distance allowed between a point and the fit (the points' units).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub tolerance: Option<f64>,
    /// The number of segments (no tolerance) or the most (with one).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub max_segments: Option<usize>,
    /// Every segment's α, fixed.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha: Option<f64>,
    /// The range α is fitted in (default [`lac::DEFAULT_ALPHA_RANGE`]).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha_range: Option<[f64; 2]>,
    /// One fitted α for every segment.
    #[serde(default)]
    pub shared_alpha: bool,
    /// Joints with continuous tangent only (else curvature too).
    #[serde(default)]
    pub g1: bool,
    /// The points go round once (the last does not repeat the first): a closed path.
    #[serde(default)]
    pub closed: bool,
    /// Hold an open fit's ends on the first and last points.
    #[serde(default)]
    pub pin_ends: bool,
    /// Huber's robust loss with this δ (the points' units) instead of least squares.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub huber: Option<f64>,
    /// A non-negative weight per point.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub weights: Option<Vec<f64>>,
}

impl FitInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"points":[[x,y],[x,y],[x,y],…],"tolerance":T,"max_segments":N}"#;

    /// The library's options for this input.
    pub fn options(&self) -> Result<FitOptions, ErrorBody> {
        let alpha = match (self.alpha, self.alpha_range) {
            (Some(_), Some(_)) => {
                return Err(ErrorBody::invalid_input(
                    "give either alpha (fixed) or alpha_range (fitted), not both",
                ))
            }
            (Some(a), None) => FitAlpha::Fixed(a),
            (None, range) => {
                let [min, max] =
                    range.unwrap_or([lac::DEFAULT_ALPHA_RANGE.0, lac::DEFAULT_ALPHA_RANGE.1]);
                FitAlpha::Range {
                    min,
                    max,
                    shared: self.shared_alpha,
                }
            }
        };
        let max_segments = match (self.max_segments, self.tolerance) {
            (Some(n), _) => n,
            (None, Some(_)) => DEFAULT_MAX_SEGMENTS,
            (None, None) => 1,
        };
        Ok(FitOptions {
            tolerance: self.tolerance,
            max_segments,
            alpha,
            continuity: if self.g1 {
                Continuity::G1
            } else {
                Continuity::G2
            },
            closure: if self.closed {
                Closure::Closed
            } else {
                Closure::Open
            },
            pin_ends: self.pin_ends,
            loss: match self.huber {
                Some(delta) => FitLoss::Huber { delta },
                None => FitLoss::Squares,
            },
            weights: self.weights.clone(),
        })
    }

    /// Fit it.
    pub fn solve(&self) -> Result<Fit, ErrorBody> {
        let points: Vec<Point> = self.points.iter().map(|&p| point(p)).collect();
        Ok(Fit::from_points(&points, &self.options()?)?)
    }
}

/// One fitted log-aesthetic segment (through an inflection, two rows of `segments`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FitPieceRow {
    /// Its α.
    pub alpha: f64,
    /// Signed curvature at its start and end.
    pub curvature: [f64; 2],
    /// Its arc length.
    pub arc_length: f64,
    /// Arc length from the fit's start to its start.
    pub s: f64,
    /// Arc length of its point of zero curvature (an S), or null.
    pub inflection: Option<f64>,
    /// The first and last of its rows in `segments`.
    pub segments: [usize; 2],
}

/// One log-aesthetic segment of a fit, as `lac path` reports its segments, with what places
/// it (its start and tangent direction there).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FitSegmentRow {
    /// The fitted piece it belongs to.
    pub piece: usize,
    /// Its slope.
    pub alpha: f64,
    /// Λ of its standard-form piece.
    pub lambda: f64,
    /// Its first point.
    pub start: Xy,
    /// Its tangent direction there, radians.
    pub theta: f64,
    /// Arc length.
    pub arc_length: f64,
    /// Signed curvature at its start and end.
    pub curvature: [f64; 2],
}

/// A joint between two fitted pieces, as the fit's check measured it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FitJointRow {
    /// The joint.
    pub point: Xy,
    /// Arc length from the fit's start.
    pub s: f64,
    /// Signed curvature before and after it.
    pub curvature: [f64; 2],
    /// |κ⁻ − κ⁺| / max(|κ⁻|, |κ⁺|).
    pub curvature_jump: f64,
    /// Distance between the two pieces' ends.
    pub gap: f64,
    /// Angle between their tangents, radians.
    pub tangent_jump: f64,
}

/// A point far from the fit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FarPointRow {
    /// Its index in the input (from 0).
    pub index: usize,
    /// The point.
    pub point: Xy,
    /// Its distance to the fit.
    pub distance: f64,
}

/// A fit: `lac fit`'s JSON. The path (segments, joints, samples, as `lac path` prints
/// them) and the fit's figures.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FitReport {
    /// `"g1"` or `"g2"`.
    pub continuity: String,
    /// Whether the fit is closed.
    pub closed: bool,
    /// Arc length of the whole fit.
    pub arc_length: f64,
    /// The largest relative curvature jump at a joint (0 without joints).
    pub max_curvature_jump: f64,
    /// How many points were fitted.
    pub point_count: usize,
    /// The tolerance asked, or null.
    pub tolerance: Option<f64>,
    /// The number of fitted log-aesthetic segments (an S counts once).
    pub fitted_segments: usize,
    /// Root mean square of the points' distances to the fit.
    pub rms: f64,
    /// The largest distance.
    pub max_distance: f64,
    /// The farthest point's index (from 0).
    pub worst_point: usize,
    /// The farthest points, farthest first (at most [`FARTHEST_LISTED`]).
    pub farthest: Vec<FarPointRow>,
    /// The fitted pieces in order (none when a result is read back without them, as
    /// `/api/export` must, whose option `pieces` it would be: its segments place it).
    #[serde(default)]
    pub pieces: Vec<FitPieceRow>,
    /// The log-aesthetic segments in order (an S's two halves are two).
    pub segments: Vec<FitSegmentRow>,
    /// The joints between pieces in order (a closed fit's last one closes it).
    pub joints: Vec<FitJointRow>,
    /// Samples equally spaced in arc length over the whole fit (none when a result is read
    /// back without them, as `/api/export` must: its segments place it).
    #[serde(default)]
    pub samples: Vec<SampleRow>,
}

impl FitReport {
    /// The report of `fit` of `points` (with `tolerance` asked) with `n` samples.
    pub fn new(
        fit: &Fit,
        points: &[Xy],
        tolerance: Option<f64>,
        n: usize,
    ) -> Result<Self, ErrorBody> {
        let samples = fit.sample_by_arc_length(n)?;
        let segments = SegmentChain::pieces(fit);
        let mut rows = Vec::with_capacity(segments.len());
        for (i, piece) in fit.pieces().iter().enumerate() {
            for seg in &segments[piece.segments[0]..=piece.segments[1]] {
                rows.push(FitSegmentRow {
                    piece: i,
                    alpha: seg.alpha(),
                    lambda: seg.lambda(),
                    start: xy(seg.start_point()),
                    theta: seg.theta_at_s(0.0)?,
                    arc_length: seg.arc_length(),
                    curvature: [seg.signed_curvature_start(), seg.signed_curvature_end()],
                });
            }
        }
        FitReport {
            continuity: continuity_name(fit.continuity()).to_string(),
            closed: fit.closure() == Closure::Closed,
            arc_length: fit.arc_length(),
            max_curvature_jump: fit
                .joints()
                .iter()
                .map(|j| j.curvature_jump)
                .fold(0.0, f64::max),
            point_count: fit.distances().len(),
            tolerance,
            fitted_segments: fit.pieces().len(),
            rms: fit.rms(),
            max_distance: fit.max_distance(),
            worst_point: fit.worst_point(),
            farthest: fit
                .farthest_points(FARTHEST_LISTED)
                .into_iter()
                .map(|k| FarPointRow {
                    index: k,
                    point: points.get(k).copied().unwrap_or([f64::NAN; 2]),
                    distance: fit.distances()[k],
                })
                .collect(),
            pieces: fit
                .pieces()
                .iter()
                .map(|p| FitPieceRow {
                    alpha: p.alpha,
                    curvature: p.curvatures,
                    arc_length: p.length,
                    s: p.s,
                    inflection: p.inflection,
                    segments: p.segments,
                })
                .collect(),
            segments: rows,
            joints: fit
                .joints()
                .iter()
                .map(|j| FitJointRow {
                    point: xy(j.point),
                    s: j.s,
                    curvature: [j.curvature_before, j.curvature_after],
                    curvature_jump: j.curvature_jump,
                    gap: j.gap,
                    tangent_jump: j.tangent_jump,
                })
                .collect(),
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }

    /// The fitted path again, from its segments' rows (numbers are printed to round trip,
    /// so each segment placed again is the one reported, to its last bits).
    pub fn path(&self) -> Result<FittedPath, ErrorBody> {
        if self.segments.is_empty() {
            return Err(ErrorBody::invalid_input(
                "a lac fit result without segments",
            ));
        }
        let segments = self
            .segments
            .iter()
            .map(|g| {
                Segment::from_curvatures(
                    point(g.start),
                    g.theta,
                    g.curvature,
                    g.arc_length,
                    g.alpha,
                )
            })
            .collect::<lac::Result<Vec<Segment>>>()?;
        let continuity = match self.continuity.as_str() {
            "g1" => Continuity::G1,
            "g2" => Continuity::G2,
            other => {
                return Err(ErrorBody::invalid_input(format!(
                    "a lac fit result's continuity is \"g1\" or \"g2\", not {other:?}"
                )))
            }
        };
        Ok(FittedPath {
            segments,
            continuity,
            closed: self.closed,
        })
    }
}

fn continuity_name(continuity: Continuity) -> &'static str {
    match continuity {
        Continuity::G1 => "g1",
        Continuity::G2 => "g2",
    }
}

impl Report for FitReport {
    fn is_finite(&self) -> bool {
        all_finite([
            self.arc_length,
            self.max_curvature_jump,
            self.rms,
            self.max_distance,
        ]) && all_finite(self.tolerance)
            && self
                .farthest
                .iter()
                .all(|f| all_finite([f.distance, f.point[0], f.point[1]]))
            && self.pieces.iter().all(|p| {
                all_finite([p.alpha, p.arc_length, p.s, p.curvature[0], p.curvature[1]])
                    && all_finite(p.inflection)
            })
            && self.segments.iter().all(|g| {
                all_finite([
                    g.alpha,
                    g.lambda,
                    g.start[0],
                    g.start[1],
                    g.theta,
                    g.arc_length,
                    g.curvature[0],
                    g.curvature[1],
                ])
            })
            && self.joints.iter().all(|j| {
                all_finite([
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
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}

/// A fitted path as a curve of its own: its log-aesthetic segments in order (an S's two
/// halves meet across a straight hair of at most 1e-12 of the piece at the inflection), G2
/// or G1, open or closed. What a fit (or a fit's result read back) is for CAD export.
#[derive(Clone, Debug)]
pub struct FittedPath {
    segments: Vec<Segment>,
    continuity: Continuity,
    closed: bool,
}

impl From<&Fit> for FittedPath {
    fn from(fit: &Fit) -> Self {
        FittedPath {
            segments: SegmentChain::pieces(fit).to_vec(),
            continuity: fit.continuity(),
            closed: fit.closure() == Closure::Closed,
        }
    }
}

impl SegmentChain for FittedPath {
    fn pieces(&self) -> &[Segment] {
        &self.segments
    }
}

impl FittedPath {
    /// G2 or G1.
    pub fn continuity(&self) -> Continuity {
        self.continuity
    }

    /// Whether it is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }
}

/// A fitted path: `lac fit`'s result (told by its `"rms"` and `"segments"`, placed again
/// from its segments) or a fit's input (told by a key only a fit takes: `"max_segments"`,
/// `"alpha_range"`, `"shared_alpha"`, `"g1"`, `"pin_ends"`, `"huber"`, `"weights"`), fitted.
pub struct FitKind;

impl Kind for FitKind {
    const NAME: &'static str = "fit";
    type Curve = FittedPath;

    fn claims(document: &Map<String, Value>) -> bool {
        let has = |key: &str| document.contains_key(key);
        (has("rms") && has("segments"))
            || [
                "max_segments",
                "alpha_range",
                "shared_alpha",
                "g1",
                "pin_ends",
                "huber",
                "weights",
            ]
            .iter()
            .any(|key| has(key))
    }

    fn solve(document: Map<String, Value>) -> Result<FittedPath, ErrorBody> {
        if document.contains_key("rms") && document.contains_key("segments") {
            fields::<FitReport>(document, "a lac fit result", "what lac fit prints")?.path()
        } else {
            let fit = fields::<FitInput>(document, "a fit", FitInput::SHAPE)?.solve()?;
            Ok(FittedPath::from(&fit))
        }
    }

    /// Segment by segment, as a path: every joint (and an S's inflection) is a knot with
    /// the fit's continuity.
    fn export(path: &FittedPath) -> Result<ExportCurve<'_>, ErrorBody> {
        let continuity = match path.continuity {
            Continuity::G1 => "G1",
            Continuity::G2 => "G2",
        };
        Ok(ExportCurve::pieces(
            Self::NAME,
            path.arc_length(),
            continuity,
            segment_pieces(&path.segments),
        ))
    }
}
