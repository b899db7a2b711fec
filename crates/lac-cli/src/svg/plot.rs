//! Plot panels with labelled axes, for the two-panel picture of `lac lcg` and the views of
//! `lac space`: the tick labels thinned out where they would touch, and the room they and the
//! axis titles take around the plot area known before the panels are placed.

use std::fmt::Write as _;

use kurbo::Point;

use super::measure::{self, Anchor, ASCENT, DESCENT, FAMILY};

/// Most intervals between ticks on an axis.
const MAX_INTERVALS: f64 = 8.0;
/// Size of the tick labels, of the axis titles and panel subtitles, and of the panel titles,
/// pixels.
const TICK_SIZE: f64 = 11.0;
const TITLE_SIZE: f64 = 13.0;
const HEADING_SIZE: f64 = 15.0;
/// Space between a tick label and the frame, and between the tick labels and the axis
/// title, pixels.
const TICK_GAP: f64 = 6.0;
const TITLE_GAP: f64 = 8.0;
/// Least space between two tick labels along an axis, pixels.
const LABEL_GAP: f64 = 8.0;
/// Baselines under the plot area: the x tick labels and the x axis title, pixels.
const X_LABELS: f64 = 18.0;
const X_TITLE: f64 = 40.0;
/// Baselines over the plot area: the panel's title and the line under it, pixels.
const TITLE_ABOVE: f64 = 32.0;
const SUBTITLE_ABOVE: f64 = 14.0;
/// The room a panel's labels take under its plot area and over it, pixels.
pub(crate) const BELOW: f64 = X_TITLE + DESCENT * TITLE_SIZE + 1.0;
pub(crate) const ABOVE: f64 = TITLE_ABOVE + ASCENT * HEADING_SIZE + 1.0;

const FRAME: &str = "#444";
const GRID: &str = "#e8e8e8";
const LABEL: &str = "#333";

/// One axis: its range, widened to whole ticks of 1, 2 or 5 × 10ᵏ.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Axis {
    /// The low end (a tick).
    pub(crate) lo: f64,
    /// The high end (a tick).
    pub(crate) hi: f64,
    step: f64,
}

impl Axis {
    /// The axis covering the finite values among `values` (0 to 1 when there is none); a
    /// single value gets a little room on both sides.
    pub(crate) fn covering(values: impl IntoIterator<Item = f64>) -> Axis {
        let (lo, hi) = values
            .into_iter()
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        if lo > hi {
            return Axis::nice(0.0, 1.0);
        }
        Axis::nice(lo, hi)
    }

