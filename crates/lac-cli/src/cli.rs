//! The command-line grammar (clap derive). Help texts here are what `lac --help` shows.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

/// Log-aesthetic curves: segments from three control points, and drawable regions.
///
/// Errors go to standard error as one line of JSON, {"error":{"kind":…,"message":…}}, with
/// exit code 2 for invalid input, 3 when the points and alpha admit no segment, 1 for I/O.
#[derive(Debug, Parser)]
#[command(name = "lac", version, max_term_width = 100)]
pub(crate) struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub(crate) command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Solve the segment for three control points and alpha; print samples as JSON, CSV or SVG
    #[command(
        override_usage = "lac segment --points \"x0,y0 x1,y1 x2,y2\" --alpha A [OPTIONS]\n       \
                                lac segment --batch FILE.jsonl [--samples N] [-o FILE]"
    )]
    Segment(SegmentArgs),
    /// Map where the middle control point gives a segment (seed 000 Fig. 9), as PNG or JSON
    Region(RegionArgs),
}

/// Arguments of `lac segment`.
#[derive(Debug, Args)]
pub(crate) struct SegmentArgs {
    /// The control points "x0,y0 x1,y1 x2,y2", separated by spaces and/or semicolons
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// Slope of the logarithmic curvature graph (-1 clothoid, 0 Nielsen spiral, 1 logarithmic
    /// spiral, 2 circle involute)
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha: Option<f64>,

    /// Read one JSON object {"points":[[x,y],[x,y],[x,y]],"alpha":A} per line ("-" for standard
    /// input) and write one JSON line per input line: the result or {"error":…}
    #[arg(long, value_name = "FILE.jsonl", conflicts_with_all = ["points", "alpha"])]
    pub(crate) batch: Option<PathBuf>,

    /// Number of samples, equally spaced in arc length from the first to the last point (the
    /// number of comb teeth in SVG)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 65,
        value_parser = clap::value_parser!(u32).range(2..=10_000_000)
    )]
    pub(crate) samples: u32,

    /// Output format
    #[arg(long, value_enum, default_value_t = SegmentFormat::Json)]
    pub(crate) format: SegmentFormat,

    /// Write to FILE instead of standard output
    #[arg(short, long, value_name = "FILE")]
    pub(crate) output: Option<PathBuf>,

    /// SVG: draw the curvature comb (normals scaled by curvature, on the convex side)
    #[arg(long)]
    pub(crate) comb: bool,

    /// SVG: draw the evolute (the centres of curvature), clipped near the drawing
    #[arg(long)]
    pub(crate) evolute: bool,
}

/// Output formats of `lac segment`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum SegmentFormat {
    /// One line: alpha, lambda, arc_length, curvature_start/end, samples [{s,x,y,theta,kappa}]
    Json,
    /// A header s,x,y,theta,kappa and one row per sample
    Csv,
    /// A drawing of the curve and its control polygon
    Svg,
}

/// Arguments of `lac region`.
#[derive(Debug, Args)]
pub(crate) struct RegionArgs {
    /// Slope of the logarithmic curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: f64,

    /// Width and height of the map in pixels, 1 to 8192; the map covers [-1,1]² with the
    /// first point at (-1,0) and the last at (1,0)
    #[arg(
        long,
        value_name = "PIXELS",
        default_value_t = 512,
        value_parser = clap::value_parser!(u32).range(1..=8192)
    )]
    pub(crate) size: u32,

    /// Write to FILE instead of standard output (PNG goes to standard output only when it is
    /// not a terminal)
    #[arg(short, long, value_name = "FILE")]
    pub(crate) output: Option<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = RegionFormat::Png)]
    pub(crate) format: RegionFormat,
}

/// Output formats of `lac region`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum RegionFormat {
    /// 8-bit grayscale: white where drawable, black where not; row 0 is y = +1
    Png,
    /// {"alpha","size","extent","first","last","drawable_fraction","drawable":[[bool…]…]}
    Json,
}
