//! `lac fit`: the log-aesthetic path nearest measured points (a FILE of points, one a line
//! or a JSON array), one least-squares segment or the fewest segments within `--tolerance`;
//! or many fits with `--batch`.
//!
//! A fit's result is read back by `lac export FILE` (lac-io's `FitKind`), so it has no flags
//! of its own there.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use lac::Curve;
use lac_io::json::{to_line, ErrorBody, FitInput, FitReport};
use lac_io::points::{read_points, Columns};

use crate::batch;
use crate::errors;
use crate::input::read_document;
use crate::limits::Limits;
use crate::output::write_document;
use crate::svg;

/// What to give when there is nothing to read.
const HINT: &str = "give a FILE of points (one \"x y\" a line, or a JSON array of [x, y]), or \
                    pipe them into standard input; '-' reads the terminal";

/// Arguments of `lac fit`.
#[derive(Debug, Args)]
pub(crate) struct FitArgs {
    /// The points, in order along the curve ("-" or nothing: standard input): one a line,
    /// "x y", "x,y" or "x<TAB>y" (further columns ignored, `#` comments, a header line
    /// skipped), or a JSON array [[x,y],…]; at most 20,000 points (1,000,000 with
    /// --allow-large)
    #[arg(value_name = "FILE", conflicts_with = "batch")]
    pub(crate) input: Option<PathBuf>,

    /// The largest distance allowed between a point and the fit (the points' units): the
    /// fewest segments, up to --max-segments, that keep every point within it
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub(crate) tolerance: Option<f64>,

    /// Without --tolerance the number of segments (default 1), with it the most (default
    /// 16); at most 64
    #[arg(long, value_name = "N")]
    pub(crate) max_segments: Option<usize>,

    /// Every segment's slope α, fixed (default: fitted within --alpha-range)
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        conflicts_with_all = ["alpha_range", "shared_alpha"]
    )]
    pub(crate) alpha: Option<f64>,

    /// The range α is fitted in, "A,B" (default -5,10)
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub(crate) alpha_range: Option<String>,

    /// One fitted α for every segment
    #[arg(long)]
    pub(crate) shared_alpha: bool,

    /// Joints with continuous tangent only (default: continuous curvature too, G2)
    #[arg(long)]
    pub(crate) g1: bool,

    /// The points go round once (the last does not repeat the first): a closed path
    #[arg(long, conflicts_with = "pin_ends")]
    pub(crate) closed: bool,

    /// Hold the fit's ends on the first and last points
    #[arg(long)]
    pub(crate) pin_ends: bool,

    /// Huber's robust loss with this δ (the points' units): distances beyond δ pull
    /// linearly, so that outliers matter less
    #[arg(long, value_name = "DELTA", allow_hyphen_values = true)]
    pub(crate) huber: Option<f64>,

    /// Read a third column of FILE (a third entry of each JSON point) as the point's weight
    #[arg(long)]
    pub(crate) weighted: bool,

    /// Read one JSON object {"points":[[x,y],…],"tolerance":T,"max_segments":N,…} per line
    /// ("-": standard input; the keys are the flags' names with underscores, "alpha_range"
    /// a pair, "weights" a list) and write one JSON line per input line, in order: the
    /// result, or {"error":…} whose message starts with the line number
    #[arg(
        long,
        value_name = "FILE|-",
        conflicts_with_all = ["tolerance", "max_segments", "alpha", "alpha_range",
            "shared_alpha", "g1", "closed", "pin_ends", "huber", "weighted"]
    )]
    pub(crate) batch: Option<PathBuf>,

    /// Number of samples of the fitted path, equally spaced in arc length (the comb's teeth
    /// in SVG); at most 1,000,000 (10,000,000 with --allow-large)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 65,
        value_parser = clap::value_parser!(u32).range(2..)
    )]
    pub(crate) samples: u32,

    /// Output format
    #[arg(long, value_enum, default_value_t = FitFormat::Json)]
    pub(crate) format: FitFormat,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac fit`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum FitFormat {
    /// One line: the path (segments, joints, samples) and the fit's figures (rms,
    /// max_distance, worst_point, farthest, fitted_segments)
    Json,
    /// A header s,x,y,theta,kappa and one row per sample of the fitted path
    Csv,
    /// The points, the fitted path with its curvature comb and joints, and the curvature
    /// plot of the fit against the points' three-point curvature
    Svg,
}

/// Run `lac fit`. The whole result is computed before the output file is created.
pub(crate) fn run(args: &FitArgs, limits: Limits) -> Result<(), ErrorBody> {
    let samples = limits.samples(args.samples as usize, "--samples")?;
    if let Some(input) = &args.batch {
        if args.format != FitFormat::Json {
            return Err(errors::usage(
                "--batch writes JSON lines; --format csv and svg need a FILE of points",
            ));
        }
        let solve = batch::from_lines(move |text| solve_line(text, samples, limits));
        // A fit costs far more than its samples: a few lines to a chunk keep every core busy.
        let chunk = batch::chunk_lines(samples.max(100_000));
        return batch::run(input, args.file.as_deref(), limits, chunk, solve);
    }
    let text = read_document(args.input.as_deref(), limits.document(), HINT)?;
    let columns = if args.weighted {
        Columns::Weighted
    } else {
        Columns::Points
    };
    let file = read_points(&text, columns)?;
    limits.points(file.points.len())?;
    let input = FitInput {
        points: file.points,
        tolerance: args.tolerance,
        max_segments: args.max_segments,
        alpha: args.alpha,
        alpha_range: args.alpha_range.as_deref().map(alpha_range).transpose()?,
        shared_alpha: args.shared_alpha,
        g1: args.g1,
        closed: args.closed,
        pin_ends: args.pin_ends,
        huber: args.huber,
        weights: file.weights,
    };
    let fit = input.solve()?;
    let report = || FitReport::new(&fit, &input.points, input.tolerance, samples);
    let document = match args.format {
        FitFormat::Json => to_line(&report()?) + "\n",
        FitFormat::Csv => report()?.to_csv(),
        FitFormat::Svg => svg::fit::render(&fit, &input, &fit.sample_by_arc_length(samples)?)?,
    };
    write_document(args.file.as_deref(), document.as_bytes())
}

/// The output line for one `--batch` line: the report, or why there is none.
fn solve_line(text: &str, samples: usize, limits: Limits) -> Result<String, ErrorBody> {
    let input: FitInput = lac_io::json::parse(text, FitInput::SHAPE)?;
    limits.points(input.points.len())?;
    let fit = input.solve()?;
    let report = FitReport::new(&fit, &input.points, input.tolerance, samples)?;
    Ok(to_line(&report))
}

/// The pair of `--alpha-range`, "A,B".
fn alpha_range(text: &str) -> Result<[f64; 2], ErrorBody> {
    let numbers: Vec<&str> = text
        .split(|c: char| c == ',' || c == ';' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    let parse = |t: &str| {
        t.parse::<f64>()
            .map_err(|_| ErrorBody::invalid_input(format!("--alpha-range: {t:?} is not a number")))
    };
    match numbers[..] {
        [a, b] => Ok([parse(a)?, parse(b)?]),
        _ => Err(ErrorBody::invalid_input(format!(
            "--alpha-range takes two numbers \"A,B\", got {text:?}"
        ))),
    }
}
