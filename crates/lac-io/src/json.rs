//! The JSON shapes of log-aesthetic curves, defined once for every front end.
//!
//! *Inputs* are what a request (or one line of a `--batch`) holds: [`SegmentInput`],
//! [`CompoundInput`], [`CurveInput`] (either of them), [`QuasiInput`], [`MonotoneInput`],
//! [`PiecesInput`]. Each solves itself with the core library. *Reports* are what is printed
//! or answered: [`SegmentReport`], [`CompoundReport`], [`QuasiReport`], [`MonotoneReport`],
//! [`LcgReport`], [`RegionReport`], and on failure [`ErrorReport`].
//!
//! Numbers are written by serde_json as the shortest decimal that reads back to the same
//! `f64`, and read correctly rounded; points are `[x, y]` arrays; names are snake_case.
//! Reports never hold NaN or infinities (serde_json would write `null`): a front end checks
//! [`Report::is_finite`] before it answers.

use kurbo::Point;
use lac::{
    Alphas, CompoundCurve, Continuity, ControlPolygon, CurvaturePoint, Curve, Frame, GraphPoint,
    LcgFit, LcgLine, Monotonicity, MonotonicityReport, Path, QuasiCurve, QuasiPiece, RationalCubic,
    Sample, Segment, SpaceSegment, SpaceShape, Tolerance, TorsionType, Vec3,
};
use lac::{Closure, SegmentChain, SpaceCurve, ToBezier};
use serde::{Deserialize, Serialize};

/// A planar point, `[x, y]`.
pub type Xy = [f64; 2];

fn xy(p: Point) -> Xy {
    [p.x, p.y]
}

fn point(p: Xy) -> Point {
    Point::new(p[0], p[1])
}

// ---------------------------------------------------------------------------------------
// Errors

/// What went wrong, in every front end's words: `{"kind":…,"message":…}`.
///
/// `kind` is the library's [`lac::ErrorKind`] in snake_case (`"not_drawable"`,
/// `"collinear_points"`, …) or one of the front ends' own: `"usage"`, `"invalid_input"`
/// (unreadable JSON or numbers, wrong shapes), `"limit"` (a request over a stated limit),
/// `"io"`, `"internal"`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ErrorBody {
    /// A stable snake_case name.
    pub kind: String,
    /// What was wrong and what would fix it.
    pub message: String,
    /// For `not_drawable` space segments whose Ω is too large: the largest Ω that works.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub omega_max: Option<f64>,
    /// For a `no_g2_path` path: the joint fractions of the nearest G1 path, where one can
    /// be drawn (pass them as `fractions` without `g2`); absent where none can.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub g1_fractions: Option<Vec<f64>>,
}

/// How a front end should treat a failure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorClass {
    /// The request itself is wrong (syntax, NaN, coincident points, a limit): exit code 2,
    /// HTTP 400.
    Invalid,
    /// The request is valid but no curve (or fit) exists for it: exit code 3, HTTP 422.
    Undrawable,
    /// Reading or writing failed: exit code 1.
    Io,
    /// A defect of lac: exit code 70, HTTP 500.
    Internal,
}

impl ErrorBody {
    /// A failure of `kind` with `message`.
    pub fn new(kind: impl Into<String>, message: impl Into<String>) -> Self {
        ErrorBody {
            kind: kind.into(),
            message: message.into(),
            omega_max: None,
            g1_fractions: None,
        }
    }

    /// Unreadable or ill-shaped input.
    pub fn invalid_input(message: impl Into<String>) -> Self {
        ErrorBody::new("invalid_input", message)
    }

    /// A request over a stated limit.
    pub fn limit(message: impl Into<String>) -> Self {
        ErrorBody::new("limit", message)
    }

    /// How a front end should treat it.
    pub fn class(&self) -> ErrorClass {
        match self.kind.as_str() {
            "not_drawable" | "fit_failed" | "tolerance_not_met" | "too_many_pieces"
            | "no_g2_path" => ErrorClass::Undrawable,
            "io" => ErrorClass::Io,
            "internal" | "numerical_failure" => ErrorClass::Internal,
            _ => ErrorClass::Invalid,
        }
    }

    /// The one line `{"error":{…}}`, without a newline.
    pub fn to_json_line(&self) -> String {
        to_line(&ErrorReport {
            error: self.clone(),
        })
    }
}

impl From<lac::Error> for ErrorBody {
    fn from(err: lac::Error) -> Self {
        let omega_max = match &err {
            lac::Error::NotDrawable(lac::NotDrawable::TorsionTooLarge { omega_max, .. }) => {
                Some(*omega_max)
            }
            _ => None,
        };
        let kind = match serde_json::to_value(err.kind()) {
            Ok(serde_json::Value::String(name)) => name,
            _ => "internal".to_string(),
        };
        ErrorBody {
            kind,
            message: err.to_string(),
            omega_max,
            g1_fractions: None,
        }
    }
}

impl std::fmt::Display for ErrorBody {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.kind, self.message)
    }
}

impl std::error::Error for ErrorBody {}

/// `{"error":{"kind":…,"message":…}}`: a failed command's standard error line, a failed
/// batch line, a server's error body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ErrorReport {
    /// What went wrong.
    pub error: ErrorBody,
}

/// Parse one JSON document as a `T`, or say what was wrong and that `shape` was expected.
pub fn parse<T: serde::de::DeserializeOwned>(text: &str, shape: &str) -> Result<T, ErrorBody> {
    if text.trim().is_empty() {
        return Err(ErrorBody::invalid_input(format!(
            "empty input; expected {shape}"
        )));
    }
    serde_json::from_str(text)
        .map_err(|e| ErrorBody::invalid_input(format!("{e}; expected {shape}")))
}

/// A report as one line of JSON, without a newline.
pub fn to_line<T: Serialize>(report: &T) -> String {
    // Reports are plain numbers, strings and arrays: serialising them cannot fail.
    serde_json::to_string(report).unwrap_or_else(|e| {
        ErrorBody::new("internal", format!("a report did not serialise: {e}")).to_json_line()
    })
}

/// A report as one line of JSON appended to `out`, without a newline: the bytes of
/// [`to_line`] without an intermediate `String` (for `--batch`, which writes many).
pub fn write_line<T: Serialize>(report: &T, out: &mut Vec<u8>) {
    let mark = out.len();
    if let Err(e) = serde_json::to_writer(&mut *out, report) {
        out.truncate(mark);
        let body = ErrorBody::new("internal", format!("a report did not serialise: {e}"));
        out.extend_from_slice(body.to_json_line().as_bytes());
    }
}

/// Reports that can say whether all their numbers are finite (JSON has no NaN).
pub trait Report: Serialize {
    /// Are all numbers finite?
    fn is_finite(&self) -> bool;

    /// The report, or an `internal` error when a number is not finite.
    fn checked(self) -> Result<Self, ErrorBody>
    where
        Self: Sized,
    {
        if self.is_finite() {
            Ok(self)
        } else {
            Err(ErrorBody::new(
                "internal",
                "a result is not finite (NaN or infinite); please report this input",
            ))
        }
    }
}

fn all_finite(values: impl IntoIterator<Item = f64>) -> bool {
    values.into_iter().all(f64::is_finite)
}

// ---------------------------------------------------------------------------------------
// Inputs

/// A segment from three control points and α (seed 000): `{"points":[[x,y]×3],"alpha":A}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SegmentInput {
    /// P0 (start), P1 (the end tangents' intersection), P2 (end).
    pub points: [Xy; 3],
    /// The slope α of the logarithmic curvature graph.
    pub alpha: f64,
}

impl SegmentInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha":A}"#;

    /// Solve it.
    pub fn solve(&self) -> Result<Segment, ErrorBody> {
        Ok(Segment::from_control_points(
            self.points.map(point),
            self.alpha,
        )?)
    }
}

/// A compound-rhythm curve (seeds 004 and 002): three points with `ratio`, or four points
/// without: `{"points":[…],"alpha0":A,"alpha1":B,"ratio":R}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CompoundInput {
    /// Three points (ends and the end tangents' intersection) or four control points.
    pub points: Vec<Xy>,
    /// Slope of the piece from the first point.
    pub alpha0: f64,
    /// Slope of the piece to the last point.
    pub alpha1: f64,
    /// Share of the turning made by the α0 piece (three points only).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
}

impl CompoundInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha0":A,"alpha1":B,"ratio":R} or {"points":[[x,y],[x,y],[x,y],[x,y]],"alpha0":A,"alpha1":B}"#;

    /// Solve it.
    pub fn solve(&self) -> Result<CompoundCurve, ErrorBody> {
        let p = &self.points;
        match (p.len(), self.ratio) {
            (3, Some(ratio)) => Ok(CompoundCurve::from_three_points(
                [point(p[0]), point(p[1]), point(p[2])],
                self.alpha0,
                self.alpha1,
                ratio,
            )?),
            (4, None) => Ok(CompoundCurve::from_four_points(
                [point(p[0]), point(p[1]), point(p[2]), point(p[3])],
                self.alpha0,
                self.alpha1,
            )?),
            (3, None) => Err(ErrorBody::invalid_input(
                "three points need a ratio (the share of the turning made by the alpha0 \
                 piece, between 0 and 1); or give four control points",
            )),
            (4, Some(_)) => Err(ErrorBody::invalid_input(
                "four control points fix the joint's tangent; a ratio applies to three \
                 points only: drop it",
            )),
            (n, _) => Err(ErrorBody::invalid_input(format!(
                "a compound curve takes three points (with a ratio) or four, not {n}"
            ))),
        }
    }
}

