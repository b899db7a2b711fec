//! `lac fit --format svg`: two panels side by side. Left, the points and the fitted path at
//! one scale, with the path's curvature comb and its joints, the farthest point ringed;
//! right, the curvature plot of the fit against the points' own three-point curvature,
//! placed at each point's foot on the fit.
//!
//! The points' curvature is that of the circle through points k − h, k and k + h (Menger's
//! curvature, signed + for a left turn), with the stride h = ⌊n / 64⌋ (at least 1), so that
//! the scatter shows the data's curvature and not only the noise of neighbouring points;
//! values beyond the plot's range (the fit's curvature range widened by itself on either
//! side) are left out and counted.

use std::fmt::Write as _;

use kurbo::{Point, Rect};
use lac::{Curve, Fit, Sample, SegmentChain};
use lac_io::json::{ErrorBody, FitInput};

use super::comb::Comb;
use super::plot::{self, Axis, Panel, ABOVE, BELOW};
use super::text::{Block, EDGE};
use super::{as_given, document, dot, polyline, short, COMB, COMB_LENGTH, CURVE, JOINT, TOLERANCE};

/// The longest side of the points' panel and the curvature plot's width, pixels.
const CELL: f64 = 440.0;
/// The curvature plot's height, pixels.
const PLOT_HEIGHT: f64 = 330.0;
/// The least room left of the first plot area, between the two, and right of the second.
const MIN_LEFT: f64 = 96.0;
const MIN_GAP: f64 = 140.0;
const MIN_RIGHT: f64 = 34.0;
/// Where the heading starts; the room under it and over the footnote, pixels.
const HEADING_TOP: f64 = 18.0;
const UNDER_HEADING: f64 = 24.0;
const OVER_FOOTNOTE: f64 = 20.0;
const SPACING: f64 = 24.0;
const HEADING_SIZE: f64 = 17.0;
const FOOTNOTE_SIZE: f64 = 12.0;
/// Room around the drawing inside the points' panel, in sides of its bounding box.
const MARGIN: f64 = 0.04;
/// The most points drawn (every k-th beyond), so that a million points stay a small file.
const MAX_DRAWN: usize = 20_000;
/// Points of the fit's curvature plot.
const PLOT_POINTS: usize = 1025;
/// The stride of the three-point curvature: n / this (at least 1).
const STRIDE_SHARE: usize = 64;

const DATA: &str = "#777";
const WORST: &str = "#d0342c";
const PLOT: &str = "#1f6fd1";
const NOTE: &str = "#555";

