//! `lac space`: the JSON's keys and meaning (the transform really maps the standard form onto
//! the samples), the planar fallback, the error lines with "omega_max", and the SVG, OBJ and
//! PLY outputs.

use crate::common;

use common::{assert_failure, assert_keys, f, json, lac, Run};
use lac::{SpaceForm, SpaceFormParams, TorsionType, Vec3};
use serde_json::Value;

/// Non-coplanar, solved as given (not reversed, not mirrored).
const PLAIN: &str = "0,0,0 1,0,0 2,1,0.3 2,2,1";
/// Its mirror image in z = 0: left-handed, the standard form mirrored.
const MIRRORED: &str = "0,0,0 1,0,0 2,1,-0.3 2,2,-1";
/// θ0 < θ1: the standard form runs from the last point to the first.
const REVERSED: &str = "0,0,0 2,0,0 2.5,1,0.3 2.5,1.5,1";
/// P2 above the plane of P0, P1, P3 (where PLAIN's P2 is below): mirrored as well.
const ABOVE: &str = "0,0,0 1,0,0 2,1,0.8 2,2,1";
/// Coplanar (the plane z = y/2): the planar segment.
const TILTED_PLANE: &str = "0,0,0 1,0,0 2,1,0.5 2,2,1";

const SAMPLE_KEYS: [&str; 6] = ["s", "x", "y", "z", "kappa", "tau"];

fn space(points: &str, extra: &[&str]) -> Run {
    let mut args = vec!["space", "--points", points];
    args.extend_from_slice(extra);
    lac(&args)
}

/// The JSON of a run that must succeed.
fn solved(points: &str, extra: &[&str]) -> (Value, String) {
    let run = space(points, extra);
    assert_eq!(run.code, 0, "{points} {extra:?}: {}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1, "one line");
    (json(&run), run.stdout)
}

/// The report without the input it repeats at its end (`points`, `alpha`, `beta`, `omega`,
/// `type`), and the text of that input.
fn without_input<'a>(v: &Value, text: &'a str) -> (Value, &'a str) {
    let mut head = v.clone();
    for key in ["points", "alpha", "beta", "omega", "type"] {
        assert!(head.as_object_mut().unwrap().remove(key).is_some(), "{key}");
    }
    let input = &text[text.rfind(r#""points":"#).unwrap()..];
    (head, input.trim_end())
}

fn vec3(v: &Value) -> Vec3 {
    let a = v
        .as_array()
        .unwrap_or_else(|| panic!("{v} is not an array"));
    assert_eq!(a.len(), 3, "{v}");
    Vec3::new(f(&a[0]), f(&a[1]), f(&a[2]))
}

fn at(sample: &Value) -> Vec3 {
    Vec3::new(f(&sample["x"]), f(&sample["y"]), f(&sample["z"]))
}

fn control_points(text: &str) -> [Vec3; 4] {
    let p: Vec<Vec3> = text
        .split_whitespace()
        .map(|t| {
            let c: Vec<f64> = t.split(',').map(|x| x.parse().unwrap()).collect();
            Vec3::new(c[0], c[1], c[2])
        })
        .collect();
    [p[0], p[1], p[2], p[3]]
}

/// `translation + scale · rotation · M · p`, as the JSON documents it.
fn apply(transform: &Value, p: Vec3) -> Vec3 {
    let scale = f(&transform["scale"]);
    vec3(&transform["translation"]) + scale * direction(transform, p)
}

/// `rotation · M · v`.
fn direction(transform: &Value, v: Vec3) -> Vec3 {
    let r: Vec<Vec3> = transform["rotation"]
        .as_array()
        .unwrap()
        .iter()
        .map(vec3)
        .collect();
    assert_eq!(r.len(), 3);
    let m = if transform["mirror_z"].as_bool().unwrap() {
        Vec3::new(v.x, v.y, -v.z)
    } else {
        v
    };
    Vec3::new(r[0].dot(m), r[1].dot(m), r[2].dot(m))
}

/// The standard form the JSON describes, built by the library.
fn standard_form(v: &Value) -> SpaceForm {
    let form = &v["standard_form"];
    SpaceForm::new(SpaceFormParams {
        alpha: f(&form["alpha"]),
        beta: f(&form["beta"]),
        lambda: f(&form["lambda"]),
        omega: f(&form["omega"]),
        nu: f(&form["nu"]),
        torsion: TorsionType::from_number(form["type"].as_u64().unwrap() as u8).unwrap(),
    })
    .unwrap()
}

/// The checks every solved result passes: ends at P0 and P3 within 1e-9 of the chord, equal
/// spacing in arc length, positive curvature, exactly the documented sample keys.
fn assert_samples_span_the_points(v: &Value, points: [Vec3; 4], n: usize) {
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), n);
    let chord = points[0].distance(points[3]);
    let first = at(&samples[0]);
    let last = at(&samples[n - 1]);
    assert!(first.distance(points[0]) <= 1e-9 * chord, "{first:?}");
    assert!(last.distance(points[3]) <= 1e-9 * chord, "{last:?}");
    let length = f(&v["arc_length"]);
    assert!(length > chord);
    for (i, s) in samples.iter().enumerate() {
        let keys: Vec<&str> = s.as_object().unwrap().keys().map(String::as_str).collect();
        let mut sorted = SAMPLE_KEYS.to_vec();
        sorted.sort_unstable();
        assert_eq!(keys, sorted, "sample {i}");
        let want = length * i as f64 / (n - 1) as f64;
        assert!((f(&s["s"]) - want).abs() <= 1e-12 * length, "sample {i}");
        assert!(f(&s["kappa"]) > 0.0, "sample {i}: {s}");
    }
    // The polyline through the samples is a little shorter than the curve.
    let polyline: f64 = samples
        .windows(2)
        .map(|w| at(&w[0]).distance(at(&w[1])))
        .sum();
    assert!(polyline <= length * (1.0 + 1e-12), "{polyline} {length}");
    if n >= 33 {
        assert!(polyline > (1.0 - 1e-3) * length, "{polyline} {length}");
    }
}

