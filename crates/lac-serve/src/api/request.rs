//! Reading requests: the input shapes of [`lac_io::json`] with the options of the API, and
//! error messages that name the shape expected.

use lac_io::json::{CompoundInput, CurveInput, ErrorBody, SegmentInput};
use serde::de::DeserializeOwned;
use serde::Deserialize;
use serde_json::{Map, Value};

/// An input shape and the number of samples to answer with: `{…input…, "samples": N}`.
#[derive(Debug, Deserialize)]
pub(crate) struct WithSamples<T> {
    /// The input.
    #[serde(flatten)]
    pub(crate) input: T,
    /// Samples of the answer (the server's default when absent).
    #[serde(default)]
    pub(crate) samples: Option<usize>,
}

/// The request's JSON object.
pub(crate) fn object(text: &str, shape: &str) -> Result<Map<String, Value>, ErrorBody> {
    match lac_io::json::parse::<Value>(text, shape)? {
        Value::Object(map) => Ok(map),
        other => Err(ErrorBody::invalid_input(format!(
            "expected a JSON object {shape}, got {}",
            kind_of(&other)
        ))),
    }
}

/// A `T` from the fields of `map`, or what was wrong and the shape expected.
pub(crate) fn field_shape<T: DeserializeOwned>(
    map: &Map<String, Value>,
    shape: &str,
) -> Result<T, ErrorBody> {
    serde_json::from_value(Value::Object(map.clone()))
        .map_err(|e| ErrorBody::invalid_input(format!("{e}; expected {shape}")))
}

/// A segment (with `alpha`) or a compound curve (with `alpha0`, `alpha1`) from the fields
/// of `map`, with the error message of the shape it resembles (serde's untagged enums say
/// only that nothing matched).
pub(crate) fn curve(map: &Map<String, Value>) -> Result<CurveInput, ErrorBody> {
    if map.contains_key("alpha0") || map.contains_key("alpha1") {
        field_shape::<CompoundInput>(map, CompoundInput::SHAPE).map(CurveInput::Compound)
    } else {
        field_shape::<SegmentInput>(map, SegmentInput::SHAPE).map(CurveInput::Segment)
    }
}

/// The optional field `name` of `map` as a `T`.
pub(crate) fn optional<T: DeserializeOwned>(
    map: &Map<String, Value>,
    name: &str,
    what: &str,
) -> Result<Option<T>, ErrorBody> {
    match map.get(name) {
        None | Some(Value::Null) => Ok(None),
        Some(value) => serde_json::from_value(value.clone())
            .map(Some)
            .map_err(|e| ErrorBody::invalid_input(format!("\"{name}\": {e}; expected {what}"))),
    }
}

/// The field `name` of `map` as a `T`.
pub(crate) fn required<T: DeserializeOwned>(
    map: &Map<String, Value>,
    name: &str,
    what: &str,
) -> Result<T, ErrorBody> {
    optional(map, name, what)?
        .ok_or_else(|| ErrorBody::invalid_input(format!("missing field \"{name}\": {what}")))
}

fn kind_of(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}
