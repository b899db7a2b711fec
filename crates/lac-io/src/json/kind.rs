//! The curve kinds, each described once ([`Kind`], in the kind's own file) and listed once
//! (`kinds!` in `json/mod.rs`), so that the front ends iterate them instead of knowing
//! them: reading a document of any kind (`lac export FILE`, the editor's `/api/export`),
//! solving it, and handing it to CAD export ([`AnyCurve::export_curve`]).
//!
//! A new kind of curve is one `impl Kind` in its file of `json/` and one line in the list.

use lac_export::ExportCurve;
use serde::de::DeserializeOwned;
use serde_json::{Map, Value};

use super::{parse, AnyCurve, ErrorBody};

/// A kind of curve, as the JSON documents describe it.
pub trait Kind {
    /// Its name: the `lac` subcommand that draws it, the export report's `"kind"`.
    const NAME: &'static str;

    /// The curve.
    type Curve;

    /// Whether `document` (a JSON object: an input, or a report read back) is one of this
    /// kind's, told by its keys. The kinds are asked in the order of their list, so a kind
    /// may claim what a later one would too.
    fn claims(document: &Map<String, Value>) -> bool;

    /// The curve a claimed document describes, solved again from what the document gives.
    fn solve(document: Map<String, Value>) -> Result<Self::Curve, ErrorBody>;

    /// The curve for CAD export: the parts it is fitted by ([`ExportCurve`]), with
    /// [`Kind::NAME`] as the report's kind.
    fn export(curve: &Self::Curve) -> Result<ExportCurve<'_>, ErrorBody>;
}

/// The fields of `document` as a `T`, or an error that says `what` was read and what shape
/// was expected.
pub fn fields<T: DeserializeOwned>(
    document: Map<String, Value>,
    what: &str,
    shape: &str,
) -> Result<T, ErrorBody> {
    serde_json::from_value(Value::Object(document))
        .map_err(|e| ErrorBody::invalid_input(format!("{what}: {e}; expected {shape}")))
}

/// The list of kinds, in the order they are asked to claim a document: [`AnyCurve`] with a
/// variant for each, and what iterates them.
macro_rules! kinds {
    ($($variant:ident: $kind:ty),* $(,)?) => {
        /// A curve of any kind, solved from a document ([`AnyCurve::read`]).
        #[derive(Clone, Debug)]
        pub enum AnyCurve {
            $(
                #[doc = concat!("A curve of the kind [`", stringify!($kind), "`].")]
                $variant(<$kind as $crate::json::Kind>::Curve),
            )*
        }

        /// The kinds' names, in the order they are asked.
        pub const KIND_NAMES: &[&str] = &[$(<$kind as $crate::json::Kind>::NAME),*];

        impl AnyCurve {
            /// The curve of a JSON object, by the first kind that claims it.
            pub fn from_fields(document: serde_json::Map<String, serde_json::Value>) -> Result<AnyCurve, $crate::json::ErrorBody> {
                $(
                    if <$kind as $crate::json::Kind>::claims(&document) {
                        return <$kind as $crate::json::Kind>::solve(document).map(AnyCurve::$variant);
                    }
                )*
                if document.contains_key("pieces") {
                    return Err($crate::json::ErrorBody::invalid_input(
                        "lac export needs the exact curve (a lac segment, compound, path, \
                         spline or space result), not Bézier pieces",
                    ));
                }
                Err($crate::json::ErrorBody::invalid_input(format!(
                    "no curve in the document: expected {}",
                    $crate::json::ANY_SHAPE
                )))
            }

            /// Its kind's name.
            pub fn name(&self) -> &'static str {
                match self {
                    $(AnyCurve::$variant(_) => <$kind as $crate::json::Kind>::NAME,)*
                }
            }

            /// The curve for CAD export.
            pub fn export_curve(
                &self,
            ) -> Result<lac_export::ExportCurve<'_>, $crate::json::ErrorBody> {
                match self {
                    $(AnyCurve::$variant(curve) => <$kind as $crate::json::Kind>::export(curve),)*
                }
            }
        }
    };
}

/// The documents [`AnyCurve::read`] takes, for error messages.
pub const ANY_SHAPE: &str = "a lac segment, compound, path, spline, space or fit result, or the \
                             input of one ({\"points\":…,\"alpha\":A}, {\"points\":…,\
                             \"alpha0\":A,\"alpha1\":B,…}, {\"points\":…,\"alpha\":A,\
                             \"closed\"|\"g2\"|\"fractions\":…}, {\"points\":…,\"alpha\":A,\
                             \"types\":[\"s\"|\"t\"|\"c\",…],…} or {\"points\":…,\
                             \"alpha\":A,\"beta\":B,…})";

impl AnyCurve {
    /// The curve of a JSON document: a result of `lac segment`, `compound`, `path`,
    /// `spline` or `space`, or the input of one.
    pub fn read(text: &str) -> Result<AnyCurve, ErrorBody> {
        match parse::<Value>(text, ANY_SHAPE)? {
            Value::Object(document) => AnyCurve::from_fields(document),
            _ => Err(ErrorBody::invalid_input(format!(
                "not a JSON object; expected {ANY_SHAPE}"
            ))),
        }
    }
}
