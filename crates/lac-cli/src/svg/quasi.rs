//! `lac quasi --format svg`: the Bézier pieces drawn over the log-aesthetic curve they
//! replace, with their control polygons and joints, and the curvature combs of both curves
//! at one scale, so that where the approximation's curvature strays shows as a gap between
//! the two envelopes.

use std::fmt::Write as _;

use kurbo::{BezPath, CubicBez, ParamCurve, ParamCurveArclen, PathSeg, Point, Rect};
use lac::Curve;
use lac::{QuasiCurve, RationalCubic, Sample, Segment};

use super::comb::{max_curvature, Comb};
use super::text::{Block, Entry, Key, Labels};
use super::view::View;
use super::{
    bounding_box, control_points, dot, drawing_size, polyline, segments, short, CAPTION_SIZE, COMB,
    COMB_LENGTH, CURVE, JOINT, LABEL_SIZE, POLYGON, TOLERANCE,
};
use lac_io::json::ErrorBody;

/// Comb teeth along the whole curve, for both combs.
const TEETH: usize = 64;
/// Samples of the log-aesthetic curve the caller passes (equally spaced in arc length): a
/// tooth at every eighth, the envelope through all.
pub(crate) const LAC_SAMPLES: usize = 8 * TEETH + 1;
/// Points on the drawn rational pieces and the approximation's comb envelope, in all.
const BEZIER_POINTS: usize = 1024;

/// The log-aesthetic curve: thin, on top, so that the approximation shows around it.
const LAC: &str = "#111";
/// The Bézier pieces: a wider translucent band under the curve.
const BEZIER: &str = "#1f6fd1";
/// The Bézier pieces' control polygons.
const BEZIER_POLYGON: &str = "#7fa7e3";
/// The approximation's comb (the curve's is [`COMB`]).
const BEZIER_COMB: &str = "#1f6fd1";

/// The layers of the drawing, in drawing coordinates.
struct Layers {
    /// The log-aesthetic curve's control points.
    points: Vec<Point>,
    /// The log-aesthetic curve.
    curve: Vec<Point>,
    beziers: Vec<RationalCubic>,
    /// The pieces as one kurbo path, when they are all plain cubics.
    path: Option<BezPath>,
    /// The curve's comb: envelope through every sample, teeth at every eighth.
    lac_comb: Comb,
    lac_teeth: Comb,
    /// The pieces' comb: envelope through dense samples, teeth paired with the curve's.
    bezier_comb: Comb,
    bezier_teeth: Comb,
}

/// The SVG document for `quasi`, the Bézier replacement of the curve made of `pieces` (in
/// order) with control points `points`; `lac_samples` are [`LAC_SAMPLES`] samples of it
/// equally spaced in arc length; `cubic`: plain cubics (drawn as `C` commands).
pub(crate) fn render(
    pieces: &[Segment],
    points: &[Point],
    lac_samples: &[Sample],
    quasi: &QuasiCurve,
    cubic: bool,
) -> Result<String, ErrorBody> {
    let layers = Layers::new(pieces, points, lac_samples, quasi)?;
    let caption = caption(pieces, quasi, cubic);
    let view = View::fit(layers.bounds(), &caption);
    let mut svg = String::new();
    open(&mut svg, &view, pieces, quasi.pieces.len(), cubic);
    layers.draw(&mut svg, &view, cubic);
    view.caption(&mut svg, &caption);
    svg.push_str("</svg>\n");
    Ok(svg)
}

