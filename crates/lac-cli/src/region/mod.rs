//! `lac region`: the drawable region of seed 000 Fig. 9 as a PNG or a JSON grid.
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
    alpha: f64,
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
    if !args.alpha.is_finite() {
        return Err(lac::Error::NonFinite {
            what: "alpha",
            value: args.alpha,
        }
        .into());
    }
    let to_terminal = args.output.is_none() && std::io::stdout().is_terminal();
    if args.format == RegionFormat::Png && to_terminal {
        return Err(Failure::usage(
            "a PNG is not written to a terminal: give -o FILE, redirect standard output, or use \
             --format json",
        ));
    }
    let size = args.size as usize;
    let rows = grid::drawable_rows(args.alpha, size);
    write_to(args.output.as_deref(), |out| match args.format {
        RegionFormat::Png => png::write_png(&rows, out),
        RegionFormat::Json => write_json(args.alpha, &rows, out),
    })
}

fn write_json(alpha: f64, rows: &[Vec<bool>], out: &mut dyn Write) -> std::io::Result<()> {
    let (first, last) = (lac::region::FIRST, lac::region::LAST);
    let report = RegionReport {
        alpha,
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
