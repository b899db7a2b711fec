//! The `lac` command: log-aesthetic curve segments, compound-rhythm curves, drawable
//! regions and space curve segments.
//!
//! `lac segment` solves a segment from three control points and α, `lac compound` a
//! compound-rhythm curve (two pieces, slopes α0 and α1) from three points and a turning
//! ratio or from four control points; both print samples as JSON, CSV or SVG, one at a time
//! or in batches of JSON lines. `lac region` maps the drawable region of seed 000 Fig. 9,
//! for segments or compound curves. `lac quasi` replaces either curve by rational or plain
//! cubic Bézier pieces (seed 001), `lac monotone` decides whether the curvature of a
//! rational cubic is monotone, and `lac lcg` plots the curvature and the logarithmic
//! curvature graph of Bézier pieces or of a curve and fits its slope. `lac space` solves a
//! log-aesthetic space curve segment from four 3-D control points (seed 003) and prints it
//! as JSON, SVG (three orthographic views and a perspective) or an OBJ/PLY polyline.
//! Failures are one line of JSON on standard error: `{"error":{"kind":…,"message":…}}`,
//! exit code 2 for invalid input, 3 for "not drawable" (and a Bézier fit that fails or
//! misses its tolerance), 1 for I/O. See `lac --help`.

mod batch;
mod cli;
mod compound;
mod curve;
mod failure;
mod lcg;
mod mesh;
mod monotone;
mod output;
mod points;
mod quasi;
mod raster;
mod region;
mod report;
mod segment;
mod serve;
mod space;
mod svg;

use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::Parser;

use cli::{Cli, Command};
use failure::Failure;

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(err)
            if matches!(
                err.kind(),
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion
            ) =>
        {
            let _ = err.print();
            return ExitCode::SUCCESS;
        }
        Err(err) => return fail(&failure::from_clap(&err)),
    };
    let result = match &cli.command {
        Command::Segment(args) => segment::run(args),
        Command::Compound(args) => compound::run(args),
        Command::Region(args) => region::run(args),
        Command::Quasi(args) => quasi::run(args),
        Command::Monotone(args) => monotone::run(args),
        Command::Lcg(args) => lcg::run(args),
        Command::Space(args) => space::run(args),
        Command::Serve(args) => serve::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => fail(&failure),
    }
}

/// Report `failure` on standard error as one line of JSON and return its exit code.
fn fail(failure: &Failure) -> ExitCode {
    eprintln!("{}", failure.to_json_line());
    ExitCode::from(failure.exit_code())
}
