//! The command-line grammar (clap derive). Help texts here are what `lac --help` shows.
//!
//! The same flag means the same thing in every subcommand: `--points` (control points
//! "x,y" or "x,y,z" separated by spaces or semicolons), `--alpha` (a segment's slope),
//! `--alpha0`/`--alpha1`/`--ratio` (a compound curve's), `--samples` (points equally spaced
//! in arc length), `--tolerance` (relative to the arc length; in model units in `export`),
//! `--format`, `-o/--output`
//! (a file, "-" for standard output) and `--batch` (JSON lines in, JSON lines out).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

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
    /// "note". When omega is too large the error line has "omega_max", the largest omega that
    /// works.
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
    /// Export a segment, compound curve, path or space segment for CAD: rational degree-3
    /// B-splines within a tolerance (DXF, STEP, IGES, JSON) or plain cubic Béziers (SVG), with
    /// the achieved deviation measured densely
    ///
    /// The curve is given as for lac segment, lac compound or lac space (--points with
    /// --alpha; --alpha0, --alpha1 and --ratio; or four 3-D points with --alpha and --beta), or
    /// as one result of those commands in FILE or on standard input; or a path (--polygon with
    /// --alpha or --alphas, --closed, --g2 or --fractions, as lac path takes them, or lac
    /// path's result). Planar curves become the quasi-aesthetic rational cubics of lac quasi
    /// (joined G2, each piece's curvature proven monotone; a path segment by segment, its
    /// joints knots with the path's continuity, G2 or G1), space curves cubic Hermite pieces (joined C1); the pieces are written as one
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
                                lac export [FILE|-] --format … -o FILE      \
                                # a lac segment, compound, path or space result"
    )]
    Export(ExportArgs),
    /// Draw a G2 spline of log-aesthetic segments through points: one segment per span (for
    /// alpha < 0, an S of two segments meeting at zero curvature where the span must
    /// inflect), the tangent angles at the points solved so that the curvature is continuous
    ///
    /// Open splines take their end tangents from --start-angle/--end-angle (radians) or from
    /// the circles through the first and last three points. The JSON has "closed", "alpha",
    /// "arc_length", "max_curvature_jump", "points", "angles", "pieces" [{span,
    /// control_points, lambda, arc_length, curvature:[start,end]}], "inflections" [{span,
    /// point, curvature}], "curvature_jumps" (at each joint) and "samples". A span that would
    /// have to inflect with alpha >= 0, or where no continuous curvature is reached, is
    /// named in the error (kind no_g2_path, exit code 3); a span whose segment cannot be
    /// drawn, likewise.
    #[command(
        override_usage = "lac spline --through \"x0,y0 x1,y1 x2,y2 …\" --alpha A [--closed] \
                                [--start-angle R --end-angle R]\n                \
                                [--samples N] [--format json|csv|svg] [-o FILE|-] [--comb] [--evolute]"
    )]
    Spline(SplineArgs),
    /// Start the interactive editor: a local web server with the editor's page (embedded,
    /// works offline) and its JSON API; prints the URL and serves until interrupted
    #[command(override_usage = "lac serve [--port P] [--open] [--host ADDR --allow-remote]")]
    Serve(ServeArgs),
}

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

    /// Read one JSON object {"points":[[x,y],[x,y],[x,y]],"alpha":A} per line ("-": standard
    /// input) and write one JSON line per input line, in order: the result, or {"error":…}
    /// whose message starts with the line number. Lines are solved in parallel and written as
    /// soon as they and the lines before them are done; a line may have at most 1 MiB. Exit
    /// code 0 when every line was solved, else that of the first failed line (2 invalid, 3 no
    /// curve, 70 internal), with a one-line summary on standard error
    #[arg(long, value_name = "FILE|-", conflicts_with_all = ["points", "alpha"])]
    pub(crate) batch: Option<PathBuf>,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

/// Arguments of `lac path`.
#[derive(Debug, Args)]
pub(crate) struct PathArgs {
    /// The control polygon "x0,y0 x1,y1 …" (at least three points), separated by spaces
    /// and/or semicolons
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) polygon: String,

    /// The slope of every segment
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        conflicts_with = "alphas"
    )]
    pub(crate) alpha: Option<f64>,

    /// One slope per segment "a1,a2,…" (per interior vertex; per vertex when closed)
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub(crate) alphas: Option<String>,

    /// Close the polygon (the last point joins the first): a closed path
    #[arg(long)]
    pub(crate) closed: bool,

    /// Solve the joints for continuous curvature (G2)
    #[arg(long, conflicts_with = "fractions")]
    pub(crate) g2: bool,

    /// G1: the fraction of each joint leg (every leg but the first and last; every leg when
    /// closed) at which its joint lies, "t1,t2,…" in (0, 1); default the midpoints
    #[arg(long, value_name = "LIST")]
    pub(crate) fractions: Option<String>,

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

    /// Read one JSON object per line ("-": standard input), {"points":[[x,y],[x,y],[x,y]],
    /// "alpha0":A,"alpha1":B,"ratio":R} or {"points":[[x,y],[x,y],[x,y],[x,y]],"alpha0":A,
    /// "alpha1":B}, and write one JSON line per input line, in order: the result, or
    /// {"error":…} whose message starts with the line number (see lac segment --help for the
    /// line limit and the exit code)
    #[arg(
        long,
        value_name = "FILE|-",
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

