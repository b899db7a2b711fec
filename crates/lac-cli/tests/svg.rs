//! `lac segment --format svg`: a standalone drawing independent of the input's scale.

mod common;

use common::lac;

/// The (cx, cy) of the control-point markers.
fn markers(svg: &str) -> Vec<(f64, f64)> {
    svg.split("<circle ")
        .skip(1)
        .map(|c| {
            let attr = |name: &str| -> f64 {
                let start = c.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
                let end = start + c[start..].find('"').unwrap();
                c[start..end].parse().unwrap()
            };
            (attr("cx"), attr("cy"))
        })
        .collect()
}

fn svg(points: &str, alpha: &str, extra: &[&str]) -> String {
    let mut args = vec![
        "segment", "--points", points, "--alpha", alpha, "--format", "svg",
    ];
    args.extend_from_slice(extra);
    let run = lac(&args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    run.stdout
}

#[test]
fn the_svg_is_a_standalone_document_with_the_curve_polygon_comb_and_evolute() {
    for alpha in ["-1", "0.5", "2"] {
        let doc = svg("0,0 2,0 2.4,1", alpha, &["--comb", "--evolute"]);
        assert!(doc.starts_with("<?xml") || doc.starts_with("<svg"));
        assert!(doc.contains("xmlns=\"http://www.w3.org/2000/svg\""));
        assert!(doc.contains("<polyline") || doc.contains("<path"));
        assert!(doc.contains("stroke-dasharray"), "dashed control polygon");
        assert!(doc.contains("curvature comb") && doc.contains("evolute"));
        assert!(doc.contains(&format!("α = {alpha}")), "caption");
        assert!(doc.trim_end().ends_with("</svg>"));
        assert!(
            !doc.contains("NaN") && !doc.contains("inf"),
            "finite coordinates"
        );
    }
}

#[test]
fn the_drawing_is_the_same_for_tiny_huge_and_offset_coordinates() {
    let reference = markers(&svg("0,0 2,0 2.4,1", "0.5", &["--comb"]));
    assert_eq!(reference.len(), 3);
    // y up: P2 (y = 1) is drawn above P0 (y = 0).
    assert!(reference[2].1 < reference[0].1);
    for (scale, offset) in [
        (1e-6, 0.0),
        (1e6, 0.0),
        (1e-6, 1e7),
        (1e6, -1e7),
        (1.0, 1e7),
    ] {
        let p = |x: f64, y: f64| format!("{:?},{:?}", offset + scale * x, offset + scale * y);
        let points = format!("{} {} {}", p(0.0, 0.0), p(2.0, 0.0), p(2.4, 1.0));
        let drawn = markers(&svg(&points, "0.5", &["--comb"]));
        for (a, b) in reference.iter().zip(&drawn) {
            let moved = (a.0 - b.0).hypot(a.1 - b.1);
            assert!(moved < 0.5, "scale {scale} offset {offset}: {a:?} vs {b:?}");
        }
    }
}

#[test]
fn a_circular_arc_marks_its_centre_as_the_evolute() {
    let doc = svg("-1,0 0,1 1,0", "-1", &["--evolute"]);
    assert!(doc.contains("Λ = 0"));
    assert!(doc.contains("h10"), "cross at the centre");
}

#[test]
fn a_long_caption_widens_a_narrow_drawing() {
    let run = lac(&[
        "compound",
        "--points",
        "0,0 0.4,3 0,4",
        "--alpha0",
        "0.123456789",
        "--alpha1",
        "0.75",
        "--ratio",
        "0.3",
        "--format",
        "svg",
        "--comb",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let doc = &run.stdout;
    let start = doc.find("<svg ").unwrap();
    let width: f64 = doc[start..]
        .split("width=\"")
        .nth(1)
        .and_then(|w| w.split('"').next())
        .unwrap()
        .parse()
        .unwrap();
    // The caption "α0 = 0.123456789  α1 = 0.75  Λ = …  ● joint s = …  arc length = …
    // ▬ curvature comb" is about 640 px wide in Liberation Sans at 13 px; the drawing itself
    // would need only 560.
    assert!(width >= 680.0, "canvas width {width}");
}
