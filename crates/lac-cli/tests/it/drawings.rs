//! Every drawing of `lac` is clean: each text lies on the canvas, no two texts overlap, each
//! coloured entry of a key is a text of its own, and everything drawn lies on the canvas; for
//! every kind of drawing, with the documentation's examples and with awkward inputs (tiny and huge
//! coordinates, coordinates far from the origin, numbers with many digits, long captions,
//! flat and elongated curves, views in which control points coincide).
//!
//! Texts are measured with the estimate the layout uses (`src/svg/measure.rs`, which bounds
//! DejaVu Sans), so the check does not depend on the fonts installed. Where DejaVu Sans is
//! installed, each text is also laid out with it by usvg, and its box must lie inside the
//! estimated one: the estimate is checked against a real font as well.

use crate::common;
#[allow(dead_code)] // the layout's estimate, of which the checks use a part
#[path = "../../src/svg/measure.rs"]
mod measure;

use std::sync::Arc;

use kurbo::{Affine, Point, Rect};
use measure::Anchor;
use resvg::usvg::{self, fontdb, Node};

use common::{lac, lac_with_input};

/// Texts may touch the canvas's edge and each other within this much, pixels (rounding of
/// the written coordinates).
const SLACK: f64 = 0.02;

/// A text of a drawing: what it says, its estimated box on the canvas, and whether it holds
/// runs in more than one colour.
#[derive(Debug)]
struct Label {
    text: String,
    rect: Rect,
    runs: bool,
}

/// The `transform` attribute, as far as the drawings use it: `translate(x,y)` and
/// `rotate(degrees)`, applied right to left.
fn transform(attribute: &str) -> Affine {
    let mut affine = Affine::IDENTITY;
    for part in attribute
        .split(')')
        .map(str::trim)
        .filter(|p| !p.is_empty())
    {
        let (name, args) = part.split_once('(').expect("name(arguments)");
        let args: Vec<f64> = args
            .split([',', ' '])
            .filter(|a| !a.is_empty())
            .map(|a| a.parse().unwrap())
            .collect();
        affine *= match (name.trim(), &args[..]) {
            ("translate", &[x, y]) => Affine::translate((x, y)),
            ("rotate", &[degrees]) => Affine::rotate(degrees.to_radians()),
            other => panic!("a transform the check does not know: {other:?}"),
        };
    }
    affine
}

/// The texts of `svg` with their estimated boxes, and its canvas.
fn labels(svg: &str) -> (Rect, Vec<Label>) {
    let doc = roxmltree::Document::parse(svg).expect("the SVG is well-formed XML");
    let root = doc.root_element();
    let size = |name: &str| -> f64 { root.attribute(name).unwrap().parse().unwrap() };
    let canvas = Rect::new(0.0, 0.0, size("width"), size("height"));
    assert_eq!(
        root.attribute("viewBox"),
        Some(format!("0 0 {} {}", canvas.x1, canvas.y1).as_str()),
        "the viewBox is the canvas"
    );
    let mut labels = Vec::new();
    for node in doc.descendants().filter(|n| n.has_tag_name("text")) {
        let inherited = |name: &str| node.ancestors().find_map(|a| a.attribute(name));
        let runs = node.children().any(|c| c.is_element());
        let text: String = node
            .descendants()
            .filter(|n| n.is_text())
            .filter_map(|n| n.text())
            .collect();
        let font_size: f64 = inherited("font-size")
            .expect("a font size")
            .parse()
            .unwrap();
        let bold = inherited("font-weight") == Some("bold");
        let anchor = match inherited("text-anchor").unwrap_or("start") {
            "start" => Anchor::Start,
            "middle" => Anchor::Middle,
            "end" => Anchor::End,
            other => panic!("text-anchor {other}"),
        };
        let at = |name: &str| node.attribute(name).map_or(0.0, |v| v.parse().unwrap());
        let local = measure::text_box(&text, font_size, bold, (at("x"), at("y")), anchor);
        let affine = node
            .ancestors()
            .filter_map(|a| a.attribute("transform"))
            .fold(Affine::IDENTITY, |inner, t| transform(t) * inner);
        let corners = [
            Point::new(local.x0, local.y0),
            Point::new(local.x1, local.y0),
            Point::new(local.x0, local.y1),
            Point::new(local.x1, local.y1),
        ]
        .map(|p| affine * p);
        let first = Rect::from_points(corners[0], corners[0]);
        let rect = corners.iter().fold(first, |r, p| r.union_pt(*p));
        labels.push(Label { text, rect, runs });
    }
    (canvas, labels)
}

