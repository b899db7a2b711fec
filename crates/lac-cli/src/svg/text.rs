//! Text laid out from the estimate of [`measure`], the same way in every
//! drawing: blocks of lines (a heading, a caption, a colour key, a footnote) set in a band
//! the canvas reserves for them, and labels beside markers placed where they are clear of
//! each other and of the edges.
//!
//! Every text is its own `<text>` element at a position computed here: a key's entries are
//! never left to run on after each other in the viewer's font, and a block is as high as
//! its lines need, so that the canvas can make room for it.

use std::fmt::Write as _;

use kurbo::{Point, Rect};

use super::measure::{self, Anchor, ASCENT, DESCENT, FAMILY};

/// Space kept free along every edge of a canvas, pixels.
pub(crate) const EDGE: f64 = 12.0;
/// Distance between the baselines of two lines of a block, in ems.
const LINE: f64 = 1.45;
/// Space between two entries of a list on one line, in ems.
const GAP: f64 = 1.5;
/// Length of a key's sample stroke, and the space between it and the entry's text, in ems.
const KEY: f64 = 1.6;
const KEY_GAP: f64 = 0.4;
/// How far a label is set off a marker's centre, pixels.
const OFFSET: f64 = 6.0;

/// What a key shows before an entry: a short stroke drawn as the layer it stands for, or a
/// dot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Key {
    /// A stroke `width` px wide in `colour`, at `opacity`, dashed when `dash` (an SVG
    /// `stroke-dasharray`) is given.
    Line {
        colour: &'static str,
        width: f64,
        opacity: f64,
        dash: Option<&'static str>,
    },
    /// A filled dot with a white rim, as a joint is marked.
    Dot(&'static str),
    /// A ring, as a joint on a control point is marked (around the point's own circle).
    Ring(&'static str),
}

impl Key {
    /// A solid, opaque stroke.
    pub(crate) fn line(colour: &'static str, width: f64) -> Key {
        Key::Line {
            colour,
            width,
            opacity: 1.0,
            dash: None,
        }
    }
}

/// One entry of a list: text in a colour, after an optional key.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Entry {
    /// What is drawn before the text.
    pub(crate) key: Option<Key>,
    /// The fill of the text.
    pub(crate) colour: &'static str,
    /// The text, unescaped.
    pub(crate) text: String,
}

impl Entry {
    /// An entry without a key.
    pub(crate) fn plain(colour: &'static str, text: impl Into<String>) -> Entry {
        Entry {
            key: None,
            colour,
            text: text.into(),
        }
    }

    /// An entry of a colour key: `key`, then `text` in the key's colour.
    pub(crate) fn keyed(key: Key, text: impl Into<String>) -> Entry {
        let colour = match key {
            Key::Line { colour, .. } | Key::Dot(colour) | Key::Ring(colour) => colour,
        };
        Entry {
            key: Some(key),
            colour,
            text: text.into(),
        }
    }

    /// Its width in `size` px text, key included.
    fn width(&self, size: f64) -> f64 {
        let key = if self.key.is_some() {
            (KEY + KEY_GAP) * size
        } else {
            0.0
        };
        key + measure::width(&self.text, size, false)
    }
}

/// How a paragraph is set.
#[derive(Clone, Debug, PartialEq)]
enum Paragraph {
    /// Running text in one colour, broken between words: one `<text>` a line.
    Prose(&'static str, String),
    /// Entries side by side, [`GAP`] apart, each moving whole to the next line when the
    /// line is full.
    List(Vec<Entry>),
}

/// Paragraphs of text in one size, laid out to a width: a heading, a caption with its colour
/// key, a footnote.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Block {
    size: f64,
    paragraphs: Vec<Paragraph>,
}

/// An entry placed on a line of a block: its left edge, from the block's left edge, pixels.
struct Placed<'a> {
    x: f64,
    key: Option<Key>,
    colour: &'static str,
    text: &'a str,
}

impl Block {
    /// An empty block of `size` px text.
    pub(crate) fn new(size: f64) -> Block {
        Block {
            size,
            paragraphs: Vec::new(),
        }
    }

    /// Add running text in `colour`, starting on a new line.
    pub(crate) fn prose(mut self, colour: &'static str, text: impl Into<String>) -> Block {
        self.paragraphs.push(Paragraph::Prose(colour, text.into()));
        self
    }

