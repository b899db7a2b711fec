//! `lac monotone`: is the curvature of a (rational) cubic Bézier curve monotone? The
//! library's decision with a proof (seed 001 §5, docs/math.md §5), for one curve given by
//! `--points` and `--weights`, for every piece of a JSON document (what `lac quasi` prints,
//! so `lac quasi … | lac monotone` works), or for each line of a `--batch`.

use std::path::PathBuf;

use clap::Args;
use lac_io::json::{to_line, ErrorBody, MonotoneDocument, MonotoneReport, PieceInput};

use crate::batch;
use crate::errors;
use crate::input::read_document;
use crate::limits::Limits;
use crate::output::write_document;
use crate::points::{parse_point_list, parse_weights};

/// What a line of `--batch` costs, in samples, for sizing the chunks of lines read together.
const LINE_COST: usize = 1_000;

/// What to give when there is nothing to read.
const HINT: &str = "give --points (and --weights), a FILE of JSON, or pipe lac quasi output \
                    into standard input (lac quasi … | lac monotone); '-' reads the terminal";

/// Arguments of `lac monotone`.
#[derive(Debug, Args)]
pub(crate) struct MonotoneArgs {
    /// A JSON document to decide ("-": standard input; nothing: standard input when it is not
    /// a terminal): one piece {"points":[[x,y]×4],"weights":[w0,w1,w2,w3]} (weights
    /// optional), or lac quasi output {"pieces":[…]} for a verdict on every piece; at most 64
    /// MiB (1 GiB with --allow-large)
    #[arg(value_name = "FILE", conflicts_with_all = ["points", "weights", "batch"])]
    pub(crate) input: Option<PathBuf>,

    /// The four control points "x0,y0 x1,y1 x2,y2 x3,y3", separated by spaces and/or
    /// semicolons
    #[arg(long, value_name = "POINTS", allow_hyphen_values = true)]
    pub(crate) points: Option<String>,

    /// The four weights "w0,w1,w2,w3", all positive (default 1,1,1,1: a plain cubic)
    #[arg(long, value_name = "WEIGHTS", requires = "points")]
    pub(crate) weights: Option<String>,

    /// Read one JSON document per line ("-": standard input), a piece or {"pieces":[…]} as
    /// for FILE, and write one JSON line per input line, in order: the verdict(s), or
    /// {"error":…} whose message starts with the line number (see lac segment --help for the
    /// line limit and the exit code)
    #[arg(long, value_name = "FILE|-", conflicts_with_all = ["points", "weights"])]
    pub(crate) batch: Option<PathBuf>,

    /// Write to FILE instead of standard output ("-": standard output)
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub(crate) file: Option<PathBuf>,
}

/// Run `lac monotone`.
pub(crate) fn run(args: &MonotoneArgs, limits: Limits) -> Result<(), ErrorBody> {
    if let Some(input) = &args.batch {
        let solve = batch::from_lines(|text| MonotoneDocument::parse(text)?.report_line());
        let chunk = batch::chunk_lines(LINE_COST);
        return batch::run(input, args.file.as_deref(), limits, chunk, solve);
    }
    let line = match &args.points {
        Some(text) => {
            let points = parse_point_list(text, &[4])?;
            let piece = PieceInput {
                points: [points[0], points[1], points[2], points[3]],
                weights: args.weights.as_deref().map(parse_weights).transpose()?,
            };
            to_line(&MonotoneReport::of(&piece)?)
        }
        None => {
            let text = read_document(args.input.as_deref(), limits.document(), HINT)?;
            if args.input.is_none() && text.trim().is_empty() {
                return Err(errors::usage(format!("nothing on standard input: {HINT}")));
            }
            MonotoneDocument::parse(&text)?.report_line()?
        }
    };
    write_document(args.file.as_deref(), format!("{line}\n").as_bytes())
}