    /// Axes drawn at one scale (the views of a space curve): each covers one `(min, max)`
    /// range on the ticks of the widest range; a range within one tick gets one step on
    /// either side.
    pub(crate) fn common(ranges: &[(f64, f64)]) -> Vec<Axis> {
        let (lo, hi) = ranges
            .iter()
            .copied()
            .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)))
            .unwrap_or((0.0, 1.0));
        let step = Axis::nice(lo, hi).step;
        ranges
            .iter()
            .map(|&(lo, hi)| {
                let (mut lo, mut hi) = ((lo / step).floor() * step, (hi / step).ceil() * step);
                if hi <= lo {
                    lo -= step;
                    hi += step;
                }
                Axis { lo, hi, step }
            })
            .collect()
    }

    /// The axis from about `lo` to `hi` (finite, `lo ≤ hi`).
    fn nice(lo: f64, hi: f64) -> Axis {
        let mut span = hi - lo;
        let (lo, hi) = if span <= 1e-9 * lo.abs().max(hi.abs()) || span == 0.0 {
            // One value (or a spread lost in its rounding): ±10 % of it, or ±1 around 0.
            let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            span = 2.0 * pad;
            (lo - pad, hi + pad)
        } else {
            (lo, hi)
        };
        // The smallest step of 1, 2 or 5 × 10ᵏ that leaves at most MAX_INTERVALS.
        let raw = span / MAX_INTERVALS;
        let magnitude = 10f64.powf(raw.log10().floor());
        let step = [1.0, 2.0, 5.0, 10.0]
            .iter()
            .map(|m| m * magnitude)
            .find(|&s| span / s <= MAX_INTERVALS)
            .unwrap_or(10.0 * magnitude);
        Axis {
            lo: (lo / step).floor() * step,
            hi: (hi / step).ceil() * step,
            step,
        }
    }

    /// The tick values, low to high.
    pub(crate) fn ticks(&self) -> Vec<f64> {
        let first = (self.lo / self.step).round() as i64;
        let last = (self.hi / self.step).round() as i64;
        (first..=last).map(|k| k as f64 * self.step).collect()
    }

    /// A tick value written with as many digits as the step needs ("0.25", "-3", "1.2e-6").
    pub(crate) fn label(&self, v: f64) -> String {
        if v.abs() < 1e-9 * self.step {
            return "0".into();
        }
        let step_digits = self.step.log10().floor() as i32;
        let largest = self.lo.abs().max(self.hi.abs());
        if (-4..6).contains(&step_digits) && largest < 1e6 {
            let decimals = (-step_digits).max(0) as usize;
            format!("{v:.decimals$}")
        } else {
            let decimals = (v.abs().log10().floor() as i32 - step_digits).max(0) as usize;
            format!("{v:.decimals$e}")
        }
    }

    /// Where `v` falls between the ends, 0 at `lo` and 1 at `hi`.
    fn fraction(&self, v: f64) -> f64 {
        (v - self.lo) / (self.hi - self.lo)
    }

    /// The ticks that get a label, with their labels, on an axis `length` pixels long whose
    /// labels take `extent(label)` pixels along it: every tick, or every 2nd, 5th, 10th, …
    /// (the multiples of that many steps), so that neighbouring labels keep [`LABEL_GAP`]
    /// apart.
    fn labels(&self, length: f64, extent: impl Fn(&str) -> f64) -> Vec<(f64, String)> {
        let ticks = self.ticks();
        let all: Vec<(f64, String)> = ticks.iter().map(|&v| (v, self.label(v))).collect();
        let widest = all.iter().map(|(_, l)| extent(l)).fold(0.0, f64::max);
        let spacing = length / (ticks.len().max(2) - 1) as f64;
        let every = [1, 2, 5, 10, 20, 50, 100]
            .into_iter()
            .find(|&k| k as f64 * spacing >= widest + LABEL_GAP)
            .unwrap_or(ticks.len());
        all.into_iter()
            .filter(|(v, _)| ((v / self.step).round() as i64).rem_euclid(every as i64) == 0)
            .collect()
    }
}

/// A plot area in pixels and the axes it shows.
#[derive(Clone, Debug)]
pub(crate) struct Panel {
    /// Left edge of the plot area, pixels.
    pub(crate) left: f64,
    /// Top edge, pixels.
    pub(crate) top: f64,
    /// Width, pixels.
    pub(crate) width: f64,
    /// Height, pixels.
    pub(crate) height: f64,
    /// The horizontal axis.
    pub(crate) x: Axis,
    /// The vertical axis (up).
    pub(crate) y: Axis,
}

impl Panel {
    /// The pixel position of the data point (x, y).
    pub(crate) fn px(&self, x: f64, y: f64) -> Point {
        Point::new(
            self.left + self.x.fraction(x) * self.width,
            self.top + (1.0 - self.y.fraction(y)) * self.height,
        )
    }

    /// The labelled ticks of the x axis, with their labels.
    fn x_labels(&self) -> Vec<(f64, String)> {
        self.x
            .labels(self.width, |l| measure::width(l, TICK_SIZE, false))
    }

    /// The labelled ticks of the y axis, with their labels.
    fn y_labels(&self) -> Vec<(f64, String)> {
        let height = (ASCENT + DESCENT) * TICK_SIZE;
        self.y.labels(self.height, |_| height)
    }

    /// The room the y tick labels and the y axis title take left of the plot area, pixels.
    pub(crate) fn room_left(&self) -> f64 {
        let widest = self
            .y_labels()
            .iter()
            .map(|(_, l)| measure::width(l, TICK_SIZE, false))
            .fold(0.0, f64::max);
        TICK_GAP + widest + TITLE_GAP + (ASCENT + DESCENT) * TITLE_SIZE
    }

    /// How far the x tick labels reach beyond the plot area on the left and on the right,
    /// pixels (half of a label centred on a corner).
    pub(crate) fn overhang(&self) -> (f64, f64) {
        let reach = |(v, l): &(f64, String)| {
            let x = self.px(*v, self.y.lo).x;
            let half = 0.5 * measure::width(l, TICK_SIZE, false);
            (
                (self.left - (x - half)).max(0.0),
                (x + half - self.left - self.width).max(0.0),
            )
        };
        self.x_labels()
            .iter()
            .map(reach)
            .fold((0.0, 0.0), |a, b| (a.0.max(b.0), a.1.max(b.1)))
    }

