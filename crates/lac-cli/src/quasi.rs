//! `lac quasi`: a segment or compound curve replaced by rational (or plain) cubic Bézier
//! pieces (seed 001, docs/math.md §5), as JSON, CSV, or drawn over the curve; or many with
//! `--batch`.

use lac::Curve;
use lac_io::json::{
    parse, to_line, CurveInput, ErrorBody, QuasiInput, QuasiReport, Report, SegmentInput,
};

use crate::batch;
use crate::cli::{QuasiArgs, QuasiFormat};
use crate::compound;
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_points};
use crate::svg;

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
    match (args.alpha, args.alpha0, args.alpha1) {
        (Some(alpha), None, None) if args.ratio.is_none() => {
            Ok(CurveInput::Segment(SegmentInput {
                points: parse_points(text)?,
                alpha,
            }))
        }
        (None, Some(alpha0), Some(alpha1)) => Ok(CurveInput::Compound(compound::from_arguments(
            text, alpha0, alpha1, args.ratio,
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