/// Either kind of planar log-aesthetic curve: a [`SegmentInput`] (with `alpha`) or a
/// [`CompoundInput`] (with `alpha0` and `alpha1`). Other fields are ignored, so a report
/// reads back as the input it was solved from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum CurveInput {
    /// A segment.
    Segment(SegmentInput),
    /// A compound curve.
    Compound(CompoundInput),
}

/// A solved planar curve of either kind.
#[derive(Clone, Debug)]
pub enum Solved {
    /// A segment.
    Segment(Segment),
    /// A compound curve.
    Compound(CompoundCurve),
}

impl Solved {
    /// The curve, whatever its kind.
    pub fn curve(&self) -> &dyn SegmentChain {
        match self {
            Solved::Segment(s) => s,
            Solved::Compound(c) => c,
        }
    }
}

impl CurveInput {
    /// Solve it.
    pub fn solve(&self) -> Result<Solved, ErrorBody> {
        match self {
            CurveInput::Segment(s) => s.solve().map(Solved::Segment),
            CurveInput::Compound(c) => c.solve().map(Solved::Compound),
        }
    }

    /// The control points as given.
    pub fn points(&self) -> Vec<Xy> {
        match self {
            CurveInput::Segment(s) => s.points.to_vec(),
            CurveInput::Compound(c) => c.points.clone(),
        }
    }
}

/// A quasi-aesthetic replacement of a curve (seed 001): the curve's fields, plus
/// `"tolerance"` (relative to the arc length; absent for the seed's single rational cubic)
/// and `"cubic"` (plain cubics, all weights 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuasiInput {
    /// The curve to replace.
    #[serde(flatten)]
    pub curve: CurveInput,
    /// Largest deviation, relative to the arc length.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub tolerance: Option<f64>,
    /// Plain cubics instead of rational ones.
    #[serde(default)]
    pub cubic: bool,
}

/// One (rational) cubic Bézier piece: `{"points":[[x,y]×4],"weights":[w0,w1,w2,w3]}`
/// (weights optional: a plain cubic).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PieceInput {
    /// Control points b0..b3.
    pub points: [Xy; 4],
    /// Weights w0..w3 (all 1 when absent).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub weights: Option<[f64; 4]>,
}

impl PieceInput {
    /// The rational cubic.
    pub fn to_rational_cubic(&self) -> Result<RationalCubic, ErrorBody> {
        Ok(RationalCubic::new(
            self.points.map(point),
            self.weights.unwrap_or([1.0; 4]),
        )?)
    }
}

/// A chain of Bézier pieces, `{"pieces":[…]}`: what `lac quasi` prints, read back.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PiecesInput {
    /// The pieces in order.
    pub pieces: Vec<PieceInput>,
}

impl PiecesInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"pieces":[{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]},…]}"#;

    /// The rational cubics.
    pub fn to_rational_cubics(&self) -> Result<Vec<RationalCubic>, ErrorBody> {
        if self.pieces.is_empty() {
            return Err(ErrorBody::invalid_input("no pieces given"));
        }
        self.pieces
            .iter()
            .map(PieceInput::to_rational_cubic)
            .collect()
    }
}

/// The monotonicity question for one (rational) cubic: `{"points":[[x,y]×4],"weights":…}`.
pub type MonotoneInput = PieceInput;

// ---------------------------------------------------------------------------------------
// Reports

/// One sample: arc length, position, tangent direction (radians) and signed curvature.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampleRow {
    /// Arc length from the first control point.
    pub s: f64,
    /// Position, x.
    pub x: f64,
    /// Position, y.
    pub y: f64,
    /// Tangent direction, radians, continuous from the first control point.
    pub theta: f64,
    /// Signed curvature, + for a left turn.
    pub kappa: f64,
}

impl From<&Sample> for SampleRow {
    fn from(s: &Sample) -> Self {
        SampleRow {
            s: s.s,
            x: s.point.x,
            y: s.point.y,
            theta: s.theta,
            kappa: s.kappa,
        }
    }
}

impl From<Sample> for SampleRow {
    fn from(s: Sample) -> Self {
        SampleRow::from(&s)
    }
}

impl SampleRow {
    fn values(&self) -> [f64; 5] {
        [self.s, self.x, self.y, self.theta, self.kappa]
    }
}

/// Samples as CSV with the header `s,x,y,theta,kappa` (shortest round-trip numbers).
pub fn samples_csv(samples: &[SampleRow]) -> String {
    let mut out = String::from("s,x,y,theta,kappa\n");
    for r in samples {
        let [s, x, y, theta, kappa] = r.values();
        out.push_str(&format!("{s:?},{x:?},{y:?},{theta:?},{kappa:?}\n"));
    }
    out
}

/// A solved segment: `lac segment`'s JSON and each good line of its `--batch`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SegmentReport {
    /// The slope of the logarithmic curvature graph.
    pub alpha: f64,
    /// Λ of the solved standard-form piece.
    pub lambda: f64,
    /// Arc length from the first to the last control point.
    pub arc_length: f64,
    /// Signed curvature (+ for a left turn) at the first control point.
    pub curvature_start: f64,
    /// Signed curvature at the last control point.
    pub curvature_end: f64,
    /// Turning angle of the control polygon, radians, in (0, π).
    pub turning_angle: f64,
    /// The control points as given.
    pub points: [Xy; 3],
    /// Samples equally spaced in arc length, first and last at the end points.
    pub samples: Vec<SampleRow>,
}

impl SegmentReport {
    /// The report of `segment` with `n` samples.
    pub fn new(segment: &Segment, n: usize) -> Result<Self, ErrorBody> {
        Self::of_input(segment, n, segment.control_points().map(xy))
    }

    /// The report of `segment` with `n` samples, and with the control points exactly as the
    /// caller gave them (`points`: the solved segment's own are within rounding of them, and
    /// are not computed).
    pub fn of_input(segment: &Segment, n: usize, points: [Xy; 3]) -> Result<Self, ErrorBody> {
        let samples = segment.sample_by_arc_length(n)?;
        SegmentReport {
            alpha: segment.alpha(),
            lambda: segment.lambda(),
            arc_length: segment.arc_length(),
            curvature_start: segment.signed_curvature_start(),
            curvature_end: segment.signed_curvature_end(),
            turning_angle: segment.turning_angle(),
            points,
            // (In place: a sample and a row are the same size.)
            samples: samples.into_iter().map(SampleRow::from).collect(),
        }
        .checked()
    }

    /// The report with the control points exactly as the caller gave them (the solved
    /// segment's own are within rounding of them).
    pub fn with_points(mut self, points: [Xy; 3]) -> Self {
        self.points = points;
        self
    }
}

impl SegmentReport {
    /// The report as one line of JSON appended to `out`, without a newline: the bytes
    /// serde_json writes (see [`to_line`]), formatted directly, for `--batch`.
    pub fn write_json(&self, out: &mut Vec<u8>) {
        let mut w = NumberWriter::default();
        out.extend_from_slice(b"{\"alpha\":");
        w.num(out, self.alpha);
        out.extend_from_slice(b",\"lambda\":");
        w.num(out, self.lambda);
        out.extend_from_slice(b",\"arc_length\":");
        let length = w.num(out, self.arc_length);
        out.extend_from_slice(b",\"curvature_start\":");
        let kappa_start = w.num(out, self.curvature_start);
        out.extend_from_slice(b",\"curvature_end\":");
        let kappa_end = w.num(out, self.curvature_end);
        out.extend_from_slice(b",\"turning_angle\":");
        w.num(out, self.turning_angle);
        out.extend_from_slice(b",\"points\":[");
        let points = self.points.each_ref().map(|&[x, y]| {
            out.extend_from_slice(if out.ends_with(b"[") { b"[" } else { b",[" });
            let x = w.num(out, x);
            out.push(b',');
            let y = w.num(out, y);
            out.push(b']');
            [x, y]
        });
        out.extend_from_slice(b"],\"samples\":[");
        // The end samples repeat the arc length, the end curvatures and (usually) the end
        // points: their bytes are copied rather than formatted again.
        let last = self.samples.len().saturating_sub(1);
        for (i, row) in self.samples.iter().enumerate() {
            let ends = if i == 0 {
                Some((&points[0], &kappa_start, None))
            } else if i == last {
                Some((&points[2], &kappa_end, Some(&length)))
            } else {
                None
            };
            out.extend_from_slice(if i == 0 { b"{\"s\":" } else { b",{\"s\":" });
            w.again(out, row.s, ends.and_then(|e| e.2));
            out.extend_from_slice(b",\"x\":");
            w.again(out, row.x, ends.map(|e| &e.0[0]));
            out.extend_from_slice(b",\"y\":");
            w.again(out, row.y, ends.map(|e| &e.0[1]));
            out.extend_from_slice(b",\"theta\":");
            w.num(out, row.theta);
            out.extend_from_slice(b",\"kappa\":");
            w.again(out, row.kappa, ends.map(|e| e.1));
            out.push(b'}');
        }
        out.extend_from_slice(b"]}");
    }
}

/// Writes numbers as serde_json does, and copies one already written when it is the same.
#[derive(Default)]
struct NumberWriter {
    floats: zmij::Buffer,
}

/// A number [`NumberWriter`] has written, and where.
struct Written {
    x: f64,
    bytes: std::ops::Range<usize>,
}

impl NumberWriter {
    /// `x` appended to `out` (`null` when not finite).
    fn num(&mut self, out: &mut Vec<u8>, x: f64) -> Written {
        let start = out.len();
        if x.is_finite() {
            push_short(out, self.floats.format_finite(x).as_bytes());
        } else {
            out.extend_from_slice(b"null");
        }
        Written {
            x,
            bytes: start..out.len(),
        }
    }