    /// The grid, the frame, the tick labels, the axis titles, and the panel's title with a
    /// line of `(colour, text)` under it, in the room [`Panel::room_left`], [`BELOW`] and
    /// [`ABOVE`] say.
    pub(crate) fn draw_frame(
        &self,
        svg: &mut String,
        title: &str,
        subtitle: (&str, &str),
        x_title: &str,
        y_title: &str,
    ) {
        let (l, t, w, h) = (self.left, self.top, self.width, self.height);
        let (b, r) = (t + h, l + w);
        let _ = write!(svg, r#"<path stroke="{GRID}" stroke-width="1" d=""#);
        for v in self.x.ticks() {
            let x = self.px(v, self.y.lo).x;
            let _ = write!(svg, "M{x:.2},{t:.2}V{b:.2}");
        }
        for v in self.y.ticks() {
            let y = self.px(self.x.lo, v).y;
            let _ = write!(svg, "M{l:.2},{y:.2}H{r:.2}");
        }
        svg.push_str("\"/>\n");
        if self.y.lo < 0.0 && self.y.hi > 0.0 {
            let y = self.px(self.x.lo, 0.0).y;
            let _ = writeln!(
                svg,
                r##"<path stroke="#999" stroke-width="1" d="M{l:.2},{y:.2}H{r:.2}"/>"##
            );
        }
        let _ = writeln!(
            svg,
            r#"<rect x="{l:.2}" y="{t:.2}" width="{w:.2}" height="{h:.2}" stroke="{FRAME}" stroke-width="1"/>"#
        );
        let _ = writeln!(
            svg,
            r#"<g fill="{LABEL}" font-family="{FAMILY}" font-size="{TICK_SIZE}">"#
        );
        for (v, label) in self.x_labels() {
            let x = self.px(v, self.y.lo).x;
            let _ = writeln!(
                svg,
                r#"<text x="{x:.2}" y="{:.2}" text-anchor="{}">{label}</text>"#,
                b + X_LABELS,
                Anchor::Middle.name(),
            );
        }
        // The labels' boxes centred on the ticks.
        let middle = 0.5 * (ASCENT - DESCENT) * TICK_SIZE;
        for (v, label) in self.y_labels() {
            let y = self.px(self.x.lo, v).y;
            let _ = writeln!(
                svg,
                r#"<text x="{:.2}" y="{:.2}" text-anchor="{}">{label}</text>"#,
                l - TICK_GAP,
                y + middle,
                Anchor::End.name(),
            );
        }
        svg.push_str("</g>\n");
        // The y title turned to read upwards: its ascent points left, away from the labels.
        let y_title_x = l - self.room_left() + ASCENT * TITLE_SIZE;
        let _ = writeln!(
            svg,
            r#"<g fill="{LABEL}" font-family="{FAMILY}" font-size="{TITLE_SIZE}"><text x="{:.2}" y="{:.2}" text-anchor="middle">{x_title}</text><text transform="translate({y_title_x:.2},{:.2}) rotate(-90)" text-anchor="middle">{y_title}</text></g>"#,
            l + 0.5 * w,
            b + X_TITLE,
            t + 0.5 * h,
        );
        panel_title(svg, l, t, title, subtitle);
    }
}

/// A panel's title in bold and a line of `(colour, text)` under it, above the plot area whose
/// top-left corner is (`left`, `top`).
pub(crate) fn panel_title(
    svg: &mut String,
    left: f64,
    top: f64,
    title: &str,
    subtitle: (&str, &str),
) {
    let _ = writeln!(
        svg,
        r##"<text x="{left:.2}" y="{:.2}" fill="#111" font-family="{FAMILY}" font-size="{HEADING_SIZE}" font-weight="bold">{title}</text>"##,
        top - TITLE_ABOVE
    );
    let (colour, text) = subtitle;
    let _ = writeln!(
        svg,
        r#"<text x="{left:.2}" y="{:.2}" fill="{colour}" font-family="{FAMILY}" font-size="{TITLE_SIZE}">{text}</text>"#,
        top - SUBTITLE_ABOVE
    );
}

/// The width of a panel's title or of the line under it, whichever is wider, pixels.
pub(crate) fn title_width(title: &str, subtitle: &str) -> f64 {
    measure::width(title, HEADING_SIZE, true).max(measure::width(subtitle, TITLE_SIZE, false))
}

/// The box of a y tick label, for tests.
#[cfg(test)]
fn y_label_box(panel: &Panel, v: f64, label: &str) -> kurbo::Rect {
    let y = panel.px(panel.x.lo, v).y + 0.5 * (ASCENT - DESCENT) * TICK_SIZE;
    measure::text_box(
        label,
        TICK_SIZE,
        false,
        (panel.left - TICK_GAP, y),
        Anchor::End,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_widen_to_round_ticks_and_label_them_with_the_digits_needed() {
        let a = Axis::covering([0.13, 2.71]);
        assert_eq!((a.lo, a.hi), (0.0, 3.0));
        assert_eq!(a.ticks().len(), 7);
        assert_eq!(a.label(1.5), "1.5");
        let tight = Axis::covering([0.0, 3.01]);
        assert_eq!((tight.lo, tight.hi), (0.0, 3.5));
        let b = Axis::covering([-1.2e-6, 3.3e-6]);
        assert!(b.lo <= -1.2e-6 && b.hi >= 3.3e-6);
        assert_eq!(b.label(b.ticks()[1]), "-1e-6");
        let c = Axis::covering([2.0, 2.0, f64::NAN]);
        assert!(c.lo < 2.0 && c.hi > 2.0);
        assert_eq!(Axis::covering([]), Axis::covering([0.0, 1.0]));
        assert_eq!(Axis::covering([-0.3, 0.3]).label(0.0), "0");
    }

    /// A panel of `width` × `height` pixels at (200, 100) showing `x` against `y`.
    fn panel(x: Axis, y: Axis, width: f64, height: f64) -> Panel {
        Panel {
            left: 200.0,
            top: 100.0,
            width,
            height,
            x,
            y,
        }
    }

    #[test]
    fn long_tick_labels_are_thinned_out_until_neighbours_keep_apart() {
        // Far from the origin, every tick needs all its digits: "1.2345665e6".
        let offset = Axis::covering([1234566.6, 1234570.4]);
        let p = panel(offset.clone(), offset, 360.0, 360.0);
        let labels = p.x_labels();
        assert!(labels.len() >= 2 && labels.len() < p.x.ticks().len());
        let boxes: Vec<kurbo::Rect> = labels
            .iter()
            .map(|(v, l)| {
                let at = (p.px(*v, p.y.lo).x, 0.0);
                measure::text_box(l, TICK_SIZE, false, at, Anchor::Middle)
            })
            .collect();
        for pair in boxes.windows(2) {
            assert!(pair[1].x0 - pair[0].x1 >= LABEL_GAP, "{pair:?}");
        }
        // Short labels are all kept.
        let short = panel(
            Axis::covering([0.0, 3.0]),
            Axis::covering([0.0, 1.0]),
            360.0,
            360.0,
        );
        assert_eq!(short.x_labels().len(), short.x.ticks().len());
        assert_eq!(short.y_labels().len(), short.y.ticks().len());
    }

    #[test]
    fn the_y_title_clears_the_widest_tick_label_inside_the_room_it_asks_for() {
        let p = panel(
            Axis::covering([0.0, 1.0]),
            Axis::covering([-1234567.0, 7654321.0]),
            420.0,
            330.0,
        );
        let mut svg = String::new();
        p.draw_frame(&mut svg, "Title", ("#555", "note"), "x", "a long y title");
        let title_x: f64 = svg
            .split("translate(")
            .nth(1)
            .and_then(|t| t.split(',').next())
            .unwrap()
            .parse()
            .unwrap();
        // Turned to read upwards, the title's ascent lies left of its baseline.
        let (left, right) = (
            title_x - ASCENT * TITLE_SIZE,
            title_x + DESCENT * TITLE_SIZE,
        );
        assert!(left >= p.left - p.room_left() - 0.01, "{left}");
        for (v, label) in p.y_labels() {
            let r = y_label_box(&p, v, &label);
            assert!(r.x0 - right >= TITLE_GAP - 0.01, "{label}: {r:?} {right}");
            assert!(svg.contains(&format!(">{label}</text>")));
        }
    }

    #[test]
    fn common_axes_share_the_widest_ones_step() {
        let axes = Axis::common(&[(0.0, 2.0), (0.1, 0.35), (0.0, 0.0)]);
        assert_eq!((axes[0].lo, axes[0].hi), (0.0, 2.0));
        assert_eq!((axes[1].lo, axes[1].hi), (0.0, 0.5));
        assert_eq!((axes[2].lo, axes[2].hi), (-0.5, 0.5));
        assert!(axes.iter().all(|a| a.step == axes[0].step));
    }
}