/// usvg's fonts: DejaVu Sans as `sans-serif` when it is installed (`None` when it is not).
fn dejavu() -> Option<Arc<fontdb::Database>> {
    let mut fonts = fontdb::Database::new();
    fonts.load_system_fonts();
    let name = "DejaVu Sans";
    let found = fonts
        .faces()
        .any(|f| f.families.iter().any(|(family, _)| family == name));
    if !found {
        return None;
    }
    fonts.set_sans_serif_family(name);
    Some(Arc::new(fonts))
}

/// Everything drawn, as usvg parses it: the boxes of the paths (strokes included) and, when
/// it has fonts, of the texts laid out with them.
fn drawn(svg: &str, fonts: Option<Arc<fontdb::Database>>) -> (Vec<Rect>, Vec<(String, Rect)>) {
    let options = usvg::Options {
        fontdb: fonts.unwrap_or_else(|| Arc::new(fontdb::Database::new())),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).expect("usvg parses the drawing");
    let rect = |r: usvg::Rect| {
        Rect::new(
            r.left().into(),
            r.top().into(),
            r.right().into(),
            r.bottom().into(),
        )
    };
    fn walk(group: &usvg::Group, visit: &mut dyn FnMut(&Node)) {
        for node in group.children() {
            visit(node);
            if let Node::Group(g) = node {
                walk(g, visit);
            }
        }
    }
    let (mut paths, mut texts) = (Vec::new(), Vec::new());
    walk(tree.root(), &mut |node| match node {
        Node::Path(p) => paths.push(rect(p.abs_stroke_bounding_box())),
        Node::Text(t) => {
            let text: String = t.chunks().iter().map(|c| c.text()).collect();
            texts.push((text, rect(t.abs_bounding_box())));
        }
        _ => {}
    });
    (paths, texts)
}

/// What is wrong with the drawing `svg`, one line a problem (none when it is clean).
fn problems(svg: &str, fonts: &Option<Arc<fontdb::Database>>) -> Vec<String> {
    let mut found = Vec::new();
    let (canvas, labels) = labels(svg);
    if labels.is_empty() {
        found.push("no text at all".to_string());
    }
    let on_canvas = canvas.inflate(SLACK, SLACK);
    let inside = |r: &Rect| on_canvas.union(*r) == on_canvas;
    for label in &labels {
        if !inside(&label.rect) {
            found.push(format!(
                "{:?} at {:.1?} leaves the canvas {:.0?}",
                label.text, label.rect, canvas
            ));
        }
        if label.runs {
            found.push(format!(
                "{:?} holds runs in several colours, left to run on after each other in the \
                 viewer's font instead of placed one by one",
                label.text
            ));
        }
    }
    for (i, a) in labels.iter().enumerate() {
        for b in &labels[i + 1..] {
            if a.rect.inset(-SLACK).intersect(b.rect.inset(-SLACK)).area() > 0.0 {
                found.push(format!(
                    "{:?} at {:.1?} overlaps {:?} at {:.1?}",
                    a.text, a.rect, b.text, b.rect
                ));
            }
        }
    }
    let (paths, texts) = drawn(svg, fonts.clone());
    if paths.is_empty() {
        found.push("nothing drawn".to_string());
    }
    for path in paths.iter().filter(|p| !inside(p)) {
        found.push(format!(
            "a path with bounds {path:.1?} leaves the canvas {canvas:.0?}"
        ));
    }
    if fonts.is_some() {
        // Each text as DejaVu Sans sets it lies inside its estimated box.
        if texts.len() != labels.len() {
            found.push(format!(
                "usvg laid out {} texts of {}",
                texts.len(),
                labels.len()
            ));
        }
        for ((text, real), label) in texts.iter().zip(&labels) {
            let estimate = label.rect.inflate(0.5, 0.5);
            if text != &label.text {
                found.push(format!("usvg read {text:?} for {:?}", label.text));
            } else if estimate.union(*real) != estimate {
                found.push(format!(
                    "{text:?} is {real:.1?} in DejaVu Sans, beyond the estimate {:.1?}",
                    label.rect
                ));
            }
        }
    }
    found
}