    /// `x` appended to `out`, copied from `before` when that is the same number.
    fn again(&mut self, out: &mut Vec<u8>, x: f64, before: Option<&Written>) {
        match before {
            Some(b) if b.x.to_bits() == x.to_bits() => {
                let mut copy = [0; SHORT];
                let n = short_copy(&mut copy, &out[b.bytes.clone()]);
                push_short(out, &copy[..n]);
            }
            _ => {
                self.num(out, x);
            }
        }
    }
}

/// The longest [`push_short`] copies: a number as zmij writes it has at most 24 bytes.
const SHORT: usize = 32;

/// `bytes` appended to `out`, as [`short_copy`] copies them.
fn push_short(out: &mut Vec<u8>, bytes: &[u8]) {
    let at = out.len();
    out.extend_from_slice(&[0; SHORT]);
    let n = short_copy(&mut out[at..], bytes);
    out.truncate(at + n);
}

/// The first `SHORT` bytes or fewer of `bytes` copied to the start of `dst` (which has
/// room for `SHORT`), returning how many: by two overlapping copies of a fixed size, which
/// compile to a few moves (a call of memcpy for each of some twenty short numbers a line
/// costs more than writing them).
fn short_copy(dst: &mut [u8], bytes: &[u8]) -> usize {
    let n = bytes.len().min(SHORT).min(dst.len());
    let (dst, bytes) = (&mut dst[..n], &bytes[..n]);
    fn two<const K: usize>(dst: &mut [u8], bytes: &[u8]) {
        if let (Some(d), Some(b)) = (dst.first_chunk_mut::<K>(), bytes.first_chunk::<K>()) {
            *d = *b;
        }
        if let (Some(d), Some(b)) = (dst.last_chunk_mut::<K>(), bytes.last_chunk::<K>()) {
            *d = *b;
        }
    }
    match n {
        16.. => two::<16>(dst, bytes),
        8.. => two::<8>(dst, bytes),
        4.. => two::<4>(dst, bytes),
        _ => dst.iter_mut().zip(bytes).for_each(|(d, b)| *d = *b),
    }
    n
}

impl SegmentInput {
    /// Read a `--batch` line: the common exact shape
    /// `{"points":[[x,y],[x,y],[x,y]],"alpha":A}` (any JSON whitespace, fields in this order)
    /// by a direct scan, anything else (other orders, escapes, errors) by [`parse`], so the
    /// numbers are the same correctly rounded doubles and every message is serde_json's.
    pub fn parse_line(text: &str) -> Result<SegmentInput, ErrorBody> {
        match scan_segment_input(text) {
            Some(input) => Ok(input),
            None => parse(text, Self::SHAPE),
        }
    }
}

/// The direct scan of [`SegmentInput::parse_line`]; `None` for anything it does not know.
fn scan_segment_input(text: &str) -> Option<SegmentInput> {
    let mut at = Scan {
        text: text.as_bytes(),
        source: text,
        pos: 0,
    };
    at.expect(b'{')?;
    at.key(b"points")?;
    at.expect(b'[')?;
    let mut points = [[0.0; 2]; 3];
    for (i, p) in points.iter_mut().enumerate() {
        if i > 0 {
            at.expect(b',')?;
        }
        at.expect(b'[')?;
        p[0] = at.number()?;
        at.expect(b',')?;
        p[1] = at.number()?;
        at.expect(b']')?;
    }
    at.expect(b']')?;
    at.expect(b',')?;
    at.key(b"alpha")?;
    let alpha = at.number()?;
    at.expect(b'}')?;
    at.skip_space();
    (at.pos == text.len()).then_some(SegmentInput { points, alpha })
}

struct Scan<'a> {
    text: &'a [u8],
    /// The same text as a `str`, to slice numbers from (they are ASCII).
    source: &'a str,
    pos: usize,
}

impl Scan<'_> {
    fn skip_space(&mut self) {
        while let Some(b' ' | b'\t' | b'\n' | b'\r') = self.text.get(self.pos) {
            self.pos += 1;
        }
    }

    fn expect(&mut self, byte: u8) -> Option<()> {
        self.skip_space();
        (self.text.get(self.pos) == Some(&byte)).then(|| self.pos += 1)
    }

    /// `"name":` (no escapes).
    fn key(&mut self, name: &[u8]) -> Option<()> {
        self.expect(b'"')?;
        let end = self.pos + name.len();
        (self.text.get(self.pos..end) == Some(name)).then_some(())?;
        self.pos = end;
        (self.text.get(self.pos) == Some(&b'"')).then_some(())?;
        self.pos += 1;
        self.expect(b':')
    }

    /// A number in JSON's grammar, `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`, read
    /// correctly rounded (as serde_json's float_roundtrip does); `None` for anything else,
    /// and for magnitudes that overflow (serde_json's error is the one to give).
    fn number(&mut self) -> Option<f64> {
        self.skip_space();
        let start = self.pos;
        let negative = self.text.get(self.pos) == Some(&b'-');
        if negative {
            self.pos += 1;
        }
        // The first 19 significant digits in `digits`, the value being digits × 10^exponent
        // plus what was dropped, if any digit was (only once `digits` ≥ 10^18).
        let (mut digits, mut exponent, mut dropped) = (0u64, 0i64, false);
        let mut read = |s: &mut Self, fraction: bool| {
            let from = s.pos;
            // Eight digits at a time while they fit (shortest round-trip output has 15–17).
            while digits < 10_000_000_000 {
                let Some(eight) = s.text.get(s.pos..s.pos + 8).and_then(eight_digits) else {
                    break;
                };
                digits = 100_000_000 * digits + eight;
                exponent -= 8 * i64::from(fraction);
                s.pos += 8;
            }
            while let Some(&b) = s.text.get(s.pos) {
                if !b.is_ascii_digit() {
                    break;
                }
                if digits < 1_000_000_000_000_000_000 {
                    digits = 10 * digits + u64::from(b - b'0');
                    exponent -= i64::from(fraction);
                } else {
                    exponent += i64::from(!fraction);
                    dropped = true;
                }
                s.pos += 1;
            }
            s.pos - from
        };
        let first = *self.text.get(self.pos)?;
        let int = read(self, false);
        if int == 0 || (first == b'0' && int > 1) {
            return None;
        }
        if self.text.get(self.pos) == Some(&b'.') {
            self.pos += 1;
            if read(self, true) == 0 {
                return None;
            }
        }
        if let Some(b'e' | b'E') = self.text.get(self.pos) {
            self.pos += 1;
            let sign = match self.text.get(self.pos) {
                Some(b'-') => -1,
                Some(b'+') => 1,
                _ => 0,
            };
            self.pos += usize::from(sign != 0);
            let from = self.pos;
            let mut power = 0i64;
            while let Some(&b) = self.text.get(self.pos).filter(|b| b.is_ascii_digit()) {
                power = (10 * power + i64::from(b - b'0')).min(1 << 40);
                self.pos += 1;
            }
            if self.pos == from {
                return None;
            }
            exponent += if sign < 0 { -power } else { power };
        }
        // Clinger's fast path: both factors exact doubles, so one correctly rounded
        // operation gives the correctly rounded value; the rest by the standard library.
        let magnitude = if digits == 0 {
            0.0
        } else if digits <= 1 << 53 && exponent.abs() <= 22 {
            let power = POWERS_OF_TEN[exponent.unsigned_abs() as usize];
            if exponent >= 0 {
                digits as f64 * power
            } else {
                digits as f64 / power
            }
        } else if let Some(x) = exactly_rounded(digits, exponent).filter(|_| !dropped) {
            x
        } else {
            let token = self.source.get(start..self.pos)?;
            return token.parse::<f64>().ok().filter(|x| x.is_finite());
        };
        Some(if negative { -magnitude } else { magnitude })
    }
}

/// digits × 10^exponent correctly rounded, by exact integer arithmetic in 128 bits, for
/// the 17- to 19-digit numbers that shortest round-trip output writes (beyond Clinger's
/// fast path) with |exponent| ≤ 19; `None` for the rest.
fn exactly_rounded(digits: u64, exponent: i64) -> Option<f64> {
    let power = 10u128.checked_pow(u32::try_from(exponent.unsigned_abs()).ok()?)?;
    if !(1..=19).contains(&exponent.abs()) {
        return None;
    }
    if exponent > 0 {
        // An exact integer below 2^128; `as` rounds it to nearest, ties to even.
        return Some((u128::from(digits) * power) as f64);
    }
    // digits / 10^k: shift digits to the top of 128 bits, divide, and fold a non-zero
    // remainder into the lowest bit (a sticky bit: the quotient has at least 128 − 64 = 64
    // bits, so that bit lies far below the rounding position) before rounding to a double.
    let shift = digits.leading_zeros() + 64;
    let numerator = u128::from(digits) << shift;
    let (quotient, remainder) = (numerator / power, numerator % power);
    let rounded = (quotient | u128::from(remainder != 0)) as f64;
    // × 2^−shift, exact: the result is at least 10^−19, a normal number.
    Some(rounded * f64::from_bits((1023 - u64::from(shift)) << 52))
}

/// The value of eight ASCII digits, `None` unless all eight are digits: all at once, in the
/// bytes of one `u64` (the first digit in the lowest byte).
fn eight_digits(bytes: &[u8]) -> Option<u64> {
    let v = u64::from_le_bytes(bytes.try_into().ok()?);
    // Every byte 0x30–0x39: high nibble 3, and adding 6 does not carry out of the low one.
    let high = 0xF0F0_F0F0_F0F0_F0F0;
    let threes = 0x3030_3030_3030_3030;
    if v & high != threes || v.wrapping_add(0x0606_0606_0606_0606) & high != threes {
        return None;
    }
    let d = v - threes;
    // Pairs: byte 2i holds 10·d(2i) + d(2i+1).
    let pairs = d.wrapping_mul(10).wrapping_add(d >> 8);
    // Bytes 0 and 4 (pairs 1 and 3), bytes 2 and 6 (pairs 2 and 4), weighted and summed
    // in the high half.
    let mask = 0x0000_00FF_0000_00FF;
    let odd = (pairs & mask).wrapping_mul(100 + (1_000_000 << 32));
    let even = ((pairs >> 16) & mask).wrapping_mul(1 + (10_000 << 32));
    Some(odd.wrapping_add(even) >> 32)
}