/// Output formats of `lac segment` and `lac compound`.
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

/// Arguments of `lac region`.
#[derive(Debug, Args)]
pub(crate) struct RegionArgs {
    /// Map segments: the slope of their logarithmic curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: Option<f64>,

    /// Map compound-rhythm curves: the slope of the piece from the first point (give --alpha1
    /// and --ratio too)
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha0: Option<f64>,

    /// Compound curves: the slope of the piece that ends at the last point
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) alpha1: Option<f64>,

    /// Compound curves: the share of the turning made by the alpha0 piece, strictly between
    /// 0 and 1
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,

    /// Width and height of the map in pixels, 1 to 2048 (8192 with --allow-large; 2048 takes
    /// about 10 s for segments and 30 s for compound curves on two cores, 8192 sixteen times
    /// that); the map covers [-1,1]² with the first point at (-1,0) and the last at (1,0)
    #[arg(
        long,
        value_name = "PIXELS",
        default_value_t = 512,
        value_parser = clap::value_parser!(u32).range(1..)
    )]
    pub(crate) size: u32,

    /// Write to FILE instead of standard output ("-": standard output; a PNG is not written
    /// to a terminal)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,

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
    /// with "alpha1" and "ratio" after "alpha" (then alpha0) for compound curves
    Json,
}

/// Arguments of `lac quasi`.
#[derive(Debug, Args)]
pub(crate) struct QuasiArgs {
    /// The control points, separated by spaces and/or semicolons: three with --alpha (a
    /// segment), three with --alpha0, --alpha1 and --ratio, or four with --alpha0 and --alpha1
    /// (a compound curve, as in lac compound)
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    pub(crate) points: Option<String>,

    /// A segment: the slope of its logarithmic curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: Option<f64>,

    /// A compound curve: the slope of the piece from the first point to the joint
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha0: Option<f64>,

    /// A compound curve: the slope of the piece from the joint to the last point
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) alpha1: Option<f64>,

    /// A compound curve from three points: the share of the turning made by the alpha0
    /// piece, strictly between 0 and 1
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,

    /// Use as many pieces as needed for a maximum deviation of T times the arc length (1e-12
    /// to 1), each with curvature proven monotone, joined with continuous curvature. Without
    /// it: the single rational cubic of seed 001
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub(crate) tolerance: Option<f64>,

    /// Plain cubic Bézier pieces (all weights 1) instead of rational ones, for consumers that
    /// only take cubics (needs --tolerance)
    #[arg(long, requires = "tolerance")]
    pub(crate) cubic: bool,

    /// Read one JSON object per line ("-": standard input): a lac segment or lac compound
    /// input ({"points":…,"alpha":A} or {"points":…,"alpha0":A,"alpha1":B,"ratio":R}) with
    /// "tolerance":T and "cubic":true as --tolerance and --cubic; write one JSON line per
    /// input line, in order: the result, or {"error":…} whose message starts with the line
    /// number (see lac segment --help for the line limit and the exit code)
    #[arg(
        long,
        value_name = "FILE|-",
        conflicts_with_all = ["points", "alpha", "alpha0", "alpha1", "ratio", "tolerance", "cubic"]
    )]
    pub(crate) batch: Option<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = QuasiFormat::Json)]
    pub(crate) format: QuasiFormat,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Output formats of `lac quasi`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum QuasiFormat {
    /// One line: pieces [{points, weights, monotone, proven, turning, max_deviation}], rms,
    /// max (relative to the arc length), arc_length, tolerance, kind ("rational" or "cubic")
    Json,
    /// A header piece,x0,y0,x1,y1,x2,y2,x3,y3,w0,w1,w2,w3,monotone,proven,t,turning0,turning1,
    /// max_deviation and one row per piece (t empty unless not monotone)
    Csv,
    /// The Bézier pieces over the log-aesthetic curve, their control polygons and joints, and
    /// the curvature combs of both
    Svg,
}

/// Arguments of `lac monotone`.
#[derive(Debug, Args)]
pub(crate) struct MonotoneArgs {
    /// A JSON document to decide ("-": standard input; nothing: standard input when it is not
    /// a terminal): one piece {"points":[[x,y]×4],"weights":[w0,w1,w2,w3]} (weights
    /// optional), or lac quasi output {"pieces":[…]} for a verdict on every piece; at most 64
    /// MiB (1 GiB with --allow-large)
    #[arg(value_name = "FILE", conflicts_with_all = ["points", "weights", "batch"])]
    pub(crate) input: Option<PathBuf>,