/// The drawing `lac args…` writes to standard output.
fn draw(args: &[&str]) -> String {
    let run = lac(args);
    assert_eq!(run.code, 0, "lac {args:?}: {}", run.stderr);
    run.stdout
}

/// The drawing `lac first… | lac lcg --format svg` writes.
fn lcg_of(first: &[&str]) -> String {
    let input = lac(first);
    assert_eq!(input.code, 0, "lac {first:?}: {}", input.stderr);
    let run = lac_with_input(&["lcg", "--format", "svg"], input.stdout.as_bytes());
    assert_eq!(run.code, 0, "lac lcg after {first:?}: {}", run.stderr);
    run.stdout
}

/// Check each of `cases` (arguments of `lac`, or of the command piped into `lac lcg`).
fn check_all(cases: &[&[&str]], lcg: bool) {
    let fonts = dejavu();
    if fonts.is_none() {
        eprintln!("DejaVu Sans is not installed: texts are checked with the estimate only");
    }
    let mut report = String::new();
    for args in cases {
        let svg = if lcg { lcg_of(args) } else { draw(args) };
        let found = problems(&svg, &fonts);
        if !found.is_empty() {
            let what = args.join(" ");
            let via = if lcg { " | lac lcg --format svg" } else { "" };
            report.push_str(&format!("lac {what}{via}:\n  {}\n", found.join("\n  ")));
        }
    }
    assert!(report.is_empty(), "drawings that are not clean:\n{report}");
}

const SVG: [&str; 2] = ["--format", "svg"];

/// `lac segment` with the points, α and options, drawn.
fn segment<'a>(points: &'a str, alpha: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec!["segment", "--points", points, "--alpha", alpha];
    args.extend_from_slice(extra);
    args
}

#[test]
fn segment_drawings_are_clean() {
    let all = ["--format", "svg", "--comb", "--evolute"];
    let cases = [
        segment("0,0 3,0 4.2,1.9", "0.5", &all),
        segment("-1,0 -0.2,0.8 1,0", "0.5", &all),
        segment("1e-6,1e-6 3e-6,1e-6 4.2e-6,2.9e-6", "0.5", &all),
        segment("1e6,1e6 3e6,1e6 4.2e6,2.9e6", "0.5", &all),
        segment(
            "10000000,10000000 10000002,10000000 10000002.4,10000001",
            "0.5",
            &all,
        ),
        segment("-1,0 0.2,0.8 1,0", "-1", &all),
        segment("0,0 1,0.3 2,0", "-3.7", &all),
        segment("-1,0 0,1 1,0", "-1", &all),
        segment("0,0 10,0.05 20,0", "0.5", &all),
        segment("0,0 0.05,10 0,20", "0.5", &all),
        segment("0,0 100,0 140,45", "1.5", &all),
        // A very elongated triangle: P1 and P2 a pixel apart.
        segment("0,0 1000,1 1001,0", "0.5", &all),
        segment(
            "0.123456789,0.987654321 3.14159265358979,0.00000123456 4.2718281828,1.9999999",
            "0.123456789012345",
            &all,
        ),
        segment("0,0 2,0 2.4,1", "0.999999999", &SVG),
    ];
    check_all(&cases.iter().map(Vec::as_slice).collect::<Vec<_>>(), false);
}

