//! `lac space --format svg`: a space curve segment in four panels, the top (xy), front (xz)
//! and side (yz) views at one scale, laid out as in a technical drawing (the top view above
//! the front view, the side view beside it), and a perspective with the curve's shadow on
//! the floor of the views' box.

use std::fmt::Write as _;

use kurbo::{Point, Rect};
use lac::SpaceCurve;
use lac::{SpaceSegment, Vec3};

use super::measure::{self, Anchor, ASCENT, DESCENT, FAMILY};
use super::plot::{self, panel_title, Axis, Panel, ABOVE, BELOW};
use super::text::{Block, Entry, Labels, EDGE};
use super::{as_given, control_points, document, polyline, short, CURVE, LABEL_SIZE, POLYGON};
use lac_io::json::ErrorBody;

/// The smallest canvas width, pixels.
const MIN_WIDTH: f64 = 1000.0;
/// The longest side of the orthographic views' plot areas (the box's longest side), and the
/// width of the perspective's, pixels.
const CELL: f64 = 360.0;
/// The lowest perspective panel, pixels (it is as high as the top view when that is higher).
const MIN_PERSPECTIVE: f64 = 240.0;
/// The least room left of the first column of plot areas, pixels.
const MIN_LEFT: f64 = 100.0;
/// The least room between the plot areas of the two columns, pixels.
const MIN_COLUMN_GAP: f64 = 130.0;
/// The least room right of the second column, pixels.
const MIN_RIGHT: f64 = 50.0;
/// Space between the labels of neighbouring panels, and between the panels and the texts
/// over and under them, pixels.
const SPACING: f64 = 18.0;
/// Where the heading's box starts, pixels.
const HEADING_TOP: f64 = 22.0;
/// Sizes of the heading, of the line under it and of the footnote, pixels.
const HEADING_SIZE: f64 = 17.0;
const SUMMARY_SIZE: f64 = 13.0;
const FOOTNOTE_SIZE: f64 = 12.0;
/// Space between the heading and the line under it, pixels.
const UNDER_HEADING: f64 = 8.0;
/// Room around the curve and its control points in the orthographic views, in sides of
/// their bounding box.
const MARGIN: f64 = 0.04;
/// Points on the drawn curve, equally spaced in arc length.
const CURVE_POINTS: usize = 513;
/// Where the perspective is seen from: azimuth from the −y axis toward +x, and elevation
/// above the xy plane, degrees.
const AZIMUTH: f64 = 35.0;
const ELEVATION: f64 = 25.0;
/// The eye's distance from the centre of the box, in half-diagonals of the box.
const DISTANCE: f64 = 4.0;
/// Space kept free inside the perspective panel's frame, pixels.
const PAD: f64 = 24.0;
/// Size of the axis triad's letters, pixels.
const TRIAD_SIZE: f64 = 13.0;

const SHADOW: &str = "#bdbdbd";
const FLOOR: &str = "#f4f4f4";
const FLOOR_GRID: &str = "#e2e2e2";
const FRAME: &str = "#444";
const NOTE: &str = "#555";
const AXIS_COLOURS: [&str; 3] = ["#d0342c", "#2e8b3a", "#1f6fd1"];

/// One orthographic view: its title, its note, the coordinates shown across and up, and its
/// panel's column and row.
struct Ortho {
    id: &'static str,
    title: &'static str,
    note: &'static str,
    across: usize,
    up: usize,
    column: usize,
    row: usize,
}

/// Where everything goes: the orthographic views' panels, the perspective's plot area, the
/// texts' top edges, the left edge of the texts and the width they are laid out to, and the
/// canvas, pixels.
struct Layout {
    /// The panels of [`VIEWS`], in order.
    panels: [Panel; 3],
    perspective: Rect,
    summary_top: f64,
    footnote_top: f64,
    left: f64,
    line_width: f64,
    width: f64,
    height: f64,
}

