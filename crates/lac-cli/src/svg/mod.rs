//! `lac segment --format svg`: a standalone drawing of a segment, its control polygon and,
//! on request, its curvature comb and evolute.

mod comb;
mod evolute;
mod view;

use std::fmt::Write as _;

use kurbo::{Point, Rect};
use lac::Segment;

use crate::failure::Failure;
use comb::Comb;
use view::{View, CAPTION};

/// Chordal tolerance of the drawn curve, relative to the drawing size (0.07 px at 720 px).
const TOLERANCE: f64 = 1e-4;
/// Longest comb tooth, relative to the drawing size.
const COMB_LENGTH: f64 = 0.25;
/// Points on the evolute.
const EVOLUTE_POINTS: usize = 1024;
/// How far the evolute is drawn beyond the curve's bounding box, in drawing sizes.
const EVOLUTE_REACH: f64 = 1.0;

const CURVE: &str = "#111";
const POLYGON: &str = "#888";
const COMB: &str = "#d0342c";
const EVOLUTE: &str = "#1f6fd1";

/// What to draw besides the curve and its control polygon.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Extras {
    /// Draw the curvature comb with this many teeth (`None`: no comb).
    pub(crate) comb_teeth: Option<usize>,
    /// Draw the evolute.
    pub(crate) evolute: bool,
}

/// The layers of a drawing, in drawing coordinates.
struct Layers {
    points: [Point; 3],
    curve: Vec<Point>,
    comb: Option<Comb>,
    evolute: Vec<Vec<Point>>,
    /// The evolute of a circular arc is its centre.
    centre: Option<Point>,
}

/// The SVG document for `segment` with control points `points`.
pub(crate) fn render(
    segment: &Segment,
    points: [Point; 3],
    extras: Extras,
) -> Result<String, Failure> {
    let layers = Layers::new(segment, points, extras)?;
    let view = View::fit(layers.bounds());
    let mut svg = String::new();
    open(&mut svg, &view, segment);
    layers.draw(&mut svg, &view);
    caption(&mut svg, &view, segment, &layers, extras);
    svg.push_str("</svg>\n");
    Ok(svg)
}

impl Layers {
    fn new(segment: &Segment, points: [Point; 3], extras: Extras) -> Result<Layers, Failure> {
        let tolerance = TOLERANCE * drawing_size(&bounding_box(&points));
        let curve: Vec<Point> = segment
            .sample_adaptive(tolerance)?
            .iter()
            .map(|s| s.point)
            .collect();
        let base = bounding_box(&points).union(bounding_box(&curve));
        let size = drawing_size(&base);
        let comb = extras
            .comb_teeth
            .map(|n| segment.sample_by_arc_length(n))
            .transpose()?
            .map(|samples| Comb::new(&samples, COMB_LENGTH * size));
        let window = base.inflate(EVOLUTE_REACH * size, EVOLUTE_REACH * size);
        let (evolute, centre) = if extras.evolute {
            evolute_layer(segment, window)?
        } else {
            (Vec::new(), None)
        };
        Ok(Layers {
            points,
            curve,
            comb,
            evolute,
            centre,
        })
    }

    /// Everything that is drawn, so that the view can fit it.
    fn bounds(&self) -> Rect {
        let mut bounds = bounding_box(&self.points).union(bounding_box(&self.curve));
        if let Some(comb) = &self.comb {
            bounds = bounds.union(bounding_box(&comb.envelope()));
        }
        for run in &self.evolute {
            bounds = bounds.union(bounding_box(run));
        }
        if let Some(c) = self.centre {
            bounds = bounds.union_pt(c);
        }
        bounds
    }

    fn draw(&self, svg: &mut String, view: &View) {
        let px = |p: &Point| view.px(*p);
        let pixels = |points: &[Point]| points.iter().map(px).collect::<Vec<_>>();
        let polygon = pixels(&self.points);
        polyline(svg, &polygon, POLYGON, 1.0, " stroke-dasharray=\"6 4\"");
        for run in &self.evolute {
            polyline(svg, &pixels(run), EVOLUTE, 1.5, "");
        }
        if let Some(c) = self.centre {
            cross(svg, view.px(c), EVOLUTE);
        }
        if let Some(comb) = &self.comb {
            let teeth: Vec<(Point, Point)> =
                comb.teeth.iter().map(|(a, b)| (px(a), px(b))).collect();
            segments(svg, &teeth, COMB, 0.6, " stroke-opacity=\"0.7\"");
            polyline(svg, &pixels(&comb.envelope()), COMB, 1.25, "");
        }
        polyline(svg, &pixels(&self.curve), CURVE, 2.0, "");
        for (i, p) in polygon.iter().enumerate() {
            marker(svg, *p, i);
        }
    }
}

/// The evolute's runs inside `window`, or for a circular arc its centre (if inside).
fn evolute_layer(
    segment: &Segment,
    window: Rect,
) -> Result<(Vec<Vec<Point>>, Option<Point>), Failure> {
    if segment.is_circle() {
        let centre = segment.evolute(2)?[0];
        return Ok((Vec::new(), window.contains(centre).then_some(centre)));
    }
    let points = segment.evolute(EVOLUTE_POINTS)?;
    Ok((evolute::clip_polyline(&points, window), None))
}

