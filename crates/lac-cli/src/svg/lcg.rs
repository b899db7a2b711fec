//! `lac lcg --format svg` (and png): two panels side by side. For a planar curve the
//! curvature plot κ(s) and the logarithmic curvature graph (ln ρ, ln(ρ |ds/dρ|)) with its
//! fitted line and slope α (and each piece's line for a compound curve); for a space curve
//! the logarithmic curvature graph and the logarithmic torsion graph (ln μ, ln(μ |ds/dμ|))
//! with their slopes α and β. Both are drawn from the report that `--format json` prints.

use std::fmt::Write as _;

use kurbo::Point;
use lac::{RationalCubic, Segment, SpaceSegment};
use lac_io::json::{GraphFitRow, LcgReport, SpaceLcgReport};

use super::plot::{self, Axis, Panel, ABOVE, BELOW};
use super::text::{Block, EDGE};
use super::{as_given, polyline, short, slopes, COMB, JOINT};

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
/// The line fitted to the whole graph.
const LINE: &str = COMB;
/// The lines fitted to each piece's graph (dashed).
const PIECE_LINE: &str = JOINT;
const NOTE: &str = "#555";

const CURVATURE_TITLE: &str = "Curvature plot";
const GRAPH_TITLE: &str = "Logarithmic curvature graph";
const TORSION_TITLE: &str = "Logarithmic torsion graph";

/// A straight line drawn over a graph: its ends, colour, whether dashed, and its class.
struct Line {
    ends: [(f64, f64); 2],
    colour: &'static str,
    dashed: bool,
    class: &'static str,
}

/// What a panel shows.
enum Content<'a> {
    /// A curve through the points, with dashed verticals at the joints' x.
    Curve {
        points: Vec<(f64, f64)>,
        joints: &'a [f64],
    },
    /// Dots at the points, and lines.
    Graph {
        points: Vec<(f64, f64)>,
        lines: Vec<Line>,
    },
}

/// One panel with its labels.
struct Side<'a> {
    title: &'static str,
    note: String,
    note_colour: &'static str,
    x_title: &'static str,
    y_title: &'static str,
    content: Content<'a>,
}

impl Side<'_> {
    /// The panel, to be placed: axes covering the points (a curvature plot from zero, so
    /// that the picture shows how far the curvature is from a straight line) and the lines.
    fn panel(&self) -> Panel {
        let (x, y) = match &self.content {
            Content::Curve { points, .. } => (
                Axis::covering(points.iter().map(|p| p.0)),
                Axis::covering(points.iter().map(|p| p.1).chain([0.0])),
            ),
            Content::Graph { points, lines } => (
                Axis::covering(points.iter().map(|p| p.0)),
                Axis::covering(
                    points
                        .iter()
                        .map(|p| p.1)
                        .chain(lines.iter().flat_map(|l| l.ends.map(|e| e.1))),
                ),
            ),
        };
        Panel {
            left: 0.0,
            top: 0.0,
            width: PANEL_WIDTH,
            height: PANEL_HEIGHT,
            x,
            y,
        }
    }

    fn draw(&self, svg: &mut String, panel: &Panel) {
        panel.draw_frame(
            svg,
            self.title,
            (self.note_colour, &self.note),
            self.x_title,
            self.y_title,
        );
        match &self.content {
            Content::Curve { points, joints } => {
                let (y0, y1) = (panel.top, panel.top + panel.height);
                for &s in *joints {
                    let x = panel.px(s, 0.0).x;
                    let _ = writeln!(
                        svg,
                        r#"<path class="joint" stroke="{JOINT}" stroke-width="1" stroke-dasharray="4 3" d="M{x:.2},{y0:.2}V{y1:.2}"/>"#
                    );
                }
                let line: Vec<Point> = points.iter().map(|&(x, y)| panel.px(x, y)).collect();
                polyline(svg, &line, DATA, 1.75, "");
            }
            Content::Graph { points, lines } => {
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
                for line in lines {
                    let ends = line.ends.map(|(x, y)| panel.px(x, y));
                    let dash = if line.dashed {
                        r#" stroke-dasharray="7 4""#
                    } else {
                        ""
                    };
                    let extra = format!(r#" class="{}"{dash}"#, line.class);
                    polyline(svg, &ends, line.colour, 1.75, &extra);
                }
            }
        }
    }
}

