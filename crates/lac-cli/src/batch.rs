//! `--batch` of every solving subcommand: one JSON input per line in, one JSON line per
//! input line out, in input order.
//!
//! A reader thread reads the input in chunks of whole lines into one buffer per chunk (no
//! allocation per line) and hands them over through a channel of two chunks; a solving
//! thread solves each chunk on rayon's pool, in slices of a few lines whose answers are
//! written straight into one output buffer per slice (sized from the answers so far), and
//! hands the slices over (waiting until they are taken); this thread writes them in input
//! order, while the next chunk is being solved. A chunk ends at [`chunk_lines`] lines, at
//! [`CHUNK_BYTES`] bytes, or as soon as no more input is waiting (so answers stream out as
//! the lines come in, one by one if they come slowly), and the output is flushed whenever
//! no answers are waiting: at most six chunks are in flight, so memory stays bounded
//! however long the input. A line longer than the limit is not kept: it is skipped to its
//! end and answered with a `limit` error.
//!
//! A line that fails (bad JSON, a blank line, a curve that does not exist, even a defect that
//! panics) gives `{"error":{"kind":…,"message":"line N: …"}}` in its place, so the output can
//! be zipped with the input. When any line failed, the batch ends with a one-line summary on
//! standard error and the exit code of the first failed line.

use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Read, Write};
use std::ops::Range;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{self, TryRecvError};
use std::sync::Arc;

use lac_io::json::ErrorBody;
use rayon::prelude::*;

use crate::errors;
use crate::limits::{mebibytes, Limits};
use crate::output::{carried, is_stdout};

/// What solves one line: its text (without the line ending) to the answer's JSON, appended
/// to the buffer without a newline. On `Err` whatever it appended is discarded.
pub(crate) type Solve = Arc<SolveFn>;

/// The function behind a [`Solve`].
pub(crate) type SolveFn = dyn Fn(&str, &mut Vec<u8>) -> Result<(), ErrorBody> + Send + Sync;

/// The answers to a few consecutive lines.
struct Slice {
    /// One line of output per input line.
    bytes: Vec<u8>,
    /// How many lines.
    lines: usize,
    /// The errors among them, in order.
    failed: Vec<ErrorBody>,
}

/// A [`Solve`] from a function that makes the answer line as a `String` (for the
/// subcommands whose lines take far longer to solve than to copy).
pub(crate) fn from_lines<F>(solve: F) -> Solve
where
    F: Fn(&str) -> Result<String, ErrorBody> + Send + Sync + 'static,
{
    Arc::new(move |text, out| {
        out.extend_from_slice(solve(text)?.as_bytes());
        Ok(())
    })
}

/// Most lines in one chunk.
const MAX_CHUNK_LINES: usize = 4096;
/// A chunk ends once its lines hold this many bytes.
const CHUNK_BYTES: usize = 1 << 22;
/// Lines solved one after the other by one task, into one output buffer.
const SLICE_LINES: usize = 16;
/// The work (in samples, or comparable units) the lines of a chunk may hold together.
const WORK_IN_FLIGHT: usize = 2_000_000;

/// How many lines a chunk may hold when each costs about `cost` (its samples): enough to
/// keep every core busy, few enough that together they stay within [`WORK_IN_FLIGHT`] (at
/// 1,000,000 samples a line, two lines: about 350 MB).
pub(crate) fn chunk_lines(cost: usize) -> usize {
    (WORK_IN_FLIGHT / cost.max(1)).clamp(2, MAX_CHUNK_LINES)
}

/// Solve every line of `input` ("-": standard input) with `solve`, in chunks of at most
/// `chunk` lines, and write one line per input line to `output` (a file, or standard output
/// for `None` or "-").
///
/// Returns `Err` when the input or output fails (after writing every answer before the
/// failure), and when a line failed: then the error is the summary, with the first failed
/// line's kind (so its exit code).
pub(crate) fn run(
    input: &Path,
    output: Option<&Path>,
    limits: Limits,
    chunk: usize,
    solve: Solve,
) -> Result<(), ErrorBody> {
    let reader = open(input)?;
    let mut out: Box<dyn Write> = match output.filter(|_| !is_stdout(output)) {
        Some(path) => Box::new(BufWriter::with_capacity(
            1 << 16,
            File::create(path).map_err(|e| errors::io("create", Some(path), &e))?,
        )),
        None => Box::new(BufWriter::with_capacity(1 << 16, io::stdout().lock())),
    };
    let write_error = |e: io::Error| match output.filter(|_| !is_stdout(output)) {
        Some(path) => errors::io("write", Some(path), &e),
        None => errors::io("write standard output", None, &e),
    };
    let mut tally = Tally::default();
    match stream(reader, &mut *out, limits.line(), chunk, solve, &mut tally) {
        Ok(()) => {}
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe && is_stdout(output) => return Ok(()),
        Err(e) => {
            let _ = out.flush();
            return Err(carried(e).unwrap_or_else(write_error));
        }
    }
    match out.flush() {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe && is_stdout(output) => return Ok(()),
        Err(e) => return Err(write_error(e)),
        Ok(()) => {}
    }
    tally.summary()
}

