//! `lac space`: a log-aesthetic space curve segment (seed 003, SPEC §6) from four 3-D control
//! points, α, β, Ω and the torsion type, as JSON, SVG, OBJ or PLY.

use lac::{SpaceSegment, SpaceShape, TorsionType, Vec3};
use lac_io::json::{to_line, SpaceReport, PLANAR_NOTE};

use crate::cli::{SpaceArgs, SpaceFormat};
use crate::failure::Failure;
use crate::mesh;
use crate::output::write_to;
use crate::points::parse_space_points;
use crate::svg;

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
    let report =
        SpaceReport::new(segment, samples, frames).map_err(|e| Failure::new(e.kind, e.message))?;
    Ok(to_line(&report))
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
