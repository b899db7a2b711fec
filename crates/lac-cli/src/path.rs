//! `lac path`: a log-aesthetic path from a control polygon (`--polygon`, `--alpha` or
//! `--alphas`, `--closed`, `--g2` or `--fractions`).

use lac::Curve;
use lac_io::json::{to_line, ErrorBody, PathInput, PathReport, Xy};

use crate::cli::{CurveFormat, PathArgs};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_polygon};
use crate::segment::check_output;
use crate::svg::{self, Extras};

/// Run `lac path`. The whole result is computed before the output file is created.
pub(crate) fn run(args: &PathArgs, limits: Limits) -> Result<(), ErrorBody> {
    let output = &args.output;
    check_output(output, false)?;
    let samples = limits.samples(output.samples as usize, "--samples")?;
    let input = path_input(
        &args.polygon,
        args.alpha,
        args.alphas.as_deref(),
        args.closed,
        args.g2,
        args.fractions.as_deref(),
    )?;
    let path = input.solve()?;
    let document = match output.format {
        CurveFormat::Json => to_line(&PathReport::new(&path, samples)?) + "\n",
        CurveFormat::Csv => PathReport::new(&path, samples)?.to_csv(),
        CurveFormat::Svg => {
            let extras = Extras {
                comb: output
                    .comb
                    .then(|| path.sample_by_arc_length(samples))
                    .transpose()?,
                evolute: output.evolute,
                closed: input.closed,
            };
            let mut polygon = kurbo_points(&input.points);
            if input.closed {
                polygon.push(polygon[0]);
            }
            svg::render(path.segments(), &polygon, extras)?
        }
    };
    write_document(output.file.as_deref(), document.as_bytes())
}

/// The path of the arguments `--polygon`, `--alpha`/`--alphas`, `--closed`, `--g2`,
/// `--fractions` (`lac path`'s, also taken by `lac export`).
pub(crate) fn path_input(
    polygon: &str,
    alpha: Option<f64>,
    alphas: Option<&str>,
    closed: bool,
    g2: bool,
    fractions: Option<&str>,
) -> Result<PathInput, ErrorBody> {
    let points: Vec<Xy> = parse_polygon(polygon, 3, lac::MAX_POLYGON_POINTS)?;
    let alphas = alphas.map(|t| numbers(t, "--alphas")).transpose()?;
    if alpha.is_none() && alphas.is_none() {
        return Err(errors::usage(
            "give --alpha A (every segment) or --alphas \"a1,a2,…\"",
        ));
    }
    if g2 && fractions.is_some() {
        return Err(errors::usage(
            "--fractions place the joints of a G1 path; --g2 solves them: drop one",
        ));
    }
    Ok(PathInput {
        points,
        closed,
        alpha,
        alphas,
        g2,
        fractions: fractions.map(|t| numbers(t, "--fractions")).transpose()?,
    })
}

/// Numbers separated by commas, spaces or semicolons.
fn numbers(text: &str, flag: &str) -> Result<Vec<f64>, ErrorBody> {
    text.split(|c: char| c == ',' || c == ';' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| {
            t.parse::<f64>()
                .map_err(|_| ErrorBody::invalid_input(format!("{flag}: {t:?} is not a number")))
        })
        .collect()
}
