//! Splines with point types (tangent points, corners, straight spans, end curvatures):
//! every condition measured on the pieces as built, through the `Curve` trait (not on the
//! solver's report): through every point, G2 at smooth and tangent points, the given
//! tangents, zero curvature where a curve meets a straight span, the end curvatures as
//! given; refusals name the point; and the share of random glyph-like outlines that solve.

use std::f64::consts::{FRAC_PI_2, TAU};

use kurbo::Point;
use lac::{Closure, Curve, Error, PointType, Spline, SplineEnd, SplineOptions};

#[path = "../../benches/common/mod.rs"]
#[allow(dead_code)]
mod bench_common;

/// The largest misses of one spline's conditions, measured on its pieces.
#[derive(Debug, Default, Clone, Copy)]
struct Misses {
    /// Distance from a point to the pieces' ends there, relative to the points' extent.
    through: f64,
    /// Relative curvature jump at a smooth or tangent point.
    g2: f64,
    /// A given tangent's miss (radians), and the tangent break at a smooth point.
    tangent: f64,
    /// |κ| where a curve meets a straight span, relative to the largest |κ| sampled.
    flat: f64,
    /// Relative miss of a given end curvature.
    end: f64,
}

impl Misses {
    fn max(self, o: Misses) -> Misses {
        Misses {
            through: self.through.max(o.through),
            g2: self.g2.max(o.g2),
            tangent: self.tangent.max(o.tangent),
            flat: self.flat.max(o.flat),
            end: self.end.max(o.end),
        }
    }
}

fn wrap(a: f64) -> f64 {
    a - TAU * (a / TAU).round()
}

/// What the pieces show on each side of point `i`: (point, θ, κ), a straight span's side its
/// direction and zero curvature, `None` outside an open spline.
fn sides(s: &Spline, i: usize) -> [Option<(Point, f64, f64)>; 2] {
    let pts = s.points();
    let n = pts.len();
    let spans = s.spans_of_pieces();
    let pieces = s.pieces();
    let lines = &s.options().lines;
    let before = if i > 0 {
        Some(i - 1)
    } else {
        s.is_closed().then_some(n - 1)
    };
    let after = (i + 1 < n || s.is_closed()).then_some(i);
    let side = |span: Option<usize>, at_end: bool| {
        let span = span?;
        if lines.contains(&span) {
            let d = pts[(span + 1) % n] - pts[span];
            return Some((pts[i], d.atan2(), 0.0));
        }
        let k = if at_end {
            spans.iter().rposition(|&x| x == span)?
        } else {
            spans.iter().position(|&x| x == span)?
        };
        let seg = &pieces[k];
        let at = if at_end { seg.arc_length() } else { 0.0 };
        Some((
            seg.point_at_s(at).unwrap(),
            seg.theta_at_s(at).unwrap(),
            seg.signed_curvature_at_s(at).unwrap(),
        ))
    };
    [side(before, true), side(after, false)]
}

