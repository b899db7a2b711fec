//! Drawable regions: where the middle control point may go ([`RegionInput`],
//! [`RegionReport`]: `lac region --format json`), and where any one control point of a curve
//! may go, the others staying put ([`PointRegionInput`], [`PointRegionReport`]: the editor's).

use serde::{Deserialize, Serialize};

use super::{all_finite, xy, CurveInput, ErrorBody, Xy};

/// Where the middle control point may go: `lac region --format json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RegionReport {
    /// α, or α0 for compound curves.
    pub alpha: f64,
    /// α1 of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha1: Option<f64>,
    /// The turning ratio of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
    /// Pixels per side.
    pub size: usize,
    /// [x_min, x_max, y_min, y_max] of the map.
    pub extent: [f64; 4],
    /// The first control point.
    pub first: Xy,
    /// The last control point.
    pub last: Xy,
    /// The share of the map that is drawable.
    pub drawable_fraction: f64,
    /// Rows top (y = y_max) to bottom, columns left (x = x_min) to right.
    pub drawable: Vec<Vec<bool>>,
}

/// Where the middle control point may go: the request of [`RegionReport`],
/// `{"alpha":A}` for segments or `{"alpha":A0,"alpha1":A1,"ratio":R}` for compound curves,
/// with the map's pixels per side.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RegionInput {
    /// α, or α0 for compound curves.
    pub alpha: f64,
    /// α1 of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub alpha1: Option<f64>,
    /// The turning ratio of compound curves.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub ratio: Option<f64>,
    /// Pixels per side (a front end's default when absent).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub size: Option<usize>,
}

impl RegionInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str =
        r#"{"alpha":A,"size":N} or {"alpha":A0,"alpha1":A1,"ratio":R,"size":N}"#;

    /// Check the parameters, for which every pixel would otherwise be "not drawable" for a
    /// reason the map does not show: finite slopes, α1 and the ratio given together, and
    /// 0 < ratio < 1.
    pub fn check(&self) -> Result<(), ErrorBody> {
        let finite = |what: &'static str, value: f64| {
            if value.is_finite() {
                Ok(())
            } else {
                Err(ErrorBody::from(lac::Error::NonFinite { what, value }))
            }
        };
        match (self.alpha1, self.ratio) {
            (None, None) => finite("alpha", self.alpha),
            (Some(alpha1), Some(ratio)) => {
                finite("alpha0", self.alpha)?;
                finite("alpha1", alpha1)?;
                finite("ratio", ratio)?;
                if ratio > 0.0 && ratio < 1.0 {
                    Ok(())
                } else {
                    Err(ErrorBody::from(lac::Error::OutOfRange {
                        name: "ratio",
                        value: ratio,
                        expected: "a share of the turning strictly between 0 and 1",
                    }))
                }
            }
            _ => Err(ErrorBody::invalid_input(
                "a compound curve's region needs both alpha1 and ratio; a segment's neither",
            )),
        }
    }

    /// One row of the map (row 0 at y = +1): [`lac::region::row`] or
    /// [`lac::region::compound_row`].
    pub fn row(&self, size: usize, row: usize) -> Vec<bool> {
        match self.alpha1.zip(self.ratio) {
            None => lac::region::row(self.alpha, size, row),
            Some((alpha1, ratio)) => {
                lac::region::compound_row(self.alpha, alpha1, ratio, size, row)
            }
        }
    }

    /// The whole map, its [`lac::region::top_rows`] computed by `map_rows` (a front end's
    /// serial or parallel map over row indices, calling [`RegionInput::row`]) and mirrored.
    pub fn rows(
        &self,
        size: usize,
        map_rows: impl FnOnce(usize) -> Vec<Vec<bool>>,
    ) -> Vec<Vec<bool>> {
        lac::region::mirror_rows(size, map_rows(lac::region::top_rows(size)))
    }

    /// The report of the rows computed by [`RegionInput::row`].
    pub fn report(&self, size: usize, drawable: Vec<Vec<bool>>) -> RegionReport {
        let count: usize = drawable.iter().flatten().filter(|&&d| d).count();
        RegionReport {
            alpha: self.alpha,
            alpha1: self.alpha1,
            ratio: self.ratio,
            size,
            extent: [-1.0, 1.0, -1.0, 1.0],
            first: xy(lac::region::FIRST),
            last: xy(lac::region::LAST),
            drawable_fraction: count as f64 / (size * size).max(1) as f64,
            drawable,
        }
    }
}

/// Where one control point of a curve may go, the others staying put:
/// `{"curve":{…a segment or compound curve…},"index":I,"extent":[x0,x1,y0,y1],"size":N}`.
/// For the middle point of a segment or a three-point compound curve the canonical
/// [`RegionReport`] says the same for every placement of the ends; for the four-point
/// compound curve, whose regions depend on all four points, this is the map.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointRegionInput {
    /// The curve as it is now.
    pub curve: CurveInput,
    /// Which of its control points moves (0-based).
    pub index: usize,
    /// [x_min, x_max, y_min, y_max] of the map, in the curve's coordinates.
    pub extent: [f64; 4],
    /// Pixels per side (a front end's default when absent).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub size: Option<usize>,
}

