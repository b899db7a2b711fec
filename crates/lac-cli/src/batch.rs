//! `--batch` of every solving subcommand: one JSON input per line in, one JSON line per
//! input line out, in input order.
//!
//! A reader thread reads the lines and hands each to rayon's pool as soon as it is read;
//! this thread writes the answers in input order, each as soon as it and every line before
//! it are done, and flushes whenever it would otherwise wait. At most a window of lines is
//! in flight (read but not yet written): the reader waits for a slot, so memory stays
//! bounded however long the input, and a slow line holds back only the lines after it. A
//! line longer than the limit is not kept: it is skipped to its end and answered with a
//! `limit` error.
//!
//! A line that fails (bad JSON, a blank line, a curve that does not exist, even a defect that
//! panics) gives `{"error":{"kind":…,"message":"line N: …"}}` in its place, so the output can
//! be zipped with the input. When any line failed, the batch ends with a one-line summary on
//! standard error and the exit code of the first failed line.

use std::collections::BTreeMap;
use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::Path;
use std::sync::mpsc::{self, Receiver, SyncSender, TryRecvError};
use std::sync::Arc;

use lac_io::json::ErrorBody;

use crate::errors;
use crate::limits::{mebibytes, Limits};
use crate::output::{carried, is_stdout};

/// What solves one line: its text (without the line ending) to the answer's JSON line.
pub(crate) type Solve = Arc<dyn Fn(&str) -> Result<String, ErrorBody> + Send + Sync>;

/// Lines in flight per pool thread when each line is light.
const LINES_PER_THREAD: usize = 16;
/// The work (in samples, or comparable units) the lines in flight may hold together.
const WORK_IN_FLIGHT: usize = 2_000_000;

/// How many lines may be in flight when each costs about `cost` (its samples): enough to
/// keep every core busy past a slow line, few enough that together they stay within
/// [`WORK_IN_FLIGHT`] (at 1,000,000 samples a line, two lines: about 350 MB).
pub(crate) fn window(cost: usize) -> usize {
    let threads = rayon::current_num_threads().max(1);
    (WORK_IN_FLIGHT / cost.max(1)).clamp(2, LINES_PER_THREAD * threads)
}

