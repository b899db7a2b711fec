//! Where results go: a file given with `-o`, or standard output (no `-o`, or `-o -`).

use std::fs::File;
use std::io::{self, BufWriter, IsTerminal, Write};
use std::path::Path;

use lac_io::json::ErrorBody;

use crate::errors;

/// Is `path` (the `-o` argument) standard output?
pub(crate) fn is_stdout(path: Option<&Path>) -> bool {
    path.is_none_or(|p| p.as_os_str() == "-")
}

/// Refuse to write a binary `format` (PNG) to a terminal: ask for `-o FILE` instead.
pub(crate) fn refuse_binary_on_terminal(
    path: Option<&Path>,
    format: &str,
    instead: &str,
) -> Result<(), ErrorBody> {
    if is_stdout(path) && io::stdout().is_terminal() {
        return Err(errors::usage(format!(
            "a {format} is not written to a terminal: give -o FILE, redirect standard output, \
             or use {instead}"
        )));
    }
    Ok(())
}

/// Run `write` on a buffered writer to `path`, or to standard output when `path` is `None`
/// or "-", and flush it.
///
/// A closed pipe on standard output (`lac … | head`) is not an error: the reader has
/// everything it wanted. `write` may fail with an [`ErrorBody`] of its own by wrapping it in
/// [`io::Error::other`]; it is passed through unchanged.
pub(crate) fn write_to<F>(path: Option<&Path>, write: F) -> Result<(), ErrorBody>
where
    F: FnOnce(&mut dyn Write) -> io::Result<()>,
{
    match path.filter(|_| !is_stdout(path)) {
        Some(path) => {
            let file = File::create(path).map_err(|e| errors::io("create", Some(path), &e))?;
            let mut out = BufWriter::new(file);
            write(&mut out)
                .and_then(|()| out.flush())
                .map_err(|e| carried(e).unwrap_or_else(|e| errors::io("write", Some(path), &e)))
        }
        None => {
            let mut out = BufWriter::new(io::stdout().lock());
            match write(&mut out).and_then(|()| out.flush()) {
                Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
                    Err(carried(e)
                        .unwrap_or_else(|e| errors::io("write standard output", None, &e)))
                }
                _ => Ok(()),
            }
        }
    }
}

/// Write a finished document to `path` (or standard output).
pub(crate) fn write_document(path: Option<&Path>, document: &[u8]) -> Result<(), ErrorBody> {
    write_to(path, |out| out.write_all(document))
}

/// The [`ErrorBody`] inside an `io::Error::other(body)`, or the error itself.
pub(crate) fn carried(err: io::Error) -> Result<ErrorBody, io::Error> {
    match err
        .get_ref()
        .and_then(|inner| inner.downcast_ref::<ErrorBody>())
    {
        Some(body) => Ok(body.clone()),
        None => Err(err),
    }
}
