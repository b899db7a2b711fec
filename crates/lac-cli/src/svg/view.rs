//! Fitting drawing coordinates (y up) into SVG pixels (y down) with a uniform scale.
//!
//! The mapping is done here in `f64`, relative to the corner of the bounds, so the SVG only
//! ever holds pixel coordinates of moderate size: stroke widths do not depend on the input
//! scale, and tiny drawings far from the origin (size 1e-6 at 1e7) keep their shape.

use kurbo::{Affine, Point, Rect};

/// Longest side of the drawn content, pixels.
const CONTENT: f64 = 720.0;
/// Space around the content for markers and labels, pixels.
const MARGIN: f64 = 40.0;
/// Height of the caption band under the drawing, pixels.
pub(crate) const CAPTION: f64 = 28.0;
/// Smallest canvas, pixels, so that the caption fits and flat curves are not cramped.
const MIN_WIDTH: f64 = 560.0;
const MIN_HEIGHT: f64 = 200.0;

/// A similarity from drawing coordinates to pixels, and the canvas size.
#[derive(Clone, Copy, Debug)]
pub(crate) struct View {
    bounds: Rect,
    scale: f64,
    left: f64,
    top: f64,
    /// Canvas width, pixels.
    pub(crate) width: f64,
    /// Canvas height including the caption band, pixels.
    pub(crate) height: f64,
}

impl View {
    /// The view that shows `bounds` (non-empty, finite) as large as [`CONTENT`] allows,
    /// centred, with the y axis pointing up, on a canvas at least `min_width` pixels wide
    /// (for the caption).
    pub(crate) fn fit(bounds: Rect, min_width: f64) -> View {
        let scale = CONTENT / bounds.width().max(bounds.height());
        let (w, h) = (bounds.width() * scale, bounds.height() * scale);
        let width = (w + 2.0 * MARGIN).max(MIN_WIDTH).max(min_width);
        let height = (h + 2.0 * MARGIN).max(MIN_HEIGHT) + CAPTION;
        View {
            bounds,
            scale,
            left: 0.5 * (width - w),
            top: 0.5 * (height - CAPTION - h),
            width,
            height,
        }
    }

    /// The pixel position of a drawing point.
    pub(crate) fn px(&self, p: Point) -> Point {
        Point::new(
            self.left + (p.x - self.bounds.x0) * self.scale,
            self.top + (self.bounds.y1 - p.y) * self.scale,
        )
    }

    /// [`px`](Self::px) as an affine map, for kurbo's paths (equal up to rounding).
    pub(crate) fn affine(&self) -> Affine {
        let s = self.scale;
        Affine::new([
            s,
            0.0,
            0.0,
            -s,
            self.left - self.bounds.x0 * s,
            self.top + self.bounds.y1 * s,
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tiny_box_far_from_the_origin_fills_the_canvas_with_y_up() {
        let (lo, hi) = (Point::new(1e7, -1e7), Point::new(1e7 + 2e-6, -1e7 + 1e-6));
        let view = View::fit(Rect::from_points(lo, hi), 0.0);
        let (a, b) = (view.px(lo), view.px(hi));
        assert!(
            ((b.x - a.x) - CONTENT).abs() < 1e-3 * CONTENT,
            "{a:?} {b:?}"
        );
        assert!(
            ((a.y - b.y) - 0.5 * CONTENT).abs() < 1e-3 * CONTENT,
            "{a:?} {b:?}"
        );
        assert!(a.x > 0.0 && b.x < view.width && b.y > 0.0 && a.y < view.height - CAPTION);
    }
}
