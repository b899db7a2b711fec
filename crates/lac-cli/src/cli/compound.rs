//! `lac compound`: one compound-rhythm curve from `--points` (three with `--ratio`, or
//! four), `--alpha0` and `--alpha1`, or many with `--batch`.
//!
//! Its slopes and ratio where other curves' flags are taken too, in `lac quasi` and `lac
//! export`, are [`CompoundFlags`].

use std::path::PathBuf;
use std::sync::Arc;

use clap::Args;
use lac::Curve;
use lac::SegmentChain;
use lac_io::json::{
    parse, to_line, write_line, AnyCurve, CompoundInput, CompoundReport, ErrorBody,
};

use crate::batch;
use crate::cli::export::{present, ExportSource, Flag, Input};
use crate::cli::segment::check_output;
use crate::cli::{CurveFlags, CurveFormat, CurveOutput};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_point_list};
use crate::svg::{self, Extras};

/// Arguments of `lac compound`.
#[derive(Debug, Args)]
pub(crate) struct CompoundArgs {
    /// Three points "x0,y0 x1,y1 x2,y2" (the ends and the intersection of the end tangents;
    /// give --ratio) or four control points "x0,y0 x1,y1 x2,y2 x3,y3" (the joint's tangent is
    /// parallel to the middle leg), separated by spaces and/or semicolons
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// Slope of the logarithmic curvature graph of the piece from the first point to the joint
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha0: Option<f64>,

    /// Slope of the piece from the joint to the last point (alpha0 < alpha1: a "valley" in the
    /// curvature graph; alpha0 > alpha1: a "mountain")
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha1: Option<f64>,

    /// Three points only: the share of the total turning made by the alpha0 piece, strictly
    /// between 0 and 1
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,

    /// Read one JSON object per line ("-": standard input), {"points":[[x,y],[x,y],[x,y]],
    /// "alpha0":A,"alpha1":B,"ratio":R} or {"points":[[x,y],[x,y],[x,y],[x,y]],"alpha0":A,
    /// "alpha1":B}, and write one JSON line per input line, in order: the result, or
    /// {"error":…} whose message starts with the line number (see lac segment --help for the
    /// line limit and the exit code)
    #[arg(
        long,
        value_name = "FILE|-",
        conflicts_with_all = ["points", "alpha0", "alpha1", "ratio"]
    )]
    pub(crate) batch: Option<PathBuf>,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// A compound curve's slopes and ratio (with `--points`) where other kinds' flags are taken
/// too, all optional: in `lac quasi` and `lac export`.
#[derive(Debug, Args)]
pub(crate) struct CompoundFlags {
    /// A compound curve: the slope of the piece from the first point to the joint
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha0: Option<f64>,

    /// A compound curve: the slope of the piece from the joint to the last point
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) alpha1: Option<f64>,

    /// A compound curve from three points: the share of the turning made by the alpha0
    /// piece, strictly between 0 and 1
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,
}

/// Run `lac compound`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &CompoundArgs, limits: Limits) -> Result<(), ErrorBody> {
    let output = &args.output;
    check_output(output, args.batch.is_some())?;
    let samples = limits.samples(output.samples as usize, "--samples")?;
    if let Some(input) = &args.batch {
        let solve: batch::Solve = Arc::new(move |text, out| solve_line(text, samples, out));
        let chunk = batch::chunk_lines(samples);
        return batch::run(input, output.file.as_deref(), limits, chunk, solve);
    }
    let (Some(text), Some(alpha0), Some(alpha1)) = (&args.points, args.alpha0, args.alpha1) else {
        return Err(errors::usage(
            "give --points, --alpha0 and --alpha1 (and --ratio for three points), or --batch FILE",
        ));
    };
    let input = from_arguments(text, alpha0, alpha1, args.ratio)?;
    let curve = input.solve()?;
    let document = match output.format {
        CurveFormat::Json => to_line(&CompoundReport::new(&curve, &input, samples)?) + "\n",
        CurveFormat::Csv => CompoundReport::new(&curve, &input, samples)?.to_csv(),
        CurveFormat::Svg => {
            let extras = Extras {
                comb: output
                    .comb
                    .then(|| curve.sample_by_arc_length(samples))
                    .transpose()?,
                evolute: output.evolute,
                closed: false,
            };
            svg::render(
                ("Compound-rhythm log-aesthetic curve", Some(curve.lambda())),
                curve.pieces(),
                &kurbo_points(&input.points),
                extras,
            )?
        }
    };
    write_document(output.file.as_deref(), document.as_bytes())
}

/// The output line for one `--batch` line: the report, or why there is none.
fn solve_line(text: &str, samples: usize, out: &mut Vec<u8>) -> Result<(), ErrorBody> {
    let input: CompoundInput = parse(text, CompoundInput::SHAPE)?;
    let report = CompoundReport::new(&input.solve()?, &input, samples)?;
    write_line(&report, out);
    Ok(())
}

/// The compound curve's input for the arguments `--points` (`text`), `--alpha0`,
/// `--alpha1` and `--ratio`: three points with a ratio (seed 004) or four without (seed
/// 002); the wrong pairing is a usage error that names the flags.
pub(crate) fn from_arguments(
    text: &str,
    alpha0: f64,
    alpha1: f64,
    ratio: Option<f64>,
) -> Result<CompoundInput, ErrorBody> {
    let points = parse_point_list(text, &[3, 4])?;
    match (points.len(), ratio) {
        (3, None) => Err(errors::usage(
            "three points need --ratio: the share of the turning made by the alpha0 piece, \
             strictly between 0 and 1 (0.5 splits it evenly); or give four control points, \
             whose middle leg sets the joint's tangent",
        )),
        (4, Some(_)) => Err(errors::usage(
            "four control points take no --ratio: the middle leg P1-P2 sets the joint's \
             tangent; drop --ratio, or give three points",
        )),
        _ => Ok(CompoundInput {
            points,
            alpha0,
            alpha1,
            ratio,
        }),
    }
}

impl ExportSource for CompoundFlags {
    fn given(&self) -> Vec<Flag> {
        present([
            Flag::slope("--alpha0", self.alpha0.is_some()),
            Flag::slope("--alpha1", self.alpha1.is_some()),
            Flag::other("--ratio", self.ratio.is_some()),
        ])
    }

    /// A compound curve when `--points`, `--alpha0` and `--alpha1` come without `--alpha` or
    /// any other kind's flags.
    fn export_input(
        &self,
        curve: &CurveFlags,
        others: &[Flag],
    ) -> Option<Result<Input, ErrorBody>> {
        let (Some(text), None, Some(alpha0), Some(alpha1)) =
            (&curve.points, curve.alpha, self.alpha0, self.alpha1)
        else {
            return None;
        };
        if !others.is_empty() {
            return None;
        }
        Some(
            from_arguments(text, alpha0, alpha1, self.ratio)
                .and_then(|input| input.solve())
                .map(AnyCurve::Compound),
        )
    }
}
