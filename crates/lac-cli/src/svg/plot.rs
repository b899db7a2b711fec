//! Plot panels with labelled axes, for the two-panel picture of `lac lcg`.

use std::fmt::Write as _;

use kurbo::Point;

/// Most intervals between ticks on an axis.
const MAX_INTERVALS: f64 = 8.0;

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

    /// The grid, the frame, the tick labels, the axis titles, and the panel's title with a
    /// line of `(colour, text)` under it.
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
            r#"<g fill="{LABEL}" font-family="sans-serif" font-size="11">"#
        );
        for v in self.x.ticks() {
            let x = self.px(v, self.y.lo).x;
            let _ = writeln!(
                svg,
                r#"<text x="{x:.2}" y="{:.2}" text-anchor="middle">{}</text>"#,
                b + 16.0,
                self.x.label(v)
            );
        }
        for v in self.y.ticks() {
            let y = self.px(self.x.lo, v).y;
            let _ = writeln!(
                svg,
                r#"<text x="{:.2}" y="{:.2}" text-anchor="end">{}</text>"#,
                l - 6.0,
                y + 4.0,
                self.y.label(v)
            );
        }
        svg.push_str("</g>\n");
        let _ = writeln!(
            svg,
            r#"<g fill="{LABEL}" font-family="sans-serif" font-size="13"><text x="{:.2}" y="{:.2}" text-anchor="middle">{x_title}</text><text transform="translate({:.2},{:.2}) rotate(-90)" text-anchor="middle">{y_title}</text></g>"#,
            l + 0.5 * w,
            b + 38.0,
            l - 62.0,
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
        r##"<text x="{left:.2}" y="{:.2}" fill="#111" font-family="sans-serif" font-size="15" font-weight="bold">{title}</text>"##,
        top - 30.0
    );
    let (colour, text) = subtitle;
    let _ = writeln!(
        svg,
        r#"<text x="{left:.2}" y="{:.2}" fill="{colour}" font-family="sans-serif" font-size="13">{text}</text>"#,
        top - 10.0
    );
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

    #[test]
    fn common_axes_share_the_widest_ones_step() {
        let axes = Axis::common(&[(0.0, 2.0), (0.1, 0.35), (0.0, 0.0)]);
        assert_eq!((axes[0].lo, axes[0].hi), (0.0, 2.0));
        assert_eq!((axes[1].lo, axes[1].hi), (0.0, 0.5));
        assert_eq!((axes[2].lo, axes[2].hi), (-0.5, 0.5));
        assert!(axes.iter().all(|a| a.step == axes[0].step));
    }
}