#[test]
fn compound_drawings_are_clean() {
    let cases: [&[&str]; 6] = [
        &[
            "compound",
            "--points",
            "0,0 2,0 2.6,1.2",
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
            "--ratio",
            "0.5",
            "--format",
            "svg",
            "--comb",
        ],
        &[
            "compound",
            "--points",
            "0,0 2,0 2.6,1.2",
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
            "--ratio",
            "0.5",
            "--format",
            "svg",
            "--comb",
            "--evolute",
        ],
        &[
            "compound",
            "--points",
            "0,0 2,0 2.5,2 0,1.5",
            "--alpha0",
            "0.5",
            "--alpha1",
            "-0.5",
            "--format",
            "svg",
            "--comb",
            "--evolute",
        ],
        &[
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
            "--evolute",
        ],
        &[
            "compound",
            "--points",
            "0,0 2e-6,0 2.6e-6,1.2e-6",
            "--alpha0",
            "-1.23456789",
            "--alpha1",
            "2.3456789",
            "--ratio",
            "0.123456789",
            "--format",
            "svg",
            "--comb",
            "--evolute",
        ],
        &[
            "compound",
            "--points",
            "0,0 2e6,0 2.5e6,2e6 0,1.5e6",
            "--alpha0",
            "0.5",
            "--alpha1",
            "-0.5",
            "--format",
            "svg",
            "--comb",
            "--evolute",
        ],
    ];
    check_all(&cases, false);
}

#[test]
fn quasi_drawings_are_clean() {
    let cases: [&[&str]; 8] = [
        &[
            "quasi",
            "--points",
            "0,0 3,0 4,1.5",
            "--alpha",
            "-1",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 3,0 4,1.5",
            "--alpha",
            "-1",
            "--tolerance",
            "1e-5",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 3,0 4.2,1.9",
            "--alpha",
            "0.5",
            "--tolerance",
            "1e-6",
            "--cubic",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 2,0 2.6,1.2",
            "--alpha0",
            "-1",
            "--alpha1",
            "2",
            "--ratio",
            "0.5",
            "--tolerance",
            "1e-5",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 2,0 2.5,2 0,1.5",
            "--alpha0",
            "0.5",
            "--alpha1",
            "-0.5",
            "--tolerance",
            "1e-4",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 3e-6,0 4e-6,1.5e-6",
            "--alpha",
            "-1.23456789",
            "--tolerance",
            "1e-6",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 3e6,0 4e6,1.5e6",
            "--alpha",
            "0.987654321",
            "--tolerance",
            "1e-7",
            "--cubic",
            "--format",
            "svg",
        ],
        &[
            "quasi",
            "--points",
            "0,0 10,0.05 20,0",
            "--alpha",
            "0.5",
            "--tolerance",
            "1e-5",
            "--format",
            "svg",
        ],
    ];
    check_all(&cases, false);
}

