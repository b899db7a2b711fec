//! `lac export`: a segment, compound curve, path, spline or space segment written for CAD
//! systems as
//! rational degree-3 B-splines (DXF, STEP, IGES, JSON) or plain cubics (SVG) within a
//! tolerance, with the deviation achieved measured on what was written
//! ([`lac_export`]).

use kurbo::Point;
use lac::Closure;
use lac::{Spline, Tolerance};
use lac_export::{export, ExportCurve, Format, Meta, DEFAULT_TOLERANCE};
use lac_io::json::{
    to_line, CurveInput, ErrorBody, LcgInput, PathInput, PathReport, SegmentInput, Solved,
    SpaceInput, SplineReport,
};

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

/// What the arguments ask to export.
enum Input {
    Plane(CurveInput),
    Path(PathInput),
    Spline(SplineInput),
    Space(SpaceInput),
}

/// A spline's points, slope, closure and end tangents (as `lac spline` takes them).
struct SplineInput {
    points: Vec<Point>,
    alpha: f64,
    closed: bool,
    ends: Option<[f64; 2]>,
}

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
    let input = if let Some(through) = &args.through {
        let Some(alpha) = args.alpha else {
            return Err(errors::usage("a spline (--through) needs --alpha"));
        };
        if args.alpha0.is_some() || args.alpha1.is_some() || args.beta.is_some() {
            return Err(errors::usage(
                "a spline takes --alpha: drop --alpha0, --alpha1 and --beta",
            ));
        }
        Input::Spline(SplineInput {
            points: kurbo_points(&parse_polygon(through, 3, lac::MAX_POLYGON_POINTS)?),
            alpha,
            closed: args.closed,
            ends: args.start_angle.zip(args.end_angle).map(|(a, b)| [a, b]),
        })
    } else if let Some(polygon) = &args.polygon {
        if args.alpha0.is_some() || args.alpha1.is_some() || args.beta.is_some() {
            return Err(errors::usage(
                "a path takes --alpha or --alphas: drop --alpha0, --alpha1 and --beta",
            ));
        }
        Input::Path(path_input(
            polygon,
            args.alpha,
            args.alphas.as_deref(),
            args.closed,
            args.g2,
            args.fractions.as_deref(),
        )?)
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
        parse_document(&text)?
    };
    let meta = Meta::now(
        args.file
            .as_deref()
            .and_then(|p| p.file_stem())
            .and_then(|s| s.to_str())
            .filter(|s| *s != "-")
            .unwrap_or("lac-curve"),
    );
    let exported = match &input {
        Input::Plane(c) => {
            let solved: Solved = c.solve()?;
            export(
                &ExportCurve::from(&solved),
                format,
                tolerance,
                args.pieces,
                &meta,
            )?
        }
        Input::Path(p) => {
            let path = p.solve()?;
            export(
                &ExportCurve::Path(&path),
                format,
                tolerance,
                args.pieces,
                &meta,
            )?
        }
        Input::Spline(s) => {
            let spline = Spline::from_points(
                &s.points,
                s.alpha,
                if s.closed {
                    Closure::Closed
                } else {
                    Closure::Open
                },
                s.ends,
            )?;
            export(
                &ExportCurve::Spline(&spline),
                format,
                tolerance,
                args.pieces,
                &meta,
            )?
        }
        Input::Space(s) => {
            let segment = s.solve()?;
            export(
                &ExportCurve::Space(&segment),
                format,
                tolerance,
                args.pieces,
                &meta,
            )?
        }
    };
    write_document(args.file.as_deref(), exported.document.as_bytes())?;
    eprintln!("{}", to_line(&exported.report));
    Ok(())
}

/// A document to export: `lac path`'s result (told by its `"segments"` and `"joints"`),
/// `lac spline`'s (told by its `"pieces"` and `"angles"`: solved again through its points
/// with its end tangents), a path's input
/// (`{"points":[…],"alpha"|"alphas":…,"closed"|"g2"|"fractions":…}`), or what [`LcgInput`]
/// reads (a segment, compound or space result).
fn parse_document(text: &str) -> Result<Input, ErrorBody> {
    let value: Option<serde_json::Value> = serde_json::from_str(text).ok();
    let has = |key: &str| value.as_ref().is_some_and(|v| v.get(key).is_some());
    if has("pieces") && has("angles") {
        let report: SplineReport = serde_json::from_str(text)
            .map_err(|e| ErrorBody::invalid_input(format!("a lac spline result: {e}")))?;
        let ends = match (report.closed, report.angles.first(), report.angles.last()) {
            (false, Some(&a), Some(&b)) => Some([a, b]),
            _ => None,
        };
        return Ok(Input::Spline(SplineInput {
            points: report
                .points
                .iter()
                .map(|p| Point::new(p[0], p[1]))
                .collect(),
            alpha: report.alpha,
            closed: report.closed,
            ends,
        }));
    }
    if has("segments") && has("joints") {
        let report: PathReport = serde_json::from_str(text)
            .map_err(|e| ErrorBody::invalid_input(format!("a lac path result: {e}")))?;
        return Ok(Input::Path(report.input()));
    }
    if ["alphas", "closed", "g2", "fractions"]
        .iter()
        .any(|k| has(k))
    {
        let input: PathInput = serde_json::from_str(text).map_err(|e| {
            ErrorBody::invalid_input(format!("a path: {e}; expected {}", PathInput::SHAPE))
        })?;
        return Ok(Input::Path(input));
    }
    match LcgInput::parse(text)? {
        LcgInput::Curve(c) => Ok(Input::Plane(c)),
        LcgInput::Space(s) => Ok(Input::Space(s)),
        LcgInput::Pieces(_) => Err(ErrorBody::invalid_input(
            "lac export needs the exact curve (a lac segment, compound, path, spline or \
             space result), not Bézier pieces",
        )),
    }
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
fn from_arguments(args: &ExportArgs) -> Result<Input, ErrorBody> {
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
        return Ok(Input::Space(SpaceInput {
            points: parse_space_points(text)?,
            alpha,
            beta,
            omega: args.omega.unwrap_or(0.0),
            torsion_type: args.torsion_type.unwrap_or(1),
        }));
    }
    if args.omega.is_some() || args.torsion_type.is_some() {
        return Err(errors::usage(
            "--omega and --type belong to a space segment: give --beta and four x,y,z points",
        ));
    }
    match (args.alpha, args.alpha0, args.alpha1) {
        (Some(alpha), None, None) if args.ratio.is_none() => {
            Ok(Input::Plane(CurveInput::Segment(SegmentInput {
                points: parse_points(text)?,
                alpha,
            })))
        }
        (None, Some(alpha0), Some(alpha1)) => Ok(Input::Plane(CurveInput::Compound(
            compound::from_arguments(text, alpha0, alpha1, args.ratio)?,
        ))),
        _ => Err(errors::usage(
            "give --alpha for a segment, --alpha0 and --alpha1 (and --ratio for three points) \
             for a compound curve, or --alpha and --beta for a space segment",
        )),
    }
}