    /// The four control points "x0,y0 x1,y1 x2,y2 x3,y3", separated by spaces and/or
    /// semicolons
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: Option<String>,

    /// The four weights "w0,w1,w2,w3", all positive (default 1,1,1,1: a plain cubic)
    #[arg(long, value_name = "WEIGHTS", requires = "points")]
    pub(crate) weights: Option<String>,

    /// Read one JSON document per line ("-": standard input), a piece or {"pieces":[…]} as
    /// for FILE, and write one JSON line per input line, in order: the verdict(s), or
    /// {"error":…} whose message starts with the line number (see lac segment --help for the
    /// line limit and the exit code)
    #[arg(long, value_name = "FILE|-", conflicts_with_all = ["points", "weights"])]
    pub(crate) batch: Option<PathBuf>,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
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

/// Arguments of `lac export`.
#[derive(Debug, Args)]
pub(crate) struct ExportArgs {
    /// One result of lac segment, lac compound, lac path, lac spline or lac space to export
    /// ("-": standard input; nothing, without --points, --polygon or --through: standard
    /// input when it is not a terminal)
    #[arg(value_name = "FILE", conflicts_with = "points")]
    pub(crate) input: Option<PathBuf>,

    /// The control points: three "x,y" with --alpha (a segment), three with --alpha0,
    /// --alpha1 and --ratio or four with --alpha0 and --alpha1 (a compound curve), or four
    /// "x,y,z" with --alpha and --beta (a space segment)
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: Option<String>,

    /// A segment's (or space segment's, or every path segment's) slope of the logarithmic
    /// curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: Option<f64>,

    /// A path: the control polygon "x0,y0 x1,y1 …" (at least three points), with --alpha
    /// or --alphas, and --closed, --g2 or --fractions as lac path takes them
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        conflicts_with_all = ["points", "input"]
    )]
    pub(crate) polygon: Option<String>,

    /// A spline: the points it passes through "x0,y0 x1,y1 …" (at least three), with
    /// --alpha, and --closed or --start-angle/--end-angle as lac spline takes them
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        conflicts_with_all = ["points", "input", "polygon"]
    )]
    pub(crate) through: Option<String>,

    /// A path: one slope per segment "a1,a2,…"
    #[arg(
        long,
        value_name = "LIST",
        allow_hyphen_values = true,
        requires = "polygon",
        conflicts_with = "alpha"
    )]
    pub(crate) alphas: Option<String>,

    /// A path or spline: close the polygon (the spline through the points)
    #[arg(long)]
    pub(crate) closed: bool,

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

    /// A path: solve the joints for continuous curvature (G2)
    #[arg(long, requires = "polygon", conflicts_with = "fractions")]
    pub(crate) g2: bool,

    /// A path (G1): the fraction of each joint leg at which its joint lies "t1,t2,…"
    #[arg(long, value_name = "LIST", requires = "polygon")]
    pub(crate) fractions: Option<String>,

    /// A compound curve: the slope of the piece from the first point to the joint
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha0: Option<f64>,

    /// A compound curve: the slope of the piece from the joint to the last point
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) alpha1: Option<f64>,

    /// A compound curve from three points: the share of the turning of the alpha0 piece
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,

    /// A space segment: the slope of the logarithmic torsion graph
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) beta: Option<f64>,

    /// A space segment: the torsion parameter (default 0)
    #[arg(long, value_name = "W", allow_hyphen_values = true)]
    pub(crate) omega: Option<f64>,

    /// A space segment: the torsion type, 1 or 2 (default 1)
    #[arg(long = "type", value_name = "1|2")]
    pub(crate) torsion_type: Option<u8>,

    /// File format (default: from the extension of -o: .dxf, .step/.stp, .iges/.igs, .svg,
    /// .json)
    #[arg(long, value_enum)]
    pub(crate) format: Option<ExportFormat>,

    /// Largest deviation allowed from the exact curve, in model units (default 1e-6)
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub(crate) tolerance: Option<f64>,

    /// Largest deviation allowed, as a fraction of the arc length (1e-12 to 1), instead of
    /// --tolerance
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        conflicts_with = "tolerance"
    )]
    pub(crate) relative_tolerance: Option<f64>,

    /// Write each Bézier piece as a B-spline of its own (one knot span), for readers that
    /// refuse interior knots of multiplicity above 1
    #[arg(long)]
    pub(crate) pieces: bool,

    /// Write to FILE ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Formats of `lac export`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum ExportFormat {
    /// DXF R2000 (AC1015): SPLINE entities with weights
    Dxf,
    /// STEP AP214: bounded rational B-spline curves in a wireframe shape
    Step,
    /// IGES 5.3: rational B-spline curves, entity 126
    Iges,
    /// SVG: plain cubic Béziers in model units (planar curves)
    Svg,
    /// JSON: {"curves":[{"degree","dimension","control_points","weights","knots"}], and the
    /// report's fields}
    Json,
}