/// The input, buffered (its buffer tells whether more input is already waiting).
type Input = BufReader<Box<dyn Read + Send>>;

/// Open `input` for reading, "-" meaning standard input.
fn open(input: &Path) -> Result<Input, ErrorBody> {
    let read: Box<dyn Read + Send> = if input.as_os_str() == "-" {
        Box::new(io::stdin())
    } else {
        Box::new(File::open(input).map_err(|e| errors::io("read", Some(input), &e))?)
    };
    Ok(BufReader::with_capacity(1 << 16, read))
}

/// Lines read together: their bytes one after the other.
#[derive(Default)]
struct Chunk {
    /// Index (from 0) of the chunk's first line in the input.
    first: usize,
    data: Vec<u8>,
    lines: Vec<Line>,
}

/// What the reader thread hands over.
enum Message {
    Lines(Chunk),
    /// Reading failed (after the lines sent before).
    ReadFailed(io::Error),
}

/// How the lines went.
#[derive(Default)]
struct Tally {
    lines: usize,
    failed: usize,
    first: Option<ErrorBody>,
}

impl Tally {
    fn record(&mut self, lines: usize, errors: Vec<ErrorBody>) {
        self.lines += lines;
        self.failed += errors.len();
        if self.first.is_none() {
            self.first = errors.into_iter().next();
        }
    }

    /// `Ok` when every line was answered, else the summary line.
    fn summary(self) -> Result<(), ErrorBody> {
        let Some(first) = self.first else {
            return Ok(());
        };
        let plural = if self.lines == 1 { "" } else { "s" };
        Err(ErrorBody::new(
            first.kind,
            format!(
                "{} of {} line{plural} failed (each has an {{\"error\":…}} line in the output); \
                 the first, {}",
                self.failed, self.lines, first.message
            ),
        ))
    }
}

/// The reader thread, the solving thread with its pool, and the ordered writing on this
/// thread; see the module documentation.
fn stream(
    reader: Input,
    out: &mut dyn Write,
    max_line: usize,
    chunk: usize,
    solve: Solve,
    tally: &mut Tally,
) -> io::Result<()> {
    let chunk = chunk.max(1);
    let (chunks, inbox) = mpsc::sync_channel::<Message>(2);
    let (answers, outbox) = mpsc::sync_channel::<Answered>(0);
    // Both detached: if the writer stops early (a closed pipe), the process ends without
    // waiting for a reader blocked on its input.
    std::thread::spawn(move || read_chunks(reader, max_line, chunk, chunks));
    // Solving the next chunk while this thread writes the last one keeps the cores busy.
    std::thread::spawn(move || solve_chunks(&inbox, max_line, &*solve, &answers));
    loop {
        let answered = match outbox.try_recv() {
            Ok(answered) => answered,
            Err(TryRecvError::Empty) => {
                // Nothing more to write for now: let the reader of our output see it.
                out.flush()?;
                match outbox.recv() {
                    Ok(answered) => answered,
                    Err(_) => return Ok(()), // the input has ended
                }
            }
            Err(TryRecvError::Disconnected) => return Ok(()),
        };
        match answered {
            Answered::Slices(solved) => {
                for slice in solved {
                    out.write_all(&slice.bytes)?;
                    tally.record(slice.lines, slice.failed);
                }
            }
            Answered::ReadFailed(e) => {
                let body = errors::io("read the batch input", None, &e);
                return Err(io::Error::other(body));
            }
        }
    }
}

/// What the solving thread hands over.
enum Answered {
    /// A chunk's answers, in order.
    Slices(Vec<Slice>),
    /// Reading failed (after the chunks answered before).
    ReadFailed(io::Error),
}

/// Solve each chunk from `inbox` on rayon's pool and send its answers, until the input
/// ends or the writer stops.
fn solve_chunks(
    inbox: &mpsc::Receiver<Message>,
    max_line: usize,
    solve: &SolveFn,
    answers: &mpsc::SyncSender<Answered>,
) {
    let line_bytes = LineBytes::default();
    while let Ok(message) = inbox.recv() {
        let answered = match message {
            Message::Lines(chunk) => {
                Answered::Slices(solve_chunk(&chunk, max_line, solve, &line_bytes))
            }
            Message::ReadFailed(e) => Answered::ReadFailed(e),
        };
        if answers.send(answered).is_err() {
            return; // the writer has stopped
        }
    }
}

