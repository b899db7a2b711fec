//! Fitting drawing coordinates (y up) into SVG pixels (y down) with a uniform scale, on a
//! canvas with a band under the drawing for its caption.
//!
//! The mapping is done here in `f64`, relative to the corner of the bounds, so the SVG only
//! ever holds pixel coordinates of moderate size: stroke widths do not depend on the input
//! scale, and tiny drawings far from the origin (size 1e-6 at 1e7) keep their shape.

use kurbo::{Affine, Point, Rect};

use super::text::{Block, EDGE};

/// Longest side of the drawn content, pixels.
const CONTENT: f64 = 720.0;
/// Space around the content for markers and labels, pixels.
const MARGIN: f64 = 40.0;
/// Smallest canvas, pixels, so that flat curves are not cramped.
const MIN_WIDTH: f64 = 560.0;
const MIN_HEIGHT: f64 = 200.0;
/// Space between the drawing's labels and the caption, pixels.
const GAP: f64 = 4.0;

/// A similarity from drawing coordinates to pixels, and the canvas it draws on.
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
    /// The top of the caption band, pixels.
    band: f64,
}

impl View {
    /// The view that shows `bounds` (non-empty, finite) as large as [`CONTENT`] allows,
    /// centred, with the y axis pointing up, and `caption` under it: the canvas is wide
    /// enough for the caption's widest entry and high enough for all its lines.
    pub(crate) fn fit(bounds: Rect, caption: &Block) -> View {
        let scale = CONTENT / bounds.width().max(bounds.height());
        let (w, h) = (bounds.width() * scale, bounds.height() * scale);
        let width = (w + 2.0 * MARGIN)
            .max(MIN_WIDTH)
            .max(caption.min_width() + 2.0 * EDGE);
        let band = (h + 2.0 * MARGIN).max(MIN_HEIGHT);
        let height = band + GAP + caption.height(width - 2.0 * EDGE) + EDGE;
        View {
            bounds,
            scale,
            left: 0.5 * (width - w),
            top: 0.5 * (band - h),
            width,
            height,
            band,
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

    /// Where labels of the drawing may go: the canvas above the caption band, less the
    /// edges.
    pub(crate) fn room(&self) -> Rect {
        Rect::new(EDGE, EDGE, self.width - EDGE, self.band)
    }

    /// Write `caption` (the block the view was fitted with) in its band.
    pub(crate) fn caption(&self, svg: &mut String, caption: &Block) {
        caption.draw(svg, EDGE, self.band + GAP, self.width - 2.0 * EDGE);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::svg::text::Entry;

    #[test]
    fn a_tiny_box_far_from_the_origin_fills_the_canvas_with_y_up() {
        let (lo, hi) = (Point::new(1e7, -1e7), Point::new(1e7 + 2e-6, -1e7 + 1e-6));
        let view = View::fit(Rect::from_points(lo, hi), &Block::new(13.0));
        let (a, b) = (view.px(lo), view.px(hi));
        assert!(
            ((b.x - a.x) - CONTENT).abs() < 1e-3 * CONTENT,
            "{a:?} {b:?}"
        );
        assert!(
            ((a.y - b.y) - 0.5 * CONTENT).abs() < 1e-3 * CONTENT,
            "{a:?} {b:?}"
        );
        assert!(a.x > 0.0 && b.x < view.width && b.y > 0.0 && a.y < view.band);
    }

    #[test]
    fn the_canvas_grows_by_the_lines_of_the_caption_and_fits_its_widest_entry() {
        let bounds = Rect::new(0.0, 0.0, 1.0, 1.0);
        let short = View::fit(bounds, &Block::new(13.0).prose("#111", "α = 1"));
        let entries = (0..40).map(|i| Entry::plain("#111", format!("entry {i}")));
        let long = View::fit(bounds, &Block::new(13.0).list(entries.collect()));
        assert_eq!(short.width, long.width);
        assert!(long.height > short.height + 3.0 * 13.0, "several lines");
        let wide = Block::new(13.0).prose("#111", "x".repeat(200));
        assert!(View::fit(bounds, &wide).width >= wide.min_width() + 2.0 * EDGE);
    }
}
