//! `lac space`: a log-aesthetic space curve segment (seed 003, docs/math.md §6) from four 3-D control
//! points, α, β, Ω and the torsion type, as JSON, CSV, SVG, OBJ or PLY; or many with
//! `--batch`. The space segment in `lac export`: [`SpaceExport`], its flags there.

use std::path::PathBuf;
use std::sync::Arc;

use clap::{Args, ValueEnum};
use lac::SpaceCurve;
use lac::{SpaceSegment, Vec3};
use lac_io::json::{
    parse, to_line, write_line, AnyCurve, ErrorBody, SpaceInput, SpaceReport, PLANAR_NOTE,
};

use crate::batch;
use crate::cli::export::{names, present, ExportSource, Flag, Input};
use crate::cli::CurveFlags;
use crate::errors;
use crate::limits::Limits;
use crate::mesh;
use crate::output::write_document;
use crate::points::parse_space_points;
use crate::svg;

/// Arguments of `lac space`.
#[derive(Debug, Args)]
pub(crate) struct SpaceArgs {
    /// The four control points "x0,y0,z0 x1,y1,z1 x2,y2,z2 x3,y3,z3", separated by spaces
    /// and/or semicolons: the curve starts at the first point, tangent to the first leg, and
    /// ends at the last point, tangent to the last leg
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// Slope of the logarithmic curvature graph
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha: Option<f64>,

