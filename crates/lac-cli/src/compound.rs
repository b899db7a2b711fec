//! `lac compound`: one compound-rhythm curve from `--points` (three with `--ratio`, or
//! four), `--alpha0` and `--alpha1`, or many with `--batch`.

use kurbo::Point;
use lac::CompoundCurve;
use lac::Curve;
use serde::Deserialize;

use crate::batch;
use crate::cli::{CompoundArgs, CurveFormat};
use crate::failure::Failure;
use crate::output::write_to;
use crate::points::parse_point_list;
use crate::report::CompoundReport;
use crate::svg::{self, Extras};

/// The shapes of a `--batch` line, for error messages.
const JOB_SHAPE: &str = r#"{"points":[[x,y],[x,y],[x,y]],"alpha0":A,"alpha1":B,"ratio":R} or {"points":[[x,y],[x,y],[x,y],[x,y]],"alpha0":A,"alpha1":B}"#;

/// One `--batch` line: three points with a ratio, or four points without.
#[derive(Debug, Deserialize)]
struct Job {
    points: Vec<[f64; 2]>,
    alpha0: f64,
    alpha1: f64,
    ratio: Option<f64>,
}

/// Run `lac compound`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &CompoundArgs) -> Result<(), Failure> {
    let output = &args.output;
    output.check(args.batch.is_some())?;
    let samples = output.samples as usize;
    if let Some(input) = &args.batch {
        let reader = batch::open(input)?;
        return write_to(output.file.as_deref(), |out| {
            batch::run(reader, input, out, |text| solve_job(text, samples))
        });
    }
    let (Some(text), Some(alpha0), Some(alpha1)) = (&args.points, args.alpha0, args.alpha1) else {
        return Err(Failure::usage(
            "give --points, --alpha0 and --alpha1 (and --ratio for three points), or --batch FILE",
        ));
    };
    let (curve, points) = from_arguments(text, alpha0, alpha1, args.ratio)?;
    let document = match output.format {
        CurveFormat::Json => {
            CompoundReport::new(&curve, &points, args.ratio, samples)?.to_json_line() + "\n"
        }
        CurveFormat::Csv => CompoundReport::new(&curve, &points, args.ratio, samples)?.to_csv(),
        CurveFormat::Svg => {
            let extras = Extras {
                comb: output
                    .comb
                    .then(|| curve.sample_by_arc_length(samples))
                    .transpose()?,
                evolute: output.evolute,
            };
            svg::render(curve.pieces(), &points, extras)?
        }
    };
    write_to(output.file.as_deref(), |out| {
        out.write_all(document.as_bytes())
    })
}

/// The output line for one `--batch` line: the report, or why there is none.
pub(crate) fn solve_job(text: &str, samples: usize) -> Result<String, Failure> {
    let job: Job = batch::parse_job(text, JOB_SHAPE)?;
    let points: Vec<Point> = job.points.iter().map(|&[x, y]| Point::new(x, y)).collect();
    let curve =
        solve(&points, job.alpha0, job.alpha1, job.ratio, "\"ratio\"").map_err(|e| match e {
            Misfit::Form(message) => {
                Failure::invalid_input(format!("{message}; expected {JOB_SHAPE}"))
            }
            Misfit::Solver(failure) => failure,
        })?;
    Ok(CompoundReport::new(&curve, &points, job.ratio, samples)?.to_json_line())
}

/// The compound curve for the command-line arguments `--points` (`text`), `--alpha0`,
/// `--alpha1` and `--ratio`, and the points it was solved from.
pub(crate) fn from_arguments(
    text: &str,
    alpha0: f64,
    alpha1: f64,
    ratio: Option<f64>,
) -> Result<(CompoundCurve, Vec<Point>), Failure> {
    let points = parse_point_list(text, &[3, 4])?;
    let curve = solve(&points, alpha0, alpha1, ratio, "--ratio").map_err(|e| match e {
        Misfit::Form(message) => Failure::usage(message),
        Misfit::Solver(failure) => failure,
    })?;
    Ok((curve, points))
}

/// Why [`solve`] gave no curve.
pub(crate) enum Misfit {
    /// The number of points and the presence of a ratio do not make one of the two forms
    /// (a usage error on the command line, invalid input in a batch).
    Form(String),
    /// The library's verdict on the numbers.
    Solver(Failure),
}

/// The compound curve for three points and `ratio` (seed 004) or four control points and no
/// ratio (seed 002); `ratio_name` is what the caller calls the ratio, for messages.
pub(crate) fn solve(
    points: &[Point],
    alpha0: f64,
    alpha1: f64,
    ratio: Option<f64>,
    ratio_name: &str,
) -> Result<CompoundCurve, Misfit> {
    let solved = match (points, ratio) {
        (&[a, b, c], Some(ratio)) => {
            CompoundCurve::from_three_points([a, b, c], alpha0, alpha1, ratio)
        }
        (&[a, b, c, d], None) => CompoundCurve::from_four_points([a, b, c, d], alpha0, alpha1),
        ([_, _, _], None) => {
            return Err(Misfit::Form(format!(
                "three points need {ratio_name}: the share of the turning made by the alpha0 \
                 piece, strictly between 0 and 1 (0.5 splits it evenly); or give four control \
                 points, whose middle leg sets the joint's tangent"
            )))
        }
        ([_, _, _, _], Some(_)) => {
            return Err(Misfit::Form(format!(
                "four control points take no {ratio_name}: the middle leg P1-P2 sets the \
                 joint's tangent; drop {ratio_name}, or give three points"
            )))
        }
        _ => {
            return Err(Misfit::Form(format!(
                "a compound curve takes 3 or 4 points, got {}",
                points.len()
            )))
        }
    };
    solved.map_err(|e| Misfit::Solver(e.into()))
}