/// The SVG document of `fit` of `input`, its comb drawn at `samples`.
pub(crate) fn render(fit: &Fit, input: &FitInput, samples: &[Sample]) -> Result<String, ErrorBody> {
    let points: Vec<Point> = input
        .points
        .iter()
        .map(|&[x, y]| Point::new(x, y))
        .collect();
    let every = points.len().div_ceil(MAX_DRAWN).max(1);
    let drawn: Vec<Point> = points.iter().step_by(every).copied().collect();
    let worst = points[fit.worst_point()];

    // The path and its comb, in the points' units.
    let size = extent(&bounds(&points));
    let mut curve: Vec<Point> = Vec::new();
    for seg in SegmentChain::pieces(fit) {
        curve.extend(
            seg.sample_adaptive(TOLERANCE * size)?
                .iter()
                .map(|s| s.point),
        );
    }
    let comb = Comb::new(samples, COMB_LENGTH * size);
    let joints: Vec<Point> = fit.joints().iter().map(|j| j.point).collect();
    let mut all = bounds(&points).union(bounds(&curve));
    if !comb.teeth.is_empty() {
        all = all.union(bounds(&comb.envelope()));
    }
    let margin = MARGIN * extent(&all);
    let [x, y]: [Axis; 2] = Axis::common(&[
        (all.x0 - margin, all.x1 + margin),
        (all.y0 - margin, all.y1 + margin),
    ])
    .try_into()
    .expect("one axis per coordinate");
    let unit = CELL / (x.hi - x.lo).max(y.hi - y.lo);
    let mut shape = Panel {
        left: 0.0,
        top: 0.0,
        width: unit * (x.hi - x.lo),
        height: unit * (y.hi - y.lo),
        x,
        y,
    };

    // The curvature plot: the fit's, and the points' at their feet.
    let along = fit.sample_by_arc_length(PLOT_POINTS)?;
    let fitted: Vec<(f64, f64)> = along.iter().map(|s| (s.s, s.kappa)).collect();
    let (k_lo, k_hi) = fitted
        .iter()
        .fold((0.0f64, 0.0f64), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
    let reach = (k_hi - k_lo)
        .max(k_hi.abs().max(k_lo.abs()))
        .max(f64::MIN_POSITIVE);
    let (lo, hi) = (k_lo - reach, k_hi + reach);
    let stride = (points.len() / STRIDE_SHARE).max(1);
    let mut measured = Vec::new();
    let mut outside = 0;
    for (k, kappa) in three_point_curvature(&points, stride) {
        if (lo..=hi).contains(&kappa) {
            measured.push((fit.feet()[k], kappa));
        } else {
            outside += 1;
        }
    }
    let every_measured = measured.len().div_ceil(MAX_DRAWN).max(1);
    let measured: Vec<(f64, f64)> = measured.into_iter().step_by(every_measured).collect();
    let mut plot = Panel {
        left: 0.0,
        top: 0.0,
        width: CELL,
        height: PLOT_HEIGHT,
        x: Axis::covering([0.0, fit.arc_length()]),
        y: Axis::covering(
            fitted
                .iter()
                .map(|p| p.1)
                .chain(measured.iter().map(|p| p.1))
                .chain([0.0]),
        ),
    };

    // The texts.
    let heading = Block::new(HEADING_SIZE).prose(CURVE, title(fit, points.len()));
    let mut footnote = Block::new(FOOTNOTE_SIZE).prose(NOTE, figures(fit, input, &points));
    let mut notes = Vec::new();
    if every > 1 {
        notes.push(format!("every {every}th point drawn"));
    }
    notes.push(format!(
        "points' curvature through points k − {stride}, k, k + {stride}"
    ));
    if outside > 0 {
        notes.push(format!("{outside} of its values beyond the plot left out"));
    }
    footnote = footnote.prose(NOTE, format!("{}.", capitalised(&notes.join("; "))));
    let shape_titles = (
        "Points and fitted path",
        "grey: points; red: comb; orange: joints",
    );
    let plot_titles = ("Curvature plot", "blue: the fit; grey: the points");

    // Left to right: the first panel's y labels, its plot area, the gap, the second's.
    let (over0, over1) = (shape.overhang(), plot.overhang());
    let left = MIN_LEFT.max(EDGE + shape.room_left()).max(EDGE + over0.0);
    let gap = MIN_GAP
        .max(over0.1 + SPACING + plot.room_left())
        .max(plot::title_width(shape_titles.0, shape_titles.1) - shape.width + SPACING);
    shape.left = left;
    plot.left = left + shape.width + gap;
    let text_width = |block: &Block| left + block.min_width() + EDGE;
    let width = (plot.left + plot.width + MIN_RIGHT.max(over1.1 + EDGE))
        .max(plot.left + plot::title_width(plot_titles.0, plot_titles.1) + EDGE)
        .max(text_width(&heading))
        .max(text_width(&footnote));
    let line_width = width - left - EDGE;
    let top = HEADING_TOP + heading.height(line_width) + UNDER_HEADING + ABOVE;
    shape.top = top;
    plot.top = top;
    let footnote_top = top + shape.height.max(plot.height) + BELOW + OVER_FOOTNOTE;
    let height = footnote_top + footnote.height(line_width) + EDGE;

    let mut svg = String::new();
    document(&mut svg, width, height, &title(fit, points.len()));
    heading.draw(&mut svg, left, HEADING_TOP, line_width);
    // The points' panel.
    shape.draw_frame(&mut svg, shape_titles.0, (NOTE, shape_titles.1), "x", "y");
    let px = |p: &Point| shape.px(p.x, p.y);
    let teeth: Vec<(Point, Point)> = comb.teeth.iter().map(|(a, b)| (px(a), px(b))).collect();
    let mut d = String::new();
    for (a, b) in &teeth {
        let _ = write!(d, "M{:.2},{:.2}L{:.2},{:.2}", a.x, a.y, b.x, b.y);
    }
    let _ = writeln!(
        svg,
        r#"<path class="comb" stroke="{COMB}" stroke-width="0.6" stroke-opacity="0.7" d="{d}"/>"#
    );
    polyline(
        &mut svg,
        &comb.envelope().iter().map(px).collect::<Vec<_>>(),
        COMB,
        1.25,
        "",
    );
    let radius = if drawn.len() > 400 { 1.2 } else { 2.2 };
    let _ = write!(svg, r#"<g class="points" fill="{DATA}">"#);
    for p in &drawn {
        let q = px(p);
        let _ = write!(
            svg,
            r#"<circle cx="{:.2}" cy="{:.2}" r="{radius}"/>"#,
            q.x, q.y
        );
    }
    svg.push_str("</g>\n");
    polyline(
        &mut svg,
        &curve.iter().map(px).collect::<Vec<_>>(),
        CURVE,
        2.0,
        r#" class="fit""#,
    );
    for j in &joints {
        dot(&mut svg, px(j), JOINT);
    }
    let w = px(&worst);
    let _ = writeln!(
        svg,
        r#"<circle class="worst" cx="{:.2}" cy="{:.2}" r="7" stroke="{WORST}" stroke-width="1.75"/>"#,
        w.x, w.y
    );
    // The curvature plot.
    plot.draw_frame(
        &mut svg,
        plot_titles.0,
        (NOTE, plot_titles.1),
        "arc length s",
        "curvature κ",
    );
    let (y0, y1) = (plot.top, plot.top + plot.height);
    for j in fit.joints() {
        if j.s < fit.arc_length() {
            let x = plot.px(j.s, 0.0).x;
            let _ = writeln!(
                svg,
                r#"<path class="joint" stroke="{JOINT}" stroke-width="1" stroke-dasharray="4 3" d="M{x:.2},{y0:.2}V{y1:.2}"/>"#
            );
        }
    }
    let _ = write!(
        svg,
        r#"<g class="measured" fill="{DATA}" fill-opacity="0.6">"#
    );
    for &(s, k) in &measured {
        let q = plot.px(s, k);
        let _ = write!(svg, r#"<circle cx="{:.2}" cy="{:.2}" r="1.6"/>"#, q.x, q.y);
    }
    svg.push_str("</g>\n");
    polyline(
        &mut svg,
        &fitted
            .iter()
            .map(|&(s, k)| plot.px(s, k))
            .collect::<Vec<_>>(),
        PLOT,
        1.75,
        r#" class="fit-curvature""#,
    );
    footnote.draw(&mut svg, left, footnote_top, line_width);
    svg.push_str("</svg>\n");
    Ok(svg)
}

/// "Log-aesthetic path (G2) fitted to 200 points: 3 segments, α = 0.5, -1, 2".
fn title(fit: &Fit, n: usize) -> String {
    let continuity = match fit.continuity() {
        lac::Continuity::G1 => "G1",
        lac::Continuity::G2 => "G2",
    };
    let closed = if fit.closure() == lac::Closure::Closed {
        "Closed log-aesthetic path"
    } else {
        "Log-aesthetic path"
    };
    let pieces = fit.pieces();
    let alphas: Vec<String> = pieces.iter().map(|p| short(p.alpha)).collect();
    let plural = if pieces.len() == 1 { "" } else { "s" };
    format!(
        "{closed} ({continuity}) fitted to {n} points: {} segment{plural}, α = {}",
        pieces.len(),
        alphas.join(", ")
    )
}

/// The fit's figures, for the footnote.
fn figures(fit: &Fit, input: &FitInput, points: &[Point]) -> String {
    let worst = points[fit.worst_point()];
    let tolerance = match input.tolerance {
        Some(t) => format!(" (tolerance {})", as_given(t)),
        None => String::new(),
    };
    format!(
        "RMS distance {}, largest {}{tolerance} at point {} ({}, {}), ringed; arc length {}.",
        short(fit.rms()),
        short(fit.max_distance()),
        fit.worst_point(),
        short(worst.x),
        short(worst.y),
        short(fit.arc_length())
    )
}

/// The signed curvature of the circle through points k − h, k, k + h, for every k that has
/// both (none where two of them coincide).
fn three_point_curvature(points: &[Point], h: usize) -> Vec<(usize, f64)> {
    let mut out = Vec::new();
    for k in h..points.len().saturating_sub(h) {
        let (a, b, c) = (points[k - h], points[k], points[k + h]);
        let (ab, bc, ca) = ((b - a).hypot(), (c - b).hypot(), (a - c).hypot());
        let cross = (b - a).cross(c - b);
        let kappa = 2.0 * cross / (ab * bc * ca);
        if kappa.is_finite() {
            out.push((k, kappa));
        }
    }
    out
}

fn bounds(points: &[Point]) -> Rect {
    let first = Rect::from_points(points[0], points[0]);
    points.iter().fold(first, |r, p| r.union_pt(*p))
}

fn extent(r: &Rect) -> f64 {
    let size = r.width().max(r.height());
    if size > 0.0 && size.is_finite() {
        size
    } else {
        1.0
    }
}

/// `text` with its first letter in upper case.
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_three_point_curvature_of_a_circle_is_its_own_signed() {
        let left: Vec<Point> = (0..20)
            .map(|i| {
                let t = 0.1 * i as f64;
                Point::new(2.0 * t.cos(), 2.0 * t.sin())
            })
            .collect();
        for (_, k) in three_point_curvature(&left, 3) {
            assert!((k - 0.5).abs() < 1e-12, "{k}");
        }
        let right: Vec<Point> = left.iter().rev().copied().collect();
        assert!(three_point_curvature(&right, 1)
            .iter()
            .all(|(_, k)| (k + 0.5).abs() < 1e-12));
    }
}
