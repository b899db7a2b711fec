//! Why a command failed: a stable kind, a message, and the exit code that goes with them.

use std::borrow::Cow;
use std::io;
use std::path::Path;

use serde::Serialize;

/// A failure reported as `{"error":{"kind":…,"message":…}}`, with `"omega_max"` after the
/// message when Ω was too large for `lac space`.
///
/// Exit codes: 2 for invalid input and usage errors, 3 when the numbers are valid but admit
/// no result ([`lac::Error::NotDrawable`], [`lac::Error::FitFailed`],
/// [`lac::Error::ToleranceNotMet`]), 1 for I/O errors.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Failure {
    /// A snake_case name: the library's [`lac::Error::kind`], or "usage", "invalid_input",
    /// "io".
    pub(crate) kind: Cow<'static, str>,
    /// What was wrong and what would fix it.
    pub(crate) message: String,
    /// [`lac::NotDrawable::TorsionTooLarge`]: the largest torsion parameter Ω for which a
    /// space segment was found; absent from the JSON otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) omega_max: Option<f64>,
}

/// The one-line JSON wrapper `{"error": …}`.
#[derive(Serialize)]
struct ErrorLine<'a> {
    error: &'a Failure,
}

impl Failure {
    /// A failure of `kind` (see [`Failure::exit_code`]) with no extra field.
    pub(crate) fn new(kind: impl Into<Cow<'static, str>>, message: impl Into<String>) -> Self {
        Failure {
            kind: kind.into(),
            message: message.into(),
            omega_max: None,
        }
    }

    /// A command-line usage error (exit code 2).
    pub(crate) fn usage(message: impl Into<String>) -> Self {
        Failure::new("usage", message)
    }

    /// Input that could not be read as control points or JSON (exit code 2).
    pub(crate) fn invalid_input(message: impl Into<String>) -> Self {
        Failure::new("invalid_input", message)
    }

    /// An I/O error on `path` ("standard input"/"standard output" when there is none).
    pub(crate) fn io(what: &str, path: Option<&Path>, err: &io::Error) -> Self {
        let target = match path {
            Some(p) => format!("{what} {}", p.display()),
            None => what.to_string(),
        };
        Failure::new("io", format!("cannot {target}: {err}"))
    }

    /// The process exit code for this failure.
    pub(crate) fn exit_code(&self) -> u8 {
        match self.kind.as_ref() {
            "io" => 1,
            "not_drawable" | "fit_failed" | "tolerance_not_met" => 3,
            _ => 2,
        }
    }

    /// The single line `{"error":{"kind":…,"message":…}}`, without a newline.
    pub(crate) fn to_json_line(&self) -> String {
        serde_json::to_string(&ErrorLine { error: self })
            .expect("a struct of strings and a number always serializes")
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.kind, self.message)
    }
}

impl std::error::Error for Failure {}

impl From<lac::Error> for Failure {
    fn from(err: lac::Error) -> Self {
        let omega_max = match &err {
            lac::Error::NotDrawable(lac::NotDrawable::TorsionTooLarge { omega_max, .. }) => {
                Some(*omega_max)
            }
            _ => None,
        };
        Failure {
            omega_max,
            ..Failure::new(kind_name(err.kind()), err.to_string())
        }
    }
}

/// The library's name for an error kind (its serde name: snake_case).
fn kind_name(kind: lac::ErrorKind) -> String {
    match serde_json::to_value(kind) {
        Ok(serde_json::Value::String(name)) => name,
        _ => "internal".to_string(),
    }
}

/// A clap error as a one-line usage failure: its text up to the usage block, on one line.
pub(crate) fn from_clap(err: &clap::Error) -> Failure {
    if err.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        return Failure::usage(
            "no subcommand given: use 'lac segment', 'lac compound', 'lac region', 'lac quasi', \
             'lac monotone', 'lac lcg' or 'lac space'; see 'lac --help'",
        );
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
    Failure::usage(message)
}
