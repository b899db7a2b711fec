//! `lac lcg`: the curvature plot and the logarithmic curvature graph (LCG) of Bézier pieces
//! or of a log-aesthetic curve, with the slope α of the line fitted to the graph (seed 001
//! §6, docs/math.md §1), or the curvature and torsion graphs of a space curve with their slopes α and
//! β (seed 003), as JSON, CSV, SVG or PNG.
//!
//! The input is one JSON document ([`LcgInput`]): `lac quasi` output, or one result of `lac
//! segment`, `lac compound` or `lac space`, which is solved again from its points and
//! parameters.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use lac::Curve;
use lac_io::json::{to_line, ErrorBody, LcgInput, LcgReport, Report, SpaceLcgReport};

use crate::input::read_document;
use crate::limits::Limits;
use crate::output::{refuse_binary_on_terminal, write_document};
use crate::raster;
use crate::svg;

/// Curvature points per Bézier piece when `--samples` is not given.
const PER_PIECE: usize = 64;
/// Curvature points along a log-aesthetic or space curve when `--samples` is not given.
const ALONG_CURVE: usize = 257;

/// What to give when there is nothing to read.
const HINT: &str = "give a FILE of JSON, or pipe it into standard input (for example lac \
                    quasi … | lac lcg); '-' reads the terminal";

/// The report and its drawing, whatever the input.
enum Analysis {
    /// A planar curve or Bézier pieces: the report, the arc lengths of the joints, a title.
    Plane(LcgReport, Vec<f64>, String),
    /// A space curve: its two graphs and a title.
    Space(SpaceLcgReport, String),
}

/// Arguments of `lac lcg`.
#[derive(Debug, Args)]
pub(crate) struct LcgArgs {
    /// The JSON to analyse ("-" or nothing: standard input): {"pieces":[{"points":[[x,y],…],
    /// "weights":[…]},…]} with four points a piece and optional weights (the output of lac
    /// quasi), one result of lac segment or lac compound, or one result of lac space; at most
    /// 64 MiB (1 GiB with --allow-large)
    #[arg(value_name = "FILE")]
    pub(crate) input: Option<PathBuf>,

    /// Curvature points: for Bézier pieces, per piece, equally spaced in t (default 64); for a
    /// log-aesthetic curve (and each of its pieces) or a space curve, in all, equally spaced in
    /// arc length (default 257); at most 1,000,000 points in all (10,000,000 with
    /// --allow-large)
    #[arg(
        long,
        value_name = "N",
        value_parser = clap::value_parser!(u32).range(2..)
    )]
    pub(crate) samples: Option<u32>,

    /// Output format
    #[arg(long, value_enum, default_value_t = LcgFormat::Json)]
    pub(crate) format: LcgFormat,

    /// Write to FILE instead of standard output ("-": standard output; a PNG is not written
    /// to a terminal)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac lcg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum LcgFormat {
    /// One line: points [{s, kappa, dkappa_ds, log_rho, log_lcg}] and fit {alpha, intercept,
    /// rms_residual, max_residual, log_rho} (null when there is no line), with "pieces"
    /// [{s, fit}] for a compound curve and "monotone": false and "note" when the curvature is
    /// not monotone; for a space curve {"curvature":{points [{s, x, y}], fit {slope, intercept,
    /// rms_residual, max_residual, x}}, "torsion":{…}} (the slopes are alpha and beta)
    Json,
    /// A header s,kappa,dkappa_ds,log_rho,log_lcg (a space curve: s,log_rho,log_lcg,log_mu,
    /// log_ltg) and one row per point, empty where there is no graph point; first a comment
    /// line "# …" with the note when there is one
    Csv,
    /// Two panels: the curvature plot and the logarithmic curvature graph with its line(s);
    /// for a space curve the curvature and torsion graphs with their lines
    Svg,
    /// The same picture as svg, rendered
    Png,
}

/// Run `lac lcg`.
pub(crate) fn run(args: &LcgArgs, limits: Limits) -> Result<(), ErrorBody> {
    if args.format == LcgFormat::Png {
        refuse_binary_on_terminal(args.file.as_deref(), "PNG", "--format svg")?;
    }
    let text = read_document(args.input.as_deref(), limits.document(), HINT)?;
    let samples = args.samples.map(|n| n as usize);
    let analysis = match LcgInput::parse(&text)? {
        LcgInput::Pieces(input) => {
            let pieces = input.to_rational_cubics()?;
            let n = samples.unwrap_or(PER_PIECE);
            limits.samples((n - 1) * pieces.len() + 1, "--samples (per piece, in all)")?;
            let report = LcgReport::of_pieces(&pieces, n)?;
            // Piece k ends at plot point k·(n − 1): consecutive pieces share that point.
            let joints = (1..pieces.len())
                .map(|k| report.points[k * (n - 1)].s)
                .collect();
            Analysis::Plane(report, joints, svg::lcg::bezier_title(&pieces))
        }
        LcgInput::Curve(input) => {
            let solved = input.solve()?;
            let curve = solved.curve();
            let n = samples.unwrap_or(ALONG_CURVE);
            let plots = if curve.pieces().len() > 1 {
                1 + curve.pieces().len()
            } else {
                1
            };
            limits.samples(n * plots, "--samples (each piece's own, in all)")?;
            let report = LcgReport::of_curve(curve, n)?;
            let title = svg::lcg::lac_title(curve.pieces());
            Analysis::Plane(report, curve.joint_arc_lengths(), title)
        }
        LcgInput::Space(input) => {
            let segment = input.solve()?;
            let n = limits.samples(samples.unwrap_or(ALONG_CURVE), "--samples")?;
            let report = SpaceLcgReport::new(&segment, n)?;
            Analysis::Space(report, svg::lcg::space_title(&segment))
        }
    };
    let svg = |analysis: &Analysis| match analysis {
        Analysis::Plane(report, joints, title) => svg::lcg::render(report, joints, title),
        Analysis::Space(report, title) => svg::lcg::render_space(report, title),
    };
    let document: Vec<u8> = match (args.format, &analysis) {
        (LcgFormat::Json, Analysis::Plane(report, ..)) => line(report),
        (LcgFormat::Json, Analysis::Space(report, _)) => line(report),
        (LcgFormat::Csv, Analysis::Plane(report, ..)) => report.to_csv().into_bytes(),
        (LcgFormat::Csv, Analysis::Space(report, _)) => report.to_csv().into_bytes(),
        (LcgFormat::Svg, analysis) => svg(analysis).into_bytes(),
        (LcgFormat::Png, analysis) => raster::png(&svg(analysis))?,
    };
    write_document(args.file.as_deref(), &document)
}

/// A report (checked when it was made) as one line of JSON.
fn line<T: Report>(report: &T) -> Vec<u8> {
    (to_line(report) + "\n").into_bytes()
}
