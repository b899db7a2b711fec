//! Drawable regions (seed 000 §4.2, Fig. 9).
//!
//! With the first control point at (−1, 0) and the last at (1, 0), the middle control
//! point is moved over the square [−1, 1]²; a pixel is drawable when a segment of slope α
//! exists for it (or, for compound curves, a compound curve with slopes α0, α1 and turning
//! ratio r_θ: the drawable regions seed 004 leaves open). The functions here are pure;
//! callers parallelise over rows.

use kurbo::Point;

use crate::compound::CompoundCurve;
use crate::error::Error;
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

/// One row of the map: `true` where drawable.
pub fn row(alpha: f64, size: usize, row: usize) -> Vec<bool> {
    (0..size)
        .map(|col| is_drawable(alpha, pixel_center(size, row, col)))
        .collect()
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