/// 10^0 … 10^22, every one exact in a double.
const POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

impl Report for SegmentReport {
    fn is_finite(&self) -> bool {
        all_finite([
            self.alpha,
            self.lambda,
            self.arc_length,
            self.curvature_start,
            self.curvature_end,
            self.turning_angle,
        ]) && all_finite(self.points.iter().flatten().copied())
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}

/// One piece's logarithmic curvature graph: log(ρ ds/dρ) = alpha log ρ + intercept over
/// log ρ ∈ log_rho (natural logarithms, in the order of travel).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LcgRow {
    /// The slope α of the piece.
    pub alpha: f64,
    /// log(ρ ds/dρ) at log ρ = 0.
    pub intercept: f64,
    /// The range of log ρ covered by the piece, [from, to] in the order of travel.
    pub log_rho: [f64; 2],
}

impl From<LcgLine> for LcgRow {
    fn from(line: LcgLine) -> Self {
        LcgRow {
            alpha: line.alpha,
            intercept: line.intercept,
            log_rho: [line.log_rho.0, line.log_rho.1],
        }
    }
}

/// A solved compound curve: `lac compound`'s JSON and each good line of its `--batch`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CompoundReport {
    /// The slope of the piece from the first point to the joint.
    pub alpha0: f64,
    /// The slope of the piece from the joint to the last point.
    pub alpha1: f64,
    /// The share of the turning made by the α0 piece, as given (three-point form only).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
    /// Λ of the joint-reference standard form (ρ = 1 at the joint).
    pub lambda: f64,
    /// Arc length from the first to the last point.
    pub arc_length: f64,
    /// Arc length from the first point to the joint.
    pub joint_s: f64,
    /// Signed curvature (+ for a left turn) at the first point.
    pub curvature_start: f64,
    /// Signed curvature at the joint (the same from both pieces: G2 and G3 there).
    pub curvature_joint: f64,
    /// Signed curvature at the last point.
    pub curvature_end: f64,
    /// Total turning of the control polygon, radians, in (0, 2π) (below π for three points).
    pub turning_angle: f64,
    /// The joint.
    pub joint: Xy,
    /// The logarithmic curvature graph of each piece; `null` for a circular arc.
    pub lcg: [Option<LcgRow>; 2],
    /// The control points as given: three, or four.
    pub points: Vec<Xy>,
    /// Samples equally spaced in arc length over the whole curve.
    pub samples: Vec<SampleRow>,
}

impl CompoundReport {
    /// The report of `curve`, solved from `input`, with `n` samples.
    pub fn new(curve: &CompoundCurve, input: &CompoundInput, n: usize) -> Result<Self, ErrorBody> {
        let samples = curve.sample_by_arc_length(n)?;
        let [alpha0, alpha1] = curve.alpha();
        CompoundReport {
            alpha0,
            alpha1,
            ratio: input.ratio,
            lambda: curve.lambda(),
            arc_length: curve.arc_length(),
            joint_s: curve.joint_s(),
            curvature_start: curve.signed_curvature_start(),
            curvature_joint: curve.signed_curvature_joint(),
            curvature_end: curve.signed_curvature_end(),
            turning_angle: curve.turning().abs(),
            joint: xy(curve.joint()),
            lcg: curve.lcg().map(|line| line.map(LcgRow::from)),
            points: input.points.clone(),
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }
}

impl Report for CompoundReport {
    fn is_finite(&self) -> bool {
        all_finite([
            self.alpha0,
            self.alpha1,
            self.ratio.unwrap_or(0.0),
            self.lambda,
            self.arc_length,
            self.joint_s,
            self.curvature_start,
            self.curvature_joint,
            self.curvature_end,
            self.turning_angle,
        ]) && all_finite(self.joint)
            && self
                .lcg
                .iter()
                .flatten()
                .all(|l| all_finite([l.alpha, l.intercept, l.log_rho[0], l.log_rho[1]]))
            && all_finite(self.points.iter().flatten().copied())
            && self.samples.iter().all(|s| all_finite(s.values()))
    }
}

/// The name of a monotonicity verdict: `increasing`, `decreasing`, `constant`,
/// `not_monotone`.
pub fn verdict_name(verdict: Monotonicity) -> &'static str {
    match verdict {
        Monotonicity::Increasing => "increasing",
        Monotonicity::Decreasing => "decreasing",
        Monotonicity::Constant => "constant",
        Monotonicity::NotMonotone { .. } => "not_monotone",
    }
}

/// Whether the curvature of a (rational) cubic is monotone: `lac monotone`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MonotoneReport {
    /// `increasing`, `decreasing`, `constant` or `not_monotone`.
    pub verdict: String,
    /// Whether the verdict is proven for the exact curve the numbers describe.
    pub proven: bool,
    /// Not monotone: a parameter where dκ/ds changes sign.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub t: Option<f64>,
}

impl From<&MonotonicityReport> for MonotoneReport {
    fn from(m: &MonotonicityReport) -> Self {
        MonotoneReport {
            verdict: verdict_name(m.verdict).to_string(),
            proven: m.proven,
            t: match m.verdict {
                Monotonicity::NotMonotone { t } => Some(t),
                _ => None,
            },
        }
    }
}

/// One Bézier piece of a [`QuasiReport`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuasiPieceRow {
    /// Control points b0..b3.
    pub points: [Xy; 4],
    /// Weights w0..w3.
    pub weights: [f64; 4],
    /// How its curvature varies: increasing, decreasing, constant, not_monotone.
    pub monotone: String,
    /// Whether `monotone` is proven for the exact curve the numbers describe.
    pub proven: bool,
    /// Not monotone: a parameter where dκ/ds changes sign.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub t: Option<f64>,
    /// The turning of the log-aesthetic curve at the piece's ends, radians from its start.
    pub turning: [f64; 2],
    /// Largest distance to the log-aesthetic curve over the piece, in the points' units.
    pub max_deviation: f64,
}

impl From<&QuasiPiece> for QuasiPieceRow {
    fn from(p: &QuasiPiece) -> Self {
        let m = MonotoneReport::from(&p.monotonicity);
        QuasiPieceRow {
            points: p.curve.points().map(xy),
            weights: p.curve.weights(),
            monotone: m.verdict,
            proven: m.proven,
            t: m.t,
            turning: [p.turning.0, p.turning.1],
            max_deviation: p.max_deviation,
        }
    }
}

/// A quasi-aesthetic replacement: `lac quasi`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuasiReport {
    /// The pieces in order from the first control point.
    pub pieces: Vec<QuasiPieceRow>,
    /// Root mean square deviation, relative to the arc length.
    pub rms: f64,
    /// Largest deviation, relative to the arc length.
    pub max: f64,
    /// Arc length of the log-aesthetic curve.
    pub arc_length: f64,
    /// The tolerance asked for (relative); `null` for the single piece of seed 001.
    pub tolerance: Option<f64>,
    /// `rational`, or `cubic` (all weights 1).
    pub kind: String,
}

impl QuasiReport {
    /// The report of `quasi`, the replacement of a curve of length `arc_length`.
    pub fn new(quasi: &QuasiCurve, arc_length: f64, tolerance: Option<f64>, cubic: bool) -> Self {
        QuasiReport {
            pieces: quasi.pieces.iter().map(QuasiPieceRow::from).collect(),
            rms: quasi.rms,
            max: quasi.max,
            arc_length,
            tolerance,
            kind: if cubic { "cubic" } else { "rational" }.to_string(),
        }
    }
}

impl Report for QuasiReport {
    fn is_finite(&self) -> bool {
        all_finite([self.rms, self.max, self.arc_length])
            && self.pieces.iter().all(|p| {
                all_finite(p.points.iter().flatten().copied())
                    && all_finite(p.weights)
                    && all_finite(p.turning)
                    && p.max_deviation.is_finite()
                    && p.t.is_none_or(f64::is_finite)
            })
    }
}

/// One point of a curvature plot and, where it has one, of the logarithmic curvature graph.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlotRow {
    /// Arc length from the start.
    pub s: f64,
    /// Signed curvature, + for a left turn.
    pub kappa: f64,
    /// dκ/ds.
    pub dkappa_ds: f64,
    /// ln ρ; `null` where κ = 0.
    pub log_rho: Option<f64>,
    /// ln(ρ |ds/dρ|); `null` where κ = 0 or dκ/ds = 0.
    pub log_lcg: Option<f64>,
}

impl From<&CurvaturePoint> for PlotRow {
    fn from(p: &CurvaturePoint) -> Self {
        let graph = p.lcg();
        PlotRow {
            s: p.s,
            kappa: p.kappa,
            dkappa_ds: p.dkappa_ds,
            log_rho: graph.map(|g| g.0),
            log_lcg: graph.map(|g| g.1),
        }
    }
}

/// The line y = alpha x + intercept fitted to a logarithmic curvature graph, over
/// x ∈ log_rho (natural logarithms).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FitRow {
    /// The slope: the α of the log-aesthetic curve that matches best.
    pub alpha: f64,
    /// The value at ln ρ = 0.
    pub intercept: f64,
    /// Root mean square residual, weighted along ln ρ.
    pub rms_residual: f64,
    /// Largest residual.
    pub max_residual: f64,
    /// The range of ln ρ covered.
    pub log_rho: [f64; 2],
}

