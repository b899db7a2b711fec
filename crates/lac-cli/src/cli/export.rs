//! `lac export`: a segment, compound curve, path, spline or space segment written for CAD
//! systems as
//! rational degree-3 B-splines (DXF, STEP, IGES, JSON) or plain cubics (SVG) within a
//! tolerance, with the deviation achieved measured on what was written
//! ([`lac_export`]).
//!
//! What to export is the curve kinds' business: each kind's module has its group of flags in
//! [`ExportArgs`] and implements [`ExportSource`] for it, saying which curve its flags (with
//! the shared [`CurveFlags`]) describe; [`ExportArgs::sources`] lists them. A document (FILE
//! or standard input) is read by lac-io's list of kinds ([`AnyCurve::read`]). This module asks
//! them in turn and writes the curve that answers.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use lac::Tolerance;
use lac_export::{export, Exported, Format, Meta, DEFAULT_TOLERANCE};
use lac_io::json::{to_line, AnyCurve, ErrorBody};

use crate::cli::{CurveFlags, ExportArgs};
use crate::errors;
use crate::input::read_document;
use crate::limits::Limits;
use crate::output::write_document;

/// The file `lac export` writes, and how.
#[derive(Debug, Args)]
pub(crate) struct ExportTo {
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

/// A flag of a curve kind's group that was given, for the usage errors of the others.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Flag {
    /// Its name, "--alpha0".
    pub(crate) name: &'static str,
    /// A slope (of a logarithmic curvature or torsion graph)? A path or spline refuses other
    /// kinds' slopes, and slopes without a curve to go with are refused.
    pub(crate) slope: bool,
}

impl Flag {
    /// The slope flag `name`, if `given`.
    pub(crate) fn slope(name: &'static str, given: bool) -> Option<Flag> {
        given.then_some(Flag { name, slope: true })
    }

    /// The flag `name` (not a slope), if `given`.
    pub(crate) fn other(name: &'static str, given: bool) -> Option<Flag> {
        given.then_some(Flag { name, slope: false })
    }
}

/// The flags given, of a kind's list of maybe-given flags.
pub(crate) fn present<const N: usize>(flags: [Option<Flag>; N]) -> Vec<Flag> {
    flags.into_iter().flatten().collect()
}

