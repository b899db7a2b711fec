//! `--format svg` of `lac segment` and `lac compound`: a standalone drawing of a curve made
//! of log-aesthetic pieces, its control polygon, the joints between pieces and, on request,
//! its curvature comb and evolute. The drawings of `lac quasi`, `lac lcg`, `lac space` and
//! `lac fit` are in the submodules of the same names.
//!
//! Every drawing sets its text the same way: measured with the conservative estimate of
//! [`measure`], in blocks (captions, headings, footnotes) and labels laid out by [`text`], in
//! room the canvas reserves for them, so that no text runs into another or off the canvas.

mod comb;
mod evolute;
pub(crate) mod fit;
pub(crate) mod lcg;
mod measure;
mod plot;
pub(crate) mod quasi;
pub(crate) mod space;
mod text;
mod view;

use std::fmt::Write as _;

use kurbo::{Point, Rect};
use lac::Curve;
use lac::{Sample, Segment};

use comb::Comb;
use lac_io::json::ErrorBody;
use text::{Block, Entry, Key, Labels};
use view::View;

/// Chordal tolerance of the drawn curve, relative to the drawing size (0.07 px at 720 px).
const TOLERANCE: f64 = 1e-4;
/// Longest comb tooth, relative to the drawing size.
const COMB_LENGTH: f64 = 0.25;
/// Points on the evolute of each piece.
const EVOLUTE_POINTS: usize = 1024;
/// How far the evolute is drawn beyond the curve's bounding box, in drawing sizes.
const EVOLUTE_REACH: f64 = 1.0;

const CURVE: &str = "#111";
const POLYGON: &str = "#888";
const COMB: &str = "#d0342c";
const EVOLUTE: &str = "#1f6fd1";
const JOINT: &str = "#e07b00";
/// The colour of the control points' markers and labels.
const MARKER: &str = "#444";

/// Size of the captions' text, pixels.
const CAPTION_SIZE: f64 = 13.0;
/// Size of the control points' labels, pixels.
const LABEL_SIZE: f64 = 12.0;
/// Control points closer than this on the canvas share one label ("P1, P2"), pixels.
const SAME_PLACE: f64 = 6.0;

/// What to draw besides the curve and its control polygon.
#[derive(Clone, Debug)]
pub(crate) struct Extras {
    /// Draw the curvature comb with a tooth at each of these samples (`None`: no comb).
    pub(crate) comb: Option<Vec<Sample>>,
    /// Draw the evolute.
    pub(crate) evolute: bool,
    /// The pieces form a closed path (the last one returns to the first's start, along a
    /// straight piece when they do not meet).
    pub(crate) closed: bool,
}

/// The layers of a drawing, in drawing coordinates.
struct Layers {
    points: Vec<Point>,
    curve: Vec<Point>,
    /// Where one piece ends and the next begins.
    joints: Vec<Point>,
    comb: Option<Comb>,
    evolute: Vec<Vec<Point>>,
    /// The evolute of a circular arc is its centre.
    centres: Vec<Point>,
}

/// The SVG document for the curve made of `pieces` (one for a segment, two for a compound
/// curve, in order) with control polygon `points`; the title names the kind of curve
/// (`what`: "Log-aesthetic segment") and its Λ when it has one.
pub(crate) fn render(
    (what, lambda): (&str, Option<f64>),
    pieces: &[Segment],
    points: &[Point],
    extras: Extras,
) -> Result<String, ErrorBody> {
    let layers = Layers::new(pieces, points, &extras)?;
    let caption = caption(pieces, &layers, &extras);
    let view = View::fit(layers.bounds(), &caption);
    let mut svg = String::new();
    open(&mut svg, &view, (what, lambda), pieces);
    layers.draw(&mut svg, &view);
    view.caption(&mut svg, &caption);
    svg.push_str("</svg>\n");
    Ok(svg)
}

