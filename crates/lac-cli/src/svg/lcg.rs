//! `lac lcg --format svg` (and png): the curvature plot κ(s) and the logarithmic curvature
//! graph (ln ρ, ln(ρ |ds/dρ|)) side by side, the graph with its fitted line and slope α.

use std::fmt::Write as _;

use kurbo::Point;
use lac::{CurvaturePoint, LogCurvatureGraph, RationalCubic, Segment};

use super::plot::{Axis, Panel};
use super::{polyline, short, slopes, COMB, JOINT};

const WIDTH: f64 = 1120.0;
const HEIGHT: f64 = 550.0;
/// Both panels' plot areas: top edge, width and height, pixels; left edges.
const TOP: f64 = 116.0;
const PANEL_WIDTH: f64 = 420.0;
const PANEL_HEIGHT: f64 = 330.0;
const LEFT: [f64; 2] = [96.0, 666.0];

const DATA: &str = "#1f6fd1";
/// The fitted line.
const LINE: &str = COMB;

/// The SVG document for the curvature plot `plot`, its graph `graph`, the arc lengths of
/// the joints between pieces (marked in the curvature plot), under the heading `title`.
pub(crate) fn render(
    plot: &[CurvaturePoint],
    graph: &LogCurvatureGraph,
    joints: &[f64],
    title: &str,
) -> String {
    let mut svg = String::new();
    super::document(&mut svg, WIDTH, HEIGHT, &format!("Curvature of {title}"));
    let _ = writeln!(
        svg,
        r##"<text x="{:.0}" y="34" fill="#111" font-family="sans-serif" font-size="17">Curvature of {title}</text>"##,
        LEFT[0]
    );
    curvature_panel(&mut svg, plot, joints);
    graph_panel(&mut svg, graph);
    let _ = writeln!(
        svg,
        r##"<text x="{:.0}" y="{:.0}" fill="#555" font-family="sans-serif" font-size="12">{}</text>"##,
        LEFT[0],
        HEIGHT - 16.0,
        footnote(plot, graph)
    );
    svg.push_str("</svg>\n");
    svg
}

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

/// κ against s, with the joints as dashed verticals.
fn curvature_panel(svg: &mut String, plot: &[CurvaturePoint], joints: &[f64]) {
    let finite: Vec<&CurvaturePoint> = plot
        .iter()
        .filter(|p| p.s.is_finite() && p.kappa.is_finite())
        .collect();
    let panel = Panel {
        left: LEFT[0],
        top: TOP,
        width: PANEL_WIDTH,
        height: PANEL_HEIGHT,
        x: Axis::covering(finite.iter().map(|p| p.s)),
        // From zero, so that the picture shows how far the curvature is from a straight line.
        y: Axis::covering(finite.iter().map(|p| p.kappa).chain([0.0])),
    };
    let note = if joints.is_empty() {
        "signed, + where the curve turns left"
    } else {
        "signed, + where the curve turns left; dashed: joints"
    };
    panel.draw_frame(
        svg,
        "Curvature plot",
        ("#555", note),
        "arc length s",
        "curvature κ",
    );
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

/// The graph's points as dots, the fitted line, and α.
fn graph_panel(svg: &mut String, graph: &LogCurvatureGraph) {
    let points: Vec<(f64, f64)> = graph
        .points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let line = graph
        .fit
        .map(|f| [f.log_rho.0, f.log_rho.1].map(|x| (x, f.alpha * x + f.intercept)));
    let ys = points
        .iter()
        .map(|p| p.1)
        .chain(line.iter().flatten().map(|p| p.1));
    let panel = Panel {
        left: LEFT[1],
        top: TOP,
        width: PANEL_WIDTH,
        height: PANEL_HEIGHT,
        x: Axis::covering(points.iter().map(|p| p.0)),
        y: Axis::covering(ys),
    };
    let (text, colour) = match (&graph.fit, points.is_empty()) {
        (Some(f), _) => (
            format!(
                "α = {} (rms residual {:.2e})",
                short(f.alpha),
                f.rms_residual
            ),
            LINE,
        ),
        (None, true) => ("no graph: κ or dκ/ds is zero throughout".into(), "#555"),
        (None, false) => ("no line: ln ρ does not vary".into(), "#555"),
    };
    panel.draw_frame(
        svg,
        "Logarithmic curvature graph",
        (colour, &text),
        "ln ρ",
        "ln(ρ |ds/dρ|)",
    );
    let radius = if points.len() > 400 { 1.5 } else { 2.5 };
    let _ = write!(svg, r#"<g fill="{DATA}" fill-opacity="0.8">"#);
    for &(x, y) in &points {
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

/// What the picture is made of: counts and the fit's spread.
fn footnote(plot: &[CurvaturePoint], graph: &LogCurvatureGraph) -> String {
    let mut text = format!(
        "{} curvature points, {} graph points (natural logarithms)",
        plot.len(),
        graph.points.len()
    );
    if let Some(f) = &graph.fit {
        let _ = write!(
            text,
            "; fitted line ln(ρ |ds/dρ|) = {} ln ρ + {}, max residual {:.2e}, ln ρ from {} to {}",
            short(f.alpha),
            short(f.intercept),
            f.max_residual,
            short(f.log_rho.0),
            short(f.log_rho.1)
        );
    }
    text
}
