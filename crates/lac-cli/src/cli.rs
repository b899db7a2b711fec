//! The command-line grammar (clap derive): the subcommands with their help and usage, and
//! what runs each ([`Command::run`]); the flag groups that several subcommands flatten
//! ([`CurveOutput`], and [`ExportArgs`], which lists the curve kinds' groups of `lac
//! export`). Each subcommand is a module below this one (`cli/segment.rs`, …) with its own
//! flags (`segment::SegmentArgs`) and, for a curve kind, its flags of `lac export`
//! (`path::PathExport`). Help texts are what `lac --help` shows.
//!
//! The same flag means the same thing in every subcommand: `--points` (control points
//! "x,y" or "x,y,z" separated by spaces or semicolons), `--alpha` (a segment's slope),
//! `--alpha0`/`--alpha1`/`--ratio` (a compound curve's), `--samples` (points equally spaced
//! in arc length), `--tolerance` (relative to the arc length; in model units in `export`),
//! `--format`, `-o/--output`
//! (a file, "-" for standard output) and `--batch` (JSON lines in, JSON lines out).
//!
//! A new subcommand is a module below this one, its `mod` line, a variant of [`Command`] and
//! its arm in [`Command::run`]; a new curve kind's flags of `lac export` are a field of
//! [`ExportArgs`] and an entry of [`ExportArgs::sources`]: all in this file.

pub(crate) mod compound;
pub(crate) mod export;
pub(crate) mod fit;
pub(crate) mod lcg;
pub(crate) mod monotone;
pub(crate) mod path;
pub(crate) mod quasi;
pub(crate) mod region;
pub(crate) mod segment;
pub(crate) mod serve;
pub(crate) mod space;
pub(crate) mod spline;

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};
use lac_io::json::ErrorBody;

use crate::limits::Limits;
use compound::{CompoundArgs, CompoundFlags};
use export::{ExportSource, ExportTo};
use fit::FitArgs;
use lcg::LcgArgs;
use monotone::MonotoneArgs;
use path::{PathArgs, PathExport};
use quasi::QuasiArgs;
use region::RegionArgs;
use segment::{SegmentArgs, SegmentExport};
use serve::ServeArgs;
use space::{SpaceArgs, SpaceExport};
use spline::{SplineArgs, SplineExport};

