//! JSON output (serde): the result structs of [`crate::examples`] derive `Serialize`;
//! fields that only serve the field output (model, displacements) are skipped.

use super::{Result, write_file};
use serde::Serialize;
use std::path::Path;

/// Pretty-printed JSON of `value`.
pub fn to_string<T: Serialize + ?Sized>(value: &T) -> Result<String> {
    Ok(serde_json::to_string_pretty(value)?)
}

/// Write `value` as pretty-printed JSON to `path` (parent directories created).
pub fn write<T: Serialize + ?Sized>(path: &Path, value: &T) -> Result<()> {
    let mut text = to_string(value)?;
    text.push('\n');
    write_file(path, text.as_bytes())
}
