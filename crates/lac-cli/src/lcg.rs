//! `lac lcg`: the curvature plot and the logarithmic curvature graph (LCG) of Bézier pieces
//! or of a log-aesthetic curve, with the slope α of the line fitted to the graph (seed 001
//! §6, SPEC §1), as JSON, CSV, SVG or PNG.
//!
//! The input is one JSON document: `{"pieces":[{"points":[[x,y]×4],"weights":[…]},…]}`
//! (what `lac quasi` prints), or one result of `lac segment` or `lac compound`, which is
//! solved again from its points and slopes.

use std::io::{self, IsTerminal, Read};
use std::path::Path;

use kurbo::Point;
use lac::{curvature_plot, log_curvature_graph, CurvaturePoint, LcgFit, RationalCubic, Segment};
use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::cli::{LcgArgs, LcgFormat};
use crate::compound::{self, Misfit};
use crate::curve::Lac;
use crate::failure::Failure;
use crate::output::write_to;
use crate::raster;
use crate::svg;

/// The shapes of the input, for error messages.
const SHAPES: &str = r#"{"pieces":[{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]},…]} (weights optional), a lac segment result {"alpha":A,"points":[[x,y],[x,y],[x,y]],…} or a lac compound result {"alpha0":A,"alpha1":B,"points":[…3 or 4…],"ratio":R,…}"#;

/// Curvature points per Bézier piece when `--samples` is not given.
const PER_PIECE: usize = 64;
/// Curvature points along a log-aesthetic curve when `--samples` is not given.
const ALONG_CURVE: usize = 257;

/// `{"pieces":[…]}`.
#[derive(Debug, Deserialize)]
struct PiecesInput {
    pieces: Vec<PieceInput>,
}

/// One Bézier piece; fields other than these (as in `lac quasi` output) are ignored.
#[derive(Debug, Deserialize)]
struct PieceInput {
    points: [[f64; 2]; 4],
    weights: Option<[f64; 4]>,
}

/// A `lac segment` result; only the fields it is solved from.
#[derive(Debug, Deserialize)]
struct SegmentInput {
    alpha: f64,
    points: Vec<[f64; 2]>,
}

/// A `lac compound` result; only the fields it is solved from.
#[derive(Debug, Deserialize)]
struct CompoundInput {
    alpha0: f64,
    alpha1: f64,
    ratio: Option<f64>,
    points: Vec<[f64; 2]>,
}

/// What the input describes.
enum Input {
    /// A chain of (rational) cubic Bézier pieces.
    Bezier(Vec<RationalCubic>),
    /// A log-aesthetic curve.
    Curve(Box<Lac>),
}

/// What `lac lcg --format json` prints.
#[derive(Debug, Serialize)]
struct LcgReport {
    points: Vec<PlotRow>,
    fit: Option<FitRow>,
}

