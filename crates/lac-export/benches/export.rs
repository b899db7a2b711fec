//! Pieces needed and export time against the tolerance (1e-3 … 1e-9 model units) for a
//! spread of α, with kurbo's `fit_to_bezpath` (plain cubics, fitted through kurbo's
//! `ParamCurveFit`) on the same curves as the baseline.
//!
//! The curves: turning 90°, legs 1 and 0.8 (control points (−1, 0), (0, 0), (0, 0.8); arc
//! length about 1.5). Before timing, a table goes to standard error: per α and tolerance,
//! the pieces of lac's rational chain, of lac's plain cubic chain and of kurbo's fit, and
//! the deviation of each measured the same way (`certify::deviation`, two-sided, 64 samples
//! per piece). Timed: `export` to STEP (fit, dense measurement, writing) and kurbo's fit.
//!
//!     cargo bench -p lac-export --bench export -- --warm-up-time 1 --measurement-time 3

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::{
    BezPath, CurveFitSample, ParamCurve, ParamCurveArclen, ParamCurveDeriv, ParamCurveFit, PathSeg,
    Point,
};
use lac::{Segment, Tolerance};
use lac_export::certify::{deviation, PlaneExact};
use lac_export::nurbs::{Nurbs, Span};
use lac_export::{export, ExportCurve, Format, Meta};

const ALPHAS: [f64; 5] = [-1.0, 0.0, 0.5, 1.0, 2.0];
const TOLERANCES: [f64; 7] = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9];

/// A segment seen through kurbo's curve-fitting trait: t ∈ [0, 1] proportional to arc
/// length (the segment's own `ParamCurve`), no cusps.
struct Fit<'a>(&'a Segment);

impl ParamCurveFit for Fit<'_> {
    fn sample_pt_tangent(&self, t: f64, _sign: f64) -> CurveFitSample {
        let (p, tangent) = self.sample_pt_deriv(t);
        CurveFitSample { p, tangent }
    }

    fn sample_pt_deriv(&self, t: f64) -> (Point, kurbo::Vec2) {
        (self.0.eval(t), self.0.deriv().eval(t).to_vec2())
    }

    fn break_cusp(&self, _range: std::ops::Range<f64>) -> Option<f64> {
        None
    }
}

fn segment(alpha: f64) -> Segment {
    let p = [Point::new(-1.0, 0.0), Point::ZERO, Point::new(0.0, 0.8)];
    Segment::from_control_points(p, alpha).expect("drawable for every α benchmarked")
}

fn meta() -> Meta {
    Meta {
        name: "bench".into(),
        timestamp: "2026-11-23T00:00:00".into(),
        version: "0".into(),
    }
}

/// kurbo's cubics as a B-spline, for the same deviation measure.
fn kurbo_nurbs(path: &BezPath) -> Nurbs {
    let mut spans = Vec::new();
    let mut breaks = vec![0.0];
    for seg in path.segments() {
        let PathSeg::Cubic(c) = seg else {
            panic!("kurbo fits cubics")
        };
        spans.push(Span {
            points: [c.p0, c.p1, c.p2, c.p3].map(|p| [p.x, p.y, 0.0]),
            weights: [1.0; 4],
        });
        breaks.push(breaks[breaks.len() - 1] + c.arclen(1e-12));
    }
    Nurbs::from_spans(&spans, &breaks, true, 0.0).expect("kurbo's path is a chain")
}

fn table() {
    eprintln!(
        "| α | tolerance | lac rational: pieces, deviation | lac cubic | kurbo fit_to_bezpath |"
    );
    eprintln!("|---|---|---|---|---|");
    for alpha in ALPHAS {
        let seg = segment(alpha);
        for tol in TOLERANCES {
            let curve = ExportCurve::whole("segment", &seg);
            let cell =
                |format| match export(&curve, format, Tolerance::Absolute(tol), false, &meta()) {
                    Ok(e) => format!("{} ({:.1e})", e.report.pieces, e.report.max_deviation),
                    Err(e) => format!("refused: {}", e.kind()),
                };
            let path = kurbo::fit_to_bezpath(&Fit(&seg), tol);
            let nurbs = kurbo_nurbs(&path);
            let d = deviation(&PlaneExact(&seg), &nurbs, 64).expect("measurable");
            eprintln!(
                "| {alpha} | {tol:.0e} | {} | {} | {} ({d:.1e}) |",
                cell(Format::Json),
                cell(Format::Svg),
                nurbs.span_count()
            );
        }
    }
}

fn bench_export(c: &mut Criterion) {
    table();
    let mut group = c.benchmark_group("export");
    for alpha in [-1.0, 0.5, 2.0] {
        let seg = segment(alpha);
        for tol in [1e-3, 1e-6, 1e-9] {
            let id = format!("alpha={alpha}/tol={tol:.0e}");
            group.bench_with_input(BenchmarkId::new("lac_step", &id), &tol, |b, &tol| {
                b.iter(|| {
                    export(
                        &ExportCurve::whole("segment", black_box(&seg)),
                        Format::Step,
                        Tolerance::Absolute(tol),
                        false,
                        &meta(),
                    )
                    .unwrap()
                })
            });
            group.bench_with_input(BenchmarkId::new("kurbo_fit", &id), &tol, |b, &tol| {
                b.iter(|| kurbo::fit_to_bezpath(&Fit(black_box(&seg)), tol))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench_export);
criterion_main!(benches);
