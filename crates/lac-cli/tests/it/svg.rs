//! `lac segment --format svg`: a standalone drawing independent of the input's scale.

use crate::common;

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
fn a_long_caption_wraps_under_a_narrow_drawing_one_entry_to_a_text() {
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
    // An attribute of the element whose attributes `element` starts with.
    let attr = |element: &str, name: &str| -> f64 {
        let element = format!(" {element}");
        let start = element.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        let end = start + element[start..].find('"').unwrap();
        element[start..end].parse().unwrap()
    };
    let svg = &doc[doc.find("<svg ").unwrap()..];
    // The drawing itself needs no more than the smallest canvas: the caption does not widen
    // it (it would be about 700 px on one line).
    assert_eq!(attr(svg, "width"), 560.0);
    let caption: Vec<(f64, f64, &str)> = doc
        .split("<text ")
        .skip(1)
        .filter(|t| t.contains("font-size=\"13\""))
        .map(|t| {
            let text = &t[t.find('>').unwrap() + 1..t.find("</text>").unwrap()];
            (attr(t, "x"), attr(t, "y"), text)
        })
        .collect();
    let texts: Vec<&str> = caption.iter().map(|c| c.2).collect();
    for entry in [
        "α0 = 0.123456789",
        "α1 = 0.75",
        "arc length = 4.03245",
        "curvature comb",
    ] {
        assert!(
            texts.contains(&entry),
            "{entry:?} is a text of its own: {texts:?}"
        );
    }
    let mut lines: Vec<f64> = caption.iter().map(|c| c.1).collect();
    lines.dedup();
    assert!(
        lines.len() >= 3,
        "facts on two lines, the key on a third: {caption:?}"
    );
    assert!(caption.iter().all(|c| c.0 >= 12.0));
}

/// The caption names what each place between pieces is: a joint, an inflection (a spline's
/// S, whose halves meet at zero curvature) or a straight piece (also the one on the leg that
/// closes a polygon, which ends the path where it starts).
#[test]
fn the_caption_tells_joints_inflections_and_straight_pieces_apart() {
    let wave = "0,0.2955 1,0.9320 2,0.8632 3,0.1411 4,-0.6878 5,-0.9962 6,-0.5507 7,0.3115";
    let run = lac(&[
        "spline",
        "--through",
        wave,
        "--alpha",
        "-0.5",
        "--format",
        "svg",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout.matches("inflection s = ").count(), 1);
    assert_eq!(run.stdout.matches("joint s = ").count(), 6);
    let eight = "1.5,-1 3,-1.8 4.5,-1 4.5,1 3,1.8 1.5,1 -1.5,-1 -3,-1.8 -4.5,-1 -4.5,1 \
                 -3,1.8 -1.5,1";
    let run = lac(&[
        "path",
        "--polygon",
        eight,
        "--closed",
        "--g2",
        "--alpha",
        "-0.5",
        "--format",
        "svg",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let straight: Vec<&str> = run
        .stdout
        .match_indices("straight s = ")
        .map(|(i, _)| &run.stdout[i..i + 40])
        .collect();
    assert_eq!(straight.len(), 2, "{straight:?}");
    // The second ends at the arc length.
    assert!(straight[1].contains("to 23.426"), "{straight:?}");
    assert_eq!(run.stdout.matches("inflection s = ").count(), 0);
}

#[test]
fn the_title_names_the_kind_of_curve() {
    let cases: [(&[&str], &str); 5] = [
        (
            &["segment", "--points", "0,0 2,0 2.4,1", "--alpha", "0.5"],
            "<title>Log-aesthetic segment, α = 0.5, Λ = ",
        ),
        (
            &[
                "compound",
                "--points",
                "0,0 2,0 2.4,1",
                "--alpha0",
                "-1",
                "--alpha1",
                "2",
                "--ratio",
                "0.5",
            ],
            "<title>Compound-rhythm log-aesthetic curve, α0 = -1, α1 = 2, Λ = ",
        ),
        (
            &[
                "path",
                "--polygon",
                "0,0 2,0 3.5,1 4,3",
                "--alpha",
                "0.5",
                "--g2",
            ],
            "<title>Log-aesthetic path (G2), α = 0.5, 2 segments</title>",
        ),
        (
            &[
                "path",
                "--polygon",
                "0,0 2,0 3.5,1 4,3 1,4",
                "--alpha",
                "0.5",
                "--closed",
            ],
            "<title>Closed log-aesthetic path (G1), α = 0.5, 5 segments</title>",
        ),
        (
            &[
                "spline",
                "--through",
                "0,0 2,1.5 4,1 5,-1 3,-3",
                "--alpha",
                "0.5",
            ],
            "<title>Log-aesthetic spline (G2), α = 0.5, 4 segments</title>",
        ),
    ];
    for (args, title) in cases {
        let run = lac(&[args, &["--format", "svg"][..]].concat());
        assert_eq!(run.code, 0, "{args:?}: {}", run.stderr);
        assert!(
            run.stdout.contains(title),
            "{args:?}: {}",
            &run.stdout[..300]
        );
    }
}