/// Read chunks of lines and send them; a chunk ends early when no more input is waiting.
fn read_chunks(
    mut reader: Input,
    max_line: usize,
    chunk_lines: usize,
    chunks: mpsc::SyncSender<Message>,
) {
    let mut index = 0;
    loop {
        let mut chunk = Chunk {
            first: index,
            ..Chunk::default()
        };
        let mut ended = false;
        while chunk.lines.len() < chunk_lines && chunk.data.len() < CHUNK_BYTES {
            match read_line(&mut reader, max_line, &mut chunk.data) {
                Ok(Some(line)) => chunk.lines.push(line),
                Ok(None) => {
                    ended = true;
                    break;
                }
                Err(e) => {
                    if !chunk.lines.is_empty() {
                        let _ = chunks.send(Message::Lines(chunk));
                    }
                    let _ = chunks.send(Message::ReadFailed(e));
                    return;
                }
            }
            if reader.buffer().is_empty() {
                break; // answer what has come before waiting for more
            }
        }
        index += chunk.lines.len();
        if !chunk.lines.is_empty() && chunks.send(Message::Lines(chunk)).is_err() {
            return; // the writer has stopped
        }
        if ended {
            return;
        }
    }
}

/// How long the answer lines have been, so that each slice's buffer is made large enough
/// at once (growing it by doubling copied each answer about twice).
struct LineBytes(AtomicUsize);

impl Default for LineBytes {
    fn default() -> Self {
        LineBytes(AtomicUsize::new(256))
    }
}

impl LineBytes {
    /// Room for `lines` answers like the longest seen so far (up to 64 KiB a line).
    fn room(&self, lines: usize) -> usize {
        self.0.load(Ordering::Relaxed).min(1 << 16) * lines
    }

    fn saw(&self, slice: &Slice) {
        let per_line = slice.bytes.len() / slice.lines.max(1) + 16;
        self.0.fetch_max(per_line, Ordering::Relaxed);
    }
}

/// The answers to a chunk's lines, in slices of consecutive lines, in order.
fn solve_chunk(
    chunk: &Chunk,
    max_line: usize,
    solve: &SolveFn,
    line_bytes: &LineBytes,
) -> Vec<Slice> {
    // Slices small enough that every thread gets several, for balance.
    let threads = rayon::current_num_threads().max(1);
    let slice = (chunk.lines.len() / (4 * threads)).clamp(1, SLICE_LINES);
    let slices: Vec<(usize, &[Line])> = chunk
        .lines
        .chunks(slice)
        .enumerate()
        .map(|(i, lines)| (chunk.first + i * slice, lines))
        .collect();
    slices
        .into_par_iter()
        .map(|(first, lines)| {
            let mut out = Vec::with_capacity(line_bytes.room(lines.len()));
            let mut failed = Vec::new();
            for (k, line) in lines.iter().enumerate() {
                if let Err(err) =
                    answer(first + k + 1, line, &chunk.data, max_line, solve, &mut out)
                {
                    out.extend_from_slice(err.to_json_line().as_bytes());
                    failed.push(err);
                }
                out.push(b'\n');
            }
            let slice = Slice {
                bytes: out,
                lines: lines.len(),
                failed,
            };
            line_bytes.saw(&slice);
            slice
        })
        .collect()
}

/// One input line: where its bytes are in the chunk (without the line ending), or its
/// length when it is longer than the limit (its bytes are skipped).
#[derive(Clone, Debug, PartialEq)]
enum Line {
    Text(Range<usize>),
    TooLong(usize),
}

/// The next line, without its line ending (`\n` or `\r\n`), appended to `data`; `None` at
/// the end of the input.
fn read_line(
    reader: &mut dyn BufRead,
    max_line: usize,
    data: &mut Vec<u8>,
) -> io::Result<Option<Line>> {
    let start = data.len();
    let mut length = 0;
    let mut last = None;
    let mut any = false;
    loop {
        let buffer = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if buffer.is_empty() {
            break;
        }
        any = true;
        let (piece, done) = match memchr::memchr(b'\n', buffer) {
            Some(i) => (&buffer[..i], Some(i + 1)),
            None => (buffer, None),
        };
        length += piece.len();
        last = piece.last().copied().or(last);
        if length <= max_line + 1 {
            data.extend_from_slice(piece);
        }
        let used = done.unwrap_or(buffer.len());
        reader.consume(used);
        if done.is_some() {
            break;
        }
    }
    if !any {
        return Ok(None);
    }
    if last == Some(b'\r') {
        length -= 1;
    }
    if length > max_line {
        data.truncate(start);
        return Ok(Some(Line::TooLong(length)));
    }
    data.truncate(start + length);
    Ok(Some(Line::Text(start..start + length)))
}

