//! `/api/region` and `/api/region/point`: where a control point may go (seed 000 Fig. 9).

use std::sync::Arc;

use lac_io::json::{parse, to_line, ErrorBody, PointRegionInput, RegionInput};
use serde_json::Value;

use super::request;

use super::App;
use crate::cache::RegionKey;
use crate::error::ApiError;

/// `POST /api/region`: the canonical map of the middle point, ends at (−1, 0) and (1, 0);
/// the page maps it onto the current ends by a similarity. Cached per parameter set.
pub(crate) fn region(app: &App, text: &str) -> Result<String, ApiError> {
    let input: RegionInput = parse(text, RegionInput::SHAPE)?;
    input.check()?;
    let size = app.limits.region_size(input.size)?;
    let key: RegionKey = (
        input.alpha.to_bits(),
        input.alpha1.map(f64::to_bits),
        input.ratio.map(f64::to_bits),
        size,
    );
    if let Some(answer) = app.regions.get(&key) {
        return Ok(answer.to_string());
    }
    let rows = input.rows(size, |top| {
        (0..top).map(|row| input.row(size, row)).collect()
    });
    let answer: Arc<str> = to_line(&input.report(size, rows)).into();
    app.regions.put(key, Arc::clone(&answer));
    Ok(answer.to_string())
}

/// `POST /api/region/point`: the map of one control point over an extent, the others
/// staying put (for the four-point compound curve, whose map depends on all its points).
pub(crate) fn point_region(app: &App, text: &str) -> Result<String, ApiError> {
    let map = request::object(text, PointRegionInput::SHAPE)?;
    let curve = match map.get("curve") {
        Some(Value::Object(curve)) => request::curve(curve)?,
        _ => {
            return Err(ErrorBody::invalid_input(format!(
                "\"curve\" must be an object, a segment or a compound curve; expected {}",
                PointRegionInput::SHAPE
            ))
            .into())
        }
    };
    let input = PointRegionInput {
        curve,
        index: request::required(&map, "index", "a control point's index, from 0")?,
        extent: request::required(&map, "extent", "[x_min, x_max, y_min, y_max]")?,
        size: request::optional(&map, "size", "pixels per side")?,
    };
    input.check()?;
    let size = app.limits.point_region_size(input.size)?;
    let rows = (0..size).map(|row| input.row(size, row)).collect();
    Ok(to_line(&input.report(size, rows)))
}