/// Log-aesthetic curves: segments from three control points, compound-rhythm curves of two
/// pieces, drawable regions, their cubic Bézier replacements, curvature analysis, and space
/// curve segments from four control points.
///
/// Errors go to standard error as one line of JSON, {"error":{"kind":…,"message":…}}, with
/// exit code 2 for invalid input (a usage error, a bad number, a limit), 3 when the input
/// admits no curve (or no Bézier fit meets the request), 1 for I/O, 70 for a defect of lac
/// (please report it). Work is limited so that one command needs at most about 1 GB and a
/// few seconds: --samples ≤ 1,000,000, region --size ≤ 2048, batch lines ≤ 1 MiB, input
/// documents ≤ 64 MiB; --allow-large raises these to 10,000,000, 8192, 64 MiB and 1 GiB.
#[derive(Debug, Parser)]
#[command(name = "lac", version, max_term_width = 100)]
pub(crate) struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub(crate) command: Command,

    /// Raise the work limits (--samples to 10,000,000, region --size to 8192, batch lines
    /// to 64 MiB, input documents to 1 GiB): a command may then need several GB and minutes
    #[arg(long, global = true)]
    pub(crate) allow_large: bool,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Solve the segment for three control points and alpha; print samples as JSON, CSV or SVG
    #[command(
        override_usage = "lac segment --points \"x0,y0 x1,y1 x2,y2\" --alpha A [--samples N] \
                                [--format json|csv|svg] [-o FILE|-] [--comb] [--evolute]\n       \
                                lac segment --batch FILE|- [--samples N] [-o FILE|-]"
    )]
    Segment(SegmentArgs),
    /// Solve a compound-rhythm curve (two pieces, slopes alpha0 then alpha1, joined with G3
    /// continuity) for three points and a turning ratio, or four control points
    #[command(
        override_usage = "lac compound --points \"x0,y0 x1,y1 x2,y2\" --alpha0 A --alpha1 B --ratio R \
                                [OPTIONS]\n       \
                                lac compound --points \"x0,y0 x1,y1 x2,y2 x3,y3\" --alpha0 A --alpha1 B \
                                [OPTIONS]\n       \
                                lac compound --batch FILE|- [--samples N] [-o FILE|-]"
    )]
    Compound(CompoundArgs),
    /// Map where the middle control point gives a segment (seed 000 Fig. 9), or a compound
    /// curve, as PNG or JSON
    #[command(
        override_usage = "lac region --alpha A [--size PIXELS] [--format png|json] [-o FILE|-]\n       \
                                lac region --alpha0 A --alpha1 B --ratio R [--size PIXELS] \
                                [--format png|json] [-o FILE|-]"
    )]
    Region(RegionArgs),
    /// Replace a segment or compound curve by rational (or plain) cubic Bézier pieces with its
    /// end points, tangents and curvatures (seed 001): one piece, or as many as a tolerance
    /// needs; print them as JSON or CSV or draw them over the curve
    ///
    /// Each piece has its control points and weights, its curvature verdict ("monotone", with
    /// "proven" true when it is a proof, and "t" where dκ/ds changes sign if not monotone), the
    /// turning of the curve at its ends (radians from the first point) and its largest
    /// deviation from the curve in the points' units; "rms" and "max" are relative to the arc
    /// length.
    #[command(
        override_usage = "lac quasi --points \"x0,y0 x1,y1 x2,y2\" --alpha A [--tolerance T [--cubic]] \
                                [--format json|csv|svg] [-o FILE|-]\n       \
                                lac quasi --points \"x0,y0 x1,y1 x2,y2\" --alpha0 A --alpha1 B --ratio R \
                                [OPTIONS]\n       \
                                lac quasi --points \"x0,y0 x1,y1 x2,y2 x3,y3\" --alpha0 A --alpha1 B \
                                [OPTIONS]\n       \
                                lac quasi --batch FILE|- [-o FILE|-]"
    )]
    Quasi(QuasiArgs),
    /// Decide, with a proof, whether the curvature of a (rational) cubic Bézier curve is
    /// monotone: of one curve, or of every piece that lac quasi prints
    ///
    /// Prints one line, {"verdict":"increasing"|"decreasing"|"constant"|"not_monotone",
    /// "proven":true|false}, with "t", a parameter where dκ/ds changes sign, when not monotone;
    /// for a chain of pieces ({"pieces":[…]}, as lac quasi prints) {"pieces":[{"verdict":…,
    /// "proven":…},…]}, a verdict for each piece. "proven" is false where dκ/ds is zero within
    /// rounding (always for a circular arc).
    #[command(
        override_usage = "lac monotone --points \"x0,y0 x1,y1 x2,y2 x3,y3\" [--weights \"w0,w1,w2,w3\"] \
                                [-o FILE|-]\n       \
                                lac monotone [FILE|-] [-o FILE|-]        (e.g. lac quasi … | lac monotone)\n       \
                                lac monotone --batch FILE|- [-o FILE|-]"
    )]
    Monotone(MonotoneArgs),
    /// Curvature plot and logarithmic curvature graph, with its fitted slope alpha, of Bézier
    /// pieces (lac quasi output) or of a lac segment or lac compound result; the curvature and
    /// torsion graphs, with their slopes alpha and beta, of a lac space result
    ///
    /// The graph plots ln ρ against ln(ρ |ds/dρ|) with the exact dκ/ds of each piece; its line
    /// is fitted by least squares weighted along ln ρ, so a log-aesthetic curve gives its own
    /// alpha back. A compound curve's report also has each piece's own line ("pieces"). When
    /// the curvature is not monotone (a piece whose dκ/ds changes sign, pieces that turn in
    /// opposite directions, an inflection) the graph is not one line: "fit" is null,
    /// "monotone" false and "note" says where, and no slope is printed.
    #[command(
        override_usage = "lac lcg [FILE|-] [--samples N] [--format json|csv|svg|png] [-o FILE|-]"
    )]
    Lcg(LcgArgs),
    /// Solve a log-aesthetic space curve segment (seed 003) for four control points, the
    /// slopes alpha and beta of its curvature and torsion graphs, and the torsion parameter
    /// omega; print its standard form and samples as JSON or CSV, draw it as SVG, or export
    /// it as an OBJ or PLY polyline
    ///
    /// The JSON has "standard_form" {alpha, beta, lambda, omega, nu, type, s_end}, "transform"
    /// {scale, rotation, translation, mirror_z, reversed} (your point = translation + scale ·
    /// rotation · M · standard-form point, M = diag(1, 1, -1) when mirror_z; when reversed
    /// the standard form runs from the last point to the first), "arc_length", "planar",
    /// "samples" [{s, x, y, z, kappa, tau}] equally spaced in arc length from the first point,
    /// and the input as given ("points", "alpha", "beta", "omega", "type"), so that lac lcg
    /// can read it. Coplanar points give the planar segment through the first point, the
    /// tangents' intersection and the last point (torsion 0): "planar" true, "standard_form"
    /// and "transform" null, and "planar_segment" {alpha, lambda, control_points} and a
    /// "note". When no segment is found for omega but one is for omega = 0, the error line has
    /// "omega_max", where that segment's branch ends as omega grows (every omega up to it has
    /// a segment).
    #[command(
        override_usage = "lac space --points \"x0,y0,z0 x1,y1,z1 x2,y2,z2 x3,y3,z3\" --alpha A --beta B \
                                [--omega W] [--type 1|2]\n                 \
                                [--samples N] [--frames] [--format json|csv|svg|obj|ply] [-o FILE|-]\n       \
                                lac space --batch FILE|- [--samples N] [--frames] [-o FILE|-]"
    )]
    Space(SpaceArgs),
    /// Draw a log-aesthetic path from a control polygon: one segment per interior vertex,
    /// joined on the legs with continuous tangent (G1), and with --g2 continuous curvature
    ///
    /// Each interior vertex Pj carries the segment with control points (Qj, Pj, Qj+1), whose
    /// joints Q lie on the legs (the ends are the first and last point). Without --g2 the
    /// joints are at the leg midpoints (or --fractions); with --g2 they are solved so that
    /// the curvature is continuous at every joint (relative jump at most 1e-9). The JSON has
    /// "continuity", "closed", "arc_length", "max_curvature_jump", "points", "segments"
    /// [{vertex, alpha, lambda, control_points, arc_length, curvature:[start,end]}], "joints"
    /// [{leg, fraction, point, s, curvature:[before,after], curvature_jump, gap,
    /// tangent_jump}], "straight_pieces" [{leg, fractions, points, s, length,
    /// curvature:[before,after]}] and "samples" [{s,x,y,theta,kappa}]. Where the polygon's
    /// turning changes direction, a G2 path passes through zero curvature: the segments on
    /// either side (alpha < 0) end at their inflection points and a straight piece on that
    /// leg joins them (the leg must be long: such a segment's inflection-side leg is 2-5
    /// times its other). When no G2 path is found the error (kind no_g2_path, exit code 3)
    /// names the joint's leg, says why, and gives the fractions of the nearest G1 path (pass
    /// them as --fractions without --g2; also as numbers in "g1_fractions", absent where no
    /// G1 path can be drawn either).
    #[command(
        override_usage = "lac path --polygon \"x0,y0 x1,y1 x2,y2 …\" (--alpha A | --alphas \"a1,a2,…\") \
                                [--closed] [--g2 | --fractions \"t1,t2,…\"]\n                \
                                [--samples N] [--format json|csv|svg] [-o FILE|-] [--comb] [--evolute]"
    )]
    Path(PathArgs),
    /// Export a segment, compound curve, path, spline or space segment for CAD: rational
    /// degree-3 B-splines within a tolerance (DXF, STEP, IGES, JSON) or plain cubic Béziers
    /// (SVG), with the achieved deviation measured densely
    ///
    /// The curve is given as for lac segment, lac compound or lac space (--points with
    /// --alpha; --alpha0, --alpha1 and --ratio; or four 3-D points with --alpha and --beta), or
    /// as one result of those commands (or of lac fit) in FILE or on standard input; or a path (--polygon with
    /// --alpha or --alphas, --closed, --g2 or --fractions, as lac path takes them, or lac
    /// path's result); or a spline (--through with --alpha, --closed, --start-angle,
    /// --end-angle, --types, --angles, --lines, --start-curvature and --end-curvature, as lac
    /// spline takes them, or lac spline's result). Planar curves become the quasi-aesthetic rational cubics of lac quasi
    /// (joined G2, each piece's curvature proven monotone; a path or spline piece by piece,
    /// its joints knots with the curve's continuity: G2, G1 at a G1 path's joints, G0 at a
    /// spline's corners), space curves cubic Hermite pieces (joined C1); the pieces are written as one
    /// clamped B-spline (interior knots of multiplicity 3), or with --pieces as one curve per
    /// piece. Lengths are in model units, declared as millimetres in DXF, STEP and IGES.
    ///
    /// A one-line JSON report goes to standard error: {"format","kind","pieces","single_spans",
    /// "tolerance","max_deviation","fit_deviation","samples_per_piece","arc_length",
    /// "continuity","monotone_proven","polynomial","units"}; max_deviation is the sampled
    /// two-sided distance between the curve written and the exact curve. Exit code 3
    /// (tolerance_not_met, too_many_pieces) when the tolerance cannot be met.
    #[command(
        override_usage = "lac export --format dxf|step|iges|svg|json [--tolerance T | \
                                --relative-tolerance R] [--pieces] -o FILE \
                                --points … --alpha A [--alpha0 A --alpha1 B [--ratio R]] [--beta B \
                                --omega W --type 1|2]\n       \
                                lac export --format … -o FILE --polygon … (--alpha A | \
                                --alphas …) [--closed] [--g2 | --fractions …]\n       \
                                lac export --format … -o FILE --through … --alpha A [--closed] \
                                [--start-angle R] [--end-angle R] [--types \"s t c …\"]\n                  \
                                [--angles \"i:θ,…\"] [--lines \"i-j,…\"] [--start-curvature K] \
                                [--end-curvature K]\n       \
                                lac export [FILE|-] --format … -o FILE      \
                                # a lac segment, compound, path, spline, space or fit result"
    )]
    // Boxed: its groups of flags make it several times the size of the other variants.
    Export(Box<ExportArgs>),
    /// Draw a G2 spline of log-aesthetic segments through points: one segment per span (for
    /// alpha < 0, an S of two segments meeting at zero curvature where the span must
    /// inflect), the tangent angles at the points solved so that the curvature is continuous
    ///
    /// Open splines take their end tangents from --start-angle/--end-angle (radians) or from
    /// the circles through the first and last three points; --start-curvature and
    /// --end-curvature give an end's curvature too (with its angle, a G2 Hermite end).
    /// Points may have types (--types, one letter a point): s smooth, t tangent (G2 with the
    /// direction given in --angles i:θ, e.g. horizontal at an extremum), c corner (the
    /// tangent may break; each side's direction free or given as --angles i:in/out); spans
    /// between consecutive points may be straight (--lines i-j), met by the curve on either
    /// side with zero curvature (alpha < 0 only; a corner there lets the tangent break
    /// instead). A condition that takes a tangent away puts a knot (a G2 joint) in the span
    /// next to it. Closed splines take types, angles and lines too.
    ///
    /// The JSON has "closed", "alpha", "arc_length", "max_curvature_jump", "points",
    /// "angles", "pieces" [{span, control_points, lambda, arc_length, curvature:[start,end]}],
    /// "inflections" [{span, point, curvature}], "curvature_jumps" (at each joint with
    /// continuous curvature), "at_points" [{type, given:[in,out], straight:[in,out],
    /// angles:[in,out], curvatures:[in,out], gap}] (null outside an open spline's ends),
    /// "lines", "start"/"end" ({angle, curvature} when an end curvature is given), "knots"
    /// [{span, point, angle, curvature_jump}] and "samples". A span that would have to
    /// inflect with alpha >= 0, or where no continuous curvature is reached, is named in the
    /// error (kind no_g2_path, exit code 3); so is a point whose type cannot be met, with
    /// what to change; a span whose segment cannot be drawn, likewise.
    #[command(
        override_usage = "lac spline --through \"x0,y0 x1,y1 x2,y2 …\" --alpha A [--closed] \
                                [--start-angle R] [--end-angle R]\n                \
                                [--types \"s t c …\"] [--angles \"i:θ,…\"] [--lines \"i-j,…\"]\n                \
                                [--start-curvature K] [--end-curvature K]\n                \
                                [--samples N] [--format json|csv|svg] [-o FILE|-] [--comb] [--evolute]"
    )]
    Spline(SplineArgs),
    /// Fit a log-aesthetic path to measured points: one least-squares segment, or the fewest
    /// segments (G2, or G1) that keep every point within --tolerance
    ///
    /// The points come from FILE (or standard input), in order along the curve: one a line,
    /// "x y", "x,y" or "x<TAB>y" (further columns ignored, `#` comments, a header line
    /// skipped), or a JSON array [[x,y],…]. Each point's distance is measured orthogonally to
    /// the fit. Without --tolerance it fits --max-segments segments (default 1); with it the
    /// fewest up to --max-segments (default 16), or fails (kind fit_tolerance_not_met, exit
    /// code 3) naming the stretch of points it could not reach and the distance it reached.
    /// α is fitted per segment in -5..10 (--alpha-range, --shared-alpha) or fixed (--alpha).
    ///
    /// The JSON has the path ("continuity", "closed", "arc_length", "max_curvature_jump",
    /// "pieces" [{alpha, curvature:[start,end], arc_length, s, inflection, segments}],
    /// "segments" [{piece, alpha, lambda, start, theta, arc_length, curvature}], "joints"
    /// [{point, s, curvature:[before,after], curvature_jump, gap, tangent_jump}], "samples")
    /// and the fit's figures ("point_count", "tolerance", "fitted_segments", "rms",
    /// "max_distance", "worst_point", "farthest" [{index, point, distance}]). lac export
    /// reads it back.
    #[command(
        override_usage = "lac fit [FILE|-] [--tolerance T] [--max-segments N] [--alpha A | \
                                --alpha-range A,B [--shared-alpha]] [--g1] [--closed | --pin-ends]\n              \
                                [--huber DELTA] [--weighted] [--samples N] [--format json|csv|svg] [-o FILE|-]\n       \
                                lac fit --batch FILE|- [--samples N] [-o FILE|-]"
    )]
    Fit(FitArgs),
    /// Start the interactive editor: a local web server with the editor's page (embedded,
    /// works offline) and its JSON API; prints the URL and serves until interrupted
    #[command(override_usage = "lac serve [--port P] [--open] [--host ADDR --allow-remote]")]
    Serve(ServeArgs),
}