/// The larger side of `bounds`, or 1 for a degenerate box so that scaling stays finite.
fn drawing_size(bounds: &Rect) -> f64 {
    let size = bounds.width().max(bounds.height());
    if size > 0.0 && size.is_finite() {
        size
    } else {
        1.0
    }
}

fn bounding_box(points: &[Point]) -> Rect {
    let first = Rect::from_points(points[0], points[0]);
    points.iter().fold(first, |r, p| r.union_pt(*p))
}

fn open(svg: &mut String, view: &View, segment: &Segment) {
    let (w, h) = (view.width, view.height);
    let _ = writeln!(svg, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}" fill="none" stroke-linecap="round" stroke-linejoin="round">"#
    );
    let _ = writeln!(
        svg,
        "<title>Log-aesthetic segment, α = {}, Λ = {}</title>",
        as_given(segment.alpha()),
        short(segment.lambda())
    );
    let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
}

fn polyline(svg: &mut String, points: &[Point], colour: &str, width: f64, extra: &str) {
    let _ = write!(
        svg,
        r#"<polyline stroke="{colour}" stroke-width="{width}"{extra} points=""#
    );
    for (i, p) in points.iter().enumerate() {
        let sep = if i == 0 { "" } else { " " };
        let _ = write!(svg, "{sep}{:.2},{:.2}", p.x, p.y);
    }
    svg.push_str("\"/>\n");
}

/// Separate line segments as one path.
fn segments(svg: &mut String, lines: &[(Point, Point)], colour: &str, width: f64, extra: &str) {
    let _ = write!(
        svg,
        r#"<path stroke="{colour}" stroke-width="{width}"{extra} d=""#
    );
    for (a, b) in lines {
        let _ = write!(svg, "M{:.2},{:.2}L{:.2},{:.2}", a.x, a.y, b.x, b.y);
    }
    svg.push_str("\"/>\n");
}

fn marker(svg: &mut String, p: Point, index: usize) {
    let _ = writeln!(
        svg,
        r##"<circle cx="{:.2}" cy="{:.2}" r="3.5" fill="white" stroke="#444" stroke-width="1.25"/><text x="{:.2}" y="{:.2}" fill="#444" font-family="sans-serif" font-size="12">P{index}</text>"##,
        p.x,
        p.y,
        p.x + 6.0,
        p.y - 6.0
    );
}

fn cross(svg: &mut String, p: Point, colour: &str) {
    let _ = writeln!(
        svg,
        r#"<path stroke="{colour}" stroke-width="1.5" d="M{:.2},{:.2}h10M{:.2},{:.2}v10"/>"#,
        p.x - 5.0,
        p.y,
        p.x,
        p.y - 5.0
    );
}

/// "α = …  Λ = …  arc length = …" and a colour key for the comb and the evolute, separated
/// by em spaces (`&#8195;`), which SVG does not collapse.
fn caption(svg: &mut String, view: &View, segment: &Segment, layers: &Layers, extras: Extras) {
    let _ = write!(
        svg,
        r#"<text x="12" y="{:.0}" fill="{CURVE}" font-family="sans-serif" font-size="13">α = {}&#8195;Λ = {}&#8195;arc length = {}"#,
        view.height - 0.5 * CAPTION + 4.0,
        as_given(segment.alpha()),
        short(segment.lambda()),
        short(segment.arc_length())
    );
    if extras.comb_teeth.is_some() {
        let _ = write!(
            svg,
            r#"<tspan fill="{COMB}">&#8195;▬ curvature comb</tspan>"#
        );
    }
    if extras.evolute {
        let note = if layers.evolute.is_empty() && layers.centre.is_none() {
            " (beyond the view)"
        } else {
            ""
        };
        let _ = write!(
            svg,
            r#"<tspan fill="{EVOLUTE}">&#8195;▬ evolute{note}</tspan>"#
        );
    }
    svg.push_str("</text>\n");
}

/// α as the user typed it when that is short (0.999999999 must not read as 1), else [`short`].
fn as_given(x: f64) -> String {
    let exact = format!("{x:?}");
    let exact = exact.strip_suffix(".0").unwrap_or(&exact);
    if exact.len() <= 12 {
        exact.to_string()
    } else {
        short(x)
    }
}

/// A number with about six significant digits, for the caption.
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor();
    if !(-3.0..6.0).contains(&magnitude) {
        return format!("{x:.5e}");
    }
    let decimals = (5.0 - magnitude) as usize;
    let text = format!("{x:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        &text
    };
    text.to_string()
}

#[cfg(test)]
mod tests {
    use super::short;

    #[test]
    fn caption_numbers_have_six_significant_digits() {
        assert_eq!(short(0.5), "0.5");
        assert_eq!(short(-1.0), "-1");
        assert_eq!(short(2.345678901), "2.34568");
        assert_eq!(short(1234567.0), "1.23457e6");
        assert_eq!(short(1.5e-6), "1.50000e-6");
        assert_eq!(super::as_given(0.999999999), "0.999999999");
        assert_eq!(super::as_given(-1.0), "-1");
        assert_eq!(super::as_given(1e-300), "1e-300");
    }
}
