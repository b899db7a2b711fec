//! `lac segment`: one segment from `--points` and `--alpha`, or many with `--batch`.

use kurbo::Point;
use lac::Curve;
use lac::Segment;
use serde::Deserialize;

use crate::batch;
use crate::cli::{CurveFormat, SegmentArgs};
use crate::failure::Failure;
use crate::output::write_to;
use crate::points::parse_points;
use crate::report::SegmentReport;
use crate::svg::{self, Extras};

/// The shape of a `--batch` line, for error messages.
const JOB_SHAPE: &str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha":A}"#;

/// One `--batch` line: `{"points":[[x,y],[x,y],[x,y]],"alpha":A}`.
#[derive(Debug, Deserialize)]
struct Job {
    points: [[f64; 2]; 3],
    alpha: f64,
}

/// Run `lac segment`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &SegmentArgs) -> Result<(), Failure> {
    let output = &args.output;
    output.check(args.batch.is_some())?;
    let samples = output.samples as usize;
    if let Some(input) = &args.batch {
        let reader = batch::open(input)?;
        return write_to(output.file.as_deref(), |out| {
            batch::run(reader, input, out, |text| solve_job(text, samples))
        });
    }
    let (Some(text), Some(alpha)) = (&args.points, args.alpha) else {
        return Err(Failure::usage("give --points and --alpha, or --batch FILE"));
    };
    let points = parse_points(text)?;
    let document = match output.format {
        CurveFormat::Json => SegmentReport::solve(points, alpha, samples)?.to_json_line() + "\n",
        CurveFormat::Csv => SegmentReport::solve(points, alpha, samples)?.to_csv(),
        CurveFormat::Svg => {
            let segment = Segment::from_control_points(points, alpha)?;
            let extras = Extras {
                comb: output
                    .comb
                    .then(|| segment.sample_by_arc_length(samples))
                    .transpose()?,
                evolute: output.evolute,
            };
            svg::render(std::slice::from_ref(&segment), &points, extras)?
        }
    };
    write_to(output.file.as_deref(), |out| {
        out.write_all(document.as_bytes())
    })
}

/// The output line for one `--batch` line: the report, or why there is none.
pub(crate) fn solve_job(text: &str, samples: usize) -> Result<String, Failure> {
    let job: Job = batch::parse_job(text, JOB_SHAPE)?;
    let points = job.points.map(|[x, y]| Point::new(x, y));
    Ok(SegmentReport::solve(points, job.alpha, samples)?.to_json_line())
}
