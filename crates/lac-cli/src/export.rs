//! `lac export`: a segment, compound curve, path, spline or space segment written for CAD
//! systems as
//! rational degree-3 B-splines (DXF, STEP, IGES, JSON) or plain cubics (SVG) within a
//! tolerance, with the deviation achieved measured on what was written
//! ([`lac_export`]).

use lac::Tolerance;
use lac_export::{export, Format, Meta, DEFAULT_TOLERANCE};
use lac_io::json::{to_line, AnyCurve, ErrorBody, SegmentInput, SpaceInput, SplineInput};

use crate::cli::{ExportArgs, ExportFormat};
use crate::compound;
use crate::errors;
use crate::input::read_document;
use crate::limits::Limits;
use crate::output::write_document;
use crate::path::path_input;
use crate::points::{kurbo_points, parse_points, parse_polygon, parse_space_points};

/// What to give when there is nothing to read.
const HINT: &str = "give --points with --alpha (and --alpha0/--alpha1/--ratio or --beta), \
                    --polygon with --alpha or --alphas, --through with --alpha, or a FILE \
                    with a lac segment, compound, path, spline or space result, or pipe \
                    one in";

/// Run `lac export`.
///
/// The file is written only after the export met its tolerance, so a refused export leaves
/// an existing file untouched.
pub(crate) fn run(args: &ExportArgs, limits: Limits) -> Result<(), ErrorBody> {
    let format = format_of(args)?;
    let tolerance = match (args.tolerance, args.relative_tolerance) {
        (_, Some(r)) => Tolerance::Relative(r),
        (Some(t), None) => Tolerance::Absolute(t),
        (None, None) => Tolerance::Absolute(DEFAULT_TOLERANCE),
    };
    if args.closed && args.polygon.is_none() && args.through.is_none() {
        return Err(errors::usage(
            "--closed closes a path's polygon (--polygon) or a spline (--through)",
        ));
    }
    let curve = if let Some(through) = &args.through {
        let Some(alpha) = args.alpha else {
            return Err(errors::usage("a spline (--through) needs --alpha"));
        };
        if args.alpha0.is_some() || args.alpha1.is_some() || args.beta.is_some() {
            return Err(errors::usage(
                "a spline takes --alpha: drop --alpha0, --alpha1 and --beta",
            ));
        }
        AnyCurve::Spline(
            SplineInput {
                points: kurbo_points(&parse_polygon(through, 3, lac::MAX_POLYGON_POINTS)?),
                alpha,
                closed: args.closed,
                ends: args.start_angle.zip(args.end_angle).map(|(a, b)| [a, b]),
            }
            .solve()?,
        )
    } else if let Some(polygon) = &args.polygon {
        if args.alpha0.is_some() || args.alpha1.is_some() || args.beta.is_some() {
            return Err(errors::usage(
                "a path takes --alpha or --alphas: drop --alpha0, --alpha1 and --beta",
            ));
        }
        AnyCurve::Path(
            path_input(
                polygon,
                args.alpha,
                args.alphas.as_deref(),
                args.closed,
                args.g2,
                args.fractions.as_deref(),
            )?
            .solve()?,
        )
    } else if args.points.is_some() {
        from_arguments(args)?
    } else {
        if args.alpha.is_some()
            || args.alpha0.is_some()
            || args.beta.is_some()
            || args.alpha1.is_some()
        {
            return Err(errors::usage(
                "the curve's parameters need --points (or --polygon for a path)",
            ));
        }
        let text = read_document(args.input.as_deref(), limits.document(), HINT)?;
        AnyCurve::read(&text)?
    };
    let meta = Meta::now(
        args.file
            .as_deref()
            .and_then(|p| p.file_stem())
            .and_then(|s| s.to_str())
            .filter(|s| *s != "-")
            .unwrap_or("lac-curve"),
    );
    let exported = export(curve.exportable(), format, tolerance, args.pieces, &meta)?;
    write_document(args.file.as_deref(), exported.document.as_bytes())?;
    eprintln!("{}", to_line(&exported.report));
    Ok(())
}

/// `--format`, or the format named by the extension of `-o`.
fn format_of(args: &ExportArgs) -> Result<Format, ErrorBody> {
    if let Some(f) = args.format {
        return Ok(match f {
            ExportFormat::Dxf => Format::Dxf,
            ExportFormat::Step => Format::Step,
            ExportFormat::Iges => Format::Iges,
            ExportFormat::Svg => Format::Svg,
            ExportFormat::Json => Format::Json,
        });
    }
    let extension = args
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

/// The curve of `--points` and the slopes.
fn from_arguments(args: &ExportArgs) -> Result<AnyCurve, ErrorBody> {
    let text = args.points.as_deref().unwrap_or_default();
    if let Some(beta) = args.beta {
        let Some(alpha) = args.alpha else {
            return Err(errors::usage("a space segment needs --alpha with --beta"));
        };
        if args.alpha0.is_some() || args.alpha1.is_some() || args.ratio.is_some() {
            return Err(errors::usage(
                "--beta is a space segment's: drop --alpha0, --alpha1 and --ratio",
            ));
        }
        let input = SpaceInput {
            points: parse_space_points(text)?,
            alpha,
            beta,
            omega: args.omega.unwrap_or(0.0),
            torsion_type: args.torsion_type.unwrap_or(1),
        };
        return Ok(AnyCurve::Space(input.solve()?));
    }
    if args.omega.is_some() || args.torsion_type.is_some() {
        return Err(errors::usage(
            "--omega and --type belong to a space segment: give --beta and four x,y,z points",
        ));
    }
    match (args.alpha, args.alpha0, args.alpha1) {
        (Some(alpha), None, None) if args.ratio.is_none() => {
            let input = SegmentInput {
                points: parse_points(text)?,
                alpha,
            };
            Ok(AnyCurve::Segment(input.solve()?))
        }
        (None, Some(alpha0), Some(alpha1)) => Ok(AnyCurve::Compound(
            compound::from_arguments(text, alpha0, alpha1, args.ratio)?.solve()?,
        )),
        _ => Err(errors::usage(
            "give --alpha for a segment, --alpha0 and --alpha1 (and --ratio for three points) \
             for a compound curve, or --alpha and --beta for a space segment",
        )),
    }
}