impl PointRegionInput {
    /// The shape, for error messages.
    pub const SHAPE: &'static str = r#"{"curve":{"points":[…],"alpha0":A,"alpha1":B},"index":I,"extent":[x_min,x_max,y_min,y_max],"size":N}"#;

    /// Check the index and the extent (finite, non-empty).
    pub fn check(&self) -> Result<(), ErrorBody> {
        let count = self.curve.points().len();
        if self.index >= count {
            return Err(ErrorBody::invalid_input(format!(
                "index {} names no control point: the curve has {count} (0 to {})",
                self.index,
                count - 1
            )));
        }
        let [x0, x1, y0, y1] = self.extent;
        if !(all_finite(self.extent) && x0 < x1 && y0 < y1) {
            return Err(ErrorBody::invalid_input(
                "extent must be [x_min, x_max, y_min, y_max], finite, with x_min < x_max and \
                 y_min < y_max",
            ));
        }
        Ok(())
    }

    /// The centre of pixel (`row`, `col`) of a `size`×`size` map of the extent; row 0 is
    /// the top (y = y_max), column 0 the left (x = x_min).
    pub fn pixel_center(&self, size: usize, row: usize, col: usize) -> Xy {
        let [x0, x1, y0, y1] = self.extent;
        let n = size as f64;
        [
            x0 + (col as f64 + 0.5) * (x1 - x0) / n,
            y1 - (row as f64 + 0.5) * (y1 - y0) / n,
        ]
    }

    /// One row of the map: `true` where the curve is drawable with the point moved to the
    /// pixel's centre.
    pub fn row(&self, size: usize, row: usize) -> Vec<bool> {
        let mut curve = self.curve.clone();
        (0..size)
            .map(|col| {
                let at = self.pixel_center(size, row, col);
                match &mut curve {
                    CurveInput::Segment(s) => s.points[self.index] = at,
                    CurveInput::Compound(c) => c.points[self.index] = at,
                }
                curve.solve().is_ok()
            })
            .collect()
    }

    /// The report of the rows computed by [`PointRegionInput::row`].
    pub fn report(&self, size: usize, drawable: Vec<Vec<bool>>) -> PointRegionReport {
        let count: usize = drawable.iter().flatten().filter(|&&d| d).count();
        PointRegionReport {
            index: self.index,
            size,
            extent: self.extent,
            drawable_fraction: count as f64 / (size * size).max(1) as f64,
            drawable,
        }
    }
}

/// Where one control point may go ([`PointRegionInput`]): pixels whose centre gives a
/// drawable curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointRegionReport {
    /// Which control point moves.
    pub index: usize,
    /// Pixels per side.
    pub size: usize,
    /// [x_min, x_max, y_min, y_max] of the map.
    pub extent: [f64; 4],
    /// The share of the map that is drawable.
    pub drawable_fraction: f64,
    /// Rows top (y = y_max) to bottom, columns left (x = x_min) to right.
    pub drawable: Vec<Vec<bool>>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::SegmentInput;

    #[test]
    fn region_rows_are_the_library_rows_and_a_moved_middle_point_agrees() {
        let input = RegionInput {
            alpha: -1.0,
            alpha1: None,
            ratio: None,
            size: None,
        };
        input.check().unwrap();
        let rows: Vec<Vec<bool>> = (0..16).map(|r| input.row(16, r)).collect();
        assert_eq!(rows[3], lac::region::row(-1.0, 16, 3));
        let report = input.report(16, rows.clone());
        assert!(report.drawable_fraction > 0.0 && report.drawable_fraction < 1.0);
        // The same map as the region of point 1 of a segment from (-1,0) to (1,0).
        let moved = PointRegionInput {
            curve: CurveInput::Segment(SegmentInput {
                points: [[-1.0, 0.0], [0.0, 0.5], [1.0, 0.0]],
                alpha: -1.0,
            }),
            index: 1,
            extent: [-1.0, 1.0, -1.0, 1.0],
            size: Some(16),
        };
        moved.check().unwrap();
        let moved_rows: Vec<Vec<bool>> = (0..16).map(|r| moved.row(16, r)).collect();
        assert_eq!(moved_rows, rows);
        let bad = RegionInput {
            ratio: Some(1.0),
            alpha1: Some(2.0),
            ..input
        };
        assert_eq!(bad.check().unwrap_err().kind, "out_of_range");
        let far = PointRegionInput { index: 3, ..moved };
        assert!(far.check().unwrap_err().message.contains("index 3"));
    }
}
