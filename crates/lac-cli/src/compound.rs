//! `lac compound`: one compound-rhythm curve from `--points` (three with `--ratio`, or
//! four), `--alpha0` and `--alpha1`, or many with `--batch`.

use std::sync::Arc;

use lac::Curve;
use lac::SegmentChain;
use lac_io::json::{parse, to_line, write_line, CompoundInput, CompoundReport, ErrorBody};

use crate::batch;
use crate::cli::{CompoundArgs, CurveFormat};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_point_list};
use crate::segment::check_output;
use crate::svg::{self, Extras};

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
            svg::render(curve.pieces(), &kurbo_points(&input.points), extras)?
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