/// One point of the curvature plot and, where it has one, of the graph.
#[derive(Debug, Serialize)]
struct PlotRow {
    /// Arc length from the start.
    s: f64,
    /// Signed curvature, + for a left turn.
    kappa: f64,
    /// dκ/ds.
    dkappa_ds: f64,
    /// ln ρ; `null` where κ = 0.
    log_rho: Option<f64>,
    /// ln(ρ |ds/dρ|); `null` where κ = 0 or dκ/ds = 0.
    log_lcg: Option<f64>,
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

/// The fitted line y = alpha x + intercept over x ∈ log_rho (natural logarithms).
#[derive(Debug, Serialize)]
struct FitRow {
    alpha: f64,
    intercept: f64,
    rms_residual: f64,
    max_residual: f64,
    log_rho: [f64; 2],
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

/// Run `lac lcg`.
pub(crate) fn run(args: &LcgArgs) -> Result<(), Failure> {
    if args.format == LcgFormat::Png && args.file.is_none() && io::stdout().is_terminal() {
        return Err(Failure::usage(
            "a PNG is not written to a terminal: give -o FILE, redirect standard output, or use \
             --format svg",
        ));
    }
    let text = read_input(args.input.as_deref())?;
    let samples = args.samples.map(|n| n as usize);
    let (plot, joints, title): (_, Vec<f64>, _) = match parse(&text)? {
        Input::Bezier(pieces) => {
            let n = samples.unwrap_or(PER_PIECE);
            let plot = curvature_plot(&pieces, n)?;
            // Piece k ends at plot point k·(n − 1): consecutive pieces share that point.
            let joints = (1..pieces.len()).map(|k| plot[k * (n - 1)].s).collect();
            (plot, joints, svg::lcg::bezier_title(&pieces))
        }
        Input::Curve(curve) => {
            let plot = curve.curvature_plot(samples.unwrap_or(ALONG_CURVE))?;
            let joints = curve.joint_s().into_iter().collect();
            (plot, joints, svg::lcg::lac_title(curve.pieces()))
        }
    };
    let graph = log_curvature_graph(&plot);
    let document: Vec<u8> = match args.format {
        LcgFormat::Json => {
            let report = LcgReport {
                points: plot.iter().map(PlotRow::from).collect(),
                fit: graph.fit.as_ref().map(FitRow::from),
            };
            let line = serde_json::to_string(&report).expect("numbers always serialize");
            (line + "\n").into_bytes()
        }
        LcgFormat::Csv => to_csv(&plot).into_bytes(),
        LcgFormat::Svg => svg::lcg::render(&plot, &graph, &joints, &title).into_bytes(),
        LcgFormat::Png => raster::png(&svg::lcg::render(&plot, &graph, &joints, &title))?,
    };
    write_to(args.file.as_deref(), |out| out.write_all(&document))
}

/// The whole input: the file, or standard input for "-" or no file (not a terminal, where
/// it would wait for typing).
fn read_input(path: Option<&Path>) -> Result<String, Failure> {
    let mut text = String::new();
    match path {
        Some(path) if path.as_os_str() != "-" => {
            return std::fs::read_to_string(path).map_err(|e| Failure::io("read", Some(path), &e));
        }
        None if io::stdin().is_terminal() => {
            return Err(Failure::usage(
                "give a FILE of JSON, or pipe it into standard input (for example lac quasi … | \
                 lac lcg); '-' reads the terminal",
            ));
        }
        _ => io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| Failure::io("read standard input", None, &e))?,
    };
    Ok(text)
}

/// Tell the three input shapes apart by their keys and build what they describe.
fn parse(text: &str) -> Result<Input, Failure> {
    let invalid = |why: String| Failure::invalid_input(format!("{why}; expected {SHAPES}"));
    let value: Value =
        serde_json::from_str(text).map_err(|e| invalid(format!("the input is not JSON: {e}")))?;
    let has = |key: &str| value.get(key).is_some();
    let read = |what: &str, e: serde_json::Error| invalid(format!("{what}: {e}"));
    if has("pieces") {
        let input: PiecesInput =
            serde_json::from_value(value).map_err(|e| read("Bézier pieces", e))?;
        let pieces = input
            .pieces
            .iter()
            .map(|p| RationalCubic::new(p.points.map(point), p.weights.unwrap_or([1.0; 4])))
            .collect::<Result<Vec<_>, _>>()?;
        return Ok(Input::Bezier(pieces));
    }
    if has("alpha0") || has("alpha1") {
        let input: CompoundInput =
            serde_json::from_value(value).map_err(|e| read("a lac compound result", e))?;
        let points: Vec<Point> = input.points.iter().map(|&p| point(p)).collect();
        let curve = compound::solve(
            &points,
            input.alpha0,
            input.alpha1,
            input.ratio,
            "\"ratio\"",
        )
        .map_err(|e| match e {
            Misfit::Form(message) => invalid(message),
            Misfit::Solver(failure) => failure,
        })?;
        return Ok(Input::Curve(Box::new(Lac::Compound(curve))));
    }
    if has("alpha") {
        let input: SegmentInput =
            serde_json::from_value(value).map_err(|e| read("a lac segment result", e))?;
        let points: [[f64; 2]; 3] = input
            .points
            .try_into()
            .map_err(|p: Vec<_>| invalid(format!("a segment has 3 points, got {}", p.len())))?;
        let segment = Segment::from_control_points(points.map(point), input.alpha)?;
        return Ok(Input::Curve(Box::new(Lac::Segment(segment))));
    }
    Err(invalid(
        "no \"pieces\", \"alpha\" or \"alpha0\" in the input".into(),
    ))
}

fn point([x, y]: [f64; 2]) -> Point {
    Point::new(x, y)
}

/// The plot as CSV with the header `s,kappa,dkappa_ds,log_rho,log_lcg`; the last two are
/// empty where there is no graph point. Numbers as in `lac segment --format csv`.
fn to_csv(plot: &[CurvaturePoint]) -> String {
    let mut out = String::from("s,kappa,dkappa_ds,log_rho,log_lcg\n");
    for p in plot {
        let (x, y) = match p.lcg() {
            Some((x, y)) => (format!("{x:?}"), format!("{y:?}")),
            None => (String::new(), String::new()),
        };
        out.push_str(&format!(
            "{:?},{:?},{:?},{x},{y}\n",
            p.s, p.kappa, p.dkappa_ds
        ));
    }
    out
}
