//! `lac monotone`: is the curvature of a (rational) cubic Bézier curve monotone? The
//! library's decision with a proof (seed 001 §5, docs/math.md §5), for one curve given by
//! `--points` and `--weights`, for every piece of a JSON document (what `lac quasi` prints,
//! so `lac quasi … | lac monotone` works), or for each line of a `--batch`.

use lac_io::json::{to_line, ErrorBody, MonotoneDocument, MonotoneReport, PieceInput};

use crate::batch;
use crate::cli::MonotoneArgs;
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