impl From<&LcgFit> for FitRow {
    fn from(f: &LcgFit) -> Self {
        FitRow {
            alpha: f.alpha,
            intercept: f.intercept,
            rms_residual: f.rms_residual,
            max_residual: f.max_residual,
            log_rho: [f.log_rho.0, f.log_rho.1],
        }
    }
}

/// A curvature plot and logarithmic curvature graph with its fitted line: `lac lcg`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LcgReport {
    /// The plot, equally spaced in arc length (or per Bézier piece).
    pub points: Vec<PlotRow>,
    /// The line fitted to the whole graph; `null` for a circle (no graph) or when the
    /// curvature is not monotone (then `note` says so).
    pub fit: Option<FitRow>,
    /// A curve of several log-aesthetic pieces (a compound curve): each piece's graph with
    /// its own fitted line, in order; absent for one piece and for Bézier pieces.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub pieces: Vec<PieceFitRow>,
    /// `false` when the curvature is not monotone (its graph is not one line, so `fit` is
    /// `null` and `note` says where); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub monotone: Option<bool>,
    /// Why there is no fitted line although the graph has points.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub note: Option<String>,
}

/// Where the middle control point may go: `lac region --format json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RegionReport {
    /// α, or α0 for compound curves.
    pub alpha: f64,
    /// α1 of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha1: Option<f64>,
    /// The turning ratio of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
    /// Pixels per side.
    pub size: usize,
    /// [x_min, x_max, y_min, y_max] of the map.
    pub extent: [f64; 4],
    /// The first control point.
    pub first: Xy,
    /// The last control point.
    pub last: Xy,
    /// The share of the map that is drawable.
    pub drawable_fraction: f64,
    /// Rows top (y = y_max) to bottom, columns left (x = x_min) to right.
    pub drawable: Vec<Vec<bool>>,
}

// ---------------------------------------------------------------------------------------
// Analysis, fits and regions: what the editor's server answers besides the curve

impl LcgReport {
    /// The plot of `plot` (a log-aesthetic curve's [`Curve::curvature_plot`] or a Bézier
    /// chain's [`lac::curvature_plot`]) with the line fitted to its logarithmic curvature
    /// graph ([`lac::log_curvature_graph`]); no line when the plot shows that the curvature
    /// is not monotone ([`LcgReport::of_pieces`] decides that for Bézier pieces with a
    /// proof).
    pub fn new(plot: &[CurvaturePoint]) -> Self {
        let report = LcgReport::fitted(plot);
        match plot_not_monotone(plot) {
            Some(why) => report.not_monotone(why),
            None => report,
        }
    }
}

impl Report for LcgReport {
    fn is_finite(&self) -> bool {
        self.points.iter().all(|p| {
            all_finite([p.s, p.kappa, p.dkappa_ds])
                && p.log_rho.is_none_or(f64::is_finite)
                && p.log_lcg.is_none_or(f64::is_finite)
        }) && self
            .fit
            .iter()
            .chain(self.pieces.iter().filter_map(|p| p.fit.as_ref()))
            .all(|f| {
                all_finite([f.alpha, f.intercept, f.rms_residual, f.max_residual])
                    && all_finite(f.log_rho)
            })
            && self.pieces.iter().all(|p| all_finite(p.s))
    }
}

impl QuasiInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha":A,"tolerance":T,"cubic":false} (or a compound curve's fields instead of "alpha")"#;

    /// Solve the curve and replace it by Bézier pieces: the seed's single rational cubic
    /// without a tolerance, else rational (or, with `cubic`, plain) cubics within
    /// `tolerance` × arc length.
    pub fn solve(&self) -> Result<(Solved, QuasiCurve), ErrorBody> {
        let solved = self.curve.solve()?;
        let quasi = match (&solved, self.tolerance, self.cubic) {
            (Solved::Segment(s), None, _) => s.to_rational_cubic(),
            (Solved::Segment(s), Some(t), false) => s.to_rational_cubics(Tolerance::Relative(t)),
            (Solved::Segment(s), Some(t), true) => s.to_cubics(Tolerance::Relative(t)),
            (Solved::Compound(c), None, _) => c.to_rational_cubic(),
            (Solved::Compound(c), Some(t), false) => c.to_rational_cubics(Tolerance::Relative(t)),
            (Solved::Compound(c), Some(t), true) => c.to_cubics(Tolerance::Relative(t)),
        }?;
        Ok((solved, quasi))
    }
}

/// Where the middle control point may go: the request of [`RegionReport`],
/// `{"alpha":A}` for segments or `{"alpha":A0,"alpha1":A1,"ratio":R}` for compound curves,
/// with the map's pixels per side.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RegionInput {
    /// α, or α0 for compound curves.
    pub alpha: f64,
    /// α1 of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha1: Option<f64>,
    /// The turning ratio of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
    /// Pixels per side (a front end's default when absent).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub size: Option<usize>,
}

impl RegionInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"alpha":A,"size":N} or {"alpha":A0,"alpha1":A1,"ratio":R,"size":N}"#;

    /// Check the parameters, for which every pixel would otherwise be "not drawable" for a
    /// reason the map does not show: finite slopes, α1 and the ratio given together, and
    /// 0 < ratio < 1.
    pub fn check(&self) -> Result<(), ErrorBody> {
        let finite = |what: &'static str, value: f64| {
            if value.is_finite() {
                Ok(())
            } else {
                Err(ErrorBody::from(lac::Error::NonFinite { what, value }))
            }
        };
        match (self.alpha1, self.ratio) {
            (None, None) => finite("alpha", self.alpha),
            (Some(alpha1), Some(ratio)) => {
                finite("alpha0", self.alpha)?;
                finite("alpha1", alpha1)?;
                finite("ratio", ratio)?;
                if ratio > 0.0 && ratio < 1.0 {
                    Ok(())
                } else {
                    Err(ErrorBody::from(lac::Error::OutOfRange {
                        name: "ratio",
                        value: ratio,
                        expected: "a share of the turning strictly between 0 and 1",
                    }))
                }
            }
            _ => Err(ErrorBody::invalid_input(
                "a compound curve's region needs both alpha1 and ratio; a segment's neither",
            )),
        }
    }

    /// One row of the map (row 0 at y = +1): [`lac::region::row`] or
    /// [`lac::region::compound_row`].
    pub fn row(&self, size: usize, row: usize) -> Vec<bool> {
        match self.alpha1.zip(self.ratio) {
            None => lac::region::row(self.alpha, size, row),
            Some((alpha1, ratio)) => {
                lac::region::compound_row(self.alpha, alpha1, ratio, size, row)
            }
        }
    }

    /// The whole map, its [`lac::region::top_rows`] computed by `map_rows` (a front end's
    /// serial or parallel map over row indices, calling [`RegionInput::row`]) and mirrored.
    pub fn rows(
        &self,
        size: usize,
        map_rows: impl FnOnce(usize) -> Vec<Vec<bool>>,
    ) -> Vec<Vec<bool>> {
        lac::region::mirror_rows(size, map_rows(lac::region::top_rows(size)))
    }

    /// The report of the rows computed by [`RegionInput::row`].
    pub fn report(&self, size: usize, drawable: Vec<Vec<bool>>) -> RegionReport {
        let count: usize = drawable.iter().flatten().filter(|&&d| d).count();
        RegionReport {
            alpha: self.alpha,
            alpha1: self.alpha1,
            ratio: self.ratio,
            size,
            extent: [-1.0, 1.0, -1.0, 1.0],
            first: xy(lac::region::FIRST),
            last: xy(lac::region::LAST),
            drawable_fraction: count as f64 / (size * size).max(1) as f64,
            drawable,
        }
    }
}

/// Where one control point of a curve may go, the others staying put:
/// `{"curve":{…a segment or compound curve…},"index":I,"extent":[x0,x1,y0,y1],"size":N}`.
/// For the middle point of a segment or a three-point compound curve the canonical
/// [`RegionReport`] says the same for every placement of the ends; for the four-point
/// compound curve, whose regions depend on all four points, this is the map.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointRegionInput {
    /// The curve as it is now.
    pub curve: CurveInput,
    /// Which of its control points moves (0-based).
    pub index: usize,
    /// [x_min, x_max, y_min, y_max] of the map, in the curve's coordinates.
    pub extent: [f64; 4],
    /// Pixels per side (a front end's default when absent).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub size: Option<usize>,
}

impl PointRegionInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"curve":{"points":[…],"alpha0":A,"alpha1":B},"index":I,"extent":[x_min,x_max,y_min,y_max],"size":N}"#;

    /// Check the index and the extent (finite, non-empty).
    pub fn check(&self) -> Result<(), ErrorBody> {
        let count = self.curve.points().len();
        if self.index >= count {
            return Err(ErrorBody::invalid_input(format!(
                "index {} names no control point: the curve has {count} (0 to {})",
                self.index,
                count - 1
            )));
        }
        let [x0, x1, y0, y1] = self.extent;
        if !(all_finite(self.extent) && x0 < x1 && y0 < y1) {
            return Err(ErrorBody::invalid_input(
                "extent must be [x_min, x_max, y_min, y_max], finite, with x_min < x_max and \
                 y_min < y_max",
            ));
        }
        Ok(())
    }

    /// The centre of pixel (`row`, `col`) of a `size`×`size` map of the extent; row 0 is
    /// the top (y = y_max), column 0 the left (x = x_min).
    pub fn pixel_center(&self, size: usize, row: usize, col: usize) -> Xy {
        let [x0, x1, y0, y1] = self.extent;
        let n = size as f64;
        [
            x0 + (col as f64 + 0.5) * (x1 - x0) / n,
            y1 - (row as f64 + 0.5) * (y1 - y0) / n,
        ]
    }

    /// One row of the map: `true` where the curve is drawable with the point moved to the
    /// pixel's centre.
    pub fn row(&self, size: usize, row: usize) -> Vec<bool> {
        let mut curve = self.curve.clone();
        (0..size)
            .map(|col| {
                let at = self.pixel_center(size, row, col);
                match &mut curve {
                    CurveInput::Segment(s) => s.points[self.index] = at,
                    CurveInput::Compound(c) => c.points[self.index] = at,
                }
                curve.solve().is_ok()
            })
            .collect()
    }

    /// The report of the rows computed by [`PointRegionInput::row`].
    pub fn report(&self, size: usize, drawable: Vec<Vec<bool>>) -> PointRegionReport {
        let count: usize = drawable.iter().flatten().filter(|&&d| d).count();
        PointRegionReport {
            index: self.index,
            size,
            extent: self.extent,
            drawable_fraction: count as f64 / (size * size).max(1) as f64,
            drawable,
        }
    }
}

