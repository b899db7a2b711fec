//! `lac space`: a log-aesthetic space curve segment (seed 003, SPEC §6) from four 3-D control
//! points, α, β, Ω and the torsion type, as JSON, SVG, OBJ or PLY.

use lac::{Frame, SpaceSegment, SpaceShape, TorsionType, Vec3};
use serde::Serialize;

use crate::cli::{SpaceArgs, SpaceFormat};
use crate::failure::Failure;
use crate::mesh;
use crate::output::write_to;
use crate::points::parse_space_points;
use crate::svg;

/// The `"note"` of a planar (coplanar-points) result.
pub(crate) const PLANAR_NOTE: &str = "the four control points are coplanar, so the planar \
     log-aesthetic segment through the first point, the tangents' intersection and the last \
     point is drawn (torsion 0)";

/// What `lac space --format json` prints. Keys in this order; `planar_segment` and `note`
/// only for coplanar points.
#[derive(Debug, Serialize)]
struct SpaceReport {
    /// The solved standard form; `null` when planar.
    standard_form: Option<FormRow>,
    /// Standard form to the caller's coordinates; `null` when planar.
    transform: Option<TransformRow>,
    /// Arc length from the first to the last control point.
    arc_length: f64,
    /// Were the points coplanar (the planar segment drawn instead)?
    planar: bool,
    /// Samples equally spaced in arc length, first and last at the end points.
    samples: Vec<SampleRow>,
    /// The planar segment drawn for coplanar points.
    #[serde(skip_serializing_if = "Option::is_none")]
    planar_segment: Option<PlanarRow>,
    /// Why the result is planar.
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<&'static str>,
}

/// The standard form (seed 003 §3) with the Λ and ν the solver found, and its arc length.
#[derive(Debug, Serialize)]
struct FormRow {
    alpha: f64,
    beta: f64,
    lambda: f64,
    omega: f64,
    nu: f64,
    #[serde(rename = "type")]
    kind: u8,
    /// The standard-form arc length of the segment.
    s_end: f64,
}

/// `caller = translation + scale · rotation · M · standard`, M = diag(1, 1, −1) if
/// `mirror_z`; `reversed`: the standard form runs from the last point to the first.
#[derive(Debug, Serialize)]
struct TransformRow {
    scale: f64,
    /// Row-major.
    rotation: [[f64; 3]; 3],
    translation: [f64; 3],
    mirror_z: bool,
    reversed: bool,
}

/// One sample; with `--frames` also the unit tangent, normal and binormal.
#[derive(Debug, Serialize)]
struct SampleRow {
    s: f64,
    x: f64,
    y: f64,
    z: f64,
    /// Curvature, ≥ 0.
    kappa: f64,
    /// Torsion, negative for a left-handed (mirrored) segment.
    tau: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    t: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    n: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    b: Option<[f64; 3]>,
}

impl SampleRow {
    fn new(f: &Frame, frames: bool) -> Self {
        let Vec3 { x, y, z } = f.point;
        SampleRow {
            s: f.s,
            x,
            y,
            z,
            kappa: f.curvature,
            tau: f.torsion,
            t: frames.then_some(f.tangent.to_array()),
            n: frames.then_some(f.normal.to_array()),
            b: frames.then_some(f.binormal.to_array()),
        }
    }
}

/// The planar segment of coplanar points, its control points in the caller's coordinates.
#[derive(Debug, Serialize)]
struct PlanarRow {
    alpha: f64,
    lambda: f64,
    /// The first point, the tangents' intersection and the last point.
    control_points: [[f64; 3]; 3],
}

/// Run `lac space`.
///
/// The whole result is computed before the output file is created, so a failed run leaves
/// an existing file untouched.
pub(crate) fn run(args: &SpaceArgs) -> Result<(), Failure> {
    if args.frames && args.format != SpaceFormat::Json {
        return Err(Failure::usage(
            "--frames adds the Frenet frames to the JSON samples; use it with --format json",
        ));
    }
    let points = parse_space_points(&args.points)?;
    let shape = SpaceShape {
        alpha: args.alpha,
        beta: args.beta,
        omega: args.omega,
        torsion: TorsionType::from_number(args.torsion_type)?,
    };
    let segment = SpaceSegment::from_control_points(points, shape)?;
    let samples = args.samples as usize;
    let document = match args.format {
        SpaceFormat::Json => to_json_line(&segment, samples, args.frames)? + "\n",
        SpaceFormat::Svg => svg::space::render(&segment)?,
        SpaceFormat::Obj => mesh::obj(&segment.sample(samples)?, &header(&segment, samples)),
        SpaceFormat::Ply => mesh::ply(&segment.sample(samples)?, &header(&segment, samples)),
    };
    write_to(args.file.as_deref(), |out| {
        out.write_all(document.as_bytes())
    })
}