/// Every condition of `s`, measured.
fn misses(s: &Spline) -> Misses {
    let pts = s.points();
    let n = pts.len();
    let o = s.options();
    let size = pts
        .iter()
        .map(|p| (*p - pts[0]).hypot())
        .fold(0.0, f64::max);
    let biggest = s
        .sample_by_arc_length(2000)
        .unwrap()
        .iter()
        .map(|x| x.kappa.abs())
        .fold(s.max_abs_curvature(), f64::max);
    let mut m = Misses::default();
    for (i, &at) in pts.iter().enumerate() {
        let kind = o.types.get(i).copied().unwrap_or_default();
        let [b, a] = sides(s, i);
        for (p, _, _) in [b, a].iter().flatten() {
            m.through = m.through.max((*p - at).hypot() / size);
        }
        let straight = [
            b.is_some() && o.lines.contains(&((i + n - 1) % n)),
            a.is_some() && o.lines.contains(&i),
        ];
        if let (Some(b), Some(a)) = (b, a) {
            if !matches!(kind, PointType::Corner { .. }) {
                m.tangent = m.tangent.max(wrap(b.1 - a.1).abs());
                if straight == [false, false] {
                    m.g2 = m.g2.max((b.2 - a.2).abs() / b.2.abs().max(a.2.abs()));
                } else if straight == [true, false] {
                    m.flat = m.flat.max(a.2.abs() / biggest);
                } else if straight == [false, true] {
                    m.flat = m.flat.max(b.2.abs() / biggest);
                }
            }
        }
        let given = match kind {
            PointType::Tangent(t) => [Some(t), Some(t)],
            PointType::Corner { before, after } => [before, after],
            PointType::Smooth => [None, None],
        };
        for (side, g) in [b, a].iter().zip(given) {
            if let (Some(side), Some(g)) = (side, g) {
                m.tangent = m.tangent.max(wrap(side.1 - g).abs());
            }
        }
    }
    if !s.is_closed() {
        for (end, side) in [(&o.start, sides(s, 0)[1]), (&o.end, sides(s, n - 1)[0])] {
            let side = side.unwrap();
            if let Some(k) = end.curvature {
                m.end = m.end.max(if k == 0.0 {
                    side.2.abs() / biggest
                } else {
                    (side.2 - k).abs() / k.abs()
                });
            }
            if let Some(t) = end.angle {
                m.tangent = m.tangent.max(wrap(side.1 - t).abs());
            }
        }
    }
    m
}

/// The targets: through every point to 1e-12 of the size, G2 to 1e-9, tangents to 1e-12
/// rad, zero curvature at straight spans to 1e-12 of the largest |κ|, end curvatures to
/// 1e-12 (relative).
fn assert_targets(m: Misses, what: &str) {
    assert!(
        m.through <= 1e-12
            && m.g2 <= 1e-9
            && m.tangent <= 1e-12
            && m.flat <= 1e-12
            && m.end <= 1e-12,
        "{what}: {m:?}"
    );
}

fn points(v: &[(f64, f64)]) -> Vec<Point> {
    v.iter().map(|&(x, y)| Point::new(x, y)).collect()
}

fn types(n: usize, special: &[(usize, PointType)]) -> Vec<PointType> {
    let mut t = vec![PointType::Smooth; n];
    for &(i, k) in special {
        t[i] = k;
    }
    t
}

/// A tangent point keeps the curvature continuous with its direction given, for every
/// kind of α; a corner lets the tangent break; both measured on the pieces.
#[test]
fn tangent_points_and_corners_for_every_alpha() {
    let arc = points(&[(0.0, 0.0), (1.0, 0.6), (2.0, 0.8), (3.0, 0.55), (4.0, 0.0)]);
    for alpha in [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5] {
        let o = SplineOptions {
            types: types(5, &[(2, PointType::Tangent(0.05))]),
            ..SplineOptions::default()
        };
        let s = Spline::from_points_with(&arc, alpha, Closure::Open, &o)
            .unwrap_or_else(|e| panic!("tangent α {alpha}: {e}"));
        assert_targets(misses(&s), &format!("tangent α {alpha}"));
        assert_eq!(s.knots().len(), 1);
        let corner = SplineOptions {
            types: types(
                5,
                &[(
                    2,
                    PointType::Corner {
                        before: Some(-0.2),
                        after: None,
                    },
                )],
            ),
            ..SplineOptions::default()
        };
        let s = Spline::from_points_with(&arc, alpha, Closure::Open, &corner)
            .unwrap_or_else(|e| panic!("corner α {alpha}: {e}"));
        assert_targets(misses(&s), &format!("corner α {alpha}"));
        let r = s.point_reports()[2];
        assert!((r.angles[0].unwrap() + 0.2).abs() < 1e-12);
        assert!(
            (r.angles[1].unwrap() - r.angles[0].unwrap()).abs() > 0.01,
            "{r:?}"
        );
    }
}

