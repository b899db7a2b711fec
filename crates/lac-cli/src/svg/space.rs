//! `lac space --format svg`: a space curve segment in four panels, the top (xy), front (xz)
//! and side (yz) views at one scale, laid out as in a technical drawing (the top view above
//! the front view, the side view beside it), and a perspective with the curve's shadow on
//! the floor of the views' box.

use std::fmt::Write as _;

use kurbo::Point;
use lac::{SpaceSegment, Vec3};

use super::plot::{panel_title, Axis, Panel};
use super::{as_given, caption_width, document, labelled_marker, polyline, short, CURVE, POLYGON};
use crate::failure::Failure;

/// The smallest canvas width, pixels, for the heading and the footnote.
const MIN_WIDTH: f64 = 1000.0;
/// The longest side of the orthographic views' plot areas (the box's longest side), and the
/// width of the perspective's, pixels.
const CELL: f64 = 360.0;
/// The lowest perspective panel, pixels (it is as high as the top view when that is higher).
const MIN_PERSPECTIVE: f64 = 240.0;
/// Left edge of the first column of plot areas, top edge of the first row, pixels.
const LEFT: f64 = 100.0;
const TOP: f64 = 130.0;
/// Room between the plot areas of two columns (tick labels, the axis title) and two rows
/// (tick labels, the axis title, the next panel's title), pixels.
const COLUMN_GAP: f64 = 130.0;
const ROW_GAP: f64 = 110.0;
/// Room under the last row: tick labels, axis title and the two footnote lines, pixels.
const BOTTOM: f64 = 100.0;
/// Room around the curve and its control points in the orthographic views, in sides of
/// their bounding box.
const MARGIN: f64 = 0.04;
/// Control points closer than this in a view share one label ("P0, P1"), pixels.
const SAME_PLACE: f64 = 6.0;
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

/// Where the panels go: the plot areas' left edges by column and top edges by row, the
/// scale of the orthographic views, the perspective's height and the canvas, pixels.
struct Layout {
    left: [f64; 2],
    top: [f64; 2],
    unit: f64,
    perspective_height: f64,
    width: f64,
    height: f64,
}

impl Layout {
    /// The layout for `axes`, on a canvas wide enough for a line of 13 px text `widest`.
    fn new(axes: &[Axis; 3], widest: &str) -> Layout {
        let span = axes.clone().map(|a| a.hi - a.lo);
        let unit = CELL / span.iter().copied().fold(0.0, f64::max);
        let [w, d, h] = span.map(|s| unit * s);
        let perspective_height = d.max(MIN_PERSPECTIVE);
        let left = [LEFT, LEFT + w + COLUMN_GAP];
        let top = [TOP, TOP + perspective_height + ROW_GAP];
        Layout {
            left,
            top,
            unit,
            perspective_height,
            width: (left[1] + d.max(CELL) + 50.0)
                .max(MIN_WIDTH)
                .max(LEFT + caption_width(&[(CURVE, widest.to_string())])),
            height: top[1] + h + BOTTOM,
        }
    }
}

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
pub(crate) fn render(segment: &SpaceSegment) -> Result<String, Failure> {
    let curve: Vec<Vec3> = segment
        .sample(CURVE_POINTS)?
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
    // A margin, so that no point sits on a frame (with its label over the panel's title).
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
    let (heading, summary) = heading(segment);
    let layout = Layout::new(&scene.axes, &summary);
    let mut svg = String::new();
    document(&mut svg, layout.width, layout.height, &heading);
    let _ = writeln!(
        svg,
        r##"<text x="{LEFT:.0}" y="40" fill="#111" font-family="sans-serif" font-size="17">{heading}</text>"##,
    );
    let _ = writeln!(
        svg,
        r#"<text x="{LEFT:.0}" y="64" fill="{NOTE}" font-family="sans-serif" font-size="13">{summary}</text>"#,
    );
    for view in &VIEWS {
        orthographic(&mut svg, &scene, view, &layout);
    }
    let floor = perspective(&mut svg, &scene, &layout);
    let footnote = [
        "Dashed: the control polygon P0 P1 P2 P3. The top, front and side views share one scale."
            .to_string(),
        format!(
            "Perspective from azimuth {AZIMUTH}° (from −y toward +x) and elevation {ELEVATION}°; \
             grey: the curve's shadow on the plane z = {}, and the control points' drop lines.",
            scene.axes[2].label(floor)
        ),
    ];
    for (i, line) in footnote.iter().enumerate() {
        let _ = writeln!(
            svg,
            r#"<text x="{LEFT:.0}" y="{:.0}" fill="{NOTE}" font-family="sans-serif" font-size="12">{line}</text>"#,
            layout.height - 34.0 + 18.0 * i as f64,
        );
    }
    svg.push_str("</svg>\n");
    Ok(svg)
}