fn to_json_line(segment: &SpaceSegment, samples: usize, frames: bool) -> Result<String, Failure> {
    let report = SpaceReport {
        standard_form: segment.standard_form().map(|form| FormRow {
            alpha: form.alpha(),
            beta: form.beta(),
            lambda: form.lambda(),
            omega: form.omega(),
            nu: form.nu(),
            kind: form.torsion_type().number(),
            s_end: segment.s_end().unwrap_or(f64::NAN),
        }),
        transform: segment.transform().map(|t| TransformRow {
            scale: t.scale,
            rotation: t.rotation,
            translation: t.translation.to_array(),
            mirror_z: t.mirror_z,
            reversed: t.reversed,
        }),
        arc_length: segment.arc_length(),
        planar: segment.is_planar(),
        samples: segment
            .sample(samples)?
            .iter()
            .map(|f| SampleRow::new(f, frames))
            .collect(),
        planar_segment: planar_control_points(segment).map(|control_points| {
            let planar = segment
                .planar()
                .expect("planar control points of a planar segment");
            PlanarRow {
                alpha: planar.alpha(),
                lambda: planar.lambda(),
                control_points: control_points.map(Vec3::to_array),
            }
        }),
        note: segment.is_planar().then_some(PLANAR_NOTE),
    };
    Ok(serde_json::to_string(&report).expect("a report of numbers always serializes"))
}

/// The control points of the planar segment drawn for coplanar points, in the caller's
/// coordinates: the planar segment lives in the plane with origin P0, x along P1 − P0 and y
/// toward the chord ([`SpaceSegment::planar`]). `None` when the segment is not planar.
pub(crate) fn planar_control_points(segment: &SpaceSegment) -> Option<[Vec3; 3]> {
    let planar = segment.planar()?;
    let [p0, p1, _, p3] = segment.control_points();
    // Divided by the length rather than `Vec3::normalize`d (a product with its reciprocal),
    // so that the printed digits stay those the command has always printed.
    let unit = |v: Vec3| v / v.length();
    let e1 = unit(p1 - p0);
    let chord = p3 - p0;
    let e2 = unit(chord - chord.dot(e1) * e1);
    Some(planar.control_points().map(|q| p0 + q.x * e1 + q.y * e2))
}

/// The comment lines of OBJ and PLY files: what was solved and how to read the numbers.
fn header(segment: &SpaceSegment, samples: usize) -> Vec<String> {
    let points: Vec<String> = segment
        .control_points()
        .iter()
        .map(|Vec3 { x, y, z }| format!("{x:?},{y:?},{z:?}"))
        .collect();
    let mut lines = vec![
        format!(
            "lac space: log-aesthetic space curve segment, alpha {:?}, beta {:?}, omega {:?}, \
             type {}",
            segment.alpha(),
            segment.beta(),
            segment.omega(),
            segment.torsion_type().number()
        ),
        format!("control points {}", points.join(" ")),
    ];
    match (
        segment.standard_form(),
        segment.transform(),
        segment.s_end(),
    ) {
        (Some(form), Some(t), Some(s_end)) => lines.push(format!(
            "standard form lambda {:?}, nu {:?}, s_end {:?}; scale {:?}, mirror_z {}, \
             reversed {}",
            form.lambda(),
            form.nu(),
            s_end,
            t.scale,
            t.mirror_z,
            t.reversed
        )),
        _ => lines.push(PLANAR_NOTE.to_string()),
    }
    lines.push(format!(
        "arc length {:?}; {samples} samples equally spaced in arc length from the first point",
        segment.arc_length()
    ));
    lines
}
