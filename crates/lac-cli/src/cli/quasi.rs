//! `lac quasi`: a segment or compound curve replaced by rational (or plain) cubic Bézier
//! pieces (seed 001, docs/math.md §5), as JSON, CSV, or drawn over the curve; or many with
//! `--batch`.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use lac::Curve;
use lac_io::json::{
    parse, to_line, CurveInput, ErrorBody, QuasiInput, QuasiReport, Report, SegmentInput,
};

use crate::batch;
use crate::cli::compound::{self, CompoundFlags};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_points};
use crate::svg;

/// Arguments of `lac quasi`.
#[derive(Debug, Args)]
pub(crate) struct QuasiArgs {
    /// The control points, separated by spaces and/or semicolons: three with --alpha (a
    /// segment), three with --alpha0, --alpha1 and --ratio, or four with --alpha0 and --alpha1
    /// (a compound curve, as in lac compound)
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// A segment: the slope of its logarithmic curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: Option<f64>,

    /// A compound curve's slopes and ratio.
    #[command(flatten)]
    pub(crate) compound: CompoundFlags,

    /// Use as many pieces as needed for a maximum deviation of T times the arc length (1e-12
    /// to 1), each with curvature proven monotone, joined with continuous curvature. Without
    /// it: the single rational cubic of seed 001
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub(crate) tolerance: Option<f64>,

    /// Plain cubic Bézier pieces (all weights 1) instead of rational ones, for consumers that
    /// only take cubics (needs --tolerance)
    #[arg(long, requires = "tolerance")]
    pub(crate) cubic: bool,

    /// Read one JSON object per line ("-": standard input): a lac segment or lac compound
    /// input ({"points":…,"alpha":A} or {"points":…,"alpha0":A,"alpha1":B,"ratio":R}) with
    /// "tolerance":T and "cubic":true as --tolerance and --cubic; write one JSON line per
    /// input line, in order: the result, or {"error":…} whose message starts with the line
    /// number (see lac segment --help for the line limit and the exit code)
    #[arg(
        long,
        value_name = "FILE|-",
        conflicts_with_all = ["points", "alpha", "alpha0", "alpha1", "ratio", "tolerance", "cubic"]
    )]
    pub(crate) batch: Option<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = QuasiFormat::Json)]
    pub(crate) format: QuasiFormat,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac quasi`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum QuasiFormat {
    /// One line: pieces [{points, weights, monotone, proven, turning, max_deviation}], rms,
    /// max (relative to the arc length), arc_length, tolerance, kind ("rational" or "cubic")
    Json,
    /// A header piece,x0,y0,x1,y1,x2,y2,x3,y3,w0,w1,w2,w3,monotone,proven,t,turning0,turning1,
    /// max_deviation and one row per piece (t empty unless not monotone)
    Csv,
    /// The Bézier pieces over the log-aesthetic curve, their control polygons and joints, and
    /// the curvature combs of both
    Svg,
}

/// What a line of `--batch` costs, in samples, for sizing the chunks of lines read together:
/// a fit evaluates its curve at a few thousand points a piece.
const LINE_COST: usize = 50_000;

/// Run `lac quasi`.
///
/// The whole result is computed before the output file is created, so a failed run leaves
/// an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &QuasiArgs, limits: Limits) -> Result<(), ErrorBody> {
    if let Some(input) = &args.batch {
        if args.format != QuasiFormat::Json {
            return Err(errors::usage(
                "--batch writes JSON lines; --format csv and svg need --points",
            ));
        }
        let solve = batch::from_lines(solve_line);
        let chunk = batch::chunk_lines(LINE_COST);
        return batch::run(input, args.file.as_deref(), limits, chunk, solve);
    }
    let input = QuasiInput {
        curve: curve_from_arguments(args)?,
        tolerance: args.tolerance,
        cubic: args.cubic,
    };
    let (solved, quasi) = input.solve()?;
    let curve = solved.curve();
    let report =
        || QuasiReport::new(&quasi, curve.arc_length(), input.tolerance, input.cubic).checked();
    let document = match args.format {
        QuasiFormat::Json => to_line(&report()?) + "\n",
        QuasiFormat::Csv => report()?.to_csv(),
        QuasiFormat::Svg => {
            let comb = curve.sample_by_arc_length(svg::quasi::LAC_SAMPLES)?;
            let points = kurbo_points(&input.curve.points());
            svg::quasi::render(curve.pieces(), &points, &comb, &quasi, input.cubic)?
        }
    };
    write_document(args.file.as_deref(), document.as_bytes())
}

/// The output line for one `--batch` line: the report, or why there is none.
fn solve_line(text: &str) -> Result<String, ErrorBody> {
    let input: QuasiInput = parse(text, QuasiInput::SHAPE)?;
    let (solved, quasi) = input.solve()?;
    let arc_length = solved.curve().arc_length();
    let report = QuasiReport::new(&quasi, arc_length, input.tolerance, input.cubic);
    Ok(to_line(&report.checked()?))
}

/// The curve for `--points` with `--alpha` (a segment), or with `--alpha0`, `--alpha1`
/// (and `--ratio`: a compound curve).
fn curve_from_arguments(args: &QuasiArgs) -> Result<CurveInput, ErrorBody> {
    let Some(text) = &args.points else {
        return Err(errors::usage("give --points, or --batch FILE"));
    };
    let CompoundFlags {
        alpha0,
        alpha1,
        ratio,
    } = args.compound;
    match (args.alpha, alpha0, alpha1) {
        (Some(alpha), None, None) if ratio.is_none() => Ok(CurveInput::Segment(SegmentInput {
            points: parse_points(text)?,
            alpha,
        })),
        (None, Some(alpha0), Some(alpha1)) => Ok(CurveInput::Compound(compound::from_arguments(
            text, alpha0, alpha1, ratio,
        )?)),
        (Some(_), None, None) => Err(errors::usage(
            "--ratio belongs to a compound curve: give --alpha0 and --alpha1 instead of --alpha",
        )),
        _ => Err(errors::usage(
            "give --alpha for a segment, or --alpha0 and --alpha1 (and --ratio for three \
             points) for a compound curve",
        )),
    }
}
