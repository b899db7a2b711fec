//! `lac space`: a log-aesthetic space curve segment (seed 003, docs/math.md §6) from four 3-D control
//! points, α, β, Ω and the torsion type, as JSON, CSV, SVG, OBJ or PLY; or many with
//! `--batch`.

use std::sync::Arc;

use lac::SpaceCurve;
use lac::{SpaceSegment, Vec3};
use lac_io::json::{parse, to_line, write_line, ErrorBody, SpaceInput, SpaceReport, PLANAR_NOTE};

use crate::batch;
use crate::cli::{SpaceArgs, SpaceFormat};
use crate::errors;
use crate::limits::Limits;
use crate::mesh;
use crate::output::write_document;
use crate::points::parse_space_points;
use crate::svg;

/// Run `lac space`.
///
/// With `--points` the whole result is computed before the output file is created, so a
/// failed run leaves an existing file untouched; `--batch` streams its lines.
pub(crate) fn run(args: &SpaceArgs, limits: Limits) -> Result<(), ErrorBody> {
    if args.frames && !matches!(args.format, SpaceFormat::Json | SpaceFormat::Csv) {
        return Err(errors::usage(
            "--frames adds the Frenet frames to the samples; use it with --format json or csv",
        ));
    }
    let samples = limits.samples(args.samples as usize, "--samples")?;
    let frames = args.frames;
    if let Some(input) = &args.batch {
        if args.format != SpaceFormat::Json {
            return Err(errors::usage(
                "--batch writes JSON lines; --format csv, svg, obj and ply need --points",
            ));
        }
        let solve: batch::Solve = Arc::new(move |text, out| solve_line(text, samples, frames, out));
        // A sample with its frame holds about three times the numbers.
        let chunk = batch::chunk_lines(samples * if frames { 3 } else { 1 });
        return batch::run(input, args.file.as_deref(), limits, chunk, solve);
    }
    let (Some(text), Some(alpha), Some(beta)) = (&args.points, args.alpha, args.beta) else {
        return Err(errors::usage(
            "give --points, --alpha and --beta, or --batch FILE",
        ));
    };
    let input = SpaceInput {
        points: parse_space_points(text)?,
        alpha,
        beta,
        omega: args.omega,
        torsion_type: args.torsion_type,
    };
    let segment = input.solve()?;
    let document = match args.format {
        SpaceFormat::Json => to_line(&SpaceReport::new(&segment, samples, frames)?) + "\n",
        SpaceFormat::Csv => SpaceReport::new(&segment, samples, frames)?.to_csv(),
        SpaceFormat::Svg => svg::space::render(&segment)?,
        SpaceFormat::Obj => mesh::obj(
            &segment.sample_by_arc_length(samples)?,
            &header(&segment, samples),
        ),
        SpaceFormat::Ply => mesh::ply(
            &segment.sample_by_arc_length(samples)?,
            &header(&segment, samples),
        ),
    };
    write_document(args.file.as_deref(), document.as_bytes())
}

/// The output line for one `--batch` line: the report, or why there is none.
fn solve_line(
    text: &str,
    samples: usize,
    frames: bool,
    out: &mut Vec<u8>,
) -> Result<(), ErrorBody> {
    let input: SpaceInput = parse(text, SpaceInput::SHAPE)?;
    let report = SpaceReport::new(&input.solve()?, samples, frames)?;
    write_line(&report, out);
    Ok(())
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
