//! The command-line grammar (clap derive). Help texts here are what `lac --help` shows.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::failure::Failure;

/// Log-aesthetic curves: segments from three control points, compound-rhythm curves of two
/// pieces, drawable regions, their cubic Bézier replacements, curvature analysis, and space
/// curve segments from four control points.
///
/// Errors go to standard error as one line of JSON, {"error":{"kind":…,"message":…}}, with
/// exit code 2 for invalid input, 3 when the points and slopes admit no curve (or no Bézier
/// fit meets the request), 1 for I/O.
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
    /// Solve a compound-rhythm curve (two pieces, slopes alpha0 then alpha1, joined with G3
    /// continuity) for three points and a turning ratio, or four control points
    #[command(
        override_usage = "lac compound --points \"x0,y0 x1,y1 x2,y2\" --alpha0 A --alpha1 B --ratio R \
                                [OPTIONS]\n       \
                                lac compound --points \"x0,y0 x1,y1 x2,y2 x3,y3\" --alpha0 A --alpha1 B \
                                [OPTIONS]\n       \
                                lac compound --batch FILE.jsonl [--samples N] [-o FILE]"
    )]
    Compound(CompoundArgs),
    /// Map where the middle control point gives a segment (seed 000 Fig. 9), or a compound
    /// curve, as PNG or JSON
    #[command(
        override_usage = "lac region --alpha A [--size PIXELS] [--format png|json] [-o FILE]\n       \
                                lac region --alpha A --alpha1 B --ratio R [OPTIONS]"
    )]
    Region(RegionArgs),
    /// Replace a segment or compound curve by rational (or plain) cubic Bézier pieces with its
    /// end points, tangents and curvatures (seed 001): one piece, or as many as a tolerance
    /// needs; print them as JSON or draw them over the curve
    ///
    /// Each piece has its control points and weights, its curvature verdict ("monotone", with
    /// "proven" true when it is a proof, and "t" where dκ/ds changes sign if not monotone), the
    /// turning of the curve at its ends (radians from the first point) and its largest
    /// deviation from the curve in the points' units; "rms" and "max" are relative to the arc
    /// length.
    #[command(
        override_usage = "lac quasi --points \"x0,y0 x1,y1 x2,y2\" --alpha A [--tolerance T [--cubic]] \
                                [--format json|svg] [-o FILE]\n       \
                                lac quasi --points \"x0,y0 x1,y1 x2,y2\" --alpha0 A --alpha1 B --ratio R \
                                [OPTIONS]\n       \
                                lac quasi --points \"x0,y0 x1,y1 x2,y2 x3,y3\" --alpha0 A --alpha1 B \
                                [OPTIONS]"
    )]
    Quasi(QuasiArgs),
    /// Decide, with a proof, whether the curvature of a (rational) cubic Bézier curve is
    /// monotone
    ///
    /// Prints one line, {"verdict":"increasing"|"decreasing"|"constant"|"not_monotone",
    /// "proven":true|false}, with "t", a parameter where dκ/ds changes sign, when not monotone.
    /// "proven" is false where dκ/ds is zero within rounding (always for a circular arc).
    #[command(
        override_usage = "lac monotone --points \"x0,y0 x1,y1 x2,y2 x3,y3\" [--weights \"w0,w1,w2,w3\"]"
    )]
    Monotone(MonotoneArgs),
    /// Curvature plot and logarithmic curvature graph, with its fitted slope alpha, of Bézier
    /// pieces (lac quasi output) or of a lac segment or lac compound result
    ///
    /// The graph plots ln ρ against ln(ρ |ds/dρ|) with the exact dκ/ds of each piece; its line
    /// is fitted by least squares weighted along ln ρ, so a log-aesthetic curve gives its own
    /// alpha back.
    #[command(
        override_usage = "lac lcg [FILE|-] [--samples N] [--format json|csv|svg|png] [-o FILE]"
    )]
    Lcg(LcgArgs),
    /// Solve a log-aesthetic space curve segment (seed 003) for four control points, the
    /// slopes alpha and beta of its curvature and torsion graphs, and the torsion parameter
    /// omega; print its standard form and samples as JSON, draw it as SVG, or export it as an
    /// OBJ or PLY polyline
    ///
    /// The JSON has "standard_form" {alpha, beta, lambda, omega, nu, type, s_end}, "transform"
    /// {scale, rotation, translation, mirror_z, reversed} (your point = translation + scale ·
    /// rotation · M · standard-form point, M = diag(1, 1, -1) when mirror_z; when reversed
    /// the standard form runs from the last point to the first), "arc_length", "planar" and
    /// "samples" [{s, x, y, z, kappa, tau}] equally spaced in arc length from the first point.
    /// Coplanar points give the planar segment through the first point, the tangents'
    /// intersection and the last point (torsion 0): "planar" true, "standard_form" and
    /// "transform" null, and "planar_segment" {alpha, lambda, control_points} and a "note".
    /// When omega is too large the error line has "omega_max", the largest omega that works.
    #[command(
        override_usage = "lac space --points \"x0,y0,z0 x1,y1,z1 x2,y2,z2 x3,y3,z3\" --alpha A --beta B \
                                [--omega W] [--type 1|2]\n                 \
                                [--samples N] [--frames] [--format json|svg|obj|ply] [-o FILE]"
    )]
    Space(SpaceArgs),
    /// Start the interactive editor: a local web server with the editor's page (embedded,
    /// works offline) and its JSON API; prints the URL and serves until interrupted
    #[command(override_usage = "lac serve [--port P] [--open] [--host ADDR --allow-remote]")]
    Serve(ServeArgs),
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

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// Arguments of `lac compound`.
#[derive(Debug, Args)]
pub(crate) struct CompoundArgs {
    /// Three points "x0,y0 x1,y1 x2,y2" (the ends and the intersection of the end tangents;
    /// give --ratio) or four control points "x0,y0 x1,y1 x2,y2 x3,y3" (the joint's tangent is
    /// parallel to the middle leg), separated by spaces and/or semicolons
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// Slope of the logarithmic curvature graph of the piece from the first point to the joint
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha0: Option<f64>,