impl Layout {
    /// The layout for `axes` (x, y and z at one scale) with `heading` and `summary` over the
    /// panels and `footnote` under them.
    fn new(axes: &[Axis; 3], heading: &Block, summary: &Block, footnote: &Block) -> Layout {
        let span = axes.clone().map(|a| a.hi - a.lo);
        let unit = CELL / span.iter().copied().fold(0.0, f64::max);
        let [w, d, _] = span.map(|s| unit * s);
        let mut panels = VIEWS.map(|view| Panel {
            left: 0.0,
            top: 0.0,
            width: unit * span[view.across],
            height: unit * span[view.up],
            x: axes[view.across].clone(),
            y: axes[view.up].clone(),
        });
        let perspective_height = d.max(MIN_PERSPECTIVE);
        let column = |c: usize| {
            VIEWS
                .iter()
                .zip(&panels)
                .filter(move |(v, _)| v.column == c)
        };
        let max = |values: &mut dyn Iterator<Item = f64>| values.fold(0.0, f64::max);
        // Left to right: the y labels of the first column, its plot areas, their x labels'
        // overhang (and titles) and the y labels of the second column, its plot areas.
        let room = |c: usize| max(&mut column(c).map(|(_, p)| p.room_left()));
        let overhang_left = max(&mut column(0).map(|(_, p)| p.overhang().0));
        let overhang_right = max(&mut column(0).map(|(_, p)| p.overhang().1));
        let titles = max(&mut column(0).map(|(v, p)| plot::title_width(v.title, v.note) - p.width));
        let left0 = MIN_LEFT.max(EDGE + room(0)).max(EDGE + overhang_left);
        let gap = MIN_COLUMN_GAP
            .max(overhang_right + SPACING + room(1))
            .max(titles + SPACING);
        let left = [left0, left0 + w + gap];
        let right_of_side = max(&mut column(1).map(|(v, p)| {
            p.overhang()
                .1
                .max(plot::title_width(v.title, v.note) - p.width)
        }));
        let text = |block: &Block| left0 + block.min_width() + EDGE;
        let width = (left[1] + d.max(CELL) + MIN_RIGHT.max(right_of_side + EDGE))
            .max(left[1] + plot::title_width("Perspective", PERSPECTIVE_NOTE) + EDGE)
            .max(text(heading))
            .max(text(summary))
            .max(text(footnote))
            .max(MIN_WIDTH);
        let line_width = width - left0 - EDGE;
        // Top to bottom: the heading, the summary, the first row, the second, the footnote.
        let summary_top = HEADING_TOP + heading.height(line_width) + UNDER_HEADING;
        let row0 = summary_top + summary.height(line_width) + SPACING + ABOVE;
        let row1 = row0 + perspective_height + BELOW + SPACING + ABOVE;
        let top = [row0, row1];
        for (view, panel) in VIEWS.iter().zip(&mut panels) {
            panel.left = left[view.column];
            panel.top = top[view.row];
        }
        let second_row = VIEWS.iter().zip(&panels).filter(|(v, _)| v.row == 1);
        let bottom = top[1] + max(&mut second_row.map(|(_, p)| p.height));
        let footnote_top = bottom + BELOW + SPACING;
        Layout {
            panels,
            perspective: Rect::new(left[1], row0, left[1] + CELL, row0 + perspective_height),
            summary_top,
            footnote_top,
            left: left0,
            line_width,
            width,
            height: footnote_top + footnote.height(line_width) + EDGE,
        }
    }
}

/// The line under the perspective's title.
const PERSPECTIVE_NOTE: &str = "azimuth 35°, elevation 25°, with its shadow";

const VIEWS: [Ortho; 3] = [
    Ortho {
        id: "top",
        title: "Top view (xy)",
        note: "seen from +z",
        across: 0,
        up: 1,
        column: 0,
        row: 0,
    },
    Ortho {
        id: "front",
        title: "Front view (xz)",
        note: "seen from −y",
        across: 0,
        up: 2,
        column: 0,
        row: 1,
    },
    Ortho {
        id: "side",
        title: "Side view (yz)",
        note: "seen from +x",
        across: 1,
        up: 2,
        column: 1,
        row: 1,
    },
];

const NAMES: [&str; 3] = ["x", "y", "z"];

/// What every panel shows, in the caller's coordinates.
struct Scene {
    curve: Vec<Vec3>,
    points: [Vec3; 4],
    /// x, y and z at one scale: each covers the curve and the control points.
    axes: [Axis; 3],
}