/// Where one control point may go ([`PointRegionInput`]): pixels whose centre gives a
/// drawable curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointRegionReport {
    /// Which control point moves.
    pub index: usize,
    /// Pixels per side.
    pub size: usize,
    /// [x_min, x_max, y_min, y_max] of the map.
    pub extent: [f64; 4],
    /// The share of the map that is drawable.
    pub drawable_fraction: f64,
    /// Rows top (y = y_max) to bottom, columns left (x = x_min) to right.
    pub drawable: Vec<Vec<bool>>,
}

// ---------------------------------------------------------------------------------------
// Space curves (seed 003): `lac space`'s JSON and the editor's

/// A 3-D point, `[x, y, z]`.
pub type Xyz = [f64; 3];

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

// ---------------------------------------------------------------------------------------
// The command line's shapes (wt-cli): what `lac lcg` and `lac monotone` read, the graphs of
// a compound curve's pieces and of a space curve, and the verdicts of a chain of pieces

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

/// One log-aesthetic piece's logarithmic curvature graph with its own fitted line, for a
/// curve of several pieces (`lac lcg` of a compound curve).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PieceFitRow {
    /// The piece's arc lengths, [from, to], along the whole curve.
    pub s: [f64; 2],
    /// The line fitted to the piece's graph (its α); `null` for a circular arc.
    pub fit: Option<FitRow>,
}

impl LcgReport {
    /// The plot of a planar log-aesthetic curve at `n` points equally spaced in arc length,
    /// with the line fitted to the whole graph and, for a curve of several pieces, each
    /// piece's line (fitted to `n` points of its own, so that a short piece is measured as
    /// well as a long one).
    pub fn of_curve(curve: &dyn SegmentChain, n: usize) -> Result<Self, ErrorBody> {
        let mut report = LcgReport::new(&curve.curvature_plot(n)?);
        let pieces = curve.pieces();
        if pieces.len() > 1 {
            let ends: Vec<f64> = curve
                .joint_arc_lengths()
                .into_iter()
                .chain([curve.arc_length()])
                .collect();
            let mut start = 0.0;
            for (piece, &end) in pieces.iter().zip(&ends) {
                let graph = lac::log_curvature_graph(&piece.curvature_plot(n)?);
                report.pieces.push(PieceFitRow {
                    s: [start, end],
                    fit: graph.fit.as_ref().map(FitRow::from),
                });
                start = end;
            }
        }
        report.checked()
    }

    /// The plot of a chain of (rational) cubic Bézier pieces, `per_piece` points a piece
    /// equally spaced in t, with the line fitted to its graph; no line when the curvature
    /// is not monotone, which is decided with each piece's proven verdict
    /// ([`RationalCubic::curvature_monotonicity`]), the directions of consecutive pieces and
    /// the jumps at their joints, and the sign of the curvature (an inflection).
    pub fn of_pieces(pieces: &[RationalCubic], per_piece: usize) -> Result<Self, ErrorBody> {
        let plot = lac::curvature_plot(pieces, per_piece)?;
        let verdicts = pieces
            .iter()
            .map(RationalCubic::curvature_monotonicity)
            .collect::<lac::Result<Vec<_>>>()?;
        let report = LcgReport::fitted(&plot);
        let why = chain_not_monotone(pieces, &verdicts).or_else(|| inflection(&plot));
        match why {
            Some(why) => report.not_monotone(why),
            None => report,
        }
        .checked()
    }

    /// The plot and the line fitted to its graph, unchecked.
    fn fitted(plot: &[CurvaturePoint]) -> Self {
        LcgReport {
            points: plot.iter().map(PlotRow::from).collect(),
            fit: lac::log_curvature_graph(plot)
                .fit
                .as_ref()
                .map(FitRow::from),
            pieces: Vec::new(),
            monotone: None,
            note: None,
        }
    }

    /// The report without its line, saying `why` the curvature is not monotone.
    fn not_monotone(self, why: String) -> Self {
        LcgReport {
            fit: None,
            monotone: Some(false),
            note: Some(format!(
                "the curvature is not monotone ({why}), so its logarithmic curvature graph \
                 is not one line and no slope alpha is fitted"
            )),
            ..self
        }
    }
}

/// The plot's dκ/ds (or κ) counts as zero where it is below this share of its scale: the
/// rounding of a circular arc's exact zero is far below it, a real change of sign far above.
const PLOT_ZERO: f64 = 1e-9;

/// Why the curvature of a sampled plot is not monotone, if it shows that: dκ/ds, made
/// dimensionless by the plot's length and largest curvature, takes both signs beyond
/// [`PLOT_ZERO`], or the curvature itself does.
fn plot_not_monotone(plot: &[CurvaturePoint]) -> Option<String> {
    let (first, last) = (plot.first()?, plot.last()?);
    let length = (last.s - first.s).abs();
    let kmax = plot.iter().fold(0.0f64, |m, p| m.max(p.kappa.abs()));
    if !(length > 0.0 && length.is_finite() && kmax > 0.0 && kmax.is_finite()) {
        return None;
    }
    let scale = length / kmax;
    let mut sign = None;
    for p in plot {
        let d = p.dkappa_ds * scale;
        // NaN counts as zero: it shows no direction.
        if d.is_nan() || d.abs() <= PLOT_ZERO {
            continue;
        }
        match sign {
            None => sign = Some(d > 0.0),
            Some(up) if up != (d > 0.0) => {
                return Some(format!("dκ/ds changes sign near s = {}", short(p.s)))
            }
            _ => {}
        }
    }
    inflection(plot)
}

/// Where the curvature of a plot changes sign (beyond [`PLOT_ZERO`] of its largest value).
fn inflection(plot: &[CurvaturePoint]) -> Option<String> {
    let kmax = plot.iter().fold(0.0f64, |m, p| m.max(p.kappa.abs()));
    let mut sign = None;
    for p in plot {
        if p.kappa.is_nan() || p.kappa.abs() <= PLOT_ZERO * kmax {
            continue;
        }
        match sign {
            None => sign = Some(p.kappa > 0.0),
            Some(left) if left != (p.kappa > 0.0) => {
                return Some(format!(
                    "the curvature changes sign near s = {}, an inflection",
                    short(p.s)
                ))
            }
            _ => {}
        }
    }
    None
}

/// Why the curvature of a chain of pieces with these verdicts is not monotone: a piece's is
/// proven not to be, two pieces' are proven to run in opposite directions, or it jumps the
/// wrong way at a joint.
fn chain_not_monotone(pieces: &[RationalCubic], verdicts: &[MonotonicityReport]) -> Option<String> {
    let n = pieces.len();
    let way = |up: bool| if up { "increases" } else { "decreases" };
    // The direction so far, and the piece that set it.
    let mut direction: Option<(bool, usize)> = None;
    let mut follow = |up: bool, k: usize, what: &str| match direction {
        None => {
            direction = Some((up, k));
            None
        }
        Some((was, j)) if was != up => Some(format!(
            "it {} along piece {} of {n} and {} {what}",
            way(was),
            j + 1,
            way(up)
        )),
        _ => None,
    };
    for (k, v) in verdicts.iter().enumerate() {
        if k > 0 {
            let (before, after) = (
                pieces[k - 1].signed_curvature(1.0),
                pieces[k].signed_curvature(0.0),
            );
            let jump = after - before;
            if jump.abs() > PLOT_ZERO * before.abs().max(after.abs()) {
                let at = format!("at the joint of pieces {k} and {}", k + 1);
                if let Some(why) = follow(jump > 0.0, k, &at) {
                    return Some(why);
                }
            }
        }
        // An unproven verdict is dκ/ds zero within rounding (a circular arc): no direction.
        if !v.proven {
            continue;
        }
        match v.verdict {
            Monotonicity::NotMonotone { t } => {
                return Some(format!(
                    "dκ/ds changes sign inside piece {} of {n}, at t = {}",
                    k + 1,
                    short(t)
                ))
            }
            Monotonicity::Constant => {}
            Monotonicity::Increasing | Monotonicity::Decreasing => {
                let up = v.verdict == Monotonicity::Increasing;
                let along = format!("along piece {}", k + 1);
                if let Some(why) = follow(up, k, &along) {
                    return Some(why);
                }
            }
        }
    }
    None
}

