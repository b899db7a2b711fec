//! Where results go: a file given with `-o`, or standard output.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use crate::failure::Failure;

/// Run `write` on a buffered writer to `path`, or to standard output when `path` is `None`,
/// and flush it.
///
/// A closed pipe on standard output (`lac … | head`) is not an error: the reader has
/// everything it wanted. `write` may fail with a [`Failure`] of its own by wrapping it in
/// [`io::Error::other`]; it is passed through unchanged.
pub(crate) fn write_to<F>(path: Option<&Path>, write: F) -> Result<(), Failure>
where
    F: FnOnce(&mut dyn Write) -> io::Result<()>,
{
    match path {
        Some(path) => {
            let file = File::create(path).map_err(|e| Failure::io("create", Some(path), &e))?;
            let mut out = BufWriter::new(file);
            write(&mut out)
                .and_then(|()| out.flush())
                .map_err(|e| carried(e).unwrap_or_else(|e| Failure::io("write", Some(path), &e)))
        }
        None => {
            let mut out = BufWriter::new(io::stdout().lock());
            match write(&mut out).and_then(|()| out.flush()) {
                Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
                    Err(carried(e)
                        .unwrap_or_else(|e| Failure::io("write standard output", None, &e)))
                }
                _ => Ok(()),
            }
        }
    }
}

/// The [`Failure`] inside an `io::Error::other(failure)`, or the error itself.
fn carried(err: io::Error) -> Result<Failure, io::Error> {
    match err
        .get_ref()
        .and_then(|inner| inner.downcast_ref::<Failure>())
    {
        Some(failure) => Ok(failure.clone()),
        None => Err(err),
    }
}