    /// Slope of the piece from the joint to the last point (alpha0 < alpha1: a "valley" in the
    /// curvature graph; alpha0 > alpha1: a "mountain")
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) alpha1: Option<f64>,

    /// Three points only: the share of the total turning made by the alpha0 piece, strictly
    /// between 0 and 1
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,

    /// Read one JSON object per line ("-" for standard input), {"points":[[x,y],[x,y],[x,y]],
    /// "alpha0":A,"alpha1":B,"ratio":R} or {"points":[[x,y],[x,y],[x,y],[x,y]],"alpha0":A,
    /// "alpha1":B}, and write one JSON line per input line: the result or {"error":…}
    #[arg(
        long,
        value_name = "FILE.jsonl",
        conflicts_with_all = ["points", "alpha0", "alpha1", "ratio"]
    )]
    pub(crate) batch: Option<PathBuf>,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// The output options shared by `lac segment` and `lac compound`.
#[derive(Debug, Args)]
pub(crate) struct CurveOutput {
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
    #[arg(long, value_enum, default_value_t = CurveFormat::Json)]
    pub(crate) format: CurveFormat,

    /// Write to FILE instead of standard output
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,

    /// SVG: draw the curvature comb (normals scaled by curvature, on the convex side)
    #[arg(long)]
    pub(crate) comb: bool,

    /// SVG: draw the evolute (the centres of curvature), clipped near the drawing
    #[arg(long)]
    pub(crate) evolute: bool,
}

impl CurveOutput {
    /// Reject combinations of flags that would be silently ignored; `batch`: is `--batch`
    /// given?
    pub(crate) fn check(&self, batch: bool) -> Result<(), Failure> {
        if batch && self.format != CurveFormat::Json {
            return Err(Failure::usage(
                "--batch writes JSON lines; --format csv and svg need --points",
            ));
        }
        if (self.comb || self.evolute) && self.format != CurveFormat::Svg {
            return Err(Failure::usage(
                "--comb and --evolute draw; add --format svg",
            ));
        }
        Ok(())
    }
}

