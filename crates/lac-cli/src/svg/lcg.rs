//! `lac lcg --format svg` (and png): the curvature plot κ(s) and the logarithmic curvature
//! graph (ln ρ, ln(ρ |ds/dρ|)) side by side, the graph with its fitted line and slope α.

use std::fmt::Write as _;

use kurbo::Point;
use lac::{CurvaturePoint, LogCurvatureGraph, RationalCubic, Segment};

use super::plot::{self, Axis, Panel, ABOVE, BELOW};
use super::text::{Block, EDGE};
use super::{polyline, short, slopes, COMB, JOINT};

/// The smallest canvas width, pixels.
const MIN_WIDTH: f64 = 1120.0;
/// Both panels' plot areas, pixels.
const PANEL_WIDTH: f64 = 420.0;
const PANEL_HEIGHT: f64 = 330.0;
/// The least room left of the first plot area and between the two, pixels.
const MIN_LEFT: f64 = 96.0;
const MIN_GAP: f64 = 150.0;
/// Space kept between the second panel's labels and the right edge, pixels.
const MIN_RIGHT: f64 = 34.0;
/// The heading's box starts this far from the top; the panels' titles start this far under
/// it, and the footnote this far under the panels' labels, pixels.
const HEADING_TOP: f64 = 18.0;
const UNDER_HEADING: f64 = 30.0;
const OVER_FOOTNOTE: f64 = 20.0;
/// Sizes of the heading and of the footnote, pixels.
const HEADING_SIZE: f64 = 17.0;
const FOOTNOTE_SIZE: f64 = 12.0;
/// Space between two panels' labels, pixels.
const SPACING: f64 = 24.0;

const DATA: &str = "#1f6fd1";
/// The fitted line.
const LINE: &str = COMB;
const NOTE: &str = "#555";

/// The SVG document for the curvature plot `plot`, its graph `graph`, the arc lengths of
/// the joints between pieces (marked in the curvature plot), under the heading `title`.
pub(crate) fn render(
    plot: &[CurvaturePoint],
    graph: &LogCurvatureGraph,
    joints: &[f64],
    title: &str,
) -> String {
    let heading = Block::new(HEADING_SIZE).prose("#111", format!("Curvature of {title}"));
    let footnote = footnote(plot, graph);
    let finite: Vec<&CurvaturePoint> = plot
        .iter()
        .filter(|p| p.s.is_finite() && p.kappa.is_finite())
        .collect();
    let points: Vec<(f64, f64)> = graph
        .points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let line = graph
        .fit
        .map(|f| [f.log_rho.0, f.log_rho.1].map(|x| (x, f.alpha * x + f.intercept)));
    let mut curvature = curvature_panel(&finite);
    let mut lcg = graph_panel(&points, line);
    let curvature_note = curvature_note(joints);
    let (graph_note, graph_colour) = graph_note(graph, points.is_empty());

    // Left to right: the room for the first panel's y labels, its plot area, the room for
    // its x labels' overhang and the second panel's y labels, the second plot area.
    let (over0, over1) = (curvature.overhang(), lcg.overhang());
    let left = MIN_LEFT
        .max(EDGE + curvature.room_left())
        .max(EDGE + over0.0);
    let gap = MIN_GAP
        .max(over0.1 + SPACING + lcg.room_left())
        .max(plot::title_width(CURVATURE_TITLE, curvature_note) - PANEL_WIDTH + SPACING);
    curvature.left = left;
    lcg.left = left + PANEL_WIDTH + gap;
    let text_width = |block: &Block| left + block.min_width() + EDGE;
    let width = (lcg.left + PANEL_WIDTH + MIN_RIGHT.max(over1.1 + EDGE))
        .max(lcg.left + plot::title_width(GRAPH_TITLE, &graph_note) + EDGE)
        .max(text_width(&heading))
        .max(text_width(&footnote))
        .max(MIN_WIDTH);
    let line_width = width - left - EDGE;
    let top = HEADING_TOP + heading.height(line_width) + UNDER_HEADING + ABOVE;
    curvature.top = top;
    lcg.top = top;
    let footnote_top = top + PANEL_HEIGHT + BELOW + OVER_FOOTNOTE;
    let height = footnote_top + footnote.height(line_width) + EDGE;

    let mut svg = String::new();
    super::document(&mut svg, width, height, &format!("Curvature of {title}"));
    heading.draw(&mut svg, left, HEADING_TOP, line_width);
    curvature.draw_frame(
        &mut svg,
        CURVATURE_TITLE,
        (NOTE, curvature_note),
        "arc length s",
        "curvature κ",
    );
    draw_curvature(&mut svg, &curvature, &finite, joints);
    lcg.draw_frame(
        &mut svg,
        GRAPH_TITLE,
        (graph_colour, &graph_note),
        "ln ρ",
        "ln(ρ |ds/dρ|)",
    );
    draw_graph(&mut svg, &lcg, &points, line);
    footnote.draw(&mut svg, left, footnote_top, line_width);
    svg.push_str("</svg>\n");
    svg
}

const CURVATURE_TITLE: &str = "Curvature plot";
const GRAPH_TITLE: &str = "Logarithmic curvature graph";

