//! `lac region`: the drawable region of seed 000 Fig. 9 as a PNG or a JSON grid, for
//! segments or (with `--alpha1` and `--ratio`) for compound-rhythm curves.
//!
//! The first control point is (−1, 0), the last (1, 0), and the middle one is the centre of
//! each pixel of [−1, 1]² ([`lac::region::pixel_center`]); row 0 is the top (y = +1).

mod grid;
mod png;

use std::io::{IsTerminal, Write};

use serde::Serialize;

use crate::cli::{RegionArgs, RegionFormat};
use crate::failure::Failure;
use crate::output::write_to;

/// What `lac region --format json` prints.
#[derive(Serialize)]
struct RegionReport<'a> {
    /// α, or α0 for compound curves.
    alpha: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    alpha1: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ratio: Option<f64>,
    size: usize,
    /// [x_min, x_max, y_min, y_max] of the map.
    extent: [f64; 4],
    first: [f64; 2],
    last: [f64; 2],
    drawable_fraction: f64,
    /// Rows top (y = +1) to bottom, columns left (x = −1) to right.
    drawable: &'a [Vec<bool>],
}

/// Run `lac region`.
pub(crate) fn run(args: &RegionArgs) -> Result<(), Failure> {
    let compound = args.alpha1.zip(args.ratio);
    check(args.alpha, compound)?;
    let to_terminal = args.output.is_none() && std::io::stdout().is_terminal();
    if args.format == RegionFormat::Png && to_terminal {
        return Err(Failure::usage(
            "a PNG is not written to a terminal: give -o FILE, redirect standard output, or use \
             --format json",
        ));
    }
    let size = args.size as usize;
    let alpha = args.alpha;
    let rows = match compound {
        None => grid::drawable_rows(size, |row| lac::region::row(alpha, size, row)),
        Some((alpha1, ratio)) => grid::drawable_rows(size, |row| {
            lac::region::compound_row(alpha, alpha1, ratio, size, row)
        }),
    };
    write_to(args.output.as_deref(), |out| match args.format {
        RegionFormat::Png => png::write_png(&rows, out),
        RegionFormat::Json => write_json(args, &rows, out),
    })
}

/// Reject parameters for which every pixel would be "not drawable" for the wrong reason.
///
/// The library checks them per curve and the region functions only say "no"; an explicit
/// error here says which one is wrong.
fn check(alpha: f64, compound: Option<(f64, f64)>) -> Result<(), Failure> {
    let finite = |what: &'static str, value: f64| {
        if value.is_finite() {
            Ok(())
        } else {
            Err(lac::Error::NonFinite { what, value })
        }
    };
    let Some((alpha1, ratio)) = compound else {
        return Ok(finite("alpha", alpha)?);
    };
    finite("alpha0", alpha)?;
    finite("alpha1", alpha1)?;
    finite("ratio", ratio)?;
    if !(ratio > 0.0 && ratio < 1.0) {
        return Err(lac::Error::OutOfRange {
            name: "ratio",
            value: ratio,
            expected: "a share of the turning strictly between 0 and 1",
        }
        .into());
    }
    Ok(())
}

fn write_json(args: &RegionArgs, rows: &[Vec<bool>], out: &mut dyn Write) -> std::io::Result<()> {
    let (first, last) = (lac::region::FIRST, lac::region::LAST);
    let report = RegionReport {
        alpha: args.alpha,
        alpha1: args.alpha1,
        ratio: args.ratio,
        size: rows.len(),
        extent: [-1.0, 1.0, -1.0, 1.0],
        first: [first.x, first.y],
        last: [last.x, last.y],
        drawable_fraction: grid::fraction(rows),
        drawable: rows,
    };
    serde_json::to_writer(&mut *out, &report)?;
    writeln!(out)
}