impl Layers {
    fn new(
        pieces: &[Segment],
        points: &[Point],
        lac_samples: &[Sample],
        quasi: &QuasiCurve,
    ) -> Result<Layers, ErrorBody> {
        let tolerance = TOLERANCE * drawing_size(&bounding_box(points));
        let mut curve: Vec<Point> = Vec::new();
        for (i, piece) in pieces.iter().enumerate() {
            let samples = piece.sample_adaptive(tolerance)?;
            if i > 0 {
                curve.pop();
            }
            curve.extend(samples.iter().map(|s| s.point));
        }
        let beziers: Vec<RationalCubic> = quasi.pieces.iter().map(|p| p.curve).collect();
        let dense = bezier_samples(&beziers, BEZIER_POINTS);
        let lac_teeth = every_eighth(lac_samples);
        // The pieces' teeth at the same share of the arc length as the curve's, so that the
        // two combs' teeth pair up and differ only where the curvatures do.
        let lac_length = lac_samples.last().map_or(0.0, |s| s.s);
        let bezier_length = dense.last().map_or(0.0, |s| s.s);
        let at: Vec<f64> = lac_teeth
            .iter()
            .map(|t| t.s / lac_length * bezier_length)
            .collect();
        let teeth = bezier_at_arc_lengths(&beziers, &at);

        // One scale for both combs: the longest tooth of either is COMB_LENGTH.
        let size = drawing_size(&bounding_box(points).union(bounding_box(&curve)));
        let k_max = max_curvature(lac_samples).max(max_curvature(&dense));
        let scale = if k_max > 0.0 {
            COMB_LENGTH * size / k_max
        } else {
            0.0
        };
        Ok(Layers {
            points: points.to_vec(),
            curve,
            beziers,
            path: quasi.to_bez_path(),
            lac_comb: Comb::scaled(lac_samples, scale),
            lac_teeth: Comb::scaled(&lac_teeth, scale),
            bezier_comb: Comb::scaled(&dense, scale),
            bezier_teeth: Comb::scaled(&teeth, scale),
        })
    }

    /// Everything that is drawn, so that the view can fit it.
    fn bounds(&self) -> Rect {
        let mut bounds = bounding_box(&self.points)
            .union(bounding_box(&self.curve))
            .union(bounding_box(&self.lac_comb.envelope()))
            .union(bounding_box(&self.bezier_comb.envelope()));
        for b in &self.beziers {
            bounds = bounds.union(bounding_box(&b.points()));
        }
        bounds
    }

    /// Back to front: the control polygons, the combs, the pieces, the curve, the joints
    /// and the control points.
    fn draw(&self, svg: &mut String, view: &View, cubic: bool) {
        let px = |p: &Point| view.px(*p);
        let pixels = |points: &[Point]| points.iter().map(px).collect::<Vec<_>>();
        let teeth = |comb: &Comb| -> Vec<(Point, Point)> {
            comb.teeth.iter().map(|(a, b)| (px(a), px(b))).collect()
        };
        let polygon = pixels(&self.points);
        polyline(svg, &polygon, POLYGON, 1.0, " stroke-dasharray=\"6 4\"");
        for b in &self.beziers {
            let control = pixels(&b.points());
            polyline(svg, &control, BEZIER_POLYGON, 0.8, "");
            for p in &control[1..3] {
                square(svg, *p, BEZIER_POLYGON);
            }
        }
        let faint = " stroke-opacity=\"0.55\"";
        segments(svg, &teeth(&self.lac_teeth), COMB, 0.6, faint);
        segments(svg, &teeth(&self.bezier_teeth), BEZIER_COMB, 0.6, faint);
        polyline(svg, &pixels(&self.lac_comb.envelope()), COMB, 1.25, "");
        let dashed = " stroke-dasharray=\"5 3\"";
        let envelope = pixels(&self.bezier_comb.envelope());
        polyline(svg, &envelope, BEZIER_COMB, 1.25, dashed);
        // Plain cubics exactly, as kurbo writes them (a similarity maps control points to
        // control points); rational pieces through dense points.
        let cubics: Option<Vec<PathSeg>> = match &self.path {
            Some(path) if cubic => Some((view.affine() * path.clone()).segments().collect()),
            _ => None,
        };
        for (i, points) in dense_points(&self.beziers).iter().enumerate() {
            match cubics.as_ref().and_then(|c| c.get(i)) {
                Some(&PathSeg::Cubic(c)) => piece_path(svg, &cubic_data(c)),
                _ => piece_path(svg, &polyline_data(&pixels(points))),
            }
        }
        polyline(svg, &pixels(&self.curve), LAC, 1.0, "");
        for b in &self.beziers[..self.beziers.len() - 1] {
            dot(svg, view.px(b.points()[3]), JOINT);
        }
        control_points(svg, &polygon, &mut Labels::new(LABEL_SIZE), view.room());
    }
}