/// "3 rational cubic Bézier pieces", "1 cubic Bézier piece" (all weights equal).
pub(crate) fn bezier_title(pieces: &[RationalCubic]) -> String {
    let plain = pieces.iter().all(|p| p.to_cubic().is_some());
    let kind = if plain { "cubic" } else { "rational cubic" };
    let plural = if pieces.len() == 1 { "" } else { "s" };
    format!("{} {kind} Bézier piece{plural}", pieces.len())
}

/// "a log-aesthetic segment, α = 0.5", "a compound-rhythm curve, α0 = -1, α1 = 2".
pub(crate) fn lac_title(pieces: &[Segment]) -> String {
    let what = if pieces.len() == 1 {
        "a log-aesthetic segment"
    } else {
        "a compound-rhythm curve"
    };
    format!("{what}, {}", slopes(pieces).join(", "))
}

/// The curvature plot's panel, to be placed: κ against s.
fn curvature_panel(finite: &[&CurvaturePoint]) -> Panel {
    Panel {
        left: 0.0,
        top: 0.0,
        width: PANEL_WIDTH,
        height: PANEL_HEIGHT,
        x: Axis::covering(finite.iter().map(|p| p.s)),
        // From zero, so that the picture shows how far the curvature is from a straight line.
        y: Axis::covering(finite.iter().map(|p| p.kappa).chain([0.0])),
    }
}

/// The line under the curvature plot's title.
fn curvature_note(joints: &[f64]) -> &'static str {
    if joints.is_empty() {
        "signed, + where the curve turns left"
    } else {
        "signed, + where the curve turns left; dashed: joints"
    }
}

/// The curve κ(s) in `panel`, with the joints as dashed verticals.
fn draw_curvature(svg: &mut String, panel: &Panel, finite: &[&CurvaturePoint], joints: &[f64]) {
    let (y0, y1) = (panel.top, panel.top + panel.height);
    for &s in joints {
        let x = panel.px(s, 0.0).x;
        let _ = writeln!(
            svg,
            r#"<path class="joint" stroke="{JOINT}" stroke-width="1" stroke-dasharray="4 3" d="M{x:.2},{y0:.2}V{y1:.2}"/>"#
        );
    }
    let line: Vec<Point> = finite.iter().map(|p| panel.px(p.s, p.kappa)).collect();
    polyline(svg, &line, DATA, 1.75, "");
}

/// The graph's panel, to be placed: its finite `points` and the fitted `line`'s ends.
fn graph_panel(points: &[(f64, f64)], line: Option<[(f64, f64); 2]>) -> Panel {
    let ys = points
        .iter()
        .map(|p| p.1)
        .chain(line.iter().flatten().map(|p| p.1));
    Panel {
        left: 0.0,
        top: 0.0,
        width: PANEL_WIDTH,
        height: PANEL_HEIGHT,
        x: Axis::covering(points.iter().map(|p| p.0)),
        y: Axis::covering(ys),
    }
}

/// The line under the graph's title, and its colour: α, or why there is no line.
fn graph_note(graph: &LogCurvatureGraph, empty: bool) -> (String, &'static str) {
    match (&graph.fit, empty) {
        (Some(f), _) => (
            format!(
                "α = {} (rms residual {:.2e})",
                short(f.alpha),
                f.rms_residual
            ),
            LINE,
        ),
        (None, true) => ("no graph: κ or dκ/ds is zero throughout".into(), NOTE),
        (None, false) => ("no line: ln ρ does not vary".into(), NOTE),
    }
}

/// The graph's points as dots, and the fitted line, in `panel`.
fn draw_graph(
    svg: &mut String,
    panel: &Panel,
    points: &[(f64, f64)],
    line: Option<[(f64, f64); 2]>,
) {
    let radius = if points.len() > 400 { 1.5 } else { 2.5 };
    let _ = write!(svg, r#"<g fill="{DATA}" fill-opacity="0.8">"#);
    for &(x, y) in points {
        let p = panel.px(x, y);
        let _ = write!(
            svg,
            r#"<circle cx="{:.2}" cy="{:.2}" r="{radius}"/>"#,
            p.x, p.y
        );
    }
    svg.push_str("</g>\n");
    if let Some(ends) = line {
        let ends = ends.map(|(x, y)| panel.px(x, y));
        polyline(svg, &ends, LINE, 1.75, r#" class="fit""#);
    }
}

/// What the picture is made of: the counts, and on a line of its own the fitted line and
/// its spread. The formula's spaces do not break.
fn footnote(plot: &[CurvaturePoint], graph: &LogCurvatureGraph) -> Block {
    let counts = format!(
        "{} curvature points, {} graph points (natural logarithms).",
        plot.len(),
        graph.points.len()
    );
    let block = Block::new(FOOTNOTE_SIZE).prose(NOTE, counts);
    let Some(f) = &graph.fit else {
        return block;
    };
    let sign = if f.intercept < 0.0 { '−' } else { '+' };
    let fit = format!(
        "Fitted line ln(ρ\u{a0}|ds/dρ|)\u{a0}=\u{a0}{}\u{a0}ln\u{a0}ρ\u{a0}{sign}\u{a0}{}, \
         max residual {:.2e}, ln\u{a0}ρ from {} to {}.",
        short(f.alpha),
        short(f.intercept.abs()),
        f.max_residual,
        short(f.log_rho.0),
        short(f.log_rho.1)
    );
    block.prose(NOTE, fit)
}