impl Command {
    /// Run the subcommand; `limits`: the work limits (`--allow-large`).
    pub(crate) fn run(&self, limits: Limits) -> Result<(), ErrorBody> {
        match self {
            Command::Segment(args) => segment::run(args, limits),
            Command::Compound(args) => compound::run(args, limits),
            Command::Region(args) => region::run(args, limits),
            Command::Quasi(args) => quasi::run(args, limits),
            Command::Monotone(args) => monotone::run(args, limits),
            Command::Lcg(args) => lcg::run(args, limits),
            Command::Space(args) => space::run(args, limits),
            Command::Path(args) => path::run(args, limits),
            Command::Export(args) => export::run(args, limits),
            Command::Spline(args) => spline::run(args, limits),
            Command::Fit(args) => fit::run(args, limits),
            Command::Serve(args) => serve::run(args),
        }
    }
}

/// The output options shared by `lac segment`, `lac compound`, `lac path` and `lac spline`.
#[derive(Debug, Args)]
pub(crate) struct CurveOutput {
    /// Number of samples, equally spaced in arc length from the first to the last point (the
    /// number of comb teeth in SVG); at most 1,000,000 (10,000,000 with --allow-large)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 65,
        value_parser = clap::value_parser!(u32).range(2..)
    )]
    pub(crate) samples: u32,

    /// Output format
    #[arg(long, value_enum, default_value_t = CurveFormat::Json)]
    pub(crate) format: CurveFormat,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,

    /// SVG: draw the curvature comb (normals scaled by curvature, on the convex side)
    #[arg(long)]
    pub(crate) comb: bool,

    /// SVG: draw the evolute (the centres of curvature), clipped near the drawing
    #[arg(long)]
    pub(crate) evolute: bool,
}