/// Output formats of `lac segment` and `lac compound`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum CurveFormat {
    /// One line: the slope(s), lambda, arc_length, curvature_start/end (compound curves also
    /// joint_s, curvature_joint, joint, lcg), samples [{s,x,y,theta,kappa}]
    Json,
    /// A header s,x,y,theta,kappa and one row per sample
    Csv,
    /// A drawing of the curve and its control polygon (and the joint of a compound curve)
    Svg,
}

/// Arguments of `lac space`.
#[derive(Debug, Args)]
pub(crate) struct SpaceArgs {
    /// The four control points "x0,y0,z0 x1,y1,z1 x2,y2,z2 x3,y3,z3", separated by spaces
    /// and/or semicolons: the curve starts at the first point, tangent to the first leg, and
    /// ends at the last point, tangent to the last leg
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: String,

    /// Slope of the logarithmic curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: f64,

    /// Slope of the logarithmic torsion graph
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) beta: f64,

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

    /// Number of samples, equally spaced in arc length from the first to the last point (the
    /// vertices of OBJ and PLY)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 65,
        value_parser = clap::value_parser!(u32).range(2..=10_000_000)
    )]
    pub(crate) samples: u32,

    /// JSON: add each sample's Frenet frame, unit vectors "t" (tangent), "n" (principal
    /// normal) and "b" (binormal)
    #[arg(long)]
    pub(crate) frames: bool,

    /// Output format
    #[arg(long, value_enum, default_value_t = SpaceFormat::Json)]
    pub(crate) format: SpaceFormat,

    /// Write to FILE instead of standard output
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac space`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum SpaceFormat {
    /// One line: standard_form, transform, arc_length, planar, samples [{s,x,y,z,kappa,tau}]
    Json,
    /// Top (xy), front (xz) and side (yz) views at one scale, and a perspective view with
    /// the curve's shadow
    Svg,
    /// Wavefront OBJ: a vertex "v x y z" per sample and one polyline "l 1 2 … N"
    Obj,
    /// ASCII PLY: vertices (x, y, z, kappa, tau) and an edge between consecutive samples
    Ply,
}

/// Arguments of `lac region`.
#[derive(Debug, Args)]
pub(crate) struct RegionArgs {
    /// Slope of the logarithmic curvature graph (with --alpha1 and --ratio: alpha0, the slope
    /// of the compound curve's piece from the first point)
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: f64,

    /// Map compound-rhythm curves instead of segments: the slope of the piece that ends at the
    /// last point (give --ratio too)
    #[arg(long, value_name = "B", allow_hyphen_values = true, requires = "ratio")]
    pub(crate) alpha1: Option<f64>,

    /// Compound curves: the share of the turning made by the --alpha piece, strictly between
    /// 0 and 1 (give --alpha1 too)
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "alpha1"
    )]
    pub(crate) ratio: Option<f64>,

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
    /// {"alpha","size","extent","first","last","drawable_fraction","drawable":[[bool…]…]},
    /// with "alpha1" and "ratio" after "alpha" for compound curves
    Json,
}

/// Arguments of `lac quasi`.
#[derive(Debug, Args)]
pub(crate) struct QuasiArgs {
    /// The control points, separated by spaces and/or semicolons: three with --alpha (a
    /// segment), three with --alpha0, --alpha1 and --ratio, or four with --alpha0 and --alpha1
    /// (a compound curve, as in lac compound)
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: String,

    /// A segment: the slope of its logarithmic curvature graph
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        conflicts_with_all = ["alpha0", "alpha1", "ratio"]
    )]
    pub(crate) alpha: Option<f64>,

    /// A compound curve: the slope of the piece from the first point to the joint
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        requires = "alpha1"
    )]
    pub(crate) alpha0: Option<f64>,

    /// A compound curve: the slope of the piece from the joint to the last point
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        requires = "alpha0"
    )]
    pub(crate) alpha1: Option<f64>,

    /// A compound curve from three points: the share of the turning made by the alpha0
    /// piece, strictly between 0 and 1
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "alpha0"
    )]
    pub(crate) ratio: Option<f64>,

    /// Use as many pieces as needed for a maximum deviation of T times the arc length (1e-12
    /// to 1), each with curvature proven monotone, joined with continuous curvature. Without
    /// it: the single rational cubic of seed 001
    #[arg(long, value_name = "T")]
    pub(crate) tolerance: Option<f64>,

    /// Plain cubic Bézier pieces (all weights 1) instead of rational ones, for consumers that
    /// only take cubics (needs --tolerance)
    #[arg(long, requires = "tolerance")]
    pub(crate) cubic: bool,

    /// Output format
    #[arg(long, value_enum, default_value_t = QuasiFormat::Json)]
    pub(crate) format: QuasiFormat,

    /// Write to FILE instead of standard output
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac quasi`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum QuasiFormat {
    /// One line: pieces [{points, weights, monotone, proven, turning, max_deviation}], rms,
    /// max (relative to the arc length), arc_length, tolerance, kind ("rational" or "cubic")
    Json,
    /// The Bézier pieces over the log-aesthetic curve, their control polygons and joints, and
    /// the curvature combs of both
    Svg,
}

