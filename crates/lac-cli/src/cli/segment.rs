//! `lac segment`: one segment from `--points` and `--alpha`, or many with `--batch`; and the
//! segment in `lac export` ([`SegmentExport`]).

use std::path::PathBuf;
use std::sync::Arc;

use clap::Args;
use lac::Curve;
use lac_io::json::{to_line, AnyCurve, ErrorBody, SegmentInput, SegmentReport};

use crate::batch;
use crate::cli::export::{ExportSource, Flag, Input};
use crate::cli::{CurveFlags, CurveFormat, CurveOutput};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_points};
use crate::svg::{self, Extras};

/// Arguments of `lac segment`.
#[derive(Debug, Args)]
pub(crate) struct SegmentArgs {
    /// The control points "x0,y0 x1,y1 x2,y2", separated by spaces and/or semicolons
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// Slope of the logarithmic curvature graph (-1 clothoid, 0 Nielsen spiral, 1 logarithmic
    /// spiral, 2 circle involute)
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha: Option<f64>,

    /// Read one JSON object {"points":[[x,y],[x,y],[x,y]],"alpha":A} per line ("-": standard
    /// input) and write one JSON line per input line, in order: the result, or {"error":…}
    /// whose message starts with the line number. Lines are solved in parallel and written as
    /// soon as they and the lines before them are done; a line may have at most 1 MiB. Exit
    /// code 0 when every line was solved, else that of the first failed line (2 invalid, 3 no
    /// curve, 70 internal), with a one-line summary on standard error
    #[arg(long, value_name = "FILE|-", conflicts_with_all = ["points", "alpha"])]
    pub(crate) batch: Option<PathBuf>,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// Run `lac segment`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &SegmentArgs, limits: Limits) -> Result<(), ErrorBody> {
    let output = &args.output;
    check_output(output, args.batch.is_some())?;
    let samples = limits.samples(output.samples as usize, "--samples")?;
    if let Some(input) = &args.batch {
        let solve: batch::Solve = Arc::new(move |text, out| solve_line(text, samples, out));
        let chunk = batch::chunk_lines(samples);
        return batch::run(input, output.file.as_deref(), limits, chunk, solve);
    }
    let (Some(text), Some(alpha)) = (&args.points, args.alpha) else {
        return Err(errors::usage("give --points and --alpha, or --batch FILE"));
    };
    let input = SegmentInput {
        points: parse_points(text)?,
        alpha,
    };
    let segment = input.solve()?;
    let report = || SegmentReport::of_input(&segment, samples, input.points);
    let document = match output.format {
        CurveFormat::Json => to_line(&report()?) + "\n",
        CurveFormat::Csv => report()?.to_csv(),
        CurveFormat::Svg => {
            let extras = Extras {
                comb: output
                    .comb
                    .then(|| segment.sample_by_arc_length(samples))
                    .transpose()?,
                evolute: output.evolute,
                closed: false,
            };
            svg::render(
                ("Log-aesthetic segment", Some(segment.lambda())),
                std::slice::from_ref(&segment),
                &kurbo_points(&input.points),
                extras,
            )?
        }
    };
    write_document(output.file.as_deref(), document.as_bytes())
}

/// The output line for one `--batch` line, appended to `out`: the report, or why there is
/// none.
fn solve_line(text: &str, samples: usize, out: &mut Vec<u8>) -> Result<(), ErrorBody> {
    let input = SegmentInput::parse_line(text)?;
    // (Checked for finiteness when made; the input points are finite numbers.)
    SegmentReport::of_input(&input.solve()?, samples, input.points)?.write_json(out);
    Ok(())
}

/// Reject combinations of output flags that would be silently ignored; `batch`: is
/// `--batch` given?
pub(crate) fn check_output(output: &CurveOutput, batch: bool) -> Result<(), ErrorBody> {
    if batch && output.format != CurveFormat::Json {
        return Err(errors::usage(
            "--batch writes JSON lines; --format csv and svg need --points",
        ));
    }
    if (output.comb || output.evolute) && output.format != CurveFormat::Svg {
        return Err(errors::usage("--comb and --evolute draw; add --format svg"));
    }
    Ok(())
}

/// The segment in `lac export`: `--points` and `--alpha`, flags that other kinds take too
/// ([`CurveFlags`]); it has none of its own.
pub(crate) struct SegmentExport;

impl ExportSource for SegmentExport {
    fn given(&self) -> Vec<Flag> {
        Vec::new()
    }

    /// A segment when `--points` and `--alpha` come without any other kind's flags.
    fn export_input(
        &self,
        curve: &CurveFlags,
        others: &[Flag],
    ) -> Option<Result<Input, ErrorBody>> {
        let (Some(text), Some(alpha)) = (&curve.points, curve.alpha) else {
            return None;
        };
        if !others.is_empty() {
            return None;
        }
        Some(
            parse_points(text)
                .and_then(|points| SegmentInput { points, alpha }.solve())
                .map(AnyCurve::Segment),
        )
    }
}