/// G2 Hermite ends: an end's angle and curvature both given (blending into a neighbouring
/// curve), or its curvature only; closed splines refuse ends.
#[test]
fn end_curvatures_as_given() {
    let arc = points(&[(0.0, 0.0), (1.0, 0.6), (2.0, 0.8), (3.0, 0.6), (4.0, 0.0)]);
    for alpha in [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0] {
        let o = SplineOptions {
            start: SplineEnd {
                angle: Some(0.7),
                curvature: Some(-0.3),
            },
            end: SplineEnd {
                angle: None,
                curvature: Some(-0.2),
            },
            ..SplineOptions::default()
        };
        let s = Spline::from_points_with(&arc, alpha, Closure::Open, &o)
            .unwrap_or_else(|e| panic!("α {alpha}: {e}"));
        let m = misses(&s);
        assert_targets(m, &format!("ends α {alpha}"));
        assert!(s.point_reports()[0].curvatures[1].is_some());
    }
    let closed = SplineOptions {
        end: SplineEnd {
            angle: None,
            curvature: Some(1.0),
        },
        ..SplineOptions::default()
    };
    let e = Spline::from_points_with(&arc, -1.0, Closure::Closed, &closed).unwrap_err();
    assert!(matches!(e, Error::SplinePoint { point: 0, .. }), "{e}");
}

/// A U: straight sides flowing into a round bottom that is horizontal at its lowest point;
/// the curve meets each side with zero curvature (α < 0), and α ≥ 0 is refused at the
/// first point that needs it, with what to change.
#[test]
fn straight_spans_meet_the_curve_with_zero_curvature() {
    let u = points(&[(0.0, 4.0), (0.0, 1.5), (1.0, 0.0), (2.0, 1.5), (2.0, 4.0)]);
    let o = SplineOptions {
        types: types(5, &[(2, PointType::Tangent(0.0))]),
        lines: vec![0, 3],
        ..SplineOptions::default()
    };
    for alpha in [-1.0, -0.75, -0.5, -0.25] {
        let s = Spline::from_points_with(&u, alpha, Closure::Open, &o)
            .unwrap_or_else(|e| panic!("α {alpha}: {e}"));
        assert_targets(misses(&s), &format!("U α {alpha}"));
        assert_eq!(s.straight_spans().len(), 2);
        // The samples run along the sides with κ = 0.
        let samples = s.sample_by_arc_length(200).unwrap();
        assert!(samples.iter().filter(|x| x.kappa == 0.0).count() > 50);
        assert!((s.start_point() - u[0]).hypot() < 1e-15 && (s.end_point() - u[4]).hypot() < 1e-15);
    }
    for alpha in [0.0, 0.5, 2.0] {
        let e = Spline::from_points_with(&u, alpha, Closure::Open, &o).unwrap_err();
        assert!(matches!(e, Error::SplinePoint { point: 1, .. }), "{e}");
        assert!(
            e.to_string()
                .contains("use alpha < 0, or make this point a corner"),
            "{e}"
        );
    }
    // A tangent point on a straight span, and two spans not in line at a smooth point.
    let mut bad = o.clone();
    bad.types[1] = PointType::Tangent(-FRAC_PI_2);
    let e = Spline::from_points_with(&u, -1.0, Closure::Open, &bad).unwrap_err();
    assert!(matches!(e, Error::SplinePoint { point: 1, .. }), "{e}");
    let mut bad = o.clone();
    bad.lines = vec![0, 1];
    bad.types[2] = PointType::Smooth;
    let e = Spline::from_points_with(&u, -1.0, Closure::Open, &bad).unwrap_err();
    assert!(matches!(e, Error::SplinePoint { point: 1, .. }), "{e}");
}

/// The default options are the smooth spline, bit for bit.
#[test]
fn default_options_are_the_smooth_spline() {
    let arc = points(&[(0.0, 0.0), (1.0, 0.6), (2.0, 0.8), (3.0, 0.55), (4.0, 0.0)]);
    let a = Spline::from_points(&arc, 0.5, Closure::Open, Some([0.6, -0.7])).unwrap();
    let b = Spline::from_points_with(
        &arc,
        0.5,
        Closure::Open,
        &SplineOptions::with_ends(Some([0.6, -0.7])),
    )
    .unwrap();
    assert_eq!(a.angles(), b.angles());
    assert_eq!(a.control_triangles(), b.control_triangles());
}