    /// Add a list of entries, starting on a new line (nothing for no entries).
    pub(crate) fn list(mut self, entries: Vec<Entry>) -> Block {
        if !entries.is_empty() {
            self.paragraphs.push(Paragraph::List(entries));
        }
        self
    }

    /// The narrowest width the block can be laid out to without a line overflowing: its
    /// widest word or entry, pixels.
    pub(crate) fn min_width(&self) -> f64 {
        let size = self.size;
        self.paragraphs
            .iter()
            .flat_map(|p| match p {
                Paragraph::Prose(_, text) => text
                    .split(' ')
                    .map(|word| measure::width(word, size, false))
                    .collect::<Vec<_>>(),
                Paragraph::List(entries) => entries.iter().map(|e| e.width(size)).collect(),
            })
            .fold(0.0, f64::max)
    }

    /// The height of the block laid out to `width`, from the top of its first line's box to
    /// the bottom of its last, pixels (0 when empty).
    pub(crate) fn height(&self, width: f64) -> f64 {
        match self.lines(width).len() {
            0 => 0.0,
            n => ((n - 1) as f64 * LINE + ASCENT + DESCENT) * self.size,
        }
    }

    /// Write the block laid out to `width` with the top-left corner of its first line's box
    /// at (`left`, `top`).
    pub(crate) fn draw(&self, svg: &mut String, left: f64, top: f64, width: f64) {
        let size = self.size;
        for (i, line) in self.lines(width).iter().enumerate() {
            let baseline = top + (ASCENT + i as f64 * LINE) * size;
            for placed in line {
                let mut x = left + placed.x;
                if let Some(key) = placed.key {
                    draw_key(svg, key, x, baseline - 0.32 * size, size);
                    x += (KEY + KEY_GAP) * size;
                }
                let _ = writeln!(
                    svg,
                    r#"<text x="{x:.2}" y="{baseline:.2}" fill="{}" font-family="{FAMILY}" font-size="{size}">{}</text>"#,
                    placed.colour,
                    escape(placed.text)
                );
            }
        }
    }

    /// The lines of the block laid out to `width` (a word or an entry wider than that gets a
    /// line of its own).
    fn lines(&self, width: f64) -> Vec<Vec<Placed<'_>>> {
        let size = self.size;
        let mut lines: Vec<Vec<Placed>> = Vec::new();
        for paragraph in &self.paragraphs {
            match paragraph {
                Paragraph::Prose(colour, text) => {
                    for line in break_lines(text, width, |t| measure::width(t, size, false)) {
                        lines.push(vec![Placed {
                            x: 0.0,
                            key: None,
                            colour,
                            text: line,
                        }]);
                    }
                }
                Paragraph::List(entries) => {
                    let mut line: Vec<Placed> = Vec::new();
                    let mut x = 0.0;
                    for entry in entries {
                        let w = entry.width(size);
                        if !line.is_empty() && x + w > width {
                            lines.push(std::mem::take(&mut line));
                            x = 0.0;
                        }
                        line.push(Placed {
                            x,
                            key: entry.key,
                            colour: entry.colour,
                            text: &entry.text,
                        });
                        x += w + GAP * size;
                    }
                    lines.push(line);
                }
            }
        }
        lines
    }
}

/// `text` broken between words into lines no wider than `width` by `measure`, as slices of
/// `text` (a word wider than that is a line of its own).
fn break_lines(text: &str, width: f64, measure: impl Fn(&str) -> f64) -> Vec<&str> {
    let mut lines = Vec::new();
    let mut start = 0;
    let mut end = 0;
    for (at, _) in text.match_indices(' ').chain([(text.len(), "")]) {
        if end > start && measure(&text[start..at]) > width {
            lines.push(&text[start..end]);
            start = end + 1;
        }
        end = at;
    }
    if start < text.len() {
        lines.push(&text[start..]);
    }
    lines
}