/// Samples of the chain `beziers`, about `total` intervals in all shared out by arc length
/// (at least two a piece), equally spaced in t on each piece; `s` is the arc length along
/// the chain. Consecutive pieces share their end sample, which appears once.
fn bezier_samples(beziers: &[RationalCubic], total: usize) -> Vec<Sample> {
    let lengths: Vec<f64> = beziers.iter().map(RationalCubic::arc_length).collect();
    let sum: f64 = lengths.iter().sum();
    let mut out: Vec<Sample> = Vec::new();
    let mut s0 = 0.0;
    for (k, (b, &length)) in beziers.iter().zip(&lengths).enumerate() {
        let intervals = ((total as f64 * length / sum).round() as usize).max(2);
        let mut prev = 0.0;
        let mut s = s0;
        for i in 0..=intervals {
            let t = i as f64 / intervals as f64;
            s += b.arc_length_between(prev, t);
            prev = t;
            if k > 0 && i == 0 {
                continue;
            }
            let d = b.derivative(t);
            out.push(Sample {
                s,
                point: b.eval(t),
                theta: d.y.atan2(d.x),
                kappa: b.signed_curvature(t),
            });
        }
        s0 += length;
    }
    out
}

/// Samples of the chain `beziers` at the arc lengths `at` (ascending, from its start).
fn bezier_at_arc_lengths(beziers: &[RationalCubic], at: &[f64]) -> Vec<Sample> {
    let mut out = Vec::with_capacity(at.len());
    let mut start = 0.0;
    let mut pieces = beziers.iter().peekable();
    for &s in at {
        let Some(mut b) = pieces.peek().copied() else {
            break;
        };
        let mut length = b.arc_length();
        while s > start + length && pieces.len() > 1 {
            pieces.next();
            start += length;
            b = pieces
                .peek()
                .copied()
                .expect("more than one piece was left");
            length = b.arc_length();
        }
        // Far below the drawing's hundredth of a pixel, at any size.
        let t = b.inv_arclen((s - start).clamp(0.0, length), 1e-9 * length);
        let d = b.derivative(t);
        out.push(Sample {
            s,
            point: b.eval(t),
            theta: d.y.atan2(d.x),
            kappa: b.signed_curvature(t),
        });
    }
    out
}

/// The points on each rational piece that its polyline is drawn through.
fn dense_points(beziers: &[RationalCubic]) -> Vec<Vec<Point>> {
    let intervals = (BEZIER_POINTS / beziers.len()).clamp(16, 128);
    beziers
        .iter()
        .map(|b| {
            (0..=intervals)
                .map(|i| b.eval(i as f64 / intervals as f64))
                .collect()
        })
        .collect()
}

/// Every eighth sample: the comb teeth among [`LAC_SAMPLES`].
fn every_eighth(samples: &[Sample]) -> Vec<Sample> {
    samples.iter().step_by(8).copied().collect()
}

/// One Bézier piece as a `<path>` with path data `d`.
fn piece_path(svg: &mut String, d: &str) {
    let _ = writeln!(
        svg,
        r#"<path class="piece" stroke="{BEZIER}" stroke-opacity="0.5" stroke-width="4" d="{d}"/>"#
    );
}

/// The path data of a plain cubic piece (pixels), to a hundredth of a pixel, from kurbo.
fn cubic_data(c: CubicBez) -> String {
    let r = |p: Point| Point::new((p.x * 100.0).round() / 100.0, (p.y * 100.0).round() / 100.0);
    let c = CubicBez::new(r(c.p0), r(c.p1), r(c.p2), r(c.p3));
    BezPath::from_path_segments(std::iter::once(PathSeg::Cubic(c))).to_svg()
}

/// The path data of a polyline through `points` (pixels).
fn polyline_data(points: &[Point]) -> String {
    let mut d = String::new();
    for (i, p) in points.iter().enumerate() {
        let command = if i == 0 { 'M' } else { 'L' };
        let _ = write!(d, "{command}{:.2},{:.2}", p.x, p.y);
    }
    d
}

/// A small hollow square: an inner control point of a Bézier piece.
fn square(svg: &mut String, p: Point, colour: &str) {
    let _ = writeln!(
        svg,
        r#"<rect x="{:.2}" y="{:.2}" width="5" height="5" fill="white" stroke="{colour}" stroke-width="1"/>"#,
        p.x - 2.5,
        p.y - 2.5
    );
}

fn open(svg: &mut String, view: &View, pieces: &[Segment], count: usize, cubic: bool) {
    let what = if pieces.len() == 1 {
        "log-aesthetic segment"
    } else {
        "compound-rhythm log-aesthetic curve"
    };
    let title = format!(
        "Quasi-aesthetic curve: {} for a {what}, {}",
        count_of(count, cubic),
        super::slopes(pieces).join(", ")
    );
    super::document(svg, view.width, view.height, &title);
}