/// Output formats of `lac segment`, `lac compound`, `lac path` and `lac spline`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum CurveFormat {
    /// One line: the slope(s), lambda, arc_length, curvature_start/end (compound curves also
    /// joint_s, curvature_joint, joint, lcg), points, samples [{s,x,y,theta,kappa}]
    Json,
    /// A header s,x,y,theta,kappa and one row per sample
    Csv,
    /// A drawing of the curve and its control polygon (and the joint of a compound curve)
    Svg,
}

/// Arguments of `lac export`: a curve given by the flags of its kind, or a FILE with one.
///
/// Each curve kind has its group here, with only optional flags whose names no other group
/// uses, and implements [`ExportSource`] for it in its module; the flags that several kinds
/// take are [`CurveFlags`]. The help lists the groups in the order of the fields.
#[derive(Debug, Args)]
pub(crate) struct ExportArgs {
    /// One result of lac segment, lac compound, lac path, lac spline, lac space or lac fit to
    /// export
    /// ("-": standard input; nothing, without --points, --polygon or --through: standard
    /// input when it is not a terminal)
    #[arg(value_name = "FILE", conflicts_with = "points")]
    pub(crate) input: Option<PathBuf>,

    /// The flags that several kinds take.
    #[command(flatten)]
    pub(crate) curve: CurveFlags,

