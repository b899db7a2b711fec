//! `--batch` of `lac segment` and `lac compound`: one JSON object per input line in, one
//! JSON line per input line out.
//!
//! Lines are read in chunks, each chunk is solved in parallel (rayon keeps the order), and
//! the results are written before the next chunk is read, so memory stays bounded and a
//! pipe sees output as it goes. A line that fails (bad JSON, a blank line, a curve that
//! does not exist) gives `{"error":{"kind":…,"message":…}}` in its place, so the output
//! can be zipped with the input.

use std::fs::File;
use std::io::{self, BufRead, BufReader, Write};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

use rayon::prelude::*;
use serde::de::DeserializeOwned;

use crate::failure::Failure;

/// Lines solved in parallel before their results are written.
const CHUNK: usize = 1024;

/// Solve every line of `reader` (opened from `input`) with `solve` and write one line per
/// input line to `out`: what `solve` returned, or its failure as `{"error":…}`.
///
/// `solve` gets the line's text (possibly blank; see [`parse_job`]). Fails only when the
/// input cannot be read or the output cannot be written; a read error comes back as an
/// [`io::Error`] that carries its [`Failure`] (see [`crate::output`]).
pub(crate) fn run<F>(
    mut reader: Box<dyn BufRead>,
    input: &Path,
    out: &mut dyn Write,
    solve: F,
) -> io::Result<()>
where
    F: Fn(&str) -> Result<String, Failure> + Sync,
{
    let read_error = |e: io::Error| io::Error::other(Failure::io("read", Some(input), &e));
    loop {
        let lines = read_chunk(&mut *reader).map_err(read_error)?;
        if lines.is_empty() {
            return Ok(());
        }
        let results: Vec<String> = lines.par_iter().map(|l| solve_line(l, &solve)).collect();
        for line in &results {
            writeln!(out, "{line}")?;
        }
    }
}

/// Open `input` for reading, "-" meaning standard input.
pub(crate) fn open(input: &Path) -> Result<Box<dyn BufRead>, Failure> {
    if input.as_os_str() == "-" {
        return Ok(Box::new(io::stdin().lock()));
    }
    let file = File::open(input).map_err(|e| Failure::io("read", Some(input), &e))?;
    Ok(Box::new(BufReader::with_capacity(1 << 16, file)))
}

/// Read one input line as a `T`, or say what was wrong and that `shape` was expected.
///
/// Numbers are read correctly rounded (serde_json's `float_roundtrip`); fields that `T`
/// does not name are ignored.
pub(crate) fn parse_job<T: DeserializeOwned>(text: &str, shape: &str) -> Result<T, Failure> {
    if text.trim().is_empty() {
        return Err(Failure::invalid_input(format!(
            "blank line; expected {shape}"
        )));
    }
    serde_json::from_str(text).map_err(|e| Failure::invalid_input(format!("{e}; expected {shape}")))
}

/// Up to [`CHUNK`] raw lines, without their line endings; empty at the end of the input.
fn read_chunk(reader: &mut dyn BufRead) -> io::Result<Vec<Vec<u8>>> {
    let mut lines = Vec::with_capacity(CHUNK);
    while lines.len() < CHUNK {
        let mut line = Vec::new();
        if reader.read_until(b'\n', &mut line)? == 0 {
            break;
        }
        if line.last() == Some(&b'\n') {
            line.pop();
        }
        if line.last() == Some(&b'\r') {
            line.pop();
        }
        lines.push(line);
    }
    Ok(lines)
}

/// The output line for one input line: what `solve` made of it, or the error, as JSON.
///
/// A panic inside the library is caught and reported as kind "internal" for this line, so
/// one bad line cannot lose the rest of the batch.
fn solve_line<F>(line: &[u8], solve: &F) -> String
where
    F: Fn(&str) -> Result<String, Failure>,
{
    let solved = catch_unwind(AssertUnwindSafe(|| {
        std::str::from_utf8(line)
            .map_err(|_| Failure::invalid_input("the line is not valid UTF-8"))
            .and_then(solve)
    }));
    match solved {
        Ok(Ok(report)) => report,
        Ok(Err(failure)) => failure.to_json_line(),
        Err(_) => Failure::new(
            "internal",
            "the solver panicked on this line; please report it with the line",
        )
        .to_json_line(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kind_of(line: &str) -> String {
        let solve = |text: &str| crate::segment::solve_job(text, 5);
        let v: serde_json::Value =
            serde_json::from_str(&solve_line(line.as_bytes(), &solve)).unwrap();
        v["error"]["kind"].as_str().unwrap_or("ok").to_string()
    }

    #[test]
    fn each_kind_of_bad_line_is_named() {
        assert_eq!(
            kind_of(r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":0.5}"#),
            "ok"
        );
        assert_eq!(kind_of(""), "invalid_input");
        assert_eq!(kind_of("{"), "invalid_input");
        assert_eq!(
            kind_of(r#"{"points":[[0,0],[1,1]],"alpha":0.5}"#),
            "invalid_input"
        );
        assert_eq!(
            kind_of(r#"{"points":[[0,0],[1,0],[2,0]],"alpha":0.5}"#),
            "collinear_points"
        );
        assert_eq!(
            kind_of(r#"{"points":[[-1,0],[0.9,0.9],[1,0]],"alpha":-1}"#),
            "not_drawable"
        );
    }

    #[test]
    fn line_endings_are_stripped_and_every_line_is_kept() {
        let mut input: &[u8] = b"a\r\n\nb";
        let lines = read_chunk(&mut input).unwrap();
        assert_eq!(lines, vec![b"a".to_vec(), vec![], b"b".to_vec()]);
    }
}