/// The SVG document of a planar curve's report: the curvature plot (with the arc lengths of
/// the joints between pieces marked) and the graph, under the heading `title`.
pub(crate) fn render(report: &LcgReport, joints: &[f64], title: &str) -> String {
    let curve: Vec<(f64, f64)> = report
        .points
        .iter()
        .map(|p| (p.s, p.kappa))
        .filter(|(s, k)| s.is_finite() && k.is_finite())
        .collect();
    let points: Vec<(f64, f64)> = report
        .points
        .iter()
        .filter_map(|p| p.log_rho.zip(p.log_lcg))
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let mut lines: Vec<Line> = report
        .fit
        .iter()
        .map(|f| Line {
            ends: f.log_rho.map(|x| (x, f.alpha * x + f.intercept)),
            colour: LINE,
            dashed: false,
            class: "fit",
        })
        .collect();
    lines.extend(
        report
            .pieces
            .iter()
            .filter_map(|p| p.fit.as_ref())
            .map(|f| Line {
                ends: f.log_rho.map(|x| (x, f.alpha * x + f.intercept)),
                colour: PIECE_LINE,
                dashed: true,
                class: "piece-fit",
            }),
    );
    let (note, note_colour) = match &report.fit {
        Some(f) => (
            format!(
                "α = {} (rms residual {:.2e})",
                slope(f.alpha),
                f.rms_residual
            ),
            LINE,
        ),
        None if report.monotone == Some(false) => {
            ("no line: the curvature is not monotone".to_string(), NOTE)
        }
        None if points.is_empty() => ("no graph: κ or dκ/ds is zero throughout".into(), NOTE),
        None => ("no line: ln ρ does not vary".into(), NOTE),
    };
    let sides = [
        Side {
            title: CURVATURE_TITLE,
            note: curvature_note(joints).to_string(),
            note_colour: NOTE,
            x_title: "arc length s",
            y_title: "curvature κ",
            content: Content::Curve {
                points: curve,
                joints,
            },
        },
        Side {
            title: GRAPH_TITLE,
            note,
            note_colour,
            x_title: "ln ρ",
            y_title: "ln(ρ |ds/dρ|)",
            content: Content::Graph {
                points: points.clone(),
                lines,
            },
        },
    ];
    let heading = format!("Curvature of {title}");
    two_panels(&heading, &sides, footnote(report, points.len()))
}