    /// A path's.
    #[command(flatten)]
    pub(crate) path: PathExport,

    /// A spline's.
    #[command(flatten)]
    pub(crate) spline: SplineExport,

    /// A compound curve's.
    #[command(flatten)]
    pub(crate) compound: CompoundFlags,

    /// A space segment's.
    #[command(flatten)]
    pub(crate) space: SpaceExport,

    /// The file to write and how.
    #[command(flatten)]
    pub(crate) to: ExportTo,
}

impl ExportArgs {
    /// What to give when there is nothing to read.
    pub(crate) const HINT: &'static str =
        "give --points with --alpha (and --alpha0/--alpha1/--ratio or --beta), --polygon with \
         --alpha or --alphas, --through with --alpha, or a FILE with a lac segment, compound, \
         path, spline, space or fit result, or pipe one in";

    /// The usage error of `--closed` with no kind that closes.
    pub(crate) const CLOSED: &'static str =
        "--closed closes a path's polygon (--polygon) or a spline (--through)";

    /// The usage error of `--points` with flags that make no curve.
    pub(crate) const POINTS: &'static str =
        "give --alpha for a segment, --alpha0 and --alpha1 (and --ratio for three points) for \
         a compound curve, or --alpha and --beta for a space segment";

    /// The usage error of slopes without `--points`, `--polygon` or `--through`.
    pub(crate) const NO_CURVE: &'static str =
        "the curve's parameters need --points (or --polygon for a path)";

