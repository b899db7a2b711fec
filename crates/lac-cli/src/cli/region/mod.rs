//! `lac region`: the drawable region of seed 000 Fig. 9 as a PNG or a JSON grid, for
//! segments (`--alpha`) or compound-rhythm curves (`--alpha0`, `--alpha1`, `--ratio`).
//!
//! The first control point is (−1, 0), the last (1, 0), and the middle one is the centre of
//! each pixel of [−1, 1]² ([`lac::region::pixel_center`]); row 0 is the top (y = +1).

mod grid;
mod png;

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use lac_io::json::{ErrorBody, RegionInput};

use crate::errors;
use crate::limits::Limits;
use crate::output::{refuse_binary_on_terminal, write_to};

/// Arguments of `lac region`.
#[derive(Debug, Args)]
pub(crate) struct RegionArgs {
    /// Map segments: the slope of their logarithmic curvature graph
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha: Option<f64>,

    /// Map compound-rhythm curves: the slope of the piece from the first point (give --alpha1
    /// and --ratio too)
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) alpha0: Option<f64>,

    /// Compound curves: the slope of the piece that ends at the last point
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub(crate) alpha1: Option<f64>,

    /// Compound curves: the share of the turning made by the alpha0 piece, strictly between
    /// 0 and 1
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub(crate) ratio: Option<f64>,

    /// Width and height of the map in pixels, 1 to 2048 (8192 with --allow-large; 2048 takes
    /// about 10 s for segments and 30 s for compound curves on two cores, 8192 sixteen times
    /// that); the map covers [-1,1]² with the first point at (-1,0) and the last at (1,0)
    #[arg(
        long,
        value_name = "PIXELS",
        default_value_t = 512,
        value_parser = clap::value_parser!(u32).range(1..)
    )]
    pub(crate) size: u32,

    /// Write to FILE instead of standard output ("-": standard output; a PNG is not written
    /// to a terminal)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = RegionFormat::Png)]
    pub(crate) format: RegionFormat,
}

/// Output formats of `lac region`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum RegionFormat {
    /// 8-bit grayscale: white where drawable, black where not; row 0 is y = +1
    Png,
    /// {"alpha","size","extent","first","last","drawable_fraction","drawable":[[bool…]…]},
    /// with "alpha1" and "ratio" after "alpha" (then alpha0) for compound curves
    Json,
}

/// Run `lac region`.
pub(crate) fn run(args: &RegionArgs, limits: Limits) -> Result<(), ErrorBody> {
    let input = input(args)?;
    input.check()?;
    check_slopes(&input)?;
    let size = limits.size(args.size as usize)?;
    if args.format == RegionFormat::Png {
        refuse_binary_on_terminal(args.file.as_deref(), "PNG", "--format json")?;
    }
    let rows = input.rows(size, |top| {
        grid::drawable_rows(top, |row| input.row(size, row))
    });
    write_to(args.file.as_deref(), |out| match args.format {
        RegionFormat::Png => png::write_png(&rows, out),
        RegionFormat::Json => {
            serde_json::to_writer(&mut *out, &input.report(size, rows))?;
            writeln!(out)
        }
    })
}

/// The map asked for: `--alpha` alone for segments, `--alpha0`, `--alpha1` and `--ratio`
/// for compound curves (as in `lac compound`).
fn input(args: &RegionArgs) -> Result<RegionInput, ErrorBody> {
    let segment = |alpha| RegionInput {
        alpha,
        alpha1: None,
        ratio: None,
        size: Some(args.size as usize),
    };
    match (args.alpha, args.alpha0, args.alpha1, args.ratio) {
        (Some(alpha), None, None, None) => Ok(segment(alpha)),
        (None, Some(alpha0), Some(alpha1), Some(ratio)) => Ok(RegionInput {
            alpha1: Some(alpha1),
            ratio: Some(ratio),
            ..segment(alpha0)
        }),
        (Some(_), None, Some(_), _) => Err(errors::usage(
            "a compound curve's slopes are --alpha0 and --alpha1, as in lac compound: write \
             lac region --alpha0 A --alpha1 B --ratio R (--alpha is a segment's slope)",
        )),
        (Some(_), _, _, _) => Err(errors::usage(
            "--alpha maps segments and takes no --alpha0, --alpha1 or --ratio; for compound \
             curves give --alpha0, --alpha1 and --ratio",
        )),
        (None, None, None, None) => Err(errors::usage(
            "give --alpha A for segments, or --alpha0 A --alpha1 B --ratio R for compound \
             curves",
        )),
        _ => Err(errors::usage(
            "a compound curve's map needs all of --alpha0, --alpha1 and --ratio",
        )),
    }
}

/// Slopes the library takes (|α| ≤ [`lac::MAX_ABS_ALPHA`]): beyond them every pixel would
/// be "not drawable" for a reason the map does not show.
fn check_slopes(input: &RegionInput) -> Result<(), ErrorBody> {
    let named = match input.alpha1 {
        None => vec![("alpha", input.alpha)],
        Some(alpha1) => vec![("alpha0", input.alpha), ("alpha1", alpha1)],
    };
    for (name, value) in named {
        if value.abs() > lac::MAX_ABS_ALPHA {
            return Err(lac::Error::OutOfRange {
                name,
                value,
                expected: "a slope with |alpha| <= 1e6, as every curve takes",
            }
            .into());
        }
    }
    Ok(())
}
