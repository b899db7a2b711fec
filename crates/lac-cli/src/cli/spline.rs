//! `lac spline`: a G2 spline of log-aesthetic segments through points (`--through`,
//! `--alpha`, `--closed`, `--start-angle`/`--end-angle`), with point types (`--types`,
//! `--angles`), straight spans (`--lines`) and end curvatures (`--start-curvature`,
//! `--end-curvature`).
//!
//! The spline in `lac export`: [`SplineExport`], its flags there, and its results as
//! documents.

use clap::Args;
use kurbo::Point;
use lac::{Curve, PointType, SplineEnd, SplineOptions};
use lac_io::json::{point_type_named, to_line, AnyCurve, ErrorBody, SplineInput, SplineReport};

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

    /// Point types, straight spans and end conditions.
    #[command(flatten)]
    pub(crate) conditions: SplineConditions,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// Run `lac spline`. The whole result is computed before the output file is created.
pub(crate) fn run(args: &SplineArgs, limits: Limits) -> Result<(), ErrorBody> {
    let output = &args.output;
    check_output(output, false)?;
    let samples = limits.samples(output.samples as usize, "--samples")?;
    let points = through_points(&args.through)?;
    let options = args.conditions.options(points.len(), args.closed)?;
    let spline = SplineInput {
        points,
        alpha: args.alpha,
        closed: args.closed,
        options,
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

/// A spline's conditions beyond its points, slope and closure: point types, straight spans
/// and an open spline's end directions and curvatures. The same flags in `lac spline` and,
/// with `--through`, in `lac export`.
#[derive(Args, Debug)]
pub(crate) struct SplineConditions {
    /// Open splines: the tangent direction at the first point, radians
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "through",
        conflicts_with = "closed"
    )]
    pub(crate) start_angle: Option<f64>,

    /// Open splines: the tangent direction at the last point, radians
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "through",
        conflicts_with = "closed"
    )]
    pub(crate) end_angle: Option<f64>,

    /// The type of each point, one letter a point: s smooth (G2, tangent solved), t tangent
    /// (G2, its direction given in --angles), c corner (the tangent may break; each side
    /// free or given in --angles as i:in/out), e.g. "c s t s c"
    #[arg(long, value_name = "TYPES", requires = "through")]
    pub(crate) types: Option<String>,

    /// The directions of the tangent points "i:θ,…" (radians, i counted from 0), and of
    /// corners' sides "i:in/out" (either may be empty: free)
    #[arg(
        long,
        value_name = "ANGLES",
        allow_hyphen_values = true,
        requires_all = ["through", "types"]
    )]
    pub(crate) angles: Option<String>,

    /// Straight spans "i-j,…" between consecutive points (j = i + 1, or 0 after the last
    /// point of a closed spline): the curve on either side meets each with zero curvature
    /// (needs alpha < 0) unless the point there is a corner
    #[arg(long, value_name = "SPANS", requires = "through")]
    pub(crate) lines: Option<String>,

    /// Open splines: the signed curvature at the first point (with --start-angle, a G2
    /// Hermite end that blends into a neighbouring curve)
    #[arg(
        long,
        value_name = "K",
        allow_hyphen_values = true,
        requires = "through",
        conflicts_with = "closed"
    )]
    pub(crate) start_curvature: Option<f64>,

    /// Open splines: the signed curvature at the last point
    #[arg(
        long,
        value_name = "K",
        allow_hyphen_values = true,
        requires = "through",
        conflicts_with = "closed"
    )]
    pub(crate) end_curvature: Option<f64>,
}

impl SplineConditions {
    /// The flags given, for `lac export`'s usage errors (the end angles aside: see
    /// [`SplineExport::given`]).
    pub(crate) fn given(&self) -> Vec<Flag> {
        present([
            Flag::other("--types", self.types.is_some()),
            Flag::other("--angles", self.angles.is_some()),
            Flag::other("--lines", self.lines.is_some()),
            Flag::other("--start-curvature", self.start_curvature.is_some()),
            Flag::other("--end-curvature", self.end_curvature.is_some()),
        ])
    }

