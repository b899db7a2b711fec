//! `lac path`: a log-aesthetic path from a control polygon (`--polygon`, `--alpha` or
//! `--alphas`, `--closed`, `--g2` or `--fractions`).
//!
//! The path in `lac export`: [`PathExport`], its flags there, and its results and inputs as
//! documents.

use clap::Args;
use lac::Curve;
use lac_io::json::{to_line, AnyCurve, ErrorBody, PathInput, PathReport, Xy};

use crate::cli::export::{names, present, ExportSource, Flag, Input};
use crate::cli::segment::check_output;
use crate::cli::{CurveFlags, CurveFormat, CurveOutput};
use crate::errors;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{kurbo_points, parse_polygon};
use crate::svg::{self, Extras};

/// Arguments of `lac path`.
#[derive(Debug, Args)]
pub(crate) struct PathArgs {
    /// The control polygon "x0,y0 x1,y1 …" (at least three points), separated by spaces
    /// and/or semicolons
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) polygon: String,

    /// The slope of every segment
    #[arg(
        long,
        value_name = "A",
        allow_hyphen_values = true,
        conflicts_with = "alphas"
    )]
    pub(crate) alpha: Option<f64>,

    /// One slope per segment "a1,a2,…" (per interior vertex; per vertex when closed)
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub(crate) alphas: Option<String>,

    /// Close the polygon (the last point joins the first): a closed path
    #[arg(long)]
    pub(crate) closed: bool,

    /// Solve the joints for continuous curvature (G2)
    #[arg(long, conflicts_with = "fractions")]
    pub(crate) g2: bool,

    /// G1: the fraction of each joint leg (every leg but the first and last; every leg when
    /// closed) at which its joint lies, "t1,t2,…" in (0, 1); default the midpoints
    #[arg(long, value_name = "LIST")]
    pub(crate) fractions: Option<String>,

    /// What to print and where.
    #[command(flatten)]
    pub(crate) output: CurveOutput,
}

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
            svg::render(
                (&path_title(&path), None),
                path.segments(),
                &polygon,
                extras,
            )?
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

/// A path's own flags in `lac export` (with `--alpha` and `--closed` of [`CurveFlags`]).
#[derive(Debug, Args)]
pub(crate) struct PathExport {
    /// A path: the control polygon "x0,y0 x1,y1 …" (at least three points), with --alpha
    /// or --alphas, and --closed, --g2 or --fractions as lac path takes them
    #[arg(
        long,
        value_name = "POINTS",
        allow_hyphen_values = true,
        conflicts_with_all = ["points", "input"]
    )]
    pub(crate) polygon: Option<String>,

    /// A path: one slope per segment "a1,a2,…"
    #[arg(
        long,
        value_name = "LIST",
        allow_hyphen_values = true,
        requires = "polygon",
        conflicts_with = "alpha"
    )]
    pub(crate) alphas: Option<String>,

    /// A path: solve the joints for continuous curvature (G2)
    #[arg(long, requires = "polygon", conflicts_with = "fractions")]
    pub(crate) g2: bool,

    /// A path (G1): the fraction of each joint leg at which its joint lies "t1,t2,…"
    #[arg(long, value_name = "LIST", requires = "polygon")]
    pub(crate) fractions: Option<String>,
}

impl ExportSource for PathExport {
    /// The flags given, none without `--polygon`: clap refuses `--alphas`, `--g2` and
    /// `--fractions` without it, except beside `--points`, which rules `--polygon` out; they
    /// are ignored there, as they always were.
    fn given(&self) -> Vec<Flag> {
        if self.polygon.is_none() {
            return Vec::new();
        }
        present([
            Flag::other("--polygon", true),
            Flag::slope("--alphas", self.alphas.is_some()),
            Flag::other("--g2", self.g2),
            Flag::other("--fractions", self.fractions.is_some()),
        ])
    }

    /// The path of `--polygon`; other kinds' slopes are refused.
    fn export_input(
        &self,
        curve: &CurveFlags,
        others: &[Flag],
    ) -> Option<Result<Input, ErrorBody>> {
        let polygon = self.polygon.as_deref()?;
        let slopes: Vec<&Flag> = others.iter().filter(|f| f.slope).collect();
        if !slopes.is_empty() {
            return Some(Err(errors::usage(format!(
                "a path takes --alpha or --alphas: drop {}",
                names(slopes)
            ))));
        }
        Some(
            path_input(
                polygon,
                curve.alpha,
                self.alphas.as_deref(),
                curve.closed,
                self.g2,
                self.fractions.as_deref(),
            )
            .and_then(|input| input.solve())
            .map(AnyCurve::Path),
        )
    }

    fn closes(&self) -> bool {
        true
    }
}

/// The drawing's name for `path`: "Log-aesthetic path (G2)", "Closed log-aesthetic path (G1)".
fn path_title(path: &lac::Path) -> String {
    let continuity = match path.continuity() {
        lac::Continuity::G1 => "G1",
        lac::Continuity::G2 => "G2",
    };
    if path.polygon().is_closed() {
        format!("Closed log-aesthetic path ({continuity})")
    } else {
        format!("Log-aesthetic path ({continuity})")
    }
}