/// Solve every line of `input` ("-": standard input) with `solve`, at most `window` lines in
/// flight, and write one line per input line to `output` (a file, or standard output for
/// `None` or "-").
///
/// Returns `Err` when the input or output fails (after writing every answer before the
/// failure), and when a line failed: then the error is the summary, with the first failed
/// line's kind (so its exit code).
pub(crate) fn run(
    input: &Path,
    output: Option<&Path>,
    limits: Limits,
    window: usize,
    solve: Solve,
) -> Result<(), ErrorBody> {
    let reader = open(input)?;
    let mut out: Box<dyn Write> = match output.filter(|_| !is_stdout(output)) {
        Some(path) => Box::new(BufWriter::new(
            File::create(path).map_err(|e| errors::io("create", Some(path), &e))?,
        )),
        None => Box::new(BufWriter::new(io::stdout().lock())),
    };
    let write_error = |e: io::Error| match output.filter(|_| !is_stdout(output)) {
        Some(path) => errors::io("write", Some(path), &e),
        None => errors::io("write standard output", None, &e),
    };
    let mut tally = Tally::default();
    match stream(reader, &mut *out, limits.line(), window, solve, &mut tally) {
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

/// Open `input` for reading, "-" meaning standard input.
fn open(input: &Path) -> Result<Box<dyn BufRead + Send>, ErrorBody> {
    if input.as_os_str() == "-" {
        return Ok(Box::new(BufReader::new(io::stdin())));
    }
    let file = File::open(input).map_err(|e| errors::io("read", Some(input), &e))?;
    Ok(Box::new(BufReader::with_capacity(1 << 16, file)))
}

/// What the reader thread tells the writer.
enum Message {
    /// Line `index` (from 0) is answered.
    Answer(usize, Result<String, ErrorBody>),
    /// The input ended after this many lines.
    End(usize),
    /// Reading failed after this many lines.
    ReadFailed(usize, io::Error),
}

/// How the lines went.
#[derive(Default)]
struct Tally {
    lines: usize,
    failed: usize,
    first: Option<ErrorBody>,
}

impl Tally {
    fn record(&mut self, answer: &Result<String, ErrorBody>) {
        self.lines += 1;
        if let Err(err) = answer {
            self.failed += 1;
            self.first.get_or_insert_with(|| err.clone());
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

/// The reader thread, the pool and the ordered writing; see the module documentation.
fn stream(
    reader: Box<dyn BufRead + Send>,
    out: &mut dyn Write,
    max_line: usize,
    window: usize,
    solve: Solve,
    tally: &mut Tally,
) -> io::Result<()> {
    let window = window.max(1);
    let (answers, inbox) = mpsc::channel::<Message>();
    let (slots, free) = mpsc::sync_channel::<()>(window);
    for _ in 0..window {
        let _ = slots.send(());
    }
    // Detached: if the writer stops early (a closed pipe), the process ends without
    // waiting for a reader blocked on its input.
    std::thread::spawn(move || read_lines(reader, max_line, solve, answers, free));
    write_in_order(out, &inbox, &slots, tally)
}

/// Read lines, each after taking a slot, and hand each to the pool; then say how many.
fn read_lines(
    mut reader: Box<dyn BufRead + Send>,
    max_line: usize,
    solve: Solve,
    answers: mpsc::Sender<Message>,
    free: Receiver<()>,
) {
    let mut index = 0;
    loop {
        if free.recv().is_err() {
            return; // the writer has stopped
        }
        let line = match read_line(&mut *reader, max_line) {
            Ok(Some(line)) => line,
            Ok(None) => {
                let _ = answers.send(Message::End(index));
                return;
            }
            Err(e) => {
                let _ = answers.send(Message::ReadFailed(index, e));
                return;
            }
        };
        let (solve, answers) = (Arc::clone(&solve), answers.clone());
        let i = index;
        rayon::spawn(move || {
            let answer = answer(i + 1, line, max_line, &*solve);
            let _ = answers.send(Message::Answer(i, answer));
        });
        index += 1;
    }
}

/// Write the answers in input order as they come, returning a slot for each line written.
fn write_in_order(
    out: &mut dyn Write,
    inbox: &Receiver<Message>,
    slots: &SyncSender<()>,
    tally: &mut Tally,
) -> io::Result<()> {
    let mut ready: BTreeMap<usize, Result<String, ErrorBody>> = BTreeMap::new();
    let mut next = 0;
    let mut end: Option<(usize, Option<io::Error>)> = None;
    loop {
        while let Some(answer) = ready.remove(&next) {
            match &answer {
                Ok(line) => writeln!(out, "{line}")?,
                Err(err) => writeln!(out, "{}", err.to_json_line())?,
            }
            tally.record(&answer);
            next += 1;
            let _ = slots.try_send(());
        }
        if let Some((lines, failure)) = &mut end {
            if next >= *lines {
                return match failure.take() {
                    Some(e) => Err(e),
                    None => Ok(()),
                };
            }
        }
        let message = match inbox.try_recv() {
            Ok(message) => message,
            Err(TryRecvError::Empty) => {
                // Nothing more to write for now: let the reader of our output see it.
                out.flush()?;
                match inbox.recv() {
                    Ok(message) => message,
                    Err(_) => return Err(io::Error::other("the batch reader stopped")),
                }
            }
            Err(TryRecvError::Disconnected) => {
                return Err(io::Error::other("the batch reader stopped"))
            }
        };
        match message {
            Message::Answer(i, answer) => {
                ready.insert(i, answer);
            }
            Message::End(lines) => end = Some((lines, None)),
            Message::ReadFailed(lines, e) => {
                let body = errors::io("read the batch input", None, &e);
                end = Some((lines, Some(io::Error::other(body))));
            }
        }
    }
}

/// One input line: its bytes without the line ending, or its length when it is longer than
/// the limit (its bytes are skipped).
enum Line {
    Text(Vec<u8>),
    TooLong(usize),
}

/// The next line, without its line ending (`\n` or `\r\n`); `None` at the end of the input.
fn read_line(reader: &mut dyn BufRead, max_line: usize) -> io::Result<Option<Line>> {
    let mut line = Vec::new();
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
        let (chunk, done) = match buffer.iter().position(|&b| b == b'\n') {
            Some(i) => (&buffer[..i], Some(i + 1)),
            None => (buffer, None),
        };
        length += chunk.len();
        last = chunk.last().copied().or(last);
        if length <= max_line + 1 {
            line.extend_from_slice(chunk);
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
        if line.len() > length {
            line.pop();
        }
    }
    Ok(Some(if length > max_line {
        Line::TooLong(length)
    } else {
        Line::Text(line)
    }))
}

/// The answer to line `number` (from 1): what `solve` made of it, or why there is none,
/// with the line number at the head of the message. A panic is caught and answered as
/// kind "internal" for this line, so one bad line cannot lose the rest of the batch.
fn answer(
    number: usize,
    line: Line,
    max_line: usize,
    solve: &(dyn Fn(&str) -> Result<String, ErrorBody> + Send + Sync),
) -> Result<String, ErrorBody> {
    let solved = errors::catching(|| {
        errors::debug_panic(&format!("line {number}"));
        match line {
            Line::TooLong(length) => Err(ErrorBody::limit(format!(
                "the line has {length} bytes, over the limit of {} a line (--allow-large \
                 raises it)",
                mebibytes(max_line)
            ))),
            Line::Text(bytes) => std::str::from_utf8(&bytes)
                .map_err(|_| ErrorBody::invalid_input("the line is not valid UTF-8"))
                .and_then(solve),
        }
    });
    let err = match solved {
        Ok(Ok(report)) => return Ok(report),
        Ok(Err(err)) => err,
        Err(_) => ErrorBody::new(
            "internal",
            "lac panicked on this line; this is a defect of lac, please report it with the line",
        ),
    };
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
        while let Some(line) = read_line(&mut input, max).unwrap() {
            out.push(match line {
                Line::Text(t) => String::from_utf8(t).unwrap(),
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
    }

    #[test]
    fn answers_carry_the_line_number_and_a_panic_stays_in_its_line() {
        let solve = |text: &str| -> Result<String, ErrorBody> {
            match text {
                "boom" => panic!("boom"),
                "bad" => Err(ErrorBody::invalid_input(
                    "expected value at line 1 column 1",
                )),
                _ => Ok(text.to_string()),
            }
        };
        let ok = answer(3, Line::Text(b"fine".to_vec()), 10, &solve);
        assert_eq!(ok.unwrap(), "fine");
        let bad = answer(17, Line::Text(b"bad".to_vec()), 10, &solve).unwrap_err();
        assert_eq!(bad.message, "line 17: expected value at column 1");
        let long = answer(2, Line::TooLong(99), 10, &solve).unwrap_err();
        assert_eq!(long.kind, "limit");
        assert!(long.message.starts_with("line 2: the line has 99 bytes"));
        let boom = answer(5, Line::Text(b"boom".to_vec()), 10, &solve).unwrap_err();
        assert_eq!(boom.kind, "internal");
        assert!(boom.message.starts_with("line 5: "));
    }

    #[test]
    fn the_window_shrinks_with_the_work_of_a_line() {
        assert_eq!(window(1_000_000), 2);
        assert!(window(65) >= 16);
        assert!(window(65) <= LINES_PER_THREAD * rayon::current_num_threads());
    }
}
