//! How `lac` fails: [`ErrorBody`], the error every front end shares, with the command line's
//! own kinds ("usage", "io"), its exit codes, and a panic hook so that even a defect is one
//! line of JSON.

use std::cell::Cell;
use std::io::{self, Write};
use std::path::Path;

use clap::CommandFactory;
use lac_io::json::{ErrorBody, ErrorClass};

use crate::cli::Cli;

/// A command-line usage error (exit code 2).
pub(crate) fn usage(message: impl Into<String>) -> ErrorBody {
    ErrorBody::new("usage", message)
}

/// An I/O error on `path` ("standard input"/"standard output" when there is none; exit
/// code 1).
pub(crate) fn io(what: &str, path: Option<&Path>, err: &io::Error) -> ErrorBody {
    let target = match path {
        Some(p) => format!("{what} {}", p.display()),
        None => what.to_string(),
    };
    ErrorBody::new("io", format!("cannot {target}: {err}"))
}

/// The process exit code of a failure, from its class: 2 invalid input, 3 no curve (or no
/// fit), 1 I/O, 70 a defect of lac.
pub(crate) fn exit_code(err: &ErrorBody) -> u8 {
    match err.class() {
        ErrorClass::Invalid => 2,
        ErrorClass::Undrawable => 3,
        ErrorClass::Io => 1,
        ErrorClass::Internal => 70,
    }
}

/// A clap error as a one-line usage failure: its text up to the usage block, on one line.
pub(crate) fn from_clap(err: &clap::Error) -> ErrorBody {
    if err.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        // Every subcommand of the grammar, in its order.
        let names: Vec<String> = Cli::command()
            .get_subcommands()
            .map(|c| format!("'lac {}'", c.get_name()))
            .collect();
        let list = match names.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
            _ => names.concat(),
        };
        return usage(format!("no subcommand given: use {list}; see 'lac --help'"));
    }
    let text = err.render().to_string();
    let mut message = String::new();
    for line in text
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
    {
        let line = line.strip_prefix("error: ").unwrap_or(line);
        if line.is_empty() {
            continue;
        }
        if !message.is_empty() {
            message.push_str(if message.ends_with(':') { " " } else { "; " });
        }
        message.push_str(line);
    }
    message.push_str(" (see --help)");
    usage(message)
}

thread_local! {
    /// Set while a `--batch` line is solved: a panic there is caught and reported in the
    /// line's place ([`catching`]), so the hook stays quiet.
    static CATCHING: Cell<bool> = const { Cell::new(false) };
}

/// Report every panic that is not caught by [`catching`] as one line of JSON,
/// `{"error":{"kind":"internal",…}}`, and exit with code 70 (never Rust's panic message).
pub(crate) fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        if CATCHING.with(Cell::get) {
            return;
        }
        let body = ErrorBody::new("internal", panic_message(info));
        let _ = writeln!(io::stderr(), "{}", body.to_json_line());
        std::process::exit(70);
    }));
}

/// What a panic says, where, and what to do about it.
fn panic_message(info: &std::panic::PanicHookInfo<'_>) -> String {
    let payload = info
        .payload()
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| info.payload().downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "no message".to_string());
    let at = info
        .location()
        .map(|l| format!(" at {}:{}", l.file(), l.line()))
        .unwrap_or_default();
    format!(
        "lac panicked{at}: {payload}; this is a defect of lac, please report it with the command"
    )
}

/// Run `f`, catching a panic (quietly: see [`install_panic_hook`]) as `Err`.
pub(crate) fn catching<T>(f: impl FnOnce() -> T) -> std::thread::Result<T> {
    CATCHING.with(|c| c.set(true));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    CATCHING.with(|c| c.set(false));
    result
}

/// A deliberate panic at `place` when the environment variable `LAC_DEBUG_PANIC` names it
/// ("main", or "line N" of a `--batch`): how the tests check that a defect still gives one
/// line of JSON and its exit code.
pub(crate) fn debug_panic(place: &str) {
    if debug_panic_place().is_some_and(|p| p == place) {
        panic!("LAC_DEBUG_PANIC={place}");
    }
}

/// [`debug_panic`] at "line `number`" of a batch, without formatting the place for every
/// line (the variable is read once).
pub(crate) fn debug_panic_at_line(number: usize) {
    if let Some(place) = debug_panic_place() {
        if place.strip_prefix("line ") == Some(number.to_string().as_str()) {
            panic!("LAC_DEBUG_PANIC={place}");
        }
    }
}

/// The value of `LAC_DEBUG_PANIC`, read once.
fn debug_panic_place() -> Option<&'static str> {
    static PLACE: std::sync::OnceLock<Option<String>> = std::sync::OnceLock::new();
    PLACE
        .get_or_init(|| {
            std::env::var_os("LAC_DEBUG_PANIC").map(|v| v.to_string_lossy().into_owned())
        })
        .as_deref()
}