/// The SVG document for `segment`.
pub(crate) fn render(segment: &SpaceSegment) -> Result<String, ErrorBody> {
    let curve: Vec<Vec3> = segment
        .sample_by_arc_length(CURVE_POINTS)?
        .iter()
        .map(|f| f.point)
        .collect();
    let points = segment.control_points();
    let ranges: Vec<(f64, f64)> = (0..3)
        .map(|c| {
            curve
                .iter()
                .chain(&points)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    (lo.min(coordinate(p, c)), hi.max(coordinate(p, c)))
                })
        })
        .collect();
    // A margin, so that no point sits on a frame.
    let margin = MARGIN * ranges.iter().map(|r| r.1 - r.0).fold(0.0, f64::max);
    let ranges: Vec<(f64, f64)> = ranges
        .iter()
        .map(|&(lo, hi)| (lo - margin, hi + margin))
        .collect();
    let [x, y, z]: [Axis; 3] = Axis::common(&ranges)
        .try_into()
        .expect("one axis per coordinate");
    let scene = Scene {
        curve,
        points,
        axes: [x, y, z],
    };
    let (title, summary) = heading(segment);
    let heading = Block::new(HEADING_SIZE).prose(CURVE, title.clone());
    let summary = Block::new(SUMMARY_SIZE).list(summary);
    let floor = scene.axes[2].lo;
    let footnote = Block::new(FOOTNOTE_SIZE)
        .prose(
            NOTE,
            "Dashed: the control polygon P0 P1 P2 P3. The top, front and side views share one \
             scale.",
        )
        .prose(
            NOTE,
            format!(
                "Perspective from azimuth {AZIMUTH}° (from −y toward +x) and elevation \
                 {ELEVATION}°; grey: the curve's shadow on the plane z\u{a0}=\u{a0}{}, and the \
                 control points' drop lines.",
                scene.axes[2].label(floor)
            ),
        );
    let layout = Layout::new(&scene.axes, &heading, &summary, &footnote);
    let mut svg = String::new();
    document(
        &mut svg,
        layout.width,
        layout.height,
        &title.replace('\u{a0}', " "),
    );
    heading.draw(&mut svg, layout.left, HEADING_TOP, layout.line_width);
    summary.draw(&mut svg, layout.left, layout.summary_top, layout.line_width);
    for (view, panel) in VIEWS.iter().zip(&layout.panels) {
        orthographic(&mut svg, &scene, view, panel);
    }
    perspective(&mut svg, &scene, layout.perspective);
    footnote.draw(
        &mut svg,
        layout.left,
        layout.footnote_top,
        layout.line_width,
    );
    svg.push_str("</svg>\n");
    Ok(svg)
}

/// The heading ("Log-aesthetic space segment, α = …, β = …, Ω = …, type …", its values'
/// spaces not breaking) and the entries under it (Λ, ν, the arc length and how the standard
/// form is placed).
fn heading(segment: &SpaceSegment) -> (String, Vec<Entry>) {
    let length = format!("arc length = {}", short(segment.arc_length()));
    let fact = |text: String| Entry::plain(NOTE, text);
    let value = |name: &str, x: f64| format!("{name}\u{a0}=\u{a0}{}", as_given(x));
    match (
        segment.standard_form(),
        segment.transform(),
        segment.s_end(),
    ) {
        (Some(form), Some(t), Some(s_end)) => {
            let heading = format!(
                "Log-aesthetic space segment, {}, {}, {}, type\u{a0}{}",
                value("α", form.alpha()),
                value("β", form.beta()),
                value("Ω", form.omega()),
                form.torsion_type().number()
            );
            let mut summary = vec![
                fact(format!("Λ = {}", short(form.lambda()))),
                fact(format!("ν = {}", short(form.nu()))),
                fact(format!("s_end = {}", short(s_end))),
                fact(format!("scale = {}", short(t.scale))),
                fact(length),
            ];
            if t.mirror_z {
                summary.push(fact("mirrored (τ < 0)".into()));
            }
            if t.reversed {
                summary.push(fact("reversed (standard form from P3 to P0)".into()));
            }
            (heading, summary)
        }
        _ => {
            let planar = segment
                .planar()
                .expect("a segment without a standard form is planar");
            let heading = format!(
                "Log-aesthetic segment of coplanar points, {}",
                value("α", planar.alpha())
            );
            let summary = vec![
                fact("Coplanar control points: the planar segment is drawn (torsion 0)".into()),
                fact(format!("Λ = {}", short(planar.lambda()))),
                fact(length),
            ];
            (heading, summary)
        }
    }
}

