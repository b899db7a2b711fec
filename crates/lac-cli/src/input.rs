//! Reading the one JSON document of `lac lcg` and `lac monotone`: a file, or standard input
//! (a pipe from another `lac`), with a size limit.

use std::fs::File;
use std::io::{self, IsTerminal, Read};
use std::path::Path;

use lac_io::json::ErrorBody;

use crate::errors;
use crate::limits::mebibytes;

/// The whole document: the file, or standard input for "-" or no file (not a terminal, where
/// it would wait for typing: then `hint` says what to give instead). At most `limit` bytes.
pub(crate) fn read_document(
    path: Option<&Path>,
    limit: usize,
    hint: &str,
) -> Result<String, ErrorBody> {
    let (reader, what): (Box<dyn Read>, Option<&Path>) = match path {
        Some(path) if path.as_os_str() != "-" => {
            let file = File::open(path).map_err(|e| errors::io("read", Some(path), &e))?;
            (Box::new(file), Some(path))
        }
        None if io::stdin().is_terminal() => return Err(errors::usage(hint)),
        _ => (Box::new(io::stdin()), None),
    };
    let fail = |e: &io::Error| match what {
        Some(path) => errors::io("read", Some(path), e),
        None => errors::io("read standard input", None, e),
    };
    let mut bytes = Vec::new();
    reader
        .take(limit as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| fail(&e))?;
    if bytes.len() > limit {
        return Err(ErrorBody::limit(format!(
            "the input is longer than {}, the most lac reads as one document (--allow-large \
             raises it)",
            mebibytes(limit)
        )));
    }
    String::from_utf8(bytes)
        .map_err(|_| ErrorBody::invalid_input("the input is not UTF-8 text; expected JSON"))
}