    /// The point types, straight spans and end conditions for `n` points of a spline,
    /// `closed` or open; malformed or misplaced ones are usage errors.
    pub(crate) fn options(&self, n: usize, closed: bool) -> Result<SplineOptions, ErrorBody> {
        let mut types = match &self.types {
            None => Vec::new(),
            Some(text) => {
                let letters: Vec<&str> = text
                    .split(|c: char| c == ',' || c.is_whitespace())
                    .filter(|t| !t.is_empty())
                    .collect();
                if letters.len() != n {
                    return Err(errors::usage(format!(
                        "--types has {} letters for {n} points: give one of s, t, c per point",
                        letters.len()
                    )));
                }
                letters
                    .iter()
                    .map(|l| {
                        point_type_named(l).ok_or_else(|| {
                            errors::usage(format!(
                            "--types: {l:?} is not a point type (s smooth, t tangent, c corner)"
                        ))
                        })
                    })
                    .collect::<Result<Vec<_>, _>>()?
            }
        };
        for item in self.angles.iter().flat_map(|a| a.split(',')) {
            let item = item.trim();
            if item.is_empty() {
                continue;
            }
            let bad = || errors::usage(format!("--angles: {item:?} is not i:θ or i:in/out"));
            let (i, value) = item.split_once(':').ok_or_else(bad)?;
            let i: usize = i.trim().parse().map_err(|_| bad())?;
            let angle = |t: &str| -> Result<Option<f64>, ErrorBody> {
                let t = t.trim();
                if t.is_empty() {
                    return Ok(None);
                }
                let a: f64 = t.parse().map_err(|_| bad())?;
                if a.is_finite() {
                    Ok(Some(a))
                } else {
                    Err(bad())
                }
            };
            match (types.get(i).copied(), value.split_once('/')) {
                (Some(PointType::Tangent(_)), None) => {
                    types[i] = PointType::Tangent(angle(value)?.ok_or_else(bad)?);
                }
                (Some(PointType::Corner { .. }), Some((before, after))) => {
                    types[i] = PointType::Corner {
                        before: angle(before)?,
                        after: angle(after)?,
                    };
                }
                (Some(PointType::Corner { .. }), None) => {
                    return Err(errors::usage(format!(
                        "--angles: point {i} is a corner: give its two sides as {i}:in/out"
                    )))
                }
                (Some(_), _) => {
                    return Err(errors::usage(format!(
                        "--angles: point {i} is smooth: type it t (tangent) or c (corner) in \
                     --types to give it a direction"
                    )))
                }
                (None, _) => {
                    return Err(errors::usage(format!("--angles: there is no point {i}")));
                }
            }
        }
        if let Some(i) = types
            .iter()
            .position(|t| matches!(t, PointType::Tangent(a) if a.is_nan()))
        {
            return Err(errors::usage(format!(
                "point {i} is a tangent point: give its direction in --angles as {i}:θ"
            )));
        }
        let mut lines = Vec::new();
        for item in self.lines.iter().flat_map(|l| l.split(',')) {
            let item = item.trim();
            if item.is_empty() {
                continue;
            }
            let bad = || {
                errors::usage(format!(
                    "--lines: {item:?} is not a span i-j between consecutive points (j = i + 1, \
                 or 0 after the last point of a closed spline)"
                ))
            };
            let (i, j) = item.split_once('-').ok_or_else(bad)?;
            let (i, j): (usize, usize) = (
                i.trim().parse().map_err(|_| bad())?,
                j.trim().parse().map_err(|_| bad())?,
            );
            let next = if closed { (i + 1) % n } else { i + 1 };
            if i >= n || j != next {
                return Err(bad());
            }
            lines.push(i);
        }
        Ok(SplineOptions {
            types,
            lines,
            start: SplineEnd {
                angle: self.start_angle,
                curvature: self.start_curvature,
            },
            end: SplineEnd {
                angle: self.end_angle,
                curvature: self.end_curvature,
            },
        })
    }
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
    /// --alpha, --closed, and the end angles, point types, straight spans and end curvatures
    /// below as lac spline takes them
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        conflicts_with_all = ["points", "input", "polygon"]
    )]
    pub(crate) through: Option<String>,

    /// Point types, straight spans and end conditions, as in `lac spline`.
    #[command(flatten)]
    pub(crate) conditions: SplineConditions,
}

impl ExportSource for SplineExport {
    /// The flags given. Without `--through`, clap refuses them all, except beside
    /// `--points`, `--polygon` or FILE, which rule `--through` out: there `--start-angle` and
    /// `--end-angle` are ignored, as they always were, and the others are listed, so that
    /// no other kind answers and [`SplineExport::export_input`] refuses them.
    fn given(&self) -> Vec<Flag> {
        let conditions = self.conditions.given();
        if self.through.is_none() {
            return conditions;
        }
        let mut given = present([
            Flag::other("--through", true),
            Flag::other("--start-angle", self.conditions.start_angle.is_some()),
            Flag::other("--end-angle", self.conditions.end_angle.is_some()),
        ]);
        given.extend(conditions);
        given
    }

    /// The spline through `--through`, with `--alpha` and the conditions given; other kinds'
    /// slopes are refused, and so are the conditions without `--through`.
    fn export_input(
        &self,
        curve: &CurveFlags,
        others: &[Flag],
    ) -> Option<Result<Input, ErrorBody>> {
        let Some(through) = self.through.as_deref() else {
            let stray = self.conditions.given();
            return (!stray.is_empty()).then(|| {
                Err(errors::usage(format!(
                    "there is no spline for {} without --through (the points it passes through)",
                    names(&stray)
                )))
            });
        };
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
                    let options = self.conditions.options(points.len(), curve.closed)?;
                    SplineInput {
                        points,
                        alpha,
                        closed: curve.closed,
                        options,
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
