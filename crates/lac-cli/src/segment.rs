//! `lac segment`: one segment from `--points` and `--alpha`, or many with `--batch`.

use lac::Segment;

use crate::batch;
use crate::cli::{SegmentArgs, SegmentFormat};
use crate::failure::Failure;
use crate::output::write_to;
use crate::points::parse_points;
use crate::report::SegmentReport;
use crate::svg::{self, Extras};

/// Run `lac segment`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &SegmentArgs) -> Result<(), Failure> {
    check_flags(args)?;
    let samples = args.samples as usize;
    if let Some(input) = &args.batch {
        let reader = batch::open(input)?;
        return write_to(args.output.as_deref(), |out| {
            batch::run(reader, input, samples, out)
        });
    }
    let (Some(text), Some(alpha)) = (&args.points, args.alpha) else {
        return Err(Failure::usage("give --points and --alpha, or --batch FILE"));
    };
    let points = parse_points(text)?;
    let document = match args.format {
        SegmentFormat::Json => SegmentReport::solve(points, alpha, samples)?.to_json_line() + "\n",
        SegmentFormat::Csv => SegmentReport::solve(points, alpha, samples)?.to_csv(),
        SegmentFormat::Svg => {
            let segment = Segment::from_control_points(points, alpha)?;
            let extras = Extras {
                comb_teeth: args.comb.then_some(samples),
                evolute: args.evolute,
            };
            svg::render(&segment, points, extras)?
        }
    };
    write_to(args.output.as_deref(), |out| {
        out.write_all(document.as_bytes())
    })
}

/// Reject combinations of flags that would be silently ignored.
fn check_flags(args: &SegmentArgs) -> Result<(), Failure> {
    if args.batch.is_some() && args.format != SegmentFormat::Json {
        return Err(Failure::usage(
            "--batch writes JSON lines; --format csv and svg need --points and --alpha",
        ));
    }
    if (args.comb || args.evolute) && args.format != SegmentFormat::Svg {
        return Err(Failure::usage(
            "--comb and --evolute draw; add --format svg",
        ));
    }
    Ok(())
}