/// A number with six significant digits at most, for messages.
pub fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        let text = format!("{x:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (5.0 - magnitude) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
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

/// What `lac lcg` reads: Bézier pieces (`lac quasi` output, [`PiecesInput`]), a planar
/// curve (`lac segment` or `lac compound` output, [`CurveInput`]) or a space curve (`lac
/// space` output, [`SpaceInput`]), told apart by their keys: `"pieces"`, `"beta"`,
/// `"alpha0"`/`"alpha1"`, `"alpha"`.
#[derive(Clone, Debug, PartialEq)]
pub enum LcgInput {
    /// A chain of (rational) cubic Bézier pieces.
    Pieces(PiecesInput),
    /// A planar log-aesthetic curve, solved again from its points and slopes.
    Curve(CurveInput),
    /// A space curve, solved again from its points and parameters.
    Space(SpaceInput),
}

impl LcgInput {
    /// The shapes, for error messages.
    pub const SHAPE: &'static str = r#"{"pieces":[{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]},…]} (weights optional; lac quasi output), a lac segment result {"points":[[x,y]×3],"alpha":A,…}, a lac compound result {"points":[…3 or 4…],"alpha0":A,"alpha1":B,"ratio":R,…} or a lac space result {"points":[[x,y,z]×4],"alpha":A,"beta":B,"omega":W,"type":1,…}"#;

    /// Read one document.
    pub fn parse(text: &str) -> Result<LcgInput, ErrorBody> {
        let value: serde_json::Value = parse(text, Self::SHAPE)?;
        let has = |key: &str| value.get(key).is_some();
        let read = |what: &str, e: serde_json::Error| {
            ErrorBody::invalid_input(format!("{what}: {e}; expected {}", Self::SHAPE))
        };
        if has("pieces") {
            let input = serde_json::from_value(value).map_err(|e| read("Bézier pieces", e))?;
            Ok(LcgInput::Pieces(input))
        } else if has("beta") {
            let input = serde_json::from_value(value).map_err(|e| read("a space curve", e))?;
            Ok(LcgInput::Space(input))
        } else if has("alpha0") || has("alpha1") {
            let input = serde_json::from_value(value).map_err(|e| read("a compound curve", e))?;
            Ok(LcgInput::Curve(CurveInput::Compound(input)))
        } else if has("alpha") {
            let input = serde_json::from_value(value).map_err(|e| read("a segment", e))?;
            Ok(LcgInput::Curve(CurveInput::Segment(input)))
        } else {
            Err(ErrorBody::invalid_input(format!(
                "no \"pieces\", \"alpha\", \"alpha0\" or \"beta\" in the input; expected {}",
                Self::SHAPE
            )))
        }
    }
}

/// What `lac monotone` reads as one document (or one `--batch` line): one piece
/// ([`PieceInput`]) or a chain of them ([`PiecesInput`], what `lac quasi` prints).
#[derive(Clone, Debug, PartialEq)]
pub enum MonotoneDocument {
    /// One (rational) cubic.
    Piece(PieceInput),
    /// A chain: a verdict for each piece.
    Pieces(PiecesInput),
}

impl MonotoneDocument {
    /// The shapes, for error messages.
    pub const SHAPE: &'static str = r#"{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]} (weights optional) or {"pieces":[…such pieces…]} (lac quasi output)"#;

    /// Read one document.
    pub fn parse(text: &str) -> Result<MonotoneDocument, ErrorBody> {
        let value: serde_json::Value = parse(text, Self::SHAPE)?;
        let pieces = value.get("pieces").is_some();
        let document = if pieces {
            serde_json::from_value(value).map(MonotoneDocument::Pieces)
        } else {
            serde_json::from_value(value).map(MonotoneDocument::Piece)
        };
        document.map_err(|e| ErrorBody::invalid_input(format!("{e}; expected {}", Self::SHAPE)))
    }

    /// Its verdicts as one line of JSON: a [`MonotoneReport`] or a [`MonotonePiecesReport`].
    pub fn report_line(&self) -> Result<String, ErrorBody> {
        match self {
            MonotoneDocument::Piece(piece) => Ok(to_line(&MonotoneReport::of(piece)?)),
            MonotoneDocument::Pieces(pieces) => Ok(to_line(&MonotonePiecesReport::new(pieces)?)),
        }
    }
}

impl MonotoneReport {
    /// The verdict on one piece.
    pub fn of(piece: &PieceInput) -> Result<Self, ErrorBody> {
        let verdict = piece.to_rational_cubic()?.curvature_monotonicity()?;
        MonotoneReport::from(&verdict).checked()
    }
}

impl Report for MonotoneReport {
    fn is_finite(&self) -> bool {
        self.t.is_none_or(f64::is_finite)
    }
}

/// The verdict on each piece of a chain: `{"pieces":[{"verdict":…,"proven":…},…]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MonotonePiecesReport {
    /// One verdict a piece, in order.
    pub pieces: Vec<MonotoneReport>,
}

impl MonotonePiecesReport {
    /// The verdict on each piece of `input`.
    pub fn new(input: &PiecesInput) -> Result<Self, ErrorBody> {
        if input.pieces.is_empty() {
            return Err(ErrorBody::invalid_input("no pieces given"));
        }
        let pieces = input
            .pieces
            .iter()
            .map(MonotoneReport::of)
            .collect::<Result<Vec<_>, _>>()?;
        MonotonePiecesReport { pieces }.checked()
    }
}

impl Report for MonotonePiecesReport {
    fn is_finite(&self) -> bool {
        self.pieces.iter().all(MonotoneReport::is_finite)
    }
}

// ---------------------------------------------------------------------------------------
// Paths from a control polygon (issue 15)

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
    /// The relative curvature jump measured at each joint.
    pub curvature_jumps: Vec<f64>,
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
            samples: samples.iter().map(SampleRow::from).collect(),
        }
        .checked()
    }

    /// The samples as CSV (`s,x,y,theta,kappa`).
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