#[test]
fn lcg_drawings_are_clean() {
    let cases: [&[&str]; 10] = [
        &[
            "quasi",
            "--points",
            "0,0 3,0 4.2,1.9",
            "--alpha",
            "0.5",
            "--tolerance",
            "1e-6",
        ],
        &["quasi", "--points", "0,0 3,0 4,1.5", "--alpha", "-1"],
        &[
            "quasi",
            "--points",
            "0,0 2,0 2.5,2 0,1.5",
            "--alpha0",
            "0.5",
            "--alpha1",
            "-0.5",
            "--tolerance",
            "1e-4",
            "--cubic",
        ],
        &[
            "quasi",
            "--points",
            "0,0 3e-6,0 4e-6,1.5e-6",
            "--alpha",
            "-1.23456789",
            "--tolerance",
            "1e-6",
        ],
        &[
            "quasi",
            "--points",
            "1e6,1e6 4e6,1e6 5e6,2.5e6",
            "--alpha",
            "0.987654321",
            "--tolerance",
            "1e-7",
        ],
        &["segment", "--points", "0,0 3,0 4.2,1.9", "--alpha", "0.5"],
        &[
            "segment",
            "--points",
            "0.123456789,0.987654321 3.14159265358979,0.00000123456 4.2718281828,1.9999999",
            "--alpha",
            "0.123456789012345",
        ],
        // A circular arc: no graph at all.
        &["segment", "--points", "-1,0 0,1 1,0", "--alpha", "-1"],
        &[
            "compound",
            "--points",
            "0,0 2e6,0 2.5e6,2e6 0,1.5e6",
            "--alpha0",
            "0.5",
            "--alpha1",
            "-0.5",
        ],
        &[
            "compound",
            "--points",
            "0,0 2e-6,0 2.6e-6,1.2e-6",
            "--alpha0",
            "-1.23456789",
            "--alpha1",
            "2.3456789",
            "--ratio",
            "0.123456789",
        ],
    ];
    check_all(&cases, true);
}

#[test]
fn lcg_drawings_of_space_curves_and_of_curvature_that_is_not_monotone_are_clean() {
    let space = |points: &'static str, rest: &[&'static str]| -> Vec<&'static str> {
        let mut args = vec!["space", "--points", points];
        args.extend_from_slice(rest);
        args
    };
    let cases = [
        space(
            "0,0,0 3,0,0 3,3,1.5 0,3,3",
            &["--alpha", "0.5", "--beta", "0", "--omega", "0.3"],
        ),
        space(
            "0,0,0 3e-6,0,0 3e-6,3e-6,1.5e-6 0,3e-6,3e-6",
            &[
                "--alpha",
                "-0.123456789",
                "--beta",
                "0.987654321",
                "--omega",
                "0.0123456789",
                "--type",
                "2",
            ],
        ),
        // No torsion graph (Ω = 0), and a planar segment with neither a torsion graph nor
        // (a circular arc) a curvature graph.
        space(
            "0,0,0 3,0,0 3,3,1.5 0,3,3",
            &["--alpha", "0.5", "--beta", "0"],
        ),
        space(
            "0,0,0 1,0,0 2,1,0 2,2,0",
            &["--alpha", "0.5", "--beta", "0", "--omega", "0.3"],
        ),
    ];
    check_all(&cases.iter().map(Vec::as_slice).collect::<Vec<_>>(), true);
    let fonts = dejavu();
    for document in [
        r#"{"pieces":[{"points":[[0,0],[1.2,0],[2,0.4],[2.4,1]]},{"points":[[0,0],[1.2,0],[2,-0.4],[2.4,-1]]}]}"#,
        r#"{"pieces":[{"points":[[0,0],[1,1],[2,-1],[3,0]]}]}"#,
    ] {
        let run = lac_with_input(&["lcg", "--format", "svg"], document.as_bytes());
        assert_eq!(run.code, 0, "{}", run.stderr);
        let found = problems(&run.stdout, &fonts);
        assert!(
            found.is_empty(),
            "lac lcg of {document}:\n  {}",
            found.join("\n  ")
        );
    }
}

