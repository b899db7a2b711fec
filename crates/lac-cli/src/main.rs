//! The `lac` command: log-aesthetic curve segments, compound-rhythm curves, drawable
//! regions, their Bézier replacements, curvature analysis and space curve segments.
//!
//! `lac segment` solves a segment from three control points and α, `lac compound` a
//! compound-rhythm curve (two pieces, slopes α0 and α1) from three points and a turning
//! ratio or from four control points. `lac region` maps the drawable region of seed 000
//! Fig. 9, for segments or compound curves. `lac quasi` replaces either curve by rational or
//! plain cubic Bézier pieces (seed 001), `lac monotone` decides whether the curvature of a
//! rational cubic is monotone, and `lac lcg` plots the curvature and the logarithmic
//! curvature graph of Bézier pieces or of a curve and fits its slope (both graphs of a space
//! curve). `lac path` draws a path of segments from a control polygon, G1 or G2, `lac spline`
//! a G2 spline through points, and `lac space` solves a log-aesthetic space curve segment from
//! four 3-D control points (seed 003); `lac export` writes any of them for CAD. Each
//! subcommand is a module of [`cli`].
//!
//! Every subcommand that prints curves offers `--format json|csv|svg` (and more) and
//! `-o FILE` (`-o -`: standard output); every solving subcommand takes `--batch FILE|-`,
//! JSON lines in and out ([`batch`]). The shapes are [`lac_io::json`]'s, shared with the
//! editor's server and the Python bindings. Failures are one line of JSON on standard error,
//! `{"error":{"kind":…,"message":…}}`, with the exit code of [`ErrorBody::class`]: 2 invalid
//! input, 3 no curve, 1 I/O, 70 a defect (even a panic: [`errors::install_panic_hook`]).

mod batch;
mod cli;
mod errors;
mod input;
mod limits;
mod mesh;
mod output;
mod points;
mod raster;
mod svg;

use std::io::Write;
use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::Parser;
use lac_io::json::ErrorBody;

use cli::Cli;
use limits::Limits;

fn main() -> ExitCode {
    errors::install_panic_hook();
    errors::debug_panic("main");
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
        Err(err) => return fail(&errors::from_clap(&err)),
    };
    let result = cli.command.run(Limits::new(cli.allow_large));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => fail(&err),
    }
}

/// Report `err` on standard error as one line of JSON and return its exit code.
fn fail(err: &ErrorBody) -> ExitCode {
    let _ = writeln!(std::io::stderr(), "{}", err.to_json_line());
    ExitCode::from(errors::exit_code(err))
}