impl Layers {
    fn new(pieces: &[Segment], points: &[Point], extras: &Extras) -> Result<Layers, ErrorBody> {
        let tolerance = TOLERANCE * drawing_size(&bounding_box(points));
        let mut curve: Vec<Point> = Vec::new();
        let mut joints = Vec::new();
        for (i, piece) in pieces.iter().enumerate() {
            let samples = piece.sample_adaptive(tolerance)?;
            if i > 0 {
                // Where this piece starts, the previous one ended: draw that point once.
                // (A path's pieces may be apart along a straight piece between them, drawn
                // as the chord from one to the other, both ends marked.)
                if gap(&pieces[i - 1], piece) > 0.0 {
                    joints.push(pieces[i - 1].end_point());
                } else {
                    curve.pop();
                }
                joints.push(samples[0].point);
            }
            curve.extend(samples.iter().map(|s| s.point));
        }
        if extras.closed && gap(&pieces[pieces.len() - 1], &pieces[0]) > 0.0 {
            joints.push(pieces[pieces.len() - 1].end_point());
            joints.push(pieces[0].start_point());
            curve.push(pieces[0].start_point());
        }
        let base = bounding_box(points).union(bounding_box(&curve));
        let size = drawing_size(&base);
        let comb = extras
            .comb
            .as_deref()
            .map(|samples| Comb::new(samples, COMB_LENGTH * size));
        let window = base.inflate(EVOLUTE_REACH * size, EVOLUTE_REACH * size);
        let (mut evolute, mut centres) = (Vec::new(), Vec::new());
        if extras.evolute {
            for piece in pieces {
                evolute_layer(piece, window, &mut evolute, &mut centres)?;
            }
        }
        Ok(Layers {
            points: points.to_vec(),
            curve,
            joints,
            comb,
            evolute,
            centres,
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
        for c in &self.centres {
            bounds = bounds.union_pt(*c);
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
        for c in &self.centres {
            cross(svg, view.px(*c), EVOLUTE);
        }
        if let Some(comb) = &self.comb {
            let teeth: Vec<(Point, Point)> =
                comb.teeth.iter().map(|(a, b)| (px(a), px(b))).collect();
            segments(svg, &teeth, COMB, 0.6, " stroke-opacity=\"0.7\"");
            polyline(svg, &pixels(&comb.envelope()), COMB, 1.25, "");
        }
        polyline(svg, &pixels(&self.curve), CURVE, 2.0, "");
        for p in &self.joints {
            // A joint on a control point (a spline's, at the points it passes through) is a
            // ring around the point's circle, which would hide a dot.
            if on_control_point(*p, &self.points) {
                ring(svg, view.px(*p), JOINT);
            } else {
                dot(svg, view.px(*p), JOINT);
            }
        }
        control_points(svg, &polygon, &mut Labels::new(LABEL_SIZE), view.room());
    }
}

/// Add the evolute of `piece` inside `window` to `runs`, or for a circular arc its centre
/// (if inside) to `centres`.
fn evolute_layer(
    piece: &Segment,
    window: Rect,
    runs: &mut Vec<Vec<Point>>,
    centres: &mut Vec<Point>,
) -> Result<(), ErrorBody> {
    if piece.is_circle() {
        let centre = piece.evolute(2)?[0];
        centres.extend(window.contains(centre).then_some(centre));
    } else {
        runs.extend(evolute::clip_polyline(
            &piece.evolute(EVOLUTE_POINTS)?,
            window,
        ));
    }
    Ok(())
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

/// The document's opening, titled with `what`, the slopes, and `lambda` when the curve has
/// one Λ (a segment, a compound curve); a path or spline says how many segments it has.
fn open(svg: &mut String, view: &View, (what, lambda): (&str, Option<f64>), pieces: &[Segment]) {
    let last = match lambda {
        Some(lambda) => format!("Λ = {}", short(lambda)),
        None => format!("{} segments", pieces.len()),
    };
    let title = format!("{what}, {}, {last}", slopes(pieces).join(", "));
    document(svg, view.width, view.height, &title);
}

/// The XML header, the `<svg>` element of `width` × `height`, its `<title>` and a white
/// background: how every drawing of `lac` starts.
pub(crate) fn document(svg: &mut String, width: f64, height: f64, title: &str) {
    let _ = writeln!(svg, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0}" height="{height:.0}" viewBox="0 0 {width:.0} {height:.0}" fill="none" stroke-linecap="round" stroke-linejoin="round">"#
    );
    let _ = writeln!(svg, "<title>{title}</title>");
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

/// The control points' markers at `points` (pixels) and their labels, "P0", "P1", …, placed
/// by `labels` inside `room`; markers closer than [`SAME_PLACE`] share one label.
fn control_points(svg: &mut String, points: &[Point], labels: &mut Labels, room: Rect) {
    for p in points {
        let _ = writeln!(
            svg,
            r#"<circle cx="{:.2}" cy="{:.2}" r="3.5" fill="white" stroke="{MARKER}" stroke-width="1.25"/>"#,
            p.x, p.y
        );
    }
    for (p, label) in text::point_labels(points, SAME_PLACE) {
        let at = labels.place(p, &label, room);
        let _ = writeln!(
            svg,
            r#"<text x="{:.2}" y="{:.2}" fill="{MARKER}" font-family="{}" font-size="{LABEL_SIZE}">{label}</text>"#,
            at.x,
            at.y,
            measure::FAMILY
        );
    }
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

/// A ring around a control point's circle, for a joint there.
fn ring(svg: &mut String, p: Point, colour: &str) {
    let _ = writeln!(
        svg,
        r#"<circle class="joint" cx="{:.2}" cy="{:.2}" r="6" fill="none" stroke="{colour}" stroke-width="2"/>"#,
        p.x, p.y
    );
}

/// Does joint `p` lie on one of the control points (to the rounding of the drawing)?
fn on_control_point(p: Point, points: &[Point]) -> bool {
    let near = 1e-9 * drawing_size(&bounding_box(points));
    points.iter().any(|q| (q.x - p.x).hypot(q.y - p.y) <= near)
}

/// A filled dot, for a joint.
fn dot(svg: &mut String, p: Point, colour: &str) {
    let _ = writeln!(
        svg,
        r#"<circle class="joint" cx="{:.2}" cy="{:.2}" r="4.5" fill="{colour}" stroke="white" stroke-width="1.25"/>"#,
        p.x, p.y
    );
}

/// The caption: the curve's numbers, "α = …", "Λ = …", "arc length = …" (a compound curve:
/// "α0 = …", "α1 = …", "Λ = …", "joint s = …", "arc length = …"; a path: each segment's α and
/// Λ, its joints and straight pieces), and on a line of its own
/// the colour key of the comb and the evolute.
/// The distance from the end of `a` to the start of `b` (0 when they meet: a path's
/// straight piece when they do not).
fn gap(a: &Segment, b: &Segment) -> f64 {
    let d = (b.start_point() - a.end_point()).hypot();
    // (Rounding apart: a joint's two ends agree to about 1e-15 of the pieces' size.)
    if d > 1e-9 * (a.arc_length() + b.arc_length()) {
        d
    } else {
        0.0
    }
}

/// A joint where the curvature is at most this share of the curve's largest |κ| is an
/// inflection (the halves of a spline's S end at 1e-12 of their other end's).
const INFLECTION_SHARE: f64 = 1e-9;

fn caption(pieces: &[Segment], layers: &Layers, extras: &Extras) -> Block {
    let evolute = extras.evolute;
    let mut facts: Vec<Entry> = slopes(pieces)
        .into_iter()
        .map(|text| Entry::plain(CURVE, text))
        .collect();
    facts.extend(
        lambdas(pieces)
            .into_iter()
            .map(|text| Entry::plain(CURVE, text)),
    );
    let largest = pieces
        .iter()
        .map(|p| {
            p.signed_curvature_start()
                .abs()
                .max(p.signed_curvature_end().abs())
        })
        .fold(0.0, f64::max);
    let mut s = 0.0;
    for (i, piece) in pieces[..pieces.len() - 1].iter().enumerate() {
        s += piece.arc_length();
        let line = gap(piece, &pieces[i + 1]);
        if line > 0.0 {
            facts.push(Entry::keyed(
                Key::Dot(JOINT),
                format!("straight s = {} to {}", short(s), short(s + line)),
            ));
            s += line;
        } else {
            // Pieces that meet at zero curvature (a spline's S, or a path's inflection with
            // a straight piece of zero length) meet at an inflection.
            let name = if piece.signed_curvature_end().abs() <= INFLECTION_SHARE * largest {
                "inflection"
            } else {
                "joint"
            };
            let key = if on_control_point(piece.end_point(), &layers.points) {
                Key::Ring(JOINT)
            } else {
                Key::Dot(JOINT)
            };
            facts.push(Entry::keyed(key, format!("{name} s = {}", short(s))));
        }
    }
    let mut length = s + pieces[pieces.len() - 1].arc_length();
    if extras.closed {
        // The straight piece on the leg that closes the polygon, if there is one, ends the
        // path where it started.
        let line = gap(&pieces[pieces.len() - 1], &pieces[0]);
        if line > 0.0 {
            facts.push(Entry::keyed(
                Key::Dot(JOINT),
                format!("straight s = {} to {}", short(length), short(length + line)),
            ));
        }
        length += line;
    }
    facts.push(Entry::plain(
        CURVE,
        format!("arc length = {}", short(length)),
    ));
    let mut key = Vec::new();
    if layers.comb.is_some() {
        key.push(Entry::keyed(Key::line(COMB, 1.25), "curvature comb"));
    }
    if evolute {
        let note = if layers.evolute.is_empty() && layers.centres.is_empty() {
            " (beyond the view)"
        } else {
            ""
        };
        key.push(Entry::keyed(
            Key::line(EVOLUTE, 1.5),
            format!("evolute{note}"),
        ));
    }
    Block::new(CAPTION_SIZE).list(facts).list(key)
}

/// "α = …" for one piece or for several that share it (a path or spline with one α),
/// "α0 = …", "α1 = …" for several that do not.
fn slopes(pieces: &[Segment]) -> Vec<String> {
    if let [piece, rest @ ..] = pieces {
        if rest.iter().all(|p| p.alpha() == piece.alpha()) {
            return vec![format!("α = {}", as_given(piece.alpha()))];
        }
    }
    pieces
        .iter()
        .enumerate()
        .map(|(i, piece)| format!("α{i} = {}", as_given(piece.alpha())))
        .collect()
}

/// The pieces' Λ: one when they share it (a compound curve's G3 joint makes them equal),
/// else each piece's, numbered as [`slopes`] numbers the α (a path's segments each have
/// their own).
fn lambdas(pieces: &[Segment]) -> Vec<String> {
    let first = pieces[0].lambda();
    if pieces
        .iter()
        .all(|p| (p.lambda() - first).abs() <= 1e-12 * first.abs())
    {
        return vec![format!("Λ = {}", short(first))];
    }
    pieces
        .iter()
        .enumerate()
        .map(|(i, piece)| format!("Λ{i} = {}", short(piece.lambda())))
        .collect()
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