/// The heading ("Log-aesthetic space segment, α = …, β = …, Ω = …, type …") and the line
/// under it (Λ, ν, the arc length and how the standard form is placed).
fn heading(segment: &SpaceSegment) -> (String, String) {
    let length = short(segment.arc_length());
    match (
        segment.standard_form(),
        segment.transform(),
        segment.s_end(),
    ) {
        (Some(form), Some(t), Some(s_end)) => {
            let heading = format!(
                "Log-aesthetic space segment, α = {}, β = {}, Ω = {}, type {}",
                as_given(form.alpha()),
                as_given(form.beta()),
                as_given(form.omega()),
                form.torsion_type().number()
            );
            let mut summary = format!(
                "Λ = {}&#8195;ν = {}&#8195;s_end = {}&#8195;scale = {}&#8195;arc length = {length}",
                short(form.lambda()),
                short(form.nu()),
                short(s_end),
                short(t.scale)
            );
            if t.mirror_z {
                summary.push_str("&#8195;mirrored (τ &lt; 0)");
            }
            if t.reversed {
                summary.push_str("&#8195;reversed (standard form from P3 to P0)");
            }
            (heading, summary)
        }
        _ => {
            let planar = segment
                .planar()
                .expect("a segment without a standard form is planar");
            let heading = format!(
                "Log-aesthetic segment of coplanar points, α = {}",
                as_given(planar.alpha())
            );
            let summary = format!(
                "Coplanar control points: the planar segment is drawn (torsion 0)&#8195;Λ = \
                 {}&#8195;arc length = {length}",
                short(planar.lambda())
            );
            (heading, summary)
        }
    }
}

/// One orthographic panel, its top-left corner fixed by the view's column and row.
fn orthographic(svg: &mut String, scene: &Scene, view: &Ortho, layout: &Layout) {
    let (across, up) = (&scene.axes[view.across], &scene.axes[view.up]);
    let panel = Panel {
        left: layout.left[view.column],
        top: layout.top[view.row],
        width: layout.unit * (across.hi - across.lo),
        height: layout.unit * (up.hi - up.lo),
        x: across.clone(),
        y: up.clone(),
    };
    let _ = writeln!(svg, r#"<g class="panel" id="{}">"#, view.id);
    panel.draw_frame(
        svg,
        view.title,
        (NOTE, view.note),
        NAMES[view.across],
        NAMES[view.up],
    );
    let px = |p: &Vec3| panel.px(coordinate(p, view.across), coordinate(p, view.up));
    draw_curve(
        svg,
        &scene.points.iter().map(px).collect::<Vec<_>>(),
        &scene.curve.iter().map(px).collect::<Vec<_>>(),
    );
    svg.push_str("</g>\n");
}

/// The control polygon (dashed), the curve and the control points' markers, in pixels;
/// points that a view puts in one place share a label ("P0, P1").
fn draw_curve(svg: &mut String, polygon: &[Point], curve: &[Point]) {
    polyline(svg, polygon, POLYGON, 1.0, " stroke-dasharray=\"6 4\"");
    polyline(svg, curve, CURVE, 2.0, "");
    let mut labels: Vec<(Point, String)> = Vec::new();
    for (i, p) in polygon.iter().enumerate() {
        match labels.iter_mut().find(|(q, _)| q.distance(*p) < SAME_PLACE) {
            Some((_, label)) => {
                let _ = write!(label, ", P{i}");
            }
            None => labels.push((*p, format!("P{i}"))),
        }
    }
    for (p, label) in &labels {
        labelled_marker(svg, *p, label);
    }
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

/// The perspective panel, in the second column of the first row; returns the height of the
/// floor the shadow falls on.
fn perspective(svg: &mut String, scene: &Scene, layout: &Layout) -> f64 {
    let (left, top) = (layout.left[1], layout.top[0]);
    let (width, height) = (CELL, layout.perspective_height);
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
    panel_title(
        svg,
        left,
        top,
        "Perspective",
        (
            NOTE,
            &format!("azimuth {AZIMUTH}°, elevation {ELEVATION}°, shadow on the floor"),
        ),
    );
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
    // The axis triad.
    let o = px(&origin);
    for (c, tip) in tips.iter().enumerate() {
        let t = px(tip);
        let colour = AXIS_COLOURS[c];
        let _ = writeln!(
            svg,
            r#"<path stroke="{colour}" stroke-width="1.5" d="M{:.2},{:.2}L{:.2},{:.2}"/><text x="{:.2}" y="{:.2}" fill="{colour}" font-family="sans-serif" font-size="13" text-anchor="middle">{}</text>"#,
            o.x,
            o.y,
            t.x,
            t.y,
            t.x + 0.15 * (t.x - o.x),
            t.y + 0.15 * (t.y - o.y) + 4.0,
            NAMES[c]
        );
    }
    draw_curve(
        svg,
        &scene.points.iter().map(px).collect::<Vec<_>>(),
        &scene.curve.iter().map(px).collect::<Vec<_>>(),
    );
    svg.push_str("</g>\n");
    floor
}