#[test]
fn json_has_the_documented_keys_in_order() {
    let (v, text) = solved(PLAIN, &["--alpha", "0", "--beta", "0"]);
    let (head, input) = without_input(&v, &text);
    assert_eq!(
        input,
        r#""points":[[0.0,0.0,0.0],[1.0,0.0,0.0],[2.0,1.0,0.3],[2.0,2.0,1.0]],"alpha":0.0,"beta":0.0,"omega":0.0,"type":1}"#,
        "the input as given, last, so that the report reads back as its input"
    );
    assert_keys(
        &text,
        &head,
        &[
            "standard_form",
            "transform",
            "arc_length",
            "planar",
            "samples",
        ],
    );
    assert!(text.starts_with(r#"{"standard_form":{"alpha":0.0,"beta":0.0,"lambda":"#));
    let form_text = &text[..text.find(r#""transform""#).unwrap()];
    assert_keys(
        form_text,
        &v["standard_form"],
        &["alpha", "beta", "lambda", "omega", "nu", "type", "s_end"],
    );
    let transform_text = &text[text.find(r#""transform""#).unwrap()..];
    assert_keys(
        transform_text,
        &v["transform"],
        &["scale", "rotation", "translation", "mirror_z", "reversed"],
    );
    assert!(text.contains(r#""samples":[{"s":0.0,"x":0.0,"y":0.0,"z":0.0,"kappa":"#));
    assert_eq!(v["planar"], false);
    assert_eq!(v["standard_form"]["omega"], 0.0, "--omega defaults to 0");
    assert_eq!(v["standard_form"]["type"], 1, "--type defaults to 1");
    assert_eq!(
        v["samples"].as_array().unwrap().len(),
        65,
        "the default sample count, as in lac segment"
    );
    assert_eq!(v["transform"]["mirror_z"], false);
    assert_eq!(v["transform"]["reversed"], false);
    assert!(f(&v["standard_form"]["lambda"]) > 0.0 && f(&v["standard_form"]["nu"]) > 0.0);
}

#[test]
fn samples_run_from_the_first_to_the_last_point_for_every_kind_of_placement() {
    for (points, extra) in [
        (PLAIN, vec!["--alpha", "0", "--beta", "0"]),
        (PLAIN, vec!["--alpha", "0", "--beta", "0", "--omega", "0.3"]),
        (
            PLAIN,
            vec![
                "--alpha", "0", "--beta", "0", "--omega", "0.3", "--type", "2",
            ],
        ),
        (
            PLAIN,
            vec![
                "--alpha", "-1", "--beta", "2", "--omega", "0.3", "--type", "2",
            ],
        ),
        (
            PLAIN,
            vec!["--alpha", "2", "--beta", "-1", "--omega", "0.2"],
        ),
        (MIRRORED, vec!["--alpha", "0.5", "--beta", "0.5"]),
        (ABOVE, vec!["--alpha", "0", "--beta", "0", "--omega", "0.3"]),
        (
            REVERSED,
            vec![
                "--alpha", "0", "--beta", "0", "--omega", "0.3", "--type", "2",
            ],
        ),
        (
            REVERSED,
            vec!["--alpha", "1", "--beta", "1", "--samples", "2"],
        ),
    ] {
        let (v, _) = solved(points, &extra);
        let n = if extra.contains(&"--samples") { 2 } else { 65 };
        assert_samples_span_the_points(&v, control_points(points), n);
    }
}

#[test]
fn the_transform_maps_the_standard_form_onto_the_samples() {
    for (points, reversed) in [(PLAIN, false), (MIRRORED, false), (REVERSED, true)] {
        for omega in ["0", "0.3"] {
            let (v, _) = solved(
                points,
                &[
                    "--alpha", "0.5", "--beta", "0", "--omega", omega, "--type", "2",
                ],
            );
            let p = control_points(points);
            let chord = p[0].distance(p[3]);
            let transform = &v["transform"];
            assert_eq!(transform["reversed"], reversed, "{points}");
            let form = standard_form(&v);
            let s_end = f(&v["standard_form"]["s_end"]);
            let scale = f(&transform["scale"]);
            assert!((scale * s_end - f(&v["arc_length"])).abs() <= 1e-12 * scale * s_end);
            // The standard form starts at the origin, tangent +x: at P0 along P1 − P0, or,
            // reversed, at P3 along P2 − P3.
            let (start, towards) = if reversed { (p[3], p[2]) } else { (p[0], p[1]) };
            assert!(vec3(&transform["translation"]).distance(start) <= 1e-12 * chord);
            let t = direction(transform, Vec3::X);
            assert!(t.distance((towards - start).normalize()) < 1e-12, "{t:?}");
            let end = if reversed { p[0] } else { p[3] };
            let mapped = apply(transform, form.frame_at_s(s_end).unwrap().point);
            assert!(mapped.distance(end) <= 1e-9 * chord, "{mapped:?} {end:?}");
            // Every sample is the standard form's point at the matching arc length.
            for sample in v["samples"].as_array().unwrap().iter().step_by(8) {
                let s = f(&sample["s"]) / scale;
                let s = if reversed { s_end - s } else { s };
                let frame = form.frame_at_s(s.max(0.0)).unwrap();
                assert!(apply(transform, frame.point).distance(at(sample)) <= 1e-9 * chord);
                assert!((frame.curvature / scale - f(&sample["kappa"])).abs() < 1e-9);
            }
        }
    }
}

#[test]
fn torsion_has_the_handedness_of_the_control_polygon() {
    for points in [PLAIN, MIRRORED, REVERSED, ABOVE] {
        let p = control_points(points);
        let handed = (p[1] - p[0]).cross(p[2] - p[1]).dot(p[3] - p[2]);
        for omega in ["0", "0.3"] {
            let (v, _) = solved(points, &["--alpha", "0", "--beta", "0", "--omega", omega]);
            let mirrored = v["transform"]["mirror_z"].as_bool().unwrap();
            for sample in v["samples"].as_array().unwrap() {
                let tau = f(&sample["tau"]);
                assert_eq!(tau > 0.0, handed > 0.0, "{points}: tau {tau}");
                assert_eq!(tau < 0.0, mirrored, "{points}: tau {tau}");
            }
        }
    }
}

#[test]
fn a_mirror_image_gives_the_same_standard_form_mirrored() {
    let args = ["--alpha", "0", "--beta", "0", "--omega", "0.3"];
    let (right, _) = solved(PLAIN, &args);
    let (left, _) = solved(MIRRORED, &args);
    assert_eq!(right["transform"]["mirror_z"], false);
    assert_eq!(left["transform"]["mirror_z"], true);
    for key in ["lambda", "nu", "s_end"] {
        let (a, b) = (
            f(&right["standard_form"][key]),
            f(&left["standard_form"][key]),
        );
        assert!((a - b).abs() <= 1e-9 * a.abs(), "{key}: {a} {b}");
    }
    let (a, b) = (right["samples"][20].clone(), left["samples"][20].clone());
    assert!((f(&a["z"]) + f(&b["z"])).abs() < 1e-9);
    assert!((f(&a["tau"]) + f(&b["tau"])).abs() < 1e-9);
    // Lifting P2 above the plane of P0, P1 and P3 instead of below it flips the handedness.
    let (above, _) = solved(ABOVE, &args);
    assert_eq!(above["transform"]["mirror_z"], true);
}

#[test]
fn frames_adds_orthonormal_frenet_frames() {
    let (v, text) = solved(
        PLAIN,
        &["--alpha", "0", "--beta", "0", "--frames", "--samples", "9"],
    );
    assert!(text.contains(r#""tau":"#) && text.contains(r#","t":["#));
    let samples = v["samples"].as_array().unwrap();
    for (i, s) in samples.iter().enumerate() {
        let mut keys: Vec<&str> = s.as_object().unwrap().keys().map(String::as_str).collect();
        keys.sort_unstable();
        assert_eq!(keys, ["b", "kappa", "n", "s", "t", "tau", "x", "y", "z"]);
        let (t, n, b) = (vec3(&s["t"]), vec3(&s["n"]), vec3(&s["b"]));
        for (u, w, want) in [
            (t, t, 1.0),
            (n, n, 1.0),
            (b, b, 1.0),
            (t, n, 0.0),
            (t, b, 0.0),
            (n, b, 0.0),
        ] {
            assert!((u.dot(w) - want).abs() < 1e-12, "sample {i}");
        }
        assert!(t.cross(n).distance(b) < 1e-12, "right-handed");
        if i + 1 < samples.len() {
            // The chord to the next sample leans along t and toward n.
            let step = at(&samples[i + 1]) - at(s);
            assert!(step.dot(t) > 0.99 * step.length());
            assert!(step.dot(n) > 0.0);
        }
    }
    let p = control_points(PLAIN);
    assert!(vec3(&samples[0]["t"]).distance((p[1] - p[0]).normalize()) < 1e-12);
    assert!(vec3(&samples[8]["t"]).distance((p[3] - p[2]).normalize()) < 1e-9);
}

#[test]
fn coplanar_points_give_the_planar_segment_with_a_note() {
    let (v, text) = solved("0,0,0 1,0,0 2,1,0 2,2,0", &["--alpha", "0", "--beta", "0"]);
    let (head, input) = without_input(&v, &text);
    assert!(input.starts_with(r#""points":[[0.0,0.0,0.0],"#), "{input}");
    assert_keys(
        &text,
        &head,
        &[
            "standard_form",
            "transform",
            "arc_length",
            "planar",
            "samples",
            "planar_segment",
            "note",
        ],
    );
    assert!(text.starts_with(r#"{"standard_form":null,"transform":null,"arc_length":"#));
    assert_eq!(v["planar"], true);
    assert!(v["note"].as_str().unwrap().contains("coplanar"));
    let planar = &v["planar_segment"];
    let planar_text = &text[text.find(r#""planar_segment""#).unwrap()..];
    assert_keys(planar_text, planar, &["alpha", "lambda", "control_points"]);
    assert_eq!(planar["alpha"], 0.0);
    let cp: Vec<Vec3> = planar["control_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(vec3)
        .collect();
    // P0, the tangents' intersection (2, 0, 0), P3.
    for (got, want) in cp.iter().zip([
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(2.0, 0.0, 0.0),
        Vec3::new(2.0, 2.0, 0.0),
    ]) {
        assert!(got.distance(want) < 1e-12, "{got:?}");
    }
    assert_samples_span_the_points(&v, control_points("0,0,0 1,0,0 2,1,0 2,2,0"), 65);
    for s in v["samples"].as_array().unwrap() {
        assert_eq!(f(&s["tau"]), 0.0);
        assert!(f(&s["z"]).abs() < 1e-15);
    }
    // The same as lac segment on the triangle, whatever the plane.
    let segment = json(&lac(&[
        "segment",
        "--points",
        "0,0 2,0 2,2",
        "--alpha",
        "0",
    ]));
    assert!((f(&segment["arc_length"]) - f(&v["arc_length"])).abs() < 1e-12);
    assert!((f(&segment["lambda"]) - f(&planar["lambda"])).abs() < 1e-12);

    let (tilted, _) = solved(TILTED_PLANE, &["--alpha", "0", "--beta", "0"]);
    assert_eq!(tilted["planar"], true);
    assert!((f(&tilted["arc_length"]) - f(&v["arc_length"])).abs() > 1e-3);
    for s in tilted["samples"].as_array().unwrap() {
        assert!(
            (f(&s["z"]) - 0.5 * f(&s["y"])).abs() < 1e-12,
            "in the plane z = y/2"
        );
    }
    assert_samples_span_the_points(&tilted, control_points(TILTED_PLANE), 65);
    assert!(v["note"]
        .as_str()
        .unwrap()
        .contains("beta and omega do not apply"));
}

/// Coplanar points whose tangents turn by 180°: the planar segment (through the tangents'
/// intersection) does not exist, and the message says so with the angles it measures.
#[test]
fn a_coplanar_u_turn_is_refused_with_the_turning_it_has() {
    let run = space(
        "0,0,0 3,0,0 3,3,0 0,3,0",
        &["--alpha", "0.5", "--beta", "0", "--omega", "0.3"],
    );
    let message = assert_failure(&run, 3, "not_drawable");
    assert!(message.contains("coplanar"), "{message}");
    assert!(message.contains("beta and omega do not apply"), "{message}");
    assert!(message.contains("turn by 180.0000 deg"), "{message}");
    assert!(
        message.contains("90.0000 deg with the start tangent"),
        "{message}"
    );
}

#[test]
fn bad_input_exits_2_with_one_json_line() {
    let ab = ["--alpha", "0", "--beta", "0"];
    for (points, extra, kind) in [
        ("nan,0,0 1,0,0 2,1,0.3 2,2,1", &ab[..], "non_finite"),
        ("0,0,0 0,0,0 2,1,0.3 2,2,1", &ab[..], "coincident_points"),
        ("0,0,0 1,0,0 2,1,0.3 2,1,0.3", &ab[..], "coincident_points"),
        ("0,0,0 1,0,0 2,1,0.3", &ab[..], "invalid_input"),
        ("0,0,0 1,0,0 2,1,0.3 2,2,1 3,3,3", &ab[..], "invalid_input"),
        ("0,0 1,0 2,1 2,2", &ab[..], "invalid_input"),
        ("0,0,0 1,0,0 2,x,0.3 2,2,1", &ab[..], "invalid_input"),
        (
            PLAIN,
            &["--alpha", "0", "--beta", "0", "--type", "3"][..],
            "out_of_range",
        ),
        (
            PLAIN,
            &["--alpha", "0", "--beta", "0", "--omega", "-0.5"][..],
            "out_of_range",
        ),
        (PLAIN, &["--alpha", "inf", "--beta", "0"][..], "non_finite"),
        (PLAIN, &["--alpha", "0"][..], "usage"),
        (
            PLAIN,
            &["--alpha", "0", "--beta", "0", "--samples", "1"][..],
            "usage",
        ),
        (
            PLAIN,
            &["--alpha", "0", "--beta", "0", "--format", "svg", "--frames"][..],
            "usage",
        ),
        (
            PLAIN,
            &["--alpha", "0", "--beta", "0", "--format", "stl"][..],
            "usage",
        ),
    ] {
        let run = space(points, extra);
        let message = assert_failure(&run, 2, kind);
        assert!(
            !run.stderr.contains("omega_max"),
            "{points} {extra:?}: {message}"
        );
    }
    let message = assert_failure(
        &space("0,0,0 1,0,0 2,1,0.3 2,2,1 3,3,3", &ab),
        2,
        "invalid_input",
    );
    assert!(message.contains("4 points \"x,y,z\""), "{message}");
}

#[test]
fn too_much_torsion_exits_3_with_the_largest_omega_that_works() {
    let run = space(PLAIN, &["--alpha", "0", "--beta", "0", "--omega", "30"]);
    let message = assert_failure(&run, 3, "not_drawable");
    assert!(message.contains("omega"), "{message}");
    let error: Value = serde_json::from_str(&run.stderr).unwrap();
    let keys: Vec<&str> = error["error"]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(keys, ["kind", "message", "omega_max"]);
    assert!(run.stderr.find("\"message\"").unwrap() < run.stderr.find("\"omega_max\"").unwrap());
    let omega_max = f(&error["error"]["omega_max"]);
    assert!(omega_max > 0.3 && omega_max < 30.0, "{omega_max}");
    let below = format!("{}", 0.99 * omega_max);
    let (v, _) = solved(PLAIN, &["--alpha", "0", "--beta", "0", "--omega", &below]);
    assert_eq!(f(&v["standard_form"]["omega"]), 0.99 * omega_max);
    assert_samples_span_the_points(&v, control_points(PLAIN), 65);
    // Other commands' error lines keep their two keys.
    let run = lac(&["segment", "--points", "0,0 1,1 2,2", "--alpha", "0"]);
    assert!(!run.stderr.contains("omega_max"));
}

/// The document, checked to be one well-formed SVG that usvg renders.
fn svg(points: &str, extra: &[&str]) -> String {
    let mut args = vec!["--format", "svg"];
    args.extend_from_slice(extra);
    let run = space(points, &args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let doc = run.stdout;
    assert!(doc.starts_with("<?xml") && doc.trim_end().ends_with("</svg>"));
    assert!(doc.contains(r#"xmlns="http://www.w3.org/2000/svg""#));
    resvg::usvg::Tree::from_str(&doc, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("usvg parses the SVG: {e}"));
    doc
}

#[test]
fn the_svg_has_three_views_and_a_perspective() {
    for (points, extra) in [
        (PLAIN, &["--alpha", "0", "--beta", "0", "--omega", "0.3"][..]),
        (REVERSED, &["--alpha", "0.5", "--beta", "1", "--type", "2"][..]),
        ("0,0,0 1,0,0 2,1,0 2,2,0", &["--alpha", "0", "--beta", "0"][..]),
        (
            "1e7,1e7,1e7 1.000001e7,1e7,1e7 1.000002e7,1.0000005e7,1.00000015e7 1.000002e7,1.000001e7,1.0000005e7",
            &["--alpha", "0", "--beta", "0"][..],
        ),
    ] {
        let doc = svg(points, extra);
        assert_eq!(doc.matches(r#"<g class="panel""#).count(), 4, "{points}");
        for id in ["top", "front", "side", "perspective"] {
            assert!(doc.contains(&format!(r#"id="{id}""#)), "{id}");
        }
        for title in ["Top view (xy)", "Front view (xz)", "Side view (yz)", "Perspective"] {
            assert!(doc.contains(title), "{title}");
        }
        assert!(doc.contains(r#"class="shadow""#));
        // Each panel: the dashed polygon and the curve; four markers (some may share one).
        assert_eq!(doc.matches(r#"stroke-dasharray="6 4""#).count(), 4);
        assert!(doc.matches("<circle").count() >= 4 * 2);
        assert!(!doc.contains("NaN") && !doc.contains("inf"));
    }
    let planar = svg("0,0,0 1,0,0 2,1,0 2,2,0", &["--alpha", "0", "--beta", "0"]);
    assert!(planar.contains("coplanar"));
    let reversed = svg(REVERSED, &["--alpha", "0", "--beta", "0"]);
    assert!(reversed.contains("reversed"));
}

#[test]
fn obj_is_one_vertex_per_sample_and_one_polyline() {
    let args = [
        "--alpha",
        "0",
        "--beta",
        "0",
        "--omega",
        "0.3",
        "--samples",
        "33",
    ];
    let (v, _) = solved(PLAIN, &args);
    let mut obj_args = args.to_vec();
    obj_args.extend(["--format", "obj"]);
    let run = space(PLAIN, &obj_args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert!(lines[0].starts_with("# lac space"));
    let vertices: Vec<Vec3> = lines
        .iter()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let c: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
            assert_eq!(c.len(), 3);
            Vec3::new(c[0], c[1], c[2])
        })
        .collect();
    assert_eq!(vertices.len(), 33);
    for (vertex, sample) in vertices.iter().zip(v["samples"].as_array().unwrap()) {
        assert_eq!(*vertex, at(sample), "the JSON's numbers, bit for bit");
    }
    let polylines: Vec<&&str> = lines.iter().filter(|l| l.starts_with("l ")).collect();
    assert_eq!(polylines.len(), 1);
    let want: Vec<String> = (1..=33).map(|i| i.to_string()).collect();
    assert_eq!(polylines[0][2..], want.join(" "));
    assert!(lines.iter().all(|l| l.starts_with("# ")
        || l.starts_with("v ")
        || l.starts_with("l ")
        || l.starts_with("o ")));
}

#[test]
fn ply_has_vertices_with_curvature_and_torsion_and_edges_between_them() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("curve.ply");
    let path_text = path.to_str().unwrap();
    let args = [
        "--alpha",
        "0",
        "--beta",
        "0",
        "--omega",
        "0.3",
        "--samples",
        "17",
    ];
    let (v, _) = solved(MIRRORED, &args);
    let mut ply_args = args.to_vec();
    ply_args.extend(["--format", "ply", "-o", path_text]);
    let run = space(MIRRORED, &ply_args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.is_empty());
    let text = std::fs::read_to_string(&path).unwrap();
    let (head, body) = text.split_once("end_header\n").unwrap();
    let head: Vec<&str> = head.lines().collect();
    assert_eq!(head[..2], ["ply", "format ascii 1.0"]);
    assert!(
        head[2..]
            .iter()
            .take_while(|l| l.starts_with("comment "))
            .count()
            >= 3
    );
    let declared: Vec<&str> = head
        .iter()
        .filter(|l| !l.starts_with("comment "))
        .copied()
        .collect();
    assert_eq!(
        declared[2..],
        [
            "element vertex 17",
            "property double x",
            "property double y",
            "property double z",
            "property double kappa",
            "property double tau",
            "element edge 16",
            "property int vertex1",
            "property int vertex2",
        ]
    );
    let rows: Vec<Vec<f64>> = body
        .lines()
        .map(|l| l.split(' ').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 17 + 16);
    for (row, sample) in rows[..17].iter().zip(v["samples"].as_array().unwrap()) {
        let want = [
            f(&sample["x"]),
            f(&sample["y"]),
            f(&sample["z"]),
            f(&sample["kappa"]),
            f(&sample["tau"]),
        ];
        assert_eq!(row[..], want);
        assert!(row[4] < 0.0, "mirrored: negative torsion");
    }
    for (i, row) in rows[17..].iter().enumerate() {
        assert_eq!(row[..], [i as f64, i as f64 + 1.0]);
    }
}

#[test]
fn a_failed_run_leaves_the_output_file_alone_and_help_names_space() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.json");
    std::fs::write(&path, "before").unwrap();
    let run = space(
        PLAIN,
        &[
            "--alpha",
            "0",
            "--beta",
            "0",
            "--omega",
            "30",
            "-o",
            path.to_str().unwrap(),
        ],
    );
    assert_failure(&run, 3, "not_drawable");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "before");

    let help = lac(&["--help"]);
    assert_eq!(help.code, 0);
    assert!(help.stdout.contains("space"), "{}", help.stdout);
    let help = lac(&["space", "--help"]);
    assert_eq!(help.code, 0);
    for word in [
        "--points", "--alpha", "--beta", "--omega", "--type", "--frames", "obj", "ply",
    ] {
        assert!(help.stdout.contains(word), "{word}");
    }
    let message = assert_failure(&lac(&[]), 2, "usage");
    assert!(message.contains("'lac space'"), "{message}");
}