    /// Slope of the logarithmic torsion graph
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) beta: Option<f64>,

    /// Torsion parameter, >= 0: how fast the radius of torsion changes along the standard
    /// form (0: constant torsion; with Λ = 0 a helix)
    #[arg(
        long,
        value_name = "W",
        allow_hyphen_values = true,
        default_value_t = 0.0
    )]
    pub(crate) omega: f64,

    /// Torsion type: 1, the radius of torsion grows along the standard form; 2, it shrinks
    #[arg(long = "type", value_name = "1|2", default_value_t = 1)]
    pub(crate) torsion_type: u8,

    /// Read one JSON object {"points":[[x,y,z]×4],"alpha":A,"beta":B,"omega":W,"type":1}
    /// per line (omega 0 and type 1 when absent; "-": standard input) and write one JSON line
    /// per input line, in order: the result, or {"error":…} whose message starts with the
    /// line number (see lac segment --help for the line limit and the exit code)
    #[arg(
        long,
        value_name = "FILE|-",
        conflicts_with_all = ["points", "alpha", "beta", "omega", "torsion_type"]
    )]
    pub(crate) batch: Option<PathBuf>,

    /// Number of samples, equally spaced in arc length from the first to the last point (the
    /// vertices of OBJ and PLY); at most 1,000,000 (10,000,000 with --allow-large)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 65,
        value_parser = clap::value_parser!(u32).range(2..)
    )]
    pub(crate) samples: u32,

    /// JSON and CSV: add each sample's Frenet frame, unit vectors "t" (tangent), "n"
    /// (principal normal) and "b" (binormal)
    #[arg(long)]
    pub(crate) frames: bool,

    /// Output format
    #[arg(long, value_enum, default_value_t = SpaceFormat::Json)]
    pub(crate) format: SpaceFormat,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac space`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum SpaceFormat {
    /// One line: standard_form, transform, arc_length, planar, samples [{s,x,y,z,kappa,tau}],
    /// and the input (points, alpha, beta, omega, type)
    Json,
    /// A header s,x,y,z,kappa,tau (with --frames also tx,ty,tz,nx,ny,nz,bx,by,bz) and one row
    /// per sample
    Csv,
    /// Top (xy), front (xz) and side (yz) views at one scale, and a perspective view with
    /// the curve's shadow
    Svg,
    /// Wavefront OBJ: a vertex "v x y z" per sample and one polyline "l 1 2 … N"
    Obj,
    /// ASCII PLY: vertices (x, y, z, kappa, tau) and an edge between consecutive samples
    Ply,
}

/// Run `lac space`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &SpaceArgs, limits: Limits) -> Result<(), ErrorBody> {
    if args.frames && !matches!(args.format, SpaceFormat::Json | SpaceFormat::Csv) {
        return Err(errors::usage(
            "--frames adds the Frenet frames to the samples; use it with --format json or csv",
        ));
    }
    let samples = limits.samples(args.samples as usize, "--samples")?;
    let frames = args.frames;
    if let Some(input) = &args.batch {
        if args.format != SpaceFormat::Json {
            return Err(errors::usage(
                "--batch writes JSON lines; --format csv, svg, obj and ply need --points",
            ));
        }
        let solve: batch::Solve = Arc::new(move |text, out| solve_line(text, samples, frames, out));
        // A sample with its frame holds about three times the numbers.
        let chunk = batch::chunk_lines(samples * if frames { 3 } else { 1 });
        return batch::run(input, args.file.as_deref(), limits, chunk, solve);
    }
    let (Some(text), Some(alpha), Some(beta)) = (&args.points, args.alpha, args.beta) else {
        return Err(errors::usage(
            "give --points, --alpha and --beta, or --batch FILE",
        ));
    };
    let input = SpaceInput {
        points: parse_space_points(text)?,
        alpha,
        beta,
        omega: args.omega,
        torsion_type: args.torsion_type,
    };
    let segment = input.solve()?;
    let document = match args.format {
        SpaceFormat::Json => to_line(&SpaceReport::new(&segment, samples, frames)?) + "\n",
        SpaceFormat::Csv => SpaceReport::new(&segment, samples, frames)?.to_csv(),
        SpaceFormat::Svg => svg::space::render(&segment)?,
        SpaceFormat::Obj => mesh::obj(
            &segment.sample_by_arc_length(samples)?,
            &header(&segment, samples),
        ),
        SpaceFormat::Ply => mesh::ply(
            &segment.sample_by_arc_length(samples)?,
            &header(&segment, samples),
        ),
    };
    write_document(args.file.as_deref(), document.as_bytes())
}

/// The output line for one `--batch` line: the report, or why there is none.
fn solve_line(
    text: &str,
    samples: usize,
    frames: bool,
    out: &mut Vec<u8>,
) -> Result<(), ErrorBody> {
    let input: SpaceInput = parse(text, SpaceInput::SHAPE)?;
    let report = SpaceReport::new(&input.solve()?, samples, frames)?;
    write_line(&report, out);
    Ok(())
}

/// The comment lines of OBJ and PLY files: what was solved and how to read the numbers.
fn header(segment: &SpaceSegment, samples: usize) -> Vec<String> {
    let points: Vec<String> = segment
        .control_points()
        .iter()
        .map(|Vec3 { x, y, z }| format!("{x:?},{y:?},{z:?}"))
        .collect();
    let mut lines = vec![
        format!(
            "lac space: log-aesthetic space curve segment, alpha {:?}, beta {:?}, omega {:?}, \
             type {}",
            segment.alpha(),
            segment.beta(),
            segment.omega(),
            segment.torsion_type().number()
        ),
        format!("control points {}", points.join(" ")),
    ];
    match (
        segment.standard_form(),
        segment.transform(),
        segment.s_end(),
    ) {
        (Some(form), Some(t), Some(s_end)) => lines.push(format!(
            "standard form lambda {:?}, nu {:?}, s_end {:?}; scale {:?}, mirror_z {}, \
             reversed {}",
            form.lambda(),
            form.nu(),
            s_end,
            t.scale,
            t.mirror_z,
            t.reversed
        )),
        _ => lines.push(PLANAR_NOTE.to_string()),
    }
    lines.push(format!(
        "arc length {:?}; {samples} samples equally spaced in arc length from the first point",
        segment.arc_length()
    ));
    lines
}

/// A space segment's own flags in `lac export` (with `--points` and `--alpha` of
/// [`CurveFlags`]).
#[derive(Debug, Args)]
pub(crate) struct SpaceExport {
    /// A space segment: the slope of the logarithmic torsion graph
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) beta: Option<f64>,

    /// A space segment: the torsion parameter (default 0)
    #[arg(long, value_name = "W", allow_hyphen_values = true)]
    pub(crate) omega: Option<f64>,

    /// A space segment: the torsion type, 1 or 2 (default 1)
    #[arg(long = "type", value_name = "1|2")]
    pub(crate) torsion_type: Option<u8>,
}

impl ExportSource for SpaceExport {
    fn given(&self) -> Vec<Flag> {
        present([
            Flag::slope("--beta", self.beta.is_some()),
            Flag::other("--omega", self.omega.is_some()),
            Flag::other("--type", self.torsion_type.is_some()),
        ])
    }

    /// A space segment when `--points` come with `--beta` (and `--alpha`, without any other
    /// kind's flags); `--omega` and `--type` without `--beta` are refused.
    fn export_input(
        &self,
        curve: &CurveFlags,
        others: &[Flag],
    ) -> Option<Result<Input, ErrorBody>> {
        let text = curve.points.as_deref()?;
        let Some(beta) = self.beta else {
            if self.omega.is_some() || self.torsion_type.is_some() {
                return Some(Err(errors::usage(
                    "--omega and --type belong to a space segment: give --beta and four x,y,z \
                     points",
                )));
            }
            return None;
        };
        let Some(alpha) = curve.alpha else {
            return Some(Err(errors::usage(
                "a space segment needs --alpha with --beta",
            )));
        };
        if !others.is_empty() {
            return Some(Err(errors::usage(format!(
                "--beta is a space segment's: drop {}",
                names(others)
            ))));
        }
        Some(
            parse_space_points(text)
                .and_then(|points| {
                    SpaceInput {
                        points,
                        alpha,
                        beta,
                        omega: self.omega.unwrap_or(0.0),
                        torsion_type: self.torsion_type.unwrap_or(1),
                    }
                    .solve()
                })
                .map(AnyCurve::Space),
        )
    }
}