/// The flags' names for a message: "--a", "--a and --b", "--a, --b and --c".
pub(crate) fn names<'a>(flags: impl IntoIterator<Item = &'a Flag>) -> String {
    let names: Vec<&str> = flags.into_iter().map(|f| f.name).collect();
    match names.split_last() {
        Some((last, [])) => (*last).to_string(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// One curve kind in `lac export`: implemented by the kind's group of flags in
/// [`ExportArgs`], in the kind's module.
pub(crate) trait ExportSource {
    /// The flags of this group that were given.
    fn given(&self) -> Vec<Flag>;

    /// The curve that this group's flags describe with the shared ones (`curve`), or why
    /// they describe none; `None` when they do not name a curve of this kind. `others`: the
    /// flags of the other kinds' groups that were given.
    fn export_input(&self, curve: &CurveFlags, others: &[Flag])
        -> Option<Result<Input, ErrorBody>>;

    /// Does this kind take `--closed`?
    fn closes(&self) -> bool {
        false
    }
}

/// What the arguments ask to export: the curve, solved.
pub(crate) type Input = AnyCurve;

/// How to write: the format, the tolerance, one span per piece or not, the file's names.
pub(crate) struct Target {
    format: Format,
    tolerance: Tolerance,
    pieces: bool,
    meta: Meta,
}

impl Target {
    /// Export `curve`.
    pub(crate) fn write(&self, curve: &AnyCurve) -> Result<Exported, ErrorBody> {
        Ok(export(
            &curve.export_curve()?,
            self.format,
            self.tolerance,
            self.pieces,
            &self.meta,
        )?)
    }
}

/// Run `lac export`.
///
/// The file is written only after the export met its tolerance, so a refused export leaves
/// an existing file untouched.
pub(crate) fn run(args: &ExportArgs, limits: Limits) -> Result<(), ErrorBody> {
    let to = &args.to;
    let format = format_of(to)?;
    let tolerance = match (to.tolerance, to.relative_tolerance) {
        (_, Some(r)) => Tolerance::Relative(r),
        (Some(t), None) => Tolerance::Absolute(t),
        (None, None) => Tolerance::Absolute(DEFAULT_TOLERANCE),
    };
    let sources = args.sources();
    let input = match from_flags(&args.curve, &sources)? {
        Some(input) => input,
        None => {
            let text = read_document(args.input.as_deref(), limits.document(), ExportArgs::HINT)?;
            AnyCurve::read(&text)?
        }
    };
    let target = Target {
        format,
        tolerance,
        pieces: to.pieces,
        meta: Meta::now(
            to.file
                .as_deref()
                .and_then(|p| p.file_stem())
                .and_then(|s| s.to_str())
                .filter(|s| *s != "-")
                .unwrap_or("lac-curve"),
        ),
    };
    let exported = target.write(&input)?;
    write_document(to.file.as_deref(), exported.document.as_bytes())?;
    eprintln!("{}", to_line(&exported.report));
    Ok(())
}

/// The curve of the flags: the one that a kind answers with, a usage error, or `None` when
/// no flag names a curve (it is then read from FILE or standard input).
fn from_flags(
    curve: &CurveFlags,
    sources: &[&dyn ExportSource],
) -> Result<Option<Input>, ErrorBody> {
    let given: Vec<Vec<Flag>> = sources.iter().map(|s| s.given()).collect();
    if curve.closed
        && !sources
            .iter()
            .zip(&given)
            .any(|(s, g)| s.closes() && !g.is_empty())
    {
        return Err(errors::usage(ExportArgs::CLOSED));
    }
    for (i, source) in sources.iter().enumerate() {
        let others: Vec<Flag> = given
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .flat_map(|(_, g)| g.iter().copied())
            .collect();
        if let Some(input) = source.export_input(curve, &others) {
            return input.map(Some);
        }
    }
    if curve.points.is_some() {
        return Err(errors::usage(ExportArgs::POINTS));
    }
    if curve.alpha.is_some() || given.iter().flatten().any(|f| f.slope) {
        return Err(errors::usage(ExportArgs::NO_CURVE));
    }
    Ok(None)
}

/// `--format`, or the format named by the extension of `-o`.
fn format_of(to: &ExportTo) -> Result<Format, ErrorBody> {
    if let Some(f) = to.format {
        return Ok(match f {
            ExportFormat::Dxf => Format::Dxf,
            ExportFormat::Step => Format::Step,
            ExportFormat::Iges => Format::Iges,
            ExportFormat::Svg => Format::Svg,
            ExportFormat::Json => Format::Json,
        });
    }
    let extension = to
        .file
        .as_deref()
        .and_then(|p| p.extension())
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("dxf") => Ok(Format::Dxf),
        Some("step" | "stp") => Ok(Format::Step),
        Some("iges" | "igs") => Ok(Format::Iges),
        Some("svg") => Ok(Format::Svg),
        Some("json") => Ok(Format::Json),
        _ => Err(errors::usage(
            "give --format dxf|step|iges|svg|json (or -o FILE with one of those extensions)",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::{names, present, Flag};

    #[test]
    fn names_are_listed_as_in_a_sentence() {
        let flags: Vec<Flag> = present([
            Flag::slope("--alpha0", true),
            Flag::other("--ratio", false),
            Flag::slope("--alpha1", true),
            Flag::slope("--beta", true),
        ]);
        assert_eq!(names(&flags[..1]), "--alpha0");
        assert_eq!(names(&flags[..2]), "--alpha0 and --alpha1");
        assert_eq!(names(&flags), "--alpha0, --alpha1 and --beta");
        assert_eq!(names(&[]), "");
    }
}