/// A key centred vertically on `y`, from `x`, for `size` px text.
fn draw_key(svg: &mut String, key: Key, x: f64, y: f64, size: f64) {
    match key {
        Key::Line {
            colour,
            width,
            opacity,
            dash,
        } => {
            let dash = dash
                .map(|d| format!(r#" stroke-dasharray="{d}""#))
                .unwrap_or_default();
            let opacity = if opacity < 1.0 {
                format!(r#" stroke-opacity="{opacity}""#)
            } else {
                String::new()
            };
            let _ = writeln!(
                svg,
                r#"<path class="key" stroke="{colour}" stroke-width="{width}"{opacity}{dash} stroke-linecap="butt" d="M{x:.2},{y:.2}h{:.2}"/>"#,
                KEY * size
            );
        }
        Key::Dot(colour) => {
            let _ = writeln!(
                svg,
                r#"<circle class="key" cx="{:.2}" cy="{y:.2}" r="4.5" fill="{colour}" stroke="white" stroke-width="1.25"/>"#,
                x + 0.5 * KEY * size
            );
        }
        Key::Ring(colour) => {
            let _ = writeln!(
                svg,
                r#"<circle class="key" cx="{:.2}" cy="{y:.2}" r="6" fill="none" stroke="{colour}" stroke-width="2"/>"#,
                x + 0.5 * KEY * size
            );
        }
    }
}

/// `text` with the characters that XML reserves escaped.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Labels beside markers, placed one after another where they are clear of the labels (and
/// other texts) placed before and inside a room.
#[derive(Clone, Debug)]
pub(crate) struct Labels {
    size: f64,
    taken: Vec<Rect>,
}

impl Labels {
    /// Labels of `size` px text, none placed yet.
    pub(crate) fn new(size: f64) -> Labels {
        Labels {
            size,
            taken: Vec::new(),
        }
    }

    /// Keep labels clear of `rect`, a text placed otherwise.
    pub(crate) fn avoid(&mut self, rect: Rect) {
        self.taken.push(rect);
    }

    /// The baseline start of `text` beside markers centred in `at` (a point, or the box of
    /// the centres of markers that share a label): above right of them, or else above left,
    /// below right or below left, the first of these inside `room` and clear of the labels
    /// placed so far; when none is, the one that leaves the least of the label outside
    /// `room`, moved into it.
    pub(crate) fn place(&mut self, at: Rect, text: &str, room: Rect) -> Point {
        let size = self.size;
        let w = measure::width(text, size, false);
        let (above, below) = (at.y0 - OFFSET, at.y1 + OFFSET + ASCENT * size);
        let (right, left) = (at.x1 + OFFSET, at.x0 - OFFSET - w);
        let candidates = [(right, above), (left, above), (right, below), (left, below)];
        let boxed =
            |(x, y): (f64, f64)| measure::text_box(text, size, false, (x, y), Anchor::Start);
        let clear = |r: &Rect| self.taken.iter().all(|t| t.intersect(*r).area() <= 0.0);
        let inside = |r: &Rect| r.union(room) == room;
        let chosen = candidates
            .iter()
            .copied()
            .find(|&c| inside(&boxed(c)) && clear(&boxed(c)))
            .unwrap_or_else(|| {
                let outside = |c: (f64, f64)| {
                    let r = boxed(c);
                    r.area() - r.intersect(room).area()
                };
                let best = candidates
                    .iter()
                    .copied()
                    .min_by(|&a, &b| outside(a).total_cmp(&outside(b)))
                    .expect("four candidates");
                let r = boxed(best);
                let dx = (room.x0 - r.x0).max(0.0) + (room.x1 - r.x1).min(0.0);
                let dy = (room.y0 - r.y0).max(0.0) + (room.y1 - r.y1).min(0.0);
                (best.0 + dx, best.1 + dy)
            });
        self.taken.push(boxed(chosen));
        Point::new(chosen.0, chosen.1)
    }
}

/// Control point labels for markers at `points`, each with the box of the markers' centres
/// it labels: markers closer than `near` pixels to the first of a group share one label, "P0,
/// P1", and three or more in a row read "P0–P3".
pub(crate) fn point_labels(points: &[Point], near: f64) -> Vec<(Rect, String)> {
    let mut groups: Vec<(Point, Vec<usize>)> = Vec::new();
    for (i, p) in points.iter().enumerate() {
        match groups.iter_mut().find(|(q, _)| q.distance(*p) < near) {
            Some((_, members)) => members.push(i),
            None => groups.push((*p, vec![i])),
        }
    }
    groups
        .into_iter()
        .map(|(_, members)| {
            let first = points[members[0]];
            let centres = members.iter().map(|&i| points[i]);
            let at = centres.fold(Rect::from_points(first, first), |r, p| r.union_pt(p));
            (at, names(&members))
        })
        .collect()
}

/// "P0", "P0, P2", "P1–P3" (ascending indices; runs of three or more shortened).
fn names(indices: &[usize]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < indices.len() {
        let mut j = i;
        while j + 1 < indices.len() && indices[j + 1] == indices[j] + 1 {
            j += 1;
        }
        if j >= i + 2 {
            parts.push(format!("P{}–P{}", indices[i], indices[j]));
        } else {
            parts.extend(indices[i..=j].iter().map(|k| format!("P{k}")));
        }
        i = j + 1;
    }
    parts.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prose_breaks_between_words_and_never_loses_one() {
        let text = "one two three four five";
        let by_chars = |t: &str| t.chars().count() as f64;
        assert_eq!(
            break_lines(text, 9.0, by_chars),
            ["one two", "three", "four five"]
        );
        assert_eq!(break_lines(text, 100.0, by_chars), [text]);
        assert_eq!(
            break_lines(text, 1.0, by_chars),
            ["one", "two", "three", "four", "five"]
        );
        assert!(break_lines("", 10.0, by_chars).is_empty());
    }

    #[test]
    fn a_list_wraps_whole_entries_and_its_height_counts_the_lines() {
        let entries: Vec<Entry> = ["alpha", "beta", "gamma"]
            .iter()
            .map(|t| Entry::plain("#111", *t))
            .collect();
        let block = Block::new(10.0).list(entries);
        let widest = measure::width("gamma", 10.0, false);
        assert_eq!(block.min_width(), widest);
        let one_line = block.height(1000.0);
        assert!((one_line - 10.0 * (ASCENT + DESCENT)).abs() < 1e-12);
        let stacked = block.height(widest);
        assert!((stacked - one_line - 2.0 * LINE * 10.0).abs() < 1e-9);
        let lines = block.lines(widest);
        assert!(lines.iter().all(|l| l.len() == 1 && l[0].x == 0.0));
    }

    #[test]
    fn a_label_that_would_leave_the_room_or_cover_another_goes_to_the_other_side() {
        let room = Rect::new(0.0, 0.0, 100.0, 100.0);
        let mut labels = Labels::new(12.0);
        let at = |x: f64, y: f64| Rect::from_points((x, y), (x, y));
        let first = labels.place(at(50.0, 50.0), "P0", room);
        assert_eq!(first, Point::new(56.0, 44.0), "above right");
        let second = labels.place(at(52.0, 50.0), "P1", room);
        assert!(second.x < 52.0, "above left, clear of P0: {second:?}");
        let edge = labels.place(at(98.0, 20.0), "P2", room);
        assert!(edge.x + measure::width("P2", 12.0, false) <= 100.0);
        // Nowhere beside the marker fits: the label is moved into the room.
        let small = Rect::new(0.0, 0.0, 60.0, 60.0);
        let corner = labels.place(at(59.0, 1.0), "P0–P2", small);
        let r = measure::text_box("P0–P2", 12.0, false, (corner.x, corner.y), Anchor::Start);
        assert!(r.x0 >= 0.0 && r.x1 <= 60.0 && r.y0 >= 0.0, "{r:?}");
    }

    #[test]
    fn markers_in_one_place_share_a_label_and_runs_are_shortened() {
        let p = |x: f64| Point::new(x, 0.0);
        let labels = point_labels(&[p(0.0), p(1.0), p(2.0), p(50.0)], 6.0);
        assert_eq!(labels.len(), 2);
        assert_eq!(
            labels[0],
            (Rect::new(0.0, 0.0, 2.0, 0.0), "P0–P2".to_string())
        );
        assert_eq!(labels[1].1, "P3");
        assert_eq!(names(&[0, 1]), "P0, P1");
        assert_eq!(names(&[0, 2, 3]), "P0, P2, P3");
        assert_eq!(names(&[0, 1, 2, 3]), "P0–P3");
    }
}
