//! Reading and writing result files: every JSON file the commands write is
//! a [`Document`] of the one result schema (`spinball_analysis::report`);
//! this module only adds the file handling (atomic writes, the path in
//! every message).

use std::fs;
use std::path::Path;

use spinball_analysis::report::{Document, PartialDocument};

use crate::error::CliError;
use crate::files::write_atomic;

/// Read the document in `path`.
///
/// # Errors
/// [`CliError::Usage`] naming the file if it cannot be read, is not a
/// document, does not hold together (an edited or damaged file) or was
/// written with another schema.
pub fn read_document(path: &Path) -> Result<Document, CliError> {
    let text = fs::read_to_string(path)
        .map_err(|e| CliError::Usage(format!("cannot read {}: {e}", path.display())))?;
    Document::from_json(&text).map_err(|e| CliError::Usage(format!("{}: {e}", path.display())))
}

/// Read the partial result (a shard or a checkpoint) in `path`.
///
/// # Errors
/// As [`read_document`]; [`CliError::Usage`] for a document of another
/// kind.
pub fn read_partial(path: &Path) -> Result<PartialDocument, CliError> {
    read_document(path)?
        .into_partial()
        .map_err(|e| CliError::Usage(format!("{} is {e}", path.display())))
}

/// Write `document` as JSON to `path` (indented if `pretty`), atomically
/// (a temporary file renamed over it), so a kill while writing never
/// leaves a torn file; a path that exists and is not a regular file is
/// refused, never replaced (see [`write_atomic`]).
///
/// # Errors
/// [`CliError::Failed`] if the file cannot be written or `path` is not a
/// regular file.
pub fn write_document(path: &Path, document: &Document, pretty: bool) -> Result<(), CliError> {
    let text = if pretty {
        document.to_json_pretty()
    } else {
        document.to_json()
    }
    .map_err(CliError::failed)?;
    write_atomic(path, (text + "\n").as_bytes())
}

/// Write the partial result `doc` to `path` (see [`write_document`]).
///
/// # Errors
/// As [`write_document`].
pub fn write_partial(path: &Path, doc: &PartialDocument) -> Result<(), CliError> {
    write_document(path, &Document::LyapunovPartial(doc.clone()), false)
}

/// Write a JSON file that is not a result (a campaign's plan, a table's
/// description) to `path`, atomically (see [`write_document`]).
///
/// # Errors
/// As [`write_document`].
pub fn write_json<T: serde::Serialize>(path: &Path, value: &T) -> Result<(), CliError> {
    let text = serde_json::to_string(value).map_err(CliError::failed)?;
    write_atomic(path, (text + "\n").as_bytes())
}