/// The SVG document of a space curve's two graphs, under the heading `title`.
pub(crate) fn render_space(report: &SpaceLcgReport, title: &str) -> String {
    let side = |graph: &GraphFitRow,
                (title, name, what): (&'static str, &str, &str),
                (x_title, y_title): (&'static str, &'static str)| {
        let points: Vec<(f64, f64)> = graph
            .points
            .iter()
            .map(|p| (p.x, p.y))
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        let lines = graph
            .fit
            .iter()
            .map(|f| Line {
                ends: f.x.map(|x| (x, f.slope * x + f.intercept)),
                colour: LINE,
                dashed: false,
                class: "fit",
            })
            .collect();
        let (note, note_colour) = match &graph.fit {
            Some(f) => (
                format!(
                    "{name} = {} (rms residual {:.2e})",
                    slope(f.slope),
                    f.rms_residual
                ),
                LINE,
            ),
            None if points.is_empty() => {
                (format!("no graph: the radius of {what} is constant"), NOTE)
            }
            None => (format!("no line: the radius of {what} does not vary"), NOTE),
        };
        Side {
            title,
            note,
            note_colour,
            x_title,
            y_title,
            content: Content::Graph { points, lines },
        }
    };
    let sides = [
        side(
            &report.curvature,
            (GRAPH_TITLE, "α", "curvature"),
            ("ln ρ", "ln(ρ |ds/dρ|)"),
        ),
        side(
            &report.torsion,
            (TORSION_TITLE, "β", "torsion"),
            ("ln μ (μ = 1/|τ|)", "ln(μ |ds/dμ|)"),
        ),
    ];
    let counts = format!(
        "{} curvature graph points, {} torsion graph points (natural logarithms).",
        report.curvature.points.len(),
        report.torsion.points.len()
    );
    let mut footnote = Block::new(FOOTNOTE_SIZE).prose(NOTE, counts);
    if let Some(note) = &report.note {
        footnote = footnote.prose(NOTE, format!("{}.", capitalised(note)));
    }
    two_panels(
        &format!("Curvature and torsion of {title}"),
        &sides,
        footnote,
    )
}

/// The heading, two panels side by side and the footnote, laid out so that no text runs
/// into another or off the canvas.
fn two_panels(heading: &str, sides: &[Side; 2], footnote: Block) -> String {
    let heading_block = Block::new(HEADING_SIZE).prose("#111", heading);
    let [mut first, mut second] = [sides[0].panel(), sides[1].panel()];
    // Left to right: the room for the first panel's y labels, its plot area, the room for
    // its x labels' overhang and the second panel's y labels, the second plot area.
    let (over0, over1) = (first.overhang(), second.overhang());
    let left = MIN_LEFT.max(EDGE + first.room_left()).max(EDGE + over0.0);
    let gap = MIN_GAP
        .max(over0.1 + SPACING + second.room_left())
        .max(plot::title_width(sides[0].title, &sides[0].note) - PANEL_WIDTH + SPACING);
    first.left = left;
    second.left = left + PANEL_WIDTH + gap;
    let text_width = |block: &Block| left + block.min_width() + EDGE;
    let width = (second.left + PANEL_WIDTH + MIN_RIGHT.max(over1.1 + EDGE))
        .max(second.left + plot::title_width(sides[1].title, &sides[1].note) + EDGE)
        .max(text_width(&heading_block))
        .max(text_width(&footnote))
        .max(MIN_WIDTH);
    let line_width = width - left - EDGE;
    let top = HEADING_TOP + heading_block.height(line_width) + UNDER_HEADING + ABOVE;
    first.top = top;
    second.top = top;
    let footnote_top = top + PANEL_HEIGHT + BELOW + OVER_FOOTNOTE;
    let height = footnote_top + footnote.height(line_width) + EDGE;

    let mut svg = String::new();
    super::document(&mut svg, width, height, heading);
    heading_block.draw(&mut svg, left, HEADING_TOP, line_width);
    sides[0].draw(&mut svg, &first);
    sides[1].draw(&mut svg, &second);
    footnote.draw(&mut svg, left, footnote_top, line_width);
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

/// "a log-aesthetic space curve segment, α = 0.5, β = 0, Ω = 0.3" ("… (planar)").
pub(crate) fn space_title(segment: &SpaceSegment) -> String {
    let planar = if segment.is_planar() { " (planar)" } else { "" };
    format!(
        "a log-aesthetic space curve segment{planar}, α = {}, β = {}, Ω = {}",
        as_given(segment.alpha()),
        as_given(segment.beta()),
        as_given(segment.omega())
    )
}

/// The line under the curvature plot's title.
fn curvature_note(joints: &[f64]) -> &'static str {
    if joints.is_empty() {
        "signed, + where the curve turns left"
    } else {
        "signed, + where the curve turns left; dashed: joints"
    }
}

/// What the picture is made of: the counts, and on lines of their own the fitted line and
/// its spread, each piece's line, or why there is no line. The formula's spaces do not
/// break.
fn footnote(report: &LcgReport, graph_points: usize) -> Block {
    let counts = format!(
        "{} curvature points, {} graph points (natural logarithms).",
        report.points.len(),
        graph_points
    );
    let mut block = Block::new(FOOTNOTE_SIZE).prose(NOTE, counts);
    if let Some(f) = &report.fit {
        let sign = if f.intercept < 0.0 { '−' } else { '+' };
        block = block.prose(
            NOTE,
            format!(
                "Fitted line ln(ρ\u{a0}|ds/dρ|)\u{a0}=\u{a0}{}\u{a0}ln\u{a0}ρ\u{a0}{sign}\u{a0}{}, \
                 max residual {:.2e}, ln\u{a0}ρ from {} to {}.",
                slope(f.alpha),
                short(f.intercept.abs()),
                f.max_residual,
                short(f.log_rho[0]),
                short(f.log_rho[1])
            ),
        );
    }
    let pieces: Vec<String> = report
        .pieces
        .iter()
        .enumerate()
        .map(|(i, p)| match &p.fit {
            Some(f) => format!(
                "piece\u{a0}{} α\u{a0}=\u{a0}{} (s\u{a0}{}\u{a0}to\u{a0}{})",
                i + 1,
                slope(f.alpha),
                short(p.s[0]),
                short(p.s[1])
            ),
            None => format!("piece\u{a0}{} a circular arc", i + 1),
        })
        .collect();
    if !pieces.is_empty() {
        block = block.prose(
            PIECE_LINE,
            format!("Each piece's own line (dashed): {}.", pieces.join(", ")),
        );
    }
    if let Some(note) = &report.note {
        block = block.prose(NOTE, format!("{}.", capitalised(note)));
    }
    block
}

/// A fitted slope for reading: to ten decimals (a straight graph's slope of ±1e-30 is the
/// rounding of 0, and reads "0", not "-0"), with six significant digits at most.
fn slope(x: f64) -> String {
    short((x * 1e10).round() / 1e10 + 0.0)
}

/// `text` with its first letter in upper case.
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}