#[test]
fn space_drawings_are_clean() {
    let space = |points: &'static str, rest: &[&'static str]| -> Vec<&'static str> {
        let mut args = vec!["space", "--points", points, "--format", "svg"];
        args.extend_from_slice(rest);
        args
    };
    let readme = ["--alpha", "0.5", "--beta", "0", "--omega", "0.3"];
    let straight = ["--alpha", "0.5", "--beta", "0"];
    let cases = [
        space("0,0,0 3,0,0 3,3,1.5 0,3,3", &readme),
        space(
            "0,0,0 3,0,0 3,3,1.5 0,3,3",
            &[
                "--alpha", "-0.75", "--beta", "0.5", "--omega", "0.1", "--type", "2",
            ],
        ),
        space("0,0,0 3,0,0 4,2,0 4,4,0", &straight),
        space("0,0,0 3e-6,0,0 3e-6,3e-6,1.5e-6 0,3e-6,3e-6", &readme),
        space("1e6,1e6,1e6 4e6,1e6,1e6 4e6,4e6,2.5e6 1e6,4e6,4e6", &readme),
        // Far from the origin: long tick labels.
        space(
            "1234567,7654321,1000000 1234570,7654321,1000000 1234570,7654324,1000001.5 \
             1234567,7654324,1000003",
            &readme,
        ),
        space(
            "0.123456789,0,0 3.14159265,0,0 3,3.14159265,1.5 0,3,3.333333333",
            &[
                "--alpha",
                "0.123456789",
                "--beta",
                "-0.987654321",
                "--omega",
                "0.0123456789",
            ],
        ),
        // Flat and tall: views in which all four points coincide.
        space("0,0,0 10,0,0 20,0.5,0.1 30,0.5,0.2", &straight),
        space("0,0,0 0,0,10 0.5,0.2,20 0,0.4,30", &straight),
    ];
    check_all(&cases.iter().map(Vec::as_slice).collect::<Vec<_>>(), false);
}

#[test]
fn the_readme_figures_are_clean() {
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs");
    let fonts = dejavu();
    let mut report = String::new();
    let mut figures = 0;
    for entry in std::fs::read_dir(&docs).expect("docs/ is there") {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "svg") {
            let svg = std::fs::read_to_string(&path).unwrap();
            let found = problems(&svg, &fonts);
            if !found.is_empty() {
                report.push_str(&format!("{}:\n  {}\n", path.display(), found.join("\n  ")));
            }
            figures += 1;
        }
    }
    assert!(
        figures >= 5,
        "segment, compound, quasi, lcg and space figures"
    );
    assert!(
        report.is_empty(),
        "figures that are not clean (regenerate them with `make docs`):\n{report}"
    );
}

#[test]
fn fit_drawings_are_clean() {
    let run = lac(&[
        "path",
        "--polygon",
        "0,0 2,0 3.5,1 4,3 3,4.5 1,5",
        "--alpha",
        "0.5",
        "--g2",
        "--format",
        "csv",
        "--samples",
        "300",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let dir = tempfile::tempdir().unwrap();
    // The samples' x and y (columns 2 and 3 of the CSV), as they are and scaled.
    let mut files = Vec::new();
    for scale in [1.0, 1e-6, 1e6] {
        let text: String = run
            .stdout
            .lines()
            .skip(1)
            .map(|l| {
                let c: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
                format!("{} {}\n", c[1] * scale, c[2] * scale)
            })
            .collect();
        let file = dir.path().join(format!("points{scale}.txt"));
        std::fs::write(&file, text).unwrap();
        files.push(file.to_str().unwrap().to_string());
    }
    let cases: Vec<Vec<&str>> = vec![
        vec!["fit", &files[0], "--format", "svg"],
        vec!["fit", &files[0], "--format", "svg", "--tolerance", "1e-4"],
        vec!["fit", &files[1], "--format", "svg", "--tolerance", "1e-10"],
        vec![
            "fit",
            &files[2],
            "--format",
            "svg",
            "--alpha",
            "1",
            "--max-segments",
            "4",
        ],
        vec![
            "fit",
            &files[0],
            "--format",
            "svg",
            "--g1",
            "--max-segments",
            "2",
        ],
    ];
    let cases: Vec<&[&str]> = cases.iter().map(Vec::as_slice).collect();
    check_all(&cases, false);
}
