//! `lac spline`: a G2 spline of log-aesthetic segments through points (`--through`,
//! `--alpha`, `--closed`, `--start-angle`/`--end-angle`).

use lac::{Closure, SegmentChain};
use lac::{Curve, Spline};
use lac_io::json::{to_line, ErrorBody, SplineReport};

use crate::cli::{CurveFormat, SplineArgs};
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_polygon};
use crate::segment::check_output;
use crate::svg::{self, Extras};

/// Run `lac spline`. The whole result is computed before the output file is created.
pub(crate) fn run(args: &SplineArgs, limits: Limits) -> Result<(), ErrorBody> {
    let output = &args.output;
    check_output(output, false)?;
    let samples = limits.samples(output.samples as usize, "--samples")?;
    let points = kurbo_points(&parse_polygon(&args.through, 3, lac::MAX_POLYGON_POINTS)?);
    let ends = args.start_angle.zip(args.end_angle).map(|(a, b)| [a, b]);
    let spline = Spline::from_points(
        &points,
        args.alpha,
        if args.closed {
            Closure::Closed
        } else {
            Closure::Open
        },
        ends,
    )?;
    let document = match output.format {
        CurveFormat::Json => to_line(&SplineReport::new(&spline, args.alpha, samples)?) + "\n",
        CurveFormat::Csv => SplineReport::new(&spline, args.alpha, samples)?.to_csv(),
        CurveFormat::Svg => {
            let extras = Extras {
                comb: output
                    .comb
                    .then(|| spline.sample_by_arc_length(samples))
                    .transpose()?,
                evolute: output.evolute,
                closed: args.closed,
            };
            let mut through = spline.points().to_vec();
            if args.closed {
                through.push(through[0]);
            }
            svg::render(spline.pieces(), &through, extras)?
        }
    };
    write_document(output.file.as_deref(), document.as_bytes())
}
