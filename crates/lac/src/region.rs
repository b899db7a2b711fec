//! Drawable regions (seed 000 §4.2, Fig. 9).
//!
//! With the first control point at (−1, 0) and the last at (1, 0), the middle control
//! point is moved over the square [−1, 1]²; a pixel is drawable when a segment of slope α
//! exists for it (or, for compound curves, a compound curve with slopes α0, α1 and turning
//! ratio r_θ: the drawable regions seed 004 leaves open). The functions here are pure;
//! callers parallelise over rows.
//!
//! The maps are symmetric, and only what they do not repeat is solved. Mirroring the middle
//! point in y = 0 mirrors the curve (same slopes, same ratio), so the bottom rows repeat the
//! top ones ([`top_rows`], [`mirror_rows`]), for segments and compound curves alike.
//! Mirroring it in x = 0 reverses a segment (a log-aesthetic curve run backwards has the
//! same α: its logarithmic curvature graph does not depend on the direction), so a
//! segment's row repeats its left half ([`row`]); a compound curve run backwards swaps α0
//! with α1 and r_θ with 1 − r_θ, so its rows are solved whole.

use kurbo::Point;

use crate::curve::compound::CompoundCurve;
use crate::foundation::error::Error;
use crate::segment::Segment;

/// The first control point of the region map.
pub const FIRST: Point = Point::new(-1.0, 0.0);
/// The last control point of the region map.
pub const LAST: Point = Point::new(1.0, 0.0);

/// Is there a segment of slope `alpha` from (−1, 0) to (1, 0) with middle point `middle`?
///
/// ```
/// use kurbo::Point;
/// use lac::region::is_drawable;
/// assert!(is_drawable(0.5, Point::new(0.9, 0.9)));     // 0 ≤ α ≤ 1: almost anything
/// assert!(!is_drawable(-1.0, Point::new(0.9, 0.9)));   // the clothoid would need an inflection
/// assert!(!is_drawable(-1.0, Point::new(0.3, 0.0)));   // collinear
/// ```
pub fn is_drawable(alpha: f64, middle: Point) -> bool {
    Segment::from_control_points([FIRST, middle, LAST], alpha).is_ok()
}

/// Why a pixel is or is not drawable: `Ok(())`, or the error the solver gave.
pub fn classify(alpha: f64, middle: Point) -> Result<(), Error> {
    Segment::from_control_points([FIRST, middle, LAST], alpha).map(|_| ())
}

/// The centre of pixel (`row`, `col`) of a `size`×`size` map of [−1, 1]²; row 0 is the top
/// (y = +1), column 0 the left (x = −1).
pub fn pixel_center(size: usize, row: usize, col: usize) -> Point {
    let step = 2.0 / size as f64;
    Point::new(
        -1.0 + (col as f64 + 0.5) * step,
        1.0 - (row as f64 + 0.5) * step,
    )
}

/// One row of the map: `true` where drawable. Its left half is solved and mirrored.
pub fn row(alpha: f64, size: usize, row: usize) -> Vec<bool> {
    let left: Vec<bool> = (0..size.div_ceil(2))
        .map(|col| is_drawable(alpha, pixel_center(size, row, col)))
        .collect();
    (0..size).map(|col| left[col.min(size - 1 - col)]).collect()
}

/// How many rows of a `size`×`size` map are solved: the top half (and the middle row of an
/// odd size); [`mirror_rows`] makes the rest.
pub fn top_rows(size: usize) -> usize {
    size.div_ceil(2)
}

/// The whole map from its [`top_rows`] rows: row `size − 1 − r` is row `r`, the middle
/// point mirrored in y = 0 (pixel centres are symmetric about it).
///
/// ```
/// use lac::region::{mirror_rows, row, top_rows};
/// let top: Vec<_> = (0..top_rows(8)).map(|r| row(0.5, 8, r)).collect();
/// let map = mirror_rows(8, top);
/// assert_eq!(map.len(), 8);
/// assert_eq!(map[1], map[6]);
/// ```
pub fn mirror_rows(size: usize, mut top: Vec<Vec<bool>>) -> Vec<Vec<bool>> {
    let solved = top.len().min(size);
    top.truncate(solved);
    for r in solved..size {
        let mirror = top[size - 1 - r].clone();
        top.push(mirror);
    }
    top
}

/// Is there a compound-rhythm curve (seed 004) from (−1, 0) to (1, 0) with middle point
/// `middle`, slopes `alpha0` (from the first point) and `alpha1`, and turning share `ratio`?
///
/// ```
/// use kurbo::Point;
/// use lac::region::is_drawable_compound;
/// assert!(is_drawable_compound(-1.0, 2.0, 0.5, Point::new(0.0, 0.5)));
/// ```
pub fn is_drawable_compound(alpha0: f64, alpha1: f64, ratio: f64, middle: Point) -> bool {
    CompoundCurve::from_three_points([FIRST, middle, LAST], alpha0, alpha1, ratio).is_ok()
}

/// One row of the compound-curve map: `true` where drawable.
pub fn compound_row(alpha0: f64, alpha1: f64, ratio: f64, size: usize, row: usize) -> Vec<bool> {
    (0..size)
        .map(|col| is_drawable_compound(alpha0, alpha1, ratio, pixel_center(size, row, col)))
        .collect()
}