/// "1 rational cubic", "3 plain cubics", …
fn count_of(count: usize, cubic: bool) -> String {
    let kind = if cubic {
        "plain cubic"
    } else {
        "rational cubic"
    };
    let plural = if count == 1 { "" } else { "s" };
    format!("{count} {kind}{plural}")
}

/// The caption: the numbers of the fit, "α = …", "3 rational cubics", "deviation rms = …,
/// max = … of the arc length …", "curvature increasing, proven", and on a line of its own
/// the colour key.
fn caption(pieces: &[Segment], quasi: &QuasiCurve, cubic: bool) -> Block {
    let length: f64 = pieces.iter().map(Curve::arc_length).sum();
    let mut facts: Vec<Entry> = super::slopes(pieces)
        .into_iter()
        .map(|text| Entry::plain(CURVE, text))
        .collect();
    facts.push(Entry::plain(CURVE, count_of(quasi.pieces.len(), cubic)));
    facts.push(Entry::plain(
        CURVE,
        format!(
            "deviation rms = {:.2e}, max = {:.2e} of the arc length {}",
            quasi.rms,
            quasi.max,
            short(length)
        ),
    ));
    let verdicts: Vec<_> = quasi.pieces.iter().map(|p| p.monotonicity).collect();
    let bad = verdicts.iter().filter(|m| !m.verdict.is_monotone()).count();
    let first = verdicts[0].verdict.name();
    facts.push(if bad > 0 {
        let n = verdicts.len();
        let of = if n == 1 {
            String::new()
        } else {
            format!(" on {bad} of {n} pieces")
        };
        Entry::plain(COMB, format!("curvature not monotone{of}"))
    } else if verdicts.iter().all(|m| m.verdict.name() == first) {
        let proven = if verdicts.iter().all(|m| m.proven) {
            ", proven"
        } else {
            ""
        };
        Entry::plain(CURVE, format!("curvature {first}{proven}"))
    } else {
        Entry::plain(CURVE, "curvature monotone on each piece")
    });
    let mut key = vec![
        Entry::keyed(Key::line(LAC, 1.0), "log-aesthetic curve"),
        Entry::keyed(
            Key::Line {
                colour: BEZIER,
                width: 4.0,
                opacity: 0.5,
                dash: None,
            },
            "Bézier pieces",
        ),
        Entry::keyed(Key::line(BEZIER_POLYGON, 0.8), "their control polygons"),
        Entry::keyed(Key::line(COMB, 1.25), "curvature comb"),
        Entry::keyed(
            Key::Line {
                colour: BEZIER_COMB,
                width: 1.25,
                opacity: 1.0,
                dash: Some("5 3"),
            },
            "comb of the pieces",
        ),
    ];
    if quasi.pieces.len() > 1 {
        key.push(Entry::keyed(Key::Dot(JOINT), "joints"));
    }
    Block::new(CAPTION_SIZE).list(facts).list(key)
}

#[cfg(test)]
mod tests {
    use kurbo::Vec2;

    use super::*;

    /// The quarter of the unit circle from angle `a` to `a + π/2` as a rational cubic.
    fn quarter(a: f64) -> RationalCubic {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let (k, w) = (2.0 * c / (1.0 + 2.0 * c), (2.0 * c + 1.0) / 3.0);
        let at = |x: f64, y: f64| Point::new(x * a.cos() - y * a.sin(), x * a.sin() + y * a.cos());
        RationalCubic::new(
            [at(1.0, 0.0), at(1.0, k), at(k, 1.0), at(0.0, 1.0)],
            [1.0, w, w, 1.0],
        )
        .unwrap()
    }

    #[test]
    fn teeth_at_arc_lengths_land_at_those_arc_lengths_along_a_chain() {
        let chain = [quarter(0.0), quarter(std::f64::consts::FRAC_PI_2)];
        let at = [0.0, 0.3, 1.5, 2.0, 3.0, std::f64::consts::PI];
        let samples = bezier_at_arc_lengths(&chain, &at);
        assert_eq!(samples.len(), at.len());
        for (s, sample) in at.iter().zip(&samples) {
            // On the unit circle, arc length is the angle.
            let want = Point::new(s.cos(), s.sin());
            assert!(
                (sample.point - want).hypot() < 1e-9,
                "{s}: {:?}",
                sample.point
            );
            assert!((sample.kappa - 1.0).abs() < 1e-12);
            let tangent = Vec2::from_angle(sample.theta);
            assert!((tangent - Vec2::new(-s.sin(), s.cos())).hypot() < 1e-9);
        }
    }
}