/// Arguments of `lac monotone`.
#[derive(Debug, Args)]
pub(crate) struct MonotoneArgs {
    /// The four control points "x0,y0 x1,y1 x2,y2 x3,y3", separated by spaces and/or
    /// semicolons
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: String,

    /// The four weights "w0,w1,w2,w3", all positive (default 1,1,1,1: a plain cubic)
    #[arg(long, value_name = "WEIGHTS")]
    pub(crate) weights: Option<String>,
}

/// Arguments of `lac lcg`.
#[derive(Debug, Args)]
pub(crate) struct LcgArgs {
    /// The JSON to analyse ("-" or nothing: standard input): {"pieces":[{"points":[[x,y],…],
    /// "weights":[…]},…]} with four points a piece and optional weights (the output of lac
    /// quasi), or one result of lac segment or lac compound
    #[arg(value_name = "FILE")]
    pub(crate) input: Option<PathBuf>,

    /// Curvature points: for Bézier pieces, per piece, equally spaced in t (default 64); for a
    /// log-aesthetic curve, in all, equally spaced in arc length (default 257)
    #[arg(
        long,
        value_name = "N",
        value_parser = clap::value_parser!(u32).range(2..=1_000_000)
    )]
    pub(crate) samples: Option<u32>,

    /// Output format
    #[arg(long, value_enum, default_value_t = LcgFormat::Json)]
    pub(crate) format: LcgFormat,

    /// Write to FILE instead of standard output (PNG goes to standard output only when it is
    /// not a terminal)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac lcg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum LcgFormat {
    /// One line: points [{s, kappa, dkappa_ds, log_rho, log_lcg}] and fit {alpha, intercept,
    /// rms_residual, max_residual, log_rho} (null when there is no line)
    Json,
    /// A header s,kappa,dkappa_ds,log_rho,log_lcg and one row per point (empty where there is
    /// no graph point)
    Csv,
    /// Two panels: the curvature plot and the logarithmic curvature graph with its line
    Svg,
    /// The same picture as svg, rendered
    Png,
}

/// Arguments of `lac serve`.
#[derive(Debug, Args)]
pub(crate) struct ServeArgs {
    /// The port to listen on (0: any free port; the URL printed says which)
    #[arg(long, value_name = "P", default_value_t = 8787)]
    pub(crate) port: u16,

    /// Open the editor in the default web browser
    #[arg(long)]
    pub(crate) open: bool,

    /// The address to listen on; anything but a loopback address needs --allow-remote
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1")]
    pub(crate) host: std::net::IpAddr,

    /// Allow a non-loopback --host: anyone who can reach the port can use the editor's API
    #[arg(long)]
    pub(crate) allow_remote: bool,
}
