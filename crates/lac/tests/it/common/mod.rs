//! What several test modules share.

pub(crate) mod space_inputs;

/// The text of the committed fixture `tests/fixtures/<name>`.
pub(crate) fn fixture_text(name: &str) -> String {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}