impl Report for SplineReport {
    fn is_finite(&self) -> bool {
        all_finite([self.arc_length, self.max_curvature_jump, self.alpha])
            && all_finite(self.points.iter().flatten().copied())
            && all_finite(self.angles.iter().copied())
            && all_finite(self.curvature_jumps.iter().copied())
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

    /// The samples as CSV (`s,x,y,theta,kappa`).
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The scan's number against the standard library's reading of the same token, and
    /// JSON's grammar: on edge cases of the fast paths (2^53, 10^22, 19 digits, zeros, near
    /// ties) and on 200,000 random tokens of every length and exponent.
    #[test]
    fn numbers_are_read_correctly_rounded_and_only_in_json_grammar() {
        let read = |token: &str| {
            let mut scan = Scan {
                text: token.as_bytes(),
                source: token,
                pos: 0,
            };
            scan.number().filter(|_| scan.pos == token.len())
        };
        let check = |token: &str| {
            let want = token.parse::<f64>().ok().filter(|x| x.is_finite());
            let got = read(token);
            assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "{token}");
        };
        for token in [
            "0",
            "-0",
            "0.0",
            "-0.0e5",
            "0e-400",
            "1",
            "-1.0",
            "9007199254740992",
            "9007199254740993",
            "9007199254740994",
            "9007199254740995",
            "1e22",
            "1e23",
            "9007199254740993e22",
            "4.9e-324",
            "2.2250738585072011e-308",
            "1.7976931348623157e308",
            "1e-22",
            "123456789012345678901234567890",
            "1234567890123456789e-19",
            "12345678901234567890",
            "0.10000000000000000555",
            "0.1000000000000000055511151231257827",
            "416.4634885398515",
            "-47.60845231828477",
            "0.0037720556121437544",
            "1E+2",
            "1e-2",
            // Just above a tie in the 128-bit division: only its remainder rounds them up.
            "5.51591418255067234",
            "5.524963189587341450",
            "3.204061910968816429",
            "6.611647786041852104",
        ] {
            check(token);
        }
        for (text, value) in [
            ("00000000", 0),
            ("12345678", 12_345_678),
            ("99999999", 99_999_999),
        ] {
            assert_eq!(eight_digits(text.as_bytes()), Some(value));
        }
        for text in ["1234567a", "/2345678", ":2345678", "1234 678", "1234567"] {
            assert_eq!(eight_digits(text.as_bytes()), None, "{text}");
        }
        for bad in [
            "", "-", "+1", "01", "-01", ".5", "1.", "1e", "1e+", "inf", "NaN", "1e400", "-2e308",
        ] {
            assert_eq!(read(bad), None, "{bad}");
        }
        // xorshift64*: tokens of 1–25 digits, a point anywhere, exponents to ±330.
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            state.wrapping_mul(0x2545_F491_4F6C_DD1D)
        };
        for _ in 0..200_000 {
            let count = 1 + (next() % 25) as usize;
            let mut digits: String = (0..count)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            if digits.len() > 1 && digits.starts_with('0') {
                digits.replace_range(0..1, "1");
            }
            let mut token = if next() % 2 == 0 {
                "-".to_string()
            } else {
                String::new()
            };
            let point = (next() % (count as u64 + 1)) as usize;
            if point > 0 && point < count {
                token.push_str(&digits[..point]);
                token.push('.');
                token.push_str(&digits[point..]);
            } else {
                token.push_str(&digits);
            }
            match next() % 3 {
                0 => {}
                1 => token.push_str(&format!("e{}", (next() % 45) as i64 - 22)),
                _ => token.push_str(&format!("e{}", (next() % 661) as i64 - 330)),
            }
            check(&token);
        }
    }

    #[test]
    fn segment_reports_are_written_byte_for_byte_as_serde_json_writes_them() {
        let seg = Segment::from_control_points(
            [
                Point::new(0.0, 0.0),
                Point::new(3.0, 0.0),
                Point::new(4.0, 1.5),
            ],
            -1.0,
        )
        .unwrap();
        let mut report = SegmentReport::new(&seg, 5).unwrap();
        for extra in [0.0, -0.0, 1e-300, 123456789.0, f64::NAN, f64::INFINITY] {
            report.samples[1].theta = extra;
            report.lambda = -extra;
            let mut out = b"prefix".to_vec();
            report.write_json(&mut out);
            assert_eq!(
                std::str::from_utf8(&out[6..]).unwrap(),
                serde_json::to_string(&report).unwrap()
            );
        }
        report.samples.clear();
        let mut out = Vec::new();
        report.write_json(&mut out);
        assert_eq!(out, serde_json::to_vec(&report).unwrap());
    }

    #[test]
    fn segment_lines_read_by_the_scan_are_what_serde_json_reads() {
        let lines = [
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":-1}"#,
            r#" { "points" : [ [ -1.5e-3 , 0.0 ] , [0.2, 8E+2], [1e400, -0] ] , "alpha": 0.5 }  "#,
            r#"{"points": [[-1.0, 0.0], [0.30000000000000004, 0.1], [1, 0]], "alpha": -0}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":12345678901234567890123}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":2.4703282292062328e-324}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":-1,"extra":1}"#,
            r#"{"alpha":-1,"points":[[-1,0],[0.2,0.8],[1,0]]}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":01}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":1.}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":.5}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":+1}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":NaN}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":inf}"#,
            r#"{"points":[[-1,0],[0.2,0.8]],"alpha":1}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":1}x"#,
            r#"{"po\u0069nts":[[-1,0],[0.2,0.8],[1,0]],"alpha":1}"#,
            "",
            "  ",
        ];
        for line in lines {
            let scanned = SegmentInput::parse_line(line);
            let serde = parse::<SegmentInput>(line, SegmentInput::SHAPE);
            match (scanned, serde) {
                (Ok(a), Ok(b)) => {
                    let bits = |i: &SegmentInput| {
                        (i.points.map(|p| p.map(f64::to_bits)), i.alpha.to_bits())
                    };
                    assert_eq!(bits(&a), bits(&b), "{line}");
                }
                (Err(a), Err(b)) => assert_eq!(a, b, "{line}"),
                (a, b) => panic!("{line}: {a:?} against {b:?}"),
            }
        }
        assert!(scan_segment_input(lines[0]).is_some());
        assert!(scan_segment_input(lines[1]).is_none(), "1e400 overflows");
        assert!(scan_segment_input(lines[2]).is_some());
    }

    #[test]
    fn a_segment_report_reads_back_as_its_input() {
        let input: SegmentInput = parse(
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":0.5}"#,
            SegmentInput::SHAPE,
        )
        .unwrap();
        let report = SegmentReport::new(&input.solve().unwrap(), 5)
            .unwrap()
            .with_points(input.points);
        let line = to_line(&report);
        let back: CurveInput = parse(&line, "a curve").unwrap();
        assert_eq!(back, CurveInput::Segment(input));
    }

    #[test]
    fn errors_carry_the_library_kind_in_snake_case() {
        let input = SegmentInput {
            points: [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]],
            alpha: 0.5,
        };
        let err = input.solve().unwrap_err();
        assert_eq!(err.kind, "collinear_points");
        assert_eq!(err.class(), ErrorClass::Invalid);
        let far = SegmentInput {
            points: [[-1.0, 0.0], [0.9, 0.9], [1.0, 0.0]],
            alpha: -1.0,
        };
        let err = far.solve().unwrap_err();
        assert_eq!(
            (err.kind.as_str(), err.class()),
            ("not_drawable", ErrorClass::Undrawable)
        );
        assert!(err
            .to_json_line()
            .starts_with(r#"{"error":{"kind":"not_drawable","message":"#));
    }

    #[test]
    fn compound_inputs_say_what_is_missing() {
        let three = CompoundInput {
            points: vec![[0.0, 0.0], [2.0, 0.0], [2.6, 1.2]],
            alpha0: -1.0,
            alpha1: 2.0,
            ratio: None,
        };
        assert!(three.solve().unwrap_err().message.contains("ratio"));
        let curve = CompoundInput {
            ratio: Some(0.5),
            ..three
        };
        let report = CompoundReport::new(&curve.solve().unwrap(), &curve, 9).unwrap();
        assert_eq!(report.samples.len(), 9);
        assert!(report.is_finite());
    }

    #[test]
    fn the_plot_of_a_segment_fits_its_own_alpha() {
        let input = SegmentInput {
            points: [[0.0, 0.0], [1.0, 0.0], [1.6, 0.9]],
            alpha: 0.5,
        };
        let report = LcgReport::new(&input.solve().unwrap().curvature_plot(65).unwrap());
        assert_eq!(report.points.len(), 65);
        let fit = report.fit.as_ref().unwrap();
        assert!((fit.alpha - 0.5).abs() < 1e-9, "{}", fit.alpha);
        assert!(report.is_finite());
    }

    #[test]
    fn a_quasi_input_fits_within_its_tolerance() {
        let input: QuasiInput = parse(
            r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-5}"#,
            QuasiInput::SHAPE,
        )
        .unwrap();
        let (solved, quasi) = input.solve().unwrap();
        assert!(quasi.max <= 1e-5);
        let report = QuasiReport::new(&quasi, solved.curve().arc_length(), input.tolerance, false);
        assert!(report.is_finite() && !report.pieces.is_empty());
    }

    #[test]
    fn region_rows_are_the_library_rows_and_a_moved_middle_point_agrees() {
        let input = RegionInput {
            alpha: -1.0,
            alpha1: None,
            ratio: None,
            size: None,
        };
        input.check().unwrap();
        let rows: Vec<Vec<bool>> = (0..16).map(|r| input.row(16, r)).collect();
        assert_eq!(rows[3], lac::region::row(-1.0, 16, 3));
        let report = input.report(16, rows.clone());
        assert!(report.drawable_fraction > 0.0 && report.drawable_fraction < 1.0);
        // The same map as the region of point 1 of a segment from (-1,0) to (1,0).
        let moved = PointRegionInput {
            curve: CurveInput::Segment(SegmentInput {
                points: [[-1.0, 0.0], [0.0, 0.5], [1.0, 0.0]],
                alpha: -1.0,
            }),
            index: 1,
            extent: [-1.0, 1.0, -1.0, 1.0],
            size: Some(16),
        };
        moved.check().unwrap();
        let moved_rows: Vec<Vec<bool>> = (0..16).map(|r| moved.row(16, r)).collect();
        assert_eq!(moved_rows, rows);
        let bad = RegionInput {
            ratio: Some(1.0),
            alpha1: Some(2.0),
            ..input
        };
        assert_eq!(bad.check().unwrap_err().kind, "out_of_range");
        let far = PointRegionInput { index: 3, ..moved };
        assert!(far.check().unwrap_err().message.contains("index 3"));
    }

    #[test]
    fn lcg_reports_fit_each_piece_and_refuse_a_line_when_the_curvature_is_not_monotone() {
        let compound = CompoundInput {
            points: vec![[0.0, 0.0], [2.0, 0.0], [2.5, 2.0], [0.0, 1.5]],
            alpha0: -1.0,
            alpha1: 2.0,
            ratio: None,
        };
        let curve = compound.solve().unwrap();
        let report = LcgReport::of_curve(&curve, 65).unwrap();
        let slopes: Vec<f64> = report
            .pieces
            .iter()
            .map(|p| p.fit.as_ref().unwrap().alpha)
            .collect();
        assert!((slopes[0] + 1.0).abs() < 1e-9 && (slopes[1] - 2.0).abs() < 1e-9);
        assert_eq!(report.pieces[1].s[1], curve.arc_length());
        assert!(report.fit.is_some() && report.monotone.is_none());
        // An S-shaped cubic: dκ/ds changes sign, so there is no line.
        let s_curve = PieceInput {
            points: [[0.0, 0.0], [1.0, 1.0], [2.0, -1.0], [3.0, 0.0]],
            weights: None,
        };
        let cubic = s_curve.to_rational_cubic().unwrap();
        let report = LcgReport::of_pieces(&[cubic], 64).unwrap();
        assert_eq!((report.fit.is_none(), report.monotone), (true, Some(false)));
        assert!(report.note.unwrap().contains("piece 1 of 1"));
        assert!(
            to_line(&LcgReport::of_pieces(&[cubic], 8).unwrap()).contains(r#""monotone":false"#)
        );
    }

    #[test]
    fn lcg_inputs_are_told_apart_by_their_keys() {
        let kinds: Vec<&str> = [
            r#"{"pieces":[{"points":[[0,0],[1,0],[2,1],[3,3]]}]}"#,
            r#"{"points":[[0,0],[1,0],[2,1]],"alpha":0.5}"#,
            r#"{"points":[[0,0],[1,0],[2,1]],"alpha0":0.5,"alpha1":1,"ratio":0.5}"#,
            r#"{"points":[[0,0,0],[1,0,0],[2,1,0],[2,2,1]],"alpha":0.5,"beta":0}"#,
        ]
        .iter()
        .map(|text| match LcgInput::parse(text).unwrap() {
            LcgInput::Pieces(_) => "pieces",
            LcgInput::Curve(CurveInput::Segment(_)) => "segment",
            LcgInput::Curve(CurveInput::Compound(_)) => "compound",
            LcgInput::Space(_) => "space",
        })
        .collect();
        assert_eq!(kinds, ["pieces", "segment", "compound", "space"]);
        let err = LcgInput::parse(r#"{"curve":1}"#).unwrap_err();
        assert_eq!(err.kind, "invalid_input");
    }

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

    #[test]
    fn short_numbers_keep_six_significant_digits() {
        assert_eq!(short(0.30000000000000004), "0.3");
        assert_eq!(short(-2.345678901), "-2.34568");
        assert_eq!(short(1.7e308), "1.7e308");
        assert_eq!(short(1.5e-7), "1.5e-7");
        assert_eq!(short(0.0), "0");
    }
}