/// A warm re-solve after moving one point agrees with the cold solve, at both slopes; so
/// does one that moves it back (warm from the warm answer, whose spans away from the point
/// are taken as they were), and one from an answer at another slope (nothing taken).
#[test]
fn warm_re_solve_agrees_with_cold() {
    let mut rng = bench_common::Rng(0x6C79);
    for alpha in [-1.0, -0.5] {
        let mut checked = 0;
        while checked < 20 {
            let g = bench_common::glyphs::glyph(&mut rng);
            let o = &g.options;
            let Ok(first) = Spline::from_points_with(&g.points, alpha, Closure::Closed, o) else {
                continue;
            };
            let mut moved = g.points.clone();
            let k = (rng.next() * moved.len() as f64) as usize;
            moved[k] += kurbo::Vec2::new(0.01 * (rng.next() - 0.5), 0.01 * (rng.next() - 0.5));
            let (Ok(cold), Ok(warm)) = (
                Spline::from_points_with(&moved, alpha, Closure::Closed, o),
                Spline::from_points_near(&moved, alpha, Closure::Closed, o, &first),
            ) else {
                continue;
            };
            let agree = |a: &Spline, b: &Spline, what: &str| {
                for (x, y) in a.angles().iter().zip(b.angles()) {
                    assert!(wrap(x - y).abs() < 1e-9, "{what} α {alpha}: {x} {y}");
                }
                assert_targets(misses(b), what);
            };
            agree(&cold, &warm, "warm");
            let back = Spline::from_points_near(&g.points, alpha, Closure::Closed, o, &warm);
            agree(&first, &back.unwrap(), "moved back");
            let other = -1.5 - alpha;
            if let (Ok(cold), Ok(warm)) = (
                Spline::from_points_with(&moved, other, Closure::Closed, o),
                Spline::from_points_near(&moved, other, Closure::Closed, o, &first),
            ) {
                agree(&cold, &warm, "another slope");
            }
            checked += 1;
        }
    }
}

/// Seeded random glyph-like outlines (closed, 8–20 points, about a quarter of them corners
/// or straight spans' ends, extrema horizontal) at α = −1 and −0.5: each solved one verified
/// against every target, each refusal naming its point; the share printed with
/// `--nocapture`. `LAC_GLYPHS=N` draws N outlines per α (default 250; docs/accuracy.md
/// quotes 1,000, of which 996 and 997 solve). The target is 97%.
#[test]
fn share_of_random_glyph_outlines() {
    let total: usize = std::env::var("LAC_GLYPHS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(250);
    for (alpha, floor) in [(-1.0, 0.97), (-0.5, 0.97)] {
        let mut rng = bench_common::Rng(0x6C79_5048);
        let (mut solved, mut worst) = (0, Misses::default());
        let mut reasons = std::collections::BTreeMap::new();
        for _ in 0..total {
            let g = bench_common::glyphs::glyph(&mut rng);
            match Spline::from_points_with(&g.points, alpha, Closure::Closed, &g.options) {
                Ok(s) => {
                    solved += 1;
                    let m = misses(&s);
                    assert_targets(m, &format!("α {alpha} {:?} {:?}", g.points, g.options));
                    worst = worst.max(m);
                }
                Err(e) => {
                    let text = e.to_string();
                    assert!(text.contains(" P"), "a refusal names its point: {text}");
                    let name = match e {
                        Error::SplinePoint { reason, .. } => format!("{reason:?}"),
                        Error::NoG2Spline { reason, .. } => format!("{reason:?}"),
                        other => format!("{other:?}"),
                    };
                    let name: String = name.split([' ', '{', '(']).take(1).collect();
                    *reasons.entry(name).or_insert(0) += 1;
                }
            }
        }
        println!(
            "glyph outlines α = {alpha}: solved {solved}/{total}; worst {worst:?}; refused \
             {reasons:?}"
        );
        assert!(solved as f64 >= floor * total as f64, "{solved}/{total}");
    }
}
