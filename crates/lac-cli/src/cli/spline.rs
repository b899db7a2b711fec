//! `lac spline`: a G2 spline of log-aesthetic segments through points (`--through`,
//! `--alpha`, `--closed`, `--start-angle`/`--end-angle`).
//!
//! The spline in `lac export`: [`SplineExport`], its flags there, and its results as
//! documents.

use clap::Args;
use kurbo::Point;
use lac::Curve;
use lac_io::json::{to_line, AnyCurve, ErrorBody, SplineInput, SplineReport};

use crate::cli::export::{names, present, ExportSource, Flag, Input};
use crate::cli::segment::check_output;
use crate::cli::{CurveFlags, CurveFormat, CurveOutput};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_polygon};
use crate::svg::{self, Extras};

/// Arguments of `lac spline`.
#[derive(Args, Debug)]
pub(crate) struct SplineArgs {
    /// The points to pass through "x0,y0 x1,y1 …" (at least three), separated by spaces
    /// and/or semicolons
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) through: String,

    /// The slope of every segment
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: f64,

    /// A closed spline (the last point joins the first)
    #[arg(long)]
    pub(crate) closed: bool,

    /// Open splines: the tangent direction at the first point, radians
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "end_angle",
        conflicts_with = "closed"
    )]
    pub(crate) start_angle: Option<f64>,

    /// Open splines: the tangent direction at the last point, radians
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "start_angle"
    )]
    pub(crate) end_angle: Option<f64>,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// Run `lac spline`. The whole result is computed before the output file is created.
pub(crate) fn run(args: &SplineArgs, limits: Limits) -> Result<(), ErrorBody> {
    let output = &args.output;
    check_output(output, false)?;
    let samples = limits.samples(output.samples as usize, "--samples")?;
    let spline = SplineInput {
        points: through_points(&args.through)?,
        alpha: args.alpha,
        closed: args.closed,
        ends: args.start_angle.zip(args.end_angle).map(|(a, b)| [a, b]),
    }
    .solve()?;
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
            svg::render(
                ("Log-aesthetic spline (G2)", None),
                spline.pieces(),
                &through,
                extras,
            )?
        }
    };
    write_document(output.file.as_deref(), document.as_bytes())
}

/// The points of `--through`: at least three.
fn through_points(text: &str) -> Result<Vec<Point>, ErrorBody> {
    Ok(kurbo_points(&parse_polygon(
        text,
        3,
        lac::MAX_POLYGON_POINTS,
    )?))
}

/// A spline's own flags in `lac export` (with `--alpha` and `--closed` of [`CurveFlags`]).
#[derive(Debug, Args)]
pub(crate) struct SplineExport {
    /// A spline: the points it passes through "x0,y0 x1,y1 …" (at least three), with
    /// --alpha, and --closed or --start-angle/--end-angle as lac spline takes them
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        conflicts_with_all = ["points", "input", "polygon"]
    )]
    pub(crate) through: Option<String>,

    /// A spline: the tangent direction at the first point, radians
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires_all = ["through", "end_angle"],
        conflicts_with = "closed"
    )]
    pub(crate) start_angle: Option<f64>,

    /// A spline: the tangent direction at the last point, radians
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires_all = ["through", "start_angle"]
    )]
    pub(crate) end_angle: Option<f64>,
}

impl ExportSource for SplineExport {
    /// The flags given, none without `--through`: clap refuses `--start-angle` and
    /// `--end-angle` without it, except beside `--points`, which rules `--through` out; they
    /// are ignored there, as they always were.
    fn given(&self) -> Vec<Flag> {
        if self.through.is_none() {
            return Vec::new();
        }
        present([
            Flag::other("--through", true),
            Flag::other("--start-angle", self.start_angle.is_some()),
            Flag::other("--end-angle", self.end_angle.is_some()),
        ])
    }

    /// The spline through `--through`, with `--alpha`; other kinds' slopes are refused.
    fn export_input(
        &self,
        curve: &CurveFlags,
        others: &[Flag],
    ) -> Option<Result<Input, ErrorBody>> {
        let through = self.through.as_deref()?;
        let Some(alpha) = curve.alpha else {
            return Some(Err(errors::usage("a spline (--through) needs --alpha")));
        };
        let slopes: Vec<&Flag> = others.iter().filter(|f| f.slope).collect();
        if !slopes.is_empty() {
            return Some(Err(errors::usage(format!(
                "a spline takes --alpha: drop {}",
                names(slopes)
            ))));
        }
        Some(
            through_points(through)
                .and_then(|points| {
                    SplineInput {
                        points,
                        alpha,
                        closed: curve.closed,
                        ends: self.start_angle.zip(self.end_angle).map(|(a, b)| [a, b]),
                    }
                    .solve()
                })
                .map(AnyCurve::Spline),
        )
    }

    fn closes(&self) -> bool {
        true
    }
}
