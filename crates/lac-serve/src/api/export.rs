//! `/api/export`: the editor's curve as a CAD file (DXF, STEP, IGES, SVG, JSON), as `lac
//! export` writes it ([`lac_export`]), answered as the file itself.

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use lac::Tolerance;
use lac_export::{export as write_export, Format, Meta, DEFAULT_TOLERANCE};
use lac_io::json::{to_line, AnyCurve, ErrorBody};

use super::request::{self, optional, required};
use super::App;
use crate::error::ApiError;

/// The request's shape, for error messages.
const SHAPE: &str = r#"{…a segment, compound, path, spline or space curve as /api/segment, /api/compound, /api/path, /api/spline or /api/space take it, or a lac spline result…, "format":"dxf"|"step"|"iges"|"svg"|"json", "tolerance":T (model units, default 1e-6) or "relative_tolerance":R, "pieces":false, "name":"lac-curve"}"#;

/// The options of the request, removed from the curve's fields before they are read (the
/// page's `samples` is ignored).
const OPTIONS: [&str; 6] = [
    "format",
    "tolerance",
    "relative_tolerance",
    "pieces",
    "name",
    "samples",
];

/// A written file.
pub(crate) struct File {
    document: String,
    format: Format,
    name: String,
    report: String,
}

impl File {
    /// The file with its content type, a download name and the export's report in the
    /// `X-Lac-Export` header (one line of JSON).
    pub(crate) fn into_response(self) -> Response {
        let (content_type, extension) = match self.format {
            Format::Dxf => ("image/vnd.dxf", "dxf"),
            Format::Step => ("model/step", "step"),
            Format::Iges => ("model/iges", "igs"),
            Format::Svg => ("image/svg+xml", "svg"),
            Format::Json => ("application/json", "json"),
        };
        let disposition = format!("attachment; filename=\"{}.{extension}\"", self.name);
        let mut response = (
            StatusCode::OK,
            [
                (header::CONTENT_TYPE, content_type.to_string()),
                (header::CONTENT_DISPOSITION, disposition),
                (header::CACHE_CONTROL, "no-store".to_string()),
            ],
            self.document,
        )
            .into_response();
        // The report is ASCII JSON (keys, numbers, booleans): always a valid header value.
        if let Ok(value) = HeaderValue::from_str(&self.report) {
            response.headers_mut().insert("x-lac-export", value);
        }
        response
    }
}

/// `POST /api/export`: see [`SHAPE`].
pub(crate) fn export(app: &App, text: &str) -> Result<File, ApiError> {
    let mut map = request::object(text, SHAPE)?;
    let format: Format = required(&map, "format", r#""dxf", "step", "iges", "svg" or "json""#)?;
    let absolute: Option<f64> = optional(&map, "tolerance", "a positive number (model units)")?;
    let relative: Option<f64> = optional(
        &map,
        "relative_tolerance",
        "a positive share of the arc length",
    )?;
    let pieces: bool = optional(&map, "pieces", "true or false")?.unwrap_or(false);
    let name: Option<String> = optional(&map, "name", "a file name without extension")?;
    let name = file_name(name.as_deref())?;
    let tolerance = match (absolute, relative) {
        (Some(_), Some(_)) => {
            return Err(ErrorBody::invalid_input(
                "give \"tolerance\" (model units) or \"relative_tolerance\", not both",
            )
            .into())
        }
        (_, Some(r)) => Tolerance::Relative(r),
        (Some(t), None) => Tolerance::Absolute(t),
        (None, None) => Tolerance::Absolute(DEFAULT_TOLERANCE),
    };
    for key in OPTIONS {
        map.remove(key);
    }
    let meta = Meta::now(name.clone());
    let curve = AnyCurve::from_fields(map)?;
    let exportable = curve.export_curve()?;
    within_limit(app, tolerance, exportable.length)?;
    let exported = write_export(&exportable, format, tolerance, pieces, &meta)?;
    Ok(File {
        report: to_line(&exported.report),
        document: exported.document,
        format,
        name,
    })
}

/// The download's name: letters, digits, `-`, `_` and `.`, at most 64 of them, not starting
/// with a dot (default `lac-curve`).
fn file_name(name: Option<&str>) -> Result<String, ErrorBody> {
    let Some(name) = name else {
        return Ok("lac-curve".to_string());
    };
    let fine = !name.is_empty()
        && name.len() <= 64
        && !name.starts_with('.')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'));
    if fine {
        Ok(name.to_string())
    } else {
        Err(ErrorBody::invalid_input(format!(
            "\"name\": {name:?} is not a plain file name: give 1 to 64 letters, digits, '-', \
             '_' or '.' (not first)"
        )))
    }
}

/// A tolerance finer than the server's limit (relative to the arc length) is refused: the
/// work grows as the tolerance shrinks (space curves: pieces ∝ tolerance^(−1/4)).
fn within_limit(app: &App, tolerance: Tolerance, length: f64) -> Result<(), ErrorBody> {
    let relative = match tolerance {
        Tolerance::Absolute(t) => t / length,
        Tolerance::Relative(r) => r,
    };
    let min = app.limits.min_export_relative_tolerance;
    // Not positive or not finite: the library's own error says so.
    if relative > 0.0 && relative < min {
        return Err(ErrorBody::limit(format!(
            "a tolerance of {relative:.1e} of the arc length {length} is finer than this \
             server exports: give at least {:e} (model units), or use lac export",
            min * length
        )));
    }
    Ok(())
}