/// One orthographic view in its `panel`.
fn orthographic(svg: &mut String, scene: &Scene, view: &Ortho, panel: &Panel) {
    let _ = writeln!(svg, r#"<g class="panel" id="{}">"#, view.id);
    panel.draw_frame(
        svg,
        view.title,
        (NOTE, view.note),
        NAMES[view.across],
        NAMES[view.up],
    );
    let px = |p: &Vec3| panel.px(coordinate(p, view.across), coordinate(p, view.up));
    let frame = Rect::new(
        panel.left,
        panel.top,
        panel.left + panel.width,
        panel.top + panel.height,
    );
    draw_curve(
        svg,
        &scene.points.iter().map(px).collect::<Vec<_>>(),
        &scene.curve.iter().map(px).collect::<Vec<_>>(),
        &mut Labels::new(LABEL_SIZE),
        frame,
    );
    svg.push_str("</g>\n");
}

/// The control polygon (dashed), the curve and the control points' markers, in pixels, with
/// their labels placed by `labels` inside `frame`.
fn draw_curve(
    svg: &mut String,
    polygon: &[Point],
    curve: &[Point],
    labels: &mut Labels,
    frame: Rect,
) {
    polyline(svg, polygon, POLYGON, 1.0, " stroke-dasharray=\"6 4\"");
    polyline(svg, curve, CURVE, 2.0, "");
    control_points(svg, polygon, labels, frame);
}

/// Coordinate `c` of `p`: x, y, z for 0, 1, 2 (the views pick theirs by number).
fn coordinate(p: &Vec3, c: usize) -> f64 {
    p.to_array()[c]
}

/// A pinhole camera looking at the centre of the box.
struct Camera {
    eye: Vec3,
    forward: Vec3,
    right: Vec3,
    up: Vec3,
}

impl Camera {
    fn new(centre: Vec3, distance: f64) -> Camera {
        let (az, el) = (AZIMUTH.to_radians(), ELEVATION.to_radians());
        let towards_eye = Vec3::new(el.cos() * az.sin(), -el.cos() * az.cos(), el.sin());
        let forward = -towards_eye;
        let right = forward.cross(Vec3::Z);
        let right = right / right.length();
        Camera {
            eye: centre + distance * towards_eye,
            forward,
            right,
            up: right.cross(forward),
        }
    }

    /// The point on the image plane at distance 1 (y up).
    fn project(&self, p: Vec3) -> Point {
        let q = p - self.eye;
        let depth = q.dot(self.forward);
        Point::new(q.dot(self.right) / depth, q.dot(self.up) / depth)
    }
}

/// The perspective panel, in the plot area `frame`, with the curve's shadow on the floor of
/// the views' box.
fn perspective(svg: &mut String, scene: &Scene, frame: Rect) {
    let (left, top) = (frame.x0, frame.y0);
    let (width, height) = (frame.width(), frame.height());
    let [ax, ay, az] = &scene.axes;
    let floor = az.lo;
    let centre = Vec3::new(
        0.5 * (ax.lo + ax.hi),
        0.5 * (ay.lo + ay.hi),
        0.5 * (az.lo + az.hi),
    );
    let half_diagonal = 0.5 * Vec3::new(ax.hi - ax.lo, ay.hi - ay.lo, az.hi - az.lo).length();
    let camera = Camera::new(centre, DISTANCE * half_diagonal);
    let on_floor = |p: &Vec3| Vec3::new(p.x, p.y, floor);
    let corners = [
        Vec3::new(ax.lo, ay.lo, floor),
        Vec3::new(ax.hi, ay.lo, floor),
        Vec3::new(ax.hi, ay.hi, floor),
        Vec3::new(ax.lo, ay.hi, floor),
    ];
    // The axis triad, a quarter of the box's largest side long, just outside the floor's
    // corner at low x and y (where it would hide a control point at that corner).
    let side = (ax.hi - ax.lo).max(ay.hi - ay.lo).max(az.hi - az.lo);
    let reach = 0.25 * side;
    let origin = Vec3::new(ax.lo - 0.08 * side, ay.lo - 0.08 * side, floor);
    let tips = [Vec3::X, Vec3::Y, Vec3::Z].map(|axis| origin + reach * axis);
    let image = |p: &Vec3| camera.project(*p);
    let everything: Vec<Point> = scene
        .curve
        .iter()
        .chain(&scene.points)
        .chain(&corners)
        .chain(&tips)
        .map(image)
        .collect();
    let (lo, hi) = everything.iter().fold(
        (
            Point::new(f64::INFINITY, f64::INFINITY),
            Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        ),
        |(lo, hi), p| {
            (
                Point::new(lo.x.min(p.x), lo.y.min(p.y)),
                Point::new(hi.x.max(p.x), hi.y.max(p.y)),
            )
        },
    );
    let k = ((width - 2.0 * PAD) / (hi.x - lo.x)).min((height - 2.0 * PAD) / (hi.y - lo.y));
    let (x0, y0) = (
        left + 0.5 * (width - k * (hi.x - lo.x)),
        top + 0.5 * (height - k * (hi.y - lo.y)),
    );
    let px = |p: &Vec3| {
        let q = image(p);
        Point::new(x0 + k * (q.x - lo.x), y0 + k * (hi.y - q.y))
    };

    let _ = writeln!(svg, r#"<g class="panel" id="perspective">"#);
    let _ = writeln!(
        svg,
        r#"<rect x="{left:.2}" y="{top:.2}" width="{width:.2}" height="{height:.2}" stroke="{FRAME}" stroke-width="1"/>"#
    );
    panel_title(svg, left, top, "Perspective", (NOTE, PERSPECTIVE_NOTE));
    // The floor with the top view's grid.
    let floor_px: Vec<Point> = corners.iter().chain(&corners[..1]).map(px).collect();
    let _ = write!(svg, r#"<polygon fill="{FLOOR}" stroke="none" points=""#);
    for (i, p) in floor_px[..4].iter().enumerate() {
        let sep = if i == 0 { "" } else { " " };
        let _ = write!(svg, "{sep}{:.2},{:.2}", p.x, p.y);
    }
    svg.push_str("\"/>\n");
    let _ = write!(svg, r#"<path stroke="{FLOOR_GRID}" stroke-width="1" d=""#);
    for v in ax.ticks() {
        let (a, b) = (
            px(&Vec3::new(v, ay.lo, floor)),
            px(&Vec3::new(v, ay.hi, floor)),
        );
        let _ = write!(svg, "M{:.2},{:.2}L{:.2},{:.2}", a.x, a.y, b.x, b.y);
    }
    for v in ay.ticks() {
        let (a, b) = (
            px(&Vec3::new(ax.lo, v, floor)),
            px(&Vec3::new(ax.hi, v, floor)),
        );
        let _ = write!(svg, "M{:.2},{:.2}L{:.2},{:.2}", a.x, a.y, b.x, b.y);
    }
    svg.push_str("\"/>\n");
    polyline(svg, &floor_px, "#cfcfcf", 1.0, "");
    // The shadow, and the control points' drop lines to it.
    let shadow: Vec<Point> = scene.curve.iter().map(|p| px(&on_floor(p))).collect();
    polyline(
        svg,
        &shadow,
        SHADOW,
        3.0,
        r#" class="shadow" stroke-opacity="0.8""#,
    );
    let _ = write!(
        svg,
        r#"<path stroke="{SHADOW}" stroke-width="1" stroke-dasharray="2 3" d=""#
    );
    for p in &scene.points {
        let (a, b) = (px(p), px(&on_floor(p)));
        let _ = write!(svg, "M{:.2},{:.2}L{:.2},{:.2}", a.x, a.y, b.x, b.y);
    }
    svg.push_str("\"/>\n");
    // The axis triad, its letters just beyond the tips; the points' labels keep clear of
    // them.
    let mut labels = Labels::new(LABEL_SIZE);
    let o = px(&origin);
    for (c, tip) in tips.iter().enumerate() {
        let t = px(tip);
        let colour = AXIS_COLOURS[c];
        let at = (
            t.x + 0.15 * (t.x - o.x),
            t.y + 0.15 * (t.y - o.y) + 0.5 * (ASCENT - DESCENT) * TRIAD_SIZE,
        );
        labels.avoid(measure::text_box(
            NAMES[c],
            TRIAD_SIZE,
            false,
            at,
            Anchor::Middle,
        ));
        let _ = writeln!(
            svg,
            r#"<path stroke="{colour}" stroke-width="1.5" d="M{:.2},{:.2}L{:.2},{:.2}"/><text x="{:.2}" y="{:.2}" fill="{colour}" font-family="{FAMILY}" font-size="{TRIAD_SIZE}" text-anchor="middle">{}</text>"#,
            o.x, o.y, t.x, t.y, at.0, at.1, NAMES[c]
        );
    }
    draw_curve(
        svg,
        &scene.points.iter().map(px).collect::<Vec<_>>(),
        &scene.curve.iter().map(px).collect::<Vec<_>>(),
        &mut labels,
        frame,
    );
    svg.push_str("</g>\n");
}