    /// The curve kinds, in the order `lac export` asks them what the flags (or a document)
    /// describe. No two kinds answer to the same flags (a path to --polygon, a spline to
    /// --through, a space segment to --points with --beta, a segment or compound curve to
    /// --points with its slopes and no other kind's flags), so the order matters only for
    /// documents: the spline before the path, since a spline's result has a "closed" as a
    /// path's input does.
    pub(crate) fn sources(&self) -> [&dyn ExportSource; 5] {
        [
            &SegmentExport,
            &self.compound,
            &self.spline,
            &self.path,
            &self.space,
        ]
    }
}

/// The flags of `lac export` that several curve kinds take.
#[derive(Debug, Args)]
pub(crate) struct CurveFlags {
    /// The control points: three "x,y" with --alpha (a segment), three with --alpha0,
    /// --alpha1 and --ratio or four with --alpha0 and --alpha1 (a compound curve), or four
    /// "x,y,z" with --alpha and --beta (a space segment)
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: Option<String>,

    /// A segment's (or space segment's, or every path segment's) slope of the logarithmic
    /// curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: Option<f64>,

    /// A path or spline: close the polygon (the spline through the points)
    #[arg(long)]
    pub(crate) closed: bool,
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    /// clap's own checks of the whole grammar: no flag defined twice in one subcommand (by
    /// its flattened groups), every conflict and requirement names a flag of its subcommand.
    #[test]
    fn the_grammar_passes_claps_checks() {
        super::Cli::command().debug_assert();
    }
}