/// The answer to line `number` (from 1), appended to `out`: what `solve` made of it, or
/// (with nothing appended) why there is none, with the line number at the head of the
/// message. A panic is caught and answered as kind "internal" for this line, so one bad
/// line cannot lose the rest of the batch.
fn answer(
    number: usize,
    line: &Line,
    data: &[u8],
    max_line: usize,
    solve: &SolveFn,
    out: &mut Vec<u8>,
) -> Result<(), ErrorBody> {
    let mark = out.len();
    let solved = errors::catching(|| {
        errors::debug_panic_at_line(number);
        match line {
            Line::TooLong(length) => Err(ErrorBody::limit(format!(
                "the line has {length} bytes, over the limit of {} a line (--allow-large \
                 raises it)",
                mebibytes(max_line)
            ))),
            Line::Text(range) => std::str::from_utf8(&data[range.clone()])
                .map_err(|_| ErrorBody::invalid_input("the line is not valid UTF-8"))
                .and_then(|text| solve(text, &mut *out)),
        }
    });
    let err = match solved {
        Ok(Ok(())) => return Ok(()),
        Ok(Err(err)) => err,
        Err(_) => ErrorBody::new(
            "internal",
            "lac panicked on this line; this is a defect of lac, please report it with the line",
        ),
    };
    out.truncate(mark);
    // serde_json counts lines within the line; the file's line number is what helps.
    let message = err.message.replace(" at line 1 column ", " at column ");
    Err(ErrorBody {
        message: format!("line {number}: {message}"),
        ..err
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(mut input: &[u8], max: usize) -> Vec<String> {
        let mut out = Vec::new();
        let mut data = Vec::new();
        while let Some(line) = read_line(&mut input, max, &mut data).unwrap() {
            out.push(match line {
                Line::Text(r) => String::from_utf8(data[r].to_vec()).unwrap(),
                Line::TooLong(n) => format!("<{n}>"),
            });
        }
        out
    }

    #[test]
    fn line_endings_are_stripped_every_line_is_kept_and_long_ones_are_measured() {
        assert_eq!(lines(b"a\r\n\nb", 10), ["a", "", "b"]);
        assert_eq!(lines(b"", 10), Vec::<String>::new());
        assert_eq!(lines(b"\n", 10), [""]);
        assert_eq!(
            lines(b"0123456789\n01234567890\r\nx", 10),
            ["0123456789", "<11>", "x"]
        );
        assert_eq!(lines(b"0123456789\r\nab\r", 10), ["0123456789", "ab"]);
    }

    #[test]
    fn answers_carry_the_line_number_and_a_panic_stays_in_its_line() {
        let solve = |text: &str, out: &mut Vec<u8>| -> Result<(), ErrorBody> {
            out.extend_from_slice(b"partial");
            match text {
                "boom" => panic!("boom"),
                "bad" => Err(ErrorBody::invalid_input(
                    "expected value at line 1 column 1",
                )),
                _ => {
                    out.extend_from_slice(text.as_bytes());
                    Ok(())
                }
            }
        };
        let text = |s: &str| (Line::Text(0..s.len()), s.as_bytes().to_vec());
        let mut out = b"before ".to_vec();
        let (line, data) = text("fine");
        answer(3, &line, &data, 10, &solve, &mut out).unwrap();
        assert_eq!(out, b"before partialfine");
        let mut out = Vec::new();
        let (line, data) = text("bad");
        let bad = answer(17, &line, &data, 10, &solve, &mut out).unwrap_err();
        assert_eq!(bad.message, "line 17: expected value at column 1");
        assert!(
            out.is_empty(),
            "a failed line's partial answer is discarded"
        );
        let long = answer(2, &Line::TooLong(99), &[], 10, &solve, &mut out).unwrap_err();
        assert_eq!(long.kind, "limit");
        assert!(long.message.starts_with("line 2: the line has 99 bytes"));
        let (line, data) = text("boom");
        let boom = answer(5, &line, &data, 10, &solve, &mut out).unwrap_err();
        assert_eq!(boom.kind, "internal");
        assert!(boom.message.starts_with("line 5: "));
        assert!(out.is_empty());
    }

    #[test]
    fn chunks_shrink_with_the_work_of_a_line() {
        assert_eq!(chunk_lines(1_000_000), 2);
        assert_eq!(chunk_lines(2), MAX_CHUNK_LINES);
        assert!(chunk_lines(65) >= 16);
    }
}
