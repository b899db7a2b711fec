//! `lac segment`: one segment from `--points` and `--alpha`, or many with `--batch`.

use std::sync::Arc;

use lac::Curve;
use lac_io::json::{to_line, ErrorBody, SegmentInput, SegmentReport};

use crate::batch;
use crate::cli::{CurveFormat, CurveOutput, SegmentArgs};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_points};
use crate::svg::{self, Extras};

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
